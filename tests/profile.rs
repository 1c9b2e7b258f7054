//! The profile cycles' flow on Fanuc 0i and GSK980TDc: `G71 P(ns) Q(nf)`
//! (and G72, G73) read the contour N(ns) … N(nf) that follows and the
//! program goes on after N(nf) — the contour is not run in line; `G70
//! P(ns) Q(nf)` runs it, the part's finished outline, and goes on after
//! itself (Fanuc 0i-TF operator's manual, multiple repetitive cycles
//! G70–G76: "the move commands of the finishing shape are specified in the
//! blocks from sequence number ns to nf"; GSK980TDc user manual §3.20 has
//! the same two-block forms). G71 and G72 rough over the contour
//! (`cycle::rough`, Series 21i-TB manual B-63604EN §13.2.1–2); G73 cuts it
//! d times, shifted (`cycle::pattern`, the pattern repeating cycle as the
//! YASNAC LX3 manual §2.8.2.5.4 draws it, A → A′ → B).

mod common;
use common::*;
use screwcut::motion::MoveKind;
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

/// G71 then G70: the roughing passes are motions of the G71 block, the
/// contour runs once, where G70 is, and the thread's crest is the diameter
/// it turned (X47.8).
#[test]
fn g71_roughs_over_its_contour_and_g70_runs_it() {
    for dialect in [Dialect::Fanuc0i, Dialect::Gsk980tdc] {
        let cycle = plan_with(
            &program(&format!("G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n{CONTOUR}"), "G70 P10 Q20\n"),
            dialect,
            &[],
        );
        let written = plan_with(&program("", CONTOUR), dialect, &[]);
        no_alarm(&cycle);
        // Without the roughing (the G71 block's motions) and G70's return, the moves are those of the
        // contour written in line.
        let mut without = cycle.clone();
        without.moves.retain(|m| m.line != 5 && m.line != 13);
        same_moves(&without, &written);
        // After the contour G70 returns to its start point A (X62 Z2) in rapid, a motion of its block,
        // and says nothing about it (Fanuc 0i-TF, G70: the tool returns to the start point A).
        let back: Vec<_> = cycle.moves.iter().filter(|m| m.line == 13).collect();
        assert_eq!(back.len(), 1, "{dialect:?}");
        assert_eq!(back[0].kind, MoveKind::Rapid);
        pt(back[0].from, 62.0, -45.0);
        pt(back[0].to, 62.0, 2.0);
        assert!(cycle.diagnostics.iter().all(|d| d.line != 13), "{:?}", cycle.diagnostics);
        assert_eq!(cycle.threads.len(), 1);
        eq(cycle.threads[0].crest, 47.8);
        // The contour's moves come from its own lines, run by G70 on line 13.
        let contour: Vec<_> = cycle.moves.iter().filter(|m| (6..=12).contains(&m.line)).collect();
        assert_eq!(contour.len(), 7, "{dialect:?}");
        assert!(cycle.with_code(Code::NotSimulated).all(|d| d.line != 5), "G71 is roughed, not noted");
        // The roughing (B-63604EN §13.2.1): from A (X62 Z2) at depths of 2 (radius) towards the contour's
        // start shifted by Δu/2 = 0.2 and Δw = 0.1 (r 22.2): r 29, 27, 25, 23 and 22.2; each cut along Z
        // to the shifted contour: the face at Z-44.9, the face at Z-29.9 (twice), the chamfer at Z-0.7, the start at Z0.1.
        let cuts: Vec<_> = cycle.moves.iter().filter(|m| m.kind == MoveKind::Rough && m.from.z == 2.0).collect();
        let got: Vec<(f64, f64)> = cuts.iter().map(|m| (m.from.x / 2.0, (m.to.z * 1e6).round() / 1e6)).collect();
        assert_eq!(got, [(29.0, -44.9), (27.0, -29.9), (25.0, -29.9), (23.0, -0.7), (22.2, 0.1)], "{dialect:?}");
        // Then the cut along the shifted contour, ending at X62.4 Z-44.9, and the rapid back to A.
        let last_rough = cycle.moves.iter().rfind(|m| m.kind == MoveKind::Rough).unwrap();
        pt(last_rough.to, 62.4, -44.9);
        let back = cycle.moves.iter().rfind(|m| m.line == 5).unwrap();
        assert_eq!(back.kind, MoveKind::Rapid);
        pt(back.to, 62.0, 2.0);
    }
}

/// Roughing alone (no G70): the contour is read, not run: no moves on its
/// lines (G72 and G73 alike: their passes are the cycle block's).
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

/// A G76 after G70: the cycle's crest is its own (X27.4 + 2 × 1.3 = 30), and
/// the thread check measures the major the program turned for it against
/// the designation's limits — M30×2-6g: major 29.682 … 29.962 (ISO 965-2,
/// table of limits for 6g; d = 30, es = −0.038, Td = 0.28). Turned at X30 the
/// major is outside; at X29.8 it gauges.
#[test]
fn a_cycle_thread_checks_the_major_the_program_turned() {
    let text = |major: &str| {
        format!(
            "O0072 (M30x2-6g)\nG21 G97 S800 M03 T0101\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n\
             N10 G00 X26.\nG01 X{major} Z-2. F0.1\nZ-40.\nX44.\nZ-60.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\n\
             T0303 S500\nG00 X32. Z5.\nG76 P020060 Q100 R0.1\nG76 X27.4 Z-36. P1300 Q400 F2.\nG00 X100. Z100.\nM30\n"
        )
    };
    let plan = plan_with(&text("30."), Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.crest_source, screwcut::thread::CrestSource::Cycle);
    eq(t.crest, 30.0);
    eq(t.turned.expect("the turned surface under the thread"), 30.0);
    let fail = plan.with_code(Code::GaugeFail).next().expect("the turned major is outside 6g");
    assert!(fail.message.contains("the turned major diameter X30 is outside 29.682 … 29.962"), "{}", fail.message);
    let plan = plan_with(&text("29.8"), Dialect::Fanuc0i, &[]);
    eq(plan.threads[0].turned.unwrap(), 29.8);
    assert!(plan.with_code(Code::GaugeFail).next().is_none(), "{:?}", plan.diagnostics);
    assert!(plan.with_code(Code::GaugeOk).next().is_some());
}

/// The part in the side section: the finished outline G70 runs, filled
/// down to the spindle axis behind everything (GSK980TDc, G32 passes cut on
/// the diameter it turned: crest X30 from the outline, no assumed crest).
#[test]
fn the_part_is_filled_under_its_turned_outline() {
    use screwcut::diagram::{Shape, Style, side};
    let text = "O0073\nG50 X100. Z100.\nT0101 S800 M03\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n\
                N10 G00 X26.\nG01 X30. Z-2. F0.1\nZ-40.\nX44.\nZ-60.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\n\
                T0303 S500\nG00 X32. Z5.\nX29.1\nG32 Z-36. F2.\nG00 X32.\nZ5.\nX27.4\nG32 Z-36. F2.\nG00 X32.\nZ5.\nM30\n";
    let plan = plan_with(text, Dialect::Gsk980tdc, &[]);
    no_alarm(&plan);
    assert_eq!(plan.threads[0].crest_source, screwcut::thread::CrestSource::Outline);
    eq(plan.threads[0].crest, 30.0);
    assert!(plan.with_code(Code::CrestAssumed).next().is_none());
    let scene = side(&plan);
    let parts: Vec<_> = scene.items.iter().filter(|i| i.style == Style::Material).collect();
    assert_eq!(parts.len(), 1, "one run of feeds from X26 Z2 to X52 Z-60");
    assert_eq!(scene.items.iter().position(|i| i.style == Style::Material), Some(1), "behind all but the axis");
    let Shape::Polygon { points } = &parts[0].shape else { panic!("a polygon") };
    // From the axis under the contour's start, along it, back to the axis under its end.
    // (The shoulder at r 22 lies beyond the radial break at r 15 + 0.65: drawn compressed, diagram::radial.)
    // The chamfer starts at X26 Z2, where N10's rapid left the tool.
    assert_eq!(points.first(), Some(&[2.0, 0.0]));
    assert_eq!(&points[1..4], &[[2.0, 13.0], [-2.0, 15.0], [-40.0, 15.0]]);
    assert_eq!(points.last().map(|p| p[0]), Some(-60.0));
    assert!(parts[0].lines.is_empty(), "hovering the part marks nothing");
}

/// The roughing cuts are drawn on demand: the side section's display list
/// leaves them out unless the view asks (the app's "Roughing", `screwcut svg --roughing`).
#[test]
fn roughing_is_drawn_on_demand() {
    use screwcut::draw::{View, display};
    let plan = plan_with(
        &program(&format!("G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n{CONTOUR}"), "G70 P10 Q20\n"),
        Dialect::Fanuc0i,
        &[],
    );
    let scene = screwcut::diagram::side(&plan);
    assert!(scene.items.iter().any(|i| i.style == screwcut::diagram::Style::Roughing));
    let uses_roughing_pen = |v: &View| {
        let l = display(&scene, v);
        l.pens.iter().any(|p| p.stroke.as_deref() == Some("#a5b4c8"))
    };
    assert!(!uses_roughing_pen(&View::default()), "hidden at first");
    assert!(uses_roughing_pen(&View { roughing: true, ..View::default() }), "shown on demand");
}

/// Planning again after an edit gives the plan a full reading gives, also
/// where the planner's checkpoint (every 256 blocks) falls inside a contour
/// a G71 is reading: the reading's state is in the checkpoint.
#[test]
fn a_roughing_cycle_across_a_checkpoint_plans_again_as_in_full() {
    let mut text = String::from("G50 X100. Z100.\nT0101 S800 M03\n");
    for k in 0..240 {
        text += &format!("G00 X{}. Z{}.\n", 80 + k % 7, 60 + k % 5);
    }
    text += "G00 X62. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z0. F0.1\n";
    for k in 0..30 {
        text += &format!("X{}. Z-{}.\n", 20 + k, 2 * k + 2);
    }
    text += "N20 X62.\nG70 P10 Q20\nG00 X70. Z5.\nX47.1\nG32 Z-20. F2.\nG00 X70.\nZ5.\nM30\n";
    let s = screwcut::Settings::new(Dialect::Fanuc0i);
    let edits = [
        text.replace("X35. Z-32.", "X35.5 Z-32."), // inside the contour, after the checkpoint
        text.replace("X21. Z-4.", "X21.2 Z-4."),   // inside the contour, before it
        text.replace("G71 U1.5 R0.5", "G71 U1.2 R0.5"), // the depth of cut
        text.replace("X47.1", "X47.0"),            // the thread after it
        text.clone(),
    ];
    let mut planner = screwcut::planner::Planner::new(s.clone());
    planner.plan(&text);
    assert!(planner.last().unwrap().moves.iter().any(|m| m.kind == MoveKind::Rough));
    for (k, t) in edits.iter().enumerate() {
        assert_ne!(k == 4, t != &text);
        let inc = planner.plan(t).clone();
        assert_eq!(inc, screwcut::plan(t, &s), "edit {k}");
    }
}

/// LinuxCNC's G70 `Q- X- Z- F-` runs the profile of subroutine o(Q) once
/// as the finishing pass, the moves the G70 block's (rs274 2.9 makes the
/// profile's first move a traverse and feeds the rest; the whole program is
/// compared with rs274 move for move in tests/linuxcnc_owords.rs,
/// `oword-g70-*`): the subroutine's blocks move nothing in line, the tool
/// ends where the profile does, and a thread cut after it takes its crest
/// from the outline, which the side section fills as the part. With D and
/// P it runs P passes, the first D from the profile, the last on it (E0):
/// those off the profile are roughing.
#[test]
fn linuxcnc_g70_runs_its_profile_subroutine_as_the_part() {
    use screwcut::diagram::{Style, side};
    use screwcut::motion::MoveKind;
    let text = std::fs::read_to_string("tests/linuxcnc/oword-g70-sought.ngc").unwrap();
    let plan = plan_with(&text, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    let g70: Vec<_> = plan.moves.iter().filter(|m| m.line == 5).collect();
    let ends: Vec<(MoveKind, f64, f64)> = g70.iter().map(|m| (m.kind, m.to.x, m.to.z)).collect();
    // Radius mode (G8): the profile's X6 … X11 are radii, diameters 12 … 22.
    assert_eq!(
        ends,
        [
            (MoveKind::Rapid, 12.0, 0.5),
            (MoveKind::Feed, 16.0, -0.5),
            (MoveKind::Feed, 16.0, -15.0),
            (MoveKind::Feed, 22.0, -15.0)
        ]
    );
    assert!(plan.moves.iter().all(|m| m.line < 13), "the subroutine's blocks move nothing in line");
    assert_eq!(plan.threads[0].crest_source, screwcut::thread::CrestSource::Outline);
    eq(plan.threads[0].crest, 16.0);
    assert!(side(&plan).items.iter().any(|i| i.style == Style::Material), "the part is drawn");
    // D1 P2: passes at 0.5 (distance (2 − 1)·(1 − 0)/2) and 0; the first
    // starts 0.5 out from X6 Z0.5 square to the chamfer's start.
    let passes = text.replace("G70 Q200 X12 Z2 F80", "G70 Q200 X12 Z2 D1 P2 F80");
    let plan = plan_with(&passes, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    let g70: Vec<_> = plan.moves.iter().filter(|m| m.line == 5).collect();
    let kinds: Vec<MoveKind> = g70.iter().map(|m| m.kind).collect();
    assert!(kinds.starts_with(&[MoveKind::Rapid, MoveKind::Rough]), "{kinds:?}");
    assert_eq!(kinds.iter().filter(|k| **k == MoveKind::Feed).count(), 3, "the last pass runs on the profile");
    assert!(plan.with_code(Code::NotSimulated).all(|d| d.line != 5));
    eq(plan.threads[0].crest, 16.0);
    // Under cutter compensation rs274 runs G70 (not G71/G72); the path is the tip's, said where G42.1 is.
    let comp = text.replace("G70 Q200 X12 Z2 F80", "G42.1 D0.4\nG0 X20 Z5\nG70 Q200 X12 Z2 F80");
    let plan = plan_with(&comp, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    assert_eq!(plan.moves.iter().filter(|m| m.line == 7 && m.kind == MoveKind::Feed).count(), 3);
    assert!(plan.with_code(Code::NotSimulated).any(|d| d.line == 5 && d.message.contains("compensation")));
}

/// LinuxCNC's G71 `Q- X- Z- D- I- R-` roughs over the profile of
/// subroutine o(Q) (`cycle::g7x`; every move compared with rs274's in
/// tests/linuxcnc_owords.rs, `oword-g71-*`): the cuts at each depth are
/// roughing, drawn faintly; with D0 the last pass runs on the profile
/// itself, the part's outline, so the G33 passes after it take their crest
/// there (X16) and the side section fills the part. With a distance D the last
/// pass leaves stock: it is roughing too, the crest is not the program's
/// until a G70 turns the profile.
#[test]
fn linuxcnc_g71_roughs_its_profile_subroutine_and_d0_turns_the_part() {
    use screwcut::diagram::{Style, side};
    use screwcut::thread::CrestSource;
    let text = std::fs::read_to_string("tests/linuxcnc/oword-g71-thread.ngc").unwrap();
    let plan = plan_with(&text, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    let g71: Vec<_> = plan.moves.iter().filter(|m| m.line == 12).collect();
    let rough = g71.iter().filter(|m| m.kind == MoveKind::Rough).count();
    // Radius 13 down to 6.5 in steps of 1.2: 6 depths, each cut once.
    assert_eq!(rough, 6, "{g71:?}");
    let outline: Vec<(f64, f64)> = g71.iter().filter(|m| m.kind == MoveKind::Feed).map(|m| (m.to.x, m.to.z)).collect();
    assert_eq!(outline, [(16.0, -1.5), (16.0, -20.0), (22.0, -20.0), (22.0, -28.0), (26.0, -28.0)]);
    assert!(plan.moves.iter().all(|m| !(5..=9).contains(&m.line)), "the subroutine's blocks move nothing in line");
    assert_eq!(plan.threads[0].crest_source, CrestSource::Outline);
    eq(plan.threads[0].crest, 16.0);
    let scene = side(&plan);
    assert!(scene.items.iter().any(|i| i.style == Style::Material), "the part is drawn");
    assert!(scene.items.iter().any(|i| i.style == Style::Roughing), "the cuts are drawn as roughing");
    // D0.3: the last pass is 0.6 over the diameter, roughing; no outline under the thread.
    let d = text.replace("D0 I1.2", "D0.3 I1.2");
    let plan = plan_with(&d, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    assert!(plan.moves.iter().filter(|m| m.line == 12).all(|m| matches!(m.kind, MoveKind::Rough | MoveKind::Rapid)));
    assert_ne!(plan.threads[0].crest_source, CrestSource::Outline);
    // A G70 then finishes it: the crest is the profile's X16 again, not the roughing's X16.6.
    let g70 = d.replace("G0 X26 Z3\nG0 X15.2", "G70 Q200 X26 Z3 F80\nG0 X26 Z3\nG0 X15.2");
    let plan = plan_with(&g70, Dialect::LinuxCnc, &[]);
    no_alarm(&plan);
    assert_eq!(plan.threads[0].crest_source, CrestSource::Outline);
    eq(plan.threads[0].crest, 16.0);
}

/// Planning again after an edit gives a full reading's plan also for a
/// LinuxCNC G71 whose profile subroutine comes after the program's end
/// and after the planner's checkpoint (every 256 blocks): edits of the
/// profile, of the cycle's words and of the thread after it.
#[test]
fn a_linuxcnc_roughing_across_a_checkpoint_plans_again_as_in_full() {
    let mut text = String::from("G18 G21 G90 G7\nM3 S600\n");
    for k in 0..240 {
        text += &format!("G0 X{} Z{}\n", 40 + k % 7, 20 + k % 5);
    }
    text +=
        "G0 X40 Z2\nG71 Q300 X40 Z2 D0.3 I1 R0.5 F120\nG0 X40 Z2\nX29\nG33 Z-20 K2\nG0 X40\nM2\no300 sub\nG1 X20 Z0\n";
    // A staircase: steps of 0.5 (diameter) and 1 along Z, no two moves along one line.
    for k in 0..30 {
        text += &if k % 2 == 0 {
            format!("G1 Z-{}\n", k / 2 + 1)
        } else {
            format!("G1 X{}\n", 20.0 + 0.5 * f64::from(k / 2 + 1))
        };
    }
    text += "G1 Z-18\nG1 X36\no300 endsub\n";
    let s = screwcut::Settings::new(Dialect::LinuxCnc);
    let edits = [
        text.replace("G1 X24\n", "G1 X24.2\n"), // inside the profile, after the checkpoint
        text.replace("D0.3 I1", "D0.2 I1"),     // the cycle's words
        text.replace("X29\n", "X28.8\n"),       // the thread after it
        text.replace("G1 X36\n", "G1 X35\nG1 Z-40\n"), // the profile's end
        text.clone(),
    ];
    let mut planner = screwcut::planner::Planner::new(s.clone());
    planner.plan(&text);
    assert!(planner.last().unwrap().moves.iter().any(|m| m.kind == MoveKind::Rough));
    for (k, t) in edits.iter().enumerate() {
        assert_ne!(k == 4, t != &text, "edit {k}");
        let inc = planner.plan(t).clone();
        assert_eq!(inc, screwcut::plan(t, &s), "edit {k}");
    }
}

/// The motions of the block on `line`: (kind, X, Z) of each end, rounded to 1e-6.
fn ends_of(plan: &Plan, line: u32) -> Vec<(MoveKind, f64, f64)> {
    let r = |v: f64| (v * 1e6).round() / 1e6;
    plan.moves.iter().filter(|m| m.line == line).map(|m| (m.kind, r(m.to.x), r(m.to.z))).collect()
}

/// Fanuc 0i, G73 (pattern repeating; YASNAC LX3 manual §2.8.2.5.4, the
/// tool path A → A′ → B, whose words are Fanuc's U, W, R; Fanuc concise
/// guide "G73 profile repetition": the profile repeated R times, moved
/// each time, U the radial stock to remove): Δi 3 (radius), Δk 0, d 3,
/// Δu 0.4, Δw 0.1 shift the three passes by 3·2/2 + 0.2 = 3.2, 3·1/2 + 0.2
/// = 1.7 and 0.2 across (diameters 6.4, 3.4, 0.4) and 0.1 along Z. Each
/// is a rapid from A (X60 Z5) to the shifted A′, the shifted contour fed,
/// a rapid back to A. G70 then turns the contour itself, the outline under
/// the G76 after it: its crest is its own (27.4 + 2 × 1.3 = 30) and the
/// turned major X30 is measured, no crest assumed.
#[test]
fn fanuc_g73_cuts_the_contour_d_times_towards_it() {
    let text = "O0073\nG21 G97 S800 M03 T0101\nG00 X60. Z5.\nG73 U3. W0. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\n\
                N10 G00 X26. Z2.\nG01 X30. Z-2. F0.1\nZ-30.\nX40. Z-40.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\n\
                T0303 S500\nG00 X34. Z5.\nG76 P020060 Q100 R0.1\nG76 X27.4 Z-26. P1300 Q400 F2.\nG00 X100. Z100.\nM30\n";
    let plan = plan_with(text, Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let (rapid, rough) = (MoveKind::Rapid, MoveKind::Rough);
    let pass = |dx: f64| {
        let r = |v: f64| (v * 1e6).round() / 1e6;
        vec![
            (rapid, r(26.0 + dx), 2.1),
            (rough, r(30.0 + dx), -1.9),
            (rough, r(30.0 + dx), -29.9),
            (rough, r(40.0 + dx), -39.9),
            (rough, r(52.0 + dx), -39.9),
            (rapid, 60.0, 5.0),
        ]
    };
    let expected: Vec<_> = [6.4, 3.4, 0.4].into_iter().flat_map(pass).collect();
    assert_eq!(ends_of(&plan, 5), expected);
    // The first pass starts at X32.4 Z2.1 (radius 16.2 = 13 + 3.2), the last at X26.4 (13 + 0.2).
    assert!(plan.with_code(Code::NotSimulated).all(|d| d.line != 4 && d.line != 5), "{:?}", plan.diagnostics);
    // G70 runs the contour on its own lines; the thread measures the diameter it turned.
    assert_eq!(plan.moves.iter().filter(|m| (6..=10).contains(&m.line)).count(), 5);
    let t = &plan.threads[0];
    eq(t.crest, 30.0);
    eq(t.turned.expect("the outline under the thread"), 30.0);
    assert!(plan.with_code(Code::CrestAssumed).next().is_none());
}

/// GSK980TDc reads the same two blocks (its R is the number of passes
/// too): Δi 4, Δk 1, d 2, Δu 0.5, Δw 0.2 put the first pass 4 + 0.25 =
/// 4.25 across (diameter 8.5) and 1.2 along Z off the contour, the second
/// at the allowance (0.25, 0.2). With R1 the one pass is at the allowance.
/// The G32 passes after G70 take their crest from the outline, X30.
#[test]
fn gsk_g73_and_one_division() {
    let text = |r: &str| {
        format!(
            "O0074\nG50 X100. Z100.\nT0101 S800 M03\nG00 X66. Z3.\nG73 U4. W1. R{r}\nG73 P10 Q20 U0.5 W0.2 F0.25\n\
             N10 G00 X24. Z1.\nG01 X30. Z-2. F0.1\nZ-28.\nX44. Z-40.\nN20 X54.\nG70 P10 Q20\nG00 X100. Z100.\n\
             T0303 S500\nG00 X32. Z5.\nX29.1\nG32 Z-26. F2.\nG00 X32.\nZ5.\nX27.4\nG32 Z-26. F2.\nG00 X32.\nZ5.\nM30\n"
        )
    };
    let plan = plan_with(&text("2"), Dialect::Gsk980tdc, &[]);
    no_alarm(&plan);
    let (rapid, rough) = (MoveKind::Rapid, MoveKind::Rough);
    assert_eq!(
        ends_of(&plan, 6),
        [
            (rapid, 32.5, 2.2),
            (rough, 38.5, -0.8),
            (rough, 38.5, -26.8),
            (rough, 52.5, -38.8),
            (rough, 62.5, -38.8),
            (rapid, 66.0, 3.0),
            (rapid, 24.5, 1.2),
            (rough, 30.5, -1.8),
            (rough, 30.5, -27.8),
            (rough, 44.5, -39.8),
            (rough, 54.5, -39.8),
            (rapid, 66.0, 3.0),
        ]
    );
    assert_eq!(plan.threads[0].crest_source, screwcut::thread::CrestSource::Outline);
    eq(plan.threads[0].crest, 30.0);
    assert!(plan.with_code(Code::CrestAssumed).next().is_none());
    // d = 1: one pass, at the allowance.
    let one = plan_with(&text("1"), Dialect::Gsk980tdc, &[]);
    no_alarm(&one);
    assert_eq!(ends_of(&one, 6), ends_of(&plan, 6)[6..].to_vec());
}

/// G73's bad words are alarms at the word, and nothing is cut: R0 and a
/// fractional R (d is a whole number of passes, 1 or more), R over
/// `limits.passes_per_start`, a relief U/W with no R before any R. Without
/// any first block the passes are not drawn, said once. A G71 depth of 0 is
/// an alarm too (Fanuc's PS0062). A long contour cut many times stops at
/// the motion bound with an alarm at the cycle block.
#[test]
fn g73_bad_words_are_alarms() {
    let text = |first: &str| {
        format!(
            "O0075\nG21 T0101 S800 M03\nG00 X60. Z5.\n{first}G73 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X26. Z2.\nG01 Z-30. F0.1\nN20 X52.\nM30\n"
        )
    };
    let cut = |plan: &Plan| plan.moves.iter().filter(|m| m.kind == MoveKind::Rough).count();
    for dialect in [Dialect::Fanuc0i, Dialect::Gsk980tdc] {
        let good = plan_with(&text("G73 U3. W0. R3\n"), dialect, &[]);
        no_alarm(&good);
        assert_eq!(cut(&good), 6);
        for (first, code, col, what) in [
            ("G73 U3. W0. R0\n", Code::ValueOutOfRange, 13, "1 or more"),
            ("G73 U3. W0. R2.5\n", Code::ValueOutOfRange, 13, "whole number"),
            ("G73 U3. W0. R1000\n", Code::PassLimit, 13, "1000 passes: more than 999"),
            ("G73 U3. W0.\n", Code::MissingWord, 1, "no number of divisions R(d)"),
        ] {
            let plan = plan_with(&text(first), dialect, &[]);
            let d = at(&plan, code, 4, col);
            assert!(d.message.contains(what), "{}", d.message);
            assert_eq!(cut(&plan), 0, "{first}");
        }
        let few = plan_with(&text("G73 U3. W0. R6\n"), dialect, &["limits.passes_per_start=5"]);
        at(&few, Code::PassLimit, 4, 13);
        let none = plan_with(&text(""), dialect, &[]);
        assert!(at(&none, Code::NotSimulated, 4, 1).message.contains("G73"));
        assert_eq!(cut(&none), 0);
        let g71 = plan_with(&text("G71 U0 R0.5\n").replace("G73 P", "G71 P"), dialect, &[]);
        at(&g71, Code::ValueOutOfRange, 4, 5);
    }
    // 999 passes of a contour of 100 moves, each with its rapid in and out: 999 × 101 = 100,899
    // motions, over the 80,000 of one cycle.
    let mut long =
        String::from("O0076\nG21 T0101 S800 M03\nG00 X60. Z5.\nG73 U3. W0. R999\nG73 P10 Q20 F0.2\nN10 G00 X20. Z2.\n");
    for k in 1..99 {
        long += &format!("G01 Z-{k}.\n");
    }
    long += "N20 X52.\nM30\n";
    let plan = plan_with(&long, Dialect::Fanuc0i, &[]);
    let d = at(&plan, Code::PassLimit, 5, 1);
    assert!(d.message.contains("100899 motions"), "{}", d.message);
    assert_eq!(cut(&plan), 0);
}

/// The contour with one pocket of `pockets` (a rise to X50 at Z-20, down to
/// X40 at Z-30 … Z-40, up to X56 at Z-45), its first block `first`.
fn pocket_program(first: &str) -> String {
    format!(
        "O0077\nG21 G97 S800 M03 T0101\nG00 X62. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n{first}\n\
         G01 Z-10. F0.1\nX50. Z-20.\nZ-25.\nX40. Z-30.\nZ-40.\nX56. Z-45.\nZ-55.\nN20 X62.\nG70 P10 Q20\nG00 X100. Z100.\nM30\n"
    )
}

/// Fanuc 0i, G71 type II: the contour's first block moves both axes (Z2.
/// beside X30.), so it may go down again along X: a pocket between the
/// rise to X50 and the wall up to X56. Depths of 2 (radius) from A (r31)
/// over the shape shifted by Δu/2 = 0.2 and Δw = 0.1: from Z2 each cut
/// ends at the first rise — r29 at the last wall (Z-54.9), r27 on the
/// rise r20.2 → r28.2 (Z-39.9 − 5·6.8/8 = Z-44.15), r25 … r17 on the rise
/// r15.2 → r25.2 (Z-9.9 − (r − 15.2)), r15.2 (A′) to Z-9.9; then the
/// pocket, entered down the wall from the top of the rise (r25.2): r25 from
/// Z-25.1 (Z-24.9 − 5·0.2/5) to Z-42.9 (Z-39.9 − 5·4.8/8),
/// r23 from Z-27.1 to Z-41.65, r21 from Z-29.1 to Z-40.4 (its floor r20.2
/// is above r19). Type I (the first block X30. alone) refuses the same
/// contour; GSK980TDc, which has type I only, refuses it either way; a
/// contour going back along Z is refused by both types.
#[test]
fn fanuc_type_ii_roughs_a_pocket() {
    let plan = plan_with(&pocket_program("N10 G00 X30. Z2."), Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let level = |m: &&screwcut::motion::Move| {
        m.line == 5
            && m.kind == MoveKind::Rough
            && (m.from.x - m.to.x).abs() < 1e-9
            && (m.from.x / 2.0).fract().abs() < 1e-9
    };
    let r6 = |v: f64| (v * 1e6).round() / 1e6;
    let cuts: Vec<(f64, f64, f64)> =
        plan.moves.iter().filter(level).map(|m| (m.from.x / 2.0, r6(m.from.z), r6(m.to.z))).collect();
    assert_eq!(
        cuts,
        [
            (29.0, 2.0, -54.9),
            (27.0, 2.0, -44.15),
            (25.0, 2.0, -19.7),
            (23.0, 2.0, -17.7),
            (21.0, 2.0, -15.7),
            (19.0, 2.0, -13.7),
            (17.0, 2.0, -11.7),
            (25.0, -25.1, -42.9),
            (23.0, -27.1, -41.65),
            (21.0, -29.1, -40.4),
        ]
    );
    // The cut at A′'s depth (r15.2) and the last cut along the shifted shape, which ends at X62.4 Z-54.9.
    assert!(
        plan.moves.iter().any(|m| m.line == 5 && m.kind == MoveKind::Rough && m.from.z == 2.0 && r6(m.to.z) == -9.9)
    );
    let last = plan.moves.iter().rfind(|m| m.line == 5 && m.kind == MoveKind::Rough).unwrap();
    pt(last.to, 62.4, -54.9);
    // G70 runs the contour itself.
    assert_eq!(plan.moves.iter().filter(|m| (6..=14).contains(&m.line)).count(), 9);

    let one = plan_with(&pocket_program("N10 G00 X30."), Dialect::Fanuc0i, &[]);
    let d = at(&one, Code::ContourNotMonotone, 5, 1);
    assert!(d.message.contains("first block moves X only (type I"), "{}", d.message);
    assert!(one.moves.iter().all(|m| m.line != 5), "not roughed");
    for first in ["N10 G00 X30.", "N10 G00 X30. Z2."] {
        let gsk = plan_with(&pocket_program(first), Dialect::Gsk980tdc, &[]);
        let d = at(&gsk, Code::ContourNotMonotone, 5, 1);
        assert!(d.message.contains("GSK980TDc roughs a shape monotone along X and Z only"), "{}", d.message);
    }
    let back = pocket_program("N10 G00 X30. Z2.").replace("Z-55.", "Z-42.");
    let d = at(&plan_with(&back, Dialect::Fanuc0i, &[]), Code::ContourNotMonotone, 5, 1);
    assert!(d.message.contains("goes back along Z"), "{}", d.message);
}
