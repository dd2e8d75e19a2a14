//! The reader: one line of programme text -> blocks of words, each with its span.
//!
//! What it understands (issue 2, item 1): `%` tape marks, `O` programme numbers, `N` sequence
//! numbers, `/` block delete, `( )` comments, `;` as the manuals' end-of-block mark, lower case,
//! words without spaces (`G92X20Z-30F1.5`), CRLF, a UTF-8 BOM, any bytes inside comments, and
//! `[expr]` values. It knows nothing of a controller's G codes: that is the interpreter's job.

pub mod expr;
pub mod macro_block;
pub mod simulator;

pub use macro_block::{MacroBlock, MacroWord, Stmt, Then};

use crate::alarm::{AlarmStyle, Diagnostic, Rule};
use crate::source::Span;

/// Longest block text accepted. FANUC and GSK tapes hold far shorter blocks; the limit keeps a
/// broken file (a binary, a 100 kB line) to one clear alarm.
pub const MAX_LINE_BYTES: usize = 4096;

/// The most of one line a streaming caller keeps (the rest of a longer line is skipped): a
/// line this long is reported as "more than" it.
pub const MAX_KEPT_LINE_BYTES: usize = 64 * 1024;

/// Most significant digits a numeric value may have (FANUC PS0003 "TOO MANY DIGIT": the
/// controls take 8 digits; one more is accepted for CAM output that pads a trailing digit).
pub const MAX_DIGITS: usize = 9;

/// The index of the `]` that closes the `[` at `open`, if the text closes it.
pub(crate) fn matching_bracket(s: &[u8], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (j, &b) in s.iter().enumerate().skip(open) {
        match b {
            b'[' => depth += 1,
            b']' => {
                depth -= 1;
                if depth == 0 {
                    return Some(j);
                }
            }
            _ => {}
        }
    }
    None
}

/// Which of the few bytes that change how a line is read it holds, found in one pass over the
/// line (a table lookup per byte; two scans for them took a twentieth of the reading thread's
/// work on the 200,000-hole programme, counted with callgrind).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ByteMarks(u8);

impl ByteMarks {
    /// The DOS end-of-file mark (0x1A) or a macro variable's `#`.
    pub const RARE: u8 = 1;
    /// A sign of another control's language: `$ @ = <` (`dialect::sniff`).
    pub const FOREIGN: u8 = 2;

    const TABLE: [u8; 256] = {
        let mut t = [0u8; 256];
        t[0x1A] = Self::RARE;
        t[b'#' as usize] = Self::RARE;
        t[b'$' as usize] = Self::FOREIGN;
        t[b'@' as usize] = Self::FOREIGN;
        t[b'=' as usize] = Self::FOREIGN;
        t[b'<' as usize] = Self::FOREIGN;
        t
    };

    pub fn of(s: &[u8]) -> ByteMarks {
        ByteMarks(s.iter().fold(0, |m, &b| m | Self::TABLE[b as usize]))
    }

    pub fn has(self, mark: u8) -> bool {
        self.0 & mark != 0
    }
}

/// The reader's note to itself that a word holds ROUND (see `read_line_into`).
const ROUND_LATER: &str = "ROUND in an address is evaluated when the block runs";

/// Whether a line has a `#` outside its comments (a macro variable).
fn has_variable(s: &[u8]) -> bool {
    // One scan first: most lines have no `#`.
    if !s.contains(&b'#') {
        return false;
    }
    let mut in_comment = false;
    for &b in s {
        match b {
            b'(' => in_comment = true,
            b')' => in_comment = false,
            b'#' if !in_comment => return true,
            _ => {}
        }
    }
    false
}

/// One address with its value, e.g. `X-12.5` or `F[25.4/10]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Word {
    /// Upper-case ASCII letter; lower case for a word written after a comma (`,A30.` is `a`:
    /// FANUC's drawing dimensions, a corner's `,C` and `,R`), an address of its own.
    pub letter: u8,
    /// The value as written (sign applied; no unit conversion).
    pub value: f64,
    /// A decimal point was written (an `[expr]` counts as having one).
    pub decimal: bool,
    /// The value came from an `[expr]`.
    pub expr: bool,
    pub span: Span,
}

impl Word {
    /// `G32.1` -> (32, Some(1)); `G01` -> (1, None). Only meaningful for G/M words.
    pub fn code(&self) -> (u32, Option<u32>) {
        let v = self.value.abs();
        let major = v.trunc() as u32;
        if self.decimal {
            let minor = ((v - v.trunc()) * 10.0).round() as u32;
            (major, Some(minor))
        } else {
            (major, None)
        }
    }

    /// Whether the value is a code as the controllers write them: a whole number, or one digit
    /// after the point (`G32.1`). `G32.16` is not read as G32.2.
    pub fn is_code(&self) -> bool {
        let tenths = self.value.abs() * 10.0;
        (tenths - tenths.round()).abs() < 1e-6
    }

    /// The word as a person would write it, for messages.
    pub fn text(&self) -> String {
        let letter = address_name(self.letter);
        if self.expr {
            return format!("{letter}[...]");
        }
        if self.decimal {
            let s = format!("{}", self.value);
            if s.contains('.') {
                format!("{letter}{s}")
            } else {
                format!("{letter}{s}.")
            }
        } else {
            format!("{letter}{}", self.value)
        }
    }
}

/// An address as written: `X`, or `,A` for the comma word stored as `a`.
pub fn address_name(letter: u8) -> String {
    if letter.is_ascii_lowercase() {
        format!(",{}", letter.to_ascii_uppercase() as char)
    } else {
        (letter as char).to_string()
    }
}

/// One block: the words between two end-of-block marks.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Block {
    /// Span of the whole block text on its line.
    pub span: Span,
    /// `/` at the start: skipped when the block-delete switch is on.
    pub block_delete: bool,
    /// Sequence number `N`, if any.
    pub sequence: Option<u32>,
    /// Programme number `O`, if any.
    pub program: Option<u32>,
    /// Every other word, in the order written.
    pub words: Vec<Word>,
    /// Comment texts (without the parentheses), lossily decoded.
    pub comments: Vec<String>,
    /// A custom macro block: a statement, or words whose values the variables give (then
    /// `words` is empty until the programme evaluates them).
    pub macro_block: Option<Box<MacroBlock>>,
}

impl Block {
    pub fn is_empty(&self) -> bool {
        self.words.is_empty() && self.sequence.is_none() && self.program.is_none() && self.macro_block.is_none()
    }
}

/// What one line gave.
#[derive(Debug, Default)]
pub struct Line {
    /// Blocks in order; a block that could not be read is its alarm. Reading a line stops at its
    /// first alarm.
    pub blocks: Vec<Result<Block, Diagnostic>>,
    /// Warnings that belong to the line as a whole (unclosed comment, text after `%`, ...).
    pub warnings: Vec<Diagnostic>,
    /// The line is a `%` tape mark.
    pub tape_mark: bool,
    /// A DOS end-of-file byte (0x1A) ended the text.
    pub end_of_file: bool,
    /// Word lists of earlier lines, kept for reuse by [`Reader::read_line_into`].
    spare: Vec<Vec<Word>>,
}

impl Line {
    /// Drop the blocks read, keeping their word lists for reuse.
    fn clear_blocks(&mut self) {
        while let Some(item) = self.blocks.pop() {
            if let Ok(b) = item {
                let mut words = b.words;
                words.clear();
                self.spare.push(words);
            }
        }
    }

    /// Empty it for the next line, keeping the allocations.
    pub(crate) fn reset(&mut self) {
        self.clear_blocks();
        self.warnings.clear();
        self.tape_mark = false;
        self.end_of_file = false;
    }

    pub(crate) fn new_block(&mut self) -> Block {
        Block { words: self.spare.pop().unwrap_or_default(), ..Block::default() }
    }

    /// A block read, its text from `start` to `end`, into the blocks; one with no text but
    /// comments stands at the line's start; an empty one gives its word list back for reuse.
    #[inline]
    fn finish_block(&mut self, line_no: u32, mut b: Block, start: Option<usize>, end: usize) {
        if let Some(st) = start {
            b.span = Span::new(line_no, st as u32 + 1, (end - st).max(1) as u32);
            self.blocks.push(Ok(b));
        } else if !b.comments.is_empty() {
            self.blocks.push(Ok(Block { span: Span::new(line_no, 1, 1), ..b }));
        } else {
            self.spare.push(b.words);
        }
    }
}

/// The UTF-8 character at the start of `s`, if the bytes there are one.
fn utf8_char(s: &[u8]) -> Option<char> {
    let len = match s.first()? {
        0xC2..=0xDF => 2,
        0xE0..=0xEF => 3,
        0xF0..=0xF4 => 4,
        _ => return None,
    };
    std::str::from_utf8(s.get(..len)?).ok()?.chars().next()
}

/// A full-width character at the start of `s` (what a Chinese input method types for `;`, `(`,
/// `,`, digits, letters), in UTF-8 or in GBK: how it looks, its ASCII twin, and its length in bytes.
fn full_width(s: &[u8]) -> Option<(String, char, usize)> {
    // GBK: 0xA3 0xA1..0xFE is the full-width form of ASCII 0x21..0x7E; 0xA1 0xA1 the wide space.
    if s.len() >= 2 && s[0] == 0xA3 && (0xA1..=0xFE).contains(&s[1]) {
        let twin = (s[1] - 0x80) as char;
        let shown = char::from_u32(twin as u32 + 0xFEE0).map(String::from).unwrap_or_default();
        return Some((shown, twin, 2));
    }
    if s.len() >= 2 && s[0] == 0xA1 && s[1] == 0xA1 {
        return Some(("\u{3000}".into(), ' ', 2));
    }
    let c = utf8_char(s)?;
    let twin = match c as u32 {
        0xFF01..=0xFF5E => char::from_u32(c as u32 - 0xFEE0)?,
        0x3000 => ' ',
        0x3001 => ',',
        0x3002 => '.',
        _ => return None,
    };
    Some((c.to_string(), twin, c.len_utf8()))
}

/// Reads lines. Holds only what a line needs.
#[derive(Debug, Clone)]
pub struct Reader {
    style: AlarmStyle,
}

fn is_blank(c: u8) -> bool {
    c == b' ' || c == b'\t' || c == b'\r' || c == b'\n' || c == 0x0c || c == 0x0b
}

impl Reader {
    pub fn new(style: AlarmStyle) -> Reader {
        Reader { style }
    }

    fn diag(&self, rule: Rule, line: u32, col: usize, len: usize, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::new(rule, self.style, Span::new(line, col as u32 + 1, len.max(1) as u32), msg)
    }

    /// Read one line (its line break may be included). `line_no` is 1-based.
    pub fn read_line(&self, line_no: u32, raw: &[u8]) -> Line {
        let mut out = Line::default();
        self.read_line_into(line_no, raw, &mut out);
        out
    }

    /// [`Reader::read_line`] into `out`, reusing its allocations (the streaming path).
    pub fn read_line_into(&self, line_no: u32, raw: &[u8], out: &mut Line) {
        self.read_marked_line_into(line_no, raw, ByteMarks::of(raw), out);
    }

    /// [`Reader::read_line_into`] with the line's [`ByteMarks`] found already.
    pub(crate) fn read_marked_line_into(&self, line_no: u32, raw: &[u8], marks: ByteMarks, out: &mut Line) {
        out.reset();
        let mut s = raw;
        if line_no == 1 && s.starts_with(&[0xEF, 0xBB, 0xBF]) {
            s = &s[3..];
        }
        while let Some((&last, rest)) = s.split_last() {
            if last == b'\n' || last == b'\r' {
                s = rest;
            } else {
                break;
            }
        }
        // A DOS end-of-file mark ends the text wherever it stands: inside a comment, after a
        // tape mark, on a line that alarms (corpus: icnc__Delorensi_FASE2.txt).
        let rare = marks.has(ByteMarks::RARE);
        if rare && s.contains(&0x1A) {
            let k = s.iter().position(|&b| b == 0x1A).unwrap_or(s.len());
            out.end_of_file = true;
            out.warnings.push(self.eof_mark(line_no, k));
            s = &s[..k];
        }
        self.read_blocks(line_no, s, out, rare);
        // A word with ROUND: the whole line as macro blocks.
        if out.blocks.last().is_some_and(|b| matches!(b, Err(d) if d.message == ROUND_LATER)) {
            out.clear_blocks();
            let start = s.iter().take_while(|c| is_blank(**c)).count();
            self.read_macro_blocks(line_no, s, start, out);
        }
    }

    /// `[BILLET X42.86 Z82` (a school simulator's stock): a warning, the line skipped; the
    /// stock is read from the line by whoever simulates the cut ([`simulator::billet`]).
    fn billet_line(&self, line_no: u32, s: &[u8], at: usize) -> Diagnostic {
        let len = s.len() - at;
        let d = match simulator::billet(&s[at..]) {
            Some(b) => self.diag(
                Rule::SimulatorStock,
                line_no,
                at,
                len,
                match b.y_mm {
                    Some(y) => format!("[BILLET: a CNC simulator's stock line, not for a controller (which would stop at '['): skipped; simulate takes the stock from it, a block {} x {y} x {} mm", b.x_mm, b.z_mm),
                    None => format!("[BILLET: a CNC simulator's stock line, not for a controller (which would stop at '['): skipped; simulate takes the stock from it, a bar of diameter {} mm, {} mm long", b.x_mm, b.z_mm),
                },
            ),
            None => self.diag(Rule::SimulatorStock, line_no, at, len, "[BILLET: a CNC simulator's stock line, not for a controller (which would stop at '['): skipped; its stock could not be read (X_ Z_, or X_ Y_ Z_ for a block, expected)"),
        };
        d.with_hint("delete the line (or put it in ( )) before the programme goes to a machine")
    }

    fn eof_mark(&self, line_no: u32, col: usize) -> Diagnostic {
        self.diag(Rule::EndOfFileMark, line_no, col, 1, "byte 0x1A (DOS end-of-file mark): the text ends here")
    }

    /// The blocks of a line without its break and without what follows an end-of-file mark:
    /// stops at the first alarm. `rare`: the line has a rare byte (`#`, 0x1A), so a word may
    /// hold a macro variable.
    fn read_blocks(&self, line_no: u32, s: &[u8], out: &mut Line, rare: bool) {
        if s.len() > MAX_LINE_BYTES {
            out.blocks.push(Err(self.line_too_long(line_no, s.len())));
            return;
        }
        let mut i = 0;
        while i < s.len() && is_blank(s[i]) {
            i += 1;
        }
        if i < s.len() && s[i] == b'%' {
            self.tape_mark(line_no, s, i, out);
            return;
        }
        if i < s.len() && s[i] == b'[' && simulator::billet_mark(&s[i..]).is_some() {
            out.warnings.push(self.billet_line(line_no, s, i));
            return;
        }
        // A line with a variable: its blocks are macro blocks, evaluated when they run.
        if rare && has_variable(&s[i..]) {
            self.read_macro_blocks(line_no, s, i, out);
            return;
        }
        self.read_nc_blocks(line_no, s, i, out);
    }

    /// The alarm for a line longer than [`MAX_LINE_BYTES`] (`len` its length, or what a
    /// streaming caller kept of it).
    #[cold]
    fn line_too_long(&self, line_no: u32, len: usize) -> Diagnostic {
        self.diag(
            Rule::LineTooLong,
            line_no,
            0,
            1,
            if len == MAX_KEPT_LINE_BYTES {
                // What a streaming caller keeps of a longer line: its length is not known.
                format!("line of at least {MAX_KEPT_LINE_BYTES} bytes: a block may be at most {MAX_LINE_BYTES} bytes long")
            } else {
                format!("line of {len} bytes: a block may be at most {MAX_LINE_BYTES} bytes long")
            },
        )
    }

    /// The `%` tape mark at `i`: the line is one, and any text after it is warned of.
    fn tape_mark(&self, line_no: u32, s: &[u8], i: usize, out: &mut Line) {
        out.tape_mark = true;
        let rest = &s[i + 1..];
        if rest.iter().any(|c| !is_blank(*c)) {
            out.warnings.push(self.diag(Rule::TextIgnored, line_no, i + 1, rest.len(), "text after the '%' tape mark is ignored"));
        }
    }

    /// The blocks of a line without variables, from `i` (past its leading blanks): each step
    /// of the loop reads one thing (a comment, a `;`, a `/`, a word) and gives the index after
    /// it, or the alarm that ends the line.
    #[inline]
    fn read_nc_blocks(&self, line_no: u32, s: &[u8], mut i: usize, out: &mut Line) {
        let mut open = OpenBlock { block: out.new_block(), start: None, end: 0 };
        while i < s.len() {
            let c = s[i];
            let next = match c {
                _ if is_blank(c) => Ok(i + 1),
                b'(' => Ok(self.comment(line_no, s, i, &mut open.block, out)),
                b';' => {
                    open.close(line_no, open.end, out);
                    open.start = None;
                    Ok(i + 1)
                }
                b'/' if open.start.is_none() && open.block.words.is_empty() && !open.block.block_delete => {
                    open.block.block_delete = true;
                    open.start = Some(i);
                    let mut j = i + 1;
                    // `/1`..`/9` select a block-delete switch; one switch is modelled.
                    if j < s.len() && (b'1'..=b'9').contains(&s[j]) {
                        j += 1;
                    }
                    open.end = j;
                    Ok(j)
                }
                // ISO code: ':' is the programme number's address, as O is (FANUC: `:0100`).
                b':' if open.block.words.is_empty() && open.block.program.is_none() && s.get(i + 1).is_some_and(u8::is_ascii_digit) => {
                    open.start.get_or_insert(i);
                    self.programme_number(line_no, s, i, &mut open)
                }
                // A comma word (`,A30.` `,C1.` `,R2.`: FANUC's drawing dimensions): the word
                // after the comma, its letter kept in lower case as an address of its own.
                b',' if s.get(i + 1).is_some_and(u8::is_ascii_alphabetic) => {
                    open.start.get_or_insert(i);
                    self.comma_word(line_no, s, i, &mut open)
                }
                _ if c.is_ascii_alphabetic() => {
                    open.start.get_or_insert(i);
                    self.address_word(line_no, s, i, &mut open, out)
                }
                _ => Err(self.not_allowed(line_no, s, i, open.start.is_none())),
            };
            match next {
                Ok(next) => i = next,
                Err(d) => {
                    out.blocks.push(Err(d));
                    return;
                }
            }
        }
        out.finish_block(line_no, open.block, open.start, open.end.max(open.start.unwrap_or(0)));
    }

    /// The comment whose `(` is at `i`, into the block (a comment not closed runs to the end
    /// of the line, with a warning): the index after it.
    #[inline]
    fn comment(&self, line_no: u32, s: &[u8], i: usize, block: &mut Block, out: &mut Line) -> usize {
        let close = s[i + 1..].iter().position(|&b| b == b')');
        let end = match close {
            Some(k) => i + 1 + k,
            None => {
                out.warnings.push(self.diag(
                    Rule::CommentNotClosed,
                    line_no,
                    i,
                    s.len() - i,
                    "comment '(' is not closed: the rest of the line is read as a comment",
                ));
                s.len()
            }
        };
        block.comments.push(String::from_utf8_lossy(&s[i + 1..end]).into_owned());
        (end + 1).min(s.len()).max(end)
    }

    /// The programme number after ISO's `:` at `i` (at most 8 digits): the index after it.
    fn programme_number(&self, line_no: u32, s: &[u8], i: usize, open: &mut OpenBlock) -> Result<usize, Diagnostic> {
        let digits = s[i + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
        let text = std::str::from_utf8(&s[i + 1..i + 1 + digits]).unwrap_or("0");
        match text.parse::<u32>() {
            Ok(n) if digits <= 8 => open.block.program = Some(n),
            _ => {
                let d = self.diag(Rule::TooManyDigits, line_no, i, digits + 1, format!(":{text}: a programme number has at most 8 digits"));
                return Err(d);
            }
        }
        open.end = i + 1 + digits;
        Ok(open.end)
    }

    /// The comma word whose `,` is at `i`, into the block: the index after it.
    #[inline]
    fn comma_word(&self, line_no: u32, s: &[u8], i: usize, open: &mut OpenBlock) -> Result<usize, Diagnostic> {
        let (mut w, next) = self.word(line_no, s, i + 1)?;
        w.letter = w.letter.to_ascii_lowercase();
        w.span = Span::new(line_no, i as u32 + 1, (next - i) as u32);
        open.block.words.push(w);
        open.end = next;
        Ok(next)
    }

    /// What starts at the letter `s[i]`: a macro statement (at the start of a block), the
    /// block's N or O, an O that starts the next programme, or a word of the block. The index
    /// after it.
    #[inline]
    fn address_word(&self, line_no: u32, s: &[u8], i: usize, open: &mut OpenBlock, out: &mut Line) -> Result<usize, Diagnostic> {
        // A macro statement starts its block (after N); inside a block two letters
        // side by side are a typing mistake (`DO1` for `D01`), answered as such.
        // (A keyword is two letters or more: a plain word is rejected at once.)
        if open.block.words.is_empty() && s.get(i + 1).is_some_and(u8::is_ascii_alphabetic) && macro_block::is_statement(&s[i..]) {
            let end = s[i..].iter().position(|&b| b == b';').map_or(s.len(), |k| i + k);
            let body_end = s[..end].iter().rposition(|b| !is_blank(*b)).map_or(i + 1, |k| (k + 1).max(i + 1));
            self.read_macro(line_no, s, i, body_end, &mut open.block)?;
            open.end = body_end;
            return Ok(end);
        }
        let word_start = i;
        let (w, next) = self.word(line_no, s, i)?;
        open.end = next;
        let block = &mut open.block;
        match w.letter {
            b'N' if block.sequence.is_none() && block.words.is_empty() => block.sequence = Some(w.value as u32),
            b'O' if block.program.is_none() && block.words.is_empty() => block.program = Some(w.value as u32),
            // An O word after other words starts the next programme on the
            // same line (`M99O0810`, a FANUC 0i punch): the block ends before it.
            b'O' if !w.decimal && !w.expr => {
                open.close(line_no, word_start, out);
                open.block.program = Some(w.value as u32);
                open.start = Some(word_start);
            }
            _ => block.words.push(w),
        }
        Ok(next)
    }

    /// The alarm for the byte at `i`, which starts nothing a block may hold: a number without
    /// its letter, a control character, a full-width or other non-ASCII character, a simulator's
    /// setting line (`first`: nothing of the block read before it).
    #[cold]
    fn not_allowed(&self, line_no: u32, s: &[u8], i: usize, first: bool) -> Diagnostic {
        let c = s[i];
        if c.is_ascii_digit() || c == b'.' || c == b'-' || c == b'+' {
            let mut j = i;
            while j < s.len() && (s[j].is_ascii_digit() || b".+-".contains(&s[j])) {
                j += 1;
            }
            self.diag(Rule::ImproperAddress, line_no, i, j - i, format!("number '{}' has no address letter before it", String::from_utf8_lossy(&s[i..j])))
                .with_hint("a letter such as G was probably left out")
        } else if c.is_ascii_control() {
            self.diag(Rule::BadCharacter, line_no, i, 1, format!("byte 0x{c:02X} (a control character) is not allowed outside a comment"))
        } else if let Some((shown, twin, len)) = full_width(&s[i..]) {
            self.diag(Rule::BadCharacter, line_no, i, len, format!("character '{shown}' (full width) is not allowed outside a comment"))
                .with_hint(format!("a Chinese input method typed it: write the ASCII '{twin}' instead"))
        } else if c.is_ascii() {
            let d = self.diag(Rule::BadCharacter, line_no, i, 1, format!("character '{}' is not allowed outside a comment", c as char));
            // `[BILLET X42.86 Z82`: a line for a CNC simulator's stock, not G-code
            // (corpus: the ICNC course programmes).
            let word = s[i + 1..].iter().take_while(|b| b.is_ascii_alphabetic()).count();
            if c == b'[' && first && word >= 3 {
                d.with_hint("a line that starts with '[' and a name is a CNC simulator's setting (its stock, say), not G-code: the control stops here; put it in ( ) or delete it")
            } else {
                d
            }
        } else if let Some(ch) = utf8_char(&s[i..]) {
            // A character of a UTF-8 text (Chinese notes between the blocks): named.
            self.diag(Rule::BadCharacter, line_no, i, ch.len_utf8(), format!("character '{ch}' is not allowed outside a comment"))
                .with_hint("text other than ASCII belongs inside ( ) comments")
        } else {
            self.diag(Rule::BadCharacter, line_no, i, 1, format!("byte 0x{c:02X} is not allowed outside a comment"))
                .with_hint("text other than ASCII belongs inside ( ) comments")
        }
    }

    /// One word starting at the letter `s[at]`. Returns the word and the index after it.
    fn word(&self, line: u32, s: &[u8], at: usize) -> Result<(Word, usize), Diagnostic> {
        let letter = s[at].to_ascii_uppercase();
        let mut i = at + 1;
        while i < s.len() && (s[i] == b' ' || s[i] == b'\t') {
            i += 1;
        }
        let span_to = |end: usize| word_span(line, at, end);
        if i < s.len() && s[i] == b'[' {
            return self.expression_word(line, s, at, letter, i);
        }
        let num_start = i;
        let mut negative = false;
        if i < s.len() && (s[i] == b'-' || s[i] == b'+') {
            negative = s[i] == b'-';
            i += 1;
            while i < s.len() && (s[i] == b' ' || s[i] == b'\t') {
                i += 1;
            }
        }
        let digits_start = i;
        let mut decimal = false;
        let mut digits = 0usize;
        // The digits as an integer and how many of them follow the point (exact while the
        // significant digits are within MAX_DIGITS).
        let mut mantissa = 0u64;
        let mut fraction_digits = 0i32;
        while i < s.len() {
            let c = s[i];
            if c.is_ascii_digit() {
                digits += 1;
                mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(c - b'0'));
                fraction_digits += i32::from(decimal);
            } else if c == b'.' {
                if decimal {
                    return Err(self.two_points(line, s, at, letter, num_start, i));
                }
                decimal = true;
            } else {
                break;
            }
            i += 1;
        }
        if digits == 0 {
            return Err(self.no_value(line, s, at, letter, digits_start, negative));
        }
        // The digits from the first one not 0 count; counted only when there could be too many.
        let significant = if digits > MAX_DIGITS { s[digits_start..i].iter().filter(|c| c.is_ascii_digit()).skip_while(|&&c| c == b'0').count() } else { 0 };
        if significant > MAX_DIGITS {
            return Err(Diagnostic::new(
                Rule::TooManyDigits,
                self.style,
                span_to(i),
                format!("{}{}: {significant} digits, at most {MAX_DIGITS} are allowed", letter as char, String::from_utf8_lossy(&s[num_start..i])),
            ));
        }
        let mut value = decimal_value(mantissa, fraction_digits, &s[digits_start..i]);
        if negative {
            value = -value;
        }
        Ok((Word { letter, value, decimal, expr: false, span: span_to(i) }, i))
    }

    /// The word of `letter` (at `at`) whose value is the `[expr]` opening at `i`, evaluated now
    /// (it holds constants only). Returns the word and the index after its `]`.
    fn expression_word(&self, line: u32, s: &[u8], at: usize, letter: u8, i: usize) -> Result<(Word, usize), Diagnostic> {
        let span_to = |end: usize| word_span(line, at, end);
        let j = matching_bracket(s, i).unwrap_or(s.len());
        if j >= s.len() {
            return Err(Diagnostic::new(Rule::Expression, self.style, span_to(s.len()), format!("{}[: the expression has no closing ']'", letter as char)));
        }
        // ROUND inside an address rounds to the address's least increment, which depends
        // on G20/G21: such a line is read as a macro line and evaluated when it runs.
        if s[i + 1..j].windows(5).any(|w| w.eq_ignore_ascii_case(b"ROUND")) {
            return Err(Diagnostic::new(Rule::Expression, self.style, span_to(j + 1), ROUND_LATER));
        }
        match expr::evaluate(&s[i + 1..j]) {
            Ok(v) => Ok((Word { letter, value: v, decimal: true, expr: true, span: span_to(j + 1) }, j + 1)),
            Err(e) => Err(Diagnostic::new(
                Rule::Expression,
                self.style,
                span_to(j + 1),
                format!("{}[{}]: {}", letter as char, String::from_utf8_lossy(&s[i + 1..j]), e.message),
            )),
        }
    }

    /// The alarm for a second decimal point at `i` in the value that starts at `num_start`.
    #[cold]
    fn two_points(&self, line: u32, s: &[u8], at: usize, letter: u8, num_start: usize, i: usize) -> Diagnostic {
        let mut end = i + 1;
        while end < s.len() && (s[end].is_ascii_digit() || s[end] == b'.') {
            end += 1;
        }
        Diagnostic::new(
            Rule::IllegalDecimalPoint,
            self.style,
            word_span(line, at, end),
            format!("{}{}: two decimal points in one value", letter as char, String::from_utf8_lossy(&s[num_start..end])),
        )
        .with_hint("delete one of the decimal points")
    }

    /// The alarm for an address with no number after it (its digits would start at
    /// `digits_start`): the letter O where a zero was meant, or a minus sign alone, named.
    #[cold]
    fn no_value(&self, line: u32, s: &[u8], at: usize, letter: u8, digits_start: usize, negative: bool) -> Diagnostic {
        let span_to = |end: usize| word_span(line, at, end);
        let next = s.get(digits_start).copied();
        let mut d = Diagnostic::new(
            Rule::NoDataAfterAddress,
            self.style,
            span_to(digits_start.max(at + 1)),
            format!("address {} has no value after it", letter as char),
        );
        if matches!(next, Some(b'O' | b'o')) {
            d.span = span_to(digits_start + 1);
            d.message = format!("{}{}: address {} is followed by the letter O, not a number", letter as char, next.unwrap() as char, letter as char);
            d = d.with_hint("letter O where a zero was probably meant");
        } else if negative {
            d.rule = Rule::IllegalMinus;
            d.code = Rule::IllegalMinus.code(self.style);
            d.message = format!("{}-: a minus sign without a number", letter as char);
        }
        d
    }
}

/// The block being read: what it holds so far and where its text starts and ends on the line.
struct OpenBlock {
    block: Block,
    /// Where its text starts: none while only blanks and comments were read.
    start: Option<usize>,
    /// Where its text read so far ends.
    end: usize,
}

impl OpenBlock {
    /// End the block at `end` (at a `;`, or before an O word that starts the next programme)
    /// into `out`, and open the next one, empty.
    #[inline]
    fn close(&mut self, line_no: u32, end: usize, out: &mut Line) {
        let next = out.new_block();
        out.finish_block(line_no, std::mem::replace(&mut self.block, next), self.start, end);
    }
}

/// The span of a word from its letter at `at` to `end` (at least one byte).
#[inline]
fn word_span(line: u32, at: usize, end: usize) -> Span {
    Span::new(line, at as u32 + 1, (end - at).max(1) as u32)
}

/// `mantissa / 10^fraction_digits`, correctly rounded as `str::parse` gives it: exact when both
/// are exact doubles (one IEEE division); `text` (digits and a point) is parsed otherwise.
fn decimal_value(mantissa: u64, fraction_digits: i32, text: &[u8]) -> f64 {
    const POW10: [f64; 23] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22];
    if mantissa < 1 << 53 && (fraction_digits as usize) < POW10.len() {
        return mantissa as f64 / POW10[fraction_digits as usize];
    }
    std::str::from_utf8(text).ok().and_then(|t| t.parse().ok()).unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `,A30.` is its own address (`a`), its span from the comma; a comma with no letter is a
    /// character not allowed.
    #[test]
    fn comma_words_are_addresses_of_their_own() {
        let r = Reader::new(AlarmStyle::Fanuc);
        let line = r.read_line(1, b"G01 X10. ,A30. ,C1.");
        let b = line.blocks[0].as_ref().unwrap();
        assert_eq!(b.words.iter().map(|w| w.letter).collect::<Vec<_>>(), vec![b'G', b'X', b'a', b'c']);
        assert_eq!((b.words[2].span.col, b.words[2].span.len), (10, 5));
        assert_eq!(b.words[2].text(), ",A30.");
        let line = r.read_line(1, b"G01 X#1 ,R#2");
        let m = line.blocks[0].as_ref().unwrap().macro_block.as_ref().unwrap();
        let Stmt::Words(words) = &m.stmt else { panic!("{m:?}") };
        assert_eq!(words[2].letter, b'r');
        assert!(r.read_line(1, b"G01 X10.,").blocks[0].is_err());
    }

    #[test]
    fn numbers_as_str_parse_reads_them() {
        for t in ["0", "5.", ".5", "1.000", "0.1", "123.456789", "99999.999", "0.000000000000000000000001", "000123.4500", "7.0000001"] {
            let l = read(&format!("X{t}"));
            let v = l.blocks[0].as_ref().unwrap().words[0].value;
            assert_eq!(v, t.parse::<f64>().unwrap(), "{t}");
        }
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..20_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let digits = format!("{}", state % 1_000_000_000);
            let point = (state >> 40) as usize % (digits.len() + 1);
            let t = format!("{}.{}", &digits[..point], &digits[point..]);
            let v = read(&format!("Y-{t}")).blocks[0].as_ref().unwrap().words[0].value;
            assert_eq!(v, -t.parse::<f64>().unwrap(), "{t}");
        }
    }

    /// FANUC PS0003: at most MAX_DIGITS significant digits; zeros before the first other
    /// digit do not count, wherever the point stands.
    #[test]
    fn significant_digits_are_counted_from_the_first_digit_not_zero() {
        let alarm = |t: &str| read(t).blocks[0].as_ref().err().map(|d| (d.rule, d.message.clone()));
        assert_eq!(alarm("X123456789"), None);
        assert_eq!(alarm("X000000000123.456789"), None);
        assert_eq!(alarm("X0.000000000123456789"), None);
        assert_eq!(alarm("X-0000.0000123456789"), None);
        assert_eq!(alarm("X1234567891"), Some((Rule::TooManyDigits, "X1234567891: 10 digits, at most 9 are allowed".to_string())));
        assert_eq!(alarm("X0.0001234567891"), Some((Rule::TooManyDigits, "X0.0001234567891: 10 digits, at most 9 are allowed".to_string())));
        assert_eq!(alarm("X12345.67891"), Some((Rule::TooManyDigits, "X12345.67891: 10 digits, at most 9 are allowed".to_string())));
    }

    /// One pass finds the bytes that change how a line is read; a `#` or 0x1A inside a
    /// comment counts too (the reader looks closer), `$ @ = <` are another language's signs.
    #[test]
    fn byte_marks_find_the_rare_and_the_foreign_bytes() {
        let marks = |t: &[u8]| (ByteMarks::of(t).has(ByteMarks::RARE), ByteMarks::of(t).has(ByteMarks::FOREIGN));
        assert_eq!(marks(b"G01 X1. Y2. F100"), (false, false));
        assert_eq!(marks(b"#1=2"), (true, true));
        assert_eq!(marks(b"G01 X#1"), (true, false));
        assert_eq!(marks(b"(a # in a note)"), (true, false));
        assert_eq!(marks(b"G01 X1.\x1a"), (true, false));
        for sign in [b'$', b'@', b'=', b'<'] {
            assert_eq!(marks(&[b'N', b'1', sign]), (false, true));
        }
        assert_eq!(read("G01 X1. (#1)").blocks[0].as_ref().unwrap().words.len(), 2);
    }

    fn read(s: &str) -> Line {
        Reader::new(AlarmStyle::Project).read_line(1, s.as_bytes())
    }

    fn words(s: &str) -> Vec<(char, f64, bool)> {
        let l = read(s);
        let b = l.blocks[0].as_ref().unwrap();
        b.words.iter().map(|w| (w.letter as char, w.value, w.decimal)).collect()
    }

    #[test]
    fn words_without_spaces() {
        assert_eq!(words("G92X20Z-30F1.5"), vec![('G', 92.0, false), ('X', 20.0, false), ('Z', -30.0, false), ('F', 1.5, true)]);
        assert_eq!(words("g01 x-.5 z+3."), vec![('G', 1.0, false), ('X', -0.5, true), ('Z', 3.0, true)]);
    }

    #[test]
    fn sequence_program_comments_and_eob() {
        let l = read("N10 G0 X1 (to X1) ; (tool) ");
        assert_eq!(l.blocks.len(), 2);
        let b = l.blocks[0].as_ref().unwrap();
        assert_eq!(b.sequence, Some(10));
        assert_eq!(b.comments, vec!["to X1".to_string()]);
        let l = read("O0012;");
        assert_eq!(l.blocks[0].as_ref().unwrap().program, Some(12));
        assert!(read("%").tape_mark);
    }

    #[test]
    fn expression_value() {
        let w = words("F[25.4/10]");
        assert_eq!(w[0].0, 'F');
        assert!((w[0].1 - 2.54).abs() < 1e-12);
        assert!(w[0].2);
    }

    #[test]
    fn typos_get_hints() {
        let l = read("GO X0.");
        let d = l.blocks[0].as_ref().unwrap_err();
        assert_eq!(d.rule, Rule::NoDataAfterAddress);
        assert!(d.hint.as_deref().unwrap().contains("letter O"));
        let l = read("G0X-4.5.Z0.");
        let d = l.blocks[0].as_ref().unwrap_err();
        assert_eq!(d.rule, Rule::IllegalDecimalPoint);
        assert_eq!(d.span.col, 3);
        let l = read("N10 21 G40");
        assert_eq!(l.blocks[0].as_ref().unwrap_err().rule, Rule::ImproperAddress);
    }

    #[test]
    fn bytes_that_are_not_utf8() {
        let l = Reader::new(AlarmStyle::Project).read_line(1, b"G0 X1 (FURA\x80AO)\r\n");
        assert!(l.blocks[0].is_ok());
        let l = Reader::new(AlarmStyle::Project).read_line(1, b"G0 X1 \xC3\xA9");
        assert_eq!(l.blocks[0].as_ref().unwrap_err().rule, Rule::BadCharacter);
        let l = Reader::new(AlarmStyle::Project).read_line(1, b"\xEF\xBB\xBF%");
        assert!(l.tape_mark);
        let l = Reader::new(AlarmStyle::Project).read_line(3, b"\x1A");
        assert!(l.end_of_file);
    }

    #[test]
    fn a_simulator_stock_line_is_a_warning_and_skipped() {
        let l = read("[BILLET X42.86 Z82");
        assert!(l.blocks.is_empty());
        assert_eq!(l.warnings[0].rule, Rule::SimulatorStock);
        assert!(l.warnings[0].message.contains("diameter 42.86 mm, 82 mm long"), "{}", l.warnings[0].message);
        let l = read("[BILLET X42.86");
        assert!(l.blocks.is_empty() && l.warnings[0].message.contains("could not be read"));
        // Another simulator's line is still an alarm, with the hint.
        let d = read("[EDGEMOVE X42.86").blocks.remove(0).unwrap_err();
        assert_eq!(d.rule, Rule::BadCharacter);
        assert!(d.hint.as_deref().unwrap().contains("simulator"));
        // A bracket after a word is an expression, not such a line.
        assert!(read("X[1+2]").blocks[0].is_ok());
    }

    #[test]
    fn long_line_is_one_alarm() {
        let s = "G1".to_string() + &" X1".repeat(40_000);
        let l = read(&s);
        assert_eq!(l.blocks.len(), 1);
        assert_eq!(l.blocks[0].as_ref().unwrap_err().rule, Rule::LineTooLong);
    }

    #[test]
    fn g_code_with_point() {
        let l = read("G32.1 X1");
        let b = l.blocks[0].as_ref().unwrap();
        assert_eq!(b.words[0].code(), (32, Some(1)));
        let l = read("G00.0");
        assert_eq!(l.blocks[0].as_ref().unwrap().words[0].code(), (0, Some(0)));
    }
}
