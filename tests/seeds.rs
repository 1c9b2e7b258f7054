//! The seed programs reproduced to the last digit.

mod common;
use common::*;
use screwcut::motion::MoveKind;
use screwcut::thread::{Axis, CrestSource, Role, Source, ThreadKind};
use screwcut::{Code, Dialect};

const O0009: &str = include_str!("../examples/o0009.nc");
const O1006: &str = include_str!("../examples/o1006.nc");

/// Seed 000 (GSK980TDc manual, G32 example): a two-pass taper thread, lead 2,
/// from X27.4286 Z3 to X48.8571 at W-75, then X26.4286 to X47.4286.
#[test]
fn o0009_taper_thread_two_passes() {
    let plan = gsk(O0009);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!(t.kind, ThreadKind::Taper);
    assert_eq!(t.source, Source::G32);
    assert_eq!(t.long_axis, Axis::Z);
    eq(t.lead, 2.0);
    assert_eq!(t.starts, 1);
    assert!(!t.internal);
    assert_eq!(t.passes.len(), 2);
    let (p1, p2) = (&t.passes[0], &t.passes[1]);
    // Pass 1: G00 X27.4286 Z3; G32 X48.8571 W-75 F2.0 (Z 3 − 75 = −72).
    pt(p1.from, 27.4286, 3.0);
    pt(p1.to, 48.8571, -72.0);
    // Pass 2: X26.4286; G32 X47.4286 W-75.
    pt(p2.from, 26.4286, 3.0);
    pt(p2.to, 47.4286, -72.0);
    assert_eq!((p1.start, p1.index, p2.start, p2.index), (1, 1, 1, 2));
    // Grouping: infeed, cut, retract (G00 X55), return (W75) per pass.
    assert_eq!(p1.lines, vec![2, 3, 4, 5]);
    assert_eq!(p2.lines, vec![6, 7, 8, 9]);
    // Crest assumed from the deepest pass: 26.4286 + 1.3·2 = 29.0286; depths
    // (29.0286 − 27.4286)/2 = 0.8 and (29.0286 − 26.4286)/2 = 1.3 (radial).
    assert_eq!(t.crest_source, CrestSource::Assumed);
    eq(t.crest, 29.0286);
    assert!((p1.depth - 0.8).abs() < 1e-9 && (p2.depth - 1.3).abs() < 1e-9);
    assert!((p2.infeed - 0.5).abs() < 1e-9, "the seed's second infeed is 0.5 mm: {}", p2.infeed);
    assert_eq!((p1.role, p2.role), (Role::Rough, Role::Finish));
    // Taper R(i) = start radius − end radius of the cut = (27.4286 − 48.8571)/2.
    eq(t.taper, (27.4286 - 48.8571) / 2.0);
    // Motions: two thread cuts, each with retract and return rapids.
    let cuts: Vec<_> = plan.moves.iter().filter(|m| m.kind == MoveKind::Thread).collect();
    assert_eq!(cuts.len(), 2);
    assert_eq!((cuts[0].line, cuts[1].line), (3, 7));
    // Each motion keeps the span of its block.
    let sp = cuts[0].span;
    assert_eq!(&O0009[sp.start as usize..sp.end as usize], "G32 X48.8571 W-75 F2.0;\t(锥螺纹第一次切削)");
    let rapids: Vec<_> = plan.moves.iter().filter(|m| m.kind == MoveKind::Rapid).map(|m| m.line).collect();
    assert_eq!(rapids, vec![4, 5, 6, 8, 9]);
    let d = one(&plan, Code::CrestAssumed);
    assert_eq!((d.line, d.column), (2, 1));
}

/// Seed 004 (textbook O1006): M48×2, five passes X47.1 46.5 45.9 45.5 45.4 from Z70 to Z13.
#[test]
fn o1006_textbook_four_block_passes() {
    let plan = gsk(O1006);
    no_alarm(&plan);
    assert_eq!(plan.threads.len(), 1);
    let t = &plan.threads[0];
    assert_eq!(t.kind, ThreadKind::Straight);
    eq(t.lead, 2.0);
    eq(t.pitch, 2.0);
    assert_eq!(t.starts, 1);
    let xs = [47.1, 46.5, 45.9, 45.5, 45.4];
    assert_eq!(t.passes.len(), 5);
    for (i, (p, x)) in t.passes.iter().zip(xs).enumerate() {
        pt(p.from, x, 70.0);
        pt(p.to, x, 13.0);
        assert_eq!(p.index as usize, i + 1);
        assert_eq!(p.start, 1);
    }
    // Table 4-4: the crest is D = 48 (45.4 + 1.3·2), infeeds 0.9 0.6 0.6 0.4 0.1 on the diameter.
    eq(t.crest, 48.0);
    let infeeds: Vec<f64> = t.passes.iter().map(|p| (2.0 * p.infeed * 1e6).round() / 1e6).collect();
    assert_eq!(infeeds, vec![0.9, 0.6, 0.6, 0.4, 0.1]);
    let depths: Vec<f64> = t.passes.iter().map(|p| (p.depth * 1e6).round() / 1e6).collect();
    assert_eq!(depths, vec![0.45, 0.75, 1.05, 1.25, 1.3]);
    eq(t.height, 1.3);
    // File lines: N30 is line 5, N40 line 6 ... each pass is infeed, cut, retract, return.
    assert_eq!(t.passes[0].lines, vec![5, 6, 7, 8]);
    assert_eq!(t.passes[1].lines, vec![9, 10, 11, 12]);
    assert_eq!(t.passes[4].lines, vec![21, 22, 23, 24]);
    assert_eq!(t.passes[4].role, Role::Finish);
    assert!(t.passes[..4].iter().all(|p| p.role == Role::Rough));
    // The programmed infeeds are table 4-3's for pitch 2.
    let d = one(&plan, Code::InfeedGuidance);
    assert!(d.message.ends_with("(as the table)"), "{}", d.message);
    // Both lists written as shown, in the message and, as text, in the plan's JSON.
    let listed = "diameter infeeds 0.9 0.6 0.6 0.4 0.1; programmed: 5 passes, 0.9 0.6 0.6 0.4 0.1 (";
    assert!(d.message.contains(listed), "{}", d.message);
    let json = plan.to_json();
    assert!(json.contains(r#""table":"0.9 0.6 0.6 0.4 0.1","count":5,"infeeds":"0.9 0.6 0.6 0.4 0.1""#), "{json}");
    assert_eq!(plan.with_code(Code::InfeedTooLarge).count(), 0);
    // G50 X0 Z0 sets the position, so the approach N20 G00 X58 Z70 is drawn from X0 Z0.
    let first = plan.moves[0];
    assert_eq!(first.kind, MoveKind::Rapid);
    pt(first.from, 0.0, 0.0);
    pt(first.to, 58.0, 70.0);
    assert_eq!(first.line, 4);
}

/// The same programs read by the Fanuc dialect: the decimal points are all
/// there, so the geometry is the same (Z3 in O0009 has no point and warns).
#[test]
fn seeds_under_fanuc() {
    let plan = plan_with(O1006, Dialect::Fanuc0i, &[]);
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.passes.len(), 5);
    // N10 G50 X0 Z0: no decimal point, but 0 is 0 either way: no warning.
    assert_eq!(plan.with_code(Code::NoDecimalPoint).filter(|d| d.line == 2).count(), 0);
    let plan = plan_with(O0009, Dialect::Fanuc0i, &[]);
    let d = at(&plan, Code::NoDecimalPoint, 2, 14);
    assert!(d.message.contains("0.003 mm"), "{}", d.message);
    pt(plan.threads[0].passes[0].from, 27.4286, 0.003);
}
