#![cfg(not(target_arch = "wasm32"))]
//! Property tests: any input gives a plan or diagnostics — never a panic, a
//! hang or unbounded output — and what the plan says is consistent with the
//! text it came from.

#[path = "common/props.rs"]
mod props;

use props::{block, check, dialect, program};
use proptest::prelude::*;
use screwcut::settings::P;
use screwcut::{Dialect, Settings};

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
