//! Micro-benchmarks of the output formats: one record of each common kind written by each
//! format. `cargo bench -p ncsight-cli`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ncsight::motion::{ArcDir, Op, Plane};
use ncsight::source::Span;
use ncsight::{profile, Event, Record, Vec3};
use ncsight_cli::format;

fn records() -> Vec<(&'static str, Event)> {
    let from = Vec3::new(1.25, -3.5, 10.0);
    let to = Vec3::new(12.3456, 7.891, -5.0);
    let rec = |name, op| {
        let mut r = Record::new(Span::new(12, 1, 10), op);
        r.t_s = 123.456789;
        (name, Event::Record(r))
    };
    vec![
        rec("rapid", Op::Rapid { from, to }),
        rec("feed", Op::Feed { from, to, feed_mm_min: 500.0 }),
        rec("arc", Op::Arc { from, to, center: Vec3::new(5.0, 5.0, 0.0), plane: Plane::XY, dir: ArcDir::Cw, feed_mm_min: 250.0 }),
    ]
}

fn formats(c: &mut Criterion) {
    let profile = profile::by_name("fanuc0m").unwrap();
    let mut out = Vec::with_capacity(1 << 20);
    for name in ["text", "jsonl", "canon"] {
        let mut g = c.benchmark_group(format!("format {name}"));
        let mut fmt = format::by_name(name, profile, false).unwrap();
        for (kind, event) in records() {
            g.bench_function(kind, |b| {
                b.iter(|| {
                    out.clear();
                    fmt.event(black_box(&event), &mut out).unwrap();
                })
            });
        }
        g.finish();
    }
}

criterion_group!(benches, formats);
criterion_main!(benches);
