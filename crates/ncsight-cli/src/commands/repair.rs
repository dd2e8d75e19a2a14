//! `repair`: the two blocks that re-cut a thread in the groove of a recorded point.

use crate::*;

#[allow(clippy::too_many_arguments)]
pub(crate) fn repair(
    m: &MachineArgs,
    start: &str,
    end: &str,
    lead: Option<f64>,
    tpi: Option<f64>,
    rpm: f64,
    measured: &str,
    j: Option<f64>,
    k: Option<f64>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let (params, _) = setup(m, None, err)?;
    let profile = params.profile();
    let Some(enable) =
        profile.thread.repair_enable.filter(|_| profile.g_code(32, Some(1)).is_some_and(|g| matches!(g.function, ncsight::profile::GFn::Thread(_))))
    else {
        let how = if profile.thread.repair_enable.is_some() { "repairs with G92 P1 / G92.1 P1 and `run --repair-position`" } else { "has no thread repair" };
        return Err(usage(format!("the thread-repair screen that writes G32.1 is a GSK988T function (GSK988T manual); {} {how}", profile.name)));
    };
    let s = numbers(start, "--start", 2)?;
    let e = numbers(end, "--end", 2)?;
    let lead_mm = match (lead, tpi) {
        (Some(f), None) if f > 0.0 && f <= 500.0 => f,
        (None, Some(n)) if (0.06..=25400.0).contains(&n) => 25.4 / n,
        _ => return Err(usage("give the lead as --lead F (0-500 mm) or --tpi N (0.06-25400)")),
    };
    if rpm == 0.0 || !rpm.is_finite() {
        return Err(usage("--rpm: a spindle speed other than 0 (negative: the negative direction)"));
    }
    let alarm = |err: &mut dyn Write, rule: ncsight::Rule, msg: String| -> Result<i32, Failure> {
        writeln!(err, "ncsight: alarm[{}]: {msg}", rule.code(profile.alarm_style))?;
        Ok(EXIT_ALARM)
    };
    let recorded = recorded(measured, "--measured")?;
    if params.get(enable) == 0.0 {
        return alarm(
            err,
            ncsight::Rule::RepairDisabled,
            format!("thread repair is not enabled: parameter {enable} (RPTH) is 0 (GSK988T manual, thread repair 1.4); give --param {enable}=1"),
        );
    }
    let job = ncsight::repair::RepairJob {
        start: ncsight::Vec3::new(s[0] / 2.0, 0.0, s[1]),
        end: ncsight::Vec3::new(e[0] / 2.0, 0.0, e[1]),
        lead_mm,
        rpm,
        j_mm: j,
        k_mm: k,
        recorded,
    };
    match job.programme() {
        Ok(text) => {
            out.write_all(text.as_bytes())?;
            Ok(EXIT_OK)
        }
        // A number the control would not take is the caller's mistake: a usage error.
        Err(ncsight::repair::RepairError::BadInput(why)) => Err(usage(format!("{why}; no programme is written"))),
        Err(e) => alarm(err, ncsight::Rule::RepairOutside, format!("{e}; no programme is written")),
    }
}
