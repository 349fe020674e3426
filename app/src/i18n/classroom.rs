//! The classroom's words (issue #49): exercises, writing tests, "Copied".
//! A table of its own, reached through [`super::Lang::classroom`], so that
//! parallel work does not collide in the big [`super::Texts`] table.

/// The classroom's strings.
pub struct Classroom {
    /// The student's view: the task's heading.
    pub task: &'static str,
    /// The button that runs the student's answer against the tests.
    pub check: &'static str,
    /// "N of M tests pass" (`{passed}`, `{total}`).
    pub result: &'static str,
    /// Said when every test passes.
    pub all_pass: &'static str,
    /// Said over the failures.
    pub not_yet: &'static str,
    /// A failing case without an author's hint.
    pub no_hint: &'static str,
    /// The ladder does not compile, so no test could pass.
    pub not_compiled: &'static str,
    /// Tests hidden from the student: `{n}` of them.
    pub hidden_count: &'static str,
    /// The student's result link.
    pub send: &'static str,
    /// Under the result link: what to do with it.
    pub send_note: &'static str,
    /// The author's view: the switch into it and out of it.
    pub edit_exercise: &'static str,
    pub done_editing: &'static str,
    /// The task's box in the page's language and in the other one.
    pub task_edit: &'static str,
    pub task_edit_other: &'static str,
    /// What the task's box takes.
    pub task_placeholder: &'static str,
    /// The checkbox that hides the tests from the student.
    pub tests_hidden: &'static str,
    /// A case's hint box.
    pub hint: &'static str,
    pub hint_placeholder: &'static str,
    /// The syntax's examples in the empty boxes.
    pub events_placeholder: &'static str,
    pub expect_placeholder: &'static str,
    /// The link to the guide's tests section.
    pub guide: &'static str,
    /// A pass, said as more than a word.
    pub pass: &'static str,
    /// Share: the link was copied.
    pub copied: &'static str,
    /// Share: the clipboard refused; the link is in the field.
    pub copy_by_hand: &'static str,
    /// A case whose device the ladder does not use yet (`{device}`).
    pub unused_device: &'static str,
    /// A result link opened: whose answer and how it did.
    pub answer_of: &'static str,
}

/// English.
pub const EN: Classroom = Classroom {
    task: "Task",
    check: "Check my answer",
    result: "{passed} of {total} tests pass",
    all_pass: "Well done: every test passes.",
    not_yet: "Not yet. What to look at:",
    no_hint: "this test does not pass yet",
    not_compiled: "Your ladder does not compile yet: see Listing & problems.",
    hidden_count: "Tests that check your answer: {n} (hidden by the author).",
    send: "Send my answer",
    send_note: "Send this link to your teacher: it opens your ladder with its result.",
    edit_exercise: "Edit the exercise",
    done_editing: "Show the student's view",
    task_edit: "Task (English)",
    task_edit_other: "Task (日本語)",
    task_placeholder: "What the student is to draw. Paragraphs are separated by a blank line;\n- a line starting with a dash is a list item;\n**bold** and `X00` (code) are kept.",
    tests_hidden: "Hide the tests from the student",
    hint: "Hint when it fails",
    hint_placeholder: "e.g. Y00 must stay on after X00 is released: hold it with its own contact.",
    events_placeholder: "# time,device,value — one change a line\n0.1s,X00,1\n0.2s,X00,0",
    expect_placeholder: "Y00 = 0 at 0.05s\nY00 rises within 0.1s..0.2s\nY00 stays 1 from 0.2s to 1s",
    guide: "How to write tests",
    pass: "✓ passes",
    copied: "Link copied",
    copy_by_hand: "Copy the link from the field",
    unused_device: "the ladder does not use {device} yet",
    answer_of: "A student's answer:",
};

/// 日本語.
pub const JA: Classroom = Classroom {
    task: "課題",
    check: "答えを確認",
    result: "{total} 件中 {passed} 件のテストに合格",
    all_pass: "よくできました。すべてのテストに合格です。",
    not_yet: "まだです。見直すところ:",
    no_hint: "このテストにはまだ合格していません",
    not_compiled: "ラダーがまだ変換できません。「リストと問題」を見てください。",
    hidden_count: "{n} 件のテストで答えを確認します (作成者が非表示にしています)。",
    send: "答えを送る",
    send_note: "このリンクを先生に送ってください。あなたのラダーと結果が開きます。",
    edit_exercise: "課題を編集",
    done_editing: "生徒の画面を表示",
    task_edit: "課題 (日本語)",
    task_edit_other: "課題 (English)",
    task_placeholder: "生徒に描いてほしいもの。空行で段落を分けます。\n- ダッシュで始まる行は箇条書き、\n**太字** と `X00` (コード) が使えます。",
    tests_hidden: "テストを生徒に見せない",
    hint: "不合格のときのヒント",
    hint_placeholder: "例: X00 を離しても Y00 が入ったままになるよう、自己保持にします。",
    events_placeholder: "# 時刻,デバイス,値 — 1行に1つの変化\n0.1s,X00,1\n0.2s,X00,0",
    expect_placeholder: "Y00 = 0 at 0.05s\nY00 rises within 0.1s..0.2s\nY00 stays 1 from 0.2s to 1s",
    guide: "テストの書き方",
    pass: "✓ 合格",
    copied: "リンクをコピーしました",
    copy_by_hand: "欄からリンクをコピーしてください",
    unused_device: "ラダーはまだ {device} を使っていません",
    answer_of: "生徒の答え:",
};
