//! Reading large ladders (docs/limits.md, docs/performance.md): the
//! analysis must stay near-linear, whatever shape the input takes.
//! - `plcopen-5000-rungs`: a 1.5 MB PLCopen file, 5 000 contact→coil rungs
//!   on one left rail, imported;
//! - `plcopen-50000-rails`: 50 000 left rails and one rung, imported;
//! - `json-20000-series`: a project with one rung of 20 000 contacts in
//!   series, read and compiled for the AVR PLC.
//!
//! Run with `cargo bench -p engine --bench ladder_input`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use engine::formats::plcopen::Document;
use engine::formats::Project;
use engine::ladder::compile::{compile, Options};

#[path = "../tests/hostile/gen.rs"]
#[allow(dead_code)] // the bench uses some of the test generators
mod gen;

fn inputs(c: &mut Criterion) {
    let mut group = c.benchmark_group("ladder_input");
    group.sample_size(10);

    let rungs = gen::plcopen_rungs(5_000, "X00", "Y00");
    group.bench_function("plcopen-5000-rungs", |b| {
        b.iter(|| {
            Document::read(black_box(&rungs))
                .and_then(|document| document.import(None, None, None))
                .map(|i| i.ladder)
                .expect("imports")
        })
    });

    let rails = gen::plcopen_rails(50_000);
    group.bench_function("plcopen-50000-rails", |b| {
        b.iter(|| {
            Document::read(black_box(&rails))
                .and_then(|document| document.import(None, None, None))
                .map(|i| i.ladder)
                .expect("imports")
        })
    });

    let series = gen::project("avr-plc", &[gen::series_rung(20_000, "R0.0", "R1.0")]);
    group.bench_function("json-20000-series", |b| {
        b.iter(|| {
            let p = Project::from_json(black_box(&series)).expect("reads");
            compile(&p.ladder, p.machine, Options::default()).expect("compiles")
        })
    });
    group.finish();
}

criterion_group!(benches, inputs);
criterion_main!(benches);
