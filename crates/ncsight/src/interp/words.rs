//! The words of one block, by address, with a record of which ones a command took. A word no
//! command takes is an alarm (issue 2, item 3): nothing is skipped silently.

use crate::read::Word;

#[derive(Debug, Default)]
pub struct Words {
    slots: [Option<Word>; 26],
    used: u32,
}

fn idx(letter: u8) -> usize {
    (letter - b'A') as usize
}

impl Words {
    /// Store a word; returns the earlier word of the same address if there was one.
    pub fn insert(&mut self, w: Word) -> Option<Word> {
        let i = idx(w.letter);
        let old = self.slots[i];
        self.slots[i] = Some(w);
        old
    }

    pub fn has(&self, letter: u8) -> bool {
        self.slots[idx(letter)].is_some()
    }

    /// Look at a word without taking it.
    pub fn peek(&self, letter: u8) -> Option<Word> {
        self.slots[idx(letter)]
    }

    /// Take a word: it is now used by a command.
    pub fn take(&mut self, letter: u8) -> Option<Word> {
        let i = idx(letter);
        let w = self.slots[i]?;
        self.used |= 1 << i;
        Some(w)
    }

    /// The first word, in the order written, that no command took.
    pub fn first_unused(&self) -> Option<Word> {
        self.slots
            .iter()
            .enumerate()
            .filter(|(i, w)| w.is_some() && self.used & (1 << i) == 0)
            .map(|(_, w)| w.unwrap())
            .min_by_key(|w| w.span.col)
    }
}
