//! Output formats: consumers of the event stream. Each writes as events arrive.

mod canon;
pub mod jsonl;
mod text;

pub use canon::Canon;
pub use jsonl::Jsonl;
pub use text::Text;

use ncsight::{Event, Profile};
use std::io::{self, Write};

/// A consumer that renders events to a writer.
pub trait Format {
    fn event(&mut self, e: &Event, w: &mut dyn Write) -> io::Result<()>;
    /// Whether diagnostics are part of this format's output (otherwise they go to stderr).
    fn carries_diagnostics(&self) -> bool;
}

/// The format of that name for a profile.
pub fn by_name(name: &str, profile: &'static Profile) -> Option<Box<dyn Format>> {
    match name {
        "text" => Some(Box::new(Text::new(profile))),
        "jsonl" => Some(Box::new(Jsonl::new(profile))),
        "canon" => Some(Box::new(Canon::new(profile))),
        _ => None,
    }
}

/// A number with at most `decimals` decimals, trailing zeros trimmed, never `-0`.
pub fn num(v: f64, decimals: usize) -> String {
    let mut s = format!("{v:.decimals$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    s
}

/// A number with exactly `decimals` decimals, never `-0.0000`.
pub fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].bytes().all(|c| c == b'0' || c == b'.') {
        s[1..].to_string()
    } else {
        s
    }
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
}
