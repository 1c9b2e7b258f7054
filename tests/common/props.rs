//! What the property tests share (`properties.rs`, `flow_properties.rs`):
//! the invariants every plan keeps and the strategies of G-code-shaped text.
#![allow(dead_code)]

use proptest::prelude::*;
use screwcut::motion::Point;
use screwcut::settings::P;
use screwcut::{Dialect, Plan, Settings};

/// The dialect `i` picks (any byte).
pub fn dialect(i: u8) -> Dialect {
    Dialect::ALL[i as usize % Dialect::ALL.len()]
}

/// Invariants every plan keeps, whatever the input.
pub fn check(text: &str, s: &Settings, plan: &Plan) {
    let lines = text.split(['\n', '\r']).count().max(1) as u32 + 1;
    assert!(plan.moves.len() <= s.int(P::LimitMoves) as usize);
    assert!(plan.diagnostics.len() <= s.int(P::LimitDiagnostics) as usize + 1);
    for d in &plan.diagnostics {
        assert!(d.line >= 1 && d.line <= lines, "{d:?}");
        assert!(d.column >= 1);
        assert!(d.span.start <= d.span.end && d.span.end as usize <= text.len(), "{d:?}");
        assert!(text.is_char_boundary(d.span.start as usize) && text.is_char_boundary(d.span.end as usize));
        assert!(!d.message.is_empty());
    }
    let finite = |p: Point| p.x.is_finite() && p.z.is_finite();
    for m in &plan.moves {
        assert!(finite(m.from) && finite(m.to), "{m:?}");
        assert!(m.line >= 1 && m.line <= lines);
    }
    for t in &plan.threads {
        assert!(!t.passes.is_empty());
        assert!(t.starts >= 1 && t.starts as i64 <= s.int(P::LimitStarts));
        assert!(t.lead > 0.0 && t.lead.is_finite());
        for p in &t.passes {
            assert!(p.start >= 1 && p.start <= t.starts && p.index >= 1);
            assert!(finite(p.from) && finite(p.to) && p.depth.is_finite());
            assert!(p.lines.iter().all(|l| *l >= 1 && *l <= lines));
        }
    }
    // The JSON always serialises.
    assert!(plan.to_json().starts_with('{'));
}

/// One word: a letter (mostly lathe addresses) and a number in any of the
/// shapes a program or a careless hand can produce.
pub fn word() -> impl Strategy<Value = String> {
    let letter = prop_oneof![
        8 => prop::sample::select(b"GXZUWFIJKQRPDLEMSTN".to_vec()),
        1 => prop::sample::select(b"ABCHOVY".to_vec()),
    ];
    let number = prop_oneof![
        Just("0".to_string()),
        (0u32..100).prop_map(|v| v.to_string()),
        (-100000i64..100000).prop_map(|v| v.to_string()),
        (-1.0e4f64..1.0e4).prop_map(|v| format!("{v:.4}")),
        Just("99999999".to_string()),
        Just("-99999999".to_string()),
        Just("12345678901234567890".to_string()),
        Just("1e308".to_string()),
        Just(".".to_string()),
        Just("-".to_string()),
        Just("1.2.3".to_string()),
        Just(String::new()),
    ];
    (letter, number).prop_map(|(l, n)| format!("{}{}", l as char, n))
}

/// A block: a few words, sometimes a G code of the threading family first,
/// sometimes a comment or a stray character.
pub fn block() -> impl Strategy<Value = String> {
    let g = prop::sample::select(vec![
        "",
        "G00 ",
        "G01 ",
        "G02 ",
        "G03 ",
        "G32 ",
        "G33 ",
        "G30 ",
        "G76 ",
        "G78 ",
        "G92 ",
        "G90 ",
        "G94 ",
        "G04 ",
        "G50 ",
        "G20 ",
        "G21 ",
        "G28 ",
        "G71 ",
        "G7 ",
        "G8 ",
        "G91 ",
        "G17 ",
        "G41.1 D1 ",
        "M3 ",
        "M5 ",
    ]);
    let tail =
        prop::sample::select(vec!["", "", "", " (c)", ";", " ; G01 X1", " (", ")", " #1", " Ｇ", " 。5", " $1", " $0"]);
    (g, prop::collection::vec(word(), 0..6), tail).prop_map(|(g, w, t)| format!("{g}{}{t}", w.join(" ")))
}

/// A program of up to 40 such blocks.
pub fn program() -> impl Strategy<Value = String> {
    prop::collection::vec(block(), 0..40).prop_map(|b| b.join("\n"))
}
