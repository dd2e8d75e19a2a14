//! The block source's memory of where things are: the place of every block a jump may go to,
//! the programmes seen (their O blocks), the subprogramme calls in progress, and the search a
//! jump makes when its target has not been read yet.
//!
//! The text itself stays with the driver (a file re-read from byte offsets, a slice): a jump is
//! a request to feed lines from another place, so a programme without backward jumps streams
//! as before and memory holds places, never text.

use crate::source::Span;
use std::collections::HashMap;

/// Where a block starts: its file, the byte offset and number of its line, and its place among
/// the blocks of the line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Place {
    pub file: u16,
    pub offset: u64,
    pub line: u32,
    pub block: u16,
}

impl Place {
    /// The start of a file.
    pub fn start_of(file: u16) -> Place {
        Place { file, offset: 0, line: 1, block: 0 }
    }
}

/// What a run asks its driver for when it must read elsewhere.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Feed the lines of `file` from byte `offset` on, the first of them numbered `line` (its
    /// blocks before `block` are passed over by the run).
    Seek(Place),
    /// Programme O`number` is in no file read so far: the driver opens one that holds it
    /// ([`super::Program::open_file`]) or says there is none ([`super::Program::no_file`]).
    Find { number: u32 },
}

/// At most this many programmes' places are kept (far more than any controller's memory holds);
/// past it a programme is found by reading again.
const MAX_PROGRAMS_INDEXED: usize = 100_000;
/// Executed stretches of a file kept apart, at most (then merged into one).
const MAX_READ_INTERVALS: usize = 4096;
/// Sequence numbers found by searches, kept to find them at once the next time; the table is
/// emptied when full, so memory stays bounded whatever a programme jumps to.
const MAX_SEQUENCES_INDEXED: usize = 65_536;

/// A subprogramme call in progress.
#[derive(Debug, Clone, Copy)]
pub(super) struct Frame {
    pub number: u32,
    /// The place of its O block (known once found).
    pub start: Option<Place>,
    /// Where each run of a call by sequence number (`M98 Q`) begins: its N block, in the
    /// calling programme (known once found).
    pub entry: Option<Place>,
    /// A G70 running the programme's blocks N ns to N nf: it ends after N nf.
    pub finishing: Option<crate::interp::FinishRequest>,
    /// The block after the calling one.
    pub back: Place,
    /// Runs left after this one (M98 P3... calls three times).
    pub remaining: u32,
    /// The calling block.
    pub call: Span,
    /// A G65 call: it has its own level of local variables.
    pub macro_call: bool,
    /// Made by a code the parameters set up (inside it, such codes are ordinary ones).
    pub builder: bool,
}

/// A WHILE loop being run: its DO number, the place of its WHILE block, the call depth.
#[derive(Debug, Clone, Copy)]
pub(super) struct Loop {
    pub label: u32,
    pub place: Place,
    pub depth: usize,
}

/// What a search looks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Target {
    /// O`n`: a called programme, or the main one named by the caller.
    Program(u32),
    /// N`n` in the running programme (M99 P).
    Sequence(u32),
    /// N`n` in the running programme (GOTO).
    Goto(u32),
    /// N`n` in the running programme, called by `M98 Q`.
    CallSequence(u32),
    /// The `END m` of a WHILE whose condition does not hold.
    LoopEnd(u32),
    /// The `END m` of a WHILE whose body is about to run for the first time: read ahead only
    /// to be sure it is there (alarm 124 before the body runs, as the controller's search for
    /// END finds it), then back to the body.
    LoopEndAhead(u32),
}

/// A jump whose target has not been read yet: the blocks are read, not executed, until it is
/// found. A controller searches forward, then from the top (docs/reference/macro.md section 6).
#[derive(Debug, Clone, Copy)]
pub(super) struct Search {
    pub target: Target,
    /// Where it began: met again after going round, the target is not there.
    pub from: Place,
    /// Where its scope starts (the file for a programme, the programme for a sequence number).
    pub scope: Place,
    /// It has gone back to the start of its scope.
    pub wrapped: bool,
    /// It reads its file once from the start, without going round (a file the driver opened
    /// for it, the main programme the caller named).
    pub once: bool,
    /// The block that asked for the jump.
    pub asked_by: Span,
    /// Where the run goes on if the target is not found and the run does not stop there (a
    /// check, a skipped call).
    pub resume: Option<Place>,
}

/// The calls, the index and the search of one run.
#[derive(Debug, Default)]
pub(super) struct Calls {
    pub frames: Vec<Frame>,
    /// WHILE loops being run, innermost last.
    pub loops: Vec<Loop>,
    /// The O number of the main programme (the first in the file, or the one the caller named)
    /// and where it starts.
    pub main: Option<(Option<u32>, Place)>,
    /// (file, number) -> the place of its O block.
    programs: HashMap<(u16, u32), Place>,
    /// (programme start, N) -> the place of its block.
    sequences: HashMap<(u16, u64, u32), Place>,
    pub search: Option<Search>,
    /// The driver's next move, when the run must read elsewhere.
    pub request: Option<Request>,
    /// Files the driver opened, by number (file 0 is the one the run began with).
    pub files: Vec<String>,
    /// The stretches of each file executed so far: a block in one runs again.
    read: Vec<Vec<(u64, u64)>>,
    /// How far each file has been read in any way (executed or searched): a search that reads
    /// a line again counts for the runaway guard.
    seen_to: Vec<u64>,
    /// Blocks executed again after a jump back (the runaway guard counts these).
    pub repeated_blocks: u64,
}

impl Calls {
    /// Calls begun (a call whose programme is still being looked for does not count).
    pub fn depth(&self) -> usize {
        self.frames.iter().filter(|f| f.start.is_some()).count()
    }

    /// The programme running now and where it starts: the innermost call's, or the main one.
    /// Calls in progress of one kind (G65 macro calls, or M98 and M98 Q calls), which nest
    /// separately; a G70 running the programme's blocks is no call.
    pub fn nesting(&self, macro_call: bool) -> usize {
        self.frames.iter().filter(|f| f.start.is_some() && f.macro_call == macro_call && f.finishing.is_none()).count()
    }

    pub fn running(&self) -> Option<(Option<u32>, Place)> {
        match self.frames.last() {
            Some(f) => f.start.map(|s| (Some(f.number), s)),
            None => self.main,
        }
    }

    pub fn note_program(&mut self, number: u32, place: Place) {
        if self.programs.len() < MAX_PROGRAMS_INDEXED {
            self.programs.entry((place.file, number)).or_insert(place);
        }
    }

    /// Where programme O`number` was seen: in `file` first, then in any file.
    pub fn program(&self, file: u16, number: u32) -> Option<Place> {
        self.programs.get(&(file, number)).copied().or_else(|| {
            // Few files are ever open: the other files' entries are looked for one by one.
            (0..self.files.len().max(1) as u16).filter(|f| *f != file).find_map(|f| self.programs.get(&(f, number)).copied())
        })
    }

    pub fn note_sequence(&mut self, scope: Place, number: u32, place: Place) {
        if self.sequences.len() >= MAX_SEQUENCES_INDEXED {
            self.sequences.clear();
        }
        self.sequences.insert((scope.file, scope.offset, number), place);
    }

    pub fn sequence(&self, scope: Place, number: u32) -> Option<Place> {
        self.sequences.get(&(scope.file, scope.offset, number)).copied()
    }

    /// Whether a line of `file` at `offset` has been executed before (a jump came back).
    pub fn was_read(&self, file: u16, offset: u64) -> bool {
        let Some(v) = self.read.get(file as usize) else { return false };
        let k = v.partition_point(|(a, _)| *a <= offset);
        k > 0 && offset < v[k - 1].1
    }

    /// The line of `file` from `start` to `end` has been executed: the executed stretches of
    /// each file are kept as sorted, merged intervals (a call forward to a subprogramme after
    /// M30 does not mark the rest of the main programme as run). Bounded: past
    /// [`MAX_READ_INTERVALS`] stretches they are merged into one (over-counting the guard a
    /// little, never missing a loop).
    pub fn mark_read(&mut self, file: u16, start: u64, end: u64) {
        let i = file as usize;
        if self.read.len() <= i {
            self.read.resize_with(i + 1, Vec::new);
        }
        let v = &mut self.read[i];
        // The common case: the next line after the last stretch.
        if let Some(last) = v.last_mut() {
            if last.0 <= start && start <= last.1 {
                last.1 = last.1.max(end);
                return;
            }
        }
        let k = v.partition_point(|(a, _)| *a <= start);
        if k > 0 && start <= v[k - 1].1 {
            v[k - 1].1 = v[k - 1].1.max(end);
        } else {
            v.insert(k, (start, end));
        }
        // Merge what the grown stretch now reaches.
        let j = if k > 0 && v[k - 1].0 <= start { k - 1 } else { k };
        while j + 1 < v.len() && v[j + 1].0 <= v[j].1 {
            v[j].1 = v[j].1.max(v[j + 1].1);
            v.remove(j + 1);
        }
        if v.len() > MAX_READ_INTERVALS {
            let whole = (v[0].0, v[v.len() - 1].1);
            v.clear();
            v.push(whole);
        }
    }

    /// A line of `file` from `start` to `end` is read: whether it had been read before.
    pub fn seen(&mut self, file: u16, start: u64, end: u64) -> bool {
        let i = file as usize;
        if self.seen_to.len() <= i {
            self.seen_to.resize(i + 1, 0);
        }
        let before = start < self.seen_to[i];
        self.seen_to[i] = self.seen_to[i].max(end);
        before
    }

    /// The call chain of a block at the current depth, outermost first.
    pub fn chain(&self) -> Vec<Span> {
        // A call whose programme is still being looked for has not begun.
        self.frames.iter().filter(|f| f.start.is_some()).map(|f| f.call).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn executed_stretches_merge() {
        let mut c = Calls::default();
        c.mark_read(0, 0, 10);
        c.mark_read(0, 10, 20);
        c.mark_read(0, 100, 120);
        assert!(c.was_read(0, 5) && c.was_read(0, 19) && !c.was_read(0, 20) && !c.was_read(0, 50) && c.was_read(0, 110));
        // A stretch between the two joins them.
        c.mark_read(0, 20, 100);
        assert_eq!(c.read[0], vec![(0, 120)]);
        c.mark_read(0, 200, 210);
        c.mark_read(0, 150, 160);
        assert_eq!(c.read[0], vec![(0, 120), (150, 160), (200, 210)]);
        assert!(!c.was_read(1, 0) && !c.was_read(0, 170));
    }
}
