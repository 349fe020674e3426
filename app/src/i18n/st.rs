//! The Structured Text pane's words (issue #55). A table of its own,
//! reached through [`super::Lang::st`], so that parallel work does not
//! collide in the big [`super::Texts`] table.

/// The ST pane's strings.
pub struct St {
    /// The program pane's language choice.
    pub language: &'static str,
    pub il: &'static str,
    pub st: &'static str,
    /// Runs to the next statement's line.
    pub step_statement: &'static str,
    /// A gutter's button: `{line}`.
    pub breakpoint_at: &'static str,
    /// The status while paused at a line: `{line}`.
    pub paused_at: &'static str,
    /// The status when a breakpoint stopped the scan: `{line}`.
    pub stopped_at: &'static str,
    /// The completion list's name.
    pub completions: &'static str,
    /// A completion's kind.
    pub variable: &'static str,
    pub block: &'static str,
    pub keyword: &'static str,
    /// Under the editor: how to reach completion and breakpoints.
    pub hint: &'static str,
    /// A project's ST replaced the text typed before, kept under a key
    /// (said after it).
    pub set_aside: &'static str,
    /// Why?: a statement of the ST that wrote a value: `{line}`.
    pub why_line: &'static str,
    /// Why? in the pane: the name asked about's field and its button.
    pub why_name: &'static str,
    pub why: &'static str,
    /// Why? found no statement that writes the name: `{name}`.
    pub why_none: &'static str,
    /// Whether the statement ran in the scan explained.
    pub why_ran: &'static str,
    pub why_not_ran: &'static str,
    /// The choice of the block instance whose values the lines show.
    pub instance: &'static str,
    /// The status's note of the call the scan stands in: `{instance}`.
    pub in_call: &'static str,
}

/// In English.
pub const EN: St = St {
    language: "Language",
    il: "IL (Instruction List)",
    st: "ST (Structured Text)",
    step_statement: "Step statement",
    breakpoint_at: "Breakpoint on line {line}",
    paused_at: "Paused before line {line}",
    stopped_at: "Breakpoint: stopped before line {line}",
    completions: "Completions",
    variable: "variable",
    block: "block",
    keyword: "keyword",
    hint: "Ctrl+Space completes a name; click a line number to set a breakpoint.",
    set_aside: "The project brought its Structured Text; the text typed before is kept under",
    why_line: "ST line {line}",
    why_name: "Why does this variable hold its value?",
    why: "Why?",
    why_none: "No statement of the program writes {name}.",
    why_ran: "ran in the last scan",
    why_not_ran: "did not run in the last scan",
    instance: "Instance shown",
    in_call: "in {instance}'s call",
};

/// 日本語.
pub const JA: St = St {
    language: "言語",
    il: "IL（命令リスト）",
    st: "ST（ストラクチャードテキスト）",
    step_statement: "文ステップ",
    breakpoint_at: "{line} 行目のブレークポイント",
    paused_at: "{line} 行目の前で一時停止中",
    stopped_at: "ブレークポイント：{line} 行目の前で停止",
    completions: "入力候補",
    variable: "変数",
    block: "ブロック",
    keyword: "キーワード",
    hint: "Ctrl+Space で名前を補完、行番号をクリックでブレークポイントを設定します。",
    set_aside: "プロジェクトのストラクチャードテキストを開きました。以前のテキストの保存先:",
    why_line: "ST {line} 行目",
    why_name: "この変数がなぜこの値なのか",
    why: "なぜ？",
    why_none: "プログラムに {name} へ書き込む文はありません。",
    why_ran: "直前のスキャンで実行",
    why_not_ran: "直前のスキャンでは未実行",
    instance: "表示するインスタンス",
    in_call: "{instance} の呼び出し中",
};
