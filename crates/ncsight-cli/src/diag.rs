//! Compiler-style diagnostics: file:line:col, the source line, the word underlined, the rule
//! and a hint, rendered by miette. Only the offending line is kept (the input streams), so the
//! source given to miette is that one line, placed at its real line number.

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents, SourceCode, SourceSpan,
    SpanContents,
};
use ncsight::{Diagnostic, Severity};
use std::fmt;

/// One line of a file, as miette's source.
struct LineSource {
    name: String,
    text: String,
    line_index: usize,
}

impl SourceCode for LineSource {
    fn read_span<'a>(
        &'a self,
        _span: &SourceSpan,
        _before: usize,
        _after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            self.text.as_bytes(),
            SourceSpan::new(0.into(), self.text.len()),
            self.line_index,
            0,
            1,
        )))
    }
}

struct Report<'a> {
    d: &'a Diagnostic,
    source: LineSource,
}

impl fmt::Debug for Report<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.d.message)
    }
}

impl fmt::Display for Report<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.d.message)
    }
}

impl std::error::Error for Report<'_> {}

impl miette::Diagnostic for Report<'_> {
    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.d.severity() {
            Severity::Alarm => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
        })
    }

    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.d.hint.as_ref().map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        if self.source.text.is_empty() { None } else { Some(&self.source) }
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        if self.source.text.is_empty() {
            return None;
        }
        let len = self.source.text.len();
        let start = (self.d.span.col as usize).saturating_sub(1).min(len);
        let width = (self.d.span.len as usize).min(len - start);
        Some(Box::new(std::iter::once(LabeledSpan::new(Some(self.d.rule.title().to_string()), start, width))))
    }
}

/// The text of a line for display: byte columns are kept (bytes that are not ASCII in an
/// invalid UTF-8 line become '?', so the underline stays under the right word).
pub fn display_line(raw: &[u8]) -> String {
    let mut raw = raw;
    while let Some((&last, rest)) = raw.split_last() {
        if last == b'\n' || last == b'\r' {
            raw = rest;
        } else {
            break;
        }
    }
    let raw = raw.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(raw);
    let raw = &raw[..raw.len().min(200)];
    match std::str::from_utf8(raw) {
        Ok(s) => s.replace('\t', " "),
        Err(_) => raw.iter().map(|&b| if b.is_ascii() && b != b'\t' { b as char } else { '?' }).collect(),
    }
}

/// Render a diagnostic; `line_text` is the raw text of its line (may be empty if unknown).
pub fn render(file: &str, line_text: &[u8], d: &Diagnostic) -> String {
    let text = display_line(line_text);
    // Columns past the displayed width (a very long line) are not underlined.
    let text = if (d.span.col as usize) > text.len() + 1 { String::new() } else { text };
    let report = Report {
        d,
        source: LineSource {
            name: file.to_string(),
            text,
            line_index: d.span.line.saturating_sub(1) as usize,
        },
    };
    let mut out = String::new();
    let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor()).with_width(100);
    if handler.render_report(&mut out, &report).is_err() {
        out.clear();
    }
    // A plain first line that tools (and people) can grep: file:line:col: severity[code]: message.
    let sev = if d.is_alarm() { "alarm" } else { "warning" };
    format!("{file}:{}:{}: {sev}[{}]: {}\n{out}", d.span.line, d.span.col, d.code, d.message)
}
