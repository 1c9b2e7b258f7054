#![cfg(not(target_arch = "wasm32"))]
//! Property tests: any input gives a plan or diagnostics — never a panic, a
//! hang or unbounded output — and what the plan says is consistent with the
//! text it came from.

use proptest::prelude::*;
use screwcut::motion::Point;
use screwcut::settings::P;
use screwcut::{Dialect, Plan, Settings};

fn dialect(i: u8) -> Dialect {
    Dialect::ALL[i as usize % Dialect::ALL.len()]
}

/// Invariants every plan keeps, whatever the input.
fn check(text: &str, s: &Settings, plan: &Plan) {
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
fn word() -> impl Strategy<Value = String> {
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
fn block() -> impl Strategy<Value = String> {
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

fn program() -> impl Strategy<Value = String> {
    prop::collection::vec(block(), 0..40).prop_map(|b| b.join("\n"))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Arbitrary text (any Unicode) never panics.
    #[test]
    fn any_text(text in "\\PC{0,400}", d in 0u8..4) {
        let s = Settings::new(dialect(d));
        let plan = screwcut::plan(&text, &s);
        check(&text, &s, &plan);
    }

    /// G-code-shaped programs with extreme numbers never panic and stay consistent.
    #[test]
    fn gcode_shaped(text in program(), d in 0u8..4) {
        let s = Settings::new(dialect(d));
        let plan = screwcut::plan(&text, &s);
        check(&text, &s, &plan);
    }

    /// Tight limits hold: a few moves, a few passes, a few diagnostics.
    #[test]
    fn limits_hold(text in program(), d in 0u8..4, moves in 1u32..20, passes in 1u32..20, diags in 1u32..5) {
        let mut s = Settings::new(dialect(d));
        s.set(P::LimitMoves, moves as f64);
        s.set(P::LimitPasses, passes as f64);
        s.set(P::LimitDiagnostics, diags as f64);
        let plan = screwcut::plan(&text, &s);
        check(&text, &s, &plan);
        for t in &plan.threads {
            use screwcut::thread::Source;
            if matches!(t.source, Source::G76 | Source::G78 | Source::LinuxG76) {
                assert!(t.passes.iter().all(|p| p.index <= passes));
            }
        }
    }

    /// Every setting at any value of its range plans without a panic.
    #[test]
    fn any_setting(text in program(), d in 0u8..4, which in 0usize..64, frac in 0.0f64..=1.0) {
        let mut s = Settings::new(dialect(d));
        let defs = screwcut::settings::DEFS;
        let def = &defs[which % defs.len()];
        let v = (def.min + (def.max - def.min) * frac).round();
        let _ = s.set_named(def.name, &v.to_string());
        let plan = screwcut::plan(&text, &s);
        check(&text, &s, &plan);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Re-planning after edits (replacing, inserting or deleting blocks
    /// anywhere) gives exactly the plan of a full re-plan.
    #[test]
    fn incremental_matches_full(
        base in prop::collection::vec(block(), 250..700),
        edits in prop::collection::vec((0.0f64..1.0, 0u8..3, block()), 1..6),
        d in 0u8..4,
        few_diagnostics in any::<bool>(),
    ) {
        let mut s = Settings::new(dialect(d));
        if few_diagnostics {
            // A small limit: which diagnostics are kept and where the rest start must match too.
            s.set(P::LimitDiagnostics, 5.0);
        }
        let mut planner = screwcut::planner::Planner::new(s.clone());
        let mut lines = base;
        planner.plan(&lines.join("\n"));
        for (at, kind, new) in edits {
            let i = ((lines.len() as f64) * at) as usize;
            match kind {
                0 if i < lines.len() => lines[i] = new,
                1 => lines.insert(i.min(lines.len()), new),
                _ if i < lines.len() => { lines.remove(i); }
                _ => lines.push(new),
            }
            let text = lines.join("\n");
            let inc = planner.plan(&text).clone();
            prop_assert_eq!(inc, screwcut::plan(&text, &s));
        }
    }
}

/// The same program planned twice gives the same plan (no hidden state).
#[test]
fn deterministic() {
    let text = include_str!("../examples/g78-m30x2.nc");
    let s = Settings::new(Dialect::Gsk980tdc);
    assert_eq!(screwcut::plan(text, &s), screwcut::plan(text, &s));
}
