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
    /// Length in bytes (at least 1 for anything a person must see underlined).
    pub len: u32,
    /// Which file holds the line: 0 is the file the run began with; a subprogramme found in
    /// another file gets the number its driver gave it (`Program::open_file`).
    pub file: u16,
}

impl Span {
    pub fn new(line: u32, col: u32, len: u32) -> Span {
        Span { line, col, len, file: 0 }
    }

    /// The smallest span covering both (same line assumed; otherwise `self`).
    pub fn to(self, other: Span) -> Span {
        if other.line != self.line || other.file != self.file {
            return self;
        }
        let start = self.col.min(other.col);
        let end = (self.col + self.len).max(other.col + other.len);
        Span { col: start, len: end - start, ..self }
    }
}
