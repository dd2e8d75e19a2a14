//! The native half of the Python package `ncsight`: a thin layer over the core and its driver
//! (`ncsight-io`). Every record and diagnostic leaves here as the JSONL line the command line
//! writes for it (one formatter for both), and the Python half turns each into a dict, so the
//! package and `ncsight run --format jsonl` agree field for field.

use ncsight::{Mode, Status};
use ncsight_io::feed::Input;
use ncsight_io::{Job, JobError};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyString};
use std::path::PathBuf;
use std::sync::mpsc;
use std::sync::Arc;

fn to_py(e: JobError) -> PyErr {
    match e {
        JobError::Usage(m) => PyValueError::new_err(m),
        JobError::Io(e) => PyOSError::new_err(e.to_string()),
    }
}

/// How a run is asked for: the machine and the command line's options, built once by the
/// Python half (`ncsight._options`).
#[pyclass(frozen)]
struct Options {
    job: Job,
}

#[pymethods]
impl Options {
    #[new]
    #[pyo3(signature = (machine, params=Vec::new(), main=None, subprogram_dirs=Vec::new(), skip_missing_subprograms=false, max_blocks=None, variables=Vec::new(), block_delete=false, optional_stop=false, setup_path=None, setup_toml=None, call_args=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        machine: &str,
        params: Vec<String>,
        main: Option<String>,
        subprogram_dirs: Vec<PathBuf>,
        skip_missing_subprograms: bool,
        max_blocks: Option<u64>,
        variables: Vec<String>,
        block_delete: bool,
        optional_stop: bool,
        setup_path: Option<PathBuf>,
        setup_toml: Option<String>,
        call_args: Option<String>,
    ) -> PyResult<Options> {
        let mut job = Job {
            machine: machine.to_string(),
            params,
            switches: ncsight::Switches { block_delete, optional_stop, repair_position: None },
            operator: ncsight::Options::default(),
            main,
            subprogram_dirs,
            skip_missing_subprograms,
            max_blocks,
            vars: variables,
            call_args,
            setup: None,
            setup_dir: None,
        };
        // The setup as a file, or as the TOML the Python half wrote from a mapping.
        if let Some(p) = setup_path {
            job.read_setup(&p.to_string_lossy()).map_err(to_py)?;
        }
        if let Some(t) = setup_toml {
            job.set_setup_text(&t, "setup").map_err(to_py)?;
        }
        Ok(Options { job })
    }
}

fn mode_of(mode: &str) -> PyResult<Mode> {
    match mode {
        "run" => Ok(Mode::Run),
        "check" => Ok(Mode::Check),
        _ => Err(PyValueError::new_err(format!("mode '{mode}': run or check"))),
    }
}

/// What a programme comes from: its text (str or bytes), or a file read as it runs.
enum Source {
    Text(Vec<u8>),
    /// A file opened once (a named pipe is read from that opening).
    File(Input),
}

impl Source {
    fn input(self) -> Input {
        match self {
            Source::Text(t) => Input::Memory(Arc::new(t)),
            Source::File(input) => input,
        }
    }
}

fn source(text: Option<&Bound<'_, PyAny>>, path: Option<PathBuf>) -> PyResult<Source> {
    match (text, path) {
        (Some(t), None) => {
            if let Ok(s) = t.downcast::<PyString>() {
                Ok(Source::Text(s.to_cow()?.as_bytes().to_vec()))
            } else if let Ok(b) = t.downcast::<PyBytes>() {
                // One copy of the buffer (not element by element).
                Ok(Source::Text(b.as_bytes().to_vec()))
            } else if let Ok(b) = t.downcast::<PyByteArray>() {
                Ok(Source::Text(b.to_vec()))
            } else {
                Err(PyValueError::new_err("the programme text is a str or bytes"))
            }
        }
        (None, Some(p)) => {
            if p.is_dir() {
                return Err(PyValueError::new_err(format!("cannot read {}: it is a directory, not a programme file", p.display())));
            }
            let input = Input::open(&p).map_err(|e| PyValueError::new_err(format!("cannot read {}: {e}", p.display())))?;
            Ok(Source::File(input))
        }
        _ => Err(PyValueError::new_err("give the programme's text or its path, not both")),
    }
}

/// The whole run as JSONL lines (the GIL is released while it runs), and whether it ended in
/// an alarm.
#[pyfunction]
#[pyo3(signature = (options, mode, name, text=None, path=None))]
fn jsonl_lines(
    py: Python<'_>,
    options: &Options,
    mode: &str,
    name: &str,
    text: Option<&Bound<'_, PyAny>>,
    path: Option<PathBuf>,
) -> PyResult<(Vec<String>, bool)> {
    let mode = mode_of(mode)?;
    let src = source(text, path)?;
    let job = &options.job;
    py.allow_threads(move || {
        let mut lines = Vec::new();
        let status = job.jsonl(src.input(), mode, name, &mut |l| {
            lines.push(l.to_string());
            Ok(())
        })?;
        Ok((lines, status == Status::Alarm))
    })
    .map_err(to_py)
}

/// Lines of a run made on another thread, taken one at a time: a programme of any size runs
/// in bounded memory (at most `IN_FLIGHT` lines wait).
#[pyclass]
struct LineStream {
    lines: Option<std::sync::Mutex<mpsc::Receiver<Result<String, JobError>>>>,
}

const IN_FLIGHT: usize = 4096;

/// The run thread's last line: the run ended (a channel that closes without it was broken).
const END: &str = "\u{0}end";

#[pymethods]
impl LineStream {
    #[new]
    #[pyo3(signature = (options, mode, name, text=None, path=None))]
    fn new(options: &Options, mode: &str, name: String, text: Option<&Bound<'_, PyAny>>, path: Option<PathBuf>) -> PyResult<LineStream> {
        let mode = mode_of(mode)?;
        let src = source(text, path)?;
        let job = options.job.clone();
        // A usage mistake is raised here, not on the first line.
        job.program(mode).map_err(to_py)?;
        let (tx, rx) = mpsc::sync_channel(IN_FLIGHT);
        std::thread::Builder::new()
            .name("ncsight-run".into())
            .spawn(move || {
                let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    job.jsonl(src.input(), mode, &name, &mut |l| {
                        // The reader went away (the iterator was dropped): stop the run.
                        tx.send(Ok(l.to_string())).map_err(|_| std::io::Error::new(std::io::ErrorKind::BrokenPipe, "closed"))
                    })
                }));
                let result = match run {
                    Ok(r) => r,
                    // A bug in ncsight: said, never taken for the end of the programme.
                    Err(_) => Err(JobError::Io(std::io::Error::other("ncsight stopped on an internal error (a panic); please report the programme"))),
                };
                let end = match result {
                    Ok(_) => Ok(END.to_string()),
                    Err(e) => Err(e),
                };
                let _ = tx.send(end);
            })
            .map_err(|e| PyOSError::new_err(e.to_string()))?;
        Ok(LineStream { lines: Some(std::sync::Mutex::new(rx)) })
    }

    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__(&mut self, py: Python<'_>) -> PyResult<Option<String>> {
        let Some(rx) = &self.lines else { return Ok(None) };
        // Only this iterator takes from the channel: the lock is never contended.
        match py.allow_threads(|| rx.lock().map_err(|_| mpsc::RecvError).and_then(|r| r.recv())) {
            Ok(Ok(line)) if line == END => {
                self.lines = None;
                Ok(None)
            }
            Ok(Ok(line)) => Ok(Some(line)),
            Ok(Err(JobError::Io(e))) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                self.lines = None;
                Ok(None)
            }
            Ok(Err(e)) => {
                self.lines = None;
                Err(to_py(e))
            }
            Err(_) => {
                self.lines = None;
                Err(PyOSError::new_err("ncsight's run thread ended without finishing the programme"))
            }
        }
    }
}

/// The profiles' names.
#[pyfunction]
fn machines() -> Vec<&'static str> {
    ncsight::profile::all().iter().map(|p| p.name).collect()
}

#[pymodule]
fn _ncsight(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(jsonl_lines, m)?)?;
    m.add_function(wrap_pyfunction!(machines, m)?)?;
    m.add_class::<LineStream>()?;
    m.add_class::<Options>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
