//! Custom macro B when a block runs: the variables (local levels, common, system), a macro
//! block's words evaluated into an NC block, and the values of statements. The jumps (GOTO,
//! WHILE/END, G65's call) are the programme's, through the block source.

use crate::alarm::{AlarmStyle, Diagnostic, Rule};
use crate::modal::{Modal, Motion};
use crate::motion::Plane;
use crate::profile::{GFn, Group, Profile};
use crate::read::expr::{self, Arena, ErrorKind, ExprError, Value};
use crate::read::{MacroWord, Word};
use crate::source::Span;

/// Local variables #1-#33 of one level.
pub(super) type Locals = [Value; 33];

/// Common variables kept: #100-#199 and #500-#999 (the FANUC option's ranges, docs/reference/macro.md section
/// 3: the large set avoids false alarms on real programmes; GSK988T manual, macro variables).
const COMMON: [(i64, i64); 2] = [(100, 199), (500, 999)];

/// The variables of a run.
#[derive(Debug)]
pub(super) struct Variables {
    /// Level 0 is the main programme's; each G65 call adds one.
    pub levels: Vec<Locals>,
    common: Vec<Value>,
    /// #3001 and #3002 may be set; the clocks then count from there.
    clock_ms_offset: f64,
    clock_h_offset: f64,
    /// #3901 parts machined, #3902 parts required (0 at the start of a run: ncsight does not
    /// count parts across runs).
    parts: [f64; 2],
    /// The machine's interface signals: inputs #1000-#1015 as the user gave them (`--var`),
    /// the 16 at once in #1032; outputs #1100-#1115 (#1132 all 16), off at the start.
    inputs: [Value; 16],
    input_word: Value,
    outputs: [bool; 16],
}

/// Interface signals (FANUC custom macro B; inferred for the GSK and YASNAC profiles, whose
/// texts at hand list no numbers; docs/reference/macro.md section 3 "system: #1000 up").
const INPUTS: std::ops::RangeInclusive<i64> = 1000..=1015;
const INPUT_WORD: i64 = 1032;

/// Whether `#n` is one of the machine's input signals.
pub(super) fn is_input(n: i64) -> bool {
    INPUTS.contains(&n) || n == INPUT_WORD
}
const OUTPUTS: std::ops::RangeInclusive<i64> = 1100..=1115;
const OUTPUT_WORD: i64 = 1132;

impl Default for Variables {
    fn default() -> Variables {
        Variables {
            levels: vec![[None; 33]],
            common: vec![None; 1000],
            clock_ms_offset: 0.0,
            clock_h_offset: 0.0,
            parts: [0.0; 2],
            inputs: [None; 16],
            input_word: None,
            outputs: [false; 16],
        }
    }
}

/// What a block reads the variables with: the modal state and the clock for system variables.
pub(super) struct Reading<'a> {
    pub vars: &'a Variables,
    pub modal: &'a Modal,
    /// Added to a position for machine coordinates (the setup's offsets in force).
    pub to_machine: crate::motion::Vec3,
    pub profile: &'static Profile,
    /// Seconds of machine time so far.
    pub clock_s: f64,
    /// The running programme's O number and the last sequence number read.
    pub program: Option<u32>,
    pub last_n: Option<u32>,
    /// A G66 modal call is in force (group 12: G66, else G67).
    pub modal_call: bool,
    /// The controlled axes in the control's order (X Y Z A B C letters).
    pub axes: &'a [u8],
    /// The machine's offset and work offset tables (#2001.., #5221.., #10001..).
    pub tables: &'a crate::interp::Tables,
}

fn no_such(number: i64, why: &str) -> ExprError {
    ExprError { at: 0, message: format!("#{number}: {why}"), kind: ErrorKind::Variable, divisor: None }
}

/// A G code's number as the profile's table names the function (`G01` -> 1, `G32.1` -> 32.1).
fn code_of(profile: &Profile, f: GFn) -> Option<f64> {
    profile.name_of(f).strip_prefix('G').and_then(|n| n.parse::<f64>().ok())
}

/// The groups ncsight accepts without modelling, and their codes at power on (the codes the
/// FANUC G-code lists mark as set at power on; inferred where a parameter may change it).
const POWER_ON: [(Group, f64); 10] = [
    (Group::CutterComp, 40.0),
    (Group::LengthComp, 49.0),
    (Group::WorkOffset, 54.0),
    (Group::PathMode, 64.0),
    // The transforms and checks off at power on, as ncsight starts them.
    (Group::StrokeCheck, 23.0),
    (Group::Scaling, 50.0),
    (Group::Rotation, 69.0),
    (Group::Polar, 15.0),
    (Group::MirrorImage, 50.1),
    (Group::SpindleCheck, 25.0),
];

impl Reading<'_> {
    /// The controlled axes in their order (the setup's, else the profile's X Z or X Y Z).
    fn controlled_axes(&self) -> &[u8] {
        self.axes
    }

    /// #4001-#4022: the code in force in FANUC group `number - 4000`, as the profile numbers
    /// its groups (#4000 + the group number; docs/reference/macro.md section 8).
    fn group_code(&self, number: i64) -> Result<Value, ExprError> {
        let (m, p) = (self.modal, self.profile);
        let group = p.macros.group_numbers.iter().find(|(n, _)| i64::from(*n) + 4000 == number).map(|(_, g)| *g);
        let Some(group) = group.filter(|g| p.g_defs().any(|d| d.group == *g)) else {
            return Err(no_such(number, &format!("{} has no G-code group {} (or ncsight does not know its codes)", p.name, number - 4000)));
        };
        let drill_code = m.drill.kind.map(|k| GFn::Drill(k)).filter(|f| p.g_defs().any(|d| d.function == *f && d.group == group));
        let f = match group {
            // A lathe's drilling cycle is a group 01 code on the GSK profiles.
            Group::Motion | Group::CannedCycle if drill_code.is_some() => drill_code,
            Group::Motion => Some(match m.modes.motion {
                Motion::Rapid => GFn::Rapid,
                Motion::Linear => GFn::Linear,
                Motion::ArcCw => GFn::ArcCw,
                Motion::ArcCcw => GFn::ArcCcw,
                Motion::Thread(cmd) => GFn::Thread(cmd),
                Motion::Box(kind) => GFn::BoxCycle(kind),
                Motion::Curve(kind) => GFn::Curve(kind),
            }),
            Group::CannedCycle => Some(GFn::CycleCancel),
            Group::Plane => Some(match m.modes.plane {
                Plane::XY => GFn::PlaneXY,
                Plane::ZX => GFn::PlaneZX,
                Plane::YZ => GFn::PlaneYZ,
            }),
            Group::Distance => Some(if m.modes.incremental { GFn::Incremental } else { GFn::Absolute }),
            Group::FeedMode => Some(if m.modes.per_rev { GFn::FeedPerRevolution } else { GFn::FeedPerMinute }),
            Group::Units => Some(if m.modes.inch { GFn::Inch } else { GFn::Metric }),
            Group::SpindleSpeedMode => Some(if m.modes.css { GFn::ConstantSurfaceSpeed } else { GFn::ConstantRpm }),
            Group::ReturnLevel => Some(if m.modes.return_initial { GFn::ReturnInitial } else { GFn::ReturnR }),
            Group::MacroCall => Some(if self.modal_call { GFn::ModalMacroCall } else { GFn::ModalMacroCancel }),
            _ => None,
        };
        if let Some(f) = f {
            // A group whose codes the profile lists as not simulated yet (G96/G97 on the mill).
            return code_of(p, f).map(Some).ok_or_else(|| no_such(number, "the codes of this group are not simulated by ncsight yet"));
        }
        // The last code commanded in the group, else its power-on code: only for a group whose
        // codes the profile simulates (G61/G64 are not simulated on the lathes yet).
        let simulated = p.g_defs().any(|d| d.group == group && !matches!(d.function, GFn::NotYet(_)));
        match m.notes.group_codes[group as usize] {
            0 if !simulated => Err(no_such(number, "the codes of this group are not simulated by ncsight yet")),
            0 => match POWER_ON.iter().find(|(g, _)| *g == group) {
                Some((_, code)) => Ok(Some(*code)),
                None => Err(no_such(number, "the code in force in this group is not simulated by ncsight yet")),
            },
            code => Ok(Some(f64::from(code) / 10.0)),
        }
    }
}

impl expr::Variables for Reading<'_> {
    fn read(&mut self, number: i64) -> Result<Value, ExprError> {
        let m = self.modal;
        // The position the controller shows (the tool's, plus a tool offset not moved out yet);
        // #5021-#5026 add the machine's offsets.
        let shown = m.place.pos + m.frame.unmoved;
        let machine = m.place.pos + self.to_machine;
        let axis = |letter: u8, p: &crate::motion::Vec3| {
            let (i, v) = match letter {
                b'X' => (0, p.x),
                b'Y' => (1, p.y),
                b'Z' => (2, p.z),
                // A rotary axis: degrees, the same in every coordinate system (no offsets).
                r => return Some(self.modal.place.rotary_deg[usize::from(r - b'A').min(2)]),
            };
            // A diameter X reads as a diameter (docs/reference/macro.md section 8, inferred).
            Some(if i == 0 && self.profile.diameter_x { v * 2.0 } else { v })
        };
        Ok(match number {
            0 => None,
            1..=33 => self.vars.levels.last().map_or(None, |l| l[number as usize - 1]),
            n if COMMON.iter().any(|(a, b)| (*a..=*b).contains(&n)) => self.vars.common[n as usize],
            3000 => None,
            3001 => Some((self.clock_s * 1000.0 - self.vars.clock_ms_offset).max(0.0).floor()),
            3002 => Some(self.clock_s / 3600.0 - self.vars.clock_h_offset),
            3901 | 3902 => Some(self.vars.parts[(number - 3901) as usize]),
            n if is_input(n) => return self.vars.input(n),
            n if OUTPUTS.contains(&n) => Some(f64::from(u8::from(self.vars.outputs[(n - 1100) as usize]))),
            OUTPUT_WORD => Some(self.vars.outputs.iter().rev().fold(0.0, |w, on| w * 2.0 + f64::from(u8::from(*on)))),
            // Modal information (FANUC #4001-#4022, #4102-#4120).
            4001..=4022 => return self.group_code(number),
            4102 => m.notes.last_words.b,
            4107 => m.notes.last_words.d,
            4108 => m.notes.last_words.e,
            4111 => m.notes.last_words.h,
            4113 => m.notes.last_words.m,
            4109 => m.modes.feed,
            4114 => self.last_n.map(f64::from),
            4115 => self.program.map(f64::from),
            4119 => Some(m.modes.s_word),
            4120 => Some(f64::from(m.modes.tool)),
            // Positions: the block end point, the machine and the current position. Without a
            // setup (work and tool offsets) the three are the same (docs/reference/macro.md section 8); with
            // one, #5021-#5026 are in machine coordinates.
            // The controlled axes in their order: X Y Z on the mill, X Z on a lathe (#5002 is a
            // lathe's Z, as SK7420's `#681=#5022(Current Z ...)` reads it), or the setup's
            // `[machine] axes` in the order written (a 4th axis A is #5004). An axis the machine
            // does not have is vacant.
            5001..=5006 | 5021..=5026 | 5041..=5046 => {
                let k = ((number - 5001) % 20) as usize;
                let p = if (5021..=5026).contains(&number) { &machine } else { &shown };
                self.controlled_axes().get(k).and_then(|a| axis(*a, p))
            }
            // The manual handle interruption (FANUC #5121-#5125): none in a simulation.
            5121..=5126 => self.controlled_axes().get((number - 5121) as usize).map(|_| 0.0),
            // The tool and work offset tables (interp/table_vars.rs).
            n => match self.tables.variable(self.profile, n) {
                Some(v) => Some(v),
                None => return Err(no_such(number, "no such variable on this control, or a system variable ncsight does not simulate yet")),
            },
        })
    }
}

impl Variables {
    /// Set an input signal before the run (`--var 1002=1`): what the machine's switches and
    /// sensors would give.
    pub fn set_input(&mut self, number: i64, value: f64) -> Result<(), String> {
        if INPUTS.contains(&number) {
            if value != 0.0 && value != 1.0 {
                return Err(format!("#{number}={value}: an input signal is 0 or 1"));
            }
            self.inputs[(number - 1000) as usize] = Some(value);
        } else if number == INPUT_WORD {
            if value.fract() != 0.0 || !(0.0..=65_535.0).contains(&value) {
                return Err(format!("#1032={value}: the 16 input signals are a whole number 0 to 65535"));
            }
            self.input_word = Some(value);
        } else {
            return Err(format!("#{number} is not an input signal (#1000-#1015, #1032)"));
        }
        // A bit and the word given both must agree (#1000 is the word's lowest bit).
        if let Some(word) = self.input_word {
            for (k, bit) in self.inputs.iter().enumerate() {
                if bit.is_some_and(|b| b != f64::from((word as u32 >> k) & 1)) {
                    return Err(format!("#{}={} disagrees with #1032={word} (bit {k})", 1000 + k, bit.unwrap_or(0.0)));
                }
            }
        }
        Ok(())
    }

    /// An input signal: as given, #1032 from #1000-#1015 when each was given. One nobody gave
    /// is alarm 115 with a hint, never a guessed 0.
    fn input(&self, number: i64) -> Result<Value, ExprError> {
        let given = if number == INPUT_WORD {
            self.input_word.or_else(|| self.inputs.iter().rev().try_fold(0.0, |w, b| b.map(|b| w * 2.0 + b)))
        } else {
            let k = (number - 1000) as usize;
            self.inputs[k].or_else(|| self.input_word.map(|w| f64::from((w as u32 >> k) & 1)))
        };
        let hint =
            if number == INPUT_WORD { "--var 1032=N (the 16 signals as one number, 0 to 65535)".to_string() } else { format!("--var {number}=1 (or 0)") };
        given.map(Some).ok_or_else(|| no_such(number, &format!("an input signal of the machine, which ncsight cannot know: give it with {hint}")))
    }

    /// Set variable `number`. #3000 is the caller's (a user alarm).
    pub fn write(&mut self, number: i64, value: Value, clock_s: f64) -> Result<(), (Rule, String)> {
        match number {
            0 => Err((Rule::WriteProtected, "#0 is always vacant and cannot be set".into())),
            1..=33 => {
                if let Some(l) = self.levels.last_mut() {
                    l[number as usize - 1] = value;
                }
                Ok(())
            }
            n if COMMON.iter().any(|(a, b)| (*a..=*b).contains(&n)) => {
                self.common[n as usize] = value;
                Ok(())
            }
            3001 => {
                self.clock_ms_offset = clock_s * 1000.0 - value.unwrap_or(0.0);
                Ok(())
            }
            3002 => {
                self.clock_h_offset = clock_s / 3600.0 - value.unwrap_or(0.0);
                Ok(())
            }
            3901 | 3902 => {
                self.parts[(number - 3901) as usize] = value.unwrap_or(0.0);
                Ok(())
            }
            // An output signal is 0 or 1; vacant counts as 0 (FANUC custom macro B, inferred).
            n if OUTPUTS.contains(&n) => {
                let v = value.unwrap_or(0.0);
                if v != 0.0 && v != 1.0 {
                    return Err((Rule::IllegalVariable, format!("#{n} = {v}: an output signal is 0 or 1")));
                }
                self.outputs[(n - 1100) as usize] = v == 1.0;
                Ok(())
            }
            OUTPUT_WORD => {
                let v = value.unwrap_or(0.0);
                if v.fract() != 0.0 || !(0.0..=65_535.0).contains(&v) {
                    return Err((Rule::IllegalVariable, format!("#1132 = {v}: the 16 output signals are a whole number 0 to 65535")));
                }
                for (k, out) in self.outputs.iter_mut().enumerate() {
                    *out = (v as u32 >> k) & 1 == 1;
                }
                Ok(())
            }
            n if is_input(n) => Err((Rule::WriteProtected, format!("#{n} is an input signal of the machine: a programme can only read it"))),
            4001..=4120 | 5001..=5140 => Err((Rule::WriteProtected, format!("#{number} is a system variable that can only be read"))),
            n => Err((Rule::IllegalVariable, format!("#{n}: no such variable (locals #1-#33, common #100-#199 and #500-#999)"))),
        }
    }
}

/// The alarm an expression's failure is, with the controller's number.
pub(super) fn expr_alarm(style: AlarmStyle, span: Span, e: &ExprError) -> Diagnostic {
    let rule = match e.kind {
        ErrorKind::Format => Rule::MacroFormat,
        ErrorKind::DivideByZero => Rule::DivideByZero,
        ErrorKind::Argument => Rule::MacroArgument,
        ErrorKind::Overflow => Rule::MacroOverflow,
        ErrorKind::Nesting => Rule::BracketNesting,
        ErrorKind::Variable => Rule::IllegalVariable,
    };
    let d = Diagnostic::new(rule, style, span, e.message.clone());
    match e.kind {
        // Most often a setting the programme expects the machine to hold (a vacant variable
        // reads as 0 in arithmetic).
        ErrorKind::DivideByZero => d.with_hint(match e.divisor {
            Some(n @ 1..=33) => format!("#{n} is a local variable, vacant unless the macro is called with its argument: run the programme as if called, with --call-args \"A1. B2.\" (the words after G65 P_) or --var {n}=V"),
            Some(n @ (100..=199 | 500..=999)) => format!("a vacant variable counts as 0: #{n} may be a value kept at the machine; give it with --var {n}=V"),
            _ => "a vacant variable counts as 0: if the divisor is a value kept at the machine (#100-#199, #500-#999), give it with --var N=V; a macro's argument (#1-#33) with --call-args".to_string(),
        }),
        _ => d,
    }
}

/// Letters whose value is a whole number (codes, numbers, counts): a value from a variable is
/// rounded (`M#1` with 1.6 is M2: NCT manual, FANUC-compatible).
fn whole_address(letter: u8) -> bool {
    matches!(letter, b'M' | b'T' | b'H' | b'D' | b'L' | b'N' | b'O' | b'P' | b'S')
}

/// A word of an NC block in a macro, evaluated: `None` when it disappears (a bare vacant
/// variable, docs/reference/macro.md section 4.2). A value from a variable has a decimal point and is rounded
/// to the address's least increment (docs/reference/macro.md section 4.4).
///
/// `arguments`: the block is a G65/G66 call, whose words are the macro's arguments: a value
/// from a variable passes as it is (no rounding to a whole number, no scaling).
pub(super) fn evaluate_word(arena: &Arena, w: &MacroWord, reading: &mut Reading, inch: bool, arguments: bool) -> Result<Option<Word>, ExprError> {
    let increment = if inch { 1e-4 } else { 1e-3 };
    let length = !matches!(w.letter, b'G' | b'F') && !whole_address(w.letter);
    let v = expr::eval_rounding(arena, w.node, reading, if length && !arguments { increment } else { 1.0 })?;
    let Some(v) = v else {
        if arena.bare_variable(w.node) {
            return Ok(None);
        }
        return Ok(Some(Word { letter: w.letter, value: 0.0, decimal: true, expr: false, span: w.span }));
    };
    if !w.decimal {
        // A constant as written: the interpreter reads it as any word.
        return Ok(Some(Word { letter: w.letter, value: v, decimal: false, expr: false, span: w.span }));
    }
    if arguments && w.letter != b'G' {
        return Ok(Some(Word { letter: w.letter, value: v, decimal: true, expr: false, span: w.span }));
    }
    let (value, decimal) = match w.letter {
        b'G' => ((v * 10.0).round() / 10.0, (v * 10.0).round() % 10.0 != 0.0),
        l if whole_address(l) && !arena.constant(w.node) => (v.round(), false),
        b'F' => (v, true),
        _ => (expr::round_to_step(v, increment), true),
    };
    Ok(Some(Word { letter: w.letter, value, decimal, expr: false, span: w.span }))
}

/// Whether a condition holds: a value other than 0 (vacant does not).
pub(super) fn holds(v: Value) -> bool {
    v.is_some_and(|x| x != 0.0)
}
