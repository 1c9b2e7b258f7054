//! What a stretch of reading depended on: the byte ranges of the lines it
//! read and whether it looked a label up. The planner keeps one per stretch
//! between two snapshots, to tell whether an edit elsewhere in the text can
//! change what the stretch did.

use crate::span::Shift;

/// The lines read in a stretch of reading (merged byte ranges) and whether
/// a jump or call looked a label up.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Reads {
    /// Byte ranges `[start, end)` read, in the order first read.
    pub runs: Vec<(usize, usize)>,
    /// Whether a program, sequence number, loop end or o-word was looked up.
    pub looked: bool,
}

impl Reads {
    /// Notes that the line `[start, end)` was read.
    pub fn read(&mut self, start: usize, end: usize) {
        if let Some(last) = self.runs.last_mut() {
            if last.1 == start {
                last.1 = end;
                return;
            }
        }
        // A line read again (a loop, a subprogram called again) is noted once.
        if self.runs.iter().any(|&(a, b)| a <= start && end <= b) {
            return;
        }
        self.runs.push((start, end));
    }

    /// Whether a line read touches the bytes an edit replaced, `[from, to)`
    /// of the old text (an insertion, `from == to`, touches the line it is
    /// made in).
    pub fn touches(&self, from: usize, to: usize) -> bool {
        let to = to.max(from + 1);
        self.runs.iter().any(|&(a, b)| a < to && b > from)
    }

    /// Makes the reads those of a text edited as `s` says.
    pub fn shift(&mut self, s: Shift) {
        self.runs.iter_mut().for_each(|r| *r = (s.pos(r.0), s.pos(r.1)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_merge_and_touch() {
        let mut r = Reads::default();
        r.read(0, 10);
        r.read(10, 20);
        r.read(100, 110);
        r.read(0, 10);
        r.read(100, 110);
        assert_eq!(r.runs, vec![(0, 20), (100, 110)]);
        assert!(r.touches(15, 16));
        assert!(r.touches(20 - 1, 30));
        assert!(!r.touches(20, 30));
        assert!(r.touches(105, 105));
        assert!(!r.touches(110, 110));
        r.shift(Shift { at: 50, by: 5 });
        assert_eq!(r.runs, vec![(0, 20), (105, 115)]);
    }
}
