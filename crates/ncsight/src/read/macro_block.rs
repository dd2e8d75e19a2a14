//! Blocks of custom macro B (docs/reference/macro.md sections 5 and 6): assignments `#1=...`, `IF [..] GOTO n`,
//! `IF [..] THEN #i=...`, `WHILE [..] DO m`, `END m`, `GOTO n`, and NC blocks whose words take
//! their values from variables or expressions (`X#1`, `Z[#2-1.5]`). They are read into
//! expression trees here; the programme evaluates them with the variables in force when the
//! block runs. A line without `#` and without a macro keyword never comes here.

use super::expr::{self, Arena, ErrorKind, ExprError};
use super::{Block, Reader};
use crate::alarm::{Diagnostic, Rule};
use crate::source::Span;

/// What a macro block does.
#[derive(Debug, Clone, PartialEq)]
pub enum Stmt {
    /// An NC block: every word of it, in order, its value a tree.
    Words(Vec<MacroWord>),
    /// `#i = value` (the tree of the variable's number, the value).
    Assign { var: u32, value: u32 },
    /// `IF [cond] GOTO n` or `IF [cond] THEN #i = value`.
    If { cond: u32, then: Then },
    /// `WHILE [cond] DO m`.
    While { cond: u32, label: u32 },
    /// `END m`.
    End { label: u32 },
    /// `GOTO n` (n may be computed).
    Goto { target: u32 },
}

#[derive(Debug, Clone, PartialEq)]
pub enum Then {
    Goto(u32),
    /// `written`: THEN was written (a real FANUC 0i programme leaves it out).
    Assign {
        var: u32,
        value: u32,
        written: bool,
    },
}

/// One word of an NC block in a macro: its letter, the tree of its value, whether it was written
/// with a decimal point (constants only: a value from a variable always has one).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MacroWord {
    pub letter: u8,
    pub node: u32,
    pub decimal: bool,
    /// A constant written without a point whose value is read in least input increments.
    pub constant: bool,
    pub span: Span,
}

/// The macro part of a block.
#[derive(Debug, Clone, PartialEq)]
pub struct MacroBlock {
    pub arena: Arena,
    pub stmt: Stmt,
}

/// Keywords that start a macro statement.
const KEYWORDS: [&[u8]; 5] = [b"IF", b"WHILE", b"GOTO", b"END", b"DO"];
/// Output statements a FANUC may have (not simulated).
const OUTPUT: [&[u8]; 5] = [b"POPEN", b"PCLOS", b"DPRNT", b"BPRNT", b"SETVN"];

fn starts_with_keyword(s: &[u8], words: &[&[u8]]) -> Option<usize> {
    let run = s.iter().take_while(|c| c.is_ascii_alphabetic()).count();
    // `GOTO5`, `END1`, `DO2`: the keyword runs into digits, never into more letters except IF.
    words.iter().find(|k| run == k.len() && s[..k.len()].eq_ignore_ascii_case(k)).map(|k| k.len())
}

/// Whether the block text at `s` (after `/` and N) is a macro statement.
pub(super) fn is_statement(s: &[u8]) -> bool {
    s.first() == Some(&b'#') || starts_with_keyword(s, &KEYWORDS).is_some() || starts_with_keyword(s, &OUTPUT).is_some()
}

impl Reader {
    fn macro_error(&self, line: u32, base: usize, e: &ExprError, what: &str) -> Diagnostic {
        let rule = match e.kind {
            ErrorKind::Nesting => Rule::BracketNesting,
            ErrorKind::DivideByZero => Rule::DivideByZero,
            ErrorKind::Argument => Rule::MacroArgument,
            _ => Rule::MacroFormat,
        };
        Diagnostic::new(rule, self.style, Span::new(line, (base + e.at) as u32 + 1, 1), format!("{what}: {}", e.message))
    }

    /// The blocks of a line that holds `#` (or a block that starts with a macro keyword): each
    /// block (split at `;` outside comments) with its `/` and N, then its body as a macro
    /// block. Pushes the blocks into `out`; stops at the first alarm.
    pub(super) fn read_macro_blocks(&self, line: u32, s: &[u8], from: usize, out: &mut super::Line) {
        let mut i = from;
        while i < s.len() {
            // The end of this block: a ';' outside a comment.
            let mut end = i;
            let mut in_comment = false;
            while end < s.len() {
                match s[end] {
                    b'(' => in_comment = true,
                    b')' => in_comment = false,
                    b';' if !in_comment => break,
                    _ => {}
                }
                end += 1;
            }
            let mut block = out.new_block();
            let mut j = i;
            while j < end && (s[j] == b' ' || s[j] == b'\t') {
                j += 1;
            }
            let first = j;
            if j < end && s[j] == b'/' {
                block.block_delete = true;
                j += 1;
                if j < end && (b'1'..=b'9').contains(&s[j]) {
                    j += 1;
                }
            }
            while j < end && (s[j] == b' ' || s[j] == b'\t') {
                j += 1;
            }
            if j < end && (s[j] == b'N' || s[j] == b'n') && s.get(j + 1).is_some_and(u8::is_ascii_digit) {
                let n = s[j + 1..end].iter().take_while(|b| b.is_ascii_digit()).count();
                let digits = std::str::from_utf8(&s[j + 1..j + 1 + n]).unwrap_or("0");
                match digits.parse::<u32>() {
                    Ok(v) if n <= 8 => block.sequence = Some(v),
                    _ => {
                        out.blocks.push(Err(Diagnostic::new(
                            Rule::TooManyDigits,
                            self.style,
                            Span::new(line, j as u32 + 1, n as u32 + 1),
                            format!("N{digits}: a sequence number has at most 8 digits"),
                        )));
                        return;
                    }
                }
                j += 1 + n;
            }
            let body_end = s[..end].iter().rposition(|b| !matches!(b, b' ' | b'\t')).map_or(j, |k| (k + 1).max(j));
            let only_comments = s[j..body_end].iter().all(|b| matches!(b, b' ' | b'\t'))
                || s[j..body_end].first() == Some(&b'(') && s[j..body_end].last() == Some(&b')') && !s[j..body_end].contains(&b'#');
            if first < body_end {
                block.span = Span::new(line, first as u32 + 1, (body_end - first) as u32);
                if only_comments {
                    if j < body_end {
                        block.comments.push(String::from_utf8_lossy(&s[j + 1..body_end - 1]).into_owned());
                    }
                } else if let Err(d) = self.read_macro(line, s, j, body_end, &mut block) {
                    out.blocks.push(Err(d));
                    return;
                }
                out.blocks.push(Ok(block));
            }
            i = end + 1;
        }
    }

    /// Read the block `s[body..end]` (without its `;`) as a macro block into `block` (its
    /// `/` and N already taken by the caller).
    pub(super) fn read_macro(&self, line: u32, s: &[u8], body: usize, end: usize, block: &mut Block) -> Result<(), Diagnostic> {
        let text = &s[body..end];
        let mut arena = Arena::default();
        let whole = String::from_utf8_lossy(text).trim().to_string();
        // Comments inside a macro block are taken out first (they hold any bytes).
        let mut clean = Vec::with_capacity(text.len());
        let mut map = Vec::with_capacity(text.len());
        let mut k = 0;
        while k < text.len() {
            if text[k] == b'(' {
                let close = text[k + 1..].iter().position(|&b| b == b')').map_or(text.len(), |c| k + 1 + c);
                block.comments.push(String::from_utf8_lossy(&text[k + 1..close]).into_owned());
                k = close + 1;
                continue;
            }
            clean.push(text[k]);
            map.push(body + k);
            k += 1;
        }
        map.push(body + text.len());
        let m = MacroText { reader: self, line, clean, map, whole };
        let stmt = m.statement(&mut arena)?;
        block.macro_block = Some(Box::new(MacroBlock { arena, stmt }));
        Ok(())
    }
}

/// The text of one macro block, its comments taken out, as the statement readers see it.
struct MacroText<'a> {
    reader: &'a Reader,
    line: u32,
    /// The block without its comments.
    clean: Vec<u8>,
    /// Where each byte of `clean` stood on the line (one more for its end).
    map: Vec<usize>,
    /// The block as written, for the alarms' messages.
    whole: String,
}

impl MacroText<'_> {
    /// The place on the line of the byte `i` of the clean text.
    fn at(&self, i: usize) -> usize {
        self.map[i.min(self.map.len() - 1)]
    }

    /// The span of the line's bytes `a..b` (at least one).
    fn span_at(&self, a: usize, b: usize) -> Span {
        Span::new(self.line, a as u32 + 1, (b - a).max(1) as u32)
    }

    /// Step over spaces and tabs.
    fn skip_ws(&self, i: &mut usize) {
        let c = &self.clean[..];
        while *i < c.len() && (c[*i] == b' ' || c[*i] == b'\t') {
            *i += 1;
        }
    }

    /// One operand at `i` (a number, a variable, a bracketed expression, a function), `i`
    /// moved past it.
    fn operand(&self, arena: &mut Arena, i: &mut usize) -> Result<u32, Diagnostic> {
        match expr::parse_operand(&self.clean[*i..], arena) {
            Ok((root, used)) => {
                *i += used;
                Ok(root)
            }
            Err(e) => Err(self.reader.macro_error(self.line, self.at(*i), &e, &self.whole)),
        }
    }

    /// The rest of the block as one expression (the value of an assignment).
    fn rest(&self, arena: &mut Arena, i: usize) -> Result<u32, Diagnostic> {
        expr::parse(&self.clean[i..], arena, false, false).map_err(|e| self.reader.macro_error(self.line, self.at(i), &e, &self.whole))
    }

    /// `#i = expr`.
    fn assignment(&self, arena: &mut Arena, mut i: usize) -> Result<(u32, u32), Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        let start = i;
        let var = self.operand(arena, &mut i)?;
        let number = match arena.nodes[var as usize] {
            expr::Node::Var(n) => n,
            _ => {
                return Err(Diagnostic::new(Rule::MacroFormat, style, self.span_at(self.at(start), self.at(i)), format!("{whole}: a variable (#) is assigned"))
                    .with_hint("write #1 = 10."))
            }
        };
        self.skip_ws(&mut i);
        if c.get(i) != Some(&b'=') {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                self.span_at(self.at(start), self.at(i)),
                format!("{whole}: '=' expected after the variable"),
            ));
        }
        let value = self.rest(arena, i + 1)?;
        Ok((number, value))
    }

    /// The condition in brackets after IF or WHILE (`key`), `i` moved past its `]`.
    fn bracket_condition(&self, arena: &mut Arena, i: &mut usize, key: &str) -> Result<u32, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        self.skip_ws(i);
        if c.get(*i) != Some(&b'[') {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                self.span_at(self.at(*i), self.at(*i) + 1),
                format!("{whole}: {key} takes a condition in brackets: {key} [#1 GT 0]"),
            ));
        }
        let Some(j) = super::matching_bracket(c, *i) else {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                self.span_at(self.at(*i), self.at(c.len())),
                format!("{whole}: the condition has no closing ']'"),
            ));
        };
        let root = expr::parse(&c[*i + 1..j], arena, true, true).map_err(|e| self.reader.macro_error(self.line, self.at(*i + 1), &e, whole))?;
        *i = j + 1;
        Ok(root)
    }

    /// The loop number after DO or END (`key`), `i` moved past it.
    fn label(&self, i: &mut usize, key: &str) -> Result<u32, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        self.skip_ws(i);
        let n = c[*i..].iter().take_while(|b| b.is_ascii_digit()).count();
        let digits = std::str::from_utf8(&c[*i..*i + n]).unwrap_or("");
        let v = digits.parse::<u32>().map_err(|_| {
            Diagnostic::new(Rule::MacroFormat, style, self.span_at(self.at(*i), self.at(*i) + 1), format!("{whole}: {key} takes a loop number (1 to 3)"))
        })?;
        *i += n;
        Ok(v)
    }

    /// Nothing but spaces may follow `i`.
    fn done(&self, i: usize) -> Result<(), Diagnostic> {
        let c = &self.clean[..];
        let mut j = i;
        self.skip_ws(&mut j);
        if j < c.len() {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                self.reader.style,
                self.span_at(self.at(j), self.at(c.len())),
                format!("{}: unexpected '{}'", self.whole, String::from_utf8_lossy(&c[j..]).trim()),
            ));
        }
        Ok(())
    }

    /// What the block does: an assignment, a statement after its keyword, or an NC block.
    fn statement(&self, arena: &mut Arena) -> Result<Stmt, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        let trimmed_start = c.iter().take_while(|c| c.is_ascii_whitespace()).count();
        let i = trimmed_start;
        let stmt = if c.get(i) == Some(&b'#') {
            let (var, value) = self.assignment(arena, i)?;
            Stmt::Assign { var, value }
        } else if let Some(n) = starts_with_keyword(&c[i..], &OUTPUT) {
            let key = String::from_utf8_lossy(&c[i..i + n]).to_ascii_uppercase();
            return Err(Diagnostic::new(
                Rule::NotSupported,
                style,
                self.span_at(self.at(i), self.at(c.len())),
                format!("{whole}: the output statement {key} is not simulated by ncsight"),
            ));
        } else if let Some(n) = starts_with_keyword(&c[i..], &KEYWORDS) {
            self.keyword_statement(arena, i, n)?
        } else {
            self.nc_words(arena, i)?
        };
        Ok(stmt)
    }

    /// IF, WHILE, END, GOTO (or a DO alone): the keyword of `n` letters at `i`, the block's
    /// first text.
    fn keyword_statement(&self, arena: &mut Arena, mut i: usize, n: usize) -> Result<Stmt, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        let trimmed_start = i;
        let key = String::from_utf8_lossy(&c[i..i + n]).to_ascii_uppercase();
        i += n;
        Ok(match key.as_str() {
            "IF" => self.if_statement(arena, i)?,
            "WHILE" => {
                let cond = self.bracket_condition(arena, &mut i, "WHILE")?;
                self.skip_ws(&mut i);
                if starts_with_keyword(&c[i..], &[b"DO"]).is_none() {
                    return Err(Diagnostic::new(
                        Rule::MacroFormat,
                        style,
                        self.span_at(self.at(i), self.at(c.len())),
                        format!("{whole}: WHILE [..] is followed by DO m"),
                    ));
                }
                i += 2;
                let label = self.label(&mut i, "DO")?;
                self.done(i)?;
                Stmt::While { cond, label }
            }
            "END" => {
                let label = self.label(&mut i, "END")?;
                self.done(i)?;
                Stmt::End { label }
            }
            "GOTO" => {
                let target = self.rest(arena, i)?;
                Stmt::Goto { target }
            }
            _ => {
                // `DO m` without WHILE: an endless loop on the controller; not simulated.
                return Err(Diagnostic::new(
                    Rule::NotSupported,
                    style,
                    self.span_at(self.at(trimmed_start), self.at(c.len())),
                    format!("{whole}: DO without WHILE (an endless loop) is not simulated by ncsight"),
                ));
            }
        })
    }

    /// `IF [cond] GOTO n` or `IF [cond] THEN #i = value`, from `i` just after IF.
    fn if_statement(&self, arena: &mut Arena, mut i: usize) -> Result<Stmt, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        let cond = self.bracket_condition(arena, &mut i, "IF")?;
        self.skip_ws(&mut i);
        let then = if starts_with_keyword(&c[i..], &[b"GOTO"]).is_some() {
            i += 4;
            let t = self.rest(arena, i)?;
            Then::Goto(t)
        } else if starts_with_keyword(&c[i..], &[b"THEN"]).is_some() {
            i += 4;
            self.skip_ws(&mut i);
            let (var, value) = self.assignment(arena, i)?;
            Then::Assign { var, value, written: true }
        } else if c.get(i) == Some(&b'#') {
            // `IF[#609GT0]#712=#609`: THEN left out, as a real FANUC 0i programme
            // does (the SK7420 punch); the profile says whether that is read as THEN
            // (docs/reference/macro.md section 6, inferred).
            let (var, value) = self.assignment(arena, i)?;
            Then::Assign { var, value, written: false }
        } else {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                self.span_at(self.at(i), self.at(c.len())),
                format!("{whole}: IF [..] is followed by GOTO n or THEN #i = ..."),
            ));
        };
        Ok(Stmt::If { cond, then })
    }

    /// An NC block whose words may take values from variables, from `i` to the end.
    fn nc_words(&self, arena: &mut Arena, mut i: usize) -> Result<Stmt, Diagnostic> {
        let (c, whole, style) = (&self.clean[..], &self.whole, self.reader.style);
        // An NC block whose words may take values from variables.
        let mut words = Vec::new();
        while i < c.len() {
            let b = c[i];
            if b == b' ' || b == b'\t' {
                i += 1;
                continue;
            }
            // A comma word (`,R#1`): the letter in lower case (read/mod.rs).
            let comma = b == b',' && c.get(i + 1).is_some_and(u8::is_ascii_alphabetic);
            let start = i;
            if comma {
                i += 1;
            }
            let b = c[i];
            if !b.is_ascii_alphabetic() {
                return Err(Diagnostic::new(
                    Rule::ImproperAddress,
                    style,
                    self.span_at(self.at(i), self.at(i) + 1),
                    format!("{whole}: '{}' is not an address letter", b as char),
                ));
            }
            let letter = if comma { b.to_ascii_lowercase() } else { b.to_ascii_uppercase() };
            i += 1;
            self.skip_ws(&mut i);
            let value_start = i;
            let node = self.operand(arena, &mut i)?;
            let written = &c[value_start..i];
            let constant = arena.constant(node);
            let decimal = !constant || written.contains(&b'.') || written.contains(&b'[');
            // A sequence or programme number from a variable is not allowed (GSK988T manual,
            // macro variables note 1; NCT manual).
            if matches!(letter, b'N' | b'O') && !constant {
                return Err(Diagnostic::new(
                    Rule::MacroFormat,
                    style,
                    self.span_at(self.at(start), self.at(i)),
                    format!("{whole}: {} cannot take its value from a variable", letter as char),
                ));
            }
            words.push(MacroWord { letter, node, decimal, constant: constant && !decimal, span: self.span_at(self.at(start), self.at(i)) });
        }
        Ok(Stmt::Words(words))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::alarm::AlarmStyle;

    fn read(text: &str) -> Result<Block, Diagnostic> {
        let r = Reader::new(AlarmStyle::Fanuc);
        let l = r.read_line(1, text.as_bytes());
        l.blocks.into_iter().next().unwrap()
    }

    fn stmt(text: &str) -> Stmt {
        read(text).unwrap().macro_block.unwrap().stmt
    }

    #[test]
    fn statements_are_read() {
        assert!(matches!(stmt("#1=10."), Stmt::Assign { .. }));
        assert!(matches!(stmt("#[#1+2] = SIN[30] * 2"), Stmt::Assign { .. }));
        assert!(matches!(stmt("IF [#1 GT 2] GOTO 10"), Stmt::If { then: Then::Goto(_), .. }));
        assert!(matches!(stmt("IF[#1EQ#0]THEN#2=1"), Stmt::If { then: Then::Assign { .. }, .. }));
        assert!(matches!(stmt("IF[#609GT0]#712=#609"), Stmt::If { then: Then::Assign { .. }, .. }));
        assert!(matches!(stmt("WHILE [#1 LT 5] DO1"), Stmt::While { label: 1, .. }));
        assert!(matches!(stmt("END 1"), Stmt::End { label: 1 }));
        assert!(matches!(stmt("GOTO #5"), Stmt::Goto { .. }));
        let b = read("N20 G01 X#1 Z[#2-1.5] F0.2 (CUT)").unwrap();
        assert_eq!((b.sequence, b.comments.len()), (Some(20), 1));
        let Stmt::Words(w) = b.macro_block.unwrap().stmt else { panic!() };
        assert_eq!(w.iter().map(|w| w.letter).collect::<Vec<_>>(), b"GXZF".to_vec());
        assert!(w[1].decimal && w[3].decimal && !w[0].decimal);
    }

    #[test]
    fn bad_statements_are_alarms() {
        assert_eq!(read("#1").unwrap_err().rule, Rule::MacroFormat);
        assert_eq!(read("IF #1 GT 2 GOTO 5").unwrap_err().rule, Rule::MacroFormat);
        assert_eq!(read("WHILE [1] 5").unwrap_err().rule, Rule::MacroFormat);
        assert_eq!(read("X##1").unwrap_err().rule, Rule::MacroFormat);
        assert_eq!(read("N#1 G00").unwrap_err().rule, Rule::MacroFormat);
        assert_eq!(read("DPRNT[X#1]").unwrap_err().rule, Rule::NotSupported);
    }
}
