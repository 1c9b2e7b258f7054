//! The fuzz target's body, shared with the test that replays the corpus
//! (`tests/fuzz_corpus.rs`): the first byte picks the dialect, a setting to
//! stress and the bounds of the program flow (which only loops, jumps and
//! calls meet), the rest is the program (lossily decoded, as the CLI reads
//! files). Any input must give a plan whose positions and numbers are sane —
//! never a panic, a hang or unbounded output.

use screwcut::settings::P;
use screwcut::{Dialect, Settings};

/// Plans `data` and checks the plan; panics on a violation.
pub fn check(data: &[u8]) {
    let Some((&head, rest)) = data.split_first() else { return };
    let n = Dialect::ALL.len() as u8;
    let mut s = Settings::new(Dialect::ALL[(head % n) as usize]);
    // Stress a few settings that change the planner's paths.
    match (head / n) % 8 {
        1 => s.set(P::No182_7, 1.0),
        2 => s.set(P::Fanuc3401_0, 1.0),
        3 => {
            s.set(P::XMode, 1.0);
            s.set(P::LinuxStartupX, 1.0);
        }
        4 => s.set(P::LimitPasses, 3.0),
        5 => s.set(P::LimitMoves, 50.0),
        6 => s.set(P::No107, 500.0),
        7 => s.set(P::Increment, 1.0),
        _ => {}
    }
    // Tight bounds of the program flow: blocks run again, call nesting, runs of a main program ending in M99.
    match head / (n * 8) {
        1 => s.set(P::LimitBlocks, 1000.0),
        2 => {
            s.set(P::LimitBlocks, 50.0);
            s.set(P::LimitCallDepth, 2.0);
        }
        3 => s.set(P::LimitCallDepth, 1.0),
        4 => {
            s.set(P::LimitBlocks, 10000.0);
            s.set(P::MainRepeats, 3.0);
        }
        5 => {
            s.set(P::LimitBlocks, 200.0);
            s.set(P::MainRepeats, 2.0);
        }
        _ => {}
    }
    let text = String::from_utf8_lossy(rest);
    let plan = screwcut::plan(&text, &s);
    assert!(plan.moves.len() <= s.int(P::LimitMoves) as usize);
    assert!(plan.diagnostics.len() <= s.int(P::LimitDiagnostics) as usize + 1);
    for d in &plan.diagnostics {
        assert!(d.line >= 1 && d.column >= 1);
        assert!(d.span.start <= d.span.end && d.span.end as usize <= text.len());
    }
    for m in &plan.moves {
        assert!(m.from.x.is_finite() && m.from.z.is_finite() && m.to.x.is_finite() && m.to.z.is_finite());
    }
    for t in &plan.threads {
        assert!(!t.passes.is_empty() && t.lead.is_finite() && t.lead > 0.0);
    }
    let _ = plan.to_json();
}
