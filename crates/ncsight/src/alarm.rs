//! Diagnostics: alarms (execution stops, as on the controller) and warnings (execution goes on).
//!
//! Every rule has a stable code. Where the controller's own alarm number is known from a manual
//! (docs/reference/parameters.md) the FANUC-family profile uses it (`PS0007`); everything
//! else carries a project code `NCS-Enn` (alarm) or `NCS-Wnn` (warning), listed in docs/alarms.md.

use crate::source::Span;

/// Alarm or warning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    Alarm,
    Warning,
}

/// Which numbering the profile's alarms follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AlarmStyle {
    /// FANUC PS numbers where known (docs/reference/parameters.md section 4).
    Fanuc,
    /// No public numbered list was found (GSK 980TDi, GSK 988T, YASNAC LX3): project codes only.
    Project,
}

macro_rules! rules {
    ($( $name:ident => $sev:ident, $proj:literal, $fanuc:expr, $title:literal; )*) => {
        /// A rule that a block can break. The code is stable; the title is the controller-style
        /// short text.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Rule { $( $name, )* }

        impl Rule {
            /// All rules, for the documentation table and its test.
            pub const ALL: &'static [Rule] = &[ $( Rule::$name, )* ];

            pub fn severity(self) -> Severity {
                match self { $( Rule::$name => Severity::$sev, )* }
            }

            /// The project code, the same on every profile.
            pub fn project_code(self) -> &'static str {
                match self { $( Rule::$name => $proj, )* }
            }

            /// The FANUC alarm number where one is known.
            pub fn fanuc_code(self) -> Option<&'static str> {
                match self { $( Rule::$name => $fanuc, )* }
            }

            /// Short controller-style title (FANUC's wording where it has one).
            pub fn title(self) -> &'static str {
                match self { $( Rule::$name => $title, )* }
            }
        }
    };
}

rules! {
    // --- reading words (docs/reference/parameters.md section 4, "Fanuc alarms") ---
    TooManyDigits => Alarm, "NCS-E03", Some("PS0003"), "TOO MANY DIGIT";
    NoDataAfterAddress => Alarm, "NCS-E05", Some("PS0005"), "NO DATA AFTER ADDRESS";
    IllegalMinus => Alarm, "NCS-E06", Some("PS0006"), "ILLEGAL USE OF MINUS SIGN";
    IllegalDecimalPoint => Alarm, "NCS-E07", Some("PS0007"), "ILLEGAL USE OF DECIMAL POINT";
    ImproperAddress => Alarm, "NCS-E09", Some("PS0009"), "IMPROPER NC-ADDRESS";
    ImproperGCode => Alarm, "NCS-E10", Some("PS0010"), "IMPROPER G-CODE";
    FeedZero => Alarm, "NCS-E11", Some("PS0011"), "FEED ZERO (COMMAND)";
    RadiusTolerance => Alarm, "NCS-E20", Some("PS0020"), "OVER TOLERANCE OF RADIUS";
    ArcDataMissing => Alarm, "NCS-E22", Some("PS0022"), "R OR I,J,K COMMAND NOT FOUND";
    PeckMissing => Alarm, "NCS-E47", Some("PS0045"), "ADDRESS Q NOT FOUND (G73/G83)";
    ContourNotFound => Alarm, "NCS-E53", Some("PS0063"), "THE BLOCK OF A SPECIFIED SEQUENCE NUMBER IS NOT FOUND";
    ContourNotMonotonic => Alarm, "NCS-E54", Some("PS0064"), "THE FINISHING SHAPE IS NOT A MONOTONOUS CHANGE";
    ContourCommand => Alarm, "NCS-E55", Some("PS0066"), "UNAVAILABLE COMMAND IN THE SHAPE PROGRAM";
    ContourEndsInCorner => Alarm, "NCS-E96", Some("PS0069"), "LAST BLOCK OF SHAPE PROGRAM IS AN ILLEGAL COMMAND";
    // FANUC 0i-F: a comma drawing word while 3405#4 CCR = 1 (a secondary list of the 0i-F alarm texts).
    DrawingComma => Alarm, "NCS-E99", Some("PS0312"), "ILLEGAL COMMAND IN DIRECT DRAWING DIMENSIONS PROGRAMMING";
    PlaneMismatch => Alarm, "NCS-E56", None, "CYCLE NOT AVAILABLE IN THIS PLANE";
    RigidTapOrder => Alarm, "NCS-E57", None, "RIGID TAPPING: M29 S_ FIRST, THEN G84/G88";
    ReferenceInCannedCycle => Alarm, "NCS-E58", Some("PS0044"), "G27-G30 NOT ALLOWED IN FIXED CYC";
    // FANUC 0 numbering (docs/reference/macro.md section 9: the 0i-F reuses 076-078 with other meanings).
    AddressPMissing => Alarm, "NCS-E59", Some("PS0076"), "ADDRESS P NOT DEFINED";
    CallNesting => Alarm, "NCS-E60", Some("PS0077"), "SUB PROGRAM NESTING ERROR";
    NumberNotFound => Alarm, "NCS-E61", Some("PS0078"), "NUMBER NOT FOUND";
    // Custom macro B, FANUC 0 numbering (docs/reference/macro.md section 9; the texts are the old list's).
    MacroOverflow => Alarm, "NCS-E64", Some("PS0111"), "CALCULATED DATA OVERFLOW";
    DivideByZero => Alarm, "NCS-E65", Some("PS0112"), "DIVIDED BY ZERO";
    MacroFormat => Alarm, "NCS-E66", Some("PS0114"), "FORMAT ERROR IN MACRO";
    IllegalVariable => Alarm, "NCS-E67", Some("PS0115"), "ILLEGAL VARIABLE NUMBER";
    WriteProtected => Alarm, "NCS-E68", Some("PS0116"), "WRITE PROTECTED VARIABLE";
    BracketNesting => Alarm, "NCS-E69", Some("PS0118"), "PARENTHESIS NESTING ERROR";
    MacroArgument => Alarm, "NCS-E70", Some("PS0119"), "ILLEGAL ARGUMENT";
    MissingEnd => Alarm, "NCS-E71", Some("PS0124"), "MISSING END STATEMENT";
    LoopNumber => Alarm, "NCS-E72", Some("PS0126"), "ILLEGAL LOOP NUMBER";
    MacroSequence => Alarm, "NCS-E73", Some("PS0128"), "ILLEGAL MACRO SEQUENCE NUMBER";
    ArgumentAddress => Alarm, "NCS-E74", Some("PS0129"), "ILLEGAL ARGUMENT ADDRESS";
    UserAlarm => Alarm, "NCS-E75", Some("PS3000"), "USER ALARM (#3000)";
    // --- project rules (no controller number known) ---
    BadCharacter => Alarm, "NCS-E30", None, "CHARACTER NOT ALLOWED";
    LineTooLong => Alarm, "NCS-E31", None, "BLOCK TOO LONG";
    Expression => Alarm, "NCS-E32", None, "BAD EXPRESSION";
    ValueOutOfRange => Alarm, "NCS-E33", None, "VALUE OUT OF RANGE";
    DuplicateWord => Alarm, "NCS-E34", None, "ADDRESS USED TWICE IN A BLOCK";
    WordNotTaken => Alarm, "NCS-E35", None, "WORD NOT USED BY THIS COMMAND";
    MissingWord => Alarm, "NCS-E36", None, "REQUIRED WORD MISSING";
    GroupConflict => Alarm, "NCS-E37", None, "G CODES THAT MAY NOT SHARE A BLOCK";
    NotSupported => Alarm, "NCS-E38", None, "NOT AVAILABLE IN NCSIGHT YET";
    SpindleStopped => Alarm, "NCS-E39", None, "FEED PER REVOLUTION WITH THE SPINDLE STOPPED";
    MotionLimit => Alarm, "NCS-E40", None, "TOO MUCH MOTION GENERATED";
    SpindleMode => Alarm, "NCS-E41", None, "SPINDLE NOT IN POSITION MODE";
    PullOutTooLong => Alarm, "NCS-E42", None, "PULL-OUT LONGER THAN THE THREAD";
    ArcThreadSector => Alarm, "NCS-E43", None, "ARC THREAD LEAVES ITS SECTOR";
    FaceThread => Alarm, "NCS-E44", None, "FACE THREAD NOT ALLOWED IN THIS CYCLE";
    TaperTooLarge => Alarm, "NCS-E45", None, "TAPER R LARGER THAN U/2";
    DrillLevels => Alarm, "NCS-E46", None, "R POINT AND HOLE BOTTOM IN THE WRONG ORDER";
    RepairOutside => Alarm, "NCS-E48", None, "REPAIR POSITION OUTSIDE THE THREAD";
    RepairDisabled => Alarm, "NCS-E49", None, "THREAD REPAIR NOT ENABLED";
    RepairNoPosition => Alarm, "NCS-E50", None, "NO REPAIR POSITION RECORDED";
    ThreadData => Alarm, "NCS-E51", None, "ILLEGAL THREAD CYCLE DATA";
    ForeignDialect => Alarm, "NCS-E52", None, "PROGRAMME FOR ANOTHER CONTROL";
    NoReturn => Alarm, "NCS-E62", None, "SUBPROGRAMME ENDS WITHOUT M99";
    Runaway => Alarm, "NCS-E63", None, "TOO MANY BLOCKS EXECUTED";
    NotExpandable => Alarm, "NCS-E76", None, "THE TARGET CONTROLLER CANNOT DO THIS";
    // Soft travel limits (stored stroke check 1): the FANUC 0i-D numbers, the axis named in the
    // message (FANUC 0 numbered them per axis; docs/setup.md).
    OvertravelPlus => Alarm, "NCS-E77", Some("OT0500"), "+ OVERTRAVEL (SOFT 1)";
    OvertravelMinus => Alarm, "NCS-E78", Some("OT0501"), "- OVERTRAVEL (SOFT 1)";
    // A chamfer or corner arc larger than its moves (GSK980TDi chamfer function, case 2; its
    // number not at hand) and FANUC's chamfer and corner R (,C ,R) and direct drawing
    // dimension alarms (numbers and texts from a FANUC 0i alarm list; docs/commands/drawing.md).
    CornerTooLarge => Alarm, "NCS-E89", Some("PS0055"), "MISSING MOVE VALUE IN CHF/CNR";
    CornerNoMove => Alarm, "NCS-E90", Some("PS0051"), "MISSING MOVE AFTER CNR/CHF";
    CornerNotLinear => Alarm, "NCS-E91", Some("PS0052"), "CODE IS NOT G01 AFTER CHF/CNR";
    CornerWords => Alarm, "NCS-E97", Some("PS0053"), "TOO MANY ADDRESS COMMANDS";
    CornerTaper => Alarm, "NCS-E98", Some("PS0054"), "NO TAPER ALLOWED AFTER CHF/CNR";
    DrawingEndMissing => Alarm, "NCS-E92", Some("PS0056"), "NO END POINT & ANGLE IN CHF/CNR";
    DrawingNoSolution => Alarm, "NCS-E93", Some("PS0057"), "NO SOLUTION OF BLOCK END";
    DrawingEndNotFound => Alarm, "NCS-E94", Some("PS0058"), "END POINT NOT FOUND";
    IllegalPlane => Alarm, "NCS-E95", Some("PS0212"), "ILLEGAL PLANE SELECT";
    // G29 with an axis no G28/G30 has given an intermediate point (no controller text found).
    NoIntermediatePoint => Alarm, "NCS-E88", None, "NO INTERMEDIATE POINT FOR G29";
    // FANUC 0-T variable lead (G34): the number and text as recalled (not verified).
    IllegalLead => Alarm, "NCS-E87", Some("PS0014"), "ILLEGAL LEAD COMMAND";
    // G05, G6.2, G7.2 of the GSK980TDi (its alarm numbers were not at hand).
    CurveData => Alarm, "NCS-E86", None, "CURVE DATA DO NOT DEFINE THE CURVE";
    // G02.2/G03.2 involute interpolation: the numbers of the FANUC 30i-MA manual, the texts of
    // its alarm list as recalled.
    InvoluteFormat => Alarm, "NCS-E100", Some("PS0241"), "ILLEGAL FORMAT IN G02.2/G03.2";
    InvoluteCommand => Alarm, "NCS-E101", Some("PS0242"), "ILLEGAL COMMAND IN G02.2/G03.2";
    // G22 stored stroke check 2 (no alarm number of these controllers at hand).
    StrokeCheck2 => Alarm, "NCS-E85", None, "FORBIDDEN AREA (STORED STROKE CHECK 2)";
    // Tool radius compensation: the FANUC 0 P/S numbers (docs/reference/macro.md 10.3; texts as recalled).
    CompNoSolution => Alarm, "NCS-E79", Some("PS0033"), "NO SOLUTION AT CRC";
    CompStartupArc => Alarm, "NCS-E80", Some("PS0034"), "NO CIRC ALLOWED IN STUP/EXT BLK";
    CompPlaneChange => Alarm, "NCS-E81", Some("PS0037"), "CAN NOT CHANGE PLANE IN CRC";
    CompInterference => Alarm, "NCS-E82", Some("PS0041"), "INTERFERENCE IN CRC";
    CompIdleBlocks => Alarm, "NCS-E83", None, "TOO MANY BLOCKS WITHOUT A MOVE IN COMPENSATION";
    // G27: the FANUC 0 number and text as recalled (not verified).
    ReferenceCheck => Alarm, "NCS-E84", Some("PS0092"), "ZERO RETURN CHECK (G27) ERROR";
    // --- warnings ---
    SameGroupTwice => Warning, "NCS-W01", None, "TWO G CODES OF ONE GROUP: THE LAST ONE COUNTS";
    IntegerLength => Warning, "NCS-W02", None, "LENGTH WITHOUT DECIMAL POINT";
    CommentNotClosed => Warning, "NCS-W03", None, "COMMENT NOT CLOSED";
    TextIgnored => Warning, "NCS-W04", None, "TEXT IGNORED";
    MachineSpecificM => Warning, "NCS-W05", None, "MACHINE-SPECIFIC M CODE";
    EndOfFileMark => Warning, "NCS-W06", None, "END-OF-FILE MARK";
    DecimalIgnored => Warning, "NCS-W07", None, "DECIMAL PART IGNORED";
    ProgramLoops => Warning, "NCS-W08", None, "M99 IN THE MAIN PROGRAMME";
    AfterEnd => Warning, "NCS-W09", None, "BLOCKS AFTER THE PROGRAMME END";
    ZeroArc => Warning, "NCS-W10", None, "ARC OF ZERO DEGREES";
    FeedClamped => Warning, "NCS-W11", None, "FEED ABOVE THE LIMIT: CLAMPED";
    NotSimulated => Warning, "NCS-W12", None, "NOT SIMULATED: PROGRAMMED PATH SHOWN";
    NoProgramEnd => Warning, "NCS-W13", None, "NO PROGRAMME END";
    ThreadWithCss => Warning, "NCS-W14", None, "THREADING UNDER G96";
    ThreadFeedHigh => Warning, "NCS-W15", None, "THREAD FEED ABOVE THE LIMIT";
    PassMismatch => Warning, "NCS-W16", None, "PASSES DO NOT LINE UP";
    InfeedGrows => Warning, "NCS-W17", None, "INFEED LARGER THAN THE PREVIOUS ONE";
    TapDirection => Warning, "NCS-W18", None, "TAPPING WITH THE SPINDLE TURNING THE WRONG WAY";
    ReturnLevel => Warning, "NCS-W19", None, "RETURN LEVEL DIFFERS FROM G98/G99";
    NotReached => Warning, "NCS-W20", None, "OPERATOR ACTION AFTER THE PROGRAMME END";
    CycleWords => Warning, "NCS-W21", None, "T, S, M BELONG BEFORE THE CYCLE";
    RoughingCollision => Warning, "NCS-W22", None, "ROUGHING MOVES THROUGH THE PART";
    HoldIgnored => Warning, "NCS-W23", None, "FEED HOLD IGNORED DURING THE THREAD";
    AllowanceNotCut => Warning, "NCS-W24", None, "FINISHING ALLOWANCE NEVER CUT";
    Implausible => Warning, "NCS-W25", None, "IMPLAUSIBLE VALUE";
    SpeedClamped => Warning, "NCS-W26", None, "SPINDLE SPEED ABOVE THE MAXIMUM: CLAMPED";
    CallSkipped => Warning, "NCS-W27", None, "SUBPROGRAMME NOT FOUND: CALL SKIPPED";
    ThenOmitted => Warning, "NCS-W28", None, "IF WITHOUT THEN";
    ExpandApproximate => Warning, "NCS-W29", None, "EXPANDED APPROXIMATELY FOR THE TARGET";
    MachineIncremental => Warning, "NCS-W30", None, "G53 IGNORED IN INCREMENTAL";
    ReferenceAssumed => Warning, "NCS-W31", None, "REFERENCE POINT NOT IN THE SETUP";
    OffsetAssumed => Warning, "NCS-W32", None, "OFFSET NOT IN THE SETUP";
    CompRadiusZero => Warning, "NCS-W33", None, "RADIUS COMPENSATION WITH RADIUS 0";
    NoSkipSignal => Warning, "NCS-W34", None, "NO SKIP SIGNAL: THE MOVE RUNS TO ITS END";
    NoMeasuringSignal => Warning, "NCS-W35", None, "NO MEASURING SIGNAL: THE OFFSET STAYS";
    CornerArcOvercut => Warning, "NCS-W36", None, "G39 AT AN INNER CORNER: OVERCUT";
    SimulatorStock => Warning, "NCS-W37", None, "SIMULATOR STOCK LINE SKIPPED";
    ArcAsLine => Warning, "NCS-W38", None, "ARC WITHOUT RADIUS OR CENTRE: STRAIGHT MOVE";
    AxisAssumed => Warning, "NCS-W39", None, "AXIS OR SPINDLE NOT IN THE SETUP: ASSUMED";
}

impl Rule {
    /// The code as this profile reports it.
    pub fn code(self, style: AlarmStyle) -> &'static str {
        match (style, self.fanuc_code()) {
            (AlarmStyle::Fanuc, Some(c)) => c,
            _ => self.project_code(),
        }
    }
}

/// A computed number as a message shows it: rounded to `decimals` (the controllers' display
/// increment: 4 for mm and mm/rev, 1 for rpm), trailing zeros dropped, never `-0`.
pub fn shown(v: f64, decimals: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let mut s = format!("{v:.decimals$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    s
}

/// One alarm or warning, tied to the text that caused it.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    pub rule: Rule,
    /// Stable code as the profile reports it (`PS0007`, `NCS-E35`, ...).
    pub code: &'static str,
    pub span: Span,
    /// Names the word and the rule broken.
    pub message: String,
    /// A likely cause, for typing mistakes (`GO` with a letter O).
    pub hint: Option<String>,
    /// Raised inside a subprogramme: the calling blocks (M98), outermost first. A boxed slice
    /// (two words, no allocation when empty): diagnostics sit beside every block the reader
    /// makes, so their size counts.
    pub calls: Box<[Span]>,
}

impl Diagnostic {
    pub fn new(rule: Rule, style: AlarmStyle, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { rule, code: rule.code(style), span, message: message.into(), hint: None, calls: Box::default() }
    }

    pub fn with_hint(mut self, hint: impl Into<String>) -> Diagnostic {
        self.hint = Some(hint.into());
        self
    }

    pub fn severity(&self) -> Severity {
        self.rule.severity()
    }

    pub fn is_alarm(&self) -> bool {
        self.severity() == Severity::Alarm
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One code, one meaning: no two rules share a project code or a FANUC number.
    #[test]
    fn every_code_belongs_to_one_rule() {
        for (i, a) in Rule::ALL.iter().enumerate() {
            for b in &Rule::ALL[i + 1..] {
                assert_ne!(a.project_code(), b.project_code(), "{a:?} and {b:?}");
                if let (Some(x), Some(y)) = (a.fanuc_code(), b.fanuc_code()) {
                    assert_ne!(x, y, "{a:?} and {b:?}");
                }
                assert_ne!(a.title(), b.title(), "{a:?} and {b:?}");
            }
        }
    }
}
