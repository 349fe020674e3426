//! The Tests pane (issue #17, docs/tests.md): the project's cases, edited
//! in place, run each on a fresh machine as fast as the engine goes, with
//! pass / fail per case; a timeline recorded from the inputs the user
//! changes while the machine runs; the exercise flag that makes a share
//! link open with the tests shown.

use engine::cases::TestCase;
use engine::ladder::Ladder;
use engine::plc::{Device, Plc};
use engine::SimTime;
use leptos::prelude::*;

pub use super::runner::run_all;
use crate::editor::state::{CaseResult, LadderCtx};

/// Records the inputs a user changes while the machine runs: the devices
/// the ladder's contacts read and no output writes, read each frame, each
/// change timed at the frame the machine first shows it (after its input
/// filter, where it has one).
#[derive(Clone, Debug)]
pub struct Recorder {
    start: SimTime,
    inputs: Vec<(String, Device, i64)>,
    outputs: Vec<(String, Device)>,
    events: Vec<(SimTime, String, i64)>,
}

impl Recorder {
    /// Starts recording on `plc` for `ladder`'s devices; inputs already
    /// on are the timeline's first events.
    pub fn new(ladder: &Ladder, plc: &dyn Plc) -> Recorder {
        let mut read = Vec::new();
        let mut written = Vec::new();
        for (_, e) in ladder.rungs.iter().flat_map(|r| r.elements()) {
            if let Some(d) = e.read_device() {
                read.push(d.to_string());
            }
            if let Some(d) = e.written_device() {
                written.push(d.to_string());
            }
        }
        engine::sort::all(&mut read);
        read.dedup();
        engine::sort::all(&mut written);
        written.dedup();
        let resolve = |name: &String| plc.device(name).ok().map(|d| (name.clone(), d));
        let inputs: Vec<(String, Device, i64)> = read
            .iter()
            .filter(|d| !written.contains(d))
            .filter_map(resolve)
            .map(|(n, d)| (n, d, 0))
            .collect();
        let mut r = Recorder {
            start: plc.now(),
            inputs,
            outputs: written.iter().filter_map(resolve).collect(),
            events: Vec::new(),
        };
        r.observe(plc);
        r
    }

    /// Notes every input whose value changed since the last look.
    pub fn observe(&mut self, plc: &dyn Plc) {
        let t = SimTime::from_nanos(plc.now().as_nanos().saturating_sub(self.start.as_nanos()));
        for (name, device, last) in &mut self.inputs {
            let value = plc.read(*device).as_i64();
            if value != *last {
                *last = value;
                self.events.push((t, name.clone(), value));
            }
        }
    }

    /// The recorded case: its timeline, and each output's value now as
    /// an expectation at this moment.
    pub fn finish(mut self, plc: &dyn Plc, name: &str) -> TestCase {
        self.observe(plc);
        let ms = |t: SimTime| t.as_nanos() / 1_000_000;
        let now = ms(SimTime::from_nanos(
            plc.now().as_nanos().saturating_sub(self.start.as_nanos()),
        ));
        TestCase {
            name: name.to_string(),
            events: self
                .events
                .iter()
                .map(|(t, d, v)| format!("{}ms,{d},{v}\n", ms(*t)))
                .collect(),
            expect: self
                .outputs
                .iter()
                // A STRING's text in quotes, so the expectation reads back.
                .map(|(d, device)| {
                    let want = engine::cases::Want::of(&plc.read(*device));
                    format!("{d} = {want} at {now}ms")
                })
                .collect(),
            hint: String::new(),
        }
    }
}

/// Changes case `i` (its result is forgotten) and saves.
fn edit_case(ctx: LadderCtx, i: usize, f: impl FnOnce(&mut TestCase)) {
    ctx.cases.tests.update(|tests| {
        if let Some(c) = tests.get_mut(i) {
            f(c);
        }
    });
    ctx.cases.results.update(|r| {
        if let Some(slot) = r.get_mut(i) {
            *slot = None;
        }
    });
    ctx.save();
}

/// Deletes case `i` and its result, and saves.
fn delete_case(ctx: LadderCtx, i: usize) {
    ctx.cases.tests.update(|v| {
        if i < v.len() {
            v.remove(i);
        }
    });
    ctx.cases.results.update(|r| {
        if i < r.len() {
            r.remove(i);
        }
    });
    ctx.save();
}

/// `[data-testid=tests]`: the author's tools, or an exercise's student
/// view; then the cases (read-only for the student, not there when the
/// author hid them).
#[component]
pub fn TestsPane(ctx: LadderCtx) -> impl IntoView {
    let c = move || ctx.page.lang.get().classroom();
    // Memoised: editing the task must not rebuild the tools under the
    // user's hands, only a switch between the two views.
    let student = Memo::new(move |_| ctx.student());
    let hidden = move || {
        student.get()
            && ctx
                .cases
                .exercise
                .with(|e| e.as_ref().is_some_and(|e| e.hidden()))
    };
    let cases = move || {
        if hidden() {
            Vec::new()
        } else {
            (0..ctx.cases.tests.with(Vec::len)).collect::<Vec<_>>()
        }
    };
    let count = move || {
        c().hidden_count
            .replace("{n}", &ctx.cases.tests.with(Vec::len).to_string())
    };
    view! {
        <section class="tests-pane" data-testid="tests" data-student=move || student.get().to_string()>
            {move || if student.get() {
                view! { <super::exercise::StudentView ctx check=Callback::new(move |()| run_all(ctx)) /> }.into_any()
            } else {
                view! {
                    <TestsBar ctx />
                    <Show when=move || ctx.cases.exercise.with(Option::is_some)>
                        <super::exercise::ExerciseEditor ctx />
                    </Show>
                }.into_any()
            }}
            <Show when=hidden>
                <p class="tests-hidden-note" data-testid="tests-hidden-note">{count}</p>
            </Show>
            <For each=cases key=|i| *i children=move |i| view! { <CaseView ctx i /> } />
        </section>
    }
}

/// Run, add, record, the exercise flag, the guide and the summary.
#[component]
fn TestsBar(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let c = move || ctx.page.lang.get().classroom();
    let recording = RwSignal::new(ctx.recording());
    let record = move |_| {
        if ctx.recording() {
            ctx.with_plc(|plc| ctx.stop_recording(plc));
        } else {
            ctx.with_plc(|plc| ctx.start_recording(plc));
        }
        recording.set(ctx.recording());
    };
    let add = move |_| {
        let n = ctx.cases.tests.with_untracked(Vec::len) + 1;
        let case = TestCase {
            name: ctx.page.lang.get_untracked().words().case_names[0]
                .replace("{n}", &n.to_string()),
            ..TestCase::default()
        };
        ctx.cases.tests.update(|v| v.push(case));
        ctx.save();
    };
    let summary = move || {
        ctx.cases.results.with(|r| {
            let pass = r.iter().filter(|x| **x == Some(CaseResult::Pass)).count();
            let run = r.iter().filter(|x| x.is_some()).count();
            if run == 0 {
                String::new()
            } else {
                format!("{pass} / {run} {}", t().passed)
            }
        })
    };
    // Turned on, the author writes the task at once.
    let toggle = move |_| {
        let on = ctx.cases.exercise.with_untracked(Option::is_none);
        ctx.cases.exercise.set(on.then(Default::default));
        ctx.cases.authoring.set(on);
        ctx.save();
    };
    let guide = move || format!("guide/{}.html#tests", ctx.page.lang.get().code());
    view! {
        <div class="find-row">
            <button type="button" data-testid="run-tests" on:click=move |_| run_all(ctx)>{move || t().run_tests}</button>
            <button type="button" data-testid="add-test" on:click=add>{move || t().add_test}</button>
            <button type="button" data-testid="record-test" aria-pressed=move || recording.get().to_string() on:click=record>
                {move || if recording.get() { t().record_stop } else { t().record_start }}
            </button>
            <label>
                <input type="checkbox" data-testid="exercise" prop:checked=move || ctx.cases.exercise.with(Option::is_some)
                    on:change=toggle />
                {move || t().exercise}
            </label>
            <a class="tests-guide" data-testid="tests-guide" href=guide target="_blank" rel="noopener">{move || c().guide}</a>
            <span data-testid="tests-summary">{summary}</span>
        </div>
    }
}

/// Case `i`: its name, timeline, expectations, hint and last result;
/// read-only in a student's view.
#[component]
fn CaseView(ctx: LadderCtx, i: usize) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let c = move || ctx.page.lang.get().classroom();
    let locked = move || ctx.student();
    let case = move || {
        ctx.cases
            .tests
            .with(|v| v.get(i).cloned().unwrap_or_default())
    };
    let result = move || ctx.cases.results.with(|r| r.get(i).cloned().flatten());
    let hook = move || match result() {
        Some(CaseResult::Pass) => "pass",
        Some(CaseResult::Fail(_) | CaseResult::Unused(_)) => "fail",
        Some(CaseResult::Error(_)) => "error",
        None => "",
    };
    let said = move || result().map(|r| said_of(ctx, &case(), r));
    let (events_error, expect_error) = (
        move || said().and_then(|s| s.1.then_some(s.0.clone())),
        move || said().and_then(|s| s.2.then_some(s.0.clone())),
    );
    let general = move || said().and_then(|s| (!s.1 && !s.2).then_some(s.0));
    let expectations = |text: String| -> Vec<String> {
        text.lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .map(String::from)
            .collect()
    };
    view! {
        <div class="test-case" data-testid=format!("test-case-{i}") data-result=hook>
            <div class="test-head">
                <input class="test-name" data-testid="test-name" aria-label=move || t().case_name prop:value=move || case().name
                    prop:readOnly=locked on:change=move |e| { let v = event_target_value(&e); edit_case(ctx, i, |c| c.name = v); } />
                <Show when=move || !locked()>
                    <button type="button" data-testid="test-delete" on:click=move |_| delete_case(ctx, i)>
                        {move || t().delete_test}
                    </button>
                </Show>
            </div>
            <div class="test-fields">
                <label class="test-field"><span>{move || t().timeline}</span>
                    <textarea data-testid="test-events" spellcheck="false" rows="5" prop:value=move || case().events
                        prop:readOnly=locked placeholder=move || c().events_placeholder
                        on:change=move |e| { let v = event_target_value(&e); edit_case(ctx, i, |c| c.events = v); } />
                    <span class="test-error" role="alert">{events_error}</span>
                </label>
                <label class="test-field"><span>{move || t().expectations}</span>
                    <textarea data-testid="test-expect" spellcheck="false" rows="5" prop:value=move || case().expect.join("\n")
                        prop:readOnly=locked placeholder=move || c().expect_placeholder
                        on:change=move |e| { let v = expectations(event_target_value(&e)); edit_case(ctx, i, |c| c.expect = v); } />
                    <span class="test-error" role="alert">{expect_error}</span>
                </label>
            </div>
            <Show when=move || !locked()>
                <label class="test-field test-hint"><span>{move || c().hint}</span>
                    <input data-testid="test-hint" prop:value=move || case().hint placeholder=move || c().hint_placeholder
                        on:change=move |e| { let v = event_target_value(&e); edit_case(ctx, i, |c| c.hint = v); } />
                </label>
            </Show>
            <div class="test-result" data-testid="test-result">{general}</div>
        </div>
    }
}

/// What a case's result says, and whether it is about the timeline's box
/// or the expectations' (shown under that box, naming its line). A
/// student is told the case's hint, never the author's error.
fn said_of(ctx: LadderCtx, case: &TestCase, result: CaseResult) -> (String, bool, bool) {
    let lang = ctx.page.lang.get();
    let (t, c) = (lang.texts(), lang.classroom());
    match result {
        CaseResult::Pass => (c.pass.to_string(), false, false),
        CaseResult::Fail(why) => {
            let why = why.in_lang(lang);
            (format!("{}: {why}", t.test_fail), false, false)
        }
        CaseResult::Unused(device) => (
            format!(
                "{}: {}",
                t.test_fail,
                c.unused_device.replace("{device}", &device)
            ),
            false,
            false,
        ),
        CaseResult::Error(_) if ctx.student() => {
            let hint = if case.hint.is_empty() {
                c.no_hint
            } else {
                case.hint.as_str()
            };
            (format!("{}: {hint}", t.test_fail), false, false)
        }
        CaseResult::Error(why) => {
            // Which box it is about, from the engine's words.
            let events = why.en.starts_with("events line");
            let expect = why.en.starts_with("expectation ");
            (why.in_lang(lang).to_string(), events, expect)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::editor::panes::runner::run_cases;
    use crate::i18n::errors::Both;
    use engine::events::InputValue;
    use engine::ladder::compile::{compile, Options};
    use engine::ladder::{Element, Rung};
    use engine::machines::new_plc;
    use engine::plc::Command;
    use engine::MachineId;

    fn self_hold() -> Ladder {
        Ladder {
            rungs: vec![Rung {
                cells: vec![
                    vec![
                        Some(Element::no("X00")),
                        Some(Element::nc("X01")),
                        Some(Element::coil("Y00")),
                    ],
                    vec![Some(Element::no("Y00"))],
                ],
                links: vec![engine::ladder::Link { row: 0, col: 1 }],
                ..Rung::default()
            }],
            ..Ladder::default()
        }
    }

    #[test]
    fn a_recorded_timeline_replays_to_the_same_outputs() {
        let ladder = self_hold();
        let program = compile(&ladder, MachineId::Io86a, Options::default()).expect("compiles");
        let mut plc = new_plc(MachineId::Io86a);
        plc.load_text(&program).expect("loads");
        plc.run_until(SimTime::from_millis(100));
        let mut rec = Recorder::new(&ladder, plc.as_ref());
        let press = |plc: &mut Box<dyn Plc>, name: &str, on: bool| {
            let d = plc.device(name).expect("device");
            plc.apply(Command::SetInput(d, InputValue::Int(i64::from(on))))
                .expect("input");
        };
        for (at, name, on) in [
            (300, "X00", true),
            (450, "X00", false),
            (900, "X01", true),
            (1000, "X01", false),
        ] {
            plc.run_until(SimTime::from_millis(100 + at));
            press(&mut plc, name, on);
            // A few frames later: the IO86A filters its inputs for ~20 ms.
            plc.run_until(SimTime::from_millis(150 + at));
            rec.observe(plc.as_ref());
        }
        plc.run_until(SimTime::from_millis(1500));
        let case = rec.finish(plc.as_ref(), "recorded");
        assert_eq!(
            case.events,
            "350ms,X00,1\n500ms,X00,0\n950ms,X01,1\n1050ms,X01,0\n"
        );
        assert_eq!(case.expect, vec!["Y00 = 0 at 1400ms".to_string()]);
        let results = run_cases(MachineId::Io86a, &[], &program, std::slice::from_ref(&case));
        assert_eq!(results, vec![CaseResult::Pass]);
        // Replayed, the hold is there between the presses, and gone after.
        let mut held = case.clone();
        held.expect = vec!["Y00 stays 1 from 550ms to 950ms".into()];
        let mut wrong = case;
        wrong.expect = vec!["Y00 = 1 at 1200ms".into()];
        let results = run_cases(MachineId::Io86a, &[], &program, &[held, wrong]);
        assert_eq!(results[0], CaseResult::Pass);
        let failed = Both {
            en: "Y00 = 1 at 1200ms: Y00 was 0 at 1200ms".into(),
            ja: "Y00 = 1 at 1200ms: Y00 は 1200ms に 0 でした".into(),
        };
        assert_eq!(results[1], CaseResult::Fail(failed), "in both languages");
    }

    #[test]
    fn a_device_an_empty_soft_plc_ladder_lacks_is_a_failure_not_an_error() {
        let program = compile(&Ladder::default(), MachineId::SoftPlc, Options::default())
            .expect("an empty ladder compiles");
        let case = |events: &str, expect: &str| TestCase {
            name: "lights".into(),
            events: events.into(),
            expect: vec![expect.into()],
            hint: String::new(),
        };
        let results = run_cases(
            MachineId::SoftPlc,
            &[],
            &program,
            &[
                case("0ms,%IX0.0,1\n", "%QX0.0 = 1 at 100ms"),
                case("", "%QX0.0 = 1 at 100ms"),
            ],
        );
        assert_eq!(
            results,
            vec![
                CaseResult::Unused("%IX0.0".into()),
                CaseResult::Unused("%QX0.0".into())
            ]
        );
        // On a machine with fixed devices a name it lacks is the author's.
        let io = run_cases(
            MachineId::Io86a,
            &[],
            "END\n",
            &[case("0ms,X99,1\n", "Y00 = 1 at 1s")],
        );
        assert!(
            matches!(&io[0], CaseResult::Error(e) if e.en.contains("X99")),
            "{io:?}"
        );
    }

    #[test]
    fn tests_past_the_work_limit_run_none_and_say_so() {
        let program = "LD X00\nOUT Y00\nEND\n";
        let long = |from: u32| TestCase {
            name: format!("from {from}"),
            events: String::new(),
            expect: vec![format!("Y00 stays 0 from {from}ms to 9000s")],
            hint: String::new(),
        };
        // Each alone is within the limit; all of them together are not.
        let one = run_cases(MachineId::Io86a, &[], program, &[long(0)]);
        assert_eq!(one, vec![CaseResult::Pass]);
        let many: Vec<TestCase> = (0..20).map(long).collect();
        let results = run_cases(MachineId::Io86a, &[], program, &many);
        assert_eq!(results.len(), 20);
        assert!(results.iter().all(|r| matches!(
            r,
            CaseResult::Error(e) if e.en.contains("more than 100000000 samples")
        )));
    }
}
