//! The plants' alarms by kind (issue #52): each plant raises its alarm as
//! an [`AlarmKind`], whose `Display` is the message the command line and
//! the logs say (`alarm: TIME: NAME: message`). The page reads a message
//! back with [`AlarmKind::parse`] to say it in Japanese from its kind and
//! numbers (app/src/i18n/plant_said.rs), as it does the engine's errors.

use std::fmt;

/// What a plant did wrong, with the numbers its message says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlarmKind {
    /// The conveyor's belt started `since` ms after a part arrived, less
    /// than `guard` ms.
    BeltTooSoon {
        /// ms from the arrival to the start.
        since: i64,
        /// The least wait (`conveyor.guard`).
        guard: i64,
    },
    /// The tank's fill valve is open and the tank is full.
    Overflow,
    /// The cars have green (else yellow) while pedestrians have walk.
    CarsOnWalk {
        /// Green; else yellow.
        green: bool,
    },
    /// The door's motor is driven up and down at once.
    BothWays,
    /// The door's motor drives up against the top limit switch (else
    /// down against the bottom one) for more than `grace` ms.
    AgainstLimit {
        /// Up against the top; else down against the bottom.
        up: bool,
        /// The reaction time allowed (`door.grace`).
        grace: i64,
    },
    /// The door closes while the photo-eye is blocked, for more than
    /// `grace` ms.
    ClosingOnEye {
        /// The reaction time allowed (`door.grace`).
        grace: i64,
    },
    /// The sorter's pusher hit a tall (else short) part mid-stroke.
    PusherHit {
        /// The part was tall; else short.
        tall: bool,
    },
}

impl fmt::Display for AlarmKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            AlarmKind::BeltTooSoon { since, guard } => write!(
                f,
                "the belt started {since} ms after a part arrived at the infeed (less than {guard} ms: dangerous)"
            ),
            AlarmKind::Overflow => {
                f.write_str("overflow: the fill valve is open and the tank is full")
            }
            AlarmKind::CarsOnWalk { green } => write!(
                f,
                "cars have {} while pedestrians have walk: danger on the crossing",
                if green { "green" } else { "yellow" }
            ),
            AlarmKind::BothWays => f.write_str("the motor is driven up and down at once"),
            AlarmKind::AgainstLimit { up, grace } => {
                let (way, limit) = if up { ("up", "top") } else { ("down", "bottom") };
                write!(
                    f,
                    "the motor drives {way} against the {limit} limit switch for more than {grace} ms"
                )
            }
            AlarmKind::ClosingOnEye { grace } => write!(
                f,
                "the door closes while the photo-eye is blocked, for more than {grace} ms"
            ),
            AlarmKind::PusherHit { tall } => write!(
                f,
                "the pusher hit a {} part mid-stroke (it was not fully in front of the face)",
                if tall { "tall" } else { "short" }
            ),
        }
    }
}

impl AlarmKind {
    /// Every kind once (each flag both ways), with numbers as a plant
    /// says them: what the tests of the messages and of their
    /// translations (the page's Japanese) go through, one list for both.
    pub const SAMPLES: [AlarmKind; 10] = [
        AlarmKind::BeltTooSoon {
            since: 301,
            guard: 1000,
        },
        AlarmKind::Overflow,
        AlarmKind::CarsOnWalk { green: true },
        AlarmKind::CarsOnWalk { green: false },
        AlarmKind::BothWays,
        AlarmKind::AgainstLimit {
            up: true,
            grace: 200,
        },
        AlarmKind::AgainstLimit {
            up: false,
            grace: 0,
        },
        AlarmKind::ClosingOnEye { grace: 200 },
        AlarmKind::PusherHit { tall: true },
        AlarmKind::PusherHit { tall: false },
    ];

    /// The kind of an alarm's message, as `Display` said it; `None` for
    /// words no plant says.
    pub fn parse(message: &str) -> Option<AlarmKind> {
        let candidates = [
            AlarmKind::Overflow,
            AlarmKind::BothWays,
            AlarmKind::CarsOnWalk { green: true },
            AlarmKind::CarsOnWalk { green: false },
            AlarmKind::PusherHit { tall: true },
            AlarmKind::PusherHit { tall: false },
        ];
        if let Some(kind) = candidates.into_iter().find(|k| k.to_string() == message) {
            return Some(kind);
        }
        let number = |text: &str| text.parse::<i64>().ok();
        if let Some(rest) = between(message, "the belt started ", " ms: dangerous)") {
            let (since, guard) =
                rest.split_once(" ms after a part arrived at the infeed (less than ")?;
            let kind = AlarmKind::BeltTooSoon {
                since: number(since)?,
                guard: number(guard)?,
            };
            return Some(kind);
        }
        for (up, head) in [
            (
                true,
                "the motor drives up against the top limit switch for more than ",
            ),
            (
                false,
                "the motor drives down against the bottom limit switch for more than ",
            ),
        ] {
            if let Some(grace) = between(message, head, " ms") {
                let grace = number(grace)?;
                return Some(AlarmKind::AgainstLimit { up, grace });
            }
        }
        let head = "the door closes while the photo-eye is blocked, for more than ";
        let grace = number(between(message, head, " ms")?)?;
        Some(AlarmKind::ClosingOnEye { grace })
    }
}

/// What lies between `head` and `tail` in `text`, when it begins and ends so.
fn between<'a>(text: &'a str, head: &str, tail: &str) -> Option<&'a str> {
    text.strip_prefix(head)?.strip_suffix(tail)
}

#[cfg(test)]
mod tests {
    use super::AlarmKind;

    #[test]
    fn every_kind_reads_back_from_its_message() {
        for kind in AlarmKind::SAMPLES {
            assert_eq!(AlarmKind::parse(&kind.to_string()), Some(kind), "{kind}");
        }
        for other in [
            "",
            "overflow",
            "the belt started x ms after a part arrived at the infeed (less than 1 ms: dangerous)",
        ] {
            assert_eq!(AlarmKind::parse(other), None, "{other}");
        }
    }
}
