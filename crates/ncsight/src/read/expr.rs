//! `[expr]` values (../shared/spec/BEHAVIOUR.md, "Numbers and words"): + - * / with the usual
//! precedence, brackets, and the FANUC macro B functions SIN COS TAN ATAN SQRT ABS ROUND FIX FUP,
//! angles in degrees. The result must be a finite number; anything else is an alarm.

/// Deepest bracket nesting accepted; a hostile programme cannot blow the stack.
pub const MAX_DEPTH: usize = 32;

/// Why an expression has no value. `at` is a byte offset inside the expression text.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprError {
    pub at: usize,
    pub message: String,
}

/// Evaluate the text between the outer brackets (without them).
pub fn evaluate(text: &[u8]) -> Result<f64, ExprError> {
    // The outer brackets, stripped by the caller, are the first level of the limit.
    let mut p = Parser { s: text, i: 0, depth: 1 };
    let v = p.sum()?;
    p.skip_ws();
    if p.i != p.s.len() {
        return Err(p.err(format!("unexpected '{}'", p.s[p.i] as char)));
    }
    if !v.is_finite() {
        return Err(ExprError { at: 0, message: "the value is not a finite number".into() });
    }
    Ok(v)
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
    depth: usize,
}

impl Parser<'_> {
    fn err(&self, message: String) -> ExprError {
        ExprError { at: self.i, message }
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

    fn sum(&mut self) -> Result<f64, ExprError> {
        let mut v = self.product()?;
        while let Some(c @ (b'+' | b'-')) = self.peek() {
            self.i += 1;
            let r = self.product()?;
            v = if c == b'+' { v + r } else { v - r };
        }
        Ok(v)
    }

    fn product(&mut self) -> Result<f64, ExprError> {
        let mut v = self.unary()?;
        while let Some(c @ (b'*' | b'/')) = self.peek() {
            let at = self.i;
            self.i += 1;
            let r = self.unary()?;
            if c == b'/' && r == 0.0 {
                return Err(ExprError { at, message: "division by zero".into() });
            }
            v = if c == b'*' { v * r } else { v / r };
        }
        Ok(v)
    }

    fn unary(&mut self) -> Result<f64, ExprError> {
        match self.peek() {
            Some(b'-') => {
                self.i += 1;
                Ok(-self.unary()?)
            }
            Some(b'+') => {
                self.i += 1;
                self.unary()
            }
            _ => self.atom(),
        }
    }

    fn bracketed(&mut self) -> Result<f64, ExprError> {
        if self.peek() != Some(b'[') {
            return Err(self.err("'[' expected".into()));
        }
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.err(format!("brackets nested deeper than {MAX_DEPTH}")));
        }
        self.i += 1;
        let v = self.sum()?;
        if self.peek() != Some(b']') {
            return Err(self.err("']' expected".into()));
        }
        self.i += 1;
        self.depth -= 1;
        Ok(v)
    }

    fn atom(&mut self) -> Result<f64, ExprError> {
        match self.peek() {
            Some(b'[') => self.bracketed(),
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let start = self.i;
                while self.i < self.s.len() && (self.s[self.i].is_ascii_digit() || self.s[self.i] == b'.') {
                    self.i += 1;
                }
                let t = std::str::from_utf8(&self.s[start..self.i]).unwrap_or("");
                t.parse::<f64>().map_err(|_| ExprError { at: start, message: format!("'{t}' is not a number") })
            }
            Some(c) if c.is_ascii_alphabetic() => {
                let start = self.i;
                while self.i < self.s.len() && self.s[self.i].is_ascii_alphabetic() {
                    self.i += 1;
                }
                let name = String::from_utf8_lossy(&self.s[start..self.i]).to_ascii_uppercase();
                let at = start;
                let arg = self.bracketed()?;
                let domain = |ok: bool, what: &str| {
                    if ok { Ok(()) } else { Err(ExprError { at, message: format!("{name}[{arg}]: {what}") }) }
                };
                let v = match name.as_str() {
                    "SIN" => arg.to_radians().sin(),
                    "COS" => arg.to_radians().cos(),
                    "TAN" => {
                        domain((arg.rem_euclid(180.0) - 90.0).abs() > 1e-12, "tangent of 90 degrees")?;
                        arg.to_radians().tan()
                    }
                    "ATAN" => {
                        // FANUC form ATAN[a]/[b]: the angle of the point (b, a), 0..360 degrees.
                        if self.peek() == Some(b'/') {
                            let save = self.i;
                            self.i += 1;
                            if self.peek() == Some(b'[') {
                                let b = self.bracketed()?;
                                let deg = arg.atan2(b).to_degrees();
                                return Ok(if deg < 0.0 { deg + 360.0 } else { deg });
                            }
                            self.i = save;
                        }
                        arg.atan().to_degrees()
                    }
                    "SQRT" => {
                        domain(arg >= 0.0, "square root of a negative number")?;
                        arg.sqrt()
                    }
                    "ABS" => arg.abs(),
                    "ROUND" => arg.round(),
                    "FIX" => arg.floor(),
                    "FUP" => arg.ceil(),
                    _ => return Err(ExprError { at, message: format!("unknown function {name}") }),
                };
                Ok(v)
            }
            Some(b'#') => Err(self.err("macro variables (#) are not supported".into())),
            Some(c) => Err(self.err(format!("unexpected '{}'", c as char))),
            None => Err(self.err("value expected".into())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::evaluate;

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
        assert_eq!(evaluate(b"FIX[-1.5]").unwrap(), -2.0);
        assert_eq!(evaluate(b"FUP[1.2]").unwrap(), 2.0);
        assert_eq!(evaluate(b"ROUND[2.5]").unwrap(), 3.0);
    }

    #[test]
    fn no_nan_ever() {
        assert!(evaluate(b"0/0").is_err());
        assert!(evaluate(b"SQRT[-1]").is_err());
        assert!(evaluate(b"1/0").is_err());
        assert!(evaluate(b"TAN[90]").is_err());
        assert!(evaluate(b"1e308").is_err());
        assert!(evaluate(b"").is_err());
        assert!(evaluate(b"1+").is_err());
        assert!(evaluate(b"#1").is_err());
        let deep = format!("{}1{}", "[".repeat(100), "]".repeat(100));
        assert!(evaluate(deep.as_bytes()).is_err());
    }
}
