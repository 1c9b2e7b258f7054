//! A diagnostics list sent as the change from the list sent before: after
//! a keystroke most of a long program's diagnostics are the same (their
//! line and column too), so only the entries between the unchanged head
//! and tail are written and sent, with every entry's offsets.

use std::hash::Hasher;

use super::keys::{KeyHasher, combine, js_key};
use crate::message::Lang;
use crate::plan::Plan;

/// The key of each diagnostic of `plan` by what a list shows of it:
/// severity, code, message (template and arguments), line and column of
/// both ends and the call chain; not its byte offsets, which a keystroke
/// above it moves.
pub fn entry_keys(plan: &Plan) -> Vec<u64> {
    plan.diagnostics
        .iter()
        .map(|d| {
            let mut h = KeyHasher::default();
            h.write_u8(d.severity as u8);
            h.write(d.code.as_str().as_bytes());
            h.write_u64(d.message_key());
            for n in [d.line, d.column, d.end_line, d.end_column] {
                h.write_u32(n);
            }
            d.via.iter().for_each(|&l| h.write_u32(l));
            h.write_usize(d.via.len());
            h.write_u32(d.repeats);
            h.finish()
        })
        .collect()
}

/// The key of a whole list of entries with keys `keys`, in `lang`.
pub fn list_key(keys: &[u64], lang: Lang) -> f64 {
    let mut h = KeyHasher::default();
    h.write(lang.name().as_bytes());
    h.write_u64(combine(keys));
    js_key(h.finish())
}

/// A change of a list: `remove` entries from `at` replaced by `insert` new ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Splice {
    /// Where the change starts (the length of the unchanged head).
    pub at: usize,
    /// How many entries of the old list it removes.
    pub remove: usize,
    /// How many entries of the new list it puts in their place.
    pub insert: usize,
}

/// The change from a list of entry keys `old` to `new`: the smallest middle
/// between their common head and common tail.
pub fn splice(old: &[u64], new: &[u64]) -> Splice {
    let head = old.iter().zip(new).take_while(|(a, b)| a == b).count();
    let room = old.len().min(new.len()) - head;
    let tail = old.iter().rev().zip(new.iter().rev()).take(room).take_while(|(a, b)| a == b).count();
    Splice { at: head, remove: old.len() - head - tail, insert: new.len() - head - tail }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Settings;

    #[test]
    fn the_change_is_the_middle_between_the_common_head_and_tail() {
        assert_eq!(splice(&[1, 2, 3, 4], &[1, 2, 3, 4]), Splice { at: 4, remove: 0, insert: 0 });
        assert_eq!(splice(&[1, 2, 3, 4], &[1, 9, 3, 4]), Splice { at: 1, remove: 1, insert: 1 });
        assert_eq!(splice(&[1, 2, 3, 4], &[1, 2, 7, 8, 3, 4]), Splice { at: 2, remove: 0, insert: 2 });
        assert_eq!(splice(&[1, 2, 3, 4], &[1, 4]), Splice { at: 1, remove: 2, insert: 0 });
        // Repeated entries: the head is not counted again as tail.
        assert_eq!(splice(&[5, 5], &[5, 5, 5]), Splice { at: 2, remove: 0, insert: 1 });
        assert_eq!(splice(&[], &[1]), Splice { at: 0, remove: 0, insert: 1 });
        assert_eq!(splice(&[1], &[]), Splice { at: 0, remove: 1, insert: 0 });
    }

    #[test]
    fn a_digit_typed_in_a_pass_changes_only_that_threads_entries() {
        // Two threads of five passes each (M24×2: the table's five infeeds,
        // then the same thread again): each has the lead-in warnings and the
        // infeed note that quotes its programmed infeeds.
        let thread = "X23.1\nG32 Z13 F2\nG00 X30\nZ70\nX22.5\nG32 Z13 F2\nG00 X30\nZ70\nX21.9\nG32 Z13 F2\nG00 X30\nZ70\n\
                      X21.5\nG32 Z13 F2\nG00 X30\nZ70\nX21.4\nG32 Z13 F2\nG00 X30\nZ70\n";
        let text = format!("G50 X100 Z100\nS300 M03 T0101\nG00 X30 Z70\n{thread}G00 X40\nG00 X30 Z70\n{thread}M30\n");
        let s = Settings::new(crate::Dialect::Gsk980tdc);
        let a = crate::plan(&text, &s);
        let b = crate::plan(&text.replacen("X22.5", "X22.55", 1), &s);
        let (ka, kb) = (entry_keys(&a), entry_keys(&b));
        assert_eq!(ka.len(), b.diagnostics.len());
        let c = splice(&ka, &kb);
        // Only entries of the first thread change (on its first line, before the second thread's).
        let second = b.diagnostics.iter().position(|d| d.line > 24).expect("the second thread's entries");
        assert!(c.at + c.insert <= second && c.insert > 0, "{c:?} against the second thread at {second}");
        assert_eq!(ka[ka.len() - (ka.len() - c.at - c.remove)..], kb[kb.len() - (kb.len() - c.at - c.insert)..]);
        assert_ne!(list_key(&ka, Lang::En), list_key(&kb, Lang::En));
        assert_ne!(list_key(&kb, Lang::En), list_key(&kb, Lang::Zh));
        // A comment typed above moves every offset but no line or column: nothing to send.
        let c2 = crate::plan(&text.replacen("S300", "S300 (spindle)", 1), &s);
        assert_eq!(entry_keys(&c2), ka);
    }
}
