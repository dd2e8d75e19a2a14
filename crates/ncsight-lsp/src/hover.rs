//! Hover: what the word under the cursor means on this controller in this block (words.toml,
//! written from the manuals' sections the docs cite), and the block's surroundings: the modal
//! state before it, where the tool is, the time so far and the block's own.

use crate::analysis::BlockState;
use crate::config::RunConfig;
use crate::text::{self, Word};
use serde::Deserialize;
use std::sync::OnceLock;

#[derive(Debug, Deserialize)]
struct Catalogue {
    #[serde(default)]
    code: Vec<CodeEntry>,
    #[serde(default)]
    address: Vec<AddressEntry>,
}

#[derive(Debug, Deserialize)]
pub struct CodeEntry {
    pub code: String,
    pub profiles: Vec<String>,
    #[serde(default)]
    pub when_has: Option<String>,
    #[serde(default)]
    pub when_lacks: Option<String>,
    pub title_en: String,
    pub title_zh: String,
    pub source: String,
    pub words: std::collections::BTreeMap<String, Meaning>,
}

#[derive(Debug, Deserialize)]
pub struct Meaning {
    pub en: String,
    pub zh: String,
}

#[derive(Debug, Deserialize)]
pub struct AddressEntry {
    pub profiles: Vec<String>,
    pub letter: String,
    pub en: String,
    pub zh: String,
}

fn catalogue() -> &'static Catalogue {
    static WORDS: OnceLock<Catalogue> = OnceLock::new();
    // A test holds words.toml well formed (`the_catalogue_reads`).
    WORDS.get_or_init(|| toml::from_str(include_str!("words.toml")).unwrap_or(Catalogue { code: Vec::new(), address: Vec::new() }))
}

/// A G or M code as the catalogue writes it: `G1` -> `G01`, `G32.1` stays, `M98`.
fn code_name(w: &Word) -> Option<String> {
    let letter = w.address.to_ascii_uppercase();
    if letter != "G" && letter != "M" {
        return None;
    }
    let v = w.value;
    let (int, frac) = v.split_once('.').unwrap_or((v, ""));
    let n: u32 = int.parse().ok()?;
    Some(if frac.is_empty() { format!("{letter}{n:02}") } else { format!("{letter}{n:02}.{frac}") })
}

/// The catalogue's entry for `code` on `machine` in a block with `words`.
fn entry_for<'c>(code: &str, machine: &str, words: &[Word]) -> Option<&'c CodeEntry> {
    let has = |a: &str| words.iter().any(|w| w.address.eq_ignore_ascii_case(a));
    let same = |a: &str, b: &str| {
        a.eq_ignore_ascii_case(b)
            || a.trim_start_matches(['G', 'M']).trim_start_matches('0') == b.trim_start_matches(['G', 'M']).trim_start_matches('0')
                && a.as_bytes().first() == b.as_bytes().first()
    };
    catalogue().code.iter().find(|e| {
        same(&e.code, code)
            && e.profiles.iter().any(|p| p == machine)
            && e.when_has.as_deref().map_or(true, has)
            && e.when_lacks.as_deref().map_or(true, |a| !has(a))
    })
}

/// The code whose words a block's words are: the block's own cycle code, else the cycle in force
/// (found by reading back to the block that set it: a group 01 code or a drilling cycle, up to
/// G80 or another motion code).
fn block_code(lines: &text::Lines, n: usize, machine: &str) -> Option<(String, usize)> {
    let here = text::words(lines.line(n));
    for k in (0..=n).rev().take(2000) {
        let words = text::words(lines.line(k));
        let codes: Vec<String> = words.iter().filter_map(code_name).collect();
        // The block's own code with an entry (M98 before the G codes it may carry).
        for c in codes.iter().rev() {
            if c.starts_with('G') && (c == "G80" || (k != n && matches!(c.as_str(), "G00" | "G01" | "G02" | "G03"))) {
                return None;
            }
            if entry_for(c, machine, &here).is_some() {
                return Some((c.clone(), k));
            }
        }
    }
    None
}

/// The hover text for byte column `col` of line `n` (0-based), in Markdown.
pub fn hover(lines: &text::Lines, n: usize, col: usize, cfg: &RunConfig, state: Option<&BlockState>) -> Option<String> {
    if n >= lines.count() {
        return None;
    }
    let line = lines.line(n);
    let words = text::words(line);
    let word = text::word_at(&words, col);
    let mut out = String::new();
    if let Some(w) = word {
        out.push_str(&word_text(w, &words, lines, n, &cfg.machine));
    }
    if let Some(s) = state {
        if !out.is_empty() {
            out.push_str("\n\n---\n\n");
        }
        out.push_str(&state_text(s, cfg));
    }
    (!out.is_empty()).then_some(out)
}

fn word_text(w: &Word, words: &[Word], lines: &text::Lines, n: usize, machine: &str) -> String {
    let addr = w.address.to_ascii_uppercase();
    if let Some(code) = code_name(w) {
        if let Some(e) = entry_for(&code, machine, words) {
            return format!("**{code}** {} ({})\n\n{}\n\n_{}_", e.title_en, machine, e.title_zh, e.source);
        }
        return format!("**{code}** on {machine}");
    }
    if let Some((code, at)) = block_code(lines, n, machine) {
        if let Some(e) = entry_for(&code, machine, words) {
            if let Some(m) = e.words.get(&addr) {
                let from = if at == n { String::new() } else { format!(", in force since line {}", at + 1) };
                return format!("**{addr}{}** in {code}{from}: {}\n\n{}\n\n_{} · {}_", w.value, m.en, m.zh, e.title_en, e.source);
            }
        }
    }
    match catalogue().address.iter().find(|a| a.letter.eq_ignore_ascii_case(&addr) && a.profiles.iter().any(|p| p == machine)) {
        Some(a) => format!("**{addr}{}**: {}\n\n{}", w.value, a.en, a.zh),
        None => format!("**{addr}{}**", w.value),
    }
}

fn motion_name(m: &ncsight::modal::Motion) -> String {
    use ncsight::modal::Motion;
    match m {
        Motion::Rapid => "G00".into(),
        Motion::Linear => "G01".into(),
        Motion::ArcCw => "G02".into(),
        Motion::ArcCcw => "G03".into(),
        other => format!("{other:?}"),
    }
}

/// The modal state before the block, the tool's position after it, and the times.
fn state_text(s: &BlockState, cfg: &RunConfig) -> String {
    let Some(st) = &s.before else { return String::new() };
    let feed = match st.modes.feed {
        Some(f) if st.modes.per_rev => format!("F{} mm/rev ({})", num(f), if s.lathe { "G99" } else { "G95" }),
        Some(f) => format!("F{} mm/min ({})", num(f), if s.lathe { "G98" } else { "G94" }),
        None => format!(
            "no F yet ({})",
            if st.modes.per_rev {
                if s.lathe {
                    "G99"
                } else {
                    "G95"
                }
            } else if s.lathe {
                "G98"
            } else {
                "G94"
            }
        ),
    };
    let spindle = match st.modes.spindle {
        ncsight::modal::SpindleDir::Stopped => "spindle stopped".to_string(),
        ncsight::modal::SpindleDir::Positive => format!("M03 S{}", num(st.modes.s_word)),
        ncsight::modal::SpindleDir::Negative => format!("M04 S{}", num(st.modes.s_word)),
    } + if st.modes.css { " m/min (G96)" } else { " rpm (G97)" };
    let tool = if s.lathe { format!("T{:02}{:02}", st.modes.tool, st.frame.offset_number) } else { format!("T{} H{}", st.modes.tool, st.frame.offset_number) };
    let distance = if s.lathe {
        "X Z absolute, U W incremental"
    } else if st.modes.incremental {
        "G91 incremental"
    } else {
        "G90 absolute"
    };
    let pos = |p: ncsight::Vec3| if s.lathe { format!("X{} (Ø) Z{}", num(2.0 * p.x), num(p.z)) } else { format!("X{} Y{} Z{}", num(p.x), num(p.y), num(p.z)) };
    format!(
        "**Before this block** on {} ({}): {} · {} · G{} · {} · {} · plane {:?} · {}\n\nTool at {} before, {} after · time so far {}, this block {}",
        cfg.machine,
        cfg.from,
        motion_name(&st.modes.motion),
        tool,
        53 + u32::from(st.frame.work),
        feed,
        spindle,
        st.modes.plane,
        distance,
        pos(st.place.pos),
        s.after_pos.map(pos).unwrap_or_default(),
        hms(s.t_before_s),
        hms(s.t_block_s)
    )
}

fn num(v: f64) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Seconds as h:mm:ss.s.
pub fn hms(s: f64) -> String {
    let t = (s * 10.0).round() / 10.0;
    let h = (t / 3600.0).floor();
    let m = ((t - h * 3600.0) / 60.0).floor();
    let sec = t - h * 3600.0 - m * 60.0;
    if h > 0.0 {
        format!("{h}:{m:02}:{sec:04.1}")
    } else {
        format!("{m}:{sec:04.1}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_reads() {
        let c: Catalogue = toml::from_str(include_str!("words.toml")).expect("words.toml");
        assert!(!c.code.is_empty() && !c.address.is_empty());
        for e in &c.code {
            for p in &e.profiles {
                assert!(ncsight::profile::by_name(p).is_some(), "{}: no profile {p}", e.code);
            }
            assert!(!e.words.is_empty() || e.code.starts_with('M') || e.code.starts_with('G'), "{}", e.code);
        }
    }

    #[test]
    fn g71_words_by_block() {
        let text = "G0 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\n";
        let lines = text::Lines::new(text);
        let cfg = RunConfig { machine: "gsk980tdi".into(), ..RunConfig::default() };
        let first = hover(&lines, 1, 4, &cfg, None).unwrap();
        let second = hover(&lines, 2, 12, &cfg, None).unwrap();
        assert!(first.starts_with("**U1.5** in G71"), "{first}");
        assert!(second.starts_with("**U0.4** in G71"), "{second}");
        assert_ne!(first.lines().next(), second.lines().next());
    }
}
