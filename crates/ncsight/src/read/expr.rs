//! Expressions: `[expr]` values and custom macro B (docs/reference/macro.md section 5). Parsed into a small
//! tree held in an arena, evaluated later with the variables in force (or at once, for a word
//! whose brackets hold constants only). Operators `* / AND` bind tighter than `+ - OR XOR`,
//! functions tightest; comparisons (EQ NE GT GE LT LE) exist in conditions. Angles in degrees.
//! The result must be a finite number; anything else is an alarm.

/// Deepest bracket nesting the reader accepts (a hostile programme cannot blow the stack); a
/// profile's own, lower limit is checked when the expression runs (FANUC alarm 118).
pub const MAX_DEPTH: usize = 32;

/// Why an expression has no value. `at` is a byte offset inside the expression text.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprError {
    pub at: usize,
    pub message: String,
    pub kind: ErrorKind,
    /// A division by zero whose divisor is a variable: its number (the hint names what gives it).
    pub divisor: Option<i64>,
}

/// What went wrong, so that the caller can give the controller's own alarm.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Not an expression (FANUC 0 alarm 114 FORMAT ERROR IN MACRO).
    Format,
    /// Division by zero, the tangent of 90 degrees (alarm 112).
    DivideByZero,
    /// Outside a function's domain: the square root of a negative number (alarm 119).
    Argument,
    /// Not a finite number (alarm 111).
    Overflow,
    /// Brackets nested deeper than allowed (alarm 118).
    Nesting,
    /// A variable where none may be (a constant expression).
    Variable,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    And,
    Or,
    Xor,
    Mod,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CmpOp {
    Eq,
    Ne,
    Gt,
    Ge,
    Lt,
    Le,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Abs,
    Round,
    Fix,
    Fup,
    Ln,
    Exp,
    Bin,
    Bcd,
}

impl Func {
    fn by_name(name: &[u8]) -> Option<Func> {
        const NAMES: [(&[u8], Func); 15] = [
            (b"SIN", Func::Sin),
            (b"COS", Func::Cos),
            (b"TAN", Func::Tan),
            (b"ASIN", Func::Asin),
            (b"ACOS", Func::Acos),
            (b"ATAN", Func::Atan),
            (b"SQRT", Func::Sqrt),
            (b"ABS", Func::Abs),
            (b"ROUND", Func::Round),
            (b"FIX", Func::Fix),
            (b"FUP", Func::Fup),
            (b"LN", Func::Ln),
            (b"EXP", Func::Exp),
            (b"BIN", Func::Bin),
            (b"BCD", Func::Bcd),
        ];
        NAMES.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|(_, f)| *f)
    }
}

/// A node of an expression tree; children are indices into the same arena.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Node {
    Num(f64),
    /// `#n`, `#[expr]`: the variable whose number the child gives.
    Var(u32),
    Neg(u32),
    Bin(BinOp, u32, u32),
    Cmp(CmpOp, u32, u32),
    Call(Func, u32),
    /// `ATAN[a]/[b]`: the angle of the point (b, a), 0 to 360 degrees.
    Atan2(u32, u32),
}

/// Expression trees of one block, side by side.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Arena {
    pub nodes: Vec<Node>,
    /// The deepest bracket nesting written in the block (functions' brackets count).
    pub depth: u8,
}

impl Arena {
    fn push(&mut self, n: Node) -> u32 {
        self.nodes.push(n);
        (self.nodes.len() - 1) as u32
    }

    /// Whether the tree at `root` reads no variable.
    pub fn constant(&self, root: u32) -> bool {
        match self.nodes[root as usize] {
            Node::Num(_) => true,
            Node::Var(_) => false,
            Node::Neg(a) | Node::Call(_, a) => self.constant(a),
            Node::Bin(_, a, b) | Node::Cmp(_, a, b) | Node::Atan2(a, b) => self.constant(a) && self.constant(b),
        }
    }

    /// Whether the tree at `root` is a bare variable (`#1`, `-#1`): a vacant one makes its word
    /// disappear (docs/reference/macro.md section 4.2).
    pub fn bare_variable(&self, root: u32) -> bool {
        match self.nodes[root as usize] {
            Node::Var(_) => true,
            Node::Neg(a) => matches!(self.nodes[a as usize], Node::Var(_)),
            _ => false,
        }
    }
}

/// A value: a number, or vacant (`#0`, a variable never set).
pub type Value = Option<f64>;

/// Where an expression reads its variables.
pub trait Variables {
    /// The value of variable `number` (a whole number); an error when there is no such variable.
    fn read(&mut self, number: i64) -> Result<Value, ExprError>;
}

/// No variables: a constant expression.
pub struct NoVariables;

impl Variables for NoVariables {
    fn read(&mut self, _: i64) -> Result<Value, ExprError> {
        Err(ExprError { at: 0, message: "a variable (#) cannot be read here".into(), kind: ErrorKind::Variable, divisor: None })
    }
}

fn fail(kind: ErrorKind, message: impl Into<String>) -> ExprError {
    ExprError { at: 0, message: message.into(), kind, divisor: None }
}

/// The number of a variable: a whole number (rounded: `#[1.4]` is #1; docs/reference/macro.md section 3).
pub fn variable_number(v: Value) -> Result<i64, ExprError> {
    let v = v.ok_or_else(|| fail(ErrorKind::Format, "a variable number is vacant"))?;
    if v.abs() > 1e9 {
        return Err(fail(ErrorKind::Format, format!("#{v}: no such variable")));
    }
    Ok(v.round() as i64)
}

/// An integer for AND, OR, XOR, BIN and BCD.
fn whole(v: f64) -> i64 {
    v.round().clamp(-9.0e15, 9.0e15) as i64
}

/// Evaluate the tree at `root`. Arithmetic treats vacant as 0; a bare variable keeps its
/// vacancy; EQ and NE tell vacant from 0, GT GE LT LE do not (docs/reference/macro.md section 4).
pub fn eval(arena: &Arena, root: u32, vars: &mut dyn Variables) -> Result<Value, ExprError> {
    eval_rounding(arena, root, vars, 1.0)
}

/// `x` rounded to a whole number of `step` (1, 0.001 or 0.0001), half away from zero, as the
/// nearest double to that decimal: 24.2660000001 to 0.001 gives the same value as `24.266`
/// written out (a multiple of 0.001 times 0.001 would not).
pub fn round_to_step(x: f64, step: f64) -> f64 {
    let per = (1.0 / step).round();
    (x * per).round() / per
}

/// [`eval`] in an NC address: ROUND rounds to the address's least increment `round_step`
/// (FANUC's own example `X[ROUND[#1]+ROUND[#2]]`, as the HAAS manual copies it).
pub fn eval_rounding(arena: &Arena, root: u32, vars: &mut dyn Variables, round_step: f64) -> Result<Value, ExprError> {
    let eval = |arena: &Arena, n: u32, vars: &mut dyn Variables| eval_rounding(arena, n, vars, round_step);
    let num = |v: Value| v.unwrap_or(0.0);
    let v = match arena.nodes[root as usize] {
        Node::Num(v) => Some(v),
        Node::Var(n) => {
            let number = variable_number(eval(arena, n, vars)?)?;
            return vars.read(number);
        }
        Node::Neg(a) => {
            let v = eval(arena, a, vars)?;
            // `-#1` with #1 vacant stays vacant (its word disappears).
            return Ok(v.map(|v| -v));
        }
        Node::Bin(op, a, b) => {
            let (x, y) = (num(eval(arena, a, vars)?), num(eval(arena, b, vars)?));
            Some(binary_operation(op, x, y).map_err(|mut e| {
                // `#10 / #700`: the divisor named, vacant or 0.
                if let Node::Var(n) = arena.nodes[b as usize] {
                    if let Node::Num(number) = arena.nodes[n as usize] {
                        e.divisor = Some(number as i64);
                        e.message = format!("{} (the divisor #{} is vacant or 0)", e.message, number as i64);
                    }
                }
                e
            })?)
        }
        Node::Cmp(op, a, b) => {
            let (x, y) = (eval(arena, a, vars)?, eval(arena, b, vars)?);
            Some(comparison(op, x, y))
        }
        Node::Call(f, a) => {
            let x = num(eval(arena, a, vars)?);
            Some(function_value(f, x, round_step)?)
        }
        Node::Atan2(a, b) => {
            let (y, x) = (num(eval(arena, a, vars)?), num(eval(arena, b, vars)?));
            let deg = y.atan2(x).to_degrees();
            Some(if deg < 0.0 { deg + 360.0 } else { deg })
        }
    };
    match v {
        Some(x) if !x.is_finite() => Err(fail(ErrorKind::Overflow, "the value is not a finite number")),
        v => Ok(v),
    }
}

/// The arithmetic and logical operators (`+ - * / MOD AND OR XOR`) on two values, vacant
/// already read as 0; division and MOD by zero are alarms.
#[inline]
fn binary_operation(op: BinOp, x: f64, y: f64) -> Result<f64, ExprError> {
    Ok(match op {
        BinOp::Add => x + y,
        BinOp::Sub => x - y,
        BinOp::Mul => x * y,
        BinOp::Div => {
            if y == 0.0 {
                return Err(fail(ErrorKind::DivideByZero, "division by zero"));
            }
            x / y
        }
        BinOp::Mod => {
            if y == 0.0 {
                return Err(fail(ErrorKind::DivideByZero, "MOD by zero"));
            }
            x % y
        }
        BinOp::And => (whole(x) & whole(y)) as f64,
        BinOp::Or => (whole(x) | whole(y)) as f64,
        BinOp::Xor => (whole(x) ^ whole(y)) as f64,
    })
}

/// A comparison, 1 when it holds and 0 when not: EQ and NE tell vacant from 0, GT GE LT LE
/// read vacant as 0.
#[inline]
fn comparison(op: CmpOp, x: Value, y: Value) -> f64 {
    let num = |v: Value| v.unwrap_or(0.0);
    let holds = match op {
        CmpOp::Eq => x == y,
        CmpOp::Ne => x != y,
        CmpOp::Gt => num(x) > num(y),
        CmpOp::Ge => num(x) >= num(y),
        CmpOp::Lt => num(x) < num(y),
        CmpOp::Le => num(x) <= num(y),
    };
    if holds {
        1.0
    } else {
        0.0
    }
}

/// A function (SIN, SQRT, ROUND, BIN, ...) of the value `x` (vacant already read as 0), ROUND
/// to `round_step`; an argument outside the function's domain is an alarm.
fn function_value(f: Func, x: f64, round_step: f64) -> Result<f64, ExprError> {
    let domain = |ok: bool, what: &str| if ok { Ok(()) } else { Err(fail(ErrorKind::Argument, what.to_string())) };
    Ok(match f {
        Func::Sin => x.to_radians().sin(),
        Func::Cos => x.to_radians().cos(),
        Func::Tan => {
            if (x.rem_euclid(180.0) - 90.0).abs() < 1e-12 {
                return Err(fail(ErrorKind::DivideByZero, format!("TAN[{x}]: the tangent of 90 degrees")));
            }
            x.to_radians().tan()
        }
        Func::Asin => {
            domain((-1.0..=1.0).contains(&x), "ASIN of a number outside -1 to 1")?;
            x.asin().to_degrees()
        }
        Func::Acos => {
            domain((-1.0..=1.0).contains(&x), "ACOS of a number outside -1 to 1")?;
            x.acos().to_degrees()
        }
        Func::Atan => x.atan().to_degrees(),
        Func::Sqrt => {
            domain(x >= 0.0, "the square root of a negative number")?;
            x.sqrt()
        }
        Func::Abs => x.abs(),
        // Half away from zero: ROUND[-1.5] = -2 (docs/reference/macro.md section 5).
        Func::Round => round_to_step(x, round_step),
        // Toward zero and away from zero: FIX[-1.2] = -1, FUP[-1.2] = -2.
        Func::Fix => x.trunc(),
        Func::Fup => {
            let t = x.trunc();
            if t == x {
                t
            } else {
                t + x.signum()
            }
        }
        Func::Ln => {
            domain(x > 0.0, "the logarithm of a number not above 0")?;
            x.ln()
        }
        Func::Exp => x.exp(),
        Func::Bin => {
            // BCD to binary: each group of four bits is a decimal digit.
            let (mut v, mut out, mut scale) = (whole(x).max(0), 0i64, 1i64);
            while v > 0 {
                let digit = v & 0xF;
                domain(digit <= 9, "BIN of a value that is not BCD")?;
                out += digit * scale;
                scale *= 10;
                v >>= 4;
            }
            out as f64
        }
        Func::Bcd => {
            let (mut v, mut out, mut shift) = (whole(x).max(0), 0i64, 0u32);
            while v > 0 && shift < 60 {
                out |= (v % 10) << shift;
                v /= 10;
                shift += 4;
            }
            out as f64
        }
    })
}

/// Parse `text` as one expression into `arena`; its root. `conditions` allows EQ NE GT GE LT
/// LE; `bracketed` says that the caller took the text out of a pair of brackets (they count
/// as the first level of nesting).
pub fn parse(text: &[u8], arena: &mut Arena, conditions: bool, bracketed: bool) -> Result<u32, ExprError> {
    let depth = usize::from(bracketed);
    arena.depth = arena.depth.max(depth as u8);
    let mut p = Parser { s: text, i: 0, depth, arena, conditions };
    let root = p.expr()?;
    p.skip_ws();
    if p.i != p.s.len() {
        return Err(p.err(format!("unexpected '{}'", p.s[p.i] as char)));
    }
    Ok(root)
}

/// Parse one operand at the start of `text` (a number, `#n`, `#[..]`, `[..]`, a function,
/// with a sign): its root and the bytes it took. How an address's value or an assignment's
/// target is read.
pub fn parse_operand(text: &[u8], arena: &mut Arena) -> Result<(u32, usize), ExprError> {
    let mut p = Parser { s: text, i: 0, depth: 0, arena, conditions: false };
    let root = p.unary()?;
    Ok((root, p.i))
}

/// Evaluate the text between the outer brackets (without them), with no variables.
pub fn evaluate(text: &[u8]) -> Result<f64, ExprError> {
    let mut arena = Arena::default();
    let root = parse(text, &mut arena, false, true)?;
    eval(&arena, root, &mut NoVariables)?.ok_or_else(|| fail(ErrorKind::Format, "no value"))
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
    depth: usize,
    arena: &'a mut Arena,
    conditions: bool,
}

impl Parser<'_> {
    fn err(&self, message: String) -> ExprError {
        ExprError { at: self.i, message, kind: ErrorKind::Format, divisor: None }
    }

    fn skip_ws(&mut self) {
        while self.i < self.s.len() && (self.s[self.i] == b' ' || self.s[self.i] == b'\t') {
            self.i += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.s.get(self.i).copied()
    }

    /// A keyword operator (AND, EQ, ...) at the cursor, case-insensitively.
    fn keyword(&mut self, words: &[&[u8]]) -> Option<usize> {
        self.skip_ws();
        let rest = &self.s[self.i..];
        words
            .iter()
            .position(|w| rest.len() >= w.len() && rest[..w.len()].eq_ignore_ascii_case(w) && !rest.get(w.len()).is_some_and(|c| c.is_ascii_alphabetic()))
    }

    /// A comparison, or a sum.
    fn expr(&mut self) -> Result<u32, ExprError> {
        let a = self.sum()?;
        if !self.conditions {
            return Ok(a);
        }
        const OPS: [(&[u8], CmpOp); 6] =
            [(b"EQ", CmpOp::Eq), (b"NE", CmpOp::Ne), (b"GT", CmpOp::Gt), (b"GE", CmpOp::Ge), (b"LT", CmpOp::Lt), (b"LE", CmpOp::Le)];
        let names: Vec<&[u8]> = OPS.iter().map(|(n, _)| *n).collect();
        match self.keyword(&names) {
            Some(k) => {
                self.i += 2;
                let b = self.sum()?;
                Ok(self.arena.push(Node::Cmp(OPS[k].1, a, b)))
            }
            None => Ok(a),
        }
    }

    fn sum(&mut self) -> Result<u32, ExprError> {
        let mut v = self.product()?;
        loop {
            let op = match self.peek() {
                Some(b'+') => (BinOp::Add, 1),
                Some(b'-') => (BinOp::Sub, 1),
                _ => match self.keyword(&[b"OR", b"XOR"]) {
                    Some(0) => (BinOp::Or, 2),
                    Some(_) => (BinOp::Xor, 3),
                    None => return Ok(v),
                },
            };
            self.i += op.1;
            let r = self.product()?;
            v = self.arena.push(Node::Bin(op.0, v, r));
        }
    }

    fn product(&mut self) -> Result<u32, ExprError> {
        let mut v = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(b'*') => (BinOp::Mul, 1),
                Some(b'/') => (BinOp::Div, 1),
                _ => match self.keyword(&[b"AND", b"MOD"]) {
                    Some(0) => (BinOp::And, 3),
                    Some(_) => (BinOp::Mod, 3),
                    None => return Ok(v),
                },
            };
            self.i += op.1;
            let r = self.unary()?;
            v = self.arena.push(Node::Bin(op.0, v, r));
        }
    }

    fn unary(&mut self) -> Result<u32, ExprError> {
        match self.peek() {
            Some(b'-') => {
                self.i += 1;
                let a = self.unary()?;
                Ok(self.arena.push(Node::Neg(a)))
            }
            Some(b'+') => {
                self.i += 1;
                self.unary()
            }
            _ => self.atom(),
        }
    }

    fn bracketed(&mut self) -> Result<u32, ExprError> {
        if self.peek() != Some(b'[') {
            return Err(self.err("'[' expected".into()));
        }
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(ExprError { at: self.i, message: format!("brackets nested deeper than {MAX_DEPTH}"), kind: ErrorKind::Nesting, divisor: None });
        }
        self.arena.depth = self.arena.depth.max(self.depth.min(255) as u8);
        self.i += 1;
        let v = self.expr()?;
        if self.peek() != Some(b']') {
            return Err(self.err("']' expected".into()));
        }
        self.i += 1;
        self.depth -= 1;
        Ok(v)
    }

    fn atom(&mut self) -> Result<u32, ExprError> {
        match self.peek() {
            Some(b'[') => self.bracketed(),
            Some(b'#') => {
                self.i += 1;
                match self.peek() {
                    Some(b'[') => {
                        let n = self.bracketed()?;
                        Ok(self.arena.push(Node::Var(n)))
                    }
                    Some(c) if c.is_ascii_digit() => {
                        let n = self.number()?;
                        Ok(self.arena.push(Node::Var(n)))
                    }
                    // `##1` is not allowed (NCT manual, FANUC-compatible).
                    _ => Err(self.err("'#' is followed by a variable number or [expression]".into())),
                }
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => self.number(),
            Some(c) if c.is_ascii_alphabetic() => {
                let start = self.i;
                while self.i < self.s.len() && self.s[self.i].is_ascii_alphabetic() {
                    self.i += 1;
                }
                let name = &self.s[start..self.i];
                let Some(f) = Func::by_name(name) else {
                    return Err(ExprError {
                        at: start,
                        message: format!("unknown function {}", String::from_utf8_lossy(name).to_ascii_uppercase()),
                        kind: ErrorKind::Format,
                        divisor: None,
                    });
                };
                let arg = self.bracketed()?;
                if f == Func::Atan && self.peek() == Some(b'/') {
                    // FANUC form ATAN[a]/[b].
                    let save = self.i;
                    self.i += 1;
                    if self.peek() == Some(b'[') {
                        let b = self.bracketed()?;
                        return Ok(self.arena.push(Node::Atan2(arg, b)));
                    }
                    self.i = save;
                }
                Ok(self.arena.push(Node::Call(f, arg)))
            }
            Some(c) => Err(self.err(format!("unexpected '{}'", c as char))),
            None => Err(self.err("value expected".into())),
        }
    }

    fn number(&mut self) -> Result<u32, ExprError> {
        self.skip_ws();
        let start = self.i;
        while self.i < self.s.len() && (self.s[self.i].is_ascii_digit() || self.s[self.i] == b'.') {
            self.i += 1;
        }
        let t = std::str::from_utf8(&self.s[start..self.i]).unwrap_or("");
        let v = t.parse::<f64>().map_err(|_| ExprError { at: start, message: format!("'{t}' is not a number"), kind: ErrorKind::Format, divisor: None })?;
        if !v.is_finite() {
            return Err(ExprError { at: start, message: "the value is not a finite number".into(), kind: ErrorKind::Overflow, divisor: None });
        }
        Ok(self.arena.push(Node::Num(v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Vars(Vec<(i64, f64)>);
    impl Variables for Vars {
        fn read(&mut self, n: i64) -> Result<Value, ExprError> {
            Ok(self.0.iter().find(|(k, _)| *k == n).map(|(_, v)| *v))
        }
    }

    fn with(text: &str, vars: &[(i64, f64)]) -> Value {
        let mut arena = Arena::default();
        let root = parse(text.as_bytes(), &mut arena, true, false).unwrap();
        eval(&arena, root, &mut Vars(vars.to_vec())).unwrap()
    }

    #[test]
    fn precedence_and_functions() {
        assert_eq!(evaluate(b"25.4/10").unwrap(), 2.54);
        assert_eq!(evaluate(b"1+2*3").unwrap(), 7.0);
        assert_eq!(evaluate(b"[1+2]*3").unwrap(), 9.0);
        assert_eq!(evaluate(b"-2*-3").unwrap(), 6.0);
        assert!((evaluate(b"SIN[30]").unwrap() - 0.5).abs() < 1e-12);
        assert!((evaluate(b"ATAN[1]/[1]").unwrap() - 45.0).abs() < 1e-12);
        assert!((evaluate(b"ATAN[-1]/[-1]").unwrap() - 225.0).abs() < 1e-12);
        assert_eq!(evaluate(b"sqrt[16]").unwrap(), 4.0);
        // FIX toward zero, FUP away from zero, ROUND half away from zero (docs/reference/macro.md section 5).
        assert_eq!(evaluate(b"FIX[-1.5]").unwrap(), -1.0);
        assert_eq!(evaluate(b"FIX[1.2]").unwrap(), 1.0);
        assert_eq!(evaluate(b"FUP[1.2]").unwrap(), 2.0);
        assert_eq!(evaluate(b"FUP[-1.2]").unwrap(), -2.0);
        assert_eq!(evaluate(b"FUP[-2]").unwrap(), -2.0);
        assert_eq!(evaluate(b"ROUND[2.5]").unwrap(), 3.0);
        assert_eq!(evaluate(b"ROUND[-1.5]").unwrap(), -2.0);
        assert_eq!(evaluate(b"ROUND[-1.4]").unwrap(), -1.0);
        assert_eq!(evaluate(b"BCD[12]").unwrap(), 18.0);
        assert_eq!(evaluate(b"BIN[18]").unwrap(), 12.0);
        assert_eq!(evaluate(b"5 AND 3").unwrap(), 1.0);
        assert_eq!(evaluate(b"5 OR 3").unwrap(), 7.0);
        assert_eq!(evaluate(b"5 XOR 3").unwrap(), 6.0);
        assert_eq!(evaluate(b"7 MOD 4").unwrap(), 3.0);
        // * / AND above + - OR XOR, left to right.
        assert_eq!(evaluate(b"1 OR 2 AND 3").unwrap(), 3.0);
        assert_eq!(evaluate(b"10-4-3").unwrap(), 3.0);
        assert_eq!(evaluate(b"12/2/3").unwrap(), 2.0);
        assert!((evaluate(b"LN[EXP[2]]").unwrap() - 2.0).abs() < 1e-12);
        assert!((evaluate(b"ASIN[1]").unwrap() - 90.0).abs() < 1e-12);
        assert!((evaluate(b"ACOS[0]").unwrap() - 90.0).abs() < 1e-12);
    }

    /// Vacant (docs/reference/macro.md section 4): a bare variable keeps its vacancy, arithmetic reads 0,
    /// EQ and NE tell vacant from 0, GT GE LT LE do not.
    #[test]
    fn vacancy() {
        assert_eq!(with("#1", &[]), None);
        assert_eq!(with("-#1", &[]), None);
        assert_eq!(with("#1*5", &[]), Some(0.0));
        assert_eq!(with("#1+#1", &[]), Some(0.0));
        assert_eq!(with("#0+1", &[]), Some(1.0));
        assert_eq!(with("#1 EQ #0", &[]), Some(1.0));
        assert_eq!(with("#1 EQ 0", &[]), Some(0.0));
        assert_eq!(with("#1 NE 0", &[]), Some(1.0));
        assert_eq!(with("#1 EQ #0", &[(1, 0.0)]), Some(0.0));
        assert_eq!(with("#1 EQ 0", &[(1, 0.0)]), Some(1.0));
        assert_eq!(with("#1 GE #0", &[]), Some(1.0));
        assert_eq!(with("#1 GE #0", &[(1, 0.0)]), Some(1.0));
        assert_eq!(with("#1 GT 0", &[]), Some(0.0));
        assert_eq!(with("#1 LT 0", &[]), Some(0.0));
        assert_eq!(with("#[#2+1]", &[(2, 4.0), (5, 7.5)]), Some(7.5));
        assert_eq!(with("[#1 GT 2] AND [#1 LT 9]", &[(1, 5.0)]), Some(1.0));
    }

    #[test]
    fn no_nan_ever() {
        assert_eq!(evaluate(b"0/0").unwrap_err().kind, ErrorKind::DivideByZero);
        assert_eq!(evaluate(b"SQRT[-1]").unwrap_err().kind, ErrorKind::Argument);
        assert!(evaluate(b"1/0").is_err());
        assert_eq!(evaluate(b"TAN[90]").unwrap_err().kind, ErrorKind::DivideByZero);
        assert!(evaluate(b"1e308").is_err());
        let big = format!("1{}*10", "0".repeat(308));
        assert_eq!(evaluate(big.as_bytes()).unwrap_err().kind, ErrorKind::Overflow);
        assert!(evaluate(b"").is_err());
        assert!(evaluate(b"1+").is_err());
        assert_eq!(evaluate(b"#1").unwrap_err().kind, ErrorKind::Variable);
        assert!(evaluate(b"##1").is_err());
        let deep = format!("{}1{}", "[".repeat(100), "]".repeat(100));
        assert_eq!(evaluate(deep.as_bytes()).unwrap_err().kind, ErrorKind::Nesting);
    }
}
