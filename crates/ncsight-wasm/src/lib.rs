//! The engine for the browser page (issue 20): the core compiled to `wasm32-unknown-unknown`,
//! with a C ABI small enough to call from plain JavaScript (no generated glue, nothing to
//! install beyond the Rust target):
//!
//! - `ncsight_alloc(len) -> ptr` gives the page a buffer to copy the programme's text and the
//!   machine's name into; `ncsight_free(ptr, len)` gives it back.
//! - `ncsight_run(text, text_len, machine, machine_len, params, params_len, setup, setup_len,
//!   mode) -> ptr` runs the text (`mode` 0: run, 1: check) with the parameter overrides `params`
//!   (`N=V` lines, as `--param` takes them; empty for none) and the machine setup `setup` (the
//!   text of a setup file, TOML, as `--setup` reads it; empty for none), and returns a buffer: 4
//!   bytes of length
//!   (little-endian), then the JSONL the
//!   command line writes for `run --format jsonl` (records and diagnostics) or `check --format
//!   jsonl`; free it with `ncsight_free(ptr, 4 + length)`. A usage mistake (an unknown machine),
//!   a bad parameter or setup is one JSONL line `{"kind":"usage","message":...}`.
//!
//! A page has no threads and no files: the programme runs from memory, on the calling thread,
//! through the core's pull iterator (`ncsight::events`), and the JSONL comes from the same
//! formatter as the command line's, so the page shows what `ncsight run` prints.

use ncsight::Mode;
use ncsight_io::format;
use ncsight_io::Job;

/// Run `text` on `machine` as `ncsight run --format jsonl` (or `check --format jsonl`, named
/// `<text>`) would, from memory on this thread: the JSONL text.
pub fn run_jsonl(text: &[u8], machine: &str, params: &str, setup: &str, mode: Mode) -> String {
    let mut job = Job { params: params.lines().map(str::trim).filter(|l| !l.is_empty()).map(String::from).collect(), ..Job::on(machine) };
    let with_setup = if setup.trim().is_empty() { Ok(()) } else { job.set_setup_text(setup, "setup") };
    let started = with_setup.and_then(|()| job.program(mode)).and_then(|(program, _)| Ok((program, job.jsonl_writer(mode, "<text>")?)));
    let (program, mut writer) = match started {
        Ok(v) => v,
        Err(e) => return format!("{{\"kind\":\"usage\",\"message\":{}}}\n", format::jsonl::json_str(&e.to_string())),
    };
    let mut out = Vec::with_capacity(text.len() * 2);
    for e in ncsight::events(program, text) {
        // Writing into a Vec cannot fail.
        let _ = writer.write(&e, None, &mut out);
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// A buffer of `len` bytes for the page to write into.
#[no_mangle]
pub extern "C" fn ncsight_alloc(len: usize) -> *mut u8 {
    let mut v = vec![0u8; len.max(1)];
    let p = v.as_mut_ptr();
    std::mem::forget(v);
    p
}

/// Give back a buffer of `len` bytes from [`ncsight_alloc`] or [`ncsight_run`].
///
/// # Safety
/// `ptr` and `len` must be exactly what one of those returned (for `ncsight_run`'s result,
/// `len` is 4 + the length in its first 4 bytes), and the buffer must not be used afterwards.
#[no_mangle]
pub unsafe extern "C" fn ncsight_free(ptr: *mut u8, len: usize) {
    if !ptr.is_null() {
        // SAFETY: the caller gives back a buffer made by `ncsight_alloc`/`answer` of this length.
        drop(unsafe { Vec::from_raw_parts(ptr, len.max(1), len.max(1)) });
    }
}

/// Run a programme: see the crate's documentation.
///
/// # Safety
/// `text`, `machine`, `params` and `setup` must point to `text_len`, `machine_len`, `params_len`
/// and `setup_len` readable bytes (buffers from [`ncsight_alloc`]).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ncsight_run(text: *const u8, text_len: usize, machine: *const u8, machine_len: usize, params: *const u8, params_len: usize, setup: *const u8, setup_len: usize, mode: u32) -> *mut u8 {
    // SAFETY: the caller guarantees the four buffers (see above).
    let (text, machine, params, setup) = unsafe {
        (std::slice::from_raw_parts(text, text_len), std::slice::from_raw_parts(machine, machine_len), std::slice::from_raw_parts(params, params_len), std::slice::from_raw_parts(setup, setup_len))
    };
    let mode = if mode == 1 { Mode::Check } else { Mode::Run };
    let jsonl = run_jsonl(text, &String::from_utf8_lossy(machine), &String::from_utf8_lossy(params), &String::from_utf8_lossy(setup), mode);
    answer(jsonl.as_bytes())
}

/// `bytes` behind their 4-byte little-endian length, in a buffer the page frees.
fn answer(bytes: &[u8]) -> *mut u8 {
    let mut v = Vec::with_capacity(4 + bytes.len());
    v.extend_from_slice(&(bytes.len() as u32).to_le_bytes());
    v.extend_from_slice(bytes);
    v.shrink_to_fit();
    let len = v.len();
    let p = ncsight_alloc(len);
    // SAFETY: `p` is a fresh buffer of `len` bytes.
    unsafe { std::ptr::copy_nonoverlapping(v.as_ptr(), p, len) };
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ABI round trip, natively: the answer's length prefix, its JSONL, and the buffers given
    /// back.
    #[test]
    fn run_through_the_abi() {
        let text = b"G21 G90 G00 X1. Y2. Z3.\nM30\n";
        let machine = b"fanuc0m";
        let tp = ncsight_alloc(text.len());
        let mp = ncsight_alloc(machine.len());
        unsafe {
            std::ptr::copy_nonoverlapping(text.as_ptr(), tp, text.len());
            std::ptr::copy_nonoverlapping(machine.as_ptr(), mp, machine.len());
            let pp = ncsight_alloc(0);
            let sp = ncsight_alloc(0);
            let r = ncsight_run(tp, text.len(), mp, machine.len(), pp, 0, sp, 0, 0);
            ncsight_free(pp, 0);
            ncsight_free(sp, 0);
            let len = u32::from_le_bytes(std::slice::from_raw_parts(r, 4).try_into().unwrap()) as usize;
            let jsonl = std::str::from_utf8(std::slice::from_raw_parts(r.add(4), len)).unwrap().to_string();
            ncsight_free(r, 4 + len);
            ncsight_free(tp, text.len());
            ncsight_free(mp, machine.len());
            assert_eq!(jsonl.lines().count(), 2, "{jsonl}");
            assert!(jsonl.starts_with("{\"line\":1,\"kind\":\"rapid\",\"x\":1,\"y\":2,\"z\":3"), "{jsonl}");
            assert!(jsonl.lines().nth(1).unwrap().contains("\"kind\":\"end\""), "{jsonl}");
        }
    }

    #[test]
    fn a_usage_mistake_is_a_line() {
        assert_eq!(run_jsonl(b"G00 X0\n", "haas", "", "", Mode::Run).lines().count(), 1);
        assert!(run_jsonl(b"G00 X0\n", "haas", "", "", Mode::Run).contains("\"kind\":\"usage\""));
        assert!(run_jsonl(b"G00 X0\n", "fanuc0m", "99999=1", "", Mode::Run).contains("\"kind\":\"usage\""));
        assert!(run_jsonl(b"G00 X0\n", "fanuc0m", "", "[wrok]\n", Mode::Run).contains("\"kind\":\"usage\""));
        // With a setup, records carry machine positions.
        assert!(run_jsonl(b"G21 G90 G00 X1. Y2. Z3.\nM30\n", "fanuc0m", "", "[work]\nG54 = { x_mm = -100.0 }\n", Mode::Run).contains("\"machine_x\":-99"));
        // A check gives diagnostics only.
        let check = run_jsonl(b"G00 X0 Q1\nM30\n", "gsk980tdi", "", "", Mode::Check);
        assert!(check.lines().all(|l| l.contains("\"severity\"")), "{check}");
    }
}
