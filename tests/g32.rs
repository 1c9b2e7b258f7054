//! G32 (GSK980TDc, reference §2): each J/K run-out rule, No.107, the Q rules,
//! long/short axis, face and continuous threads, F and I.

mod common;
use common::*;
use screwcut::motion::MoveKind;
use screwcut::thread::{Axis, ThreadKind};
use screwcut::{Code, Dialect};

fn runouts(plan: &screwcut::Plan) -> Vec<(screwcut::motion::Point, screwcut::motion::Point)> {
    plan.moves.iter().filter(|m| m.kind == MoveKind::Runout).map(|m| (m.from, m.to)).collect()
}

const START: &str = "G00 X40 Z5\n";

/// J and K given: the cut stops K before the end on the long axis (Z), and
/// the run-out ends J (radius) outward: Z5→Z−30 is 35 long; K4 → cut to Z−26;
/// J2 → X40 + 2·2 = X44 at Z−30.
#[test]
fn j_and_k_run_out() {
    let plan = gsk(&format!("{START}G32 Z-30 F2 J2 K4\n"));
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.from, 40.0, 5.0);
    pt(p.to, 40.0, -26.0);
    pt(p.runout_to.unwrap(), 44.0, -30.0);
    let r = runouts(&plan);
    assert_eq!(r.len(), 1);
    pt(r[0].0, 40.0, -26.0);
    pt(r[0].1, 44.0, -30.0);
}

/// Rules 1–2: J omitted, or J and K omitted: no run-out.
#[test]
fn j_omitted_no_run_out() {
    for src in ["G32 Z-30 F2\n", "G32 Z-30 F2 K4\n"] {
        let plan = gsk(&format!("{START}{src}"));
        no_alarm(&plan);
        assert!(runouts(&plan).is_empty(), "{src}");
        pt(plan.threads[0].passes[0].to, 40.0, -30.0);
        assert_eq!(plan.threads[0].passes[0].runout_to, None);
    }
}

/// Rule 2: K omitted → K = J (45°): J−1.5 (inward, an internal thread's run-out)
/// gives a cut to Z−28.5 and a run-out to X37 at Z−30.
#[test]
fn k_omitted_is_j() {
    let plan = gsk(&format!("{START}G32 Z-30 F2 J-1.5\n"));
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.to, 40.0, -28.5);
    pt(p.runout_to.unwrap(), 37.0, -30.0);
}

/// Rules 3 and 5: J = 0 (with K = 0, or with K ≠ 0): no run-out.
#[test]
fn j_zero_no_run_out() {
    for src in ["G32 Z-30 F2 J0\n", "G32 Z-30 F2 J0 K0\n", "G32 Z-30 F2 J0 K5\n"] {
        let plan = gsk(&format!("{START}{src}"));
        no_alarm(&plan);
        assert!(runouts(&plan).is_empty(), "{src}");
    }
}

/// Rule 4: J ≠ 0, K = 0 → K = J.
#[test]
fn k_zero_is_j() {
    let plan = gsk(&format!("{START}G32 Z-30 F2 J3 K0\n"));
    let p = &plan.threads[0].passes[0];
    pt(p.to, 40.0, -27.0);
    pt(p.runout_to.unwrap(), 46.0, -30.0);
}

/// J/K are modal across consecutive thread blocks (note 1) and cancelled by a
/// non-thread motion block.
#[test]
fn j_k_modal_and_cancelled() {
    // Two continuous blocks: the second, without J/K, retracts as the first.
    let plan = gsk(&format!("{START}G32 Z-10 F2 J1 K2\nZ-30\nG00 X50\nZ5\nX40\nG32 Z-30 F2\n"));
    no_alarm(&plan);
    let r = runouts(&plan);
    assert_eq!(r.len(), 2, "{r:?}");
    // Block 2: J1 K2 → cut from (42, −10) to Z−28, run-out to X44 Z−30.
    pt(r[1].0, 42.0, -28.0);
    pt(r[1].1, 44.0, -30.0);
    // After G00 (a non-thread motion) the last G32 has no run-out.
    assert_eq!(plan.threads.len(), 2);
    assert_eq!(plan.threads[1].passes[0].runout_to, None);
    // A block without motion (M08) does not cancel the modal J/K.
    let plan = gsk(&format!("{START}G32 Z-10 F2 J1\nM08\nG32 Z-30\n"));
    assert_eq!(runouts(&plan).len(), 2);
}

/// The run-out of a face thread (long axis X) is along Z: J is a Z amount,
/// K a radius length of X.
#[test]
fn face_thread_run_out_on_z() {
    let plan = gsk("G00 X20 Z0\nG32 X60 F3 J1 K2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.kind, ThreadKind::Face);
    assert_eq!(t.long_axis, Axis::X);
    // X20 → X60 is 20 of radius; K2 (radius) stops the cut at X56; J1 ends at Z1.
    pt(t.passes[0].to, 56.0, 0.0);
    pt(t.passes[0].runout_to.unwrap(), 60.0, 1.0);
}

/// A run-out longer than the thread is an alarm at the K word.
#[test]
fn run_out_longer_than_thread() {
    let plan = gsk(&format!("{START}G32 W-10 F2 J1 K12\n"));
    let d = at(&plan, Code::RunoutTooLong, 2, 16);
    assert!(d.message.contains("12") && d.message.contains("10"), "{}", d.message);
}

/// No.107 ≠ 0: the short axis retracts at No.107 mm/min while Z feeds at
/// lead × S = 2 × 300 = 600 mm/min, so J2 takes 2 × 600 / 400 = 3 mm of Z
/// (K4 is not used): the cut ends at Z−27.
#[test]
fn parameter_107_run_out_speed() {
    let src = format!("{START}S300 M03\nG32 Z-30 F2 J2 K4\n");
    let plan = plan_with(&src, Dialect::Gsk980tdc, &["No.107=400"]);
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.to, 40.0, -27.0);
    pt(p.runout_to.unwrap(), 44.0, -30.0);
    let d = at(&plan, Code::RunoutSpeed, 3, 13);
    assert!(d.message.contains("No.107") && d.message.contains("600"), "{}", d.message);
    // Without S the rule cannot apply: J/K are used and the note says so.
    let plan = plan_with(&format!("{START}G32 Z-30 F2 J2 K4\n"), Dialect::Gsk980tdc, &["No.107=400"]);
    pt(plan.threads[0].passes[0].to, 40.0, -26.0);
    assert!(one(&plan, Code::RunoutSpeed).message.contains("unknown"));
}

/// Q: NO182.7 = 0 reads increments of 0.001°, with or without a decimal point
/// (Q180 and Q180.0 are 0.18°; Q180000 is 180°); NO182.7 = 1 reads degrees.
#[test]
fn q_units() {
    let angle = |q: &str, sets: &[&str]| {
        let plan = plan_with(&format!("{START}G32 Z-30 F2 {q}\n"), Dialect::Gsk980tdc, sets);
        no_alarm(&plan);
        plan.threads[0].passes[0].angle
    };
    eq(angle("Q180", &[]), 0.18);
    eq(angle("Q180.0", &[]), 0.18);
    eq(angle("Q180000", &[]), 180.0);
    eq(angle("", &[]), 0.0);
    eq(angle("Q180", &["NO182.7=1"]), 180.0);
    eq(angle("Q90.5", &["NO182.7=1"]), 90.5);
    // IS-C: increments of 0.0001°.
    eq(angle("Q1800000", &["increment=is-c"]), 180.0);
    // Out of range.
    let plan = gsk(&format!("{START}G32 Z-30 F2 Q360001\n"));
    at(&plan, Code::ValueOutOfRange, 2, 13);
}

/// Q counts only on the first block of a continuous thread; later Q warns and is ignored.
#[test]
fn q_ignored_in_continuous_thread() {
    let plan = gsk(&format!("{START}G32 W-10 F2 Q90000\nG32 W-10 Q180000\n"));
    no_alarm(&plan);
    let d = at(&plan, Code::QIgnored, 3, 10);
    assert!(d.message.contains("Q180000"));
    let t = &plan.threads[0];
    assert_eq!(t.passes.len(), 1);
    eq(t.passes[0].angle, 90.0);
}

/// Q is not modal: passes cut with Q0 and Q180000 are one two-start thread,
/// each start with its own pass sequence.
#[test]
fn q_multi_start() {
    let mut src = String::new();
    for x in [39.0, 38.0] {
        for q in [0, 180000] {
            src += &format!("G00 X45 Z5\nX{x}\nG32 Z-30 F4 Q{q}\n");
        }
    }
    let plan = gsk(&src);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!(t.starts, 2);
    eq(t.lead, 4.0);
    eq(t.pitch, 2.0);
    let order: Vec<(u32, u32)> = t.passes.iter().map(|p| (p.start, p.index)).collect();
    assert_eq!(order, vec![(1, 1), (2, 1), (1, 2), (2, 2)]);
    eq(t.passes[1].angle, 180.0);
    // Each start's second pass is 0.5 deeper (radial) than its first.
    eq(t.passes[2].infeed, 0.5);
    eq(t.passes[3].infeed, 0.5);
    // More starts than limits.starts is an alarm at the first block over it.
    let plan = plan_with(&src, Dialect::Gsk980tdc, &["limits.starts=1"]);
    // The second pass (line 6) brings the second start.
    at(&plan, Code::TooManyStarts, 6, 1);
}

/// Continuous multi-segment thread: consecutive G32 blocks are one pass with
/// its corner points; a straight then a taper piece.
#[test]
fn continuous_thread_segments() {
    let plan = gsk(&format!("{START}G32 Z-20 F1.5\nX50 Z-30\nG00 X60\n"));
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.passes.len(), 1);
    let p = &t.passes[0];
    pt(p.from, 40.0, 5.0);
    pt(p.to, 50.0, -30.0);
    assert_eq!(p.segments.len(), 3);
    pt(p.segments[1], 40.0, -20.0);
    // The longer piece (25 of Z) is straight: the thread is straight.
    assert_eq!(t.kind, ThreadKind::Straight);
    assert_eq!(p.lines, vec![1, 2, 3, 4]);
}

/// F and I: F is the lead, modal; I is threads per inch: 25.4/I mm in a
/// metric program, 1/I inch in an inch program.
#[test]
fn lead_from_f_and_i() {
    let plan = gsk(&format!("{START}G32 Z-30 I8\n"));
    no_alarm(&plan);
    eq(plan.threads[0].lead, 3.175);
    let plan = gsk(&format!("G20\n{START}G32 Z-30 I8\n"));
    eq(plan.threads[0].lead, 0.125);
    assert_eq!(plan.units, screwcut::plan::Units::Inch);
    // Modal: the second G32 without F keeps lead 1.5; a G01 F0.2 does not change it.
    let plan = gsk(&format!("{START}G32 Z-30 F1.5\nG01 X50 F0.2\nG00 X40 Z5\nG32 Z-30\n"));
    no_alarm(&plan);
    eq(plan.threads[1].lead, 1.5);
    // No lead at all.
    let plan = gsk(&format!("{START}G32 Z-30\n"));
    at(&plan, Code::MissingLead, 2, 1);
    // F and I together.
    let plan = gsk(&format!("{START}G32 Z-30 F2 I8\n"));
    at(&plan, Code::UnexpectedWord, 2, 13);
}

/// The long axis is the larger travel with X counted as a radius, and the lead
/// is measured along it.
#[test]
fn long_axis_x_for_steep_taper() {
    let plan = gsk("G00 X20 Z0\nG32 X60 Z-10 F2\n");
    let t = &plan.threads[0];
    assert_eq!(t.kind, ThreadKind::Taper);
    assert_eq!(t.long_axis, Axis::X);
}

/// Fanuc G32: Q in 0.001° without a decimal point; no J/K/I.
#[test]
fn fanuc_g32_words() {
    let plan = plan_with("G00 X40. Z5.\nG32 Z-30. F2. Q180000\n", Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    eq(plan.threads[0].passes[0].angle, 180.0);
    let plan = plan_with("G00 X40. Z5.\nG32 Z-30. F2. Q180.\n", Dialect::Fanuc0i, &[]);
    at(&plan, Code::DecimalPointNotAllowed, 2, 15);
    let plan = plan_with("G00 X40. Z5.\nG32 Z-30. F2. J2.\n", Dialect::Fanuc0i, &[]);
    at(&plan, Code::UnexpectedWord, 2, 15);
    // One F register: a G32 without F after G01 F0.2 cuts a 0.2 lead, and warns.
    let plan = plan_with("G00 X40. Z5.\nG01 X39. F0.2\nG32 Z-30.\n", Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let d = at(&plan, Code::LeadFromFeed, 3, 1);
    assert!(d.message.contains("F0.2 from line 2"), "{}", d.message);
    eq(plan.threads[0].lead, 0.2);
    // The F of a G32 is the lead again for the next G32 (no warning then).
    let plan = plan_with(
        "G00 X40. Z5.\nG01 X39. F0.2\nG32 Z-30. F2.\nG00 X45.\nZ5.\nX39.\nG32 Z-30.\n",
        Dialect::Fanuc0i,
        &[],
    );
    assert_eq!(plan.with_code(Code::LeadFromFeed).count(), 0);
    eq(plan.threads[0].lead, 2.0);
    // An F0 in the register cannot be a lead: an alarm, no thread.
    let plan = plan_with("F0\nG32 X1\n", Dialect::Fanuc0i, &[]);
    assert!(at(&plan, Code::MissingLead, 2, 1).message.contains("F0 from line 1"));
    assert!(plan.threads.is_empty());
    // GSK keeps them apart: the same program without a lead alarms and says why.
    let plan = gsk("G00 X40 Z5\nG01 X39 F0.2\nG32 Z-30\n");
    assert!(at(&plan, Code::MissingLead, 3, 1).message.contains("F0.2 of line 2"));
}

/// A face thread cut block by block: the infeed and retract are Z moves, the
/// return an X move; each pass lists those lines, and the depth grows in −Z.
#[test]
fn face_thread_passes_group() {
    let plan = gsk("G00 X20 Z2\nZ0.5\nG32 X60 F3\nG00 Z5\nX20\nZ0\nG32 X60\nG00 Z5\nX20\n");
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!((t.kind, t.long_axis), (ThreadKind::Face, Axis::X));
    assert_eq!(t.passes[0].lines, vec![2, 3, 4, 5]);
    assert_eq!(t.passes[1].lines, vec![6, 7, 8, 9]);
    eq(t.passes[1].infeed, 0.5);
    // Crest assumed 1.3 × 3 / 2 = 1.95 above the deepest pass (Z0): Z1.95.
    eq(t.crest, 1.95);
}

/// Fanuc's G32 has no run-out word (0i-TF G32: X Z F Q), so a program
/// writes the chamfer after the cut as a second G32 block. A G32 that
/// continues a thread, leaves the work (against the infeed, X58 → X47.1
/// inward here) and makes `group.runout_angle` (30°) or more with the axis
/// is the pass's run-out: 45° here, 1.5 radius over 1.5 of Z.
#[test]
fn a_fanuc_chamfer_block_is_the_passs_run_out() {
    let pass = "G00 X58. Z70.\nX47.1\nG32 Z13. F2.\nG32 X50.1 Z11.5\nG00 X58.\nZ70.\n";
    let plan = plan_with(pass, Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.to, 47.1, 13.0);
    pt(p.runout_to.unwrap(), 50.1, 11.5);
    assert!(p.segments.is_empty());
    assert_eq!(runouts(&plan).len(), 1);
    assert_eq!(p.lines, [2, 3, 4, 5, 6]);
    // A steeper setting makes it a segment of a continuous thread again.
    let seg = plan_with(pass, Dialect::Fanuc0i, &["group.runout_angle=50"]);
    let q = &seg.threads[0].passes[0];
    pt(q.to, 50.1, 11.5);
    assert_eq!((q.runout_to, q.segments.len(), runouts(&seg).len()), (None, 3, 0));
    // Into the work (X44.1, the way of the infeed) it is a segment.
    let inward = plan_with(&pass.replace("X50.1 Z11.5", "X44.1 Z11.5"), Dialect::Fanuc0i, &[]);
    assert_eq!(inward.threads[0].passes[0].segments.len(), 3);
    // Followed by another G32 it was not the end of the cut: a segment too.
    let on = plan_with(&pass.replace("Z11.5\n", "Z11.5\nG32 Z5.\n"), Dialect::Fanuc0i, &[]);
    let r = &on.threads[0].passes[0];
    pt(r.to, 50.1, 5.0);
    assert_eq!((r.runout_to, r.segments.len()), (None, 4));
}

/// A comment `(crest X…)` between the previous thread and a block-by-block
/// thread states its crest (what `expand` writes for a cycle's thread): the
/// depths are measured from it, not from the 1.3·P assumption (X48.2 −
/// X47.1 = 0.55 radial, then X46.2: 1.0), and the next thread, after the
/// first one's last line, does not take it.
#[test]
fn a_crest_comment_states_the_crest() {
    let pass = |x: &str, z0: &str, z1: &str| format!("G00 X58 Z{z0}\nX{x}\nG32 Z{z1} F2\nG00 X58\nZ{z0}\n");
    let src = format!(
        "(crest X48.2)\n{}{}{}M30\n",
        pass("47.1", "70", "13"),
        pass("46.2", "70", "13"),
        pass("47.1", "-20", "-40")
    );
    let plan = gsk(&src);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 2);
    let t = &plan.threads[0];
    assert_eq!(t.crest_source, screwcut::thread::CrestSource::Comment);
    eq(t.crest, 48.2);
    let depths: Vec<f64> = t.passes.iter().map(|p| (p.depth * 1e9).round() / 1e9).collect();
    assert_eq!(depths, [0.55, 1.0]);
    assert_eq!(plan.threads[1].crest_source, screwcut::thread::CrestSource::Assumed);
    assert_eq!(one(&plan, Code::CrestAssumed).line, 13);
}
