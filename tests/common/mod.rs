//! Helpers shared by the integration tests.
#![allow(dead_code)]

use screwcut::diagnostic::Diagnostic;
use screwcut::{Code, Dialect, Plan, Settings};

/// Plans `src` with the defaults of `dialect` plus `sets` (`NAME=VALUE`).
pub fn plan_with(src: &str, dialect: Dialect, sets: &[&str]) -> Plan {
    let mut s = Settings::new(dialect);
    for a in sets {
        s.assign(a).unwrap_or_else(|e| panic!("{a}: {e}"));
    }
    screwcut::plan(src, &s)
}

/// Plans `src` as Fanuc 0i with default settings.
pub fn fanuc(src: &str) -> Plan {
    plan_with(src, Dialect::Fanuc0i, &[])
}

/// Plans `src` as GSK980TDc with default settings.
pub fn gsk(src: &str) -> Plan {
    plan_with(src, Dialect::Gsk980tdc, &[])
}

/// The only diagnostic with `code` (fails when there is none or several).
pub fn one(plan: &Plan, code: Code) -> Diagnostic {
    let v: Vec<_> = plan.with_code(code).cloned().collect();
    assert_eq!(v.len(), 1, "expected one {code}, got {v:#?}\nall: {:#?}", plan.diagnostics);
    v[0].clone()
}

/// Asserts one diagnostic with `code` at `line`:`column` and returns it.
pub fn at(plan: &Plan, code: Code, line: u32, column: u32) -> Diagnostic {
    let d = plan
        .with_code(code)
        .find(|d| d.line == line && d.column == column)
        .cloned()
        .unwrap_or_else(|| panic!("no {code} at {line}:{column}; diagnostics: {:#?}", plan.diagnostics));
    assert_eq!(d.severity, code.severity());
    d
}

/// Asserts there is no alarm.
pub fn no_alarm(plan: &Plan) {
    let alarms: Vec<_> = plan.diagnostics.iter().filter(|d| d.severity == screwcut::Severity::Error).collect();
    assert!(alarms.is_empty(), "unexpected alarms: {alarms:#?}");
}

/// Asserts two lengths agree to 1e-9.
#[track_caller]
pub fn eq(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-9, "{a} != {b}");
}

/// Asserts a point is `[x, z]` to 1e-9.
#[track_caller]
pub fn pt(p: screwcut::motion::Point, x: f64, z: f64) {
    assert!((p.x - x).abs() < 1e-9 && (p.z - z).abs() < 1e-9, "({}, {}) != ({x}, {z})", p.x, p.z);
}

/// The passes and motions of two plans are the same (lines aside: the macro
/// program's passes come from other lines than the unrolled one's).
#[track_caller]
pub fn same_cut(a: &Plan, b: &Plan) {
    no_alarm(a);
    no_alarm(b);
    assert_eq!(a.threads.len(), b.threads.len(), "threads");
    for (ta, tb) in a.threads.iter().zip(&b.threads) {
        assert_eq!(ta.passes.len(), tb.passes.len(), "passes");
        eq(ta.crest, tb.crest);
        eq(ta.lead, tb.lead);
        for (pa, pb) in ta.passes.iter().zip(&tb.passes) {
            pt(pa.from, pb.from.x, pb.from.z);
            pt(pa.to, pb.to.x, pb.to.z);
            eq(pa.depth, pb.depth);
        }
    }
    assert_eq!(a.moves.len(), b.moves.len(), "moves");
    for (ma, mb) in a.moves.iter().zip(&b.moves) {
        assert_eq!(ma.kind, mb.kind);
        pt(ma.to, mb.to.x, mb.to.z);
    }
}

/// Checks one diagnostic's message in both languages: its English is the
/// `message` field; every argument its template (and the phrases given as
/// arguments) names is supplied, and every argument supplied is named.
/// Returns the Chinese text.
pub fn check_languages(d: &Diagnostic) -> String {
    assert_eq!(d.render(screwcut::message::Lang::En), d.message, "{}", d.template.name);
    check_message(&screwcut::message::Message::new(d.template, d.args.clone()))
}

/// [`check_languages`] of a message (a thread check's note): the Chinese text.
pub fn check_message(m: &screwcut::message::Message) -> String {
    use screwcut::message::Lang;
    for lang in [Lang::En, Lang::Zh] {
        let mut used = std::collections::BTreeSet::new();
        names_used(m.template.text(lang), &m.args, lang, &mut used);
        let given: std::collections::BTreeSet<&str> = m.args.0.iter().map(|(n, _)| *n).collect();
        assert_eq!(used, given, "{} ({}): arguments named and given differ", m.template.name, lang.name());
    }
    m.render(Lang::Zh)
}

/// The argument names `text` uses, with those of the phrases it is given; panics on a name not given.
fn names_used<'a>(
    text: &'a str,
    args: &'a screwcut::message::Args,
    lang: screwcut::message::Lang,
    out: &mut std::collections::BTreeSet<&'a str>,
) {
    for name in screwcut::message::names(text) {
        let arg = args.get(name).unwrap_or_else(|| panic!("{{{name}}} of {text:?} is not given"));
        out.insert(name);
        if let screwcut::message::Arg::Phrase(p) = arg {
            names_used(p.text(lang), args, lang, out);
        }
    }
}

/// The words of a Chinese message that are English: ASCII words outside
/// quotes (“LinuxCNC's message”, 'program text') that are not G-code
/// words, numbers, units, names of settings, parameters, codes or standards.
pub fn english_words(zh: &str) -> Vec<String> {
    const KEPT: &[&str] = &[
        "mm", "min", "ms", "s", "ISO", "ASME", "NPT", "NPTF", "UN", "UNC", "UNF", "UNEF", "GSK", "Fanuc", "Renhe",
        "LinuxCNC", "DPI", "IS", "Ph", "Td", "TD", "cos", "tan", "mmrraa", "d", "D", "P", "k", "x", "r", "m", "a", "n",
        "L", "U", "W", "X", "Z", "Q", "R", "E", "F", "H", "I", "J", "K", "S", "M", "G", "B", "C", "A", "O", "N", "T",
        "Y", "V",
    ];
    let mut out = Vec::new();
    let mut rest = zh;
    // Quoted text is the program's or LinuxCNC's own: drop it.
    let mut plain = String::new();
    while let Some(i) = rest.find(['“', '\'']) {
        plain.push_str(&rest[..i]);
        let close = if rest[i..].starts_with('“') { '”' } else { '\'' };
        let after = &rest[i + rest[i..].chars().next().map_or(1, char::len_utf8)..];
        match after.find(close) {
            Some(j) => rest = &after[j + close.len_utf8()..],
            None => {
                rest = "";
            }
        }
    }
    plain.push_str(rest);
    for token in plain.split(|c: char| !(c.is_ascii_alphanumeric() || "._#-/Δδα".contains(c))) {
        let token = token.trim_matches(|c: char| ".-/".contains(c));
        if token.is_empty()
            || token.chars().any(|c| c.is_ascii_digit() || !c.is_ascii())
            || token.contains(['.', '_', '#'])
        {
            continue; // a number, a word with its value, a symbol (Δdmin), a setting or parameter name
        }
        for word in token.split(['-', '/']) {
            // A single letter is an address or a symbol (tolerance position e, f, g, h).
            if word.len() > 1 && !KEPT.contains(&word) && !word.chars().all(|c| c.is_ascii_uppercase()) {
                out.push(word.to_string());
            }
        }
    }
    out
}

/// Three passes of G32 written out block by block (the macro tests' programs
/// of calls and loops cut the same).
pub const UNROLLED: &str = "\
O0001
G97 S300 M03
G00 X58. Z70.
X47.1
G32 Z13. F2.
G00 X58.
Z70.
X46.5
G32 Z13. F2.
G00 X58.
Z70.
X45.9
G32 Z13. F2.
G00 X58.
Z70.
G00 X100. Z100.
M30
";
