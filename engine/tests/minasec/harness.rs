//! Helpers shared by the MINASEC-U tests.

use engine::minasec::control::FAST_PERIOD;
use engine::minasec::{Address, Command, Machine, Mode, Program, TimerId};
use engine::SimTime;

/// One scan at FAST: 256 × 33 µs.
pub const SCAN: SimTime = SimTime::from_nanos(256 * 33_000);

/// Parses a listing that the test knows is good.
pub fn program(text: &str) -> Program {
    Program::parse(text).unwrap_or_else(|e| panic!("test program does not parse: {e:?}"))
}

/// A powered machine at RUN/FAST from t = 0 with `text` loaded.
pub fn running(text: &str) -> Machine {
    let mut m = Machine::for_run();
    m.load(&program(text));
    m
}

/// Like [`running`], but halted, for stepping with the CLOCK button.
pub fn halted(text: &str) -> Machine {
    let mut m = Machine::new();
    m.load(&program(text));
    m
}

/// Applies a command that the test knows is valid.
pub fn apply(m: &mut Machine, command: Command) {
    m.apply(command)
        .unwrap_or_else(|e| panic!("{command:?} was rejected: {e}"));
}

/// Sets input terminal `X0n`.
pub fn input(m: &mut Machine, n: u8, on: bool) {
    apply(m, Command::SetInput(n, on));
}

/// Presses and releases CLOCK `n` times (the machine must be at HALT).
pub fn clocks(m: &mut Machine, n: usize) {
    for _ in 0..n {
        apply(m, Command::ClockButton(true));
        apply(m, Command::ClockButton(false));
    }
}

/// The address named `name`.
pub fn addr(name: &str) -> Address {
    Address::parse(name).unwrap_or_else(|e| panic!("{e}"))
}

/// The output terminal `Y0n`.
pub fn lamp(m: &Machine, n: u8) -> bool {
    m.output_terminals() >> n & 1 != 0
}

/// The rising edge of step `k` of scan `s` (both from 0) on a machine set
/// to RUN at t = 0: the clock starts low, so the first rise is half a
/// period in.
pub fn rise(s: u64, k: u64) -> SimTime {
    let p = FAST_PERIOD.as_nanos();
    SimTime::from_nanos(s * 256 * p + p - p / 2 + k * p)
}

/// The seed test program's machine with the book's panel settings:
/// RV1 at 1.1 s, RV2 at 1 s, counter set to 10.
pub fn seed_machine() -> Machine {
    let mut m = running(engine::minasec::SEED_TEST_PROGRAM);
    apply(
        &mut m,
        Command::SetDelay(TimerId::T0, SimTime::from_millis(1100)),
    );
    apply(
        &mut m,
        Command::SetDelay(TimerId::T1, SimTime::from_secs(1)),
    );
    apply(&mut m, Command::SetCounterPreset(1, 0));
    m
}

/// Moves the RUN-HALT-RESET switch.
pub fn mode(m: &mut Machine, mode: Mode) {
    apply(m, Command::SetMode(mode));
}
