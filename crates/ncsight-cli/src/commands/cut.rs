//! `simulate`: the stock cut by the programme, measured, drawn.

use crate::*;

#[allow(clippy::too_many_arguments)]
pub(crate) fn simulate(
    file: &str,
    m: &MachineArgs,
    stock: Option<&str>,
    expect: Option<&str>,
    format: &str,
    outputs: SimOutputs,
    resolution: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let image = outputs.image;
    if format != "text" && format != "json" {
        return Err(usage(format!("unknown format '{format}': choose text or json")));
    }
    let mut head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let decoding = m.decoding()?;
    let mut job = job_setup(m, params.profile(), stock)?;
    let reads = m.read_files(file);
    let image_out = image.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    let stl_out = outputs.stl.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    let dxf = match outputs.section {
        Some(p) if p.to_ascii_lowercase().ends_with(".dxf") => true,
        Some(p) if p.to_ascii_lowercase().ends_with(".svg") => false,
        Some(p) => return Err(usage(format!("--section {p}: name the drawing OUT.svg or OUT.dxf"))),
        None => false,
    };
    if outputs.section.is_some() && !params.profile().is_lathe() {
        return Err(usage(format!(
            "--section draws a turned part's axial section; {} is a machining centre (--stl writes its cut block)",
            params.profile().name
        )));
    }
    let section_out = outputs.section.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    if image_out.is_some() && !params.profile().is_lathe() {
        return Err(usage(format!(
            "--image draws the unrolled surface of a thread on a lathe; {} is a machining centre: the drilling simulation has no image (its holes are in the text or JSON output)",
            params.profile().name
        )));
    }
    let opts = simulate::options(resolution, expect).map_err(usage)?;
    let lathe = params.profile().is_lathe();
    // Two runs of the programme: a survey (the tools to assume, the stock to guess, the grid),
    // then the cut, each record as it comes; nothing holds the programme's records, so a
    // programme of any length is simulated. Standard input or a pipe is read once, into a
    // temporary file both runs read.
    let source = Spooled::of(file, head.input.take())?;
    let shown = if file == "-" { "<stdin>" } else { file };
    let mut lathe_survey = ncsight::stock::survey::LatheSurvey::new(&job);
    let mut mill_survey = ncsight::stock::survey::MillSurvey::default();
    // A school simulator's `[BILLET` line gives the stock where neither --stock nor the setup does.
    let mut billet_free = if lathe { job.stock.is_none() } else { job.block.is_none() };
    let alarmed = {
        let mut program = Program::new(params.clone(), switches, Mode::Run);
        let mut library = m.prepare(&mut program)?;
        drive(file, source.input()?, &mut library, &mut program, &mut |e, text, name| {
            match e {
                Event::Diagnostic(d) if d.rule == ncsight::Rule::SimulatorStock && billet_free => {
                    let given = ncsight::read::simulator::billet(text).and_then(|b| b.stock_text(lathe));
                    if let Some(stock) = given.filter(|s| job.set_stock_text(s, lathe).is_ok()) {
                        billet_free = false;
                        writeln!(err, "{}: stock {stock} mm from its [BILLET line", name.unwrap_or(shown))?;
                        lathe_survey.stock_given(&job);
                    }
                }
                Event::Record(r) if lathe => lathe_survey.add(r),
                Event::Record(r) => mill_survey.add(r),
                Event::Diagnostic(d) if d.is_alarm() => err.write_all(diag::render(name.unwrap_or(shown), text, d, diag::Style::Full, &decoding).as_bytes())?,
                Event::Diagnostic(_) => {}
            }
            Ok(())
        })?;
        program.status() == Status::Alarm
    };
    let mut program = Program::new(params, switches, Mode::Run);
    let mut library = m.prepare(&mut program)?;
    if !lathe {
        let mut cut = match ncsight::stock::measure::MillCut::new(&mill_survey, &job, opts.dz_mm, None) {
            Ok(cut) => cut,
            Err(e) => return not_simulated(alarmed || !mill_survey.cuts(), alarmed, e, err),
        };
        cut_beside(file, source.input()?, &mut library, &mut program, &mut |r| cut.add(r))?;
        let sim = cut.finish();
        let body = if format == "json" { simulate::mill_json(&sim) } else { simulate::mill_text(&sim) };
        out.write_all(body.as_bytes())?;
        if let Some(mut w) = stl_out {
            simulate::stl(&mut w, &|each| ncsight::stock::mesh::mill(&sim.stock, each))?;
            w.flush()?;
        }
        return Ok(status_with_findings(alarmed, &sim.findings));
    }
    let mut cut = match ncsight::stock::measure::LatheCut::new(&lathe_survey, &job, &opts) {
        Ok(cut) => cut,
        Err(e) => return not_simulated(alarmed || lathe_survey.guessed_bar(false).is_none(), alarmed, e, err),
    };
    let (total, mut done) = (lathe_survey.records, 0usize);
    let mut progress = progress_on(err);
    drive(file, source.input()?, &mut library, &mut program, &mut |e, _, _| {
        if let Event::Record(r) = e {
            cut.add(r);
            done += 1;
            progress(done, total);
        }
        Ok(())
    })?;
    let sim = cut.finish(&opts);
    let body = if format == "json" { simulate::json(&sim.measurement) } else { simulate::text(&sim.measurement) };
    out.write_all(body.as_bytes())?;
    if let Some(mut w) = image_out {
        simulate::image(&sim, &mut w)?;
        w.flush()?;
    }
    if let Some(mut w) = stl_out {
        simulate::stl(&mut w, &|each| ncsight::stock::mesh::lathe(&sim.stock, each))?;
        w.flush()?;
    }
    if let Some(mut w) = section_out {
        if dxf {
            simulate::section_dxf(&mut w, &sim.stock)?
        } else {
            simulate::section_svg(&mut w, &sim.stock)?
        }
        w.flush()?;
    }
    Ok(status_with_findings(alarmed, &sim.measurement.findings))
}

/// The stock could not be set up (no stock given and nothing cut to guess it from, a grid too
/// large): a usage mistake, unless there is nothing to simulate: the programme stopped on an
/// alarm, or ran and cut nothing. Then it says so and the exit status is the run's (the alarm
/// is already shown).
pub(crate) fn not_simulated(nothing_to_cut: bool, alarmed: bool, why: String, err: &mut dyn Write) -> Result<i32, Failure> {
    if !nothing_to_cut {
        return Err(usage(why));
    }
    writeln!(err, "ncsight: the stock was not simulated: {why}")?;
    Ok(if alarmed { EXIT_ALARM } else { 0 })
}

/// Records a batch takes from the interpreter to the cut beside it.
pub(crate) const CUT_BATCH: usize = 512;

/// Run the programme and hand its records to `cut` on a thread of its own, in batches, so the
/// interpreter and the cut work at once (a machining centre's cut is one thread's work).
pub(crate) fn cut_beside(
    file: &str,
    input: feed::Input,
    library: &mut feed::Library,
    program: &mut Program,
    cut: &mut (dyn FnMut(&ncsight::Record) + Send),
) -> Result<(), Failure> {
    let (to_cut, batches) = std::sync::mpsc::sync_channel::<Vec<ncsight::Record>>(8);
    std::thread::scope(|scope| {
        // The cut runs on the parallel pool's threads, where a move splits its rows between the
        // two at little cost (from a thread outside the pool each split waits for a wake-up).
        let cutter = scope.spawn(move || {
            let pool = rayon::ThreadPoolBuilder::new().build();
            let work = || {
                for batch in batches {
                    batch.iter().for_each(&mut *cut);
                }
            };
            match pool {
                Ok(pool) => pool.install(work),
                Err(_) => work(),
            }
        });
        let mut batch = Vec::with_capacity(CUT_BATCH);
        let ran = drive(file, input, library, program, &mut |e, _, _| {
            if let Event::Record(r) = e {
                batch.push(r.clone());
                if batch.len() == CUT_BATCH {
                    // The cut ends only when this sender is dropped: a send cannot fail first.
                    let _ = to_cut.send(std::mem::replace(&mut batch, Vec::with_capacity(CUT_BATCH)));
                }
            }
            Ok(())
        });
        if !batch.is_empty() {
            let _ = to_cut.send(batch);
        }
        drop(to_cut);
        if cutter.join().is_err() {
            return Err(Failure::Io(io::Error::other("the stock simulation's thread failed")));
        }
        ran
    })
}

/// A programme `simulate` reads twice: a file, read again; standard input or a pipe, copied once
/// into a temporary file that goes when this does.
pub(crate) struct Spooled {
    pub(crate) path: std::path::PathBuf,
    pub(crate) temporary: bool,
}

impl Spooled {
    /// `file`, or its `input` already opened (standard input or a pipe, its first line read).
    pub(crate) fn of(file: &str, input: Option<feed::Input>) -> Result<Spooled, Failure> {
        if file != "-" {
            let regular = std::fs::metadata(file).map(|m| m.is_file()).map_err(|e| usage(format!("cannot read {file}: {e}")))?;
            if regular {
                return Ok(Spooled { path: file.into(), temporary: false });
            }
        }
        static NEXT: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!("ncsight-simulate-{}-{n}.nc", std::process::id()));
        let spooled = Spooled { path, temporary: true };
        let mut to =
            std::fs::File::create(&spooled.path).map_err(|e| usage(format!("cannot write a temporary copy of {file} at {}: {e}", spooled.path.display())))?;
        let input = match input {
            Some(input) => input,
            None => open(file)?,
        };
        let copied = match input {
            feed::Input::Stream(mut r) => io::copy(&mut r, &mut to),
            feed::Input::File(p) => std::fs::File::open(p).and_then(|mut f| io::copy(&mut f, &mut to)),
            feed::Input::Memory(t) => to.write_all(&t).map(|_| t.len() as u64),
        };
        copied.map_err(|e| usage(format!("cannot read {file}: {e}")))?;
        Ok(spooled)
    }

    pub(crate) fn input(&self) -> Result<feed::Input, Failure> {
        Ok(feed::Input::File(self.path.clone()))
    }
}

impl Drop for Spooled {
    fn drop(&mut self) {
        if self.temporary {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// The files `simulate` writes besides its report.
pub(crate) struct SimOutputs<'a> {
    pub(crate) image: Option<&'a str>,
    pub(crate) stl: Option<&'a str>,
    pub(crate) section: Option<&'a str>,
}
