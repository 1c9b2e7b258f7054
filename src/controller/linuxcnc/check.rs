//! LinuxCNC's checks of a block before it runs, in the interpreter's order:
//! the integer words as they are read (H, L), the motion codes that need an
//! axis word (`enhance_block`), then every word against the codes that use
//! it (`check_other_codes`). The messages are the interpreter's own (the
//! installed `librs274`), each after the word it is about.

use super::{Reader, g_word_span};
use crate::args;
use crate::block::{Block, Word};
use crate::message::{self as msg, Arg};

/// Checks `b`, whose motion (×10) is `motion`; false after an alarm.
pub fn block(r: &mut Reader, b: &Block, motion: Option<i64>) -> bool {
    integers(r, b) && axes(r, b) && other_codes(r, b, motion.unwrap_or(-1))
}

/// H and L are read as integers (within 0.0001); L must not be negative.
fn integers(r: &mut Reader, b: &Block) -> bool {
    for w in b.words().iter().filter(|w| matches!(w.letter, b'H' | b'L')) {
        let v = w.value();
        if v - v.floor() > 1e-4 && v.ceil() - v > 1e-4 {
            let what = if w.letter == b'H' { &msg::SPRING_COUNT_H } else { &msg::L_WORD };
            r.diag(&msg::LCNC_NON_INTEGER, w.span, args![word = w, what]);
            return false;
        }
        if w.letter == b'L' && v.round() < 0.0 {
            r.diag(&msg::LCNC_NEGATIVE_L, w.span, args![word = w]);
            return false;
        }
    }
    true
}

/// G33, G33.1 and G76 need an axis word.
fn axes(r: &mut Reader, b: &Block) -> bool {
    for w in b.all(b'G') {
        let code = (w.value() * 10.0).round() as i64;
        if matches!(code, 330 | 331 | 760) && !r.has_axes(b) {
            r.diag(&msg::LCNC_ALL_AXES_MISSING, w.span, args![word = w]);
            return false;
        }
    }
    true
}

/// The words checked, in the interpreter's order, with its message when no code uses one.
const WORDS: [(u8, &str); 11] = [
    (b'$', "$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, G33.1, G76, G95, G96 or G97 to use it"),
    (b'D', "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it"),
    (b'E', "E word with no G70, G76, M66, M67 or M68 to use it"),
    (b'H', "H word with no G43 or G76 to use it"),
    (b'I', "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it"),
    (b'J', "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it"),
    (b'K', "K word with no G2, G3, G33, G33.1, G76, or G87 to use it"),
    (b'L', "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or NURBS code"),
    (
        b'P',
        "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 M65 M66 M98 or user M code to use it",
    ),
    (b'Q', "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that uses it"),
    (b'R', "R word with no g code that uses it"),
];

/// The G codes (×10) and M codes of a block.
struct Codes {
    g: Vec<i64>,
    m: Vec<i64>,
}

impl Codes {
    fn of(b: &Block) -> Codes {
        Codes {
            g: b.all(b'G').map(|w| (w.value() * 10.0).round() as i64).collect(),
            m: b.all(b'M').filter_map(|w| w.num.integer()).collect(),
        }
    }

    fn g(&self, codes: &[i64]) -> bool {
        self.g.iter().any(|c| codes.contains(c))
    }

    fn m(&self, codes: &[i64]) -> bool {
        self.m.iter().any(|c| codes.contains(c))
    }
}

/// Whether a word with `letter` has a code to use it, the block's motion being `mo`.
fn used(letter: u8, mo: i64, c: &Codes) -> bool {
    let cycle = (810..=890).contains(&mo);
    let comp = [410, 411, 420, 421];
    // The lathe profile cycles: rs274 reads D, I, R and Q with the roughing
    // cycles G71/G72 (and their .1/.2 forms), D, E, P and Q with G70, although
    // its D message names only G71 (recorded: words-g70-g72, err-g72-j-word,
    // err-g71-e-word, err-g70-r-word).
    let roughing = c.g(&[710, 711, 712, 720, 721, 722]);
    let finishing = c.g(&[700]);
    match letter {
        b'$' => [330, 331, 760].contains(&mo) || c.m(&[3, 4, 5, 19, 51]) || c.g(&[950, 960, 970]),
        b'D' => c.g(&comp) || c.g(&[960]) || roughing || finishing,
        // G33 takes an E word and ignores it (recorded: g33-e-word).
        b'E' => [760, 330].contains(&mo) || finishing || c.m(&[66, 67, 68]),
        b'H' => mo == 760 || c.g(&[430, 432]),
        b'I' => [20, 30, 50, 51, 331, 760, 870].contains(&mo) || c.g(&[100]) || roughing,
        b'J' => [20, 30, 50, 51, 760, 870].contains(&mo) || c.g(&[100]),
        b'K' => [20, 30, 330, 331, 760, 870].contains(&mo),
        b'L' => cycle || [760, 52, 730].contains(&mo) || c.g(&[100]) || c.g(&comp) || c.m(&[66, 98]),
        b'P' => {
            [20, 30, 50, 52, 760, 820, 860, 880, 890].contains(&mo)
                || c.g(&[40, 100, 640])
                || finishing
                || c.m(&[19, 50, 51, 52, 53, 62, 63, 64, 65, 66, 98])
        }
        b'Q' => {
            [50, 730, 760, 830].contains(&mo) || c.g(&[100, 640]) || roughing || finishing || c.m(&[19, 61, 66, 67, 68])
        }
        b'R' => [20, 30, 730, 760].contains(&mo) || cycle || c.g(&[100, 411, 421]) || roughing || c.m(&[19]),
        _ => true,
    }
}

/// The word with `letter` of `b` (`$` is the spindle word); Q−1 is the interpreter's "no Q".
fn word(b: &Block, letter: u8) -> Option<Word> {
    match letter {
        b'$' => b.spindle,
        b'Q' => b.get(b'Q').copied().filter(|w| w.value() != -1.0),
        _ => b.get(letter).copied(),
    }
}

/// Every word against the codes that use it, then what G96, G33 and G76 require.
fn other_codes(r: &mut Reader, b: &Block, mo: i64) -> bool {
    let c = Codes::of(b);
    for (letter, message) in WORDS {
        if let Some(w) = word(b, letter) {
            if !used(letter, mo, &c) {
                r.diag(&msg::LCNC_WORD_UNUSED, w.span, args![word = w, message = Arg::lit(message)]);
                return false;
            }
        }
    }
    if c.g(&[960]) && !b.has(b'S') {
        r.diag(&msg::LCNC_S_MISSING_G96, g_word_span(b, 960), args![]);
        return false;
    }
    let span = g_word_span(b, mo);
    if mo == 330 || mo == 331 {
        if !b.has(b'K') {
            r.diag(&msg::LCNC_K_MISSING_G33, span, args![]);
            return false;
        }
        if let Some(f) = b.get(b'F') {
            r.diag(&msg::LCNC_F_WITH_G33, f.span, args![word = f]);
            return false;
        }
    }
    if mo == 760 {
        return g76_words(r, b, span);
    }
    true
}

/// G76 needs P (P−1 is the interpreter's "no P") and I, J, K.
fn g76_words(r: &mut Reader, b: &Block, span: crate::span::Span) -> bool {
    if b.get(b'P').is_none_or(|p| p.value() == -1.0) {
        let t = if b.has(b'P') { &msg::LCNC_P_MINUS_ONE_G76 } else { &msg::LCNC_P_MISSING_G76 };
        r.diag(t, span, args![]);
        return false;
    }
    let missing =
        [(b'I', &msg::LCNC_I_MISSING_G76), (b'J', &msg::LCNC_J_MISSING_G76), (b'K', &msg::LCNC_K_MISSING_G76)]
            .into_iter()
            .find(|(l, _)| !b.has(*l));
    if let Some((letter, t)) = missing {
        r.diag(t, span, args![letter = letter as char]);
        return false;
    }
    true
}
