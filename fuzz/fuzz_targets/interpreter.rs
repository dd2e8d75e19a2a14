//! The whole interpreter on any bytes, on every profile (the first byte picks it), in run and
//! check mode: never a panic, never a number that is not finite in a record, and the lines read
//! ahead in packed batches (as the command line feeds them) give the same events as the lines
//! fed one by one.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ncsight::profile::{self, Params};
use ncsight::{CallOptions, Event, Mode, Program, ReadBatch, Request, Switches};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, text)) = data.split_first() else { return };
    let profiles = profile::all();
    let p = profiles[pick as usize % profiles.len()];
    let mode = if pick & 0x80 == 0 { Mode::Run } else { Mode::Check };
    // A loop the programme never leaves stops at the runaway guard; a low limit keeps each run
    // short (the guard itself is what is tested, not its default).
    let calls = CallOptions { max_repeated_blocks: 20_000, ..CallOptions::default() };
    let mut first = Program::new(Params::defaults(p), Switches::default(), mode);
    first.set_call_options(calls);
    let events: Vec<Event> = ncsight::events(first, text).collect();
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
    program.set_call_options(calls);
    // As the pull iterator above: a drilling block too big to hold keeps the cap (NCS-E40)
    // instead of being made as it is handed on, so the two paths are compared alike.
    program.set_deferred_blocks(false);
    // The tape leader, decided from the first lines as every driver does.
    let mut scan = program.leader_scan();
    for l in text.split_inclusive(|&b| b == b'\n') {
        if scan.push(l) {
            break;
        }
    }
    program.set_tape_leader(scan.lines());
    let reader = program.line_reader();
    let mut batch = ReadBatch::default();
    // Compared as they come, so that a long run is not held twice.
    let mut k = 0usize;
    let mut same = |e: Event| {
        assert_eq!(events.get(k), Some(&e), "event {k}");
        k += 1;
    };
    let lines: Vec<&[u8]> = text.split_inclusive(|&b| b == b'\n').collect();
    // The next line to batch (0-based); a jump (a subprogramme call or return) moves it.
    let mut next = 0usize;
    loop {
        while next < lines.len() && program.wants_more() {
            batch.clear();
            let first = next;
            for l in &lines[first..(first + per_batch).min(lines.len())] {
                next += 1;
                batch.push(&reader, next as u32, l);
            }
            for i in 0..batch.len() {
                program.feed_from(&batch, i, &mut same);
                if let Some(r) = program.take_request() {
                    next = follow(&mut program, r, &mut same);
                    break;
                }
            }
        }
        match program.end_of_text(&mut same) {
            Some(r) => next = follow(&mut program, r, &mut same),
            None => break,
        }
    }
    assert_eq!(k, events.len());
});

/// Where the run asks to read next, as a line index: a seek in the one text, or no other file.
fn follow(program: &mut Program, mut r: Request, same: &mut dyn FnMut(Event)) -> usize {
    loop {
        match r {
            Request::Seek(p) => return p.line.saturating_sub(1) as usize,
            Request::Find { .. } => {
                program.no_file(same);
                match program.take_request() {
                    Some(next) => r = next,
                    None => return usize::MAX,
                }
            }
        }
    }
}
