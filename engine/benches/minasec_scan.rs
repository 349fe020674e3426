//! MINASEC-U execution speed, inputs held at 0, on the fast path as shipped
//! (gate network), on the fast path's step kernel alone, and on the exact
//! path, for two programs:
//! - `bench-256`: the seed test program repeated over all 256 steps (the
//!   figure the README quotes);
//! - `bench-dense`: `AND Xn / ST Mn` 128 times, the most gates a scan can
//!   need, the gate network's worst case.
//!
//! Run with `cargo bench -p engine --bench minasec_scan`; throughput is in
//! steps (one step = one clock = one instruction).

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use engine::minasec::control::FAST_PERIOD;
use engine::minasec::{Machine, Program};
use engine::SimTime;

const PROGRAMS: [(&str, &str); 2] = [
    (
        "bench-256",
        include_str!("../programs/minasec-u/bench-256.il"),
    ),
    (
        "bench-dense",
        include_str!("../programs/minasec-u/bench-dense.il"),
    ),
];
/// Scans per iteration: enough that per-call overhead vanishes.
const SCANS: u64 = 1_000;

fn machine(text: &str, fast: bool, network: bool) -> Machine {
    let program = Program::parse(text).expect("the bench program parses");
    let mut m = Machine::for_run();
    m.set_fast_path(fast);
    m.set_gate_network(network);
    m.load(&program);
    m
}

fn scans(c: &mut Criterion) {
    let paths = [
        ("fast path", true, true),
        ("step kernel", true, false),
        ("exact path", false, false),
    ];
    for (program, text) in PROGRAMS {
        let mut group = c.benchmark_group(format!("minasec-u/{program}"));
        group.throughput(Throughput::Elements(SCANS * 256));
        for (name, fast, network) in paths {
            let mut m = machine(text, fast, network);
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
}

criterion_group!(benches, scans);
criterion_main!(benches);
