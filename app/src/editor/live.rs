//! Running the drawn ladder: Run writes it to the machine and starts it;
//! Step scan, Step instruction and (MINASEC-U) Step clock advance it by
//! hand, paused; the watch table shows chosen devices live. Contacts and
//! coils show their device's state (`data-on`), and every cell the power
//! the machine computed for it in its last scan (`data-powered`, from its
//! trace through the compiler's source map: `engine::ladder::live`).

use engine::ladder::edit::device_names;
use engine::plc::Command;
use leptos::prelude::*;

use super::LadderCtx;

/// Run: writes the drawing to the machine and starts it (RUN, simulated
/// time going); whether it could (else the problems are said). Write to
/// PLC is the same action.
/// A machine still on its way (its part, issue #53) runs the drawing
/// when it arrives.
pub fn run_drawing(ctx: LadderCtx) -> bool {
    if !ctx.attached() {
        ctx.when_attached(move || {
            run_drawing(ctx);
        });
        return true;
    }
    let t = ctx.page.lang.get_untracked().texts();
    if !ctx.write_drawing() {
        ctx.panes.message.set(Some(t.run_needs_compile.to_string()));
        // Where the problems are said, each at its cell.
        ctx.page.docks.show(crate::docks::Tool::Listing);
        return false;
    }
    ctx.live.unwritten.set(false);
    ctx.operate(|plc: &mut dyn engine::plc::Plc| {
        plc.set_tracing(true);
        let _ = plc.apply(Command::Run(true));
    });
    ctx.page.paused.set(false);
    true
}

/// [`run_drawing`] for a button outside the run bar.
pub fn run_action(ctx: LadderCtx) -> impl Fn() -> bool + Copy {
    move || run_drawing(ctx)
}

/// After a single instruction was stepped: which step ran, its rung, and
/// the element it came from (marked on the ladder).
pub fn show_stepped(ctx: LadderCtx, stepped: Option<usize>) {
    let rung = stepped.and_then(|s| {
        ctx.drawing
            .listing
            .with_untracked(|l| l.as_ref().and_then(|l| l.rung_of_step(s)))
    });
    ctx.live.stepped.set(stepped.map(|s| (s, rung)));
    ctx.live
        .stepped_cell
        .set(stepped.and_then(|s| ctx.cell_of_step(s)));
}

/// What the run means for the drawing: not written to the machine yet,
/// the step the last single step ran. The run controls themselves are the
/// app bar's (`crate::appbar::run`).
#[component]
pub fn RunStatus(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    view! {
        <span class="run-status">
            <span class="not-written" data-testid="not-written" role="status"
                hidden=move || !ctx.live.unwritten.get()>{move || t().not_written}</span>
            <span data-testid="step-at">{move || ctx.live.stepped.get().map(|(s, rung)| match rung {
                Some(r) => format!("{} {s} · {} {}", t().step, t().rung, r + 1),
                None => format!("{} {s}", t().step),
            })}</span>
        </span>
    }
}

/// `[data-testid=watch]`: devices by name, with their live values (a
/// timer's or counter's current value in brackets).
#[component]
pub fn WatchTable(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let name = RwSignal::new(String::new());
    let names = device_names(ctx.machine);
    let add = move || {
        let n = name.get_untracked().trim().to_string();
        if n.is_empty() {
            return;
        }
        if ctx.live.watch.with_untracked(|w| w.contains(&n)) {
            return;
        }
        ctx.live.watch.update(|w| w.push(n));
        name.set(String::new());
    };
    let list_id = format!("watch-names-{}", ctx.machine.name());
    // The coupled plant's names (`conveyor.motor`), offered as the
    // machine's devices are; changed only when the plant does.
    let plant = use_context::<crate::rig::ShownPlant>();
    let plant_names = Memo::new(move |_| {
        let shown = plant.map(|p| {
            p.0.with(|s| s.as_ref().map(crate::rig::Shown::device_names))
        });
        shown.flatten().unwrap_or_default()
    });
    view! {
        <section class="watch-pane">
            <h3>{move || t().watch}</h3>
            <div class="find-row">
                <input data-testid="watch-input" list=list_id.clone() spellcheck="false" aria-label=move || t().watch
                    prop:value=move || name.get() on:input=move |e| name.set(event_target_value(&e))
                    on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Enter" { add() } />
                <datalist id=list_id>
                    {names.into_iter().map(|n| view! { <option value=n></option> }).collect_view()}
                    {move || plant_names.get().into_iter().map(|n| view! { <option value=n></option> }).collect_view()}
                </datalist>
                <button type="button" data-testid="watch-add" on:click=move |_| add()>"+"</button>
            </div>
            <table class="watch" data-testid="watch">
                <tbody>
                    {move || {
                        let values = ctx.live.watch_values.get();
                        ctx.live.watch.get().into_iter().enumerate().map(|(i, n)| {
                            let v = values.get(i).cloned().unwrap_or_default();
                            let gone = n.clone();
                            view! {
                                <tr data-testid=format!("watch-{n}")>
                                    <th>{n.clone()}</th>
                                    <td class="watch-value">{v}</td>
                                    <td><button type="button" on:click=move |_| ctx.live.watch.update(|w| { w.retain(|x| *x != gone); })>"×"</button></td>
                                </tr>
                            }
                        }).collect_view()
                    }}
                </tbody>
            </table>
        </section>
    }
}

/// A click on a contact while the machine runs the drawn ladder: its
/// device, when the machine takes it as an input, toggles (held until
/// released from the force list); with Shift it is on for one scan.
pub fn drive_from_ladder(ctx: LadderCtx, device: &str, pulse: bool) {
    let t = ctx.page.lang.get_untracked().texts();
    let mut refused = None;
    let mut held = None;
    ctx.operate(|plc| {
        let Ok(d) = plc.device(device) else {
            return;
        };
        let on = engine::events::InputValue::Int(1);
        if let Err(e) = plc.check_input(d, on) {
            refused = Some(crate::i18n::errors::plc_error(
                ctx.page.lang.get_untracked(),
                &e,
            ));
            return;
        }
        if pulse {
            let off = engine::events::InputValue::Int(0);
            let _ = plc.apply(Command::SetInput(d, on));
            plc.step_scan();
            let _ = plc.apply(Command::SetInput(d, off));
            held = Some(false);
        } else {
            let now = plc.read(d).is_on();
            let value = engine::events::InputValue::Int(i64::from(!now));
            let _ = plc.apply(Command::SetInput(d, value));
            held = Some(!now);
        }
    });
    if let Some(why) = refused {
        ctx.panes
            .message
            .set(Some(format!("{device}: {why} ({})", t.not_an_input)));
        return;
    }
    if let Some(value) = held {
        ctx.live.forced.update(|f| {
            f.retain(|(d, _)| d != device);
            f.push((device.to_string(), value));
        });
    }
}

/// `[data-testid=forces]`: the inputs held from the ladder, each with
/// its value and a release.
#[component]
pub fn ForceList(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let release = move |device: String| {
        ctx.operate(|plc| {
            if let Ok(d) = plc.device(&device) {
                let _ = plc.apply(Command::ReleaseInput(d));
            }
        });
        ctx.live.forced.update(|f| f.retain(|(d, _)| *d != device));
    };
    view! {
        <section class="forces-pane" data-testid="forces">
            <h3>{move || t().forces}</h3>
            <ul>
                {move || ctx.live.forced.get().into_iter().map(|(device, value)| {
                    let d = device.clone();
                    view! {
                        <li data-testid=format!("force-{device}")>
                            <b>{device.clone()}</b> " = " {u8::from(value)} " "
                            <button type="button" data-testid="force-release" on:click=move |_| release(d.clone())>
                                {move || t().release}
                            </button>
                        </li>
                    }
                }).collect_view()}
            </ul>
        </section>
    }
}
