//! `compare`: two plans pass by pass. A program and its own expansion (the
//! plan written back block by block, `expand`) cut the same passes in its
//! own dialect and written for GSK980TDc and Fanuc 0i; a Fanuc G76 and its
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
];

#[test]
fn every_example_cuts_the_passes_of_its_expansion() {
    for &(name, text, dialect) in EXAMPLES {
        let plan = plan_with(text, dialect, &[]);
        for to in [dialect, Dialect::Gsk980tdc, Dialect::Fanuc0i] {
            let again = plan_with(&expand(&plan, to).program, to, &[]);
            let c = compare(&plan, &again);
            if name == "linuxcnc-g76" {
                // LinuxCNC's G76 moves between passes along its drive line and
                // compound angle; written block by block, the same cuts take
                // other rapids: only the passes' times differ.
                assert!(c.differences.iter().all(|d| d.what == "time"), "{name} → {to}: {:#?}", c.differences);
                continue;
            }
            assert!(c.same(), "{name} → {to}: {:#?}", c.differences);
            assert_eq!(c.passes[0], c.passes[1]);
        }
    }
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
