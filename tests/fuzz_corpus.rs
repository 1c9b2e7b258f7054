#![cfg(not(target_arch = "wasm32"))]
//! Replays the fuzz corpus (`fuzz/corpus/plan/`) and any saved crash inputs
//! (`fuzz/regressions/`) through the planner with the fuzz target's checks,
//! so every input the fuzzer kept is a regression test in the normal suite.

use std::path::Path;

use screwcut::settings::P;
use screwcut::{Dialect, Settings};

/// The fuzz target's body: the first byte picks the dialect and a setting.
fn run(data: &[u8]) {
    let Some((&head, rest)) = data.split_first() else { return };
    let mut s = Settings::new(Dialect::ALL[(head % 3) as usize]);
    match (head / 3) % 8 {
        1 => s.set(P::No182_7, 1.0),
        2 => s.set(P::Fanuc3401_0, 1.0),
        3 => s.set(P::XMode, 1.0),
        4 => s.set(P::LimitPasses, 3.0),
        5 => s.set(P::LimitMoves, 50.0),
        6 => s.set(P::No107, 500.0),
        7 => s.set(P::Increment, 1.0),
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

fn replay(dir: &str) -> usize {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let Ok(entries) = std::fs::read_dir(&dir) else { return 0 };
    let mut n = 0;
    for e in entries.flatten() {
        // A file the fuzzer is rewriting right now may be gone: skip it.
        let Ok(data) = std::fs::read(e.path()) else { continue };
        run(&data);
        n += 1;
    }
    n
}

#[test]
fn corpus_and_regressions_plan_cleanly() {
    let corpus = replay("fuzz/corpus/plan");
    assert!(corpus >= 10, "the corpus has {corpus} inputs");
    replay("fuzz/regressions");
}
