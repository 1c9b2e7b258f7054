//! The G92, G76 and G78 rules as the manuals state them, each with its
//! source and values worked out by hand.
//!
//! Sources (pages as printed):
//! - GSK980TDc Turning CNC System User Manual (English), §3.21.6 "Thread
//!   cutting cycle G92", p.125: "J … it is modal parameter"; "When the sign
//!   of R is not the same that of U, │R│≤│U/2│".
//! - GSK988TA/TA1/TB User Manual [Programming & Operation], G92, p.104: "J …
//!   K … L Multi threads: 1~99 and it is modal parameter".
//! - GSK980TDc manual §3.21.7 "Multiple thread cutting cycle G76" (pp.134–138
//!   of the GSK980TD-family English edition): the definitions of points A,
//!   B, C, D, E, the parameters P(m)(r)(a) ("00~99 … the system parameter
//!   №057 value is rewritten to m", №019 to r, №058 to a), and steps ①–⑩.

mod common;
use common::*;
use screwcut::thread::Role;
use screwcut::{Code, Dialect, Plan};

const TAN30: f64 = 0.5773502691896257;

fn depths(plan: &Plan) -> Vec<f64> {
    plan.threads[0].passes.iter().map(|p| (p.depth * 1e6).round() / 1e6).collect()
}

/// GSK G92: J, K and L are modal. The manual's own example gives J3 K1
/// once (`G92 X58.7 Z-28 F3 J3 K1; X57.7; X57; X56.9;`); here the pass
/// blocks repeat Z, which must not drop them. Every pass: run-out K1 from
/// Z−27 to Z−28, retracting J3 (radius, +6 on X), two starts (L2) 1.5 apart.
#[test]
fn g92_j_k_l_are_modal_with_or_without_z() {
    let plan = gsk("G00 X70 Z5\nG92 X58.7 Z-28 F3 J3 K1 L2\nX57.7 Z-28\nX57\nX56.9 Z-28\n");
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!(t.starts, 2);
    assert_eq!(t.passes.len(), 8, "four passes of two starts");
    for p in &t.passes {
        pt(p.to, p.from.x, -27.0);
        pt(p.runout_to.unwrap(), p.from.x + 6.0, -28.0);
    }
    let xs: Vec<f64> = t.passes.iter().filter(|p| p.start == 1).map(|p| p.from.x).collect();
    assert_eq!(xs, vec![58.7, 57.7, 57.0, 56.9]);
    // A new motion mode ends the cycle and its modal words: a later G92 is single-start, No.019 run-out.
    let plan = gsk("G00 X70 Z5\nG92 X58.7 Z-28 F3 J3 K1 L2\nG00 X70 Z5\nG92 X57.7 Z-20 F2\n");
    assert_eq!(plan.threads.len(), 2);
    let last = &plan.threads[1];
    assert_eq!(last.starts, 1);
    // No.019 = 10: 10 × 0.1 × 2 = 2 mm at 45°: from Z−18, +4 on X.
    pt(last.passes[0].to, 57.7, -18.0);
    pt(last.passes[0].runout_to.unwrap(), 61.7, -20.0);
}

/// Taper R(i) of G92, G76 and G78: with R and U of opposite signs, |R| ≤
/// |U/2|. From A = X50 to the end X43.2: U/2 = −3.4. R3 is fine (the cut
/// starts at X43.2 + 6 = X49.2, inside A); R3.4 starts at A's diameter;
/// R5 would start at X53.2, beyond the start point: an alarm.
#[test]
fn taper_must_not_run_back_over_the_start_point() {
    let ok = gsk("G00 X50 Z5\nG92 X43.2 Z-30 R3 F2\n");
    no_alarm(&ok);
    pt(ok.threads[0].passes[0].from, 49.2, 5.0);
    no_alarm(&gsk("G00 X50 Z5\nG92 X43.2 Z-30 R3.4 F2\n"));
    let bad = gsk("G00 X50 Z5\nG92 X43.2 Z-30 R5 F2\n");
    let d = at(&bad, Code::TaperBeyondStart, 2, 1);
    assert!(d.message.contains("X53.2") && d.message.contains("U/2 = -3.4"), "{}", d.message);
    assert!(bad.threads.is_empty());
    // The same rule for G76 and G78 (and for Fanuc's G92).
    at(&gsk("G00 X50 Z5\nG76 X43.2 Z-30 R5 P1300 Q400 F2\n"), Code::TaperBeyondStart, 2, 1);
    at(&gsk("G00 X50 Z5\nG78 X43.2 Z-30 R5 P1300 Q400 F2\n"), Code::TaperBeyondStart, 2, 1);
    at(&plan_with("G00 X50. Z5.\nG92 X43.2 Z-30. R5. F2.\n", Dialect::Fanuc0i, &[]), Code::TaperBeyondStart, 2, 1);
    // Same signs: the taper grows towards the end, any size is fine.
    no_alarm(&gsk("G00 X50 Z5\nG92 X43.2 Z-30 R-5 F2\n"));
}

/// G76 step ①: the first pass is at Δd even when Δd < Δdmin; Δdmin applies
/// from the second pass. Δd 0.1 (Q100), Δdmin 0.2 (Q200), k 1.3, d 0.1:
/// 0.1; max(0.1√2, 0.1 + 0.2) = 0.3; 0.5; 0.7; 0.9; 1.1; 1.3 ≥ k − d → 1.2;
/// finishing 1.3.
#[test]
fn g76_first_pass_at_delta_d_even_below_delta_dmin() {
    let plan = gsk("G00 X32 Z5\nG76 P010060 Q200 R0.1\nG76 X27.4 Z-20 P1300 Q100 F2\n");
    no_alarm(&plan);
    assert_eq!(depths(&plan), vec![0.1, 0.3, 0.5, 0.7, 0.9, 1.1, 1.2, 1.3]);
}

/// G76 step ⑤: pass n at the larger of Δd√n and, when that cut is below
/// Δdmin, the previous depth + Δdmin ("Δdmin is regarded as the cutting
/// travel of current roughing"); the last roughing pass clamped at k − d;
/// steps ⑨–⑩: the first finishing pass removes d at k, the others are
/// spring passes. k 1.3, Δd 0.4, Δdmin 0.1, d 0.1, m 2:
/// 0.4, 0.565685, 0.692820, 0.8, 0.9, 1.0, 1.1, 1.2 | 1.3 (finish), 1.3 (spring).
/// The formula as the manual prints it, √(n−1)·Δd + Δdmin (setting
/// `cycle.dmin_rule = printed`), differs from the sixth pass: 0.9, then
/// 0.4√5 + 0.1 = 0.994427, 0.4√6 + 0.1 = 1.079796, 0.4√7 + 0.1 = 1.158301, 1.2.
/// The P(m) sentence ("every feed cutting amount is equal to d dividing m",
/// `cycle.finish_rule = split`): 1.25 and 1.3.
#[test]
fn g76_degressive_schedule_and_its_settings() {
    let src = "G00 X32 Z5\nG76 P021060 Q100 R0.1\nG76 X27.4 Z-20 P1300 Q400 F2\n";
    let plan = gsk(src);
    no_alarm(&plan);
    assert_eq!(depths(&plan), vec![0.4, 0.565685, 0.69282, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.3]);
    let roles: Vec<Role> = plan.threads[0].passes[7..].iter().map(|p| p.role).collect();
    assert_eq!(roles, vec![Role::Rough, Role::Finish, Role::Spring]);
    let printed = plan_with(src, Dialect::Gsk980tdc, &["cycle.dmin_rule=printed"]);
    assert_eq!(depths(&printed), vec![0.4, 0.565685, 0.69282, 0.8, 0.9, 0.994427, 1.079796, 1.158301, 1.2, 1.3, 1.3]);
    let split = plan_with(src, Dialect::Gsk980tdc, &["cycle.finish_rule=split"]);
    assert_eq!(depths(&split)[8..], [1.25, 1.3]);
}

/// G76 flank infeed (§3.21.7 definitions and steps ①–②): depth 0 at B, on
/// A's Z; pass h starts h·tan(a/2) from A's Z in the direction of A→D
/// ("the tool traverses in X and Z direction and its direction is the same
/// that of A→D"); every pass cuts parallel to C→D up to the line D→E, so
/// every pass ends on the programmed end; the run-out r = 10 (one lead, 2
/// mm) starts there. A = X32 Z5, D = X27.4 Z−20, k 1.3, a = 60: pass 0.4
/// starts at X29.2 Z5 − 0.4·t = Z4.769060, the finishing pass at X27.4
/// Z5 − 1.3·t = Z4.249445; all end at Z−18, run out to Z−20.
#[test]
fn g76_passes_walk_down_the_flank_from_the_start_point_and_end_on_the_end() {
    let plan = gsk("G00 X32 Z5\nG76 P011060 Q100 R0.1\nG76 X27.4 Z-20 P1300 Q400 F2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    for p in &t.passes {
        let x = 27.4 + 2.0 * (1.3 - p.depth);
        pt(p.from, x, 5.0 - p.depth * TAN30);
        pt(p.to, x, -18.0);
        pt(p.runout_to.unwrap(), x + 4.0, -20.0);
    }
    pt(t.passes[0].from, 29.2, 4.769059892324149);
    let last = t.passes.last().unwrap();
    assert!((last.from.z - 4.249445).abs() < 1e-6);
    // The same towards +Z (an internal thread cut from the chuck side): starts move +Z.
    let plan = gsk("G00 X20 Z-25\nG76 P011060 Q100 R0.1\nG76 X30 Z5 P1300 Q400 F2\n");
    no_alarm(&plan);
    for p in &plan.threads[0].passes {
        assert!((p.from.z - (-25.0 + p.depth * TAN30)).abs() < 1e-9);
        assert!((p.to.z - 3.0).abs() < 1e-9);
    }
}

/// GSK G76 P(m): "Times of thread finishing: 00~99"; m = 00 is accepted
/// (steps ⑧–⑩ still run the finishing pass ⑨ once). Fanuc's m is 01–99.
#[test]
fn g76_m_00_is_valid_on_gsk() {
    let plan = gsk("G00 X32 Z5\nG76 P001060 Q100 R0.1\nG76 X27.4 Z-20 P1300 Q400 F2\n");
    no_alarm(&plan);
    let roles: Vec<Role> = plan.threads[0].passes.iter().map(|p| p.role).collect();
    assert_eq!(roles.iter().filter(|r| **r == Role::Finish).count(), 1);
    assert_eq!(depths(&plan).last(), Some(&1.3));
    let fanuc = plan_with("G00 X32. Z5.\nG76 P001060 Q100 R0.1\n", Dialect::Fanuc0i, &[]);
    assert!(at(&fanuc, Code::ValueOutOfRange, 2, 5).message.contains("01..99"));
}

/// The G76 first block rewrites its parameters for the rest of the program:
/// GSK №057 (m), №019 (r), №058 (a). After `G76 P020555`, a G92 without
/// J/K runs out over №019 = 5: 5 × 0.1 × 2 = 1 mm (not 2); a G78 without
/// P(a) and a G32 thread take a = №058 = 55°.
#[test]
fn g76_first_block_rewrites_gsk_parameters() {
    let src = concat!(
        "G00 X32 Z5\nG76 P020555 Q100 R0.1\nG76 X27.4 Z-20 P1300 Q400 F2\n",
        "G00 X32 Z5\nG92 X27.4 Z-20 F2\n",
        "G00 X32 Z5\nG78 X27.4 Z-20 P1300 Q400 F2\n",
        "G00 X32 Z40\nX27.4\nG32 Z25 F2\nG00 X32\n",
    );
    let plan = gsk(src);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 4);
    let g92 = &plan.threads[1].passes[0];
    pt(g92.to, 27.4, -19.0);
    pt(g92.runout_to.unwrap(), 29.4, -20.0);
    assert_eq!(plan.threads[2].tool_angle, 55.0);
    assert_eq!(plan.threads[3].tool_angle, 55.0);
    // Without the G76, the same G92 runs out over №019 = 10: 2 mm.
    let plain = gsk("G00 X32 Z5\nG92 X27.4 Z-20 F2\n");
    pt(plain.threads[0].passes[0].to, 27.4, -18.0);
}

/// Fanuc: the first block rewrites 5142 (m), 5130 (r), 5143 (a), 5140
/// (Δdmin) and 5141 (d). After `G76 P011529 Q50 R0.1`, a G92 chamfers over
/// 5130 = 15: 1.5 leads (3 mm at lead 2), and G32 threads have a = 29°.
#[test]
fn g76_first_block_rewrites_fanuc_parameters() {
    let src = concat!(
        "G00 X32. Z5.\nG76 P011529 Q50 R0.1\n",
        "G92 X27.4 Z-20. F2.\n",
        "G00 X32. Z40.\nX27.4\nG32 Z25. F2.\nG00 X32.\n",
    );
    let plan = plan_with(src, Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    pt(plan.threads[0].passes[0].to, 27.4, -17.0);
    assert_eq!(plan.threads[1].tool_angle, 29.0);
}
