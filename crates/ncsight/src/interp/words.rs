//! The words of one block, by address, with a record of which ones a command took. A word no
//! command takes is an alarm (issue 2, item 3): nothing is skipped silently.

use crate::read::Word;

/// Indices into the block's words, so that the table stays small to move.
#[derive(Debug)]
pub struct Words<'w> {
    all: &'w [Word],
    /// 1 + the index in `all` of each address's word; 0 for none (A-Z, then the comma words
    /// ,A-,Z).
    slots: [u16; 52],
    present: u64,
    used: u64,
}

fn idx(letter: u8) -> usize {
    if letter.is_ascii_lowercase() {
        26 + (letter - b'a') as usize
    } else {
        (letter - b'A') as usize
    }
}

impl<'w> Words<'w> {
    /// An empty table over a block's words.
    pub fn new(all: &'w [Word]) -> Words<'w> {
        Words { all, slots: [0; 52], present: 0, used: 0 }
    }

    fn slot(&self, i: usize) -> Option<&'w Word> {
        let all: &'w [Word] = self.all;
        self.slots[i].checked_sub(1).map(|k| &all[k as usize])
    }

    /// Store the word at `index` of the block; returns the earlier word of the same address if
    /// there was one.
    pub fn insert(&mut self, index: usize) -> Option<&'w Word> {
        let i = idx(self.all[index].letter);
        let old = self.slot(i);
        self.slots[i] = u16::try_from(index + 1).expect("a block holds fewer words than a line has bytes");
        self.present |= 1 << i;
        old
    }

    pub fn has(&self, letter: u8) -> bool {
        self.present & (1 << idx(letter)) != 0
    }

    /// A word of this address is in the block and no command has taken it yet.
    pub fn has_unused(&self, letter: u8) -> bool {
        (self.present & !self.used) & (1 << idx(letter)) != 0
    }

    /// Look at a word without taking it.
    pub fn peek(&self, letter: u8) -> Option<&'w Word> {
        self.slot(idx(letter))
    }

    /// Take a word: it is now used by a command.
    pub fn take(&mut self, letter: u8) -> Option<&'w Word> {
        let i = idx(letter);
        let w = self.slot(i)?;
        self.used |= 1 << i;
        Some(w)
    }

    /// The first word, in the order written, that no command took.
    /// Every word of the block, used or not, in the order written.
    pub fn all(&self) -> &'w [Word] {
        self.all
    }

    pub fn first_unused(&self) -> Option<&'w Word> {
        let unused = self.present & !self.used;
        if unused == 0 {
            return None;
        }
        (0..52).filter(|i| unused & (1 << i) != 0).filter_map(|i| self.slot(i)).min_by_key(|w| w.span.col)
    }
}
