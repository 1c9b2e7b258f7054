//! The profile cycles' flow on Fanuc 0i and GSK980TDc: `G71 P(ns) Q(nf)`
//! (and G72, G73) read the contour N(ns) … N(nf) that follows and the
//! program goes on after N(nf) — the contour is not run in line; `G70
//! P(ns) Q(nf)` runs it, the part's finished outline, and goes on after
//! itself (Fanuc 0i-TF operator's manual, multiple repetitive cycles
//! G70–G76: "the move commands of the finishing shape are specified in the
//! blocks from sequence number ns to nf"; GSK980TDc user manual §3.20 has
//! the same two-block forms). The roughing passes themselves are not
//! planned yet: a not-simulated note says so.

mod common;
use common::*;
use screwcut::{Code, Dialect, Plan};

const CONTOUR: &str = "\
N10 G00 X44.
G01 Z0. F0.1
X47.8 Z-1.9
Z-30.
X56.
Z-45.
N20 X62.
";

fn program(g71: &str, g70: &str) -> String {
    format!(
        "O0071\nG21 G97 S800 M03 T0101\nG00 X62. Z2.\n{g71}{g70}G00 X100. Z100.\nT0303\nG00 X50. Z5.\nG92 X47.1 Z-28. F2.\nX46.5\nX45.9\nG00 X100. Z100.\nM30\n"
    )
}

/// The moves' kinds and end points are those of `b`.
#[track_caller]
fn same_moves(a: &Plan, b: &Plan) {
    assert_eq!(a.moves.len(), b.moves.len(), "moves");
    for (ma, mb) in a.moves.iter().zip(&b.moves) {
        assert_eq!(ma.kind, mb.kind);
        pt(ma.to, mb.to.x, mb.to.z);
    }
}

/// G71 then G70: the contour runs once, where G70 is, and the thread's
/// crest is the diameter it turned (X47.8).
#[test]
fn g71_reads_its_contour_and_g70_runs_it() {
    for dialect in [Dialect::Fanuc0i, Dialect::Gsk980tdc] {
        let cycle = plan_with(
            &program(&format!("G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n{CONTOUR}"), "G70 P10 Q20\n"),
            dialect,
            &[],
        );
        let written = plan_with(&program("", CONTOUR), dialect, &[]);
        no_alarm(&cycle);
        same_moves(&cycle, &written);
        assert_eq!(cycle.threads.len(), 1);
        eq(cycle.threads[0].crest, 47.8);
        // The contour's moves come from its own lines, run by G70 on line 13.
        let contour: Vec<_> = cycle.moves.iter().filter(|m| (6..=12).contains(&m.line)).collect();
        assert_eq!(contour.len(), 7, "{dialect:?}");
        let g71 = cycle.with_code(Code::NotSimulated).find(|d| d.line == 4).expect("the roughing noted");
        assert!(g71.message.contains("roughing of G71"), "{}", g71.message);
    }
}

/// Roughing alone (no G70): the contour is read, not run: no moves on its lines.
#[test]
fn without_g70_the_contour_is_not_run() {
    let plan = plan_with(
        &program(&format!("G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n{CONTOUR}"), ""),
        Dialect::Fanuc0i,
        &[],
    );
    no_alarm(&plan);
    assert!(
        plan.moves.iter().all(|m| !(6..=12).contains(&m.line)),
        "{:?}",
        plan.moves.iter().map(|m| m.line).collect::<Vec<_>>()
    );
    // G72 and G73 read theirs the same way.
    for g in ["G72 W2. R0.5\nG72", "G73 U3. W0. R3\nG73"] {
        let plan = plan_with(&program(&format!("{g} P10 Q20 U0.4 W0.1 F0.25\n{CONTOUR}"), ""), Dialect::Fanuc0i, &[]);
        assert!(plan.moves.iter().all(|m| !(6..=12).contains(&m.line)), "{g}");
    }
}

/// A Q that names no block is the controller's alarm, at the Q word.
#[test]
fn a_missing_end_of_contour_is_an_alarm() {
    let plan = plan_with(
        &program(&format!("G71 U2. R0.5\nG71 P10 Q30 U0.4 W0.1 F0.25\n{CONTOUR}"), ""),
        Dialect::Fanuc0i,
        &[],
    );
    let d = plan.diagnostics.iter().find(|d| d.code == Code::JumpTarget).expect("an alarm");
    assert_eq!((d.line, d.column), (5, 9));
}
