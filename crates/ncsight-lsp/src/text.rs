//! The document as an editor sees it: lines, positions in the client's encoding (UTF-16 code
//! units unless the client takes UTF-8), and the words of a block found without running it
//! (for definitions, symbols and hover). Comments `( )` are skipped, as the reader skips them;
//! `;` ends a block, and the words after it are the next block's.

use lsp_types::{Position, Range};

/// How the client counts columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    Utf8,
    Utf16,
}

/// Where each line starts (byte offsets), for a text held by the server.
pub struct Lines<'a> {
    pub text: &'a str,
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    pub fn new(text: &'a str) -> Lines<'a> {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Lines { text, starts }
    }

    pub fn count(&self) -> usize {
        self.starts.len()
    }

    /// Line `n` (0-based) without its line end.
    pub fn line(&self, n: usize) -> &'a str {
        let Some(&start) = self.starts.get(n) else { return "" };
        let end = self.starts.get(n + 1).map_or(self.text.len(), |&e| e - 1);
        self.text[start..end.max(start)].trim_end_matches('\r')
    }

    /// The byte offset of a client position (clamped to the text).
    pub fn offset(&self, p: Position, enc: Encoding) -> usize {
        let Some(&start) = self.starts.get(p.line as usize) else { return self.text.len() };
        let line = self.line(p.line as usize);
        start + byte_col(line, p.character, enc)
    }

    /// The client position of a byte column (0-based) of line `n` (0-based).
    pub fn position(&self, n: usize, byte_col: usize, enc: Encoding) -> Position {
        Position { line: n as u32, character: client_col(self.line(n), byte_col, enc) }
    }

    /// The range of bytes `from..to` of line `n`.
    pub fn range(&self, n: usize, from: usize, to: usize, enc: Encoding) -> Range {
        Range { start: self.position(n, from, enc), end: self.position(n, to, enc) }
    }
}

/// A client column on `line` as a byte column.
pub fn byte_col(line: &str, character: u32, enc: Encoding) -> usize {
    match enc {
        // A column inside a character (a client that counts wrongly) goes to its start.
        Encoding::Utf8 => floor_char_boundary(line, (character as usize).min(line.len())),
        Encoding::Utf16 => {
            let mut units = 0u32;
            for (i, c) in line.char_indices() {
                if units >= character {
                    return i;
                }
                units += c.len_utf16() as u32;
            }
            line.len()
        }
    }
}

/// A byte column on `line` as the client counts it.
pub fn client_col(line: &str, byte_col: usize, enc: Encoding) -> u32 {
    let cut = floor_char_boundary(line, byte_col.min(line.len()));
    match enc {
        Encoding::Utf8 => cut as u32,
        Encoding::Utf16 => line[..cut].encode_utf16().count() as u32,
    }
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// Apply an edit of the client (a range replaced, or the whole text) to `text`.
pub fn apply_change(text: &mut String, range: Option<Range>, new: &str, enc: Encoding) {
    match range {
        None => *text = new.to_string(),
        Some(r) => {
            let lines = Lines::new(text);
            let (a, b) = (lines.offset(r.start, enc), lines.offset(r.end, enc));
            let (a, b) = (a.min(b), a.max(b));
            text.replace_range(a..b, new);
        }
    }
}

/// One word of a block: its address (a letter, or a keyword such as GOTO), the number as
/// written, and where it is on the line (bytes).
#[derive(Debug, Clone, PartialEq)]
pub struct Word<'a> {
    pub address: &'a str,
    pub value: &'a str,
    pub from: usize,
    pub to: usize,
}

impl Word<'_> {
    /// The value as a whole number (`P0031000`, `N10`, `1234`), if it is one.
    pub fn integer(&self) -> Option<u64> {
        let v = self.value.trim_start_matches('+');
        (!v.is_empty() && v.len() <= 12 && v.bytes().all(|b| b.is_ascii_digit())).then(|| v.parse().ok()).flatten()
    }
}

const KEYWORDS: [&str; 6] = ["GOTO", "WHILE", "IF", "THEN", "END", "DO"];

/// The words of a line, comments skipped. A macro expression (`#1`, `[...]`) is not a value:
/// the word keeps what is written up to the next address.
pub fn words(line: &str) -> Vec<Word<'_>> {
    let b = line.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == b'(' {
            i = line[i..].find(')').map_or(b.len(), |e| i + e + 1);
            continue;
        }
        // `;` ends a block (the reader reads on after it): the words after it are the next
        // block's, on the same line.
        if c == b';' {
            i += 1;
            continue;
        }
        if c.is_ascii_alphabetic() || c == b',' {
            let start = i;
            // A keyword, or a letter (a comma word `,C` is an address of its own).
            // Bytes, not characters: a letter may stand before a Chinese character.
            let kw = KEYWORDS.iter().find(|k| b[i..].get(..k.len()).is_some_and(|w| w.eq_ignore_ascii_case(k.as_bytes())));
            let addr_end = match kw {
                Some(k) => i + k.len(),
                None if c == b',' && i + 1 < b.len() && b[i + 1].is_ascii_alphabetic() => i + 2,
                None => i + 1,
            };
            let mut j = addr_end;
            while j < b.len() && b[j] == b' ' {
                j += 1;
            }
            let v_start = j;
            while j < b.len() && (b[j].is_ascii_digit() || matches!(b[j], b'.' | b'-' | b'+' | b'#' | b'[' | b']' | b'*' | b'/')) {
                j += 1;
            }
            out.push(Word { address: &line[start..addr_end], value: line[v_start..j].trim_end(), from: start, to: j.max(addr_end) });
            i = j.max(addr_end);
            continue;
        }
        i += 1;
    }
    out
}

/// The word under byte column `col` (or just before it: the cursor after the last digit).
pub fn word_at<'a>(words: &'a [Word<'a>], col: usize) -> Option<&'a Word<'a>> {
    words.iter().find(|w| w.from <= col && col < w.to).or_else(|| words.iter().find(|w| w.to == col))
}

/// The number of a line's O word at its start (`O1234`, `:1234` as ISO tapes write it).
pub fn programme_number(line: &str) -> Option<u64> {
    let t = line.trim_start();
    let rest = t.strip_prefix(['O', 'o', ':'])?;
    let digits: &str = &rest[..rest.bytes().take_while(u8::is_ascii_digit).count()];
    (!digits.is_empty()).then(|| digits.parse().ok()).flatten()
}

/// The sequence number of a block (`N10` first, after a block delete `/`), and where it is.
pub fn sequence_number(line: &str) -> Option<(u64, usize, usize)> {
    let w = words(line);
    let first = w.first()?;
    let before = &line[..first.from];
    if !before.trim_start_matches([' ', '\t', '/']).is_empty() || !first.address.eq_ignore_ascii_case("N") {
        return None;
    }
    Some((first.integer()?, first.from, first.to))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_in_utf16_and_bytes() {
        let text = "G0 X1 (刀具) Z2\nN10 G1";
        let lines = Lines::new(text);
        // "Z2" starts at byte 15 (the two Chinese characters are 3 bytes each), column 11 in UTF-16.
        let z = lines.line(0).find('Z').unwrap();
        assert_eq!(z, 15);
        assert_eq!(lines.position(0, z, Encoding::Utf16), Position { line: 0, character: 11 });
        assert_eq!(lines.offset(Position { line: 0, character: 11 }, Encoding::Utf16), z);
        assert_eq!(lines.offset(Position { line: 1, character: 4 }, Encoding::Utf8), text.find("G1").unwrap());
    }

    #[test]
    fn an_edit_replaces_its_range() {
        let mut t = String::from("G0 X1\nG1 Z-5 F0.2\n");
        apply_change(&mut t, Some(Range { start: Position { line: 1, character: 3 }, end: Position { line: 1, character: 6 } }), "Z-10.", Encoding::Utf16);
        assert_eq!(t, "G0 X1\nG1 Z-10. F0.2\n");
    }

    #[test]
    fn words_skip_comments_and_find_keywords() {
        // A comment ends at its first ')' (they do not nest); ';' ends a block, the next one's
        // words follow; a letter before a Chinese character is no keyword and no panic.
        let w = words("/N20 M98 P0031000 (CALL GOTO 5) ; GOTO 6 T刀");
        let a: Vec<_> = w.iter().map(|w| (w.address, w.value)).collect();
        assert_eq!(a, [("N", "20"), ("M", "98"), ("P", "0031000"), ("GOTO", "6"), ("T", "")]);
        let w = words("IF [#1 GT 2] GOTO 30");
        assert!(w.iter().any(|w| w.address == "GOTO" && w.value == "30"));
        assert_eq!(sequence_number(" /N20 G1"), Some((20, 2, 5)));
        assert_eq!(sequence_number("G1 N20"), None);
        assert_eq!(programme_number("O0012 (PART)"), Some(12));
    }
}
