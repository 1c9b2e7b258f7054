#![cfg(not(target_arch = "wasm32"))]
//! Replays the fuzz corpus (`fuzz/corpus/plan/`) and any saved crash inputs
//! (`fuzz/regressions/`) through the planner with the fuzz target's checks,
//! so every input the fuzzer kept is a regression test in the normal suite.

use std::path::Path;

#[path = "../fuzz/fuzz_targets/check.rs"]
mod check;

fn replay(dir: &str) -> usize {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let Ok(entries) = std::fs::read_dir(&dir) else { return 0 };
    let mut n = 0;
    for e in entries.flatten() {
        // A file the fuzzer is rewriting right now may be gone: skip it.
        let Ok(data) = std::fs::read(e.path()) else { continue };
        check::check(&data);
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
