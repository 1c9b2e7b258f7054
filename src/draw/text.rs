//! Text widths without a font engine, and the wrapping of long notes.

/// Advances of the printable ASCII characters (space to `~`) of a
/// sans-serif (DejaVu Sans, the widest of the common ones) at 12 px, in
/// hundredths of a pixel.
const ASCII: [u16; 95] = [
    381, 481, 552, 1005, 763, 1140, 936, 330, 468, 468, 600, 1005, 381, 433, 381, 404, //
    763, 763, 763, 763, 763, 763, 763, 763, 763, 763, 404, 404, 1005, 1005, 1005, 637, //
    1200, 821, 823, 838, 924, 758, 690, 930, 902, 354, 354, 787, 669, 1035, 898, 945, //
    724, 945, 834, 762, 733, 878, 821, 1187, 822, 733, 822, 468, 404, 468, 1005, 600, //
    600, 735, 762, 660, 762, 738, 422, 762, 761, 333, 333, 695, 333, 1169, 761, 734, //
    762, 762, 493, 625, 471, 761, 710, 981, 710, 710, 630, 763, 404, 763, 1005,
];

/// The advance of `c` at 12 px: the table for ASCII, the symbols the labels
/// use, a full em for CJK and other wide characters (U+2E80 and above),
/// 0.6 em for the rest.
fn advance(c: char) -> f64 {
    let u = c as u32;
    if (0x20..0x7f).contains(&u) {
        return f64::from(ASCII[(u - 0x20) as usize]) / 100.0;
    }
    match c {
        'Ø' | 'ø' => 9.45,
        'δ' | 'θ' => 7.34,
        'Δ' => 8.21,
        '·' => 3.81,
        '°' => 6.0,
        '×' | '−' => 10.05,
        '–' => 6.0,
        '…' => 12.0,
        c if c >= '\u{2E80}' => 12.0,
        _ => 7.2,
    }
}

/// Estimated width of text `s` at `font_size` px (see [`advance`]).
pub fn measure(s: &str, font_size: f64) -> f64 {
    s.chars().map(advance).sum::<f64>() * font_size / 12.0
}

/// Whether a line may break after `c` when the next character is not one of these.
fn breaks_after(c: char) -> bool {
    c.is_whitespace() || matches!(c, ':' | '：' | ',' | '，' | '、')
}

/// A CJK character a line may break beside (not its punctuation).
fn cjk(c: char) -> bool {
    c >= '\u{2E80}' && !matches!(c, '：' | '，' | '、' | '（' | '）' | '(' | ')')
}

/// `text` cut where a line may break: after a space, a colon or a comma,
/// before a parenthesis, between two CJK characters; never inside parentheses.
fn pieces(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut piece = String::new();
    let mut depth = 0usize;
    for (k, &ch) in chars.iter().enumerate() {
        let next = chars.get(k + 1).copied();
        piece.push(ch);
        if matches!(ch, '(' | '（') {
            depth += 1;
        }
        if matches!(ch, ')' | '）') {
            depth = depth.saturating_sub(1);
        }
        let cut = match next {
            None => true,
            Some(n) => {
                let after = breaks_after(ch) && !breaks_after(n);
                depth == 0 && (after || matches!(n, '(' | '（') || (cjk(ch) && (cjk(n) || n.is_whitespace())))
            }
        };
        if cut {
            out.push(std::mem::take(&mut piece));
        }
    }
    out
}

/// `text` broken into lines at most `max` px wide (by `width`) where a line
/// may break (see [`pieces`]); a piece wider than `max` keeps a line of its
/// own. `None` when it fits on one line.
pub fn wrap(text: &str, max: f64, width: impl Fn(&str) -> f64) -> Option<Vec<String>> {
    if width(text) <= max || max.is_nan() {
        return None;
    }
    let mut lines = Vec::new();
    let mut line = String::new();
    for p in pieces(text) {
        let joined = format!("{line}{p}");
        if !line.is_empty() && width(joined.trim_end()) > max {
            lines.push(line.trim_end().to_string());
            line = p.trim_start().to_string();
        } else {
            line = joined;
        }
    }
    if !line.trim().is_empty() {
        lines.push(line.trim_end().to_string());
    }
    (lines.len() > 1).then_some(lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widths_follow_the_table() {
        assert!((measure("Ph 2", 12.0) - (7.24 + 7.61 + 3.81 + 7.63)).abs() < 1e-9);
        assert_eq!(measure("导程", 12.0), 24.0);
        assert_eq!(measure("ab", 24.0), 2.0 * measure("ab", 12.0));
    }

    #[test]
    fn long_notes_break_where_they_may() {
        let w = |s: &str| measure(s, 12.0);
        let note = "one start and every n-th pass drawn (1/starts n/all): 1/2 3/12";
        let lines = wrap(note, 160.0, w).expect("wrapped");
        assert!(lines.len() >= 2 && lines.iter().all(|l| w(l) <= 160.0 || !l.contains(' ')), "{lines:?}");
        assert!(lines.iter().any(|l| l.contains("(1/starts n/all):")), "no break inside parentheses: {lines:?}");
        assert_eq!(lines.join(" "), note);
        let zh = "只画一头、每隔 n 次走刀画一次(1/头数 n/总数)：1/2 3/12";
        let lines = wrap(zh, 160.0, w).expect("wrapped");
        assert!(lines.len() >= 2, "{lines:?}");
        assert_eq!(wrap("short", 160.0, w), None);
    }
}
