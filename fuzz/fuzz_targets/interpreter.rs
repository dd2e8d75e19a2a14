//! The whole interpreter on any bytes, on every profile (the first byte picks it), in run and
//! check mode: never a panic, never a number that is not finite in a record, and the lines read
//! ahead in packed batches (as the command line feeds them) give the same events as the lines
//! fed one by one.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ncsight::profile::{self, Params};
use ncsight::{run_text, Event, Mode, Program, ReadBatch, Switches};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, text)) = data.split_first() else { return };
    let profiles = profile::all();
    let p = profiles[pick as usize % profiles.len()];
    let mode = if pick & 0x80 == 0 { Mode::Run } else { Mode::Check };
    let events = run_text(Params::defaults(p), Switches::default(), mode, text);
    for e in &events {
        if let Event::Record(r) = e {
            assert!(r.t_s.is_finite(), "{r:?}");
            if let Some(q) = r.op.end_point() {
                assert!(q.x.is_finite() && q.y.is_finite() && q.z.is_finite(), "{r:?}");
            }
        }
    }
    // Batches of 3 lines (the second pick bit varies it to 1), reused.
    let per_batch = if pick & 0x40 == 0 { 3 } else { 1 };
    let mut program = Program::new(Params::defaults(p), Switches::default(), mode);
    let reader = program.line_reader();
    let mut batch = ReadBatch::default();
    // Compared as they come, so that a long run is not held twice.
    let mut k = 0usize;
    let mut same = |e: Event| {
        assert_eq!(events.get(k), Some(&e), "event {k}");
        k += 1;
    };
    let lines: Vec<&[u8]> = text.split_inclusive(|&b| b == b'\n').collect();
    let mut line_no = 0u32;
    for part in lines.chunks(per_batch) {
        if !program.wants_more() {
            break;
        }
        batch.clear();
        for l in part {
            line_no += 1;
            batch.push(&reader, line_no, l);
        }
        for i in 0..batch.len() {
            program.feed_from(&batch, i, &mut same);
        }
    }
    program.finish(&mut same);
    assert_eq!(k, events.len());
});
