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
}
