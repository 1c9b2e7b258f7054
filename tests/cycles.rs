//! G78, G76 and G92 pass by pass: depths, X and Z of every pass for each
//! depth mode and infeed mode, multi-start, screw-in and run-out, GSK and
//! Fanuc forms. Expected values are worked out by hand from the rules.

mod common;
use common::*;
use screwcut::motion::MoveKind;
use screwcut::thread::{CrestSource, Infeed, Role, Source, ThreadKind};
use screwcut::{Code, Dialect, Plan};

const TAN30: f64 = 0.5773502691896257;

fn depths(plan: &Plan) -> Vec<f64> {
    plan.threads[0].passes.iter().map(|p| (p.depth * 1e6).round() / 1e6).collect()
}

/// G78 degressive (m = 1), radial (r = 0), a = 60, Δdmin 0.1, d 0.05, D2,
/// k 1.3, Δd 0.4, lead 2, from A = X35 Z5 to X27.4 Z−30.
/// Roughing to k − d = 1.25: 0.4; 0.4√2 = 0.565685; 0.4√3 = 0.692820;
/// 0.4√4 = 0.8; then the √n cut falls under Δdmin = 0.1: 0.4√5 = 0.894427 <
/// 0.8 + 0.1 → 0.9; 1.0; 1.1; 1.2; 1.3 ≥ 1.25 → 1.25. Finishing 1.3, spring 1.3.
/// X = 27.4 + 2·(1.3 − depth). Run-out from No.019 = 10: 10 × 0.1 × 2 = 2 mm
/// at 45°: the cut ends at Z−28, the run-out at X + 4, Z−30.
#[test]
fn g78_degressive_radial() {
    let plan = gsk(include_str!("../examples/g78-m30x2.nc"));
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!((t.source, t.kind, t.infeed, t.starts), (Source::G78, ThreadKind::Straight, Infeed::Radial, 1));
    eq(t.lead, 2.0);
    eq(t.height, 1.3);
    eq(t.crest, 30.0); // 27.4 + 2 × 1.3
    assert_eq!(t.crest_source, CrestSource::Cycle);
    assert_eq!(depths(&plan), vec![0.4, 0.565685, 0.69282, 0.8, 0.9, 1.0, 1.1, 1.2, 1.25, 1.3, 1.3]);
    let roles: Vec<Role> = t.passes.iter().map(|p| p.role).collect();
    assert_eq!(roles[8], Role::Rough);
    assert_eq!((roles[9], roles[10]), (Role::Finish, Role::Spring));
    for p in &t.passes {
        let x = 27.4 + 2.0 * (1.3 - p.depth);
        pt(p.from, x, 5.0);
        pt(p.to, x, -28.0);
        pt(p.runout_to.unwrap(), x + 4.0, -30.0);
        assert_eq!(p.shift, 0.0);
        assert_eq!(p.lines, vec![3, 4]);
        assert_eq!(p.start, 1);
    }
    eq(t.passes[4].infeed, 0.1);
    // Area: tan 30° · (h1² − h0²); pass 1: 0.577350 × 0.16.
    assert!((t.passes[0].area.unwrap() - TAN30 * 0.16).abs() < 1e-12);
    // Every motion of the cycle points at the second block: approach, cut,
    // run-out, retract, return per pass; then G00 X100 Z100.
    let cycle: Vec<_> = plan.moves.iter().filter(|m| m.line == 4).collect();
    assert_eq!(cycle.len(), 11 * 5);
    let kinds: Vec<MoveKind> = cycle[..5].iter().map(|m| m.kind).collect();
    assert_eq!(kinds, [MoveKind::Rapid, MoveKind::Thread, MoveKind::Runout, MoveKind::Rapid, MoveKind::Rapid]);
    pt(cycle[0].from, 35.0, 5.0); // A
    pt(cycle[3].to, 35.0, -30.0); // retract to A's diameter
    pt(cycle[4].to, 35.0, 5.0); // return to A
}

/// Equal depth (m = 0), left flank (r = 1, the −Z flank), a = 60, Δd 0.4,
/// k 1.3, d 0.1: 0.4, 0.8, 1.2 (= k − d), finishing 1.3. The tip runs on the
/// −Z flank: its shift from the finished thread's middle is −(k − h)·tan 30°:
/// −0.9·t, −0.5·t, −0.1·t, 0 (the tooth view draws these).
///
/// Where the passes sit along Z follows G76's definitions (GSK980TDc manual
/// §3.21.7, "Relevant definitions" and steps ①–②: depth 0 at the start
/// point's Z, each pass cuts parallel to C→D up to the line D→E), setting
/// `g78.flank_anchor`:
/// - `start` (default): depth 0 at A's Z, the tip walks down the −Z flank,
///   which moves it +Z as it deepens: pass h starts at Z5 + h·t
///   (5.230940, 5.461880, 5.692820, 5.750555);
/// - `thread`: the finished thread at A's Z: pass h starts at Z5 − (k − h)·t.
///
/// Either way every pass ends on the programmed end: the run-out (No.019 =
/// 10: 2 mm) starts at Z−28 — no pass overruns it.
#[test]
fn g78_equal_left_flank() {
    let src = "G00 X35 Z5\nG78 P0160 Q50 R0.1 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n";
    let plan = gsk(src);
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.infeed, Infeed::Left);
    assert_eq!(depths(&plan), vec![0.4, 0.8, 1.2, 1.3]);
    let want = [-0.9 * TAN30, -0.5 * TAN30, -0.1 * TAN30, 0.0];
    for (p, s) in t.passes.iter().zip(want) {
        eq(p.shift, s);
        pt(p.from, 27.4 + 2.0 * (1.3 - p.depth), 5.0 + p.depth * TAN30);
        pt(p.to, 27.4 + 2.0 * (1.3 - p.depth), -28.0);
    }
    assert!((t.passes[3].from.z - 5.750555).abs() < 1e-6);
    let plan = plan_with(src, Dialect::Gsk980tdc, &["g78.flank_anchor=thread"]);
    for (p, s) in plan.threads[0].passes.iter().zip(want) {
        eq(p.shift, s);
        pt(p.from, 27.4 + 2.0 * (1.3 - p.depth), 5.0 + s);
        pt(p.to, 27.4 + 2.0 * (1.3 - p.depth), -28.0);
    }
    // flank.r1_side = plus-z puts the left flank on the +Z side.
    let plan = plan_with(src, Dialect::Gsk980tdc, &["flank.r1_side=plus-z"]);
    eq(plan.threads[0].passes[0].shift, 0.9 * TAN30);
}

/// Right flank (r = 2): +(k − h)·tan 30°; alternating (r = 3): left, right, left…
#[test]
fn g78_right_and_alternating() {
    let right = gsk("G00 X35 Z5\nG78 P0260 Q50 R0.1 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    let s: Vec<f64> = right.threads[0].passes.iter().map(|p| p.shift).collect();
    assert_eq!(right.threads[0].infeed, Infeed::Right);
    eq(s[0], 0.9 * TAN30);
    eq(s[1], 0.5 * TAN30);
    let alt = gsk("G00 X35 Z5\nG78 P0360 Q50 R0.1 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    let s: Vec<f64> = alt.threads[0].passes.iter().map(|p| p.shift).collect();
    assert_eq!(alt.threads[0].infeed, Infeed::Alternating);
    eq(s[0], -0.9 * TAN30);
    eq(s[1], 0.5 * TAN30);
    eq(s[2], -0.1 * TAN30);
    eq(s[3], 0.0);
}

/// P with fewer than four digits: the missing m and r come from No.061 and
/// No.062 — or are 0 with g78.missing_p_digits = zero.
#[test]
fn g78_missing_p_digits() {
    let src = "G00 X35 Z5\nG78 P60 Q50 R0.1 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n";
    let plan = plan_with(src, Dialect::Gsk980tdc, &["No.061=0", "No.062=2"]);
    assert_eq!(plan.threads[0].infeed, Infeed::Right);
    assert_eq!(depths(&plan), vec![0.4, 0.8, 1.2, 1.3]); // equal depth
    let plan = plan_with(src, Dialect::Gsk980tdc, &["No.061=0", "No.062=2", "g78.missing_p_digits=zero"]);
    assert_eq!(plan.threads[0].infeed, Infeed::Radial);
    // Without a first block every value is a parameter: No.061 = 1, No.062 = 0, No.058 = 60,
    // No.059 = 100 → 0.1, No.060 = 100 → 0.1, D = 1: 0.4, 0.565685, 0.692820, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3.
    let plan = gsk("G00 X35 Z5\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    assert_eq!(depths(&plan), vec![0.4, 0.565685, 0.69282, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3]);
    assert_eq!(plan.threads[0].passes.last().unwrap().role, Role::Finish);
}

/// Two starts (L2) repeat every pass shifted half a turn; screw-in E0.5
/// starts each pass 0.5 (radius) out and ramps in over one lead (2 mm of Z);
/// J1 K3 retract 1 over the last 3 of Z.
#[test]
fn g78_starts_screw_in_run_out() {
    let plan = gsk("G00 X35 Z5\nG78 P1060 Q100 R0.05 D1 J1 K3 L2 E0.5\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.starts, 2);
    eq(t.pitch, 1.0);
    let n = t.passes.len() / 2;
    assert_eq!(n, 10); // nine roughing passes (as above, to 1.25) and one finishing pass
    let (s1, s2) = t.passes.split_at(n);
    assert!(s1.iter().all(|p| p.start == 1) && s2.iter().all(|p| p.start == 2));
    eq(s2[0].angle, 180.0);
    assert_eq!(s2[3].index, 4);
    for p in &t.passes {
        let x = 27.4 + 2.0 * (1.3 - p.depth);
        pt(p.screw_in_from.unwrap(), x + 1.0, 5.0);
        pt(p.from, x, 3.0);
        pt(p.to, x, -27.0);
        pt(p.runout_to.unwrap(), x + 2.0, -30.0);
    }
    let screw = plan.moves.iter().filter(|m| m.kind == MoveKind::ScrewIn).count();
    assert_eq!(screw, 20);
    // J/K are non-modal: the next cycle uses No.019 again (2 mm at 45°).
    let plan =
        gsk("G00 X35 Z5\nG78 P1060 Q100 R0.05 D1 J1 K3\nG78 X27.4 Z-30 P1300 Q400 F2\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    pt(plan.threads[1].passes[0].to, 29.2, -28.0);
}

/// A taper: R(i) = −1 (radius) makes the root run from X25.4 at Z5 to X27.4 at Z−30.
#[test]
fn g78_taper() {
    let plan = gsk("G00 X35 Z5\nG78 P1060 Q100 R0.05 D1 J0\nG78 X27.4 Z-30 R-1 P1300 Q400 F2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.kind, ThreadKind::Taper);
    eq(t.taper, -1.0);
    let last = t.passes.last().unwrap();
    pt(last.from, 25.4, 5.0);
    pt(last.to, 27.4, -30.0);
    assert_eq!(last.runout_to, None); // J0: no run-out
}

/// G78 alarms: no P(k), no Q(Δd), a face thread, values out of range, too many passes.
#[test]
fn g78_alarms() {
    let p = gsk("G00 X35 Z5\nG78 X27.4 Z-30 Q400 F2\n");
    at(&p, Code::MissingThreadHeight, 2, 1);
    let p = gsk("G00 X35 Z5\nG78 X27.4 Z-30 P1300 F2\n");
    at(&p, Code::MissingFirstDepth, 2, 1);
    let p = gsk("G00 X35 Z5\nG78 X60 P1300 Q400 F2\n");
    at(&p, Code::FaceThreadNotAllowed, 2, 1);
    let p = gsk("G00 X35 Z5\nG78 P1460 Q100\n");
    assert!(at(&p, Code::ValueOutOfRange, 2, 5).message.contains("r = 4"));
    let p = gsk("G00 X35 Z5\nG78 P1060 D100\n");
    at(&p, Code::ValueOutOfRange, 2, 11);
    let p = gsk("G00 X35 Z5\nG78 P1060 L0\n");
    at(&p, Code::ValueOutOfRange, 2, 11);
    // Δd 0.001 degressive with Δdmin 0 to k − d = 1.25: (1.25 / 0.001)² = 1,562,500 roughing passes + 1.
    let p = gsk("G00 X35 Z5\nG78 P1060 Q0 R0.05 D1\nG78 X27.4 Z-30 P1300 Q1 F2\n");
    let d = at(&p, Code::PassLimit, 3, 1);
    assert!(d.message.contains("1562501 passes"), "{}", d.message);
    assert!(p.threads.is_empty());
    assert!(p.moves.iter().all(|m| m.line != 3));
    // A decimal point in increment mode is ignored, and said so: P1.3 is 0.0013 mm.
    let p = gsk("G00 X35 Z5\nG78 X27.4 Z-30 P1.3 Q400 F2\n");
    assert!(at(&p, Code::DecimalPointIgnored, 2, 16).message.contains("0.0013"));
    // NO182.7 = 1: P and Q in mm.
    let p = plan_with("G00 X35 Z5\nG78 X27.4 Z-30 P1.3 Q0.4 F2\n", Dialect::Gsk980tdc, &["NO182.7=1"]);
    no_alarm(&p);
    eq(p.threads[0].height, 1.3);
    // A start point inside the thread warns.
    let p = gsk("G00 X29 Z5\nG78 X27.4 Z-30 P1300 Q400 F2\n");
    at(&p, Code::StartInsideThread, 2, 1);
}

/// An internal thread: A inside the root, depths grow outward: X = 30 − 2·(1.3 − h).
#[test]
fn g78_internal() {
    let plan = gsk("G00 X20 Z5\nG78 P1060 Q100 R0.05 D1\nG78 X30 Z-30 P1300 Q400 F2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert!(t.internal);
    eq(t.crest, 27.4);
    let p = &t.passes[0];
    pt(p.from, 30.0 - 2.0 * 0.9, 5.0);
    // The run-out goes inward, away from the work: 2 mm radial.
    pt(p.runout_to.unwrap(), 28.2 - 4.0, -30.0);
}

/// Fanuc's G76 example (P011060 Q100 R0.2; X60.64 Z25 P3680 Q1800 F6):
/// depths 1.8, 1.8√2, 1.8√3, then 3.6 ≥ k − d = 3.48 → 3.48, finishing 3.68.
/// X = 60.64 + 2·(3.68 − h). Single flank infeed towards the cut (−Z).
/// GSK980TDc manual §3.21.7 (the same cycle): depth 0 at B, on A's Z; "the
/// tool traverses in X and Z direction and its direction is the same that
/// of A→D", so pass h starts h·tan 30° towards −Z: Z130 − h·t (128.960770,
/// 128.530306, 128.200000, 127.990821, 127.875351); "the tool cuts threads
/// paralleling with C→D to the intersection of D→E": every pass ends on the
/// programmed end. Chamfer r = 10: one lead (6) at 45° (parameter 5131): the
/// cut ends at Z31, the run-out at X + 12, Z25, for every pass. The shift
/// from the finished thread's middle (tooth view) is (3.68 − h)·tan 30°.
#[test]
fn g76_fanuc_example() {
    let plan = plan_with(include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!((t.source, t.infeed), (Source::G76, Infeed::Right));
    assert_eq!(depths(&plan), vec![1.8, 2.545584, 3.117691, 3.48, 3.68]);
    let xs = [64.4, 62.908831, 61.764617, 61.04, 60.64];
    let zs = [128.960770, 128.530306, 128.2, 127.990821, 127.875351];
    for ((p, x), z) in t.passes.iter().zip(xs).zip(zs) {
        eq(p.shift, (3.68 - p.depth) * TAN30);
        assert!((p.from.x - x).abs() < 1e-6 && (p.from.z - (130.0 - p.depth * TAN30)).abs() < 1e-9);
        assert!((p.from.z - z).abs() < 1e-6, "{} vs {z}", p.from.z);
        assert!((p.to.z - 31.0).abs() < 1e-9 && (p.to.x - x).abs() < 1e-6);
        let r = p.runout_to.unwrap();
        assert!((r.x - (p.to.x + 12.0)).abs() < 1e-9 && (r.z - 25.0).abs() < 1e-9);
        assert_eq!(p.lines, vec![3, 4]);
    }
    assert_eq!(t.passes[4].role, Role::Finish);
    // The chamfer angle is parameter 5131: at 30° J = 6·tan 30°.
    let plan = plan_with(include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i, &["5131=30"]);
    let p = &plan.threads[0].passes[4];
    eq(p.runout_to.unwrap().x, 60.64 + 2.0 * 6.0 * TAN30);
}

/// Fanuc G76 unit rule and alarms: P/Q are integer increments; a decimal
/// point alarms; the tool angle must be one of 80, 60, 55, 30, 29, 0.
#[test]
fn g76_fanuc_words() {
    let p =
        plan_with("G00 X80. Z130.\nG76 P011060 Q100 R0.2\nG76 X60.64 Z25. P3.68 Q1800 F6.\n", Dialect::Fanuc0i, &[]);
    at(&p, Code::DecimalPointNotAllowed, 3, 17);
    let p = plan_with("G00 X80. Z130.\nG76 P011045 Q100 R0.2\n", Dialect::Fanuc0i, &[]);
    assert!(at(&p, Code::ValueOutOfRange, 2, 5).message.contains("45°"));
    // Without a first block: 5142 m = 1, 5130 r = 10, 5143 a = 60, 5140 Δdmin 100 → 0.1, 5141 d 100 → 0.1.
    let p = plan_with("G00 X80. Z130.\nG76 X60.64 Z25. P3680 Q1800 F6.\n", Dialect::Fanuc0i, &[]);
    no_alarm(&p);
    // Roughing to 3.58: 1.8, 2.545584, 3.117691, 3.6 → 3.58; finishing 3.68.
    assert_eq!(depths(&p), vec![1.8, 2.545584, 3.117691, 3.58, 3.68]);
    let p = plan_with("G00 X80. Z130.\nG76 X60.64 P3680 Q1800 F6.\n", Dialect::Fanuc0i, &[]);
    at(&p, Code::FaceThreadNotAllowed, 2, 1);
}

/// GSK two-block G76: P020560 = two finishing passes, run-out 0.5 lead, 60°;
/// P/Q per NO182.7 (increments by default).
#[test]
fn g76_gsk() {
    let plan = gsk("G00 X35 Z5\nG76 P020560 Q100 R0.05\nG76 X27.4 Z-30 P1300 Q400 F2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    // Degressive to 1.25 as in G78 above, then finishing and one spring pass.
    assert_eq!(depths(&plan), vec![0.4, 0.565685, 0.69282, 0.8, 0.9, 1.0, 1.1, 1.2, 1.25, 1.3, 1.3]);
    assert_eq!(t.passes[10].role, Role::Spring);
    // Run-out 5 × 0.1 × 2 = 1 mm at 45°.
    let last = t.passes.last().unwrap();
    pt(last.to, 27.4, -29.0);
    pt(last.runout_to.unwrap(), 29.4, -30.0);
}

/// Fanuc G92: one pass per block, X-only blocks continue; the chamfer is
/// parameter 5130 (10 → one lead, 2 mm) at 45°: the cut ends at Z15, the
/// run-out at X + 4, Z13. The passes group into one thread.
#[test]
fn g92_fanuc_passes() {
    let src = "G00 X58. Z70.\nG92 X47.1 Z13. F2.\nX46.5\nX45.9\nX45.5\nX45.4\nG00 X100. Z100.\n";
    let plan = plan_with(src, Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!(t.source, Source::G92);
    let xs = [47.1, 46.5, 45.9, 45.5, 45.4];
    for (i, (p, x)) in t.passes.iter().zip(xs).enumerate() {
        pt(p.from, x, 70.0);
        pt(p.to, x, 15.0);
        pt(p.runout_to.unwrap(), x + 4.0, 13.0);
        assert_eq!(p.lines, vec![i as u32 + 2]);
    }
    // Per pass: rapid in X, cut, run-out, rapid out, rapid back.
    let block2: Vec<MoveKind> = plan.moves.iter().filter(|m| m.line == 2).map(|m| m.kind).collect();
    assert_eq!(block2, [MoveKind::Rapid, MoveKind::Thread, MoveKind::Runout, MoveKind::Rapid, MoveKind::Rapid]);
    // The crest is assumed as for G32 (45.4 + 2.6 = 48).
    eq(t.crest, 48.0);
    // 5130 = 0: no chamfer.
    let plan = plan_with(src, Dialect::Fanuc0i, &["5130=0"]);
    pt(plan.threads[0].passes[0].to, 47.1, 13.0);
    // A start angle Q splits starts.
    let plan = plan_with("G00 X58. Z70.\nG92 X47.1 Z13. F4. Q0\nG92 X47.1 Z13. F4. Q180000\n", Dialect::Fanuc0i, &[]);
    assert_eq!(plan.threads[0].starts, 2);
}

/// GSK G92 with L2 and J/K: each block cuts both starts; the continuation
/// blocks keep Z, J, K and L. J1 K3: cut to Z−27, run-out X + 2 at Z−30.
#[test]
fn g92_gsk_starts_and_run_out() {
    let plan = gsk("G00 X30 Z5\nG92 X23.2 Z-30 F3 J1 K3 L2\nX22.6\nX22.05\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!((t.starts, t.passes.len()), (2, 6));
    eq(t.pitch, 1.5);
    let order: Vec<(u32, u32)> = t.passes.iter().map(|p| (p.start, p.index)).collect();
    assert_eq!(order, [(1, 1), (2, 1), (1, 2), (2, 2), (1, 3), (2, 3)]);
    for p in &t.passes {
        pt(p.to, p.from.x, -27.0);
        pt(p.runout_to.unwrap(), p.from.x + 2.0, -30.0);
    }
    // Without Z and no G92 before: an alarm.
    let p = gsk("G00 X30 Z5\nG92 X23.2 F3\n");
    at(&p, Code::MissingWord, 2, 1);
}

/// Chip areas: whatever the infeed, every pass stays inside the finished
/// thread space, so the areas of all passes add up to the V of the final
/// depth, tan 30°·1.3² = 0.975729; radial passes remove tan 30°·(h₁² − h₀²)
/// each, alternating ones remove more on some passes (the slivers left by
/// the other flank) and less on others.
#[test]
fn chip_areas_add_up_to_the_thread_space() {
    let full = TAN30 * 1.3 * 1.3;
    let mut per_mode = Vec::new();
    for r in 0..4 {
        let plan = gsk(&format!("G00 X35 Z5\nG78 P0{r}60 Q50 R0.1 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n"));
        let areas: Vec<f64> = plan.threads[0].passes.iter().map(|p| p.area.unwrap()).collect();
        let sum: f64 = areas.iter().sum();
        assert!((sum - full).abs() < 1e-9, "r = {r}: {sum} against {full}");
        per_mode.push(areas);
    }
    // Radial (r = 0): pass 2 from 0.4 to 0.8 removes tan 30°·(0.64 − 0.16).
    eq(per_mode[0][1], TAN30 * 0.48);
    // Left flank (r = 1): the same areas as radial.
    for (a, b) in per_mode[0].iter().zip(&per_mode[1]) {
        eq(*a, *b);
    }
    // Alternating (r = 3): pass 2 takes more than the radial formula.
    assert!(per_mode[3][1] > TAN30 * 0.48 + 1e-3, "{:?}", per_mode[3]);
}
