//! The interface's two languages. Every visible string comes from here.

/// A language of the interface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lang {
    /// 日本語.
    Ja,
    /// English.
    En,
}

impl Lang {
    /// The code used in the `lang` select and in storage.
    pub const fn code(self) -> &'static str {
        match self {
            Lang::Ja => "ja",
            Lang::En => "en",
        }
    }

    /// The language for a code; `None` for any other.
    pub fn from_code(code: &str) -> Option<Lang> {
        match code {
            "ja" => Some(Lang::Ja),
            "en" => Some(Lang::En),
            _ => None,
        }
    }

    /// The default for a browser language tag (`ja-JP` → Japanese).
    pub fn from_browser(tag: &str) -> Lang {
        if tag.to_ascii_lowercase().starts_with("ja") {
            Lang::Ja
        } else {
            Lang::En
        }
    }

    /// This language's strings.
    pub const fn texts(self) -> &'static Texts {
        match self {
            Lang::Ja => &JA,
            Lang::En => &EN,
        }
    }
}

/// Every string the interface shows.
pub struct Texts {
    pub title: &'static str,
    pub language: &'static str,
    pub example: &'static str,
    pub example_none: &'static str,
    pub example_seed: &'static str,
    pub undo_open: &'static str,
    pub speed: &'static str,
    pub speed_max: &'static str,
    pub pause: &'static str,
    pub resume: &'static str,
    pub power: &'static str,
    pub run: &'static str,
    pub halt: &'static str,
    pub reset: &'static str,
    pub slow: &'static str,
    pub fast: &'static str,
    pub clock: &'static str,
    pub write: &'static str,
    pub count_clear: &'static str,
    pub pc: &'static str,
    pub instruction: &'static str,
    pub accumulator: &'static str,
    pub inputs: &'static str,
    pub outputs: &'static str,
    pub counter: &'static str,
    pub counter_set: &'static str,
    pub tens: &'static str,
    pub ones: &'static str,
    pub dip: &'static str,
    pub timer: &'static str,
    pub seconds: &'static str,
    pub program: &'static str,
    pub load: &'static str,
    pub loaded: &'static str,
    pub not_loaded: &'static str,
    pub errors_none: &'static str,
    pub line: &'static str,
    pub sheet: &'static str,
    pub sheet_address: &'static str,
    pub sheet_opcode: &'static str,
    pub sheet_operand: &'static str,
    pub sheet_binary: &'static str,
    pub corrupt_saved: &'static str,
    pub storage_unavailable: &'static str,
    pub crashed: &'static str,
    pub sim_time: &'static str,
    pub scans: &'static str,
    pub machine: &'static str,
    pub title_io86a: &'static str,
    pub terminal: &'static str,
    pub terminal_hint: &'static str,
    pub ctrl_c: &'static str,
    pub two_devices: &'static str,
    pub device_a: &'static str,
    pub device_b: &'static str,
    pub ir_remote: &'static str,
    pub analog_in: &'static str,
    pub servo: &'static str,
    pub pwm: &'static str,
    pub running: &'static str,
    pub stopped: &'static str,
}

static JA: Texts = Texts {
    title: "Hashigo 梯子 — MINASEC-U",
    language: "言語",
    example: "サンプル",
    example_none: "（サンプルを開く）",
    example_seed: "本のテストプログラム",
    undo_open: "開く前のプログラムに戻す",
    speed: "速度",
    speed_max: "最高速",
    pause: "一時停止",
    resume: "再開",
    power: "電源",
    run: "RUN",
    halt: "HALT",
    reset: "RESET",
    slow: "SLOW",
    fast: "FAST",
    clock: "CLOCK",
    write: "WRITE",
    count_clear: "CNTCLR",
    pc: "プログラムカウンター",
    instruction: "命令",
    accumulator: "アキュムレーター",
    inputs: "入力 X",
    outputs: "出力 Y",
    counter: "カウンター",
    counter_set: "カウンター設定値",
    tens: "10の位",
    ones: "1の位",
    dip: "データスイッチ",
    timer: "タイマー",
    seconds: "秒",
    program: "プログラム",
    load: "書き込む",
    loaded: "書き込み済み",
    not_loaded: "未書き込みの変更あり",
    errors_none: "エラーなし",
    line: "行",
    sheet: "プログラミングシート",
    sheet_address: "アドレス",
    sheet_opcode: "オペコード",
    sheet_operand: "オペランド",
    sheet_binary: "2進数",
    corrupt_saved: "保存データを読めませんでした。元のデータは次のキーに退避しました:",
    storage_unavailable: "ブラウザーの保存領域が使えません。変更は保存されません。",
    crashed: "内部エラーが発生しました。ページを再読み込みしてください。プログラムは自動保存されています。",
    sim_time: "シミュレーション時間",
    scans: "スキャン",
    machine: "機種",
    title_io86a: "Hashigo 梯子 — PLC-IO86A",
    terminal: "シリアルターミナル",
    terminal_hint: "コマンドを入力して Enter（例: Y? , L , R）",
    ctrl_c: "Ctrl-C（停止）",
    two_devices: "2台をシリアル接続",
    device_a: "デバイス A",
    device_b: "デバイス B",
    ir_remote: "赤外線リモコン（X07）",
    analog_in: "アナログ入力",
    servo: "RCサーボ",
    pwm: "PWM",
    running: "実行中",
    stopped: "停止中",
};

static EN: Texts = Texts {
    title: "Hashigo — MINASEC-U",
    language: "Language",
    example: "Example",
    example_none: "(open an example)",
    example_seed: "The book's test program",
    undo_open: "Back to the program before opening",
    speed: "Speed",
    speed_max: "As fast as possible",
    pause: "Pause",
    resume: "Resume",
    power: "Power",
    run: "RUN",
    halt: "HALT",
    reset: "RESET",
    slow: "SLOW",
    fast: "FAST",
    clock: "CLOCK",
    write: "WRITE",
    count_clear: "CNTCLR",
    pc: "Program counter",
    instruction: "Instruction",
    accumulator: "Accumulator",
    inputs: "Inputs X",
    outputs: "Outputs Y",
    counter: "Counter",
    counter_set: "Counter set value",
    tens: "tens",
    ones: "ones",
    dip: "Data switches",
    timer: "Timer",
    seconds: "s",
    program: "Program",
    load: "Load into the board",
    loaded: "loaded",
    not_loaded: "changes not loaded",
    errors_none: "no errors",
    line: "line",
    sheet: "Programming sheet",
    sheet_address: "Addr",
    sheet_opcode: "Opcode",
    sheet_operand: "Operand",
    sheet_binary: "Binary",
    corrupt_saved: "The saved data could not be read. It was kept aside under the key:",
    storage_unavailable: "The browser's storage is unavailable: changes are not saved.",
    crashed: "An internal error occurred. Please reload the page; your program is autosaved.",
    sim_time: "Simulated time",
    scans: "scans",
    machine: "Machine",
    title_io86a: "Hashigo — PLC-IO86A",
    terminal: "Serial terminal",
    terminal_hint: "Type a command and press Enter (e.g. Y?, L, R)",
    ctrl_c: "Ctrl-C (stop)",
    two_devices: "Link a second device",
    device_a: "Device A",
    device_b: "Device B",
    ir_remote: "IR remote (X07)",
    analog_in: "Analog input",
    servo: "RC servo",
    pwm: "PWM",
    running: "running",
    stopped: "stopped",
};
