//! Micro-benchmarks of the core: the lexer, block interpretation, and the whole line driver in
//! check and run modes. `cargo bench -p ncsight`.

use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use ncsight::profile::{self, Params};
use ncsight::read::{Line, Reader};
use ncsight::{Interpreter, Mode, Program, Switches};

/// A FANUC 0-M drilling programme of `holes` G81 holes, as the LinuxCNC comparison uses.
fn holes(holes: usize) -> Vec<u8> {
    let mut s = String::from("G21 G17 G90 G00 X0. Y0. Z10.\nF500.\nG98 G81 X1.000 Y1.000 Z-5.000 R2.000\n");
    for i in 0..holes {
        s.push_str(&format!("X{:.3} Y{:.3}\n", (i % 1000) as f64 * 0.5 + 1.0, (i / 1000) as f64 * 0.5 + 1.0));
    }
    s.push_str("G80\nM30\n");
    s.into_bytes()
}

fn fanuc() -> Params {
    Params::defaults(profile::by_name("fanuc0m").unwrap())
}

fn lexer(c: &mut Criterion) {
    let reader = Reader::new(ncsight::alarm::AlarmStyle::Fanuc);
    let mut line = Line::default();
    let mut g = c.benchmark_group("lexer");
    for text in ["X123.456 Y-78.9", "N120 G01 X12.5 Z-30. F0.25 (finish pass)", "G92 X[20-2*0.6] Z-30 F1.5"] {
        g.throughput(Throughput::Bytes(text.len() as u64));
        g.bench_function(text, |b| b.iter(|| reader.read_line_into(1, black_box(text.as_bytes()), &mut line)));
    }
    g.finish();
}

fn interpret(c: &mut Criterion) {
    let reader = Reader::new(ncsight::alarm::AlarmStyle::Fanuc);
    let mut g = c.benchmark_group("interpret block");
    for (name, setup, text) in [
        ("G01 move", "G90 G01 F500.", "X12.5 Y-3. Z-1."),
        ("G81 hole", "G90 G98 G81 X1. Y1. Z-5. R2. F500.", "X10.5 Y3."),
        ("G02 arc", "G90 G17 G01 X10. Y0. F500.", "G02 X0. Y10. R10."),
    ] {
        let mut interp = Interpreter::new(fanuc(), Switches::default());
        for b in reader.read_line(1, setup.as_bytes()).blocks.into_iter().flatten() {
            interp.execute(&b).unwrap();
        }
        let block = reader.read_line(2, text.as_bytes()).blocks.remove(0).unwrap();
        let mut out = Default::default();
        g.bench_function(name, |b| {
            // A fresh copy each time, so that every iteration starts from the same state.
            b.iter_batched_ref(|| interp.clone(), |i| i.execute_into(black_box(&block), &mut out).unwrap(), BatchSize::SmallInput)
        });
    }
    g.finish();
}

fn program(c: &mut Criterion) {
    let text = holes(10_000);
    let mut g = c.benchmark_group("program, 10000 G81 holes");
    g.throughput(Throughput::Bytes(text.len() as u64));
    g.sample_size(20);
    g.bench_function("check (diagnostics only)", |b| {
        b.iter(|| {
            let mut p = Program::diagnostics_only(fanuc(), Switches::default());
            let mut n = 0usize;
            for l in text.split_inclusive(|&c| c == b'\n') {
                p.feed_line(l, &mut |_| n += 1);
            }
            p.finish(&mut |_| n += 1);
            n
        })
    });
    g.bench_function("run (timed records)", |b| {
        b.iter(|| {
            let mut p = Program::new(fanuc(), Switches::default(), Mode::Run);
            let mut n = 0usize;
            for l in text.split_inclusive(|&c| c == b'\n') {
                p.feed_line(l, &mut |_| n += 1);
            }
            p.finish(&mut |_| n += 1);
            n
        })
    });
    g.finish();
}

criterion_group!(benches, lexer, interpret, program);
criterion_main!(benches);
