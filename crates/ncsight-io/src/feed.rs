//! Feeding a programme from a byte stream (issue 9): one thread reads the input and turns its
//! lines into blocks while the calling thread interprets the lines read before, so reading and
//! interpreting share the two cores a small machine has. Memory stays bounded: a few batches of
//! at most `BATCH_BYTES` (plus one kept line) are in flight, and their buffers are reused.

use ncsight::{Event, LineReader, Program, ReadBatch, Request};
use std::io::{self, BufRead, Read};
use std::ops::Range;
use std::sync::mpsc;

/// Longest line kept; the rest of a longer line is skipped, so memory stays bounded (the
/// reader still sees the line as too long).
pub const MAX_KEPT_LINE_BYTES: usize = ncsight::read::MAX_KEPT_LINE_BYTES;

/// A batch is handed over once it holds this much text or `BATCH_LINES` lines.
const BATCH_BYTES: usize = 64 * 1024;
const BATCH_LINES: usize = 2048;

/// Batches read but not yet interpreted, at most.
const BATCHES_IN_FLIGHT: usize = 4;

/// Where a programme text comes from.
pub enum Input {
    /// A file: read ahead on a second thread while the programme only goes forward, read
    /// again through a page cache once it jumps back (nothing is held whole).
    File(std::path::PathBuf),
    /// A text already in memory (the report reads it whole).
    Memory(std::sync::Arc<Vec<u8>>),
    /// A stream such as a pipe: read once, so a jump back is refused with a clear error.
    Stream(Box<dyn BufRead + Send>),
}

impl Input {
    /// A programme file, opened once here. A named pipe or a device gives its data once, so it
    /// is read from this opening as a stream (a jump back is then refused with a clear error);
    /// a regular file is opened again by the reader, which reads it ahead and again after a
    /// jump back.
    pub fn open(path: &std::path::Path) -> io::Result<Input> {
        let f = std::fs::File::open(path)?;
        if f.metadata().is_ok_and(|m| !m.is_file()) {
            return Ok(Input::Stream(Box::new(io::BufReader::with_capacity(1 << 16, f))));
        }
        Ok(Input::File(path.to_path_buf()))
    }

    /// The stream the reading thread reads, and what the page cache reads a jump from.
    fn split(self) -> io::Result<(Box<dyn BufRead + Send>, Source)> {
        Ok(match self {
            Input::File(path) => {
                let f = std::fs::File::open(&path)?;
                (Box::new(io::BufReader::with_capacity(1 << 16, f)), Source::Path(path))
            }
            Input::Memory(text) => (Box::new(io::Cursor::new(ArcText(text.clone()))), Source::Memory(text)),
            Input::Stream(r) => (r, Source::Once),
        })
    }
}

/// A shared text as a cursor's buffer.
struct ArcText(std::sync::Arc<Vec<u8>>);

impl AsRef<[u8]> for ArcText {
    fn as_ref(&self) -> &[u8] {
        &self.0
    }
}

/// Line `line` (1-based) of the file at `path` into `out` (at most [`MAX_KEPT_LINE_BYTES`] of
/// it); left empty when the file cannot be read or is shorter.
pub fn line_of(path: &std::path::Path, line: u32, out: &mut Vec<u8>) {
    out.clear();
    let Ok(f) = std::fs::File::open(path) else { return };
    let mut r = io::BufReader::new(f);
    let mut n = 0u32;
    loop {
        let buf = match r.fill_buf() {
            Ok(b) if !b.is_empty() => b,
            _ => return,
        };
        let (piece, complete) = match memchr::memchr(b'\n', buf) {
            Some(k) => (&buf[..=k], true),
            None => (buf, false),
        };
        let used = piece.len();
        if n + 1 == line {
            let room = MAX_KEPT_LINE_BYTES.saturating_sub(out.len());
            out.extend_from_slice(&piece[..used.min(room)]);
        }
        r.consume(used);
        if complete {
            n += 1;
            if n == line {
                return;
            }
        }
    }
}

/// Line `line` (1-based) of a text into `out` (empty when it cannot be read again).
fn numbered_line(source: &Source, line: u32, out: &mut Vec<u8>) {
    out.clear();
    match source {
        Source::Path(p) => line_of(p, line, out),
        Source::Memory(text) => {
            if let Some(l) = text.split_inclusive(|&b| b == b'\n').nth((line as usize).saturating_sub(1)) {
                out.extend_from_slice(&l[..l.len().min(MAX_KEPT_LINE_BYTES)]);
            }
        }
        Source::Once => {}
    }
}

/// Whether a file's name is programme O`number`'s: `O1234`, `o1234.nc`, any extension, any
/// case, leading zeros or not.
fn named_after(p: &std::path::Path, number: u32) -> bool {
    let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    let digits = stem.strip_prefix('O').or_else(|| stem.strip_prefix('o'));
    digits.is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()) && d.parse::<u32>().ok() == Some(number))
}

/// Where a called programme that the text lacks is looked for (`--subprogram-dir`).
#[derive(Debug, Default)]
pub struct Library {
    pub dirs: Vec<std::path::PathBuf>,
    /// Each file of the directories, with the programme numbers it holds (read once, when a
    /// programme is first looked for by content).
    contents: Option<Vec<(std::path::PathBuf, Vec<u32>)>>,
}

/// Files above this size in a subprogramme folder are no programme files and are left out of
/// [`library_files`].
pub const MAX_LIBRARY_FILE_BYTES: u64 = 8 << 20;

/// Every file of `dirs` (in name order, each at most [`MAX_LIBRARY_FILE_BYTES`]) with its name
/// and bytes: the called programmes a run held in memory looks for (the page, a port).
pub fn library_files(dirs: &[std::path::PathBuf]) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<std::path::PathBuf> = dirs
        .iter()
        .filter_map(|d| std::fs::read_dir(d).ok())
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.metadata().map(|m| m.is_file() && m.len() <= MAX_LIBRARY_FILE_BYTES).unwrap_or(false))
        .collect();
    files.sort();
    files.into_iter().filter_map(|p| Some((p.file_name()?.to_string_lossy().into_owned(), std::fs::read(&p).ok()?))).collect()
}

impl Library {
    pub fn new(dirs: Vec<std::path::PathBuf>) -> Library {
        Library { dirs, contents: None }
    }

    fn files(&self) -> Vec<std::path::PathBuf> {
        let mut files: Vec<_> = self
            .dirs
            .iter()
            .filter_map(|d| std::fs::read_dir(d).ok())
            .flat_map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.is_file()).collect::<Vec<_>>())
            .collect();
        files.sort();
        files
    }

    /// The entries of the directories named after programme O`number` that are no readable
    /// file (a folder, a named pipe or device, a file that cannot be opened), each with why:
    /// passed over by [`Library::find`], and named when the programme is not found.
    pub fn passed_over(&self, number: u32) -> Vec<String> {
        let mut out = Vec::new();
        for d in &self.dirs {
            let Ok(rd) = std::fs::read_dir(d) else { continue };
            let mut entries: Vec<_> = rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| named_after(p, number)).collect();
            entries.sort();
            for p in entries {
                let why = match std::fs::metadata(&p) {
                    Ok(m) if m.is_dir() => "a folder".to_string(),
                    Ok(m) if !m.is_file() => "a named pipe or a device, not a regular file".to_string(),
                    Ok(_) => match std::fs::File::open(&p) {
                        Ok(_) => continue,
                        Err(e) => format!("cannot be read: {e}"),
                    },
                    Err(e) => format!("cannot be read: {e}"),
                };
                out.push(format!("{} ({why})", p.display()));
            }
        }
        out
    }

    /// The file that holds programme O`number`: one named after it (`O1234`, `o1234.nc`, any
    /// extension, any case, leading zeros or not), else one whose text holds it.
    pub fn find(&mut self, number: u32, reader: &LineReader) -> Option<std::path::PathBuf> {
        let named = |p: &std::path::PathBuf| named_after(p, number);
        let files = self.files();
        if let Some(p) = files.iter().find(|p| named(p)) {
            return Some(p.clone());
        }
        let contents = self.contents.get_or_insert_with(|| {
            files
                .iter()
                .map(|p| {
                    let mut numbers = Vec::new();
                    if let Ok(f) = std::fs::File::open(p) {
                        let mut r = io::BufReader::new(f);
                        let mut line = Vec::new();
                        while r.read_until(b'\n', &mut line).is_ok_and(|n| n > 0) {
                            reader.program_numbers(&line, &mut numbers);
                            line.clear();
                        }
                    }
                    (p.clone(), numbers)
                })
                .collect()
        });
        contents.iter().find(|(_, n)| n.contains(&number)).map(|(p, _)| p.clone())
    }
}

/// Lines on their way from the reading thread to the interpreting one: their text (for the
/// diagnostics) and what the reader made of them.
#[derive(Default)]
struct Batch {
    text: Vec<u8>,
    /// Each line's text in `text`.
    ranges: Vec<Range<usize>>,
    read: ReadBatch,
}

impl Batch {
    fn clear(&mut self) {
        self.text.clear();
        self.ranges.clear();
        self.read.clear();
    }

    fn is_full(&self) -> bool {
        self.text.len() >= BATCH_BYTES || self.ranges.len() >= BATCH_LINES
    }

    /// Read the text from `start` to the end as line `line_no`, `bytes` long in the input.
    fn read_line(&mut self, reader: &LineReader, line_no: u32, start: usize, bytes: u64) {
        let range = start..self.text.len();
        self.read.push(reader, line_no, &self.text[range.clone()]);
        if bytes != range.len() as u64 {
            self.read.set_last_line_bytes(bytes);
        }
        self.ranges.push(range);
    }
}

/// An error reading the input (not writing the output): the caller names the file.
#[derive(Debug)]
pub struct ReadFailure(pub io::Error);

impl std::fmt::Display for ReadFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::error::Error for ReadFailure {}

/// Whether an error of [`drive`] came from reading the input.
pub fn is_read_failure(e: &io::Error) -> bool {
    e.get_ref().is_some_and(|i| i.is::<ReadFailure>())
}

/// The file an event's line is in: `None` for the file the run began with, else the name of
/// the subprogramme file the library gave.
pub type FileName<'a> = Option<&'a str>;

/// Feed `input` line by line into `program`; `on_event` gets each event with its line's text
/// and, for a line of another file, that file's name. A programme that only reads forward is
/// read ahead on a second thread; once it jumps (a subprogramme call or return) its lines are
/// read from byte offsets through a page cache, and from the files of `library`. Stops reading
/// when the programme wants no more (an alarm in a run, the end of the text).
pub fn drive(
    input: Input,
    library: &mut Library,
    program: &mut Program,
    on_event: &mut dyn FnMut(&Event, &[u8], FileName) -> io::Result<()>,
) -> io::Result<()> {
    let (mut stream, source) = input.split().map_err(|e| io::Error::new(e.kind(), ReadFailure(e)))?;
    // The first lines decide whether the file has a tape leader; they are read again after.
    let mut head = Vec::new();
    let mut scan = program.leader_scan();
    loop {
        let start = head.len();
        let room = ncsight::LEADER_SCAN_BYTES.saturating_sub(start) as u64;
        let n = (&mut stream).take(room).read_until(b'\n', &mut head).map_err(|e| io::Error::new(e.kind(), ReadFailure(e)))?;
        if n == 0 || scan.push(&head[start..]) {
            break;
        }
    }
    program.set_tape_leader(scan.lines());
    let stream: Box<dyn BufRead + Send> = Box::new(io::Cursor::new(head).chain(stream));
    let mut pending: io::Result<()> = Ok(());
    let Some(request) = stream_forward(stream, &source, program, &mut |e, text| {
        if pending.is_ok() {
            pending = on_event(e, text, None);
        }
        pending.is_ok()
    })?
    else {
        return pending;
    };
    pending?;
    let mut pages = Pages::new(source);
    follow_jumps(request, &mut pages, library, program, on_event)
}

/// How long a thread of the forward phase spins for its partner before it sleeps.
const SPIN: std::time::Duration = std::time::Duration::from_micros(300);

/// Hand a batch to the interpreting thread: spinning a little while the batches in flight are
/// all taken (the interpreter is about to finish one), then waiting; an error when it has gone.
fn send_batch<T>(tx: &mpsc::SyncSender<T>, batch: T) -> Result<(), ()> {
    let start = std::time::Instant::now();
    let mut batch = batch;
    loop {
        match tx.try_send(batch) {
            Ok(()) => return Ok(()),
            Err(mpsc::TrySendError::Disconnected(_)) => return Err(()),
            Err(mpsc::TrySendError::Full(back)) if start.elapsed() < SPIN => {
                batch = back;
                std::hint::spin_loop();
            }
            Err(mpsc::TrySendError::Full(back)) => return tx.send(back).map_err(|_| ()),
        }
    }
}

/// The next batch from the reading thread, or none when it has ended. A batch is usually a
/// fraction of a millisecond away: the thread spins that long before it sleeps, since being put
/// to sleep and woken costs more than the wait on a virtual machine's processors (measured on
/// the 200,000-hole programme: 101 context switches before, 11 with both threads spinning;
/// `check` right after rs274, median of 7 alternating runs, 37 ms before, 32-34 ms after).
fn next_batch<T>(rx: &mpsc::Receiver<T>) -> Option<T> {
    let start = std::time::Instant::now();
    loop {
        match rx.try_recv() {
            Ok(batch) => return Some(batch),
            Err(mpsc::TryRecvError::Disconnected) => return None,
            Err(mpsc::TryRecvError::Empty) if start.elapsed() < SPIN => std::hint::spin_loop(),
            Err(mpsc::TryRecvError::Empty) => return rx.recv().ok(),
        }
    }
}

/// The forward phase: lines read ahead on a second thread. Returns the run's first request to
/// read elsewhere, if it makes one (the run is then not finished).
/// `on_event` says whether its consumer wants more: once it does not (a reader that went away,
/// a record the output cannot take), the run stops at the end of that line.
fn stream_forward(
    input: Box<dyn BufRead + Send>,
    source: &Source,
    program: &mut Program,
    on_event: &mut dyn FnMut(&Event, &[u8]) -> bool,
) -> io::Result<Option<Request>> {
    let reader = program.line_reader();
    let (full_tx, full_rx) = mpsc::sync_channel::<io::Result<Batch>>(BATCHES_IN_FLIGHT);
    let (empty_tx, empty_rx) = mpsc::channel::<Batch>();
    let reading = std::thread::Builder::new().name("ncsight-read".into()).spawn(move || read_ahead(input, &reader, &full_tx, &empty_rx))?;
    let mut stopped = false;
    // The number of the line being fed (the reader counts the same way), and the text of the
    // last line fed once its batch is gone (for what the end of the input says about it).
    let mut line_no = 0u32;
    let mut last_text = Vec::new();
    'batches: while let Some(batch) = next_batch(&full_rx) {
        let mut batch = batch?;
        for (i, range) in batch.ranges.iter().enumerate() {
            if !program.wants_more() {
                if let Some(r) = i.checked_sub(1).map(|k| batch.ranges[k].clone()) {
                    last_text.clear();
                    last_text.extend_from_slice(&batch.text[r]);
                }
                stopped = true;
                break 'batches;
            }
            line_no = line_no.wrapping_add(1);
            let line = &batch.text[range.clone()];
            let (ranges, text) = (&batch.ranges, &batch.text);
            let mut consumer_gone = false;
            program.feed_from(&batch.read, i, &mut |e| {
                // A diagnostic about an earlier line (a cycle that ends here) gets that line's
                // text while the line is still in this batch, none once it is gone.
                let text = match &e {
                    Event::Diagnostic(d) if d.span.line != line_no => {
                        let back = line_no.wrapping_sub(d.span.line) as usize;
                        match i.checked_sub(back) {
                            Some(k) if d.span.line < line_no => &text[ranges[k].clone()],
                            _ => &b""[..],
                        }
                    }
                    _ => line,
                };
                consumer_gone |= !on_event(&e, text);
            });
            if consumer_gone {
                stopped = true;
                break 'batches;
            }
            if let Some(r) = program.take_request() {
                // The reader ends at its next send (the channel is closed).
                return Ok(Some(r));
            }
        }
        if let Some(r) = batch.ranges.last() {
            last_text.clear();
            last_text.extend_from_slice(&batch.text[r.clone()]);
        }
        batch.clear();
        // The reader may have ended already; then the batch is simply dropped.
        let _ = empty_tx.send(batch);
        if !program.wants_more() {
            stopped = true;
            break;
        }
    }
    drop(full_rx);
    if !stopped {
        // The reader sent its last batch and returned; a panic there is a bug to pass on.
        if let Err(p) = reading.join() {
            std::panic::resume_unwind(p);
        }
    }
    // Otherwise the reader ends at its next send (the channel is closed); it is not waited for,
    // as it may be waiting for input that never comes (a terminal, a pipe left open).
    // An alarm the end of the text raises about an earlier line (a WHILE without END, a
    // search that found nothing) gets that line's text read again.
    let mut again = Vec::new();
    Ok(program.end_of_text(&mut |e| {
        let text = match &e {
            Event::Diagnostic(d) if d.span.line == line_no => &last_text[..],
            Event::Diagnostic(d) if d.is_alarm() && d.span.line > 0 => {
                numbered_line(source, d.span.line, &mut again);
                &again[..]
            }
            _ => &b""[..],
        };
        on_event(&e, text);
    }))
}

/// The jumping phase: the run says where to read, lines come from the page cache.
fn follow_jumps(
    first: Request,
    pages: &mut Pages,
    library: &mut Library,
    program: &mut Program,
    on_event: &mut dyn FnMut(&Event, &[u8], FileName) -> io::Result<()>,
) -> io::Result<()> {
    let reader = program.line_reader();
    let mut names: Vec<String> = vec![String::new()];
    let mut pending: io::Result<()> = Ok(());
    let mut at = (0u16, 0u64);
    let mut request = Some(first);
    let mut line = Vec::new();
    let mut again = Vec::new();
    // The file and number of the line being fed (a seek sets them).
    let mut here = (0u16, 0u32);
    let mut deliver = |e: Event, text: &[u8], here: (u16, u32), names: &[String], pages: &Pages, pending: &mut io::Result<()>| {
        let file = match &e {
            Event::Diagnostic(d) => d.span.file,
            Event::Record(r) => r.span.file,
        };
        let name = (file > 0).then(|| names.get(file as usize).map(String::as_str)).flatten();
        // A diagnostic about a line no longer at hand (one read before the jump) gets its
        // text read again.
        let text = match &e {
            Event::Diagnostic(d) if (d.span.file, d.span.line) != here && d.span.line > 0 => {
                pages.numbered_line(d.span.file, d.span.line, &mut again);
                &again[..]
            }
            _ => text,
        };
        if pending.is_ok() {
            *pending = on_event(&e, text, name);
        }
    };
    loop {
        while let Some(r) = request.take() {
            match r {
                Request::Seek(p) => {
                    if p.file as usize >= names.len() {
                        let name = program.file_name(p.file).to_string();
                        pages.open(p.file, std::path::PathBuf::from(&name))?;
                        names.resize(p.file as usize + 1, String::new());
                        names[p.file as usize] = name;
                    }
                    at = (p.file, p.offset);
                    here = (p.file, p.line.wrapping_sub(1));
                }
                Request::Find { number } => {
                    match library.find(number, &reader) {
                        Some(path) => {
                            program.open_file(path.display().to_string());
                        }
                        None => {
                            let passed_over = library.passed_over(number);
                            program.no_file_passing_over(&passed_over, &mut |e| deliver(e, b"", (u16::MAX, 0), &names, pages, &mut pending))
                        }
                    }
                    request = program.take_request();
                }
            }
        }
        pending.as_ref().map_err(|e| io::Error::new(e.kind(), e.to_string()))?;
        let bytes = if program.wants_more() { pages.line(at.0, at.1, &mut line)? } else { None };
        match bytes {
            Some(bytes) => {
                here.1 = here.1.wrapping_add(1);
                program.feed_line_of(&line, bytes, &mut |e| deliver(e, &line, here, &names, pages, &mut pending));
                at.1 += bytes;
                request = program.take_request();
            }
            None => {
                request = program.end_of_text(&mut |e| deliver(e, b"", (u16::MAX, 0), &names, pages, &mut pending));
                if request.is_none() {
                    return pending;
                }
            }
        }
    }
}

/// A text read again from byte offsets once the run jumps: fixed pages of each file, the least
/// recently used dropped past [`MAX_PAGES`], so memory stays bounded whatever the file's size.
struct Pages {
    files: Vec<Source>,
    pages: Vec<Page>,
    clock: u64,
}

/// What a jump is read from.
enum Source {
    Path(std::path::PathBuf),
    Memory(std::sync::Arc<Vec<u8>>),
    /// Read once (a pipe).
    Once,
}

struct Page {
    file: u16,
    index: u64,
    used: u64,
    bytes: Vec<u8>,
}

const PAGE_BYTES: u64 = 64 * 1024;
const MAX_PAGES: usize = 64;

impl Pages {
    fn new(main: Source) -> Pages {
        Pages { files: vec![main], pages: Vec::new(), clock: 0 }
    }

    fn open(&mut self, file: u16, path: std::path::PathBuf) -> io::Result<()> {
        let i = file as usize;
        while self.files.len() <= i {
            self.files.push(Source::Once);
        }
        std::fs::metadata(&path).map_err(|e| io::Error::new(e.kind(), ReadFailure(io::Error::new(e.kind(), format!("{}: {e}", path.display())))))?;
        self.files[i] = Source::Path(path);
        Ok(())
    }

    /// The bytes of page `index` of `file` (shorter at the end of the file, empty past it).
    fn page(&mut self, file: u16, index: u64) -> io::Result<&[u8]> {
        self.clock += 1;
        let clock = self.clock;
        if let Some(k) = self.pages.iter().position(|p| p.file == file && p.index == index) {
            self.pages[k].used = clock;
            return Ok(&self.pages[k].bytes);
        }
        let mut bytes = Vec::new();
        match &self.files[file as usize] {
            Source::Memory(text) => {
                let start = (index * PAGE_BYTES).min(text.len() as u64) as usize;
                let end = (start + PAGE_BYTES as usize).min(text.len());
                bytes.extend_from_slice(&text[start..end]);
            }
            Source::Path(path) => {
                use std::io::{Read, Seek};
                let mut f = std::fs::File::open(path).map_err(|e| io::Error::new(e.kind(), ReadFailure(e)))?;
                f.seek(io::SeekFrom::Start(index * PAGE_BYTES)).map_err(|e| io::Error::new(e.kind(), ReadFailure(e)))?;
                f.take(PAGE_BYTES).read_to_end(&mut bytes).map_err(|e| io::Error::new(e.kind(), ReadFailure(e)))?;
            }
            Source::Once => {
                let e = io::Error::new(
                    io::ErrorKind::Unsupported,
                    "the programme jumps back (a subprogramme call or return), and a pipe cannot be read again: give the programme as a file",
                );
                return Err(io::Error::new(e.kind(), ReadFailure(e)));
            }
        }
        let page = Page { file, index, used: clock, bytes };
        let k = if self.pages.len() < MAX_PAGES {
            self.pages.push(page);
            self.pages.len() - 1
        } else {
            let k = self.pages.iter().enumerate().min_by_key(|(_, p)| p.used).map_or(0, |(k, _)| k);
            self.pages[k] = page;
            k
        };
        Ok(&self.pages[k].bytes)
    }

    /// Line `line` (1-based) of `file` into `out` (empty when there is none to read).
    fn numbered_line(&self, file: u16, line: u32, out: &mut Vec<u8>) {
        out.clear();
        if let Some(source) = self.files.get(file as usize) {
            numbered_line(source, line, out);
        }
    }

    /// The line of `file` that starts at byte `offset` into `out` (at most
    /// [`MAX_KEPT_LINE_BYTES`] of it, with its break), and its whole length; `None` at the end.
    fn line(&mut self, file: u16, offset: u64, out: &mut Vec<u8>) -> io::Result<Option<u64>> {
        out.clear();
        let mut at = offset;
        loop {
            let (index, within) = (at / PAGE_BYTES, (at % PAGE_BYTES) as usize);
            let page = self.page(file, index)?;
            if within >= page.len() {
                return Ok((at > offset).then_some(at - offset));
            }
            let rest = &page[within..];
            let (piece, complete) = match memchr::memchr(b'\n', rest) {
                Some(k) => (&rest[..=k], true),
                None => (rest, false),
            };
            let room = MAX_KEPT_LINE_BYTES.saturating_sub(out.len());
            out.extend_from_slice(&piece[..piece.len().min(room)]);
            at += piece.len() as u64;
            if complete {
                return Ok(Some(at - offset));
            }
        }
    }
}

/// The reading thread: lines into batches, until the input ends or nobody listens.
fn read_ahead(mut input: Box<dyn BufRead + Send>, reader: &LineReader, full: &mpsc::SyncSender<io::Result<Batch>>, empty: &mpsc::Receiver<Batch>) {
    let mut batch = Batch::default();
    let mut line_no = 0u32;
    // Where the line being gathered starts in the batch text, how long it is in the input; the
    // rest of an over-long line is being skipped.
    let mut start = 0usize;
    let mut line_bytes = 0u64;
    let mut skipping = false;
    loop {
        let buf = match input.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => {
                // The lines read before the error are interpreted first.
                if !batch.ranges.is_empty() {
                    batch.text.truncate(start);
                    let _ = full.send(Ok(batch));
                }
                let _ = full.send(Err(io::Error::new(e.kind(), ReadFailure(e))));
                return;
            }
        };
        if buf.is_empty() {
            if batch.text.len() > start {
                line_no = line_no.wrapping_add(1);
                batch.read_line(reader, line_no, start, line_bytes);
            }
            if !batch.ranges.is_empty() {
                let _ = full.send(Ok(batch));
            }
            return;
        }
        let (piece, complete) = match memchr::memchr(b'\n', buf) {
            Some(k) => (&buf[..=k], true),
            None => (buf, false),
        };
        let used = piece.len();
        line_bytes += used as u64;
        // The buffer is used up: the next read may wait (a terminal, a pipe), so the lines
        // read so far go now.
        let drained = used == buf.len();
        if !skipping {
            let room = MAX_KEPT_LINE_BYTES - (batch.text.len() - start);
            batch.text.extend_from_slice(&piece[..used.min(room)]);
            skipping = !complete && batch.text.len() - start == MAX_KEPT_LINE_BYTES;
        }
        if complete {
            // The line is read with its whole length (the start of an over-long one is kept).
            line_no = line_no.wrapping_add(1);
            batch.read_line(reader, line_no, start, line_bytes);
            start = batch.text.len();
            line_bytes = 0;
            skipping = false;
        }
        input.consume(used);
        if !batch.ranges.is_empty() && (batch.is_full() || drained) {
            // The line being gathered, if any, moves on to the next batch.
            let mut next = empty.try_recv().unwrap_or_default();
            next.clear();
            next.text.extend_from_slice(&batch.text[start..]);
            batch.text.truncate(start);
            if send_batch(full, Ok(std::mem::replace(&mut batch, next))).is_err() {
                return;
            }
            start = 0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ncsight::profile::{self, Params};
    use ncsight::{Mode, Switches};

    fn program(mode: Mode) -> Program {
        Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), mode)
    }

    fn events_of(input: Box<dyn BufRead + Send>, mode: Mode) -> (Vec<Event>, Vec<Vec<u8>>) {
        let mut p = program(mode);
        let (mut events, mut texts) = (Vec::new(), Vec::new());
        drive(Input::Stream(input), &mut Library::default(), &mut p, &mut |e, text, _| {
            events.push(e.clone());
            texts.push(text.to_vec());
            Ok(())
        })
        .unwrap();
        (events, texts)
    }

    /// The threaded feed gives what feeding the lines one by one gives: the same events, each
    /// with its own line's text, across many batches, CRLF, blank lines and a last line without
    /// a line break.
    #[test]
    fn same_events_as_line_by_line() {
        let mut text = String::from("G21 G17 G90 G00 X0. Y0. Z10.\r\nF500.\n\nG98 G81 X1. Y1. Z-5. R2.\n");
        for i in 0..20_000 {
            text.push_str(&format!("X{}.{} Y{}.5\n", i % 300, i % 10, i / 300));
            if i % 4999 == 0 {
                text.push_str("X1. Q5.\n"); // an alarm now and then (Q is not taken by G81)
            }
        }
        text.push_str("G80\nM30");
        for mode in [Mode::Run, Mode::Check] {
            let expected = ncsight::run_text(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), mode, text.as_bytes());
            let (events, texts) = events_of(Box::new(io::Cursor::new(text.clone().into_bytes())), mode);
            assert_eq!(events, expected, "{mode:?}");
            let lines: Vec<&str> = text.split('\n').collect();
            for (e, t) in events.iter().zip(&texts) {
                if let Event::Diagnostic(d) = e {
                    if d.span.line as usize <= lines.len() && !t.is_empty() {
                        assert_eq!(String::from_utf8_lossy(t).trim_end(), lines[d.span.line as usize - 1].trim_end());
                    }
                }
            }
        }
    }

    /// Jumps through the threaded feed (a file re-read from byte offsets, batches of an old
    /// place dropped) give what the core's own pull iterator gives: calls forward and back
    /// across many batches, repeats, a search that goes round the file, M99 P, a programme
    /// that no file holds, in a run and a check.
    #[test]
    fn jumps_give_what_the_pull_iterator_gives() {
        let mut text = String::from("O0001\nG21 G17 G90 G00 X0. Y0. Z10.\nM98 P0030100\n");
        for i in 0..6_000 {
            text.push_str(&format!("G01 X{}. Y{}. F900.\n", i % 50, i % 7));
        }
        text.push_str("M98 P0020200\nM98 P0300\nG00 X7.\nN77 M98 P0400\nM30\nO0100\nG91 G00 Z-0.5\nG90\nM98 P0200\nM99\n");
        text.push_str("O0200\nG01 X3. F300.\nM99\nO0300\nG00 Y4.\nM99 P77\n");
        for mode in [Mode::Run, Mode::Check] {
            let expected: Vec<Event> = {
                let mut p = program(mode);
                p.set_call_options(ncsight::CallOptions::default());
                ncsight::events(p, text.as_bytes()).collect()
            };
            // The run stops at O0400 (in no file): FANUC 0 alarm 078; a check goes on.
            assert!(expected.iter().any(|e| matches!(e, Event::Diagnostic(d) if d.code == "PS0078")));
            let mut p = program(mode);
            let mut events = Vec::new();
            drive(Input::Memory(std::sync::Arc::new(text.clone().into_bytes())), &mut Library::default(), &mut p, &mut |e, _, _| {
                events.push(e.clone());
                Ok(())
            })
            .unwrap();
            assert_eq!(events.len(), expected.len(), "{mode:?}");
            assert!(events == expected, "{mode:?}");
        }
    }

    /// An input error after some lines: those lines are interpreted, then the error is given.
    #[test]
    fn lines_before_an_input_error_count() {
        struct Broken(Option<Vec<u8>>);
        impl io::Read for Broken {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                match self.0.take() {
                    Some(d) => {
                        buf[..d.len()].copy_from_slice(&d);
                        Ok(d.len())
                    }
                    None => Err(io::Error::new(io::ErrorKind::ConnectionReset, "reset")),
                }
            }
        }
        let mut p = program(Mode::Check);
        let mut alarms = Vec::new();
        let r =
            drive(Input::Stream(Box::new(io::BufReader::new(Broken(Some(b"G0 X1. Q5\nG0 X2".to_vec()))))), &mut Library::default(), &mut p, &mut |e, _, _| {
                if let Event::Diagnostic(d) = e {
                    alarms.push(d.span.line);
                }
                Ok(())
            });
        assert_eq!(r.unwrap_err().kind(), io::ErrorKind::ConnectionReset);
        assert_eq!(alarms, vec![1]);
    }

    /// What the end of the input says about the last line (no programme end) comes with that
    /// line's text; a diagnostic about an earlier line in the same batch with its own.
    #[test]
    fn late_diagnostics_keep_their_line() {
        let (events, texts) = events_of(Box::new(io::Cursor::new(b"G0 X1.\nG1 X2. F100.\n".to_vec())), Mode::Check);
        let k = events.iter().position(|e| matches!(e, Event::Diagnostic(d) if d.rule == ncsight::Rule::NoProgramEnd)).unwrap();
        assert_eq!(texts[k], b"G1 X2. F100.\n");
        let text = "G99 M03 S500\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X20. Z2.\nG01 X40. Z-10.\nZ-15.\nN20 X30. Z-20.\nM30\n";
        let mut p = Program::new(Params::defaults(profile::by_name("gsk980tdi").unwrap()), Switches::default(), Mode::Check);
        let mut seen = Vec::new();
        drive(Input::Memory(std::sync::Arc::new(text.as_bytes().to_vec())), &mut Library::default(), &mut p, &mut |e, t, _| {
            if let Event::Diagnostic(d) = e {
                seen.push((d.span.line, String::from_utf8_lossy(t).into_owned()));
            }
            Ok(())
        })
        .unwrap();
        // The step-8 warning belongs to the G71 block of line 4, given when the contour ends.
        assert!(seen.iter().any(|(l, t)| *l == 4 && t.starts_with("G71 P10")), "{seen:?}");
    }

    /// A line longer than the kept length: its start is read (and is one alarm), the rest is
    /// skipped, and the next line is line 2.
    #[test]
    fn overlong_line_is_cut_and_counted_once() {
        let mut text = "G01 X1.".repeat(20_000);
        text.push_str("\nG0 X1 Q\nM30\n");
        let (events, _) = events_of(Box::new(io::Cursor::new(text.into_bytes())), Mode::Check);
        let lines: Vec<u32> = events
            .iter()
            .filter_map(|e| match e {
                Event::Diagnostic(d) if d.is_alarm() => Some(d.span.line),
                _ => None,
            })
            .collect();
        assert_eq!(lines, vec![1, 2]);
    }

    /// Input that never ends (a pipe left open) after the programme end: the run returns.
    #[test]
    fn endless_input_after_the_end() {
        struct Endless(Vec<u8>, usize);
        impl io::Read for Endless {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                let n = buf.len().min(self.0.len() - self.1);
                buf[..n].copy_from_slice(&self.0[self.1..self.1 + n]);
                self.1 = (self.1 + n) % self.0.len();
                Ok(n)
            }
        }
        struct Stuck(Option<Vec<u8>>, mpsc::Receiver<()>);
        impl io::Read for Stuck {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                match self.0.take() {
                    Some(d) => {
                        buf[..d.len()].copy_from_slice(&d);
                        Ok(d.len())
                    }
                    None => {
                        let _ = self.1.recv(); // blocks: nobody sends
                        Ok(0)
                    }
                }
            }
        }
        let (tx, rx) = mpsc::channel();
        let (tx2, rx2) = mpsc::channel::<()>();
        let (done_tx, done_rx) = mpsc::channel();
        std::thread::spawn(move || {
            let (e1, _) = events_of(Box::new(io::BufReader::new(Endless(b"G0 X1.\nM30\n".to_vec(), 0))), Mode::Run);
            let (e2, _) = events_of(Box::new(io::BufReader::new(Stuck(Some(b"G0 X1.\nM30\n".to_vec()), rx))), Mode::Run);
            // A line begun but not ended after the programme end: the run does not wait for it.
            let (e3, _) = events_of(Box::new(io::BufReader::new(Stuck(Some(b"G0 X1.\nM30\nG0 X".to_vec()), rx2))), Mode::Run);
            done_tx.send((e1.len(), e2.len().min(e3.len()))).unwrap();
        });
        let (n1, n2) = done_rx.recv_timeout(std::time::Duration::from_secs(20)).expect("the run did not return");
        assert!(n1 > 0 && n2 > 0);
        drop((tx, tx2));
    }
}
