//! Going to definitions and references, and the document's outline: M98 P / Q, M99 P, G65 P,
//! G66 P, GOTO n and G70-G73 P / Q to their O and N blocks, across the files of the
//! subprogramme folders; programmes, the N labels jumped to, tool changes and cycles.

use crate::text::{self, Encoding, Lines, Word};
use lsp_types::{DocumentSymbol, Location, Range, SymbolKind, Url};
use std::path::{Path, PathBuf};

/// What a word points at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A programme O`n`.
    Programme(u64),
    /// A block N`n` of the same programme.
    Sequence(u64),
}

fn has_code(words: &[Word], letter: &str, codes: &[u32]) -> bool {
    words.iter().any(|w| {
        w.address.eq_ignore_ascii_case(letter)
            && w.value.split('.').next().and_then(|v| v.parse::<u32>().ok()).is_some_and(|v| codes.contains(&v) && !w.value.contains('.'))
    })
}

/// The target of word `w` in a block of `words` (the controller does not change how a call is
/// written, the kind of machine does: G70-G73 P/Q are sequence numbers on lathes only).
pub fn target_of(w: &Word, words: &[Word], _machine: &str, lathe: bool) -> Option<Target> {
    let addr = w.address.to_ascii_uppercase();
    let n = w.integer()?;
    match addr.as_str() {
        "GOTO" => Some(Target::Sequence(n)),
        "O" => Some(Target::Programme(n)),
        "N" => Some(Target::Sequence(n)),
        "P" if has_code(words, "M", &[98]) => {
            // M98 P○○○○□□□□ without L: the count before the four-digit programme number, as the
            // engine reads it on every profile (GSK980TDi manual, M98); with L (FANUC's
            // M98 P_ L_), P is the number.
            let digits = w.value.trim_start_matches('+');
            let has_l = words.iter().any(|x| x.address.eq_ignore_ascii_case("L"));
            let number = if !has_l && digits.len() > 4 { digits[digits.len() - 4..].parse().ok()? } else { n };
            Some(Target::Programme(number))
        }
        "Q" if has_code(words, "M", &[98]) => Some(Target::Sequence(n)),
        "P" if has_code(words, "M", &[99]) => Some(Target::Sequence(n)),
        "P" if has_code(words, "G", &[65, 66]) => Some(Target::Programme(n)),
        "P" | "Q" if lathe && has_code(words, "G", &[70, 71, 72, 73]) => Some(Target::Sequence(n)),
        _ => None,
    }
}

/// Where target `t` is in the document (the line and the word's bytes), the search for a
/// sequence number starting in the programme that holds line `from`.
pub fn find_in(lines: &Lines, t: Target, from: usize) -> Option<(usize, usize, usize)> {
    match t {
        Target::Programme(n) => (0..lines.count()).find_map(|k| {
            let l = lines.line(k);
            (text::programme_number(l) == Some(n)).then(|| {
                let start = l.len() - l.trim_start().len();
                (k, start, start + 1 + l.trim_start()[1..].bytes().take_while(u8::is_ascii_digit).count())
            })
        }),
        Target::Sequence(n) => {
            // The programme holding `from`: from its O line to the next (a controller searches
            // its own programme).
            let top = (0..=from.min(lines.count().saturating_sub(1))).rev().find(|&k| text::programme_number(lines.line(k)).is_some()).unwrap_or(0);
            let end = (top + 1..lines.count()).find(|&k| text::programme_number(lines.line(k)).is_some()).unwrap_or(lines.count());
            (top..end).find_map(|k| text::sequence_number(lines.line(k)).filter(|s| s.0 == n).map(|(_, a, b)| (k, a, b)))
        }
    }
}

/// A programme in the subprogramme folders: the file named after it (O1234, o1234.nc, ...) or
/// the first file (in name order) with a line O1234; and where its O word is.
pub fn find_programme_file(dirs: &[PathBuf], n: u64, skip: Option<&Path>) -> Option<(PathBuf, usize, usize, usize)> {
    let mut files: Vec<PathBuf> = dirs
        .iter()
        .filter_map(|d| std::fs::read_dir(d).ok())
        .flat_map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()))
        .filter(|p| p.is_file() && Some(p.as_path()) != skip)
        .collect();
    files.sort();
    let stem_number = |p: &Path| p.file_stem().and_then(|s| s.to_str()).and_then(|s| s.strip_prefix(['O', 'o'])).and_then(|d| d.parse::<u64>().ok());
    files.sort_by_key(|p| stem_number(p) != Some(n));
    for f in files {
        // Programme files are small; a large other file is passed over.
        if std::fs::metadata(&f).map_or(true, |m| m.len() > 8 << 20) {
            continue;
        }
        let Ok(bytes) = std::fs::read(&f) else { continue };
        let text = String::from_utf8_lossy(&bytes);
        let lines = Lines::new(&text);
        if let Some((k, a, b)) = find_in(&lines, Target::Programme(n), 0) {
            return Some((f, k, a, b));
        }
    }
    None
}

/// Every word of the document that points at `t` (calls and jumps), as (line, from, to).
pub fn references(lines: &Lines, t: Target, machine: &str, lathe: bool) -> Vec<(usize, usize, usize)> {
    let mut out = Vec::new();
    for k in 0..lines.count() {
        let words = text::words(lines.line(k));
        for w in &words {
            if w.address.eq_ignore_ascii_case("N") || w.address.eq_ignore_ascii_case("O") {
                continue;
            }
            if target_of(w, &words, machine, lathe) == Some(t) {
                out.push((k, w.from, w.to));
            }
        }
    }
    out
}

/// Symbols the outline shows at most (a long programme has an N on every line).
pub const MAX_SYMBOLS: usize = 5000;

/// The outline: each programme (O), holding the N labels that something jumps to, the tool
/// changes and the cycles and calls.
#[allow(deprecated)] // DocumentSymbol's `deprecated` field must be written
pub fn symbols(lines: &Lines, enc: Encoding, machine: &str, lathe: bool) -> Vec<DocumentSymbol> {
    let jumped: std::collections::HashSet<u64> = (0..lines.count())
        .flat_map(|k| {
            let words = text::words(lines.line(k));
            words
                .iter()
                .filter_map(|w| match target_of(w, &words, machine, lathe) {
                    Some(Target::Sequence(n)) if !w.address.eq_ignore_ascii_case("N") => Some(n),
                    _ => None,
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let mut top: Vec<DocumentSymbol> = Vec::new();
    let mut count = 0;
    let sym = |name: String, detail: Option<String>, kind: SymbolKind, range: Range| DocumentSymbol {
        name,
        detail,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range: range,
        children: None,
    };
    for k in 0..lines.count() {
        if count >= MAX_SYMBOLS {
            break;
        }
        let line = lines.line(k);
        let whole = lines.range(k, 0, line.len(), enc);
        if let Some(n) = text::programme_number(line) {
            let comment = line.find('(').map(|a| line[a + 1..].trim_end_matches(')').trim().to_string());
            top.push(sym(format!("O{n:04}"), comment, SymbolKind::MODULE, whole));
            count += 1;
            continue;
        }
        let words = text::words(line);
        let mut add = |s: DocumentSymbol| {
            count += 1;
            match top.last_mut() {
                Some(p) if p.kind == SymbolKind::MODULE => {
                    p.range.end = s.range.end;
                    p.children.get_or_insert_with(Vec::new).push(s);
                }
                _ => top.push(s),
            }
        };
        if let Some((n, _, _)) = text::sequence_number(line).filter(|(n, _, _)| jumped.contains(n)) {
            add(sym(format!("N{n}"), None, SymbolKind::KEY, whole));
        }
        for w in &words {
            let a = w.address.to_ascii_uppercase();
            let cycle =
                a == "G" && matches!(w.value.split('.').next().and_then(|v| v.parse::<u32>().ok()), Some(32 | 33 | 34 | 65 | 66 | 70..=89 | 90 | 92 | 94));
            let call = a == "M" && matches!(w.value.parse::<u32>().ok(), Some(98));
            if a == "T" || cycle || call {
                let kind = if a == "T" { SymbolKind::OBJECT } else { SymbolKind::EVENT };
                add(sym(line[w.from..w.to].trim().to_string(), Some(line.trim().to_string()), kind, whole));
            }
        }
    }
    top
}

/// A location in another file, from its path.
pub fn location(path: &Path, range: Range) -> Option<Location> {
    Some(Location { uri: Url::from_file_path(path).ok()?, range })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn calls_and_jumps_find_their_blocks() {
        let text = "O0001\nN10 G0 X20.\nM98 P0021234\nG71 P10 Q20 U0.4\nN20 G1 Z-5.\nM30\nO1234\nN5 G0 X1.\nM99\n";
        let lines = Lines::new(text);
        let w = text::words(lines.line(2));
        assert_eq!(target_of(&w[1], &w, "gsk980tdi", true), Some(Target::Programme(1234)));
        // The same without L on the FANUC (the engine reads the count before the number there
        // too); with L, P is the number.
        assert_eq!(target_of(&w[1], &w, "fanuc0t", true), Some(Target::Programme(1234)));
        let l = text::words("M98 P21234 L3");
        assert_eq!(target_of(&l[1], &l, "fanuc0t", true), Some(Target::Programme(21234)));
        assert_eq!(find_in(&lines, Target::Programme(1234), 0).map(|f| f.0), Some(6));
        let w = text::words(lines.line(3));
        assert_eq!(target_of(&w[2], &w, "gsk980tdi", true), Some(Target::Sequence(20)));
        assert_eq!(find_in(&lines, Target::Sequence(20), 3), Some((4, 0, 3)));
        // N5 is in O1234, not found from O0001's blocks.
        assert_eq!(find_in(&lines, Target::Sequence(5), 3), None);
        assert_eq!(references(&lines, Target::Sequence(10), "gsk980tdi", true), vec![(3, 4, 7)]);
        let s = symbols(&lines, Encoding::Utf16, "gsk980tdi", true);
        let names: Vec<_> = s.iter().map(|s| s.name.clone()).collect();
        assert_eq!(names, ["O0001", "O1234"]);
        let children: Vec<_> = s[0].children.as_ref().unwrap().iter().map(|c| c.name.clone()).collect();
        assert_eq!(children, ["N10", "M98", "G71", "N20"]);
    }
}
