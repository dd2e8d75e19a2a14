//! Lines written for a school's CNC simulator rather than for a controller (issue 35): many
//! training programmes begin with the stock as Denford's simulators read it, `[BILLET X50 Z100`
//! (a turned bar: X its diameter, Z its length) or `[BILLET X100 Y80 Z20` (a milled block). No
//! controller takes such a line (a FANUC stops at the `[`); ncsight reads the stock from it, says
//! with a warning that the line is not for a controller, and goes on with the next line.

/// The stock a `[BILLET` line gives, in millimetres as written (the line comes before any G20,
/// so its unit is not known when it is read: millimetres assumed, docs/setup.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Billet {
    /// A bar's diameter, or a block's length along X.
    pub x_mm: f64,
    /// A block's width along Y (milling simulators only).
    pub y_mm: Option<f64>,
    /// A bar's length, or a block's height.
    pub z_mm: f64,
}

impl Billet {
    /// The stock as `--stock` writes it: `DIAxLEN` on a lathe, `XxYxZ` on a machining centre
    /// (`None` when a block's Y is missing).
    pub fn stock_text(&self, lathe: bool) -> Option<String> {
        if lathe {
            return Some(format!("{}x{}", self.x_mm, self.z_mm));
        }
        self.y_mm.map(|y| format!("{}x{}x{}", self.x_mm, y, self.z_mm))
    }
}

/// The length of `[BILLET` at the start of a line (after blanks, any case), if it starts so.
pub fn billet_mark(s: &[u8]) -> Option<usize> {
    let start = s.iter().take_while(|b| b.is_ascii_whitespace()).count();
    let rest = &s[start..];
    (rest.len() >= 7 && rest[0] == b'[' && rest[1..7].eq_ignore_ascii_case(b"BILLET")).then_some(start + 7)
}

/// The stock of a `[BILLET X_ [Y_] Z_` line: each address once, a positive number after it
/// (spaces between words optional); anything else (another word, a comment) makes it unreadable.
pub fn billet(line: &[u8]) -> Option<Billet> {
    let mut at = billet_mark(line)?;
    let (mut x, mut y, mut z) = (None, None, None);
    loop {
        while at < line.len() && line[at].is_ascii_whitespace() {
            at += 1;
        }
        let Some(&letter) = line.get(at) else { break };
        let slot = match letter.to_ascii_uppercase() {
            b'X' => &mut x,
            b'Y' => &mut y,
            b'Z' => &mut z,
            b']' if line[at + 1..].iter().all(|b| b.is_ascii_whitespace()) => break,
            _ => return None,
        };
        let digits = line[at + 1..].iter().take_while(|b| b.is_ascii_digit() || **b == b'.' || **b == b'+').count();
        let value: f64 = std::str::from_utf8(&line[at + 1..at + 1 + digits]).ok()?.parse().ok()?;
        if slot.is_some() || !(value > 0.0 && value.is_finite()) {
            return None;
        }
        *slot = Some(value);
        at += 1 + digits;
    }
    Some(Billet { x_mm: x?, y_mm: y, z_mm: z? })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bar_and_a_block() {
        assert_eq!(billet(b"[BILLET X42.86 Z82"), Some(Billet { x_mm: 42.86, y_mm: None, z_mm: 82.0 }));
        assert_eq!(billet(b"  [billet x100 y80 z20]\r"), Some(Billet { x_mm: 100.0, y_mm: Some(80.0), z_mm: 20.0 }));
        assert_eq!(billet(b"[BILLETX55Z81"), Some(Billet { x_mm: 55.0, y_mm: None, z_mm: 81.0 }));
        assert_eq!(billet(b"[BILLET X42.86 Z82").unwrap().stock_text(true).as_deref(), Some("42.86x82"));
    }

    #[test]
    fn what_is_not_a_stock() {
        for bad in [&b"[BILLET X42.86"[..], b"[BILLET X-4 Z8", b"[BILLET X4 X5 Z8", b"[BILLET X4 Z8 G0", b"[EDGEMOVE X4", b"X[1]"] {
            assert_eq!(billet(bad), None, "{}", String::from_utf8_lossy(bad));
        }
    }
}
