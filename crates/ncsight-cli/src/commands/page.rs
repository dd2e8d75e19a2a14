//! `report` and `app`: the page, with a job or without.

use crate::*;

/// What the machine setup gives and what the run assumes without it (docs/setup.md), as the
/// report says it.
pub(crate) fn setup_notes(setup: Option<(&str, &ncsight::stock::Setup)>, profile: &ncsight::Profile) -> Vec<String> {
    let x = if profile.diameter_x { 2.0 } else { 1.0 };
    let r = profile.reference_point_mm;
    let assumed_reference = if profile.is_lathe() { format!("X{} Z{}", r.x * x, r.z) } else { format!("X{} Y{} Z{}", r.x, r.y, r.z) };
    let Some((path, s)) = setup else {
        return vec![format!(
            "no machine setup (--setup): work and tool offsets 0, radius compensation with radius 0, no travel limits, the reference point assumed at {assumed_reference}, the tool at programme zero at power on"
        )];
    };
    let mut out = vec![format!("machine setup {path}")];
    let m = s.machine.as_ref();
    out.push(match m.and_then(|m| m.reference) {
        Some(_) => "reference point from the setup; the tool there at power on".into(),
        None => format!("no [machine.reference]: the reference point assumed at {assumed_reference}, the tool at programme zero at power on"),
    });
    out.push(match m.and_then(|m| m.limits) {
        Some(_) => "soft travel limits from the setup".into(),
        None => "no travel limits".into(),
    });
    let works: Vec<&str> = s
        .work
        .as_ref()
        .map(|w| ["external", "G54", "G55", "G56", "G57", "G58", "G59"].into_iter().zip(w.all()).filter(|(_, p)| p.is_some()).map(|(n, _)| n).collect())
        .unwrap_or_default();
    out.push(if works.is_empty() { "work offsets 0".into() } else { format!("work offsets {} from the setup, the others 0", works.join(", ")) });
    out.push(if s.offsets.is_empty() {
        "no offset table: tool offsets and radii 0".into()
    } else {
        format!("{} tool offset(s) from the setup, the others 0", s.offsets.len())
    });
    out
}

/// The job setup from `--setup` (as the run's job read and checked it) and `--stock`.
pub(crate) fn job_setup(m: &MachineArgs, profile: &ncsight::profile::Profile, stock: Option<&str>) -> Result<ncsight::stock::Setup, Failure> {
    let mut job = m.job(profile.name)?.setup.unwrap_or_default();
    if let Some(s) = stock {
        job.set_stock_text(s, profile.is_lathe()).map_err(|e| usage(e.to_string()))?;
    }
    Ok(job)
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn report(
    file: &str,
    m: &MachineArgs,
    operator: &OperatorArgs,
    stock: Option<&str>,
    expect: Option<&str>,
    output: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    if let Some(why) = report::engine_missing() {
        return Err(usage(why));
    }
    let mut head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let decoding = m.decoding()?;
    let file_out = output.map(|path| output::LazyFile::new(path, &m.read_files(file), 1 << 16)).transpose().map_err(usage)?;
    let opts = operator.options()?;
    let job = job_setup(m, params.profile(), stock)?;
    let sim_options = simulate::options(None, expect).map_err(usage)?;
    let source = match head.input.take() {
        Some(feed::Input::Stream(mut r)) => {
            let mut v = Vec::new();
            r.read_to_end(&mut v)?;
            v
        }
        Some(feed::Input::Memory(text)) => text.to_vec(),
        Some(feed::Input::File(_)) | None => std::fs::read(file).map_err(|e| usage(format!("cannot read {file}: {e}")))?,
    };
    let mut settings = vec![format!("profile {} ({})", params.profile().name, params.profile().title)];
    settings.extend(setup_notes(m.setup.as_deref().map(|p| (p, &job)), params.profile()));
    if m.repair_position.is_some() {
        settings.push("--repair-position is not passed to the page: its runs have no recorded repair position".into());
    }
    settings.push("assumptions: docs/guide.md and docs/commands/*.md".into());
    // The run here gives the exit status and, on a lathe that cuts a thread, the records the
    // stock simulation measures; the page runs the programme again itself.
    let mut program = Program::with_operator(params.clone(), switches, Mode::Run, opts.clone());
    let mut library = m.prepare(&mut program)?;
    let lathe = params.profile().is_lathe();
    let text = std::sync::Arc::new(source.clone());
    let mut survey = ncsight::stock::survey::LatheSurvey::new(&job);
    let mut threads = false;
    drive(file, feed::Input::Memory(text.clone()), &mut library, &mut program, &mut |e, _, _| {
        if let (Event::Record(r), true) = (e, lathe) {
            threads |= r.op.is_thread();
            survey.add(r);
        }
        Ok(())
    })?;
    // The thread section: simulated when the programme cuts a thread on a lathe (a second run,
    // cut record by record); when it cannot be, the page says why (never "cuts no thread" for a
    // thread it could not simulate).
    let (sim, sim_error) = if threads {
        match ncsight::stock::measure::LatheCut::new(&survey, &job, &sim_options) {
            Ok(mut cut) => {
                let mut again = Program::with_operator(params.clone(), switches, Mode::Run, opts.clone());
                let mut library = m.prepare(&mut again)?;
                drive(file, feed::Input::Memory(text), &mut library, &mut again, &mut |e, _, _| {
                    if let Event::Record(r) = e {
                        cut.add(r);
                    }
                    Ok(())
                })?;
                (Some(cut.finish(&sim_options)), None)
            }
            Err(e) => (None, Some(e)),
        }
    } else {
        (None, None)
    };
    let extra = page_settings(m);
    let page = report::Preload {
        file_name: if file == "-" { "<stdin>" } else { file },
        text: editor_text(&source, &decoding),
        original: &source,
        encoding: decoding.label(),
        machine: params.profile().name,
        params: &m.params,
        setup: m.setup_text()?.map(str::to_string),
        options: &opts,
        switches,
        extra_options: extra,
        stock: job.stock,
        expect: sim_options.expect.as_ref(),
        library: library_texts(&m.subprogram_dirs, &decoding),
        settings,
        sim: sim.as_ref(),
        sim_error: sim_error.as_deref(),
    };
    match file_out {
        Some(mut w) => {
            report::write(Some(&page), &mut w)?;
            w.flush()?;
        }
        None => report::write(Some(&page), out)?,
    }
    Ok(status_with_findings(program.status() == Status::Alarm, sim.as_ref().map(|s| &s.measurement.findings[..]).unwrap_or(&[])))
}

/// What the report's command line gave besides the machine, as the page's operator settings
/// pass it on (`main=`, `var=`, `call_args=`, `skip_missing_subprograms=`, `max_blocks=`).
pub(crate) fn page_settings(m: &MachineArgs) -> Vec<String> {
    let mut extra = Vec::new();
    extra.extend(m.main.iter().map(|v| format!("main={v}")));
    extra.extend(m.vars.iter().map(|v| format!("var={v}")));
    extra.extend(m.call_args.iter().map(|v| format!("call_args={v}")));
    if m.skip_missing_subprograms {
        extra.push("skip_missing_subprograms=1".into());
    }
    extra.extend(m.max_blocks.iter().map(|v| format!("max_blocks={v}")));
    extra
}

/// The files of the `--subprogram-dir` directories, for the page to look for called
/// programmes in (each by its file name, as the editor would show it). Files over 8 MB are left
/// out (not programme files; the page says so if one is called).
pub(crate) fn library_texts(dirs: &[std::path::PathBuf], decoding: &diag::Decoding) -> Vec<(String, String)> {
    feed::library_files(dirs).into_iter().map(|(name, bytes)| (name, editor_text(&bytes, decoding))).collect()
}

/// A programme file as the page's editor shows it: without a byte-order mark, each line as
/// written, UTF-8, or decoded where it is not (`--encoding`; GB18030 by default), CR LF as LF.
pub(crate) fn editor_text(bytes: &[u8], decoding: &diag::Decoding) -> String {
    let body = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(bytes);
    let lines: Vec<String> = body.split(|&b| b == b'\n').map(|l| decoding.decode(l.strip_suffix(b"\r").unwrap_or(l))).collect();
    lines.join("\n")
}

/// `ncsight app`: the page with no programme in it.
pub(crate) fn app(output: Option<&str>, out: &mut dyn Write) -> Result<i32, Failure> {
    if let Some(why) = report::engine_missing() {
        return Err(usage(why));
    }
    match output {
        Some(path) => {
            let mut w = output::LazyFile::new::<&str>(path, &[], 1 << 16).map_err(usage)?;
            report::write(None, &mut w)?;
            w.flush()?;
        }
        None => report::write(None, out)?,
    }
    Ok(0)
}
