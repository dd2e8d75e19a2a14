//! Calls a machine builder sets up by parameter: a G or M code that runs a macro programme of
//! the machine (O9001-O9029) as G65 or M98 would (docs/reference/macro.md section 2: FANUC 6050-6089; the
//! GSK980TDi's data parameters No.86-95 and its M9000-M9999). All 0 (none) by default: a
//! programme that relies on them is run with `--param 6050=100` and the machine's macros in
//! `--subprogram-dir`.

use super::{ParamDef, ParamKey};

/// The largest code such a parameter holds: a G code (0-999) or an M code (up to 8 digits).
const G: f64 = 999.0;
const M: f64 = 99_999_999.0;

/// Where each kind of call is described.
const FANUC_G: &str = "FANUC 0i parameter manual, 6050-6059 (the G-code macro call; ncsight setting, inferred for the FANUC 0)";
const FANUC_M98: &str = "FANUC 0i parameter manual, 6071-6079 (the M-code subprogramme call; inferred for the FANUC 0)";
const FANUC_M65: &str = "FANUC 0i parameter manual, 6080-6089 (the M-code macro call; inferred for the FANUC 0)";
const GSK_G: &str = "GSK980TDi help text, macro call by G code (data parameters No.86-95)";

/// One such parameter: the code it holds (0: none).
const fn call(number: u32, meaning: &'static str, max: f64, source: &'static str) -> ParamDef {
    ParamDef { key: ParamKey::Number(number, None), meaning, unit: "code", min: 0.0, max, default: 0.0, source }
}

/// FANUC: 6050-6059 (G codes -> O9010-O9019), 6071-6079 (M codes -> O9001-O9009, as M98),
/// 6080-6089 (M codes -> O9020-O9029, as G65).
pub(super) const FANUC: &[ParamDef] = &[
    call(6050, "G code that calls O9010 as G65 does (0: none)", G, FANUC_G),
    call(6051, "G code that calls O9011 as G65 does (0: none)", G, FANUC_G),
    call(6052, "G code that calls O9012 as G65 does (0: none)", G, FANUC_G),
    call(6053, "G code that calls O9013 as G65 does (0: none)", G, FANUC_G),
    call(6054, "G code that calls O9014 as G65 does (0: none)", G, FANUC_G),
    call(6055, "G code that calls O9015 as G65 does (0: none)", G, FANUC_G),
    call(6056, "G code that calls O9016 as G65 does (0: none)", G, FANUC_G),
    call(6057, "G code that calls O9017 as G65 does (0: none)", G, FANUC_G),
    call(6058, "G code that calls O9018 as G65 does (0: none)", G, FANUC_G),
    call(6059, "G code that calls O9019 as G65 does (0: none)", G, FANUC_G),
    call(6071, "M code that calls O9001 as M98 does (0: none)", M, FANUC_M98),
    call(6072, "M code that calls O9002 as M98 does (0: none)", M, FANUC_M98),
    call(6073, "M code that calls O9003 as M98 does (0: none)", M, FANUC_M98),
    call(6074, "M code that calls O9004 as M98 does (0: none)", M, FANUC_M98),
    call(6075, "M code that calls O9005 as M98 does (0: none)", M, FANUC_M98),
    call(6076, "M code that calls O9006 as M98 does (0: none)", M, FANUC_M98),
    call(6077, "M code that calls O9007 as M98 does (0: none)", M, FANUC_M98),
    call(6078, "M code that calls O9008 as M98 does (0: none)", M, FANUC_M98),
    call(6079, "M code that calls O9009 as M98 does (0: none)", M, FANUC_M98),
    call(6080, "M code that calls O9020 as G65 does (0: none)", M, FANUC_M65),
    call(6081, "M code that calls O9021 as G65 does (0: none)", M, FANUC_M65),
    call(6082, "M code that calls O9022 as G65 does (0: none)", M, FANUC_M65),
    call(6083, "M code that calls O9023 as G65 does (0: none)", M, FANUC_M65),
    call(6084, "M code that calls O9024 as G65 does (0: none)", M, FANUC_M65),
    call(6085, "M code that calls O9025 as G65 does (0: none)", M, FANUC_M65),
    call(6086, "M code that calls O9026 as G65 does (0: none)", M, FANUC_M65),
    call(6087, "M code that calls O9027 as G65 does (0: none)", M, FANUC_M65),
    call(6088, "M code that calls O9028 as G65 does (0: none)", M, FANUC_M65),
    call(6089, "M code that calls O9029 as G65 does (0: none)", M, FANUC_M65),
];

/// GSK980TDi: data parameters No.86-95 (G codes -> O9010-O9019).
pub(super) const GSK980TDI: &[ParamDef] = &[
    call(86, "G code that calls O9010 as G65 does (0: none)", G, GSK_G),
    call(87, "G code that calls O9011 as G65 does (0: none)", G, GSK_G),
    call(88, "G code that calls O9012 as G65 does (0: none)", G, GSK_G),
    call(89, "G code that calls O9013 as G65 does (0: none)", G, GSK_G),
    call(90, "G code that calls O9014 as G65 does (0: none)", G, GSK_G),
    call(91, "G code that calls O9015 as G65 does (0: none)", G, GSK_G),
    call(92, "G code that calls O9016 as G65 does (0: none)", G, GSK_G),
    call(93, "G code that calls O9017 as G65 does (0: none)", G, GSK_G),
    call(94, "G code that calls O9018 as G65 does (0: none)", G, GSK_G),
    call(95, "G code that calls O9019 as G65 does (0: none)", G, GSK_G),
];
