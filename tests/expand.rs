//! `expand`: a plan written back block by block, planned again, gives the
//! same passes — every pass's synchronised path (screw-in, cut, run-out)
//! within 0.001 mm, its start and, where the target has a run-out word,
//! its end — and the same start angles.

mod common;
use common::{no_alarm, plan_with};
use screwcut::expand::expand;
use screwcut::motion::MoveKind;
use screwcut::motion::Point;
use screwcut::thread::Pass;
use screwcut::{Dialect, Plan};

use Dialect::{Fanuc0i as F, Gsk980tdc as G, LinuxCnc as L, Renhe as R};

const TOL: f64 = 0.001;

/// The synchronised path of a pass: where its first synchronised move
/// starts and where each ends (screw-in, cut segments, run-out).
fn path(plan: &Plan, p: &Pass) -> Vec<Point> {
    let cut = &plan.moves[p.moves.cut.clone()];
    assert!(cut.iter().all(|m| matches!(m.kind, MoveKind::Thread | MoveKind::ScrewIn | MoveKind::Runout)));
    cut.first().map(|m| m.from).into_iter().chain(cut.iter().map(|m| m.to)).collect()
}

/// What a round trip must keep besides every pass's synchronised path and start angle.
#[derive(Clone, Copy)]
struct Keep {
    /// The pass's cut start and end (the target writes screw-in and run-out as the source has them).
    ends: bool,
    /// The thread's lead (the target's first block gives the lead along the thread's axis).
    lead: bool,
}

const ALL: Keep = Keep { ends: true, lead: true };
const PATH: Keep = Keep { ends: false, lead: true };

#[track_caller]
fn near(what: &str, a: Point, b: Point) {
    assert!((a.x - b.x).abs() <= TOL && (a.z - b.z).abs() <= TOL, "{what}: ({}, {}) != ({}, {})", a.x, a.z, b.x, b.z);
}

/// Expands `src` (in `from`) for `to`, plans it again and compares; returns the program.
fn round_trip(src: &str, from: Dialect, to: Dialect, keep: Keep) -> String {
    let before = plan_with(src, from, &[]);
    no_alarm(&before);
    let e = expand(&before, to);
    let after: Plan = plan_with(&e.program, to, &[]);
    let ctx = format!("{from} → {to}:\n{}", e.program);
    let alarms: Vec<_> = after.diagnostics.iter().filter(|d| d.severity == screwcut::Severity::Error).collect();
    assert!(alarms.is_empty(), "{ctx}\n{alarms:#?}");
    assert_eq!(after.threads.len(), before.threads.len(), "{ctx}");
    for (a, b) in before.threads.iter().zip(&after.threads) {
        assert_eq!(a.passes.len(), b.passes.len(), "{ctx}");
        assert_eq!(a.starts, b.starts, "{ctx}");
        assert!(!keep.lead || (a.lead - b.lead).abs() < 1e-4, "{ctx}: lead {} != {}", a.lead, b.lead);
        for (p, q) in a.passes.iter().zip(&b.passes) {
            let what = format!("{from} → {to}, start {} pass {}", p.start, p.index);
            assert_eq!((p.start, p.index), (q.start, q.index), "{what}");
            assert!((p.angle - q.angle).abs() < 1e-6, "{what}: angle {} != {}", p.angle, q.angle);
            let (pp, qp) = (path(&before, p), path(&after, q));
            assert_eq!(pp.len(), qp.len(), "{what}: {pp:?} / {qp:?}\n{ctx}");
            for (x, y) in pp.iter().zip(&qp) {
                near(&what, *x, *y);
            }
            if keep.ends {
                near(&format!("{what} from"), p.from, q.from);
                near(&format!("{what} to"), p.to, q.to);
            }
        }
    }
    e.program
}

const G92_TAPER_JK: &str = "G00 X40 Z5\nG92 X31.2 Z-30 R-2 F2 J1.5 K2\nX30.6\nX30.2\nX30.05\nG00 X100 Z100\nM30\n";

#[test]
fn fanuc_g76_into_fanuc_and_gsk() {
    let src = include_str!("../examples/g76-fanuc.nc");
    let fanuc = round_trip(src, F, F, PATH);
    // Fanuc's G32 has no run-out word: the chamfer is a second block, F is the lead.
    assert!(fanuc.contains("G32 X64.4 Z31. F6.\nG32 X76.4 Z25. F6.\n"), "{fanuc}");
    let gsk = round_trip(src, F, G, ALL);
    assert!(gsk.contains("G32 X64.4 Z25 F6 J6 K6\n"), "{gsk}");
}

/// Fanuc's G32 has no run-out word: a G76 expanded for Fanuc writes each
/// pass's chamfer (r = 10: one lead, 6 mm of Z at 45°) as a second G32
/// block, which is read back as the pass's run-out, not as a second piece
/// of it; and the crest the cycle gave (root X60.64 + 2 × k 3.68 = X68) is
/// written as `(crest X68.)`, which the planner reads. Planned again: the
/// same five passes, each cut ending at Z31 and running out to X+12 at Z25,
/// the same crest, depths (Δd 1.8, 1.8·√2, 1.8·√3, then k − d = 3.48 and
/// k = 3.68: GSK980TDc manual §3.21.7 steps ①–⑩, the 0i-TF's G76 alike)
/// and roles. Before, the chamfer made each pass a taper piece: crest
/// X68.3134 and depths 1.9567 … 3.9.
#[test]
fn fanuc_g76_into_fanuc_keeps_crest_depths_and_passes() {
    let src = include_str!("../examples/g76-fanuc.nc");
    let before = plan_with(src, F, &[]);
    let text = round_trip(src, F, F, ALL);
    assert!(text.contains("(crest X68.)\nG00 X64.4 Z128.9608\nG32 X64.4 Z31. F6.\nG32 X76.4 Z25. F6.\n"), "{text}");
    let after = plan_with(&text, F, &[]);
    let (a, b) = (&before.threads[0], &after.threads[0]);
    let depths =
        |t: &screwcut::thread::Thread| t.passes.iter().map(|p| (p.depth * 1e4).round() / 1e4).collect::<Vec<_>>();
    assert_eq!(depths(a), [1.8, 2.5456, 3.1177, 3.48, 3.68]);
    assert_eq!(depths(b), depths(a));
    assert_eq!(a.crest, 68.0);
    assert!((b.crest - 68.0).abs() < 1e-9 && (a.height - 3.68).abs() < 1e-9 && (b.height - 3.68).abs() < 1e-9);
    assert_eq!(b.crest_source, screwcut::thread::CrestSource::Comment);
    let roles = |t: &screwcut::thread::Thread| t.passes.iter().map(|p| p.role).collect::<Vec<_>>();
    assert_eq!(roles(b), roles(a));
    for (p, q) in a.passes.iter().zip(&b.passes) {
        near("run-out", p.runout_to.unwrap(), q.runout_to.unwrap());
        assert!(q.segments.is_empty(), "one piece and its run-out: {:?}", q.segments);
        // The chamfer block is a run-out motion, drawn and timed as one.
        assert_eq!(after.moves[q.moves.cut.end - 1].kind, MoveKind::Runout);
    }
    // Into GSK the run-out is J/K: the same crest and depths there too.
    let gsk = plan_with(&expand(&before, G).program, G, &[]);
    assert!((gsk.threads[0].crest - 68.0).abs() < 1e-9);
    assert_eq!(depths(&gsk.threads[0]), depths(a));
}

#[test]
fn gsk_g78_two_starts_alternating_into_gsk() {
    let src = "G00 X35 Z5\nG78 P0360 Q50 R0.1 D1 L2\nG78 X27.4 Z-30 P1300 Q300 F4\nG00 X100 Z100\nM30\n";
    let before = plan_with(src, G, &[]);
    assert_eq!(before.threads[0].starts, 2);
    assert_eq!(before.threads[0].infeed, screwcut::thread::Infeed::Alternating);
    let out = round_trip(src, G, G, ALL);
    // The second start by its start angle, 180° in 0.001° (NO182.7 = 0).
    assert!(out.contains(" Q180000\n"), "{out}");
    // And the screw-in variant of the same cycle (E) into GSK.
    round_trip(include_str!("../examples/g78-flank-alternating.nc"), G, G, PATH);
}

#[test]
fn gsk_g92_taper_with_jk_into_gsk() {
    let before = plan_with(G92_TAPER_JK, G, &[]);
    assert_eq!(before.threads[0].kind, screwcut::thread::ThreadKind::Taper);
    assert!(before.threads[0].passes[0].runout_to.is_some());
    let out = round_trip(G92_TAPER_JK, G, G, ALL);
    assert!(out.contains(" J1.5 K2\n"), "{out}");
}

#[test]
fn renhe_spiral_tail_into_renhe_and_gsk() {
    let src = include_str!("../examples/renhe-tails.nc");
    let renhe = round_trip(src, R, R, ALL);
    assert!(renhe.contains("G30 U10 W2\nG33 W-40 F1.5\n"), "{renhe}");
    let gsk = round_trip(src, R, G, ALL);
    // The spiral tail (retract 10 on the diameter over the last 2 mm) as G32 J5 K2.
    assert!(gsk.contains(" J5 K2\n"), "{gsk}");
}

#[test]
fn every_example_into_every_dialect_with_a_start_angle() {
    for (name, src, from) in [
        ("o1006", include_str!("../examples/o1006.nc"), G),
        ("o0009", include_str!("../examples/o0009.nc"), G),
        ("g32-multistart-q", include_str!("../examples/g32-multistart-q.nc"), G),
        ("g92-two-start", include_str!("../examples/g92-two-start.nc"), G),
        ("g78-m30x2", include_str!("../examples/g78-m30x2.nc"), G),
        ("fanuc-g92", include_str!("../examples/fanuc-g92.nc"), F),
    ] {
        for to in [G, F] {
            let out = round_trip(src, from, to, if to == G { ALL } else { PATH });
            assert!(out.ends_with("M30\n"), "{name}");
        }
    }
}

/// Into LinuxCNC: G33 with K along the move, multi-start by axial offset.
#[test]
fn into_linuxcnc() {
    let src = include_str!("../examples/g92-two-start.nc");
    let before = plan_with(src, G, &[]);
    let e = expand(&before, L);
    let after = plan_with(&e.program, L, &[]);
    no_alarm(&after);
    // No start angle word: the second start's passes start lead/2 = 1.5 further
    // back along Z and end where they did, so the same two helices are cut, and
    // read again they are the thread's second start.
    let t = &after.threads[0];
    assert_eq!((t.passes.len(), t.starts), (8, 2));
    let b = &before.threads[0];
    let second = b.passes.iter().position(|p| p.start == 2).unwrap();
    assert!((t.passes[second].from.z - (b.passes[second].from.z + 1.5)).abs() < TOL, "{}", e.program);
    assert!((t.passes[second].to.z - b.passes[second].to.z).abs() < TOL, "{}", e.program);
    assert_eq!(t.passes[second].start, 2);
    assert!((t.passes[0].from.z - b.passes[0].from.z).abs() < TOL);
    // A taper G33: K is along the move, the lead along Z stays.
    let taper = plan_with(G92_TAPER_JK, G, &[]);
    let lx = plan_with(&expand(&taper, L).program, L, &[]);
    no_alarm(&lx);
    assert!((lx.threads[0].lead - 2.0).abs() < 1e-6);
    let p = (&taper.threads[0].passes[0], &lx.threads[0].passes[0]);
    near("taper from", p.0.from, p.1.from);
    // Its chamfer, a second G33 leaving the work, is read back as the run-out.
    near("taper to", p.0.to, p.1.to);
    near("taper run-out", p.0.runout_to.unwrap(), p.1.runout_to.unwrap());
}

/// LinuxCNC's G76 (tapers at both ends) into GSK and back into LinuxCNC.
#[test]
fn linuxcnc_g76_round_trips() {
    let src = "G18 G21 G90 G8\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1 Q29.5 E2 L3\nM2\n";
    // A block-by-block thread takes its lead from its first block, here the
    // X-only entry (a face segment at the taper pitch): only the paths are kept.
    let keep = Keep { ends: false, lead: false };
    round_trip(src, L, G, keep);
    round_trip(src, L, L, keep);
}

/// The spindle speed goes with the passes: O1006 (seed 004, S300) expanded
/// for every controller cuts in the same 28.5 s (5 × 57 mm at 2 mm × 300 rev/min).
#[test]
fn the_spindle_speed_is_kept() {
    let src = plan_with(include_str!("../examples/o1006.nc"), G, &[]);
    assert_eq!(src.threads[0].shop.cut_time_s.map(|t| (t * 10.0).round()), Some(285.0));
    for to in [G, F, R, L] {
        let text = expand(&src, to).program;
        let again = plan_with(&text, to, &[]);
        let t = again.threads[0].shop.cut_time_s.unwrap_or_else(|| panic!("{to:?}: no cutting time\n{text}"));
        assert!((t - 28.5).abs() < 1e-6, "{to:?}: {t}\n{text}");
    }
}
