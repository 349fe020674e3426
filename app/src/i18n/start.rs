//! The first five minutes' words (issue #47): the start screen's frame,
//! the guided first rung and the guide's frame. The start screen's and the
//! guide's own text are static files fetched on first use
//! (`web/start/`, `web/guide/`), so they cost the first screen nothing.

/// The strings of the start screen, the tour and the guide's panel.
pub struct StartTexts {
    pub start_label: &'static str,
    pub start_close: &'static str,
    pub start_again: &'static str,
    pub fetch_failed: &'static str,
    pub retry: &'static str,
    pub loading: &'static str,
    pub guide: &'static str,
    pub guide_close: &'static str,
    pub guide_section: &'static str,
    pub tour_label: &'static str,
    pub tour_next: &'static str,
    pub tour_skip: &'static str,
    pub tour_close: &'static str,
    pub tour_done_mark: &'static str,
    /// Each step's title and what to do, with `{0}` `{1}` `{2}` standing
    /// for the machine's start input, stop input and output.
    pub steps: [(&'static str, &'static str); 10],
    pub tour_keys: &'static str,
    pub tour_taps: &'static str,
}

/// English.
pub static EN: StartTexts = StartTexts {
    start_label: "Start",
    start_close: "Close the start screen",
    start_again: "Start screen",
    fetch_failed: "This could not be fetched (offline?).",
    retry: "Try again",
    loading: "Loading…",
    guide: "Guide",
    guide_close: "Close the guide",
    guide_section: "Open this part of the guide",
    tour_label: "Your first rung",
    tour_next: "Next",
    tour_skip: "Skip this step",
    tour_close: "Leave the tour (Esc)",
    tour_done_mark: "Done",
    steps: [
        (
            "A start/stop circuit",
            "You will draw the rung every PLC course starts with: {0} starts {2}, {1} stops it, and {2} holds itself on in between. Each step is checked as you do it.",
        ),
        (
            "1. The start button",
            "Put a normally open contact {0} at the start of the first rung.",
        ),
        (
            "2. The stop button",
            "Next to it, put a normally closed contact {1}.",
        ),
        ("3. The output", "Put the coil {2} on the same rung."),
        (
            "4. The self-hold",
            "The cursor is under {0}: put a contact {2} there as a branch (Shift+F5, or the palette's └┤ ├┘), so that {2} keeps itself on when {0} is let go.",
        ),
        (
            "5. Run it",
            "Press Run in the bar at the top. The ladder lights up where power flows.",
        ),
        (
            "6. Start",
            "Turn {0} on: click its contact on the running ladder (or its switch on the panel). {2} comes on.",
        ),
        (
            "7. Let go",
            "Turn {0} off again. {2} stays on: it holds itself through its own contact.",
        ),
        ("8. Stop", "Turn {1} on. {2} goes off and stays off."),
        (
            "Well done",
            "That is a self-hold, the heart of most ladders. The guide (Help → Guide) shows what else you can do: timers, counters, tests, Why?, sharing.",
        ),
    ],
    tour_keys: "Keys: select the cell, then F5 (contact), F6 (closed contact), F7 (coil), Shift+F5 (contact as a branch); type the device and press Enter.",
    tour_taps: "Taps: tap the cell, then a button of the palette above the ladder; type the device and tap OK.",
};

/// 日本語.
pub static JA: StartTexts = StartTexts {
    start_label: "スタート",
    start_close: "スタート画面を閉じる",
    start_again: "スタート画面",
    fetch_failed: "読み込めませんでした (オフライン?)。",
    retry: "再試行",
    loading: "読み込み中…",
    guide: "ガイド",
    guide_close: "ガイドを閉じる",
    guide_section: "ガイドのこの項を開く",
    tour_label: "はじめてのラダー",
    tour_next: "次へ",
    tour_skip: "この手順を飛ばす",
    tour_close: "ツアーを終える (Esc)",
    tour_done_mark: "完了",
    steps: [
        (
            "起動・停止回路",
            "PLC の講習で最初に描く回路を描きます。{0} で {2} が起動し、{1} で停止し、その間 {2} は自己保持します。手順ごとに、できたかどうかを確かめます。",
        ),
        ("1. 起動ボタン", "最初の回路の先頭に a 接点 {0} を置きます。"),
        ("2. 停止ボタン", "その右に b 接点 {1} を置きます。"),
        ("3. 出力", "同じ回路にコイル {2} を置きます。"),
        (
            "4. 自己保持",
            "カーソルは {0} の下にあります。そこに {2} の a 接点を並列に置きます (Shift+F5、またはパレットの └┤ ├┘)。{0} を離しても {2} が自分の接点で入り続けます。",
        ),
        (
            "5. 実行",
            "上のバーの「実行」を押します。電流が流れるところが光ります。",
        ),
        (
            "6. 起動",
            "{0} を入れます。実行中のラダーでその接点をクリックします (パネルのスイッチでも)。{2} が入ります。",
        ),
        (
            "7. 離す",
            "{0} を切ります。{2} は入ったまま: 自分の接点で保持しています。",
        ),
        ("8. 停止", "{1} を入れます。{2} が切れ、切れたままになります。"),
        (
            "できました",
            "これが自己保持回路、たいていのラダーの基本です。ほかにできること (タイマ、カウンタ、テスト、なぜ?、共有) はガイド (ヘルプ → ガイド) にあります。",
        ),
    ],
    tour_keys: "キー: セルを選び、F5 (a 接点)、F6 (b 接点)、F7 (コイル)、Shift+F5 (並列の a 接点)。デバイス名を入力して Enter。",
    tour_taps: "タップ: セルをタップし、ラダーの上のパレットのボタンをタップ。デバイス名を入力して OK。",
};
