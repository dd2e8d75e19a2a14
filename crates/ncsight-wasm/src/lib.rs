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
//! - `ncsight_scene(text, machine, params, setup, options, library)` (each a pointer and a length)
//!   runs the text for the page and answers its scene (`ncsight_io::format::scene`, packed
//!   columns the page reads into typed arrays); `ncsight_check` with the same arguments answers
//!   every diagnostic of a check as JSON. Both answer `NCSE` and a message for a usage mistake.
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
    let started = page_job(machine, params, setup, "", &[]).and_then(|(job, _)| Ok((job.program(mode)?.0, job.jsonl_writer(mode, "<text>")?)));
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

/// The job of the page's arguments: the parameter overrides `params`, the setup `setup` (TOML),
/// the operator's settings `options` (`key=value` lines, `Job::set_operator_text`), and the files
/// `library` where called programmes the text lacks are looked for: each a u32 length and the
/// file's name, a u32 length and its text.
fn page_job<'l>(machine: &str, params: &str, setup: &str, options: &str, library: &'l [u8]) -> Result<(Job, Vec<(String, &'l [u8])>), ncsight_io::JobError> {
    let mut job = Job { params: params.lines().map(str::trim).filter(|l| !l.is_empty()).map(String::from).collect(), ..Job::on(machine) };
    if !setup.trim().is_empty() {
        job.set_setup_text(setup, "setup")?;
    }
    job.set_operator_text(options)?;
    let files = files(library).ok_or_else(|| ncsight_io::JobError::Usage("the library of called programmes is cut short".into()))?;
    Ok((job, files))
}

/// A usage mistake as the page reads it: `NCSE` and the message.
fn usage_answer(e: ncsight_io::JobError) -> Vec<u8> {
    [b"NCSE".as_slice(), e.to_string().as_bytes()].concat()
}

/// The scene of `text` on `machine` (see `ncsight_io::format::scene`), a run with the job of
/// [`page_job`]. A usage mistake is `NCSE` and its message.
pub fn scene(text: &[u8], machine: &str, params: &str, setup: &str, options: &str, library: &[u8]) -> Vec<u8> {
    page_job(machine, params, setup, options, library).and_then(|(job, files)| format::scene::scene(&job, text, files)).unwrap_or_else(usage_answer)
}

/// Every diagnostic of a check of `text` (see `ncsight_io::format::scene::check`), with the same
/// arguments as [`scene`], as JSON; a usage mistake is `NCSE` and its message.
pub fn check(text: &[u8], machine: &str, params: &str, setup: &str, options: &str, library: &[u8]) -> Vec<u8> {
    page_job(machine, params, setup, options, library)
        .and_then(|(job, files)| format::scene::check(&job, text, files))
        .map(String::into_bytes)
        .unwrap_or_else(usage_answer)
}

/// The cut stock of `text` for the page's 3D view (see `ncsight_io::format::stock`), with the
/// arguments of [`scene`]; `options` may also hold `stock=DIAxLEN` (a mill's `XxYxZ`),
/// `until_s=T` (cut only what has ended by T seconds) and `resolution_mm=R` (the grid's cell
/// along Z on a lathe, across on a mill, instead of the view's own). A usage mistake, or a programme with no
/// stock to cut, is `NCSE` and its message.
pub fn stock(text: &[u8], machine: &str, params: &str, setup: &str, options: &str, library: &[u8]) -> Vec<u8> {
    let (mut stock_text, mut until_s, mut resolution, mut rest) = (String::new(), None, None, String::new());
    for line in options.lines() {
        match line.split_once('=').map(|(k, v)| (k.trim(), v.trim())) {
            Some(("stock", v)) => stock_text = v.to_string(),
            Some(("resolution_mm", v)) => match v.parse::<f64>() {
                Ok(r) if r.is_finite() && r > 0.0 => resolution = Some(r),
                _ => return usage_answer(ncsight_io::JobError::Usage(format!("resolution_mm={v}: expected a cell size in mm"))),
            },
            Some(("until_s", v)) => match v.parse::<f64>() {
                Ok(t) if t.is_finite() => until_s = Some(t),
                _ => return usage_answer(ncsight_io::JobError::Usage(format!("until_s={v}: expected a number of seconds"))),
            },
            _ => {
                rest.push_str(line);
                rest.push('\n');
            }
        }
    }
    page_job(machine, params, setup, &rest, library)
        .and_then(|(job, files)| format::stock::stock_view(&job, text, files, &stock_text, until_s, resolution))
        .unwrap_or_else(usage_answer)
}

/// The programme ported to another controller (`ncsight port`, ncsight_io::port): `options` holds
/// `to=MACHINE`. JSON: `{"to","exact","text","rewritten":[{"line","why"}],"differences":[{"line",
/// "what","size"}]}`, or `{"alarm":{"line","message"}}` when the programme alarms on its own
/// controller. A usage mistake is `NCSE` and its message.
pub fn port(text: &[u8], machine: &str, params: &str, setup: &str, options: &str, library: &[u8]) -> Vec<u8> {
    use ncsight_io::format::jsonl::json_str;
    let to = options.lines().find_map(|l| l.trim().strip_prefix("to=")).unwrap_or("").trim().to_string();
    let answer = page_job(machine, params, setup, "", library).and_then(|(job, _)| {
        // The page has one setup: the target machine is taken to have it too.
        let mut target = Job::on(&to);
        target.profile()?;
        if !setup.trim().is_empty() {
            target.set_setup_text(setup, "setup")?;
        }
        Ok(match ncsight_io::port::port(&job, &target, text) {
            Ok(p) => {
                let rewritten: Vec<String> = p.rewritten.iter().map(|(l, why)| format!("{{\"line\":{l},\"why\":{}}}", json_str(why))).collect();
                let diffs: Vec<String> =
                    p.differences.iter().map(|d| format!("{{\"line\":{},\"what\":{},\"size\":{}}}", d.line, json_str(&d.what), d.size)).collect();
                format!(
                    "{{\"to\":{},\"exact\":{},\"text\":{},\"rewritten\":[{}],\"differences\":[{}]}}",
                    json_str(&to),
                    p.exact(),
                    json_str(&p.text),
                    rewritten.join(","),
                    diffs.join(",")
                )
            }
            Err(ncsight_io::port::PortError::SourceAlarm(line, message)) => format!("{{\"alarm\":{{\"line\":{line},\"message\":{}}}}}", json_str(&message)),
            Err(ncsight_io::port::PortError::Usage(m)) => return Err(ncsight_io::JobError::Usage(m)),
        })
    });
    answer.map(String::into_bytes).unwrap_or_else(usage_answer)
}

/// The files of a library buffer (see [`scene`]); None when it is cut short.
fn files(mut b: &[u8]) -> Option<Vec<(String, &[u8])>> {
    fn take<'a>(b: &mut &'a [u8]) -> Option<&'a [u8]> {
        let n = u32::from_le_bytes(b.get(..4)?.try_into().ok()?) as usize;
        let v = b.get(4..4 + n)?;
        *b = &b[4 + n..];
        Some(v)
    }
    let mut out = Vec::new();
    while !b.is_empty() {
        let name = String::from_utf8_lossy(take(&mut b)?).into_owned();
        let text = take(&mut b)?;
        out.push((name, text));
    }
    Some(out)
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
pub unsafe extern "C" fn ncsight_run(
    text: *const u8,
    text_len: usize,
    machine: *const u8,
    machine_len: usize,
    params: *const u8,
    params_len: usize,
    setup: *const u8,
    setup_len: usize,
    mode: u32,
) -> *mut u8 {
    // SAFETY: the caller guarantees the four buffers (see above).
    let (text, machine, params, setup) = unsafe {
        (
            std::slice::from_raw_parts(text, text_len),
            std::slice::from_raw_parts(machine, machine_len),
            std::slice::from_raw_parts(params, params_len),
            std::slice::from_raw_parts(setup, setup_len),
        )
    };
    let mode = if mode == 1 { Mode::Check } else { Mode::Run };
    let jsonl = run_jsonl(text, &String::from_utf8_lossy(machine), &String::from_utf8_lossy(params), &String::from_utf8_lossy(setup), mode);
    answer(jsonl.as_bytes())
}

/// The six buffers of [`ncsight_scene`] and [`ncsight_check`], as [`scene`] takes them.
///
/// # Safety
/// Each pointer must point to its length's readable bytes.
unsafe fn page_call(b: [(*const u8, usize); 6], f: fn(&[u8], &str, &str, &str, &str, &[u8]) -> Vec<u8>) -> *mut u8 {
    // SAFETY: the caller guarantees the six buffers.
    let [text, machine, params, setup, options, library] = b.map(|(p, n)| unsafe { std::slice::from_raw_parts(p, n) });
    let s = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    answer(&f(text, &s(machine), &s(params), &s(setup), &s(options), library))
}

/// The scene of a programme (see [`scene`]), behind its 4-byte little-endian length.
///
/// # Safety
/// As [`ncsight_run`], with `options` and `library` pointing to `options_len` and `library_len`
/// readable bytes.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ncsight_scene(
    text: *const u8,
    text_len: usize,
    machine: *const u8,
    machine_len: usize,
    params: *const u8,
    params_len: usize,
    setup: *const u8,
    setup_len: usize,
    options: *const u8,
    options_len: usize,
    library: *const u8,
    library_len: usize,
) -> *mut u8 {
    // SAFETY: the caller guarantees the six buffers (see above).
    unsafe {
        page_call([(text, text_len), (machine, machine_len), (params, params_len), (setup, setup_len), (options, options_len), (library, library_len)], scene)
    }
}

/// Every diagnostic of a check (see [`check`]) as JSON, behind its 4-byte little-endian length.
///
/// # Safety
/// As [`ncsight_scene`].
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ncsight_check(
    text: *const u8,
    text_len: usize,
    machine: *const u8,
    machine_len: usize,
    params: *const u8,
    params_len: usize,
    setup: *const u8,
    setup_len: usize,
    options: *const u8,
    options_len: usize,
    library: *const u8,
    library_len: usize,
) -> *mut u8 {
    // SAFETY: the caller guarantees the six buffers (see above).
    unsafe {
        page_call([(text, text_len), (machine, machine_len), (params, params_len), (setup, setup_len), (options, options_len), (library, library_len)], check)
    }
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

    /// The scene of a drilling programme: its header, its motions' columns and its holes.
    #[test]
    fn scene_columns() {
        let text = b"G21 G17 G90 G00 X0 Y0 Z10.\nT3 M06\nG99 G81 X10. Y5. Z-4. R2. F100.\nX20.\nG80 G00 Z10.\nG02 X30. Y5. R5. F200.\nM30\n";
        let b = scene(text, "fanuc0m", "", "", "", &[]);
        assert_eq!(&b[..4], b"NCS1");
        let j = u32::from_le_bytes(b[4..8].try_into().unwrap()) as usize;
        let head = std::str::from_utf8(&b[8..8 + j]).unwrap();
        // Motions: the rapid to X0 Y0 Z10; the first hole a rapid in X/Y, one to R, the feed to
        // Z-4, the rapid back to R (G99); the second starts at R: 1 + 4 + 3, then Z10 and the arc.
        assert!(head.contains("\"segments\":10,\"holes\":2,\"hole_kinds\":[\"G81\"]"), "{head}");
        let n = 10;
        let mut at = (8 + j).div_ceil(8) * 8;
        let f64s = |at: usize, k: usize| -> Vec<f64> { (0..k).map(|i| f64::from_le_bytes(b[at + 8 * i..at + 8 * i + 8].try_into().unwrap())).collect() };
        let f32s = |at: usize, k: usize| -> Vec<f32> { (0..k).map(|i| f32::from_le_bytes(b[at + 4 * i..at + 4 * i + 4].try_into().unwrap())).collect() };
        let t = f64s(at, n);
        assert!(t.windows(2).all(|w| w[1] >= w[0]) && t[n - 1] > 0.0, "{t:?}");
        at += 8 * n;
        let points = f32s(at, 6 * n);
        // The feed of the first hole: from R (Z2) to Z-4 at X10 Y5.
        assert_eq!(&points[6 * 3..6 * 4], &[10.0, 5.0, 2.0, 10.0, 5.0, -4.0]);
        at += 24 * n;
        let arcs = f32s(at, 4 * n);
        // The G02 from X20 Y5 to X30 Y5 with R5: centre X25 Y5, half a turn clockwise.
        assert_eq!(&arcs[4 * 9..4 * 9 + 3], &[25.0, 5.0, 10.0]);
        assert!((arcs[4 * 9 + 3] + std::f32::consts::PI).abs() < 1e-5, "{arcs:?}");
        at += 16 * n;
        let rate = f32s(at, n);
        assert_eq!((rate[0], rate[3], rate[9]), (0.0, 100.0, 200.0));
        at += 4 * n;
        let lines: Vec<u32> = (0..n).map(|i| u32::from_le_bytes(b[at + 4 * i..at + 4 * i + 4].try_into().unwrap())).collect();
        assert_eq!(lines, [1, 3, 3, 3, 3, 4, 4, 4, 5, 6]);
        at += 4 * n;
        let tools: Vec<u16> = (0..n).map(|i| u16::from_le_bytes(b[at + 2 * i..at + 2 * i + 2].try_into().unwrap())).collect();
        assert_eq!(tools, [0, 3, 3, 3, 3, 3, 3, 3, 3, 3]);
        at += 2 * n;
        let kinds = &b[at..at + n];
        // Rapid, feed at the hole, the arc in XY; each hole ends a block for single block.
        assert_eq!(kinds[0] & 7, 0);
        assert_eq!(kinds[3] & 7, 1);
        assert_eq!(kinds[9] & 7, 2);
        assert_eq!(kinds[4] & 64, 64);
        at = (at + n).div_ceil(4) * 4;
        let holes = f32s(at, 6);
        assert_eq!(holes, [10.0, 5.0, -4.0, 20.0, 5.0, -4.0]);
        assert_eq!(b.len(), at + 12 * 2 + 4 * 2 + 2);
        assert!(scene(b"G0 X0\n", "haas", "", "", "", &[]).starts_with(b"NCSE"));
        assert!(scene(b"G0 X0\n", "fanuc0m", "", "", "feed_override=300", &[]).starts_with(b"NCSE"));
        assert!(scene(b"G0 X0\n", "fanuc0m", "", "", "", &[9, 0, 0, 0, b'a']).starts_with(b"NCSE"));
        // A called programme from the library: M98 P1234 runs O1234's move.
        let lib = [&4u32.to_le_bytes()[..], b"sub1", &17u32.to_le_bytes()[..], b"O1234\nG0 X7.\nM99\n"].concat();
        let b = scene(b"G21 G90 G0 X0 Y0 Z0\nM98 P1234\nM30\n", "fanuc0m", "", "", "", &lib);
        let j = u32::from_le_bytes(b[4..8].try_into().unwrap()) as usize;
        let head = std::str::from_utf8(&b[8..8 + j]).unwrap();
        // (The rapid to X0 Y0 Z0 does not move from the power-on position.)
        assert!(head.contains("\"segments\":1,") && head.contains("\"diagnostics_total\":0,"), "{head}");
        let at = (8 + j).div_ceil(8) * 8 + 8;
        assert_eq!(f32::from_le_bytes(b[at + 12..at + 16].try_into().unwrap()), 7.0);
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

/// A programme ported to another controller (see [`port`]), behind its 4-byte little-endian length.
///
/// # Safety
/// As [`ncsight_scene`].
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ncsight_port(
    text: *const u8,
    text_len: usize,
    machine: *const u8,
    machine_len: usize,
    params: *const u8,
    params_len: usize,
    setup: *const u8,
    setup_len: usize,
    options: *const u8,
    options_len: usize,
    library: *const u8,
    library_len: usize,
) -> *mut u8 {
    // SAFETY: the caller guarantees the six buffers (see above).
    unsafe {
        page_call([(text, text_len), (machine, machine_len), (params, params_len), (setup, setup_len), (options, options_len), (library, library_len)], port)
    }
}

/// The cut stock of a programme for the page's 3D view (see [`stock`]), behind its 4-byte
/// little-endian length.
///
/// # Safety
/// As [`ncsight_scene`].
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ncsight_stock(
    text: *const u8,
    text_len: usize,
    machine: *const u8,
    machine_len: usize,
    params: *const u8,
    params_len: usize,
    setup: *const u8,
    setup_len: usize,
    options: *const u8,
    options_len: usize,
    library: *const u8,
    library_len: usize,
) -> *mut u8 {
    // SAFETY: the caller guarantees the six buffers (see above).
    unsafe {
        page_call([(text, text_len), (machine, machine_len), (params, params_len), (setup, setup_len), (options, options_len), (library, library_len)], stock)
    }
}
