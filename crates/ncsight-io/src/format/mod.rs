//! Output formats: consumers of the event stream. Each writes as events arrive.

mod canon;
pub mod expand;
pub mod jsonl;
pub mod scene;
pub mod stock;
mod text;

pub use canon::Canon;
pub use jsonl::Jsonl;
pub use text::Text;

use ncsight::{Event, Profile};
use std::fmt::Write as _;
use std::io::{self, Write};

/// A consumer that renders events to a writer.
pub trait Format {
    /// One event; `file` names the file of its line when that is not the file the run began
    /// with (a subprogramme from `--subprogram-dir`).
    fn event(&mut self, e: &Event, file: Option<&str>, w: &mut dyn Write) -> io::Result<()>;
    /// Whether diagnostics are part of this format's output (otherwise they go to stderr).
    fn carries_diagnostics(&self) -> bool;
    /// Warnings the format itself has about the events so far (what its target cannot express
    /// exactly), to be shown with the line being run. None for most formats.
    fn take_notes(&mut self) -> Vec<ncsight::Diagnostic> {
        Vec::new()
    }
    /// The events have ended (the programme's end, an alarm, a refusal): write what closes the
    /// output. `why` says why it stopped early, if it did.
    fn finish(&mut self, _why: Option<&str>, _w: &mut dyn Write) -> io::Result<()> {
        Ok(())
    }
}

/// The format of that name for a profile.
pub fn by_name(name: &str, profile: &'static Profile, machine_positions: bool) -> Option<Box<dyn Format>> {
    match name {
        "text" => Some(Box::new(Text::new(profile))),
        "jsonl" => Some(Box::new(Jsonl::new(profile, machine_positions))),
        "canon" => Some(Box::new(Canon::new(profile))),
        _ => None,
    }
}

/// Which of X, Y, Z a format shows: the machine's axes, and any other once a programme moves it
/// (the GSK988T's arc threads in G17/G19 on a machine with a Y axis), from then on.
pub struct ShownAxes(std::cell::Cell<[bool; 3]>);

impl ShownAxes {
    pub fn new(profile: &Profile) -> ShownAxes {
        ShownAxes(std::cell::Cell::new(['X', 'Y', 'Z'].map(|a| profile.axes.contains(a))))
    }

    /// Whether axis 0..3 is shown at point `p`.
    pub fn show(&self, axis: usize, p: &ncsight::Vec3) -> bool {
        let mut shown = self.0.get();
        if !shown[axis] {
            if p.axis(axis).abs() < 1e-9 {
                return false;
            }
            shown[axis] = true;
            self.0.set(shown);
        }
        true
    }
}

/// A number with at most `decimals` decimals, trailing zeros trimmed, never `-0`.
pub fn num(v: f64, decimals: usize) -> String {
    let mut s = String::new();
    push_num(&mut s, v, decimals);
    s
}

/// A number with exactly `decimals` decimals, never `-0.0000`.
pub fn fixed(v: f64, decimals: usize) -> String {
    let mut s = String::new();
    push_fixed(&mut s, v, decimals);
    s
}

/// Append [`num`]`(v, decimals)`.
pub fn push_num(out: &mut String, v: f64, decimals: usize) {
    let start = out.len();
    push_fixed(out, v, decimals);
    if out[start..].contains('.') {
        let kept = out.trim_end_matches('0').trim_end_matches('.').len();
        out.truncate(kept);
    }
    if &out[start..] == "-0" {
        out.truncate(start);
        out.push('0');
    }
}

/// Append [`fixed`]`(v, decimals)`: the digits `format!("{v:.decimals$}")` prints, computed
/// exactly in integers for the usual range (the formatter's own path otherwise).
pub fn push_fixed(out: &mut String, v: f64, decimals: usize) {
    let Some(scaled) = scaled_abs(v, decimals) else {
        let start = out.len();
        write!(out, "{v:.decimals$}").expect("a String takes any text");
        if out[start..].starts_with('-') && out[start + 1..].bytes().all(|c| c == b'0' || c == b'.') {
            out.remove(start);
        }
        return;
    };
    // Right to left: the fraction, the point, the integer part, the sign.
    let mut buf = [0u8; 32];
    let mut at = buf.len();
    let pow = POW10[decimals];
    if decimals > 0 {
        at = write_digits(&mut buf, at, scaled % pow, decimals);
        at -= 1;
        buf[at] = b'.';
    }
    let int_part = scaled / pow;
    let int_digits = int_part.checked_ilog10().unwrap_or(0) as usize + 1;
    at = write_digits(&mut buf, at, int_part, int_digits);
    if v.is_sign_negative() && scaled != 0 {
        at -= 1;
        buf[at] = b'-';
    }
    out.push_str(std::str::from_utf8(&buf[at..]).expect("ASCII digits"));
}

/// "00", "01", ..., "99".
const DIGIT_PAIRS: [u8; 200] = {
    let mut t = [0u8; 200];
    let mut i = 0;
    while i < 100 {
        t[2 * i] = b'0' + (i / 10) as u8;
        t[2 * i + 1] = b'0' + (i % 10) as u8;
        i += 1;
    }
    t
};

/// Write the last `count` decimal digits of `n` (zero-padded) ending before `end`, two at a
/// time; returns where they start.
fn write_digits(buf: &mut [u8], end: usize, mut n: u64, count: usize) -> usize {
    let mut at = end;
    let start = end - count;
    while at - start >= 2 {
        let pair = (n % 100) as usize * 2;
        n /= 100;
        at -= 2;
        buf[at..at + 2].copy_from_slice(&DIGIT_PAIRS[pair..pair + 2]);
    }
    if at > start {
        at -= 1;
        buf[at] = b'0' + (n % 10) as u8;
    }
    at
}

const POW10: [u64; 10] = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000, 100_000_000, 1_000_000_000];

/// |v| * 10^decimals rounded half to even from the exact binary value (as `format!` rounds),
/// when it fits a u64 and `decimals` is at most 9; `None` otherwise (also NaN and infinities).
fn scaled_abs(v: f64, decimals: usize) -> Option<u64> {
    if decimals >= POW10.len() || v.is_nan() || v.abs() >= 1e9 {
        return None;
    }
    let bits = v.abs().to_bits();
    let (exp, frac) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
    // v = mantissa * 2^-shift exactly, shift > 0 since |v| < 2^30.
    let (mantissa, shift) = if exp == 0 { (frac, 1074) } else { (frac | 1 << 52, 1075 - exp) };
    let scaled = mantissa as u128 * POW10[decimals] as u128;
    if shift >= 127 {
        return Some(0); // scaled < 2^83: less than half a unit
    }
    let (q, rem, half) = (scaled >> shift, scaled & ((1u128 << shift) - 1), 1u128 << (shift - 1));
    let rounded = if rem > half || (rem == half && q & 1 == 1) { q + 1 } else { q };
    Some(rounded as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert_eq!(num(65.0, 4), "65");
        assert_eq!(num(58.7, 4), "58.7");
        assert_eq!(num(-0.00001, 4), "0");
        assert_eq!(num(1.23456, 4), "1.2346");
        assert_eq!(fixed(-0.00001, 4), "0.0000");
        assert_eq!(fixed(-1.5, 4), "-1.5000");
    }

    /// The integer path prints what `format!` prints: random values, halves and ties.
    #[test]
    fn same_digits_as_format() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            1.5,
            2.5,
            -2.5,
            0.00005,
            0.03125,
            -0.03125,
            1e-300,
            5e-324,
            999_999_999.99999,
            1e9,
            -1e9,
            1e20,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for _ in 0..20_000 {
            let r = next();
            values.push(f64::from_bits(r));
            values.push((r % 2_000_000_001) as f64 / 1000.0 - 1e6);
            // Exact ties at 4 to 6 decimals: k / 2^n.
            values.push((r % 1_000_000) as f64 / f64::from(1u32 << (r % 20)));
            values.push((r as i64 as f64) * 1e-15);
        }
        for v in values {
            for d in 0..=9 {
                let want = format!("{v:.d$}");
                let want_fixed = if want.starts_with('-') && want[1..].bytes().all(|c| c == b'0' || c == b'.') { want[1..].to_string() } else { want };
                assert_eq!(fixed(v, d), want_fixed, "{v:e} at {d}");
            }
        }
    }
}
