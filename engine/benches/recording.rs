//! What recording costs (issue #16): each machine running flat out for
//! 1 000 scans, an input toggled every 50, plain (`run_until`, what the
//! page does without recording) and recorded (`Recording::run`), with
//! tracing off and on (the page traces while the live ladder shows);
//! then seeking to recorded scans (a keyframe copied and replayed) and
//! making a keyframe's images for the timing chart. Memory per 1 000
//! scans is printed once per machine.
//!
//! Run with `cargo bench -p engine --bench recording`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use engine::events::InputValue;
use engine::machines::{ArduinoPlc, AvrPlc, Io86aPlc, MinasecPlc};
use engine::plc::{Command, Device, Plc};
use engine::record::{run_scans, Recording, DEFAULT_BUDGET};
use engine::SimTime;

const SCANS: u64 = 1_000;
const SEGMENT: u64 = 50;

/// The end times of each 50-scan segment of `m`'s first 1 000 scans.
fn segments<M: Plc + Clone>(m: &M) -> Vec<SimTime> {
    let mut probe = m.clone();
    let mut ends = Vec::new();
    run_scans(&mut probe, SimTime::from_secs(36_000), |x| {
        if x.scans().is_multiple_of(SEGMENT) {
            ends.push(x.now());
        }
        x.scans() < SCANS
    });
    ends
}

fn toggle(n: usize, input: Device) -> Command {
    Command::SetInput(input, InputValue::Int(i64::from(n.is_multiple_of(2))))
}

fn bench_machine<M: Plc + Clone>(c: &mut Criterion, name: &str, m: M, input: &str) {
    let input = m.device(input).expect("input");
    for traced in [false, true] {
        let mut m = m.clone();
        m.set_tracing(traced);
        let ends = segments(&m);
        let tag = if traced { "traced" } else { "untraced" };
        let mut group = c.benchmark_group(format!("recording/{name}/{tag}"));
        group.bench_function("plain", |b| {
            b.iter(|| {
                let mut m = m.clone();
                for (n, &t) in ends.iter().enumerate() {
                    let _ = m.apply(toggle(n, input));
                    m.run_until(t);
                }
                black_box(m.scans())
            })
        });
        group.bench_function("recorded", |b| {
            b.iter(|| {
                let mut m = m.clone();
                let mut rec = Recording::new(&m, DEFAULT_BUDGET);
                for (n, &t) in ends.iter().enumerate() {
                    let _ = rec.apply(&mut m, toggle(n, input));
                    rec.run(&mut m, t, None);
                }
                black_box(rec.last())
            })
        });
        let mut live = m.clone();
        let mut rec = Recording::new(&live, DEFAULT_BUDGET);
        for (n, &t) in ends.iter().enumerate() {
            let _ = rec.apply(&mut live, toggle(n, input));
            rec.run(&mut live, t, None);
        }
        let last = rec.last();
        let before = rec.bytes();
        let bare = rec.clone();
        rec.values(&live, input, 0, last);
        println!(
            "{name} {tag}: {last} scans: {} bytes per 1 000 scans recorded, {} with every image made",
            before as u64 * 1_000 / last.max(1),
            rec.bytes() as u64 * 1_000 / last.max(1)
        );
        let mut mark = 0;
        group.bench_function("seek", |b| {
            b.iter(|| {
                // Steps through the marks so every distance from a keyframe counts.
                mark = (mark + 37) % last;
                black_box(rec.machine_at(mark).map(|m| m.scans()))
            })
        });
        group.bench_function("values of 1 000 scans", |b| {
            b.iter(|| {
                // From scratch: every keyframe's images made by replay.
                let mut fresh = bare.clone();
                black_box(fresh.values(&live, input, 0, last).len())
            })
        });
        group.finish();
    }
}

fn recording(c: &mut Criterion) {
    let mut minasec = MinasecPlc::new();
    minasec
        .load_text(include_str!("../programs/minasec-u/bench-256.il"))
        .expect("bench program");
    bench_machine(c, "minasec-u", minasec, "X00");
    let mut io86a = Io86aPlc::new();
    io86a
        .load_text(include_str!("../programs/io86a/timer.il"))
        .expect("example");
    bench_machine(c, "io86a", io86a, "X00");
    let mut avr = AvrPlc::new();
    avr.load_text(include_str!("../programs/avr-plc/e-stop-timer.asm"))
        .expect("example");
    bench_machine(c, "avr-plc", avr, "Run");
    let mut arduino = ArduinoPlc::new();
    arduino
        .load_text(include_str!("../programs/arduino-plc/self-hold.txt"))
        .expect("example");
    bench_machine(c, "arduino-plc", arduino, "X000");
}

criterion_group!(benches, recording);
criterion_main!(benches);
