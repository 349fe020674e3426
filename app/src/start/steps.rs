//! The guided first rung's steps and their checks, as plain data over the
//! engine's ladder (tested natively): what the user has drawn, and what the
//! running machine shows. The tour view only asks these.

use engine::ladder::target::capabilities;
use engine::ladder::{CoilKind, ContactKind, Element, Ladder, Net};
use engine::MachineId;

/// A step of the tour, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Step {
    /// What the tour is about; Next begins.
    Intro,
    /// A normally open contact on the start input.
    Contact,
    /// A normally closed contact on the stop input.
    Stop,
    /// The coil.
    Coil,
    /// The output's own contact in parallel with the start input.
    Hold,
    /// Run pressed.
    Run,
    /// The start input on, the output on.
    Press,
    /// The start input off again, the output still on.
    Release,
    /// The stop input on, the output off.
    Halt,
    /// All done.
    Done,
}

impl Step {
    /// Every step, in order.
    pub const ALL: [Step; 10] = [
        Step::Intro,
        Step::Contact,
        Step::Stop,
        Step::Coil,
        Step::Hold,
        Step::Run,
        Step::Press,
        Step::Release,
        Step::Halt,
        Step::Done,
    ];

    /// Its place in [`Step::ALL`] (the texts' index).
    pub fn index(self) -> usize {
        Step::ALL.iter().position(|s| *s == self).unwrap_or(0)
    }

    /// Its name in `data-step`.
    pub const fn hook(self) -> &'static str {
        match self {
            Step::Intro => "intro",
            Step::Contact => "contact",
            Step::Stop => "stop",
            Step::Coil => "coil",
            Step::Hold => "hold",
            Step::Run => "run",
            Step::Press => "press",
            Step::Release => "release",
            Step::Halt => "halt",
            Step::Done => "done",
        }
    }

    /// The step after this one (the last stays).
    pub fn next(self) -> Step {
        Step::ALL
            .get(self.index() + 1)
            .copied()
            .unwrap_or(Step::Done)
    }

    /// A drawing step: the user edits the ladder.
    pub fn draws(self) -> bool {
        matches!(self, Step::Contact | Step::Stop | Step::Coil | Step::Hold)
    }
}

/// The machine's start input, stop input and output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Devices {
    pub start: String,
    pub stop: String,
    pub out: String,
}

impl Devices {
    /// `machine`'s first two inputs and first output.
    pub fn of(machine: MachineId) -> Devices {
        let [start, stop, out] = capabilities(machine).starter;
        Devices {
            start: start.to_string(),
            stop: stop.to_string(),
            out: out.to_string(),
        }
    }

    /// `text` with `{0}`, `{1}`, `{2}` replaced by the devices.
    pub fn fill(&self, text: &str) -> String {
        text.replace("{0}", &self.start)
            .replace("{1}", &self.stop)
            .replace("{2}", &self.out)
    }
}

/// What the running machine shows, for the steps after drawing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Running {
    /// Run is pressed and the machine runs the drawing.
    pub running: bool,
    pub start_on: bool,
    pub stop_on: bool,
    pub out_on: bool,
}

/// Whether a drawn device is one the tour asks for. The editor keeps
/// every device in the machine's own spelling (`target::check_element`),
/// so names compare as text, case aside.
fn same(drawn: &str, wanted: &str) -> bool {
    drawn.eq_ignore_ascii_case(wanted)
}

/// Whether `step` is done, given the ladder as drawn and the machine.
pub fn done(step: Step, machine: MachineId, ladder: &Ladder, now: Running) -> bool {
    let d = Devices::of(machine);
    let has = |want: &dyn Fn(&Element) -> bool| {
        ladder
            .rungs
            .iter()
            .any(|r| r.elements().any(|(_, e)| want(e)))
    };
    match step {
        Step::Intro | Step::Done => false,
        Step::Contact => has(
            &|e| matches!(e, Element::Contact { kind: ContactKind::No, device } if same(device, &d.start)),
        ),
        Step::Stop => has(
            &|e| matches!(e, Element::Contact { kind: ContactKind::Nc, device } if same(device, &d.stop)),
        ),
        Step::Coil => has(
            &|e| matches!(e, Element::Coil { kind: CoilKind::Normal, device } if same(device, &d.out)),
        ),
        Step::Hold => holds(machine, ladder, &d),
        Step::Run => now.running,
        Step::Press => now.running && now.start_on && now.out_on,
        Step::Release => now.running && !now.start_on && now.out_on,
        Step::Halt => now.running && now.stop_on && !now.out_on,
    }
}

/// The cell under the start contact, where the self-hold's branch goes
/// (the tour puts the cursor there when it asks for it).
pub fn under_start(machine: MachineId, ladder: &Ladder) -> Option<engine::ladder::edit::Cursor> {
    let d = Devices::of(machine);
    ladder.rungs.iter().enumerate().find_map(|(r, rung)| {
        rung.elements().find_map(|(at, e)| match e {
            Element::Contact {
                kind: ContactKind::No,
                device,
            } if same(device, &d.start) => {
                Some(engine::ladder::edit::Cursor::new(r, at.row + 1, at.col))
            }
            _ => None,
        })
    })
}

/// Whether the ladder holds a start/stop self-hold: a rung whose coil is
/// the output and whose contacts, on the start, the stop and the output
/// only, conduct exactly when (start or output) and not stop. Judged by
/// the rung's truth table, so any drawing that behaves so counts.
pub fn holds(machine: MachineId, ladder: &Ladder, d: &Devices) -> bool {
    let Ok(rungs) = ladder.logic(machine) else {
        return false;
    };
    rungs.iter().any(|rung| {
        let drives = rung.outputs.iter().any(|(e, _)| {
            matches!(e, Element::Coil { kind: CoilKind::Normal, device } if same(device, &d.out))
        });
        drives
            && (0..8u8).all(|bits| {
                let (start, stop, out) = (bits & 1 != 0, bits & 2 != 0, bits & 4 != 0);
                let value = |device: &str| {
                    if same(device, &d.start) {
                        Some(start)
                    } else if same(device, &d.stop) {
                        Some(stop)
                    } else if same(device, &d.out) {
                        Some(out)
                    } else {
                        None
                    }
                };
                conducts(&rung.condition, &value) == Some((start || out) && !stop)
            })
    })
}

/// Whether `net` conducts with the devices at `value`; `None` when it
/// holds anything but contacts on those devices.
fn conducts(net: &Net, value: &dyn Fn(&str) -> Option<bool>) -> Option<bool> {
    match net {
        Net::Leaf(Element::Contact { kind, device }, _) => match kind {
            ContactKind::No => value(device),
            ContactKind::Nc => value(device).map(|on| !on),
            _ => None,
        },
        Net::Leaf(..) => None,
        Net::Series(parts) => parts
            .iter()
            .try_fold(true, |all, p| Some(conducts(p, value)? && all)),
        Net::Parallel(parts) => parts
            .iter()
            .try_fold(false, |any, p| Some(conducts(p, value)? || any)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::ladder::edit::{Cursor, Edit, Editor};

    fn drawn(edits: &[(Cursor, Element, bool)]) -> Ladder {
        let mut editor = Editor::new(Ladder::default());
        for (at, element, branch) in edits {
            let (at, element) = (*at, element.clone());
            let edit = if *branch {
                Edit::PlaceBranch { at, element }
            } else {
                Edit::Place { at, element }
            };
            editor.apply(edit).expect("the edit applies");
        }
        editor.ladder().clone()
    }

    fn self_hold(machine: MachineId, with_branch: bool) -> Ladder {
        let d = Devices::of(machine);
        let mut edits = vec![
            (Cursor::new(0, 0, 0), Element::no(&d.start), false),
            (Cursor::new(0, 0, 1), Element::nc(&d.stop), false),
            (Cursor::new(0, 0, 2), Element::coil(&d.out), false),
        ];
        if with_branch {
            edits.push((Cursor::new(0, 1, 0), Element::no(&d.out), true));
        }
        drawn(&edits)
    }

    #[test]
    fn every_machine_draws_and_checks_the_self_hold() {
        let idle = Running::default();
        for machine in MachineId::ALL {
            let ladder = self_hold(machine, true);
            for step in [Step::Contact, Step::Stop, Step::Coil, Step::Hold] {
                assert!(done(step, machine, &ladder, idle), "{machine:?} {step:?}");
            }
        }
    }

    #[test]
    fn the_branch_goes_under_the_start_contact() {
        let m = MachineId::Io86a;
        let ladder = drawn(&[
            (Cursor::new(0, 0, 0), Element::no("X05"), false),
            (Cursor::new(1, 0, 0), Element::nc("X01"), false),
            (Cursor::new(1, 0, 1), Element::no("X00"), false),
        ]);
        assert_eq!(under_start(m, &ladder), Some(Cursor::new(1, 1, 1)));
        assert_eq!(under_start(m, &Ladder::default()), None);
    }

    #[test]
    fn a_rung_without_the_branch_does_not_hold() {
        for machine in MachineId::ALL {
            let ladder = self_hold(machine, false);
            assert!(done(Step::Coil, machine, &ladder, Running::default()));
            assert!(
                !done(Step::Hold, machine, &ladder, Running::default()),
                "{machine:?}"
            );
        }
    }

    #[test]
    fn a_branch_around_the_stop_contact_does_not_hold() {
        let m = MachineId::MinasecU;
        let ladder = drawn(&[
            (Cursor::new(0, 0, 0), Element::no("X00"), false),
            (Cursor::new(0, 0, 1), Element::nc("X01"), false),
            (Cursor::new(0, 0, 2), Element::coil("Y00"), false),
            (Cursor::new(0, 1, 1), Element::no("Y00"), true),
        ]);
        assert!(done(Step::Coil, m, &ladder, Running::default()));
        assert!(!done(Step::Hold, m, &ladder, Running::default()));
    }

    #[test]
    fn a_contact_of_the_wrong_kind_or_device_is_not_the_step() {
        let m = MachineId::MinasecU;
        let nc_start = drawn(&[(Cursor::new(0, 0, 0), Element::nc("X00"), false)]);
        assert!(!done(Step::Contact, m, &nc_start, Running::default()));
        let other = drawn(&[(Cursor::new(0, 0, 0), Element::no("X02"), false)]);
        assert!(!done(Step::Contact, m, &other, Running::default()));
        let empty = Ladder::default();
        assert!(!done(Step::Contact, m, &empty, Running::default()));
    }

    #[test]
    fn the_running_steps_follow_the_inputs_and_the_output() {
        let m = MachineId::MinasecU;
        let l = Ladder::default();
        let pressed = Running {
            running: true,
            start_on: true,
            stop_on: false,
            out_on: true,
        };
        assert!(done(Step::Press, m, &l, pressed));
        assert!(!done(Step::Release, m, &l, pressed));
        let held = Running {
            start_on: false,
            ..pressed
        };
        assert!(done(Step::Release, m, &l, held));
        let stopped = Running {
            stop_on: true,
            out_on: false,
            ..held
        };
        assert!(done(Step::Halt, m, &l, stopped));
        assert!(!done(Step::Run, m, &l, Running::default()));
    }

    #[test]
    fn steps_run_in_order_and_end_at_done() {
        assert_eq!(Step::Intro.next(), Step::Contact);
        assert_eq!(Step::Halt.next(), Step::Done);
        assert_eq!(Step::Done.next(), Step::Done);
        let d = Devices::of(MachineId::AvrPlc);
        assert_eq!(d.fill("{0}/{1}/{2}"), "R0.0/R0.1/R1.0");
    }
}
