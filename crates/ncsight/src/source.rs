//! Source positions. A span names one line and a run of bytes on it; columns are 1-based
//! byte columns counted after a leading UTF-8 byte-order mark, so they match what an editor shows
//! for ASCII text (every G-code word is ASCII).

/// Where a block, a word or a diagnostic sits in the programme text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    /// 1-based line number in the input file.
    pub line: u32,
    /// 1-based byte column of the first byte.
    pub col: u32,
    /// Length in bytes (at least 1 for anything a person must see underlined); a block is at
    /// most 4096 bytes long, so 16 bits hold it (the span stays 12 bytes: every word has one).
    pub len: u16,
    /// Which file holds the line: 0 is the file the run began with; a subprogramme found in
    /// another file gets the number its driver gave it (`Program::open_file`).
    pub file: u16,
}

impl Span {
    pub fn new(line: u32, col: u32, len: u32) -> Span {
        Span { line, col, len: len.min(u32::from(u16::MAX)) as u16, file: 0 }
    }

    /// The smallest span covering both (same line assumed; otherwise `self`).
    pub fn to(self, other: Span) -> Span {
        if other.line != self.line || other.file != self.file {
            return self;
        }
        let start = self.col.min(other.col);
        let end = (self.col + u32::from(self.len)).max(other.col + u32::from(other.len));
        Span { col: start, len: (end - start).min(u32::from(u16::MAX)) as u16, ..self }
    }
}
