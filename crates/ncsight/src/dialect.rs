//! Programmes written for another control: one clear answer instead of a cascade of alarms
//! (issue 10). Okuma OSP and Sinumerik programmes reuse the G numbers of FANUC's cycles with other
//! meanings (Okuma OSP7000L: G85 rough turning, G87 finish turning, G81/G80 a contour's start and
//! end; Sinumerik 850: G71 metric, R-parameter drilling cycles), LinuxCNC programmes use `o` words
//! and `#<name>` parameters. A line that only another dialect writes names it.

/// A dialect other than the profile's, recognised on a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Foreign {
    OkumaOsp,
    Sinumerik,
    LinuxCnc,
}

impl Foreign {
    pub fn name(self) -> &'static str {
        match self {
            Foreign::OkumaOsp => "an Okuma OSP programme",
            Foreign::Sinumerik => "a Siemens Sinumerik programme",
            Foreign::LinuxCnc => "a LinuxCNC (RS274NGC) programme",
        }
    }
}

fn starts_with_ci(s: &[u8], p: &str) -> bool {
    s.len() >= p.len() && s[..p.len()].eq_ignore_ascii_case(p.as_bytes())
}

fn contains_ci(s: &[u8], p: &str) -> bool {
    s.windows(p.len()).any(|w| w.eq_ignore_ascii_case(p.as_bytes()))
}

/// The text of a line outside its `( )` comments.
fn outside_comments(line: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(line.len());
    let mut depth = 0;
    for &b in line {
        match b {
            b'(' => depth += 1,
            b')' if depth > 0 => depth -= 1,
            _ if depth == 0 => out.push(b),
            _ => {}
        }
    }
    out
}

/// Whether the line is written in another control's language, and which.
pub fn sniff(line: &[u8]) -> Option<Foreign> {
    let code = outside_comments(line);
    let t: &[u8] = {
        let s = code.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(code.len());
        &code[s..]
    };
    if t.is_empty() {
        return None;
    }
    // Okuma OSP: `$NAME.MIN%` file headers, `NAT..` labels, `V` system variables with brackets,
    // `CALL O...` subprogrammes, `DEF WORK` / `DRAW` blocks.
    if (t[0] == b'$' && contains_ci(t, ".MIN")) || starts_with_ci(t, "NAT") && t.get(3).is_some_and(|c| c.is_ascii_digit()) {
        return Some(Foreign::OkumaOsp);
    }
    if contains_ci(t, "CALL O") || starts_with_ci(t, "DEF WORK") || starts_with_ci(t, "DRAW") || contains_ci(t, "VGRIN[") {
        return Some(Foreign::OkumaOsp);
    }
    // Sinumerik: `%MPF`/`%SPF` headers, `R1=` parameters, `@` commands.
    if starts_with_ci(t, "%MPF") || starts_with_ci(t, "%SPF") || t[0] == b'@' {
        return Some(Foreign::Sinumerik);
    }
    let r_assign =
        t.windows(3).any(|w| (w[0] == b'R' || w[0] == b'r') && w[1].is_ascii_digit() && (w[2] == b'=' || (w[2].is_ascii_digit()))) && t.contains(&b'=');
    if r_assign && !t.contains(&b'#') {
        return Some(Foreign::Sinumerik);
    }
    // LinuxCNC: `o100 sub`, `#<name>`.
    if (t[0] == b'o' || t[0] == b'O') && [" sub", " endsub", " call", " if", " while", " endif", " else", " do"].iter().any(|k| contains_ci(t, k))
        || contains_ci(t, "#<")
    {
        return Some(Foreign::LinuxCnc);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dialects() {
        assert_eq!(sniff(b"$BR0137.MIN%"), Some(Foreign::OkumaOsp));
        assert_eq!(sniff(b"NAT00 G85 N0207 D7"), Some(Foreign::OkumaOsp));
        assert_eq!(sniff(b"CALL OCHEK"), Some(Foreign::OkumaOsp));
        assert_eq!(sniff(b"%MPF  90"), Some(Foreign::Sinumerik));
        assert_eq!(sniff(b"G81 R2=2 R3=-10 R10=5"), Some(Foreign::Sinumerik));
        assert_eq!(sniff(b"@371 R52 K2 K0"), Some(Foreign::Sinumerik));
        assert_eq!(sniff(b"o100 sub"), Some(Foreign::LinuxCnc));
        assert_eq!(sniff(b"g0 x#<OD>"), Some(Foreign::LinuxCnc));
        for fanuc in [&b"G92 X58.7 Z-28 F3 J3 K1"[..], b"N10 G81 X10. R2. Z-5. F100.", b"O0012 (R1=5 in a comment)", b"G2 X10 R5.", b"%", b"#1=5"] {
            assert_eq!(sniff(fanuc), None, "{}", String::from_utf8_lossy(fanuc));
        }
    }
}
