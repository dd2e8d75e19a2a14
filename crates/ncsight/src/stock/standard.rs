//! Named threads for `--expect`: ISO metric (`M30x3.5`, `M30` for the coarse pitch), unified
//! (`1/2-13UNC`, `3/4-16UNF`), or explicit `major=60,minor=56.3,pitch=3`. External thread
//! basic dimensions: ISO 68-1 (H = 0.866025 P; minor d3 = d - 1.226869 P) and the unified basic
//! profile (minor = d - 1.299038 P for an external thread).

/// What the thread should be.
#[derive(Debug, Clone, PartialEq)]
pub struct Expected {
    pub name: String,
    pub major_mm: f64,
    pub minor_mm: f64,
    pub pitch_mm: f64,
}

/// ISO 261 coarse pitches of the common sizes.
const ISO_COARSE: &[(f64, f64)] = &[
    (3.0, 0.5),
    (4.0, 0.7),
    (5.0, 0.8),
    (6.0, 1.0),
    (8.0, 1.25),
    (10.0, 1.5),
    (12.0, 1.75),
    (16.0, 2.0),
    (20.0, 2.5),
    (24.0, 3.0),
    (30.0, 3.5),
    (36.0, 4.0),
    (42.0, 4.5),
    (48.0, 5.0),
    (56.0, 5.5),
    (64.0, 6.0),
];

fn number(t: &str) -> Option<f64> {
    let t = t.trim();
    if let Some((a, b)) = t.split_once('/') {
        let (a, b): (f64, f64) = (a.trim().parse().ok()?, b.trim().parse().ok()?);
        return (b != 0.0).then(|| a / b);
    }
    t.parse().ok().filter(|v: &f64| v.is_finite())
}

/// Parse an `--expect` value.
pub fn parse(spec: &str) -> Result<Expected, String> {
    let s = spec.trim();
    let bad = || format!("--expect {spec}: write M30x3.5, M30, 1/2-13UNC, or major=..,minor=..,pitch=..");
    if s.contains('=') {
        let (mut major, mut minor, mut pitch) = (None, None, None);
        for part in s.split(',') {
            let (k, v) = part.split_once('=').ok_or_else(bad)?;
            let v = number(v).ok_or_else(bad)?;
            match k.trim() {
                "major" => major = Some(v),
                "minor" => minor = Some(v),
                "pitch" => pitch = Some(v),
                _ => return Err(bad()),
            }
        }
        let (major, minor, pitch) = (major.ok_or_else(bad)?, minor.ok_or_else(bad)?, pitch.ok_or_else(bad)?);
        if !(pitch > 0.0 && minor > 0.0 && major > minor) {
            return Err(format!("--expect {spec}: the pitch must be more than 0 and the major diameter more than the minor, both more than 0"));
        }
        return Ok(Expected { name: s.into(), major_mm: major, minor_mm: minor, pitch_mm: pitch });
    }
    if let Some(rest) = s.strip_prefix(['M', 'm']) {
        let (d, p) = match rest.split_once(['x', 'X']) {
            Some((d, p)) => (number(d).ok_or_else(bad)?, number(p).ok_or_else(bad)?),
            None => {
                let d = number(rest).ok_or_else(bad)?;
                let p = ISO_COARSE.iter().find(|(s, _)| (*s - d).abs() < 1e-9).map(|(_, p)| *p);
                (d, p.ok_or_else(|| format!("--expect {spec}: no coarse pitch known for M{d}; give it as M{d}xP"))?)
            }
        };
        if !(d > 0.0 && p > 0.0) {
            return Err(bad());
        }
        return Ok(Expected { name: s.into(), major_mm: d, minor_mm: d - 1.226869 * p, pitch_mm: p });
    }
    let upper = s.to_ascii_uppercase();
    for series in ["UNC", "UNF", "UNEF", "UN"] {
        if let Some(body) = upper.strip_suffix(series) {
            let (d, tpi) = body.trim_end_matches('-').split_once('-').ok_or_else(bad)?;
            let d_in = number(d).ok_or_else(bad)?;
            let tpi = number(tpi).ok_or_else(bad)?;
            if !(d_in > 0.0 && tpi > 0.0) {
                return Err(bad());
            }
            let d = d_in * 25.4;
            let p = 25.4 / tpi;
            return Ok(Expected { name: s.into(), major_mm: d, minor_mm: d - 1.299038 * p, pitch_mm: p });
        }
    }
    Err(bad())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        let m = parse("M30x3.5").unwrap();
        assert_eq!((m.major_mm, m.pitch_mm), (30.0, 3.5));
        assert!((m.minor_mm - (30.0 - 1.226869 * 3.5)).abs() < 1e-12);
        assert_eq!(parse("M24").unwrap().pitch_mm, 3.0);
        let u = parse("1/2-13UNC").unwrap();
        assert!((u.major_mm - 12.7).abs() < 1e-12 && (u.pitch_mm - 25.4 / 13.0).abs() < 1e-12);
        let e = parse("major=60,minor=56.3,pitch=3").unwrap();
        assert_eq!(e.minor_mm, 56.3);
        assert!(parse("M7").is_err() && parse("hello").is_err() && parse("M30x0").is_err());
        // Issue 15: no thread of pitch 0, or with the minor above the major.
        assert!(parse("major=60,minor=56.3,pitch=0").is_err() && parse("major=50,minor=56.3,pitch=3").is_err());
    }
}
