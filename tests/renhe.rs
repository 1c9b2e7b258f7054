//! Renhe (seed 003): G30 tails, G33 metric and G32 inch threads, the
//! incremental-only rule and the E18 alarms, spindle advice.

mod common;
use common::*;
use screwcut::motion::MoveKind;
use screwcut::thread::Source;
use screwcut::{Code, Dialect, Plan};

fn renhe(src: &str) -> Plan {
    plan_with(src, Dialect::Renhe, &[])
}

/// Seed: "N0080 G30 U10 W2 / N0090 G00 U-16 / N0100 G33 W-40 F1.5": on a
/// 40 mm thread X starts retracting when 2 mm remain (at 38), by 10 (U is a
/// diameter), while Z completes the rest. From X50 Z10: U-16 → X34; the cut
/// runs Z10 → Z−28, the tail to X44 Z−30.
#[test]
fn seed_spiral_tail() {
    let plan = renhe("G00 X50 Z10\nN0080 G30 U10 W2\nN0090 G00 U-16\nN0100 G33 W-40 F1.5\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert_eq!(t.source, Source::Renhe);
    eq(t.lead, 1.5);
    let p = &t.passes[0];
    pt(p.from, 34.0, 10.0);
    pt(p.to, 34.0, -28.0);
    pt(p.runout_to.unwrap(), 44.0, -30.0);
    assert_eq!(p.lines, vec![3, 4]);
    let tail: Vec<_> = plan.moves.iter().filter(|m| m.kind == MoveKind::Runout).collect();
    assert_eq!(tail.len(), 1);
    assert_eq!(tail[0].line, 4);
}

/// Seed: "N0160 G33 W-50 F1.5": a metric right-hand thread of pitch 1.5, 50 mm
/// towards −Z, with the standard tail (no G30): 1.2 mm radial at 45°, so the
/// cut stops 1.2 before the end and the tail ends 2.4 up on the diameter.
#[test]
fn seed_metric_standard_tail() {
    let plan = renhe("G00 X40 Z5\nG00 U-10\nN0160 G33 W-50 F1.5\n");
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.from, 30.0, 5.0);
    pt(p.to, 30.0, -43.8);
    pt(p.runout_to.unwrap(), 32.4, -45.0);
    // G30 U0 W0: no tail (tapping to a shoulder).
    let plan = renhe("G00 X40 Z5\nG30 U0 W0\nG00 U-10\nG33 W-50 F1.5\n");
    let p = &plan.threads[0].passes[0];
    pt(p.to, 30.0, -45.0);
    assert_eq!(p.runout_to, None);
    // The standard tail is a setting: 0.8 mm at 30° takes 0.8/tan 30° = 1.385641 of Z.
    let plan = plan_with(
        "G00 X40 Z5\nG00 U-10\nG33 W-50 F1.5\n",
        Dialect::Renhe,
        &["renhe.runout=0.8", "renhe.runout_angle=30"],
    );
    let p = &plan.threads[0].passes[0];
    assert!((p.to.z - (-45.0 + 0.8 / 0.5773502691896257)).abs() < 1e-9);
    pt(p.runout_to.unwrap(), 31.6, -45.0);
}

/// Seed: "N0180 G32 W50 F11.2": 50 mm towards +Z (a left-hand thread), inch,
/// 11 threads per inch with the fraction 1/2: 11.5 TPI, lead 25.4/11.5 = 2.208696 mm.
#[test]
fn seed_inch_fraction() {
    let plan = renhe("G00 X40 Z-60\nG00 U-10\nN0180 G32 W50 F11.2\n");
    no_alarm(&plan);
    let t = &plan.threads[0];
    eq(t.lead, 25.4 / 11.5);
    let p = &t.passes[0];
    pt(p.from, 30.0, -60.0);
    // Towards +Z: the tail is in the last 1.2 mm before Z−10.
    pt(p.to, 30.0, -11.2);
    pt(p.runout_to.unwrap(), 32.4, -10.0);
    // renhe.inch_f = decimal reads F11.2 as 11.2 TPI.
    let plan = plan_with("G00 X40 Z-60\nG00 U-10\nG32 W50 F11.2\n", Dialect::Renhe, &["renhe.inch_f=decimal"]);
    eq(plan.threads[0].lead, 25.4 / 11.2);
}

/// Seed: "N0150 G01 U-10 F150 / N0160 G33 W-50 F2": the X feed is negative, so
/// the tail retracts positive; after a positive feed it retracts negative.
#[test]
fn seed_run_out_direction() {
    let plan = renhe("G00 X40 Z5\nN0150 G01 U-10 F150\nN0160 G33 W-50 F2\n");
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    assert!(p.runout_to.unwrap().x > p.to.x);
    let plan = renhe("G00 X20 Z5\nG01 U10 F150\nG33 W-50 F2\n");
    let p = &plan.threads[0].passes[0];
    pt(p.runout_to.unwrap(), 30.0 - 2.4, -45.0);
    assert!(plan.threads[0].internal);
}

/// A taper: U is a diameter difference.
#[test]
fn taper_with_u() {
    let plan = renhe("G00 X40 Z5\nG30 U0 W0\nG00 U-10\nG33 U4 W-40 F2\n");
    no_alarm(&plan);
    let p = &plan.threads[0].passes[0];
    pt(p.to, 34.0, -35.0);
    assert_eq!(plan.threads[0].kind, screwcut::thread::ThreadKind::Taper);
}

/// E18-03: X or Z in a thread block; E18-04: |W| not above |U| or 4 mm;
/// E18-05: no X feed before the thread.
#[test]
fn e18_alarms() {
    let p = renhe("G00 X40 Z5\nG00 U-10\nG33 Z-40 F1.5\n");
    assert!(at(&p, Code::E18_03, 3, 5).message.contains("W instead of Z-40"));
    let p = renhe("G00 X40 Z5\nG00 U-10\nG32 X30 W-40 F11\n");
    at(&p, Code::E18_03, 3, 5);
    let p = renhe("G00 X40 Z5\nG00 U-10\nG33 W-3 F1\n");
    at(&p, Code::E18_04, 3, 5);
    let p = renhe("G00 X40 Z5\nG00 U-10\nG33 U-20 W-10 F1\n");
    assert!(at(&p, Code::E18_04, 3, 10).message.contains("|U| = 20"));
    let p = renhe("G00 X40 Z5\nG33 W-40 F1.5\n");
    at(&p, Code::E18_05, 2, 1);
    assert!(p.threads.is_empty());
    // Ranges: metric pitch 0.25..12, inch 3..33 TPI.
    let p = renhe("G00 X40 Z5\nG00 U-10\nG33 W-40 F13\n");
    at(&p, Code::ValueOutOfRange, 3, 10);
    let p = renhe("G00 X40 Z5\nG00 U-10\nG32 W-40 F40\n");
    at(&p, Code::ValueOutOfRange, 3, 10);
    // A spiral tail longer than the thread.
    let p = renhe("G00 X40 Z5\nG30 U4 W50\nG00 U-10\nG33 W-40 F1.5\n");
    at(&p, Code::RunoutTooLong, 4, 1);
    // G30 with U only.
    let p = renhe("G30 U4\n");
    at(&p, Code::MissingWord, 1, 1);
}

/// n ≤ 2300/t − 60: pitch 2 allows 1090 rev/min; S1500 warns once, S1000 does not.
#[test]
fn spindle_advice() {
    let p = renhe("S1500 M03\nG00 X40 Z5\nG00 U-10\nG33 W-40 F2\nG00 U10\nW40\nU-10.4\nG33 W-40\n");
    let d = one(&p, Code::SpindleSpeed);
    assert_eq!((d.line, d.column), (4, 1));
    assert!(d.message.contains("1090"), "{}", d.message);
    let p = renhe("S1000 M03\nG00 X40 Z5\nG00 U-10\nG33 W-40 F2\n");
    assert_eq!(p.with_code(Code::SpindleSpeed).count(), 0);
    // Inch threads are converted: 8 TPI is 3.175 mm, 2300/3.175 − 60 = 664.4.
    let p = renhe("S700 M03\nG00 X40 Z5\nG00 U-10\nG32 W-40 F8\n");
    assert!(one(&p, Code::SpindleSpeed).message.contains("664"));
}

/// Renhe passes cut in the textbook pattern group into one thread.
#[test]
fn passes_group() {
    let mut src = String::from("G00 X58 Z70\nG30 U0 W0\n");
    // O1006 written incrementally: infeed from X58 to 47.1, 46.5, 45.9, 45.5, 45.4.
    for x in [47.1, 46.5, 45.9, 45.5, 45.4] {
        let u: f64 = 58.0 - x;
        src += &format!("G00 U-{u:.1}\nG33 W-57 F2\nG00 U{u:.1}\nW57\n");
    }
    let p = renhe(&src);
    no_alarm(&p);
    assert_eq!(p.threads.len(), 1, "{:#?}", p.threads);
    let t = &p.threads[0];
    assert_eq!(t.passes.len(), 5);
    pt(t.passes[4].from, 45.4, 70.0);
    pt(t.passes[4].to, 45.4, 13.0);
    assert_eq!(t.passes[1].lines, vec![7, 8, 9, 10]);
    eq(t.crest, 48.0);
}
