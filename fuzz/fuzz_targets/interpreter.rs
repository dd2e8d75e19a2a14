//! The whole interpreter on any bytes, on every profile (the first byte picks it), in run and
//! check mode: never a panic, never a number that is not finite in a record.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ncsight::profile::{self, Params};
use ncsight::{run_text, Event, Mode, Switches};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, text)) = data.split_first() else { return };
    let profiles = profile::all();
    let p = profiles[pick as usize % profiles.len()];
    let mode = if pick & 0x80 == 0 { Mode::Run } else { Mode::Check };
    for e in run_text(Params::defaults(p), Switches::default(), mode, text) {
        if let Event::Record(r) = e {
            assert!(r.t_s.is_finite(), "{r:?}");
            if let Some(q) = r.op.end_point() {
                assert!(q.x.is_finite() && q.y.is_finite() && q.z.is_finite(), "{r:?}");
            }
        }
    }
});
