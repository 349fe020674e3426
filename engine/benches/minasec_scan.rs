//! MINASEC-U execution speed: the seed test program repeated over all 256
//! steps, inputs held at 0, on the fast path and on the exact path.
//!
//! Run with `cargo bench -p engine --bench minasec_scan`; throughput is in
//! steps (one step = one clock = one instruction).

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use engine::minasec::control::FAST_PERIOD;
use engine::minasec::{Machine, Program};
use engine::SimTime;

const BENCH_PROGRAM: &str = include_str!("../programs/minasec-u/bench-256.il");
/// Scans per iteration: enough that per-call overhead vanishes.
const SCANS: u64 = 1_000;

fn machine(fast: bool) -> Machine {
    let program = Program::parse(BENCH_PROGRAM).expect("the bench program parses");
    let mut m = Machine::for_run();
    m.set_fast_path(fast);
    m.load(&program);
    m
}

fn scans(c: &mut Criterion) {
    let mut group = c.benchmark_group("minasec-u");
    group.throughput(Throughput::Elements(SCANS * 256));
    for (name, fast) in [("fast path", true), ("exact path", false)] {
        let mut m = machine(fast);
        let span = SimTime::from_nanos(SCANS * 256 * FAST_PERIOD.as_nanos());
        group.bench_function(name, |b| {
            b.iter(|| {
                m.tick(span);
                black_box(m.output_terminals())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, scans);
criterion_main!(benches);
