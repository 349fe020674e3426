//! Exercises in the Tests pane (issue #49, docs/tests.md "Exercises"):
//! the student's view (the task, **Check my answer**, the result in the
//! student's words, a result link to send back) and the author's (the
//! task in both languages, tests hidden or shown).

use engine::cases::TestCase;
use engine::formats::project::{Exercise, TestsShown};
use leptos::prelude::*;

use crate::editor::state::{CaseResult, LadderCtx};

/// A piece of a task's line: plain, **bold** or `code`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Span {
    /// Plain text.
    Text(String),
    /// Between `**`.
    Bold(String),
    /// Between backticks.
    Code(String),
}

/// A block of a task: a paragraph, or a list of `- ` items.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Block {
    /// Lines up to a blank line, joined by spaces.
    Para(Vec<Span>),
    /// Consecutive lines starting with `- `.
    List(Vec<Vec<Span>>),
}

/// Reads a task's simple formatting: paragraphs separated by a blank
/// line, `- ` list items, `**bold**` and `` `code` `` (docs/tests.md).
/// Anything else is text as written (never markup: it is shown as text).
pub fn blocks(task: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut para: Vec<&str> = Vec::new();
    let mut items: Vec<Vec<Span>> = Vec::new();
    let flush_para = |para: &mut Vec<&str>, out: &mut Vec<Block>| {
        if !para.is_empty() {
            out.push(Block::Para(spans(&para.join(" "))));
            para.clear();
        }
    };
    for line in task.lines().map(str::trim_end) {
        let trimmed = line.trim_start();
        if let Some(item) = trimmed.strip_prefix("- ") {
            flush_para(&mut para, &mut out);
            items.push(spans(item.trim()));
            continue;
        }
        if !items.is_empty() {
            out.push(Block::List(std::mem::take(&mut items)));
        }
        if trimmed.is_empty() {
            flush_para(&mut para, &mut out);
        } else {
            para.push(trimmed);
        }
    }
    flush_para(&mut para, &mut out);
    if !items.is_empty() {
        out.push(Block::List(items));
    }
    out
}

/// A line's bold and code spans; an unclosed marker is text.
pub fn spans(line: &str) -> Vec<Span> {
    let mut out = Vec::new();
    let mut text = String::new();
    let mut rest = line;
    while !rest.is_empty() {
        let marked = if let Some(after) = rest.strip_prefix("**") {
            after
                .find("**")
                .map(|end| (Span::Bold(after[..end].into()), &after[end + 2..]))
        } else if let Some(after) = rest.strip_prefix('`') {
            after
                .find('`')
                .map(|end| (Span::Code(after[..end].into()), &after[end + 1..]))
        } else {
            None
        };
        match marked {
            Some((span, after)) => {
                if !text.is_empty() {
                    out.push(Span::Text(std::mem::take(&mut text)));
                }
                out.push(span);
                rest = after;
            }
            None => {
                let c = rest.chars().next().unwrap_or(' ');
                text.push(c);
                rest = &rest[c.len_utf8()..];
            }
        }
    }
    if !text.is_empty() {
        out.push(Span::Text(text));
    }
    out
}

/// How the student's answer did: what passed, and each failing case's
/// name with its author's hint (never the engine's or the author's
/// error: those are the author's to read).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// Cases that passed.
    pub passed: usize,
    /// Cases run.
    pub total: usize,
    /// Each failing case: its name and hint (empty: none written).
    pub failures: Vec<(String, String)>,
}

/// The verdict of `results` on `cases` (a case not run counts as failed).
pub fn verdict(cases: &[TestCase], results: &[Option<CaseResult>]) -> Verdict {
    let mut v = Verdict {
        passed: 0,
        total: cases.len(),
        failures: Vec::new(),
    };
    for (i, case) in cases.iter().enumerate() {
        if results.get(i) == Some(&Some(CaseResult::Pass)) {
            v.passed += 1;
        } else {
            v.failures.push((case.name.clone(), case.hint.clone()));
        }
    }
    v
}

/// A task shown with its formatting.
#[component]
fn TaskText(text: String) -> impl IntoView {
    let line = |spans: Vec<Span>| {
        spans
            .into_iter()
            .map(|s| match s {
                Span::Text(t) => view! { <span>{t}</span> }.into_any(),
                Span::Bold(t) => view! { <strong>{t}</strong> }.into_any(),
                Span::Code(t) => view! { <code>{t}</code> }.into_any(),
            })
            .collect_view()
    };
    blocks(&text)
        .into_iter()
        .map(|b| match b {
            Block::Para(spans) => view! { <p>{line(spans)}</p> }.into_any(),
            Block::List(items) => view! {
                <ul>{items.into_iter().map(|i| view! { <li>{line(i)}</li> }).collect_view()}</ul>
            }
            .into_any(),
        })
        .collect_view()
}

/// The student's view: the task, Check my answer (`check`: runs the
/// cases), the result, the link to send back, and the author's way in.
#[component]
pub fn StudentView(ctx: LadderCtx, check: Callback<()>) -> impl IntoView {
    let c = move || ctx.page.lang.get().classroom();
    let task = move || {
        let lang = ctx.page.lang.get().code();
        ctx.cases
            .exercise
            .with(|e| e.as_ref().map(|e| e.task.in_lang(lang).to_string()))
            .unwrap_or_default()
    };
    let sent = RwSignal::new(None::<String>);
    // A link made before an edit holds the ladder as it was: taken away
    // at the edit, so the student never sends an answer they changed.
    Effect::new(move |first: Option<()>| {
        ctx.drawing.revision.track();
        if first.is_some() {
            sent.set(None);
        }
    });
    let send = move |_| {
        use crate::editor::shared;
        let project = shared::project_of(ctx);
        let said = move |e| {
            let lang = ctx.page.lang.get_untracked();
            ctx.panes.message.set(Some(shared::codec_failed(lang, e)));
        };
        wasm_bindgen_futures::spawn_local(async move {
            match shared::encode(project).await {
                Ok(Ok(fragment)) => sent.set(Some(shared::answer_url(&fragment))),
                Ok(Err(e)) => said(Ok(e)),
                Err(missing) => said(Err(missing)),
            }
        });
    };
    let check_now = move |_| {
        check.run(());
        // The result is drawn under the buttons, which a short dock may
        // hide: brought into view, the page moved no more than needed.
        request_animation_frame(|| {
            let found = document().query_selector("[data-testid=exercise-result]");
            if let Ok(Some(result)) = found {
                let options = web_sys::ScrollIntoViewOptions::new();
                options.set_block(web_sys::ScrollLogicalPosition::Nearest);
                result.scroll_into_view_with_scroll_into_view_options(&options);
            }
        });
    };
    view! {
        <div class="exercise" data-testid="exercise-view">
            <Show when=move || !task().trim().is_empty()>
                <div class="exercise-task" data-testid="exercise-task" role="region" aria-label=move || c().task>
                    <h3>{move || c().task}</h3>
                    {move || view! { <TaskText text=task() /> }}
                </div>
            </Show>
            <div class="find-row">
                <button type="button" class="primary" data-testid="exercise-check"
                    on:click=check_now>{move || c().check}</button>
                <button type="button" data-testid="exercise-send" on:click=send>{move || c().send}</button>
                <button type="button" class="quiet" data-testid="exercise-edit"
                    on:click=move |_| ctx.cases.authoring.set(true)>{move || c().edit_exercise}</button>
            </div>
            <ResultView ctx />
            <Show when=move || sent.with(Option::is_some)>
                <p class="exercise-send-note">{move || c().send_note}</p>
                <input class="share-url" data-testid="exercise-answer-url" readonly aria-label=move || c().send
                    prop:value=move || sent.get().unwrap_or_default() />
            </Show>
        </div>
    }
}

/// `[data-testid=exercise-result]`, once the answer was checked.
#[component]
fn ResultView(ctx: LadderCtx) -> impl IntoView {
    let c = move || ctx.page.lang.get().classroom();
    let f = move || ctx.page.lang.get().plant_faults();
    let v = move || {
        let results = ctx.cases.results.get();
        let mut v =
            (!results.is_empty()).then(|| ctx.cases.tests.with(|t| verdict(t, &results)))?;
        // Where the plant hides a fault, naming it is one more thing graded.
        if let Some(right) = ctx.cases.report.with(|r| r.1) {
            v.total += 1;
            if right {
                v.passed += 1;
            } else {
                v.failures
                    .push((f().fault_case.into(), f().fault_wrong.into()));
            }
        }
        Some(v)
    };
    move || {
        v().map(|v| {
            let ok = v.passed == v.total;
            let said = c()
                .result
                .replace("{passed}", &v.passed.to_string())
                .replace("{total}", &v.total.to_string());
            let uncompiled = ctx.drawing.listing.with_untracked(Option::is_none);
            let failures = v
                .failures
                .into_iter()
                .map(|(name, hint)| {
                    let hint = if hint.trim().is_empty() { c().no_hint.to_string() } else { hint };
                    view! { <li><strong>{name}</strong>": "{hint}</li> }
                })
                .collect_view();
            view! {
                <div class=if ok { "exercise-result pass" } else { "exercise-result fail" } role="status"
                    data-testid="exercise-result" data-passed=v.passed.to_string() data-total=v.total.to_string()>
                    <p class="exercise-score"><span aria-hidden="true">{if ok { "✓ " } else { "✗ " }}</span>{said}</p>
                    <p>{if ok { c().all_pass } else if uncompiled { c().not_compiled } else { c().not_yet }}</p>
                    <ul>{failures}</ul>
                </div>
            }
        })
    }
}

/// The author's exercise: the task in both languages, tests hidden or
/// shown, and the way to the student's view.
#[component]
pub fn ExerciseEditor(ctx: LadderCtx) -> impl IntoView {
    let c = move || ctx.page.lang.get().classroom();
    let ja = move || ctx.page.lang.get().code() == "ja";
    let edit = move |f: &dyn Fn(&mut Exercise)| {
        ctx.cases.exercise.update(|e| {
            if let Some(e) = e {
                f(e);
            }
        });
        ctx.save();
    };
    // The page's language first: the box an author most likely writes in.
    let text_of = move |first: bool| {
        ctx.cases.exercise.with(|e| {
            e.as_ref()
                .map(|e| {
                    if first == ja() {
                        e.task.ja.clone()
                    } else {
                        e.task.en.clone()
                    }
                })
                .unwrap_or_default()
        })
    };
    let set_text = move |first: bool, v: String| {
        let in_ja = first == ja();
        edit(&|e| {
            if in_ja {
                e.task.ja = v.clone()
            } else {
                e.task.en = v.clone()
            }
        });
    };
    let hidden = move || {
        ctx.cases
            .exercise
            .with(|e| e.as_ref().is_some_and(Exercise::hidden))
    };
    view! {
        <div class="exercise-editor">
            <label class="test-field">{move || c().task_edit}
                <textarea data-testid="exercise-task-edit" rows="5" placeholder=move || c().task_placeholder
                    prop:value=move || text_of(true) on:change=move |e| set_text(true, event_target_value(&e)) />
            </label>
            <label class="test-field">{move || c().task_edit_other}
                <textarea data-testid="exercise-task-edit-other" rows="3" placeholder=move || c().task_placeholder
                    prop:value=move || text_of(false) on:change=move |e| set_text(false, event_target_value(&e)) />
            </label>
            <div class="find-row">
                <label>
                    <input type="checkbox" data-testid="exercise-tests-hidden" prop:checked=hidden
                        on:change=move |e| {
                            let on = event_target_checked(&e);
                            edit(&|x| x.tests = if on { TestsShown::Hidden } else { TestsShown::Shown });
                        } />
                    {move || c().tests_hidden}
                </label>
                <button type="button" data-testid="exercise-student-view"
                    on:click=move |_| ctx.cases.authoring.set(false)>{move || c().done_editing}</button>
            </div>
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_task_reads_as_paragraphs_lists_bold_and_code() {
        let task = "Light **Y00** while `X00` is on.\nKeep it simple.\n\n- one contact\n- one coil\nThen **check";
        assert_eq!(
            blocks(task),
            vec![
                Block::Para(vec![
                    Span::Text("Light ".into()),
                    Span::Bold("Y00".into()),
                    Span::Text(" while ".into()),
                    Span::Code("X00".into()),
                    Span::Text(" is on. Keep it simple.".into()),
                ]),
                Block::List(vec![
                    vec![Span::Text("one contact".into())],
                    vec![Span::Text("one coil".into())],
                ]),
                Block::Para(vec![Span::Text("Then **check".into())]),
            ]
        );
    }

    #[test]
    fn markup_in_a_task_stays_text() {
        assert_eq!(
            spans("<img src=x onerror=alert(1)> ✓"),
            vec![Span::Text("<img src=x onerror=alert(1)> ✓".into())]
        );
        assert_eq!(blocks("\n\n"), vec![]);
    }

    #[test]
    fn a_verdict_names_each_failing_case_with_its_hint_never_an_error() {
        let case = |name: &str, hint: &str| TestCase {
            name: name.into(),
            hint: hint.into(),
            ..TestCase::default()
        };
        let cases = [case("a", "hold it"), case("b", ""), case("c", "x")];
        let results = vec![
            Some(CaseResult::Fail("Y00 was 0 at 100ms".into())),
            Some(CaseResult::Pass),
            Some(CaseResult::Error("events line 1: unknown device".into())),
        ];
        let v = verdict(&cases, &results);
        assert_eq!((v.passed, v.total), (1, 3));
        assert_eq!(
            v.failures,
            vec![("a".into(), "hold it".into()), ("c".into(), "x".into())]
        );
    }
}
