//! Positions as a browser editor counts them. The plan gives byte offsets
//! into the UTF-8 text; JavaScript strings (and so CodeMirror) count UTF-16
//! code units, so a full-width `Ｇ` is three bytes but one unit, and a
//! character outside the Basic Multilingual Plane is four bytes but two.

/// Converts byte offsets into UTF-16 offsets of the same text, in one walk.
/// An offset inside a character maps to that character's start; offsets
/// past the end map to the end.
pub fn utf16_offsets(text: &str, bytes: &[u32]) -> Vec<u32> {
    if text.is_ascii() {
        return bytes.iter().map(|&b| b.min(text.len() as u32)).collect();
    }
    let mut order: Vec<usize> = (0..bytes.len()).collect();
    crate::order::sort_by_key(&mut order, |&i| (bytes[i], i));
    let mut out = vec![0u32; bytes.len()];
    let mut chars = text.char_indices().peekable();
    let mut units = 0u32;
    for i in order {
        let want = bytes[i] as usize;
        while let Some(&(at, c)) = chars.peek() {
            if at + c.len_utf8() > want {
                break;
            }
            units += c.len_utf16() as u32;
            chars.next();
        }
        out[i] = units;
    }
    out
}

/// Replaces UTF-16 units `from..to` of `text` with `inserted`, as a
/// browser editor states a change. Returns false, `text` unchanged, when
/// the range is reversed, runs past the end or cuts a character in two.
/// Work in proportion to `to` at most (none beyond an ASCII check when the
/// text up to `to` is ASCII), and to the text after it for the move.
pub fn replace_utf16(text: &mut String, from: usize, to: usize, inserted: &str) -> bool {
    if from > to {
        return false;
    }
    let (Some(a), Some(b)) = (byte_at(text, from), byte_at(text, to)) else { return false };
    text.replace_range(a..b, inserted);
    true
}

/// The byte offset of UTF-16 offset `units` in `text`: none past the end or
/// inside a character written as two units.
fn byte_at(text: &str, units: usize) -> Option<usize> {
    // An ASCII prefix counts one unit a byte.
    if text.as_bytes().get(..units).is_some_and(<[u8]>::is_ascii) {
        return Some(units);
    }
    let mut n = 0;
    for (at, c) in text.char_indices() {
        if n == units {
            return Some(at);
        }
        n += c.len_utf16();
        if n > units {
            return None;
        }
    }
    (n == units).then_some(text.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn full_width_and_astral_characters() {
        let text = "Ｇ32 X1\n😀Z2";
        // Bytes: Ｇ=0..3, '3'=3, '2'=4, ' '=5, 'X'=6, '1'=7, '\n'=8, 😀=9..13, 'Z'=13.
        let got = utf16_offsets(text, &[0, 3, 6, 9, 13, 14, 99, 1]);
        assert_eq!(got, vec![0, 1, 4, 7, 9, 10, 11, 0]);
    }

    #[test]
    fn ascii_is_identity() {
        assert_eq!(utf16_offsets("G32 Z1", &[0, 4, 6, 10]), vec![0, 4, 6, 6]);
    }

    /// Changes as CodeMirror states them (UTF-16 offsets): typed, deleted
    /// and pasted over ASCII, full-width and astral characters.
    #[test]
    fn editor_changes_replace_the_units_they_name() {
        let edit = |text: &str, from, to, ins| {
            let mut t = text.to_string();
            replace_utf16(&mut t, from, to, ins).then_some(t)
        };
        assert_eq!(edit("G32 Z1\n", 6, 6, "3").as_deref(), Some("G32 Z13\n"));
        assert_eq!(edit("G32 Z13\n", 5, 7, "").as_deref(), Some("G32 Z\n"));
        assert_eq!(edit("G32", 3, 3, "\nX1").as_deref(), Some("G32\nX1"));
        // Ｇ is three bytes, one unit; 😀 four bytes, two units.
        assert_eq!(edit("Ｇ32 X1", 1, 3, "00").as_deref(), Some("Ｇ00 X1"));
        assert_eq!(edit("Ｇ32 X1", 0, 1, "G").as_deref(), Some("G32 X1"));
        assert_eq!(edit("(😀) X1", 1, 3, "ok").as_deref(), Some("(ok) X1"));
        assert_eq!(edit("(😀) X1", 7, 7, "5").as_deref(), Some("(😀) X15"));
        // Refused, the text as it was: inside 😀, past the end, reversed.
        assert_eq!(edit("(😀) X1", 2, 3, ""), None);
        assert_eq!(edit("(😀) X1", 1, 2, ""), None);
        assert_eq!(edit("G32", 2, 4, ""), None);
        assert_eq!(edit("G32", 4, 4, "X"), None);
        assert_eq!(edit("G32", 2, 1, ""), None);
        let mut t = String::from("Ｇ32");
        assert!(!replace_utf16(&mut t, 0, 9, "") && t == "Ｇ32");
    }
}
