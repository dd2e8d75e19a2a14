//! Feeding a programme from a byte stream (issue 9): one thread reads the input and turns its
//! lines into blocks while the calling thread interprets the lines read before, so reading and
//! interpreting share the two cores a small machine has. Memory stays bounded: a few batches of
//! at most `BATCH_BYTES` (plus one kept line) are in flight, and their buffers are reused.

use ncsight::{Event, LineReader, Program, ReadBatch, Request};
use std::io::{self, BufRead};
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

/// A programme text the reading thread reads: a stream, and for a file a way back to any byte
/// offset (a jump to an earlier block re-reads the file from there, so nothing is held whole).
pub trait Text: BufRead + Send {
    /// Go on reading from byte `offset`.
    fn seek_to(&mut self, offset: u64) -> io::Result<()>;
}

impl Text for io::BufReader<std::fs::File> {
    fn seek_to(&mut self, offset: u64) -> io::Result<()> {
        io::Seek::seek(self, io::SeekFrom::Start(offset)).map(|_| ())
    }
}

impl<T: AsRef<[u8]> + Send> Text for io::Cursor<T> {
    fn seek_to(&mut self, offset: u64) -> io::Result<()> {
        self.set_position(offset);
        Ok(())
    }
}

/// A text that can only be read once (a pipe): a jump back is refused with a clear error.
pub struct Stream(pub Box<dyn BufRead + Send>);

impl io::Read for Stream {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.0.read(buf)
    }
}

impl BufRead for Stream {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        self.0.fill_buf()
    }
    fn consume(&mut self, n: usize) {
        self.0.consume(n)
    }
}

impl Text for Stream {
    fn seek_to(&mut self, _: u64) -> io::Result<()> {
        Err(io::Error::new(io::ErrorKind::Unsupported, "the programme jumps back (a subprogramme call or return), and a pipe cannot be read again: give the programme as a file"))
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
        let (piece, complete) = match buf.iter().position(|&b| b == b'\n') {
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

/// Where a called programme that the text lacks is looked for (`--subprogram-dir`).
#[derive(Debug, Default)]
pub struct Library {
    pub dirs: Vec<std::path::PathBuf>,
    /// Each file of the directories, with the programme numbers it holds (read once, when a
    /// programme is first looked for by content).
    contents: Option<Vec<(std::path::PathBuf, Vec<u32>)>>,
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

    /// The file that holds programme O`number`: one named after it (`O1234`, `o1234.nc`, any
    /// extension, any case, leading zeros or not), else one whose text holds it.
    pub fn find(&mut self, number: u32, reader: &LineReader) -> Option<std::path::PathBuf> {
        let named = |p: &std::path::PathBuf| {
            let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("");
            let digits = stem.strip_prefix('O').or_else(|| stem.strip_prefix('o'));
            digits.is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()) && d.parse::<u32>().ok() == Some(number))
        };
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
    /// Which seek these lines follow (lines of an earlier one are dropped).
    generation: u32,
    /// The text ends after these lines.
    end: bool,
}

impl Batch {
    fn clear(&mut self) {
        self.text.clear();
        self.ranges.clear();
        self.read.clear();
        self.end = false;
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

/// What the interpreting thread tells the reading one: read `file` (opening `path` the first
/// time) from byte `offset`, the first line numbered `line`.
struct Seek {
    generation: u32,
    file: u16,
    path: Option<std::path::PathBuf>,
    offset: u64,
    line: u32,
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
/// and, for a line of another file, that file's name. Jumps (subprogramme calls and returns)
/// re-read the input from an earlier place, or a file of `library`. Stops reading when the
/// programme wants no more (an alarm in a run, the end of the text).
pub fn drive(
    input: Box<dyn Text>,
    library: &mut Library,
    program: &mut Program,
    on_event: &mut dyn FnMut(&Event, &[u8], FileName) -> io::Result<()>,
) -> io::Result<()> {
    let reader = program.line_reader();
    let thread_reader = reader.clone();
    let (full_tx, full_rx) = mpsc::sync_channel::<io::Result<Batch>>(BATCHES_IN_FLIGHT);
    let (empty_tx, empty_rx) = mpsc::channel::<Batch>();
    let (seek_tx, seek_rx) = mpsc::channel::<Seek>();
    let reading = std::thread::Builder::new()
        .name("ncsight-read".into())
        .spawn(move || read_ahead(input, &thread_reader, &full_tx, &empty_rx, &seek_rx))?;
    let mut pending: io::Result<()> = Ok(());
    let mut stopped = false;
    // The number of the line being fed (the reader counts the same way), and the text of the
    // last line fed once its batch is gone (for what the end of the input says about it).
    let mut line_no = 0u32;
    let mut last_text = Vec::new();
    // The seek the batches must follow, the file being read and the names of the files opened.
    let mut generation = 0u32;
    let mut file = 0u16;
    let mut names: Vec<String> = vec![String::new()];
    let mut deliver = |e: Event, text: &[u8], names: &[String], pending: &mut io::Result<()>| {
        let name = match &e {
            Event::Diagnostic(d) if d.span.file > 0 => names.get(d.span.file as usize).map(String::as_str),
            Event::Record(r) if r.span.file > 0 => names.get(r.span.file as usize).map(String::as_str),
            _ => None,
        };
        if pending.is_ok() {
            *pending = on_event(&e, text, name);
        }
    };
    // Where the run asks to read next: the reading thread is told, and lines of the old place
    // still on their way are dropped.
    let mut follow = |request: Request, program: &mut Program, names: &mut Vec<String>, generation: &mut u32, file: &mut u16, line_no: &mut u32, pending: &mut io::Result<()>, deliver: &mut dyn FnMut(Event, &[u8], &[String], &mut io::Result<()>)| -> bool {
        let mut request = Some(request);
        while let Some(r) = request.take() {
            match r {
                Request::Seek(p) => {
                    *generation += 1;
                    let path = (p.file as usize >= names.len()).then(|| std::path::PathBuf::from(program.file_name(p.file)));
                    if let Some(path) = &path {
                        names.resize(p.file as usize + 1, String::new());
                        names[p.file as usize] = path.display().to_string();
                    }
                    *file = p.file;
                    *line_no = p.line.wrapping_sub(1);
                    if seek_tx.send(Seek { generation: *generation, file: p.file, path, offset: p.offset, line: p.line }).is_err() {
                        return false;
                    }
                }
                Request::Find { number } => match library.find(number, &reader) {
                    Some(path) => {
                        program.open_file(path.display().to_string());
                        request = program.take_request();
                    }
                    None => {
                        let names_now = names.clone();
                        program.no_file(&mut |e| deliver(e, b"", &names_now, pending));
                        request = program.take_request();
                    }
                },
            }
        }
        true
    };
    'batches: for batch in full_rx.iter() {
        let mut batch = batch?;
        if batch.generation != generation {
            batch.clear();
            let _ = empty_tx.send(batch);
            continue;
        }
        let mut jumped = false;
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
            let here = (line_no, file);
            program.feed_from(&batch.read, i, &mut |e| {
                // A diagnostic about an earlier line (a cycle that ends here) gets that line's
                // text while the line is still in this batch, none once it is gone.
                let text = match &e {
                    Event::Diagnostic(d) if d.span.file != here.1 => &b""[..],
                    Event::Diagnostic(d) if d.span.line != here.0 => {
                        let back = here.0.wrapping_sub(d.span.line) as usize;
                        match i.checked_sub(back) {
                            Some(k) if d.span.line < here.0 => &text[ranges[k].clone()],
                            _ => &b""[..],
                        }
                    }
                    _ => line,
                };
                deliver(e, text, &names, &mut pending);
            });
            pending.as_ref().map_err(|e| io::Error::new(e.kind(), e.to_string()))?;
            if let Some(r) = program.take_request() {
                last_text.clear();
                last_text.extend_from_slice(line);
                if !follow(r, program, &mut names, &mut generation, &mut file, &mut line_no, &mut pending, &mut deliver) {
                    break 'batches;
                }
                jumped = true;
                break;
            }
        }
        if !jumped {
            if let Some(r) = batch.ranges.last() {
                last_text.clear();
                last_text.extend_from_slice(&batch.text[r.clone()]);
            }
        }
        let end = batch.end && !jumped;
        batch.clear();
        // The reader may have ended already; then the batch is simply dropped.
        let _ = empty_tx.send(batch);
        if !program.wants_more() {
            stopped = true;
            break;
        }
        if end {
            let names_now = names.clone();
            let r = program.end_of_text(&mut |e| {
                let text = match &e {
                    Event::Diagnostic(d) if d.span.line == line_no => &last_text[..],
                    _ => &b""[..],
                };
                deliver(e, text, &names_now, &mut pending)
            });
            match r {
                Some(r) => {
                    if !follow(r, program, &mut names, &mut generation, &mut file, &mut line_no, &mut pending, &mut deliver) {
                        break;
                    }
                }
                None => {
                    drop(seek_tx);
                    drop(full_rx);
                    if let Err(p) = reading.join() {
                        std::panic::resume_unwind(p);
                    }
                    return pending;
                }
            }
        }
    }
    drop(full_rx);
    drop(seek_tx);
    let _ = stopped;
    // The reader ends at its next send or wait (the channels are closed); it is not waited
    // for, as it may be waiting for input that never comes (a terminal, a pipe left open).
    let names_now = names.clone();
    let mut request = program.end_of_text(&mut |e| {
        let text = match &e {
            Event::Diagnostic(d) if d.span.line == line_no => &last_text[..],
            _ => &b""[..],
        };
        deliver(e, text, &names_now, &mut pending)
    });
    // Nothing more is read: a run that still asks to read elsewhere ends here.
    while request.is_some() {
        request = program.end_of_text(&mut |e| deliver(e, b"", &names_now, &mut pending));
    }
    pending
}

/// The reading thread: lines into batches, until the input ends or nobody listens; at the end
/// of a text it waits for a seek (a jump back, a subprogramme in another file).
fn read_ahead(
    input: Box<dyn Text>,
    reader: &LineReader,
    full: &mpsc::SyncSender<io::Result<Batch>>,
    empty: &mpsc::Receiver<Batch>,
    seeks: &mpsc::Receiver<Seek>,
) {
    let mut texts: Vec<Option<Box<dyn Text>>> = vec![Some(input)];
    let mut current = 0usize;
    let mut generation = 0u32;
    let mut batch = Batch::default();
    let mut line_no = 0u32;
    // Where the line being gathered starts in the batch text, how long it is in the input; the
    // rest of an over-long line is being skipped.
    let mut start = 0usize;
    let mut line_bytes = 0u64;
    let mut skipping = false;
    let mut at_end = false;
    loop {
        // A seek: the lines gathered for the old place are dropped.
        let seek = if at_end { seeks.recv().ok() } else { seeks.try_recv().ok() };
        if at_end && seek.is_none() {
            return;
        }
        if let Some(s) = seek {
            // Only the latest seek counts.
            let mut s = s;
            while let Ok(later) = seeks.try_recv() {
                s = later;
            }
            generation = s.generation;
            batch.clear();
            batch.generation = generation;
            (start, line_bytes, skipping, at_end) = (0, 0, false, false);
            line_no = s.line.wrapping_sub(1);
            let i = s.file as usize;
            if texts.len() <= i {
                texts.resize_with(i + 1, || None);
            }
            if texts[i].is_none() {
                if let Some(path) = &s.path {
                    match std::fs::File::open(path) {
                        Ok(f) => texts[i] = Some(Box::new(io::BufReader::with_capacity(1 << 16, f))),
                        Err(e) => {
                            let _ = full.send(Err(io::Error::new(e.kind(), ReadFailure(io::Error::new(e.kind(), format!("{}: {e}", path.display()))))));
                            return;
                        }
                    }
                }
            }
            current = i;
            let result = match texts[i].as_mut() {
                Some(t) => t.seek_to(s.offset),
                None => Err(io::Error::new(io::ErrorKind::NotFound, "no such file")),
            };
            if let Err(e) = result {
                let _ = full.send(Err(io::Error::new(e.kind(), ReadFailure(e))));
                return;
            }
        }
        let Some(input) = texts[current].as_mut() else { return };
        let buf = match input.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => {
                // The lines read before the error are interpreted first.
                if !batch.ranges.is_empty() {
                    batch.text.truncate(start);
                    let next = Batch { generation, ..Batch::default() };
                    let _ = full.send(Ok(std::mem::replace(&mut batch, next)));
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
            batch.end = true;
            let mut next = empty.try_recv().unwrap_or_default();
            next.clear();
            next.generation = generation;
            if full.send(Ok(std::mem::replace(&mut batch, next))).is_err() {
                return;
            }
            (start, line_bytes, skipping, at_end) = (0, 0, false, true);
            continue;
        }
        let (piece, complete) = match buf.iter().position(|&b| b == b'\n') {
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
            if complete || batch.text.len() - start == MAX_KEPT_LINE_BYTES {
                if complete {
                    line_no = line_no.wrapping_add(1);
                    batch.read_line(reader, line_no, start, line_bytes);
                    line_bytes = 0;
                }
                skipping = !complete;
                if complete {
                    start = batch.text.len();
                }
            }
        } else if complete {
            // The end of an over-long line: its start is read now, with its whole length.
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
            next.generation = generation;
            next.text.extend_from_slice(&batch.text[start..]);
            batch.text.truncate(start);
            if full.send(Ok(std::mem::replace(&mut batch, next))).is_err() {
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
        drive(Box::new(Stream(input)), &mut Library::default(), &mut p, &mut |e, text, _| {
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
            drive(Box::new(io::Cursor::new(text.clone().into_bytes())), &mut Library::default(), &mut p, &mut |e, _, _| {
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
        let r = drive(Box::new(Stream(Box::new(io::BufReader::new(Broken(Some(b"G0 X1. Q5\nG0 X2".to_vec())))))), &mut Library::default(), &mut p, &mut |e, _, _| {
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
        drive(Box::new(io::Cursor::new(text.as_bytes().to_vec())), &mut Library::default(), &mut p, &mut |e, t, _| {
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
