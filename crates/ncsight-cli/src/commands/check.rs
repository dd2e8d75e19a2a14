//! `check`: every alarm and warning of one or more programmes.

use crate::*;

pub(crate) fn check(files: &[String], m: &MachineArgs, format: &str, out: &mut dyn Write, err: &mut dyn Write) -> Result<i32, Failure> {
    // With --machine, every file on it; without, each file on the machine its first line
    // names, else gsk980tdi (said once).
    let given = m.machine.as_ref().map(|_| setup(m, None, err)).transpose()?;
    let mut default_said = false;
    let mut machines: Vec<(String, (Params, Switches))> = Vec::new();
    let decoding = m.decoding()?;
    let style = match format {
        "full" => Some(diag::Style::Full),
        "short" => Some(diag::Style::Short),
        "jsonl" => None,
        _ => return Err(usage(format!("unknown format '{format}': choose full, short or jsonl"))),
    };
    let mut any_alarm = false;
    let mut unreadable = false;
    let mut w = Tolerant::new(io::BufWriter::new(Tolerant::new(out)));
    for file in files {
        let shown = shown(file);
        // A file that cannot be read, or whose first line names no machine ncsight has, is
        // reported, and the others are still checked.
        let read = Head::of(file).and_then(|mut head| {
            let machine = machine_for(m, head.named(shown), !default_said, err)?;
            default_said |= head.named.is_none();
            Ok((machine, head.input(file)?))
        });
        let (machine, input) = match read {
            Ok(r) => r,
            Err(Failure::Usage(msg)) => {
                writeln!(err, "ncsight: {msg}")?;
                unreadable = true;
                continue;
            }
            Err(e) => return Err(e),
        };
        let (params, switches) = match &given {
            Some(p) => p.clone(),
            None => match machines.iter().find(|(n, _)| *n == machine) {
                Some((_, p)) => p.clone(),
                None => {
                    let p = setup_on(m, &machine)?;
                    machines.push((machine, p.clone()));
                    p
                }
            },
        };
        let mut program = Program::diagnostics_only(params.clone(), switches);
        let mut library = m.prepare(&mut program)?;
        let (mut alarms, mut warnings) = (0usize, 0usize);
        let result = drive(file, input, &mut library, &mut program, &mut |e, text, name| {
            if let Event::Diagnostic(d) = e {
                if d.is_alarm() {
                    alarms += 1
                } else {
                    warnings += 1
                }
                let shown = name.unwrap_or(shown);
                match style {
                    Some(style) => w.write_all(diag::render(shown, text, d, style, &decoding).as_bytes())?,
                    None => w.write_all(format::jsonl::diagnostic_line(shown, d).as_bytes())?,
                }
            }
            Ok(())
        });
        match result {
            Ok(()) => {}
            Err(Failure::Usage(msg)) => {
                writeln!(err, "ncsight: {msg}")?;
                unreadable = true;
            }
            Err(e) => return Err(e),
        }
        if style.is_some() {
            writeln!(w, "{shown}: {alarms} alarm(s), {warnings} warning(s) on {}", params.profile().name)?;
        }
        any_alarm |= alarms > 0;
    }
    w.flush()?;
    // An unreadable file outranks what the others held: the check is not complete.
    Ok(if unreadable {
        EXIT_USAGE
    } else if any_alarm {
        EXIT_ALARM
    } else {
        EXIT_OK
    })
}

/// Progress of long work on a terminal: after a second, "simulating: 37 %" on standard error,
/// rewritten in place a few times a second; nothing when standard error is not a terminal.
pub(crate) fn progress_on(err: &mut dyn Write) -> impl FnMut(usize, usize) + '_ {
    use std::io::IsTerminal;
    let terminal = io::stderr().is_terminal();
    let start = std::time::Instant::now();
    let mut last = start;
    move |done, total| {
        if !terminal || total == 0 {
            return;
        }
        let now = std::time::Instant::now();
        if now.duration_since(start).as_secs_f64() < 1.0 || now.duration_since(last).as_secs_f64() < 0.2 {
            if done == total && now.duration_since(start).as_secs_f64() >= 1.0 {
                let _ = write!(err, "\rsimulating: 100 %\n");
            }
            return;
        }
        last = now;
        let _ = write!(err, "\rsimulating: {} %", done * 100 / total);
        if done == total {
            let _ = writeln!(err);
        }
    }
}
