//! `compare`: two plans pass by pass. A program and its own expansion (the
//! plan written back block by block, `expand`) cut the same passes in every
//! dialect but where the target cannot write them (listed); a Fanuc G76 and its
//! GSK expansion compare equal (the example); programs that differ
//! say where; the CLI's exit status says which.

mod common;
use common::plan_with;
use screwcut::Dialect;
use screwcut::compare::compare;
use screwcut::expand::expand;

const EXAMPLES: &[(&str, &str, Dialect)] = &[
    ("o1006", include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc),
    ("o0009", include_str!("../examples/o0009.nc"), Dialect::Gsk980tdc),
    ("g32-multistart-q", include_str!("../examples/g32-multistart-q.nc"), Dialect::Gsk980tdc),
    ("g32-continuous", include_str!("../examples/g32-continuous.nc"), Dialect::Gsk980tdc),
    ("g78-m30x2", include_str!("../examples/g78-m30x2.nc"), Dialect::Gsk980tdc),
    ("g78-flank-alternating", include_str!("../examples/g78-flank-alternating.nc"), Dialect::Gsk980tdc),
    ("g92-two-start", include_str!("../examples/g92-two-start.nc"), Dialect::Gsk980tdc),
    ("fanuc-g92", include_str!("../examples/fanuc-g92.nc"), Dialect::Fanuc0i),
    ("g76-fanuc", include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i),
    ("renhe-tails", include_str!("../examples/renhe-tails.nc"), Dialect::Renhe),
    ("linuxcnc-g76", include_str!("../examples/linuxcnc-g76.ngc"), Dialect::LinuxCnc),
    ("fanuc-g71-g76", include_str!("../examples/fanuc-g71-g76.nc"), Dialect::Fanuc0i),
    ("linuxcnc-g71-g76", include_str!("../examples/linuxcnc-g71-g76.ngc"), Dialect::LinuxCnc),
];

/// What a target cannot write of an example, and so the passes that differ.
/// Renhe's G30 tail is modal: every thread block after it ends with it
/// (Renhe manual, seed 003, §8.3.1.5 (4)), so a run-out on the last block of
/// a continuous thread only (`g32-continuous`) needs a G30 block between its
/// segments, which ends the continuous thread as the planner reads it; and a
/// thread block must be longer than 4 mm and than its U (§8.3.1.5 2.(2),
/// E18-04), which G78's 2 mm oblique screw-in (`g78-flank-alternating`) is not.
const NOT_WRITABLE: &[(&str, Dialect)] =
    &[("g32-continuous", Dialect::Renhe), ("g78-flank-alternating", Dialect::Renhe)];

#[test]
fn every_example_cuts_the_passes_of_its_expansion() {
    let targets = [Dialect::Gsk980tdc, Dialect::Fanuc0i, Dialect::Renhe, Dialect::LinuxCnc];
    let mut unequal = Vec::new();
    for &(name, text, dialect) in EXAMPLES {
        let plan = plan_with(text, dialect, &[]);
        for to in targets {
            let again = plan_with(&expand(&plan, to).program, to, &[]);
            let c = compare(&plan, &again);
            if NOT_WRITABLE.contains(&(name, to)) {
                assert!(!c.same(), "{name} → {to} is written as it is now: take it off the list");
                unequal.push(name);
                continue;
            }
            assert!(c.same(), "{name} → {to}: {:#?}", c.differences);
            assert_eq!(c.passes[0], c.passes[1]);
        }
    }
    assert_eq!(unequal.len(), NOT_WRITABLE.len());
}

/// Multi-start threads into controllers without a start angle word: each
/// start's passes begin lead/starts further back and are read again as the
/// same starts (two-start G32 Q and G92 L examples, lead 4 and 3).
#[test]
fn multi_start_threads_keep_their_starts_without_a_start_angle_word() {
    for (text, lead) in
        [(include_str!("../examples/g32-multistart-q.nc"), 4.0), (include_str!("../examples/g92-two-start.nc"), 3.0)]
    {
        let plan = plan_with(text, Dialect::Gsk980tdc, &[]);
        for to in [Dialect::Renhe, Dialect::LinuxCnc] {
            let again = plan_with(&expand(&plan, to).program, to, &[]);
            let (a, b) = (&plan.threads[0], &again.threads[0]);
            assert_eq!((b.starts, b.lead, b.pitch), (2, lead, lead / 2.0), "{to}");
            let seconds = |t: &screwcut::thread::Thread| {
                t.passes.iter().filter(|p| p.start == 2).map(|p| (p.from.z, p.to.z)).collect::<Vec<_>>()
            };
            // Begun half a lead further back (the cut runs toward −Z), ended where they were.
            for ((az, aend), (bz, bend)) in seconds(a).into_iter().zip(seconds(b)) {
                assert!((bz - az - lead / 2.0).abs() < 1e-9 && (bend - aend).abs() < 1e-9, "{to}: {az}→{bz}");
            }
            assert!(b.passes.iter().all(|p| p.angle == 0.0));
        }
    }
}

/// LinuxCNC's G76 returns between passes along its drive line, back and
/// across at once as the depth changes (straight back for the spring pass):
/// written block by block, each return is timed with the same pass as in the
/// cycle (the diagonal one begins the next pass's approach, a straight one
/// ends the pass before), so passes 2 to 19 take the same time.
#[test]
fn a_cycles_returns_are_timed_with_the_same_passes_written_block_by_block() {
    let text = include_str!("../examples/linuxcnc-g76.ngc");
    let plan = plan_with(text, Dialect::LinuxCnc, &[]);
    let again = plan_with(&expand(&plan, Dialect::LinuxCnc).program, Dialect::LinuxCnc, &[]);
    let (a, b) = (&plan.threads[0].shop.pass_time_s, &again.threads[0].shop.pass_time_s);
    assert_eq!((a.len(), b.len()), (19, 19));
    // The first pass's approach in the cycle starts at the drive point (X22 Z3) with a
    // move out to the drive line, which the block-by-block program makes before it:
    // 0.01 s, within the compare's 1%.
    assert!((a[0] - b[0]).abs() < 0.01 * a[0], "pass 1: {} against {}", a[0], b[0]);
    for (i, (x, y)) in a.iter().zip(b).enumerate().skip(1) {
        assert!((x - y).abs() < 1e-3, "pass {}: {x} against {y}", i + 1);
    }
    // The second pass's approach begins with the return back and across from the first's end.
    let p2 = &again.threads[0].passes[1];
    let first = &again.moves[p2.moves.approach.start];
    assert!(first.from.z < -18.0 && first.to.z > 2.0 && (first.from.x - first.to.x).abs() > 0.1, "{first:?}");
}

#[test]
fn programs_that_differ_say_where() {
    let a = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    // The third pass 0.05 deeper: X45.85 instead of X45.9.
    let b = plan_with(&include_str!("../examples/o1006.nc").replace("X45.9", "X45.85"), Dialect::Gsk980tdc, &[]);
    let c = compare(&a, &b);
    assert!(!c.same());
    let x = c.differences.iter().find(|d| d.what == "x").expect("the pass's X");
    assert_eq!((x.thread, x.pass, x.a, x.b), (1, Some(3), Some(45.9), Some(45.85)));
    let d = c.differences.iter().find(|d| d.what == "depth").expect("its depth");
    assert!((d.a.unwrap() - 1.05).abs() < 1e-9 && (d.b.unwrap() - 1.075).abs() < 1e-9, "{d:?}");
    // One pass fewer.
    let fewer = include_str!("../examples/o1006.nc").replace("N190 X45.4;", "").replace("N200 G32 Z13.0 F2.0;", "");
    let c = compare(&a, &plan_with(&fewer, Dialect::Gsk980tdc, &[]));
    assert!(
        c.differences.iter().any(|d| d.what == "passes" && d.a == Some(5.0) && d.b == Some(4.0)),
        "{:#?}",
        c.differences
    );
}

#[test]
fn the_command_line_exits_by_the_comparison() {
    let bin = env!("CARGO_BIN_EXE_screwcut");
    let dir = std::env::temp_dir().join(format!("screwcut-compare-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let g76 = dir.join("g76.nc");
    std::fs::write(&g76, include_str!("../examples/g76-fanuc.nc")).unwrap();
    let plan = plan_with(include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i, &[]);
    let gsk = dir.join("gsk.nc");
    std::fs::write(&gsk, expand(&plan, Dialect::Gsk980tdc).program).unwrap();
    let run = |args: &[&str]| std::process::Command::new(bin).args(args).output().unwrap();
    let (g76, gsk) = (g76.to_str().unwrap(), gsk.to_str().unwrap());
    let same = run(&["compare", g76, gsk, "--dialect", "fanuc0i", "--dialect-b", "gsk980tdc"]);
    assert_eq!(same.status.code(), Some(0), "{}", String::from_utf8_lossy(&same.stdout));
    assert!(String::from_utf8_lossy(&same.stdout).contains("cut the same passes: 1 thread(s), 5 pass(es)"));
    // Read as GSK, the G76 is another cycle's words: they differ, exit 1; as JSON too.
    let differ = run(&["compare", g76, gsk, "--dialect-b", "fanuc0i", "--json"]);
    assert_eq!(differ.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&differ.stdout).unwrap();
    assert_eq!(v["same"], false);
    let missing = run(&["compare", g76, "/nonexistent/screwcut.nc"]);
    assert_eq!(missing.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}
