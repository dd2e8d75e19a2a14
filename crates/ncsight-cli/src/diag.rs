//! Compiler-style diagnostics: `file:line:col: alarm[CODE]: message`, then the source line with
//! the word underlined and the rule's title, then the hint. One rendering per diagnostic (the
//! message is not repeated). Only the offending line is kept (the input streams).
//!
//! Lines are shown as written: UTF-8, or, where a line is not UTF-8, GB18030 (what GSK controls
//! and Chinese Windows editors save; GBK is its subset), or Windows-1252 where it is not that
//! either; `--encoding` names another. Columns are bytes in the file, so the underline is placed
//! by the byte offsets and drawn in display columns (a CJK character takes two).

use ncsight::{Diagnostic, Severity};
use unicode_width::UnicodeWidthChar;

/// How lines that are not UTF-8 are decoded.
#[derive(Debug, Clone, Copy, Default)]
pub struct Decoding {
    /// `None`: GB18030, then Windows-1252 (the default); `Some`: that encoding for every line
    /// that is not UTF-8.
    forced: Option<&'static encoding_rs::Encoding>,
}

impl Decoding {
    /// `--encoding NAME` (any WHATWG label: gbk, gb18030, big5, shift_jis, windows-1252, ...).
    pub fn by_label(label: &str) -> Option<Decoding> {
        encoding_rs::Encoding::for_label(label.trim().as_bytes()).map(|e| Decoding { forced: Some(e) })
    }

    /// The encoding of a line that is not UTF-8.
    fn encoding_of(&self, raw: &[u8]) -> &'static encoding_rs::Encoding {
        match self.forced {
            Some(e) => e,
            None if encoding_rs::GB18030.decode_without_bom_handling_and_without_replacement(raw).is_some() => encoding_rs::GB18030,
            None => encoding_rs::WINDOWS_1252,
        }
    }

    /// The WHATWG name of the encoding lines that are not UTF-8 are read in (`gb18030` by
    /// default; a line that is not GB18030 either falls back to windows-1252 as it is read).
    pub fn label(&self) -> &'static str {
        self.forced.unwrap_or(encoding_rs::GB18030).name()
    }

    /// One line's text.
    pub fn decode(&self, raw: &[u8]) -> String {
        match std::str::from_utf8(raw) {
            Ok(s) => s.to_string(),
            Err(_) => self.encoding_of(raw).decode_without_bom_handling(raw).0.into_owned(),
        }
    }

    /// The line's characters, each with the byte offset it starts at in the line (the whole line
    /// decoded once, so that byte columns map to characters exactly).
    fn chars(&self, raw: &[u8]) -> Vec<(usize, char)> {
        if let Ok(s) = std::str::from_utf8(raw) {
            return s.char_indices().collect();
        }
        let mut decoder = self.encoding_of(raw).new_decoder_without_bom_handling();
        let mut out = Vec::with_capacity(raw.len());
        let mut buf = String::with_capacity(64);
        let mut start = 0;
        for k in 0..=raw.len() {
            buf.clear();
            let (piece, last) = if k < raw.len() { (&raw[k..k + 1], false) } else { (&raw[..0], true) };
            let _ = decoder.decode_to_string(piece, &mut buf, last);
            if !buf.is_empty() {
                out.extend(buf.chars().map(|c| (start.min(raw.len().saturating_sub(1)), c)));
                start = k + 1;
            }
        }
        out
    }
}

/// The width of a character as shown (after [`printable`]).
fn shown_width(c: char) -> usize {
    if c.is_control() {
        1
    } else {
        c.width().unwrap_or(0)
    }
}

/// The line without its break and byte-order mark, at most 200 bytes, tabs as spaces.
fn trimmed(raw: &[u8]) -> &[u8] {
    let mut raw = raw;
    while let Some((&last, rest)) = raw.split_last() {
        if last == b'\n' || last == b'\r' {
            raw = rest;
        } else {
            break;
        }
    }
    raw.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(raw)
}

/// Control characters (a NUL byte, an escape) are never printed raw inside a message.
fn printable(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_control() && c != '\t' {
                '\u{fffd}'
            } else if c == '\t' {
                ' '
            } else {
                c
            }
        })
        .collect()
}

/// At most this many characters of a line are shown.
const SHOWN_CHARS: usize = 200;

/// The text of a line for display (the report and the tests use it too).
pub fn display_line(raw: &[u8], decoding: &Decoding) -> String {
    printable(&decoding.decode(trimmed(raw))).chars().take(SHOWN_CHARS).collect()
}

/// How diagnostics are printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// The header line, the source line underlined, the hint.
    Full,
    /// The header line only (`--format short`).
    Short,
}

/// Render a diagnostic; `line_text` is the raw text of its line (may be empty if unknown).
pub fn render(file: &str, line_text: &[u8], d: &Diagnostic, style: Style, decoding: &Decoding) -> String {
    let sev = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
    let message = printable(&d.message);
    let mut out = format!("{file}:{}:{}: {sev}[{}]: {message}\n", d.span.line, d.span.col, d.code);
    if style == Style::Short {
        return out;
    }
    let raw = trimmed(line_text);
    let chars: Vec<(usize, char)> = decoding.chars(raw).into_iter().take(SHOWN_CHARS).collect();
    let shown = display_line(line_text, decoding);
    let start_byte = (d.span.col as usize).saturating_sub(1);
    // The byte just past the characters shown: a column beyond it is not underlined.
    let shown_end = if chars.len() < SHOWN_CHARS { raw.len() } else { chars.last().map_or(0, |(o, _)| *o) };
    if !shown.is_empty() && start_byte <= shown_end {
        let number = d.span.line.to_string();
        let pad = " ".repeat(number.len());
        let end_byte = (start_byte + d.span.len.max(1) as usize).min(shown_end.max(start_byte + 1));
        // Display columns: the widths of the characters before the span, and of those in it.
        let lead: usize = chars.iter().filter(|(o, _)| *o < start_byte).map(|(_, c)| shown_width(*c)).sum();
        let marks: usize = chars.iter().filter(|(o, _)| *o >= start_byte && *o < end_byte).map(|(_, c)| shown_width(*c)).sum::<usize>().max(1);
        out.push_str(&format!(" {number} | {shown}\n {pad} | {}{} {}\n", " ".repeat(lead), "^".repeat(marks), d.rule.title()));
    }
    if let Some(h) = &d.hint {
        out.push_str(&format!("   = hint: {}\n", printable(h)));
    }
    // Raised in a subprogramme: the calls that led there, innermost first.
    for (i, c) in d.calls.iter().rev().enumerate() {
        let whose = if i == 0 { "in a subprogramme called" } else { "    which was called" };
        let place = if c.file != d.span.file && i == 0 { " of the calling file" } else { "" };
        out.push_str(&format!("   = {whose} at line {}, column {}{place}\n", c.line, c.col));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gbk_comments_show_as_written() {
        // "(螺纹刀)" in GBK.
        let raw = b"G0 X150 Z50 T0101 (\xC2\xDD\xCE\xC6\xB5\xB6)";
        assert_eq!(display_line(raw, &Decoding::default()), "G0 X150 Z50 T0101 (螺纹刀)");
        let latin = b"(FURA\xC7\xC3O)";
        assert_eq!(display_line(latin, &Decoding::by_label("latin1").unwrap()), "(FURAÇÃO)");
        // A NUL byte is never printed raw.
        assert_eq!(display_line(b"G0\0X1", &Decoding::default()), "G0\u{fffd}X1");
    }

    fn underline(raw: &[u8], col: u32, len: u32) -> String {
        let d = ncsight::Diagnostic::new(ncsight::Rule::BadCharacter, ncsight::alarm::AlarmStyle::Project, ncsight::source::Span::new(1, col, len), "m");
        let r = render("f", raw, &d, Style::Full, &Decoding::default());
        r.lines().nth(2).unwrap_or_else(|| panic!("{r}")).to_string()
    }

    /// The underline stands under the word whatever precedes it: a control byte, GBK text, CJK
    /// characters two columns wide.
    #[test]
    fn the_underline_is_under_the_word() {
        // "(A\x01B) G0 X#1": '#' at byte 10 (column 11) shows at display column 10.
        let u = underline(b"(A\x01B) G0 X#1", 11, 1);
        assert_eq!(u.find('^'), Some(" 1 | ".len() + 10), "{u}");
        // GBK "(\u{87ba}\u{7eb9}) Q5": Q at byte 7; the two characters take two columns each.
        let u = underline(b"(\xC2\xDD\xCE\xC6) Q5", 8, 2);
        assert_eq!(u.find('^'), Some(" 1 | ".len() + 7), "{u}");
        assert_eq!(u.matches('^').count(), 2);
        // A long UTF-8 comment cut at 200 characters: the underline stays within what is shown.
        let mut long = b"G0 X1 (".to_vec();
        for _ in 0..300 {
            long.extend("\u{87ba}".as_bytes());
        }
        let u = underline(&long, 7, (long.len() - 6) as u32);
        assert!(u.matches('^').count() <= 2 * 200, "{}", u.len());
    }

    /// Any bytes, any span: rendering never panics, the underline never runs past the line shown.
    #[test]
    fn any_bytes_render() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..2000 {
            let len = (next() % 300) as usize;
            let raw: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            let col = (next() % 320) as u32 + 1;
            let span = (next() % 50) as u32;
            let d = ncsight::Diagnostic::new(ncsight::Rule::BadCharacter, ncsight::alarm::AlarmStyle::Project, ncsight::source::Span::new(1, col, span), "m");
            for decoding in [Decoding::default(), Decoding::by_label("big5").unwrap()] {
                let r = render("f", &raw, &d, Style::Full, &decoding);
                let lines: Vec<&str> = r.lines().collect();
                if lines.len() >= 3 {
                    let shown: usize = lines[1].chars().map(shown_width).sum();
                    let under: usize = lines[2].chars().map(shown_width).sum();
                    let title = d.rule.title().len() + 1;
                    assert!(under <= shown + title + 1, "{raw:?} {col} {span}\n{r}");
                }
            }
        }
    }
}
