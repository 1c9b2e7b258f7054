//! Parses the rs274 outputs recorded in `tests/linuxcnc/` and, where rs274
//! is installed, checks that it still prints them.

#[path = "common/rs274.rs"]
mod rs274;

use rs274::{Call, Kind, dir, parse, read, synced_runs};

fn recorded(name: &str) -> Vec<Call> {
    parse(&read(&format!("{name}.out"))).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn files(ext: &str) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter_map(|f| f.strip_suffix(ext).map(str::to_owned))
        .collect();
    v.sort();
    v
}

/// The programs rs274 refuses: `err-*` (G33 and G76) and `oword-err-*`.
fn refused(name: &str) -> bool {
    name.starts_with("err-") || name.starts_with("oword-err-")
}

#[track_caller]
fn near(a: f64, b: f64) {
    assert!((a - b).abs() < 5e-5, "{a} != {b}");
}

#[test]
fn every_recorded_output_parses() {
    let names = files(".out");
    assert!(names.len() >= 40, "{names:?}");
    for n in &names {
        recorded(n);
    }
}

#[test]
fn g76_straight_passes_and_retracts() {
    let c = recorded("g76-straight");
    let runs = synced_runs(&c);
    assert_eq!(runs.len(), 5);
    for (run, x) in runs.iter().zip([8.8, 8.6, 8.4, 8.2, 8.0]) {
        assert_eq!(run.len(), 1);
        near(run[0].from.0, x);
        near(run[0].from.1, 5.0);
        near(run[0].to.0, x);
        near(run[0].to.1, -20.0);
        assert_eq!((run[0].pitch, run[0].n), (1.5, Some(20)));
    }
    // The first move of the cycle retracts beyond the drive line X10 by K - J.
    let moves: Vec<_> = c
        .iter()
        .filter_map(|m| if let Call::Move { kind, x, z, .. } = m { Some((*kind, *x, *z)) } else { None })
        .collect();
    assert_eq!(moves[1].0, Kind::Traverse);
    near(moves[1].1, 10.8);
    near(moves.last().unwrap().1, 10.0);
    near(moves.last().unwrap().2, -20.0);
}

#[test]
fn diameter_mode_prints_radius() {
    assert_eq!(recorded("g76-g7")[1..], recorded("g76-straight")[1..]);
    let runs = synced_runs(&recorded("g33-g7-g8"));
    assert_eq!(runs.len(), 2);
    assert_eq!(runs[0][0].to, runs[1][0].to);
    near(runs[0][0].to.0, 10.0);
}

#[test]
fn inch_programs_print_inches() {
    let c = recorded("g33-inch");
    assert!(c.contains(&Call::Inches(true)));
    let runs = synced_runs(&c);
    assert_eq!(runs[0][0].pitch, 0.0625);
    near(runs[0][0].to.1, -1.0);
}

#[test]
fn taper_ends_change_pitch_within_one_run() {
    for (l, len) in [(0, 1), (1, 3), (2, 2), (3, 4)] {
        let runs = synced_runs(&recorded(&format!("g76-taper-l{l}")));
        assert_eq!(runs.len(), 5, "L{l}");
        assert!(runs.iter().all(|r| r.len() == len), "L{l}: {runs:?}");
    }
    let r = &synced_runs(&recorded("g76-taper-l3"))[0];
    near(r[0].pitch, 1.677051); // 1.5 * hypot(E2, K1) / E2
    assert_eq!(r[0].from, (10.8, 5.0)); // the synchronised move in from the retract
    assert_eq!(r[1].to, (8.8, 3.0)); // the entry taper: K down over E
    assert_eq!((r[2].pitch, r[2].to), (1.5, (8.8, -18.0)));
    assert_eq!(r[3].to, (9.8, -20.0)); // the exit taper
}

#[test]
fn errors_are_recorded_on_stderr() {
    let names = files(".err");
    for n in names.iter().filter(|n| refused(n)) {
        let err = read(&format!("{n}.err"));
        assert_eq!(err.lines().count(), 3, "{n}: {err}");
    }
    assert_eq!(read("err-g76-i0.err").lines().nth(1), Some("In G76, I must not be 0"));
}

#[test]
fn rs274_still_prints_the_recorded_output() {
    if !rs274::available() {
        eprintln!("rs274 is not installed (apt-get install linuxcnc-uspace): live check skipped");
        return;
    }
    // Two o-word messages name the file: the temporary one here.
    let unnamed = |e: &str| {
        let (message, block) = e.split_once('\n').unwrap_or((e, ""));
        format!("{}\n{block}", rs274::without_file(message))
    };
    for n in files(".ngc") {
        let got = rs274::run(&read(&format!("{n}.ngc")));
        if refused(&n) {
            let err = read(&format!("{n}.err"));
            let err = err.lines().skip(1).collect::<Vec<_>>().join("\n");
            assert_eq!(got.map_err(|e| unnamed(&e)), Err(unnamed(&err)), "{n}");
        } else {
            assert_eq!(got, Ok(recorded(&n)), "{n}");
        }
    }
    let src = "G18 G21\nM3 S300\nG0 X10 Z5\nG33 Z-20 K1.5\nM2\n";
    let runs = synced_runs(&rs274::run(&rs274::numbered(src)).unwrap());
    assert_eq!(runs[0][0].n, Some(4));
}
