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
#[derive(Debug, Clone, Copy)]
pub struct Decoding {
    /// `None`: GB18030, then Windows-1252 (the default); `Some`: that encoding for every line
    /// that is not UTF-8.
    forced: Option<&'static encoding_rs::Encoding>,
}

impl Default for Decoding {
    fn default() -> Decoding {
        Decoding { forced: None }
    }
}

impl Decoding {
    /// `--encoding NAME` (any WHATWG label: gbk, gb18030, big5, shift_jis, windows-1252, ...).
    pub fn by_label(label: &str) -> Option<Decoding> {
        encoding_rs::Encoding::for_label(label.trim().as_bytes()).map(|e| Decoding { forced: Some(e) })
    }

    /// One line's text.
    pub fn decode(&self, raw: &[u8]) -> String {
        if let Ok(s) = std::str::from_utf8(raw) {
            return s.to_string();
        }
        if let Some(e) = self.forced {
            return e.decode_without_bom_handling(raw).0.into_owned();
        }
        if let Some(s) = encoding_rs::GB18030.decode_without_bom_handling_and_without_replacement(raw) {
            return s.into_owned();
        }
        encoding_rs::WINDOWS_1252.decode_without_bom_handling(raw).0.into_owned()
    }

    /// The decoded text of `raw[..byte]`: how far a byte column is into the displayed line.
    fn prefix_width(&self, raw: &[u8], byte: usize) -> usize {
        // Decode the prefix alone: a byte column always starts a character of the line.
        width(&self.decode(&raw[..byte.min(raw.len())]))
    }
}

fn width(s: &str) -> usize {
    s.chars().map(|c| if c == '\t' { 1 } else { c.width().unwrap_or(0) }).sum()
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
    s.chars().map(|c| if c.is_control() && c != '\t' { '\u{fffd}' } else if c == '\t' { ' ' } else { c }).collect()
}

/// The text of a line for display (the report and the tests use it too).
pub fn display_line(raw: &[u8], decoding: &Decoding) -> String {
    printable(&decoding.decode(trimmed(raw))).chars().take(200).collect()
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
    let shown = display_line(line_text, decoding);
    let start_byte = (d.span.col as usize).saturating_sub(1);
    if !shown.is_empty() && start_byte <= raw.len() && start_byte < 200 {
        let number = d.span.line.to_string();
        let pad = " ".repeat(number.len());
        let end_byte = (start_byte + d.span.len.max(1) as usize).min(raw.len()).min(200).max(start_byte);
        let lead = decoding.prefix_width(raw, start_byte);
        let marks = decoding.prefix_width(raw, end_byte).saturating_sub(lead).max(1);
        out.push_str(&format!(" {number} | {shown}\n {pad} | {}{} {}\n", " ".repeat(lead), "^".repeat(marks), d.rule.title()));
    }
    if let Some(h) = &d.hint {
        out.push_str(&format!("   = hint: {}\n", printable(h)));
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
}
