//! Comments of a program's source lines, read where a step needs what a
//! comment says about a thread: its designation (`(M48x2-6g)`, the shop
//! step) or its crest (`(crest X68.)`, the advice step). A comment is `( … )`
//! or the text after `;`, full-width characters folded to ASCII. Most lines
//! have none and are passed over unread.

use crate::span::Span;

/// Whether a source line may hold a comment: a `(` (or
/// its full-width form) or text after a `;` (GSK and Renhe end every block
/// with one). Most lines have neither and are passed over unread.
pub fn may_comment(line: &str) -> bool {
    let b = line.as_bytes();
    // Full-width `（` is EF BC 88 and `；` EF BC 9B in UTF-8.
    let wide = |tail: u8| b.windows(3).position(|w| w == [0xEF, 0xBC, tail]);
    if memchr::memchr(b'(', b).is_some() || (memchr::memchr(0xEF, b).is_some() && wide(0x88).is_some()) {
        return true;
    }
    let semi = match (memchr::memchr(b';', b), memchr::memchr(0xEF, b).and_then(|_| wide(0x9B))) {
        (Some(a), Some(w)) if w < a => Some(w + 3),
        (Some(a), _) => Some(a + 1),
        (None, Some(w)) => Some(w + 3),
        (None, None) => None,
    };
    semi.is_some_and(|i| !line[i..].trim().is_empty())
}

/// The lines of `s`, ended by `\n`, `\r\n` or a lone `\r` (as the line index counts them).
pub fn split_lines(s: &str) -> Vec<&str> {
    let b = s.as_bytes();
    let (mut out, mut start) = (Vec::new(), 0);
    while let Some(k) = memchr::memchr2(b'\n', b'\r', &b[start..]) {
        let i = start + k;
        out.push(&s[start..i]);
        start = if b[i] == b'\r' && b.get(i + 1) == Some(&b'\n') { i + 2 } else { i + 1 };
    }
    out.push(&s[start..]);
    out
}

/// The comments of a source line: `( … )` and what follows `;`, full-width
/// characters folded to ASCII, each cut at 256 bytes.
pub fn comments(line: &str) -> Vec<String> {
    let folded: String = line
        .chars()
        .take(4096)
        .map(|c| match c {
            '\u{FF01}'..='\u{FF5E}' => char::from_u32(c as u32 - 0xFEE0).unwrap_or(c),
            '\u{3000}' => ' ',
            _ => c,
        })
        .collect();
    let mut out = Vec::new();
    let mut open: Option<usize> = None;
    for (i, c) in folded.char_indices() {
        match (c, open) {
            ('(', None) => open = Some(i + 1),
            (')', Some(s)) => {
                out.push(folded[s..i].to_string());
                open = None;
            }
            (';', None) => {
                out.push(folded[i + 1..].to_string());
                break;
            }
            _ => {}
        }
    }
    for c in &mut out {
        if c.len() > 256 {
            let mut end = 256;
            while !c.is_char_boundary(end) {
                end -= 1;
            }
            c.truncate(end);
        }
    }
    out
}

/// The crest a comment states, `crest X68.` (or `crest Z…` for a face
/// thread, `axis`), case aside: the value as written, in program units.
pub fn crest(comment: &str, axis: u8) -> Option<f64> {
    let c = comment.trim_start();
    let word = c.get(..5)?;
    if !word.eq_ignore_ascii_case("crest") {
        return None;
    }
    let rest = c[5..].trim_start();
    let (letter, number) = (rest.as_bytes().first()?, rest.get(1..)?);
    if !letter.eq_ignore_ascii_case(&axis) {
        return None;
    }
    let number = number.trim_start();
    let end = number.find(|ch: char| !(ch.is_ascii_digit() || matches!(ch, '.' | '-' | '+'))).unwrap_or(number.len());
    number[..end].parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The first `Some` of `f(line, comment)` over the comments of lines
/// `first` back to `stop` (1-based, inclusive; `spans` gives each line's
/// byte span in `text`), nearest first, the last comment of a line first.
pub fn find_back<T>(
    text: &str,
    spans: &dyn Fn(u32) -> Span,
    stop: u32,
    first: u32,
    mut f: impl FnMut(u32, &str) -> Option<T>,
) -> Option<T> {
    // The lines from `stop` to `first`, read from the last back (one slice, split at line ends).
    let (from, to) = (spans(stop).start as usize, spans(first).end as usize);
    let region = text.get(from..to.max(from)).unwrap_or("");
    // A comment needs `(` or `;` or their full-width forms (which begin with
    // byte EF): where none is, no line is read (most threads of a program).
    memchr::memchr3(b'(', b';', 0xEF, region.as_bytes())?;
    for (back, line_text) in split_lines(region).into_iter().rev().enumerate() {
        let line = first.saturating_sub(back as u32);
        if may_comment(line_text) {
            for c in comments(line_text).iter().rev() {
                if let Some(found) = f(line, c) {
                    return Some(found);
                }
            }
        }
        // A thread in a subprogram is not named by the comments of the program before it.
        if starts_program(line_text) {
            break;
        }
    }
    None
}

/// The first line [`find_back`] reads between `stop` and `first`: `stop`,
/// or the line that starts the program (or LinuxCNC subroutine) `first` is in.
pub fn window_start(text: &str, spans: &dyn Fn(u32) -> Span, stop: u32, first: u32) -> u32 {
    let (from, to) = (spans(stop).start as usize, spans(first).end as usize);
    let region = text.get(from..to.max(from)).unwrap_or("");
    let lines = split_lines(region);
    for (back, line_text) in lines.iter().rev().enumerate() {
        if starts_program(line_text) {
            return first.saturating_sub(back as u32);
        }
    }
    stop
}

/// Whether a line starts a program (`O1000`, `O1000 (NAME)`) or a LinuxCNC
/// subroutine (`o100 sub`, `o<name> sub`).
pub fn starts_program(line: &str) -> bool {
    let t = line.trim_start();
    let Some(rest) = t.strip_prefix(['O', 'o']) else { return false };
    let (label, after) = if let Some(r) = rest.strip_prefix('<') {
        match r.find('>') {
            Some(k) => (&r[..k], &r[k + 1..]),
            None => return false,
        }
    } else {
        let n = rest.bytes().take_while(u8::is_ascii_digit).count();
        (&rest[..n], &rest[n..])
    };
    if label.is_empty() {
        return false;
    }
    let after = after.trim_start();
    after.is_empty()
        || after.starts_with(['(', ';', '%'])
        || after.get(..3).is_some_and(|w| w.eq_ignore_ascii_case("sub"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_crest_comment() {
        assert_eq!(crest("crest X68.", b'X'), Some(68.0));
        assert_eq!(crest(" CREST x47.25 from the G76 cycle", b'X'), Some(47.25));
        assert_eq!(crest("crest Z-3.5", b'Z'), Some(-3.5));
        assert_eq!(crest("crest Z-3.5", b'X'), None);
        assert_eq!(crest("crest of the thread", b'X'), None);
        assert_eq!(crest("M48x2-6g", b'X'), None);
        assert_eq!(crest("crest X", b'X'), None);
    }

    #[test]
    fn comments_of_a_line() {
        assert_eq!(comments("N20 G00 X58 (M48x2-6g) Z70; note"), vec!["M48x2-6g", " note"]);
        assert_eq!(comments("（Ｍ４８×２－６ｇ）"), vec!["M48×2-6g"]);
        assert!(comments("G00 X10").is_empty());
        assert_eq!(comments("(open").len(), 0);
    }

    /// Comments of every form are found from the line of a thread back, the
    /// nearest first, and not past the start of its program.
    #[test]
    fn comments_found_back() {
        let text = "O1\nG00 X58 ; M30x2\nG00 X60\nG32 Z-20 F2\nO2\n（Ｍ４８×２）\nG00 X60\n(M20x1.5)\nG32 Z-9 F1.5\n";
        let index = crate::span::LineIndex::new(text);
        let spans = |line: u32| {
            let start = index.line_start(line);
            Span::new(start, text[start..].find('\n').map_or(text.len(), |e| start + e))
        };
        let found = |stop, first| find_back(text, &spans, stop, first, |line, c| Some((line, c.trim().to_string())));
        assert_eq!(found(1, 4), Some((2, "M30x2".to_string())));
        assert_eq!(found(1, 9), Some((8, "M20x1.5".to_string())));
        assert_eq!(found(1, 7), Some((6, "M48×2".to_string())));
        assert_eq!(found(6, 7), Some((6, "M48×2".to_string())));
        assert_eq!(found(3, 4), None);
        assert_eq!(found(5, 5), None);
    }

    #[test]
    fn lines_end_as_the_line_index_says() {
        assert_eq!(split_lines("a\nb\r\nc\rd"), ["a", "b", "c", "d"]);
        assert_eq!(split_lines("a\n\nb"), ["a", "", "b"]);
        assert_eq!(split_lines(""), [""]);
    }

    #[test]
    fn lines_without_a_comment_are_passed_over() {
        assert!(!may_comment("N10 G00 X58 Z70;"));
        assert!(!may_comment("N10 G00 X58 Z70;  "));
        assert!(!may_comment("G32 Z13 F2"));
        assert!(may_comment("N10 G00 X58; M48x2-6g"));
        assert!(may_comment("G00 X58 (M48x2-6g)"));
        assert!(may_comment("（Ｍ４８×２－６ｇ）"));
        assert!(may_comment("G00；注释"));
    }
}
