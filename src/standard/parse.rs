//! Reading thread designations from free text.

use super::{Class, Designation, Error, IsoZone, Kind, MM_PER_INCH, Series, System, iso, npt, unified};
use crate::args;
use crate::message as msg;

/// The medium ISO class (ISO 965-1): 6g external, 6H internal.
pub(super) fn iso_default(kind: Kind) -> Class {
    let position = if kind == Kind::External { 'g' } else { 'H' };
    let z = IsoZone { grade: 6, position };
    Class::Iso { pitch: z, crest: z }
}

/// Text made uniform: `×`, `*` and `X` between numbers become `x`, the
/// enclosing parentheses of a G-code comment and inch marks are dropped.
fn normalise(text: &str) -> String {
    let t = text.trim();
    let t = t.strip_prefix('(').unwrap_or(t);
    let t = t.strip_suffix(')').unwrap_or(t);
    t.trim().replace(['×', '*'], "x").replace(['"', '”', '″'], "").replace(['–', '—'], "-")
}

/// Reads one designation; see [`super::parse`].
pub(super) fn parse(text: &str) -> Result<Designation, Error> {
    let s = normalise(text);
    if s.is_empty() {
        return Err(Error::new(&msg::STD_EMPTY, args![]));
    }
    if !s.is_ascii() {
        return Err(Error::new(&msg::STD_NOT_ASCII, args![s]));
    }
    let upper = s.to_ascii_uppercase();
    let mut chars = s.chars();
    let first = chars.next().unwrap_or(' ');
    let second = chars.next().unwrap_or(' ');
    let d = if (first == 'M' || first == 'm') && (second.is_ascii_digit() || second == '.') {
        parse_iso(&s)
    } else if upper.contains("NPT") {
        parse_npt(&s, &upper)
    } else if upper.contains("UN") {
        parse_unified(&s, &upper)
    } else {
        Err(Error::new(&msg::STD_NOT_A_DESIGNATION, args![s]))
    }?;
    Ok(Designation { text: text.to_string(), ..d })
}

/// Finds the first designation in free text, such as a G-code comment
/// `(ROUGH M48x2-6g)` or `; thread 1/4-20 UNC-2A`. Returns `None` when no
/// part of the text reads as one. Give it comment text: a bare program word
/// such as `M30` reads as an M30 thread.
pub fn find(text: &str) -> Option<Designation> {
    let tokens: Vec<&str> =
        text.split(|c: char| c.is_whitespace() || "();,".contains(c)).filter(|t| !t.is_empty()).collect();
    for i in 0..tokens.len() {
        for len in (1..=4).rev() {
            let Some(group) = tokens.get(i..i + len) else { continue };
            if let Ok(d) = parse(&group.join(" ")) {
                return Some(d);
            }
        }
    }
    None
}

/// A cursor over ASCII text.
struct Cursor<'a> {
    s: &'a [u8],
    i: usize,
}

impl Cursor<'_> {
    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }

    fn rest(&self) -> &str {
        std::str::from_utf8(self.s.get(self.i..).unwrap_or_default()).unwrap_or_default()
    }

    fn spaces(&mut self) {
        while self.peek() == Some(b' ') {
            self.i += 1;
        }
    }

    fn eat(&mut self, c: u8) -> bool {
        let hit = self.peek().is_some_and(|b| b.eq_ignore_ascii_case(&c));
        self.i += usize::from(hit);
        hit
    }

    fn eat_word(&mut self, w: &str) -> bool {
        let hit = self.s.get(self.i..self.i + w.len()).is_some_and(|b| b.eq_ignore_ascii_case(w.as_bytes()));
        if hit {
            self.i += w.len();
        }
        hit
    }

    /// A decimal number `12`, `1.5`, `.75`; `None` (cursor unmoved) if absent.
    fn number(&mut self) -> Option<f64> {
        let start = self.i;
        while self.peek().is_some_and(|b| b.is_ascii_digit() || b == b'.') {
            self.i += 1;
        }
        let v = self.rest_from(start).parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0);
        if v.is_none() {
            self.i = start;
        }
        v
    }

    fn rest_from(&self, start: usize) -> &str {
        std::str::from_utf8(self.s.get(start..self.i).unwrap_or_default()).unwrap_or_default()
    }
}

/// An ISO class token `6g`, `5g6g`, `6H`; `None` if the text is not one.
fn iso_class(c: &mut Cursor) -> Option<Result<(Class, Kind), Error>> {
    let b = c.s.get(c.i..)?;
    let zone = |g: u8, p: u8| {
        (g.is_ascii_digit() && b"efghGH".contains(&p)).then(|| IsoZone { grade: g - b'0', position: p as char })
    };
    let first = zone(*b.first()?, *b.get(1)?)?;
    let second = b.get(2).zip(b.get(3)).and_then(|(g, p)| zone(*g, *p));
    c.i += if second.is_some() { 4 } else { 2 };
    let crest = second.unwrap_or(first);
    let kind = if first.position.is_ascii_lowercase() { Kind::External } else { Kind::Internal };
    let ext = |z: IsoZone| z.position.is_ascii_lowercase();
    if ext(first) != ext(crest) {
        return Some(Err(Error::new(&msg::STD_ISO_MIXED, args![])));
    }
    let (pd_ok, crest_ok) = match kind {
        Kind::External => ((3..=9).contains(&first.grade), [4, 6, 8].contains(&crest.grade)),
        Kind::Internal => ((4..=8).contains(&first.grade), (4..=8).contains(&crest.grade)),
    };
    if !pd_ok || !crest_ok {
        let t = if kind == Kind::External { &msg::STD_ISO_EXTERNAL_GRADES } else { &msg::STD_ISO_INTERNAL_GRADES };
        return Some(Err(Error::new(t, args![])));
    }
    Some(Ok((Class::Iso { pitch: first, crest }, kind)))
}

/// Class (with its kind), left hand, and notes.
type IsoSuffixes = (Option<(Class, Kind)>, bool, Vec<String>);

/// Class, hand and engagement group after the size of an ISO designation.
fn iso_suffixes(c: &mut Cursor, s: &str) -> Result<IsoSuffixes, Error> {
    let mut class = None;
    let mut left_hand = false;
    let mut notes = Vec::new();
    loop {
        while matches!(c.peek(), Some(b' ' | b'-')) {
            c.i += 1;
        }
        if c.peek().is_none() {
            break;
        }
        if c.eat_word("LH") {
            left_hand = true;
        } else if c.eat_word("RH") {
        } else if let Some(k) = iso_class(c) {
            if class.is_some() {
                return Err(Error::new(&msg::STD_TWO_CLASSES, args![s]));
            }
            class = Some(k?);
        } else if let Some(g) = [b'S', b'N', b'L'].into_iter().find(|g| c.s.get(c.i) == Some(g)) {
            c.i += 1;
            notes.push(format!("length of engagement group {} noted; limits do not depend on it", g as char));
        } else if c.peek() == Some(b'/') {
            return Err(Error::new(&msg::STD_FIT, args![s]));
        } else {
            return Err(Error::new(&msg::STD_NOT_UNDERSTOOD, args![s, rest = c.rest()]));
        }
    }
    Ok((class, left_hand, notes))
}

/// `M<d>[x<P> | xPh<L>P<P>][-<class>][-LH]`.
fn parse_iso(s: &str) -> Result<Designation, Error> {
    let mut c = Cursor { s: s.as_bytes(), i: 1 };
    let d = c.number().ok_or_else(|| Error::new(&msg::STD_NO_DIAMETER, args![s]))?;
    c.spaces();
    let (mut pitch, mut lead) = (None, None);
    if c.eat(b'x') {
        c.spaces();
        if c.eat_word("Ph") {
            lead = Some(c.number().ok_or_else(|| Error::new(&msg::STD_NO_LEAD, args![s]))?);
            c.spaces();
            if !c.eat(b'P') {
                return Err(Error::new(&msg::STD_NO_PITCH_AFTER_LEAD, args![s]));
            }
        }
        pitch = Some(c.number().ok_or_else(|| Error::new(&msg::STD_NO_PITCH, args![s]))?);
    } else if c.peek() == Some(b'-') {
        // "M8-1.25": pitch after a hyphen, when no class letter follows the number.
        let save = c.i;
        c.i += 1;
        c.spaces();
        match c.number() {
            Some(p) if !c.peek().is_some_and(|b| b.is_ascii_alphabetic()) => pitch = Some(p),
            _ => c.i = save,
        }
    }
    let (class, left_hand, mut notes) = iso_suffixes(&mut c, s)?;
    let coarse = iso::coarse_pitch(d);
    let pitch = match pitch.or(coarse) {
        Some(p) => p,
        None => {
            return Err(Error::new(&msg::STD_NO_COARSE_PITCH, args![d]));
        }
    };
    let lead = lead.unwrap_or(pitch);
    let ratio = lead / pitch;
    if (ratio - ratio.round()).abs() > 1e-6 || ratio < 1.0 {
        return Err(Error::new(&msg::STD_LEAD_NOT_MULTIPLE, args![s, lead, pitch]));
    }
    let series = if coarse.is_some_and(|p| (p - pitch).abs() < 1e-9) { Series::Coarse } else { Series::Fine };
    let (class, kind, defaulted) = match class {
        Some((cl, k)) => (cl, k, false),
        None => {
            notes.push(
                "no tolerance class given: the medium class 6g (external) / 6H (internal) of ISO 965-1 is assumed"
                    .into(),
            );
            (iso_default(Kind::External), Kind::External, true)
        }
    };
    Ok(Designation {
        text: String::new(),
        system: System::IsoMetric,
        series,
        nominal_mm: d,
        nominal_in: None,
        pitch_mm: pitch,
        tpi: None,
        lead_mm: lead,
        starts: ratio.round() as u32,
        kind,
        class: Some(class),
        class_defaulted: defaulted,
        left_hand,
        notes,
    })
}

/// An inch size: `1/4`, `1 1/2`, `1-1/2`, `0.250`, `#10`, `1`.
fn inch_size(t: &str) -> Option<f64> {
    let t = t.trim();
    if let Some(n) = t.strip_prefix('#') {
        return unified::number_size(n.trim().parse().ok()?);
    }
    let frac = |f: &str| {
        let (a, b) = f.split_once('/')?;
        let (a, b) = (a.trim().parse::<f64>().ok()?, b.trim().parse::<f64>().ok()?);
        (b > 0.0).then(|| a / b)
    };
    if t.contains('/') {
        return match t.rsplit_once([' ', '-']) {
            Some((whole, f)) if !whole.contains('/') => Some(whole.trim().parse::<f64>().ok()? + frac(f)?),
            _ => frac(t),
        };
    }
    t.parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0)
}

/// Splits `<size>-<tpi>` (the last hyphen separates them) or a bare size.
fn size_and_tpi(head: &str) -> Option<(&str, Option<f64>)> {
    let head = head.trim().trim_end_matches('-').trim();
    match head.rsplit_once('-') {
        Some((size, tpi)) if !tpi.contains('/') => Some((size, Some(tpi.trim().parse::<f64>().ok()?))),
        _ => Some((head, None)),
    }
}

fn series_of(word: &str) -> Option<Series> {
    Some(match word {
        "UNC" | "UNRC" => Series::Unc,
        "UNF" | "UNRF" => Series::Unf,
        "UNEF" | "UNREF" => Series::Unef,
        "UN" | "UNR" => Series::Un,
        "UNS" => Series::Uns,
        _ => return None,
    })
}

/// `<size>-<tpi> <series>[-<class>][ LH]`.
fn parse_unified(s: &str, upper: &str) -> Result<Designation, Error> {
    let at = upper.find("UN").unwrap_or(0);
    let end = upper[at..].find(|c: char| !c.is_ascii_alphabetic()).map_or(upper.len(), |e| at + e);
    let word = &upper[at..end];
    let series = series_of(word).ok_or_else(|| Error::new(&msg::STD_UNKNOWN_SERIES, args![s, word]))?;
    // "8UN": a pitch-series prefix glued to UN is dropped.
    let head = s[..at].trim_end_matches(|c: char| c.is_ascii_digit() && !s[..at].trim_end().ends_with('-'));
    let head = if head.trim().is_empty() { &s[..at] } else { head };
    let (size_text, tpi) = size_and_tpi(head).ok_or_else(|| Error::new(&msg::STD_NO_SIZE_AND_TPI, args![s]))?;
    let whole: Option<u32> = size_text.trim().parse().ok();
    let d = match (whole, tpi) {
        (Some(n), Some(t)) if unified::is_number_size_pitch(n, t) => unified::number_size(n),
        _ => inch_size(size_text),
    }
    .ok_or_else(|| Error::new(&msg::STD_NO_SIZE, args![s, size = size_text.trim()]))?;
    let tpi = match tpi.or_else(|| unified::series_tpi(series, d)) {
        Some(t) if t > 0.0 && t.is_finite() => t,
        _ => return Err(Error::new(&msg::STD_GIVE_TPI, args![s])),
    };
    let mut notes = Vec::new();
    if let Some(std_tpi) = unified::series_tpi(series, d).filter(|t| (t - tpi).abs() > 1e-9) {
        notes.push(format!("{word} at this size is {std_tpi} tpi, not {tpi}; limits follow the given pitch"));
    }
    let (grade, kind, left_hand) = unified_class(&s[end..])?;
    let defaulted = grade.is_none();
    if defaulted {
        notes.push("no class given: the medium class 2A (external) / 2B (internal) of ASME B1.1 is assumed".into());
    }
    let pitch = MM_PER_INCH / tpi;
    Ok(Designation {
        text: String::new(),
        system: System::Unified,
        series,
        nominal_mm: d * MM_PER_INCH,
        nominal_in: Some(d),
        pitch_mm: pitch,
        tpi: Some(tpi),
        lead_mm: pitch,
        starts: 1,
        kind: kind.unwrap_or(Kind::External),
        class: Some(Class::Unified { grade: grade.unwrap_or(2) }),
        class_defaulted: defaulted,
        left_hand,
        notes,
    })
}

type UnifiedTail = (Option<u8>, Option<Kind>, bool);

/// The part after the series: `-2A`, ` 3B`, `-2A-LH`.
fn unified_class(tail: &str) -> Result<UnifiedTail, Error> {
    let mut grade = None;
    let mut kind = None;
    let mut lh = false;
    for tok in tail.split(['-', ' ']).filter(|t| !t.is_empty()) {
        let t = tok.to_ascii_uppercase();
        let b = t.as_bytes();
        if t == "LH" {
            lh = true;
        } else if t == "RH" {
        } else if b.len() == 2 && (b'1'..=b'3').contains(&b[0]) && (b[1] == b'A' || b[1] == b'B') && grade.is_none() {
            grade = Some(b[0] - b'0');
            kind = Some(if b[1] == b'A' { Kind::External } else { Kind::Internal });
        } else {
            return Err(Error::new(&msg::STD_UNIFIED_CLASS, args![tok]));
        }
    }
    Ok((grade, kind, lh))
}

/// `<size>[-<tpi>] NPT`.
fn parse_npt(s: &str, upper: &str) -> Result<Designation, Error> {
    let at = upper.find("NPT").unwrap_or(0);
    let tail = upper[at + 3..].trim();
    if !tail.is_empty() {
        return Err(if tail.starts_with('F') {
            Error::new(&msg::STD_NPTF, args![s])
        } else {
            Error::new(&msg::STD_AFTER_NPT, args![s, tail])
        });
    }
    let (size_text, tpi) =
        size_and_tpi(&s[..at]).ok_or_else(|| Error::new(&msg::STD_NO_PIPE_SIZE_AND_TPI, args![s]))?;
    let nominal = inch_size(size_text).ok_or_else(|| Error::new(&msg::STD_NO_PIPE_SIZE, args![s]))?;
    let (od, std_tpi) = npt::size(nominal).ok_or_else(|| Error::new(&msg::STD_NOT_NPT_SIZE, args![s, nominal]))?;
    if let Some(t) = tpi.filter(|t| (t - std_tpi).abs() > 1e-9) {
        return Err(Error::new(&msg::STD_NPT_TPI, args![s, size = size_text.trim(), standard = std_tpi, tpi = t]));
    }
    let pitch = MM_PER_INCH / std_tpi;
    Ok(Designation {
        text: String::new(),
        system: System::Npt,
        series: Series::Npt,
        nominal_mm: od * MM_PER_INCH,
        nominal_in: Some(od),
        pitch_mm: pitch,
        tpi: Some(std_tpi),
        lead_mm: pitch,
        starts: 1,
        kind: Kind::External,
        class: None,
        class_defaulted: false,
        left_hand: false,
        notes: vec![format!("nominal pipe size {nominal} in: outside diameter {od} in")],
    })
}

#[cfg(test)]
mod tests {
    use super::super::parse as p;
    use super::*;

    fn iso_class_of(s: &str) -> String {
        p(s).unwrap().class.unwrap().to_string()
    }

    #[test]
    fn iso_forms() {
        let d = p("M10").unwrap();
        assert_eq!((d.nominal_mm, d.pitch_mm, d.series, d.class_defaulted), (10.0, 1.5, Series::Coarse, true));
        assert_eq!(iso_class_of("M10x1.5"), "6g");
        let d = p("M10×1.25-6g").unwrap();
        assert_eq!((d.pitch_mm, d.series, d.class_defaulted), (1.25, Series::Fine, false));
        assert_eq!(iso_class_of("(M48x2-6g)"), "6g");
        let d = p("M20x1.5-6H").unwrap();
        assert_eq!((d.kind, iso_class_of("M20x1.5-6H")), (Kind::Internal, "6H".to_string()));
        assert_eq!(iso_class_of("M16x1.5-5g6g"), "5g6g");
        let d = p("M30xPh6P2-6g").unwrap();
        assert_eq!((d.pitch_mm, d.lead_mm, d.starts), (2.0, 6.0, 3));
        assert_eq!(p("M8-1.25").unwrap().pitch_mm, 1.25);
        assert_eq!(iso_class_of("M8-6e"), "6e");
        assert!(p("M12x1.5-6g-LH").unwrap().left_hand);
        assert_eq!(p("m6 x 0.75 - 4h").unwrap().pitch_mm, 0.75);
    }

    #[test]
    fn iso_errors_say_what() {
        assert!(p("M15").unwrap_err().message.contains("coarse pitch"));
        assert!(p("M10x1.5-6k").unwrap_err().message.contains("did not understand"));
        // Td has no grade 5: a single "5h" names a crest zone that does not exist.
        assert!(p("M10x1.5-5h").is_err());
        assert!(p("M10x1.5-5h6h").is_ok());
        assert!(p("M10x1.5-2g").unwrap_err().message.contains("grades"));
        assert!(p("M10x1.5-6g6H").unwrap_err().message.contains("mixes"));
        assert!(p("M20x2-6H/6g").unwrap_err().message.contains("fit"));
        assert!(p("M30xPh5P2").unwrap_err().message.contains("whole multiple"));
        assert!(p("Mx1").is_err());
        assert!(p("G32 Z13 F2").is_err());
        assert!(p("").is_err());
    }

    #[test]
    fn unified_forms() {
        let d = p("1/4-20 UNC-2A").unwrap();
        assert_eq!((d.nominal_in, d.tpi, d.kind, d.series), (Some(0.25), Some(20.0), Kind::External, Series::Unc));
        let d = p("3/8-24 UNF-2B").unwrap();
        assert_eq!((d.kind, d.class), (Kind::Internal, Some(Class::Unified { grade: 2 })));
        assert_eq!(p("#10-32 UNF-2A").unwrap().nominal_in, Some(0.19));
        assert!((p("10-32 UNF").unwrap().nominal_in.unwrap() - 0.19).abs() < 1e-12);
        assert_eq!(p("1-8 UN-2A").unwrap().nominal_in, Some(1.0));
        assert_eq!(p("1-64 UNC-3A").unwrap().nominal_in.map(|v| (v * 1000.0).round()), Some(73.0));
        assert_eq!(p("1 1/2-6 UNC-2A").unwrap().nominal_in, Some(1.5));
        assert_eq!(p("1-1/2-6 UNC-2A").unwrap().nominal_in, Some(1.5));
        assert_eq!(p("1/4 UNC").unwrap().tpi, Some(20.0));
        assert_eq!(p("1/2-13UNC-3A").unwrap().class, Some(Class::Unified { grade: 3 }));
        assert!(p("1/4-20 UNC-2A LH").unwrap().left_hand);
        assert!(p("1/4-20 UNC").unwrap().class_defaulted);
        assert!(p("1/4-28 UNEF").unwrap().notes.iter().any(|n| n.contains("32")));
    }

    #[test]
    fn unified_errors() {
        assert!(p("1/4-20 UNX-2A").unwrap_err().message.contains("series"));
        assert!(p("1/4-20 UNC-4A").unwrap_err().message.contains("did not understand"));
        assert!(p("1-1/16 UN").unwrap_err().message.contains("threads per inch"));
    }

    #[test]
    fn npt_forms() {
        let d = p("1/2-14 NPT").unwrap();
        assert_eq!((d.nominal_in, d.tpi, d.system), (Some(0.84), Some(14.0), System::Npt));
        assert_eq!(p("1/8 NPT").unwrap().tpi, Some(27.0));
        assert_eq!(p("1-1/4-11.5 NPT").unwrap().nominal_in, Some(1.66));
        assert!(p("1/2-18 NPT").unwrap_err().message.contains("14"));
        assert!(p("1/2-14 NPTF").unwrap_err().message.contains("NPTF"));
        assert!(p("7/16-14 NPT").is_err());
    }

    #[test]
    fn find_in_comments() {
        assert_eq!(find("(ROUGH M48x2-6g)").unwrap().nominal_mm, 48.0);
        assert_eq!(find("; thread 1/4-20 UNC-2A finish").unwrap().tpi, Some(20.0));
        assert_eq!(find("(PIPE 1/2-14 NPT)").unwrap().system, System::Npt);
        assert!(find("(FINISH PASS)").is_none());
        assert!(find("").is_none());
    }

    #[test]
    fn no_panic_on_odd_text() {
        for s in [
            "M",
            "M.",
            "M0",
            "Mx",
            "M1e9",
            "M10x",
            "M10xPh",
            "M10xPh3",
            "#",
            "#-",
            "/-UN",
            "-UN",
            "UN",
            "NPT",
            "1/0-20 UNC",
            "1/-UN",
            "M10-",
            "M10--6g",
            "M 10",
            "-",
            "((",
            "Mé",
            "M10x0",
            "1e400-20 UNC",
            "0-0 UNC",
            "1-0 UN",
        ] {
            let _ = p(s);
            let _ = find(s);
            if let Ok(d) = p(s) {
                let _ = super::super::limits(&d);
            }
        }
    }
}
