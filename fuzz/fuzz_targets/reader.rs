//! The reader on any bytes: never a panic; every diagnostic inside the line.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ncsight::alarm::AlarmStyle;
use ncsight::read::Reader;

fuzz_target!(|data: &[u8]| {
    let reader = Reader::new(AlarmStyle::Project);
    for (i, line) in data.split(|&b| b == b'\n').enumerate() {
        let out = reader.read_line(i as u32 + 1, line);
        for d in out.blocks.iter().filter_map(|b| b.as_ref().err()).chain(out.warnings.iter()) {
            assert!(d.span.col >= 1 && d.span.line == i as u32 + 1);
        }
    }
});
