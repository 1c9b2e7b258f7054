//! Shop-floor truths (issue #13): cycle time, machine limits, δ1/δ2 from the
//! speed, chip load, helix angle and the thread check, with the arithmetic
//! worked by hand in the comments.
//!
//! Sources:
//! - [REF] /work/shared/reference/threading.md §6 (O1006) and §9 (thread
//!   feed, δ1 ≈ n·L/500, δ2 ≈ n·L/1800, cycle time, d2 = X − 2r·(1/sin(a/2) − 1)
//!   + P/(2·tan(a/2)), helix angle, M48×2-6g d2 46.483 … 46.663).
//! - [O1006] seed 004, the textbook chapter: O1006 at S300, passes X47.1 …
//!   X45.4 from Z70 to Z13, F2; figure 4.6 puts the work at Z15 … Z65
//!   (δ1 = 5, δ2 = 2, thread length 50).
//! - [DIN13], [EFUNDA], [ALLOYS]: the published limit tables cited in
//!   tests/standards.rs (ISO 965-2 / DIN 13 6g/6H, ASME B1.1, ASME B1.20.1).

mod common;
use common::*;
use screwcut::planner::Planner;
use screwcut::settings::Settings;
use screwcut::shop::ClearanceSource;
use screwcut::standard::{Kind, System};
use screwcut::{Code, Dialect, Plan};

const O1006: &str = include_str!("../examples/o1006.nc");

/// √3/2: P/(2·tan 30°) per unit of pitch.
const H60: f64 = 0.866_025_403_784_438_6;

const SPEED_CODES: [Code; 5] =
    [Code::ThreadFeedLimit, Code::SpindleLimit, Code::ThreadCss, Code::Delta1Speed, Code::Delta2Speed];

#[track_caller]
fn near(a: Option<f64>, b: f64, tol: f64) {
    let a = a.unwrap_or_else(|| panic!("no value, wanted {b}"));
    assert!((a - b).abs() <= tol, "{a} != {b} (±{tol})");
}

fn none_of(plan: &Plan, codes: &[Code]) {
    for c in codes {
        assert_eq!(plan.with_code(*c).count(), 0, "unexpected {c}: {:#?}", plan.diagnostics);
    }
}

/// O1006 with the textbook's designation in a comment before its first block.
fn o1006_named() -> String {
    O1006.replace("N20 G00 X58.0 Z70.0;", "(M48x2-6g)\nN20 G00 X58.0 Z70.0;")
}

// ---- time ----

/// [O1006] at S300: each pass cuts Z70 → Z13 = 57 mm at lead 2 × 300 = 600
/// mm/min, 5.7 s; five passes 28.5 s. The rapids at the default 5000 (X,
/// radius) and 10000 (Z) mm/min: passes 1–4 go in and out by (58 − X)/2
/// each way, (58 − X)·0.006 s per way, and back 57 mm in Z, 0.342 s; pass 5
/// goes in 6.3 mm (0.0756 s), out X45.4 → X100 27.3 mm (0.3276 s) and back
/// Z13 → Z100 87 mm (0.522 s). Rapids: (10.9 + 11.5 + 12.1 + 12.5)·0.012 +
/// 4·0.342 + 0.0756 + 0.3276 + 0.522 = 2.8572 s; total 31.3572 s.
#[test]
fn o1006_at_s300_cuts_in_28_5_seconds() {
    let plan = gsk(O1006);
    no_alarm(&plan);
    none_of(&plan, &SPEED_CODES);
    let s = &plan.threads[0].shop;
    near(s.cut_time_s, 28.5, 1e-9);
    near(s.time_s, 31.3572, 1e-9);
    near(plan.time_s, 31.3572, 1e-9);
    // Pass 1: 5.7 + 10.9·0.012 + 0.342 = 6.1728 s.
    near(s.pass_time_s.first().copied(), 6.1728, 1e-9);
    assert_eq!(s.pass_time_s.len(), 5);
    near(s.rpm, 300.0, 0.0);
    near(s.thread_feed, 600.0, 1e-9);
    // δ1 ≈ 300·2/500 = 1.2, δ2 ≈ 300·2/1800 = 0.3333 against the assumed 5 and 2.
    near(s.lead_in_needed, 1.2, 1e-9);
    near(s.run_out_needed, 600.0 / 1800.0, 1e-9);
    assert_eq!(s.clearance_source, Some(ClearanceSource::Assumed));
    near(s.lead_in, 5.0, 0.0);
    near(s.run_out, 2.0, 0.0);
    // The JSON carries them on the thread and the plan.
    let json = plan.to_json();
    for key in ["\"cut_time_s\":28.5", "\"time_s\":31.3572", "\"rpm_limit\":4000", "\"gauge\":null"] {
        assert!(json.contains(key), "{key} not in the JSON");
    }
}

/// Rapid rates are settings: at 2500/5000 mm/min the rapids take twice as long.
#[test]
fn rapid_rates_are_settings() {
    let plan = plan_with(O1006, Dialect::Gsk980tdc, &["machine.rapid_x=2500", "machine.rapid_z=5000"]);
    near(plan.threads[0].shop.time_s, 28.5 + 2.0 * 2.8572, 1e-9);
}

/// No S before the thread: no time, no speed checks, no diagnostics about it.
#[test]
fn no_spindle_speed_no_time() {
    let plan = gsk(&O1006.replace("N15 S300 M03 T0101;", "N15 M03 T0101;"));
    let s = &plan.threads[0].shop;
    assert_eq!((s.cut_time_s, s.time_s, s.rpm, plan.time_s), (None, None, None, None));
    none_of(&plan, &SPEED_CODES);
}

/// An inch program: 1/4-20 at S1000 is 0.05 in × 1000 = 50 in/min; each
/// pass cuts Z0.2 → Z-1 = 1.2 in, 1.44 s; two passes 2.88 s. The rapids
/// convert to mm: X0.4 → X0.2 is 0.1 in of radius = 2.54 mm, 0.03048 s.
#[test]
fn inch_program_time() {
    let src = "G20\nS1000 M03\nG00 X0.4 Z0.2\nX0.2\nG32 Z-1.0 F0.05\nG00 X0.4\nZ0.2\nX0.1713\nG32 Z-1.0\nG00 X0.4\nZ0.2\nM30\n";
    let plan = gsk(src);
    let s = &plan.threads[0].shop;
    near(s.cut_time_s, 2.88, 1e-9);
    near(s.thread_feed, 50.0, 1e-9);
    // Pass 1: in 2.54 mm and out 2.54 mm at 5000 (0.03048 s each), back 1.2 in = 30.48 mm at 10000 (0.18288 s).
    near(s.pass_time_s.first().copied(), 1.44 + 2.0 * 0.03048 + 0.18288, 1e-9);
}

// ---- machine limits ----

/// [REF] §9: a 6 mm lead at S3000 is 18000 mm/min, over the 8000 of
/// `machine.max_thread_feed`; 8000/6 = 1333.3: S1333 fits.
#[test]
fn feed_limit_at_a_6mm_lead_and_s3000() {
    let src = "S3000 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F6\nG00 X58\nZ70\n";
    let plan = gsk(src);
    let d = at(&plan, Code::ThreadFeedLimit, 4, 1);
    for part in ["18000 mm/min", "lead 6 mm × 3000 rev/min", "machine's 8000 mm/min", "at most S1333"] {
        assert!(d.message.contains(part), "{part}: {}", d.message);
    }
    near(plan.threads[0].shop.rpm_limit, 1333.0, 0.0);
    // A faster machine takes it.
    let plan = plan_with(src, Dialect::Gsk980tdc, &["machine.max_thread_feed=20000"]);
    assert_eq!(plan.with_code(Code::ThreadFeedLimit).count(), 0);
}

/// S above `machine.max_rpm`: one warning per thread with the numbers.
#[test]
fn spindle_above_the_machine() {
    let src = "S5000 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F1\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\nZ70\n";
    let plan = gsk(src);
    assert!(one(&plan, Code::SpindleLimit).message.contains("S5000"));
    let plan = plan_with(src, Dialect::Gsk980tdc, &["machine.max_rpm=6000"]);
    assert_eq!(plan.with_code(Code::SpindleLimit).count(), 0);
}

/// [REF] §9: under G96 the speed changes with X. G96 S150 (m/min) at X47.1:
/// n = 1000·150/(π·47.1) = 1013.7 rev/min; with G50 S800 the clamp holds it
/// at 800 and the 57 mm cut takes 57/(2·800) min = 2.1375 s.
#[test]
fn thread_under_g96() {
    let src = "G96 S150 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n";
    let plan = gsk(src);
    let d = one(&plan, Code::ThreadCss);
    assert!(d.message.contains("1014 rev/min at X47.1") && d.message.contains("G97"), "{}", d.message);
    let n = 150_000.0 / (std::f64::consts::PI * 47.1);
    near(plan.threads[0].shop.rpm, n, 1e-9);
    near(plan.threads[0].shop.cut_time_s, 57.0 / (2.0 * n) * 60.0, 1e-9);
    let plan = gsk(&format!("G50 S800\n{src}"));
    near(plan.threads[0].shop.cut_time_s, 2.1375, 1e-9);
    // G97 cancels it.
    let plan = gsk(&src.replace("G96 S150", "G97 S1000"));
    assert_eq!(plan.with_code(Code::ThreadCss).count(), 0);
}

// ---- δ1/δ2 from the speed ----

/// [O1006] at S1500: δ1 ≈ 1500·2/500 = 6 > the 5 mm lead-in (assumed: the
/// program does not turn the work); δ2 ≈ 1500·2/1800 = 1.667 < 2. The cut
/// takes 28.5·300/1500 = 5.7 s.
#[test]
fn o1006_at_s1500_needs_a_longer_lead_in() {
    let plan = gsk(&O1006.replace("S300", "S1500"));
    let d = at(&plan, Code::Delta1Speed, 5, 1);
    for part in ["δ1 = 5", "n·L/500 = 6 at S1500", "shop.assumed_lead_in", "1 earlier", "S1250"] {
        assert!(d.message.contains(part), "{part}: {}", d.message);
    }
    assert_eq!(plan.with_code(Code::Delta2Speed).count(), 0);
    near(plan.threads[0].shop.cut_time_s, 5.7, 1e-9);
    // Without an assumed lead-in nothing is judged.
    let plan = plan_with(&O1006.replace("S300", "S1500"), Dialect::Gsk980tdc, &["shop.assumed_lead_in=0"]);
    assert_eq!(plan.with_code(Code::Delta1Speed).count(), 0);
}

/// [O1006] figure 4.6 turned: the work from Z65 to Z15 at X48, so the
/// program's own δ1 = 70 − 65 = 5 and δ2 = 15 − 13 = 2 are measured. At
/// S300 both suffice (and the textbook's 2–10 mm too); at S1500 δ1 does not.
#[test]
fn figure_4_6_clearances_are_measured() {
    let turned =
        O1006.replace("N20 G00 X58.0 Z70.0;", "N16 G00 X48.0 Z65.0;\nN17 G01 Z15.0 F0.2;\nN20 G00 X58.0 Z70.0;");
    let plan = gsk(&turned);
    none_of(&plan, &[Code::Delta1Speed, Code::Delta2Speed, Code::Clearance]);
    let s = &plan.threads[0].shop;
    assert_eq!(s.clearance_source, Some(ClearanceSource::Outline));
    near(s.lead_in, 5.0, 1e-9);
    near(s.run_out, 2.0, 1e-9);
    let plan = gsk(&turned.replace("S300", "S1500"));
    assert!(one(&plan, Code::Delta1Speed).message.contains("the program's lead-in"));
    // At S2000 δ2 ≈ 2000·2/1800 = 2.2222 > 2 as well.
    let plan = gsk(&turned.replace("S300", "S2000"));
    assert!(one(&plan, Code::Delta2Speed).message.contains("= 2.2222 at S2000"));
}

// ---- the thread check ----

/// [REF] §9 on O1006 named `(M48x2-6g)`, the tool not known: a
/// full-profile insert, r = 0.125·P = 0.25 (ISO 965-1's smallest root
/// radius of an external thread), so the final pass X45.4 cuts d2 = 45.4 −
/// 2·0.25·(1/sin 30° − 1) + 0.866025·2 = 46.632051, within 46.483 … 46.663
/// ([REF], [DIN13]): it gauges, ΔX = 46.573 − 46.632051 = −0.059051, and
/// the note gives the radii that keep d2 within its limits: 47.132051 − 2r
/// in 46.483 … 46.663, r from 0.234526 to 0.324526. With a small-radius
/// insert given (r = 0.05): d2 = 47.032051 > 46.663, it will not gauge,
/// ΔX = 46.573 − 47.032051.
#[test]
fn o1006_with_the_tool_unknown_and_given() {
    let plan = gsk(&o1006_named());
    let g = plan.threads[0].shop.gauge.as_ref().expect("a thread check");
    assert_eq!(
        (g.designation.as_str(), g.system, g.kind, g.class.as_deref()),
        ("M48x2-6g", System::IsoMetric, Kind::External, Some("6g"))
    );
    assert_eq!(g.line, Some(4));
    assert!(g.nose_radius_assumed);
    near(Some(g.nose_radius), 0.25, 1e-12);
    near(Some(g.pitch_diameter), 45.4 - 0.5 + 2.0 * H60, 1e-9);
    near(g.pitch_diameter_min, 46.483, 1e-9);
    near(g.pitch_diameter_max, 46.663, 1e-9);
    // ISO 965: basic d2 = 48 − 0.649519·2 = 46.701; d3 45.251 … 45.797 [DIN13]; d 47.682 … 47.962.
    near(Some(g.basic_pitch), 46.700962, 1e-6);
    near(g.minor_diameter_min, 45.251, 1e-9);
    near(g.minor_diameter_max, 45.797, 1e-9);
    near(g.major_diameter_min, 47.682, 1e-9);
    near(g.minor_diameter, 45.4, 1e-9);
    assert_eq!(g.major_diameter, None, "the program does not turn the crest");
    assert!(g.ok, "{:?}", g.notes);
    near(g.delta_x, 46.573 - (44.9 + 2.0 * H60), 1e-7);
    let [lo, hi] = g.gauges_with_nose.expect("a range of radii");
    near(Some(lo), (45.4 + 2.0 * H60 - 46.663) / 2.0, 1e-4);
    near(Some(hi), (45.4 + 2.0 * H60 - 46.483) / 2.0, 1e-4);
    // Over three wires ([REF] §11): best wire w = P/(2·cos 30°) = 1.154701, M = d2 + 3w − 0.866025·P.
    let wires = g.over_wires.expect("an over-wire measurement");
    near(Some(wires.wire), 2.0 / (2.0 * 30f64.to_radians().cos()), 1e-9);
    near(Some(wires.m), 44.9 + 2.0 * H60 + 3.0 * wires.wire - 2.0 * H60, 1e-9);
    near(wires.m_min, 46.483 + 3.0 * wires.wire - 2.0 * H60, 1e-9);
    near(wires.m_max, 46.663 + 3.0 * wires.wire - 2.0 * H60, 1e-9);
    let d = one(&plan, Code::GaugeOk);
    assert!(d.message.contains("46.6321 (46.483 … 46.663, 6g): it gauges"), "{}", d.message);
    assert!(d.message.contains("r = 0.125·P = 0.25") && d.message.contains("from 0.2345 to 0.3245"), "{}", d.message);
    // Helix angle at that d2: atan(2/(π·46.632051)) = 0.7822°.
    near(
        plan.threads[0].shop.helix_angle_deg,
        (2.0 / (std::f64::consts::PI * (44.9 + 2.0 * H60))).atan().to_degrees(),
        1e-12,
    );

    let plan = plan_with(&o1006_named(), Dialect::Gsk980tdc, &["tool.nose_radius=0.05"]);
    let g = plan.threads[0].shop.gauge.as_ref().unwrap();
    assert!(!g.nose_radius_assumed && g.gauges_with_nose.is_none());
    near(Some(g.pitch_diameter), 45.4 - 0.1 + 2.0 * H60, 1e-9);
    assert!(!g.ok);
    near(g.delta_x, 46.573 - (45.3 + 2.0 * H60), 1e-7);
    let d = one(&plan, Code::GaugeFail);
    assert!(d.message.contains("47.0321 is too large") && d.message.contains("X44.9409"), "{}", d.message);
    assert!(!d.message.contains("not known"), "{}", d.message);
}

/// The setting names the thread when no comment does; a comment naming
/// another pitch is not this thread's.
#[test]
fn designation_from_the_setting() {
    let plan = plan_with(O1006, Dialect::Gsk980tdc, &["thread.designation=M48x2-6g"]);
    let g = plan.threads[0].shop.gauge.as_ref().unwrap();
    assert_eq!((g.source, g.line), (screwcut::figures::DesignationSource::Setting, None));
    let other = O1006.replace("N20 G00 X58.0 Z70.0;", "(M48x1.5-6g)\nN20 G00 X58.0 Z70.0;");
    assert!(gsk(&other).threads[0].shop.gauge.is_none());
    // The comment wins over the setting; the O1006 comments in Chinese name nothing.
    let plan = plan_with(&o1006_named(), Dialect::Gsk980tdc, &["thread.designation=M48x2-4h"]);
    assert_eq!(plan.threads[0].shop.gauge.as_ref().unwrap().class.as_deref(), Some("6g"));
}

/// An internal fine thread, M20x1.5-6H in a bore turned to X18.5, the tool
/// not known: an internal full-profile insert, r = H/8 = 0.108253·1.5 =
/// 0.162380 (the largest within ISO 68-1's basic root flat). The final pass
/// X20.1 cuts D2 = 20.1 − 0.866025·1.5 + 2r = 19.125722 within 19.026 …
/// 19.216 [DIN13]; ΔX = 19.121 − 19.125722 = −0.004722; the root X20.1 is
/// above D min 20 and the bore 18.5 within D1 18.376 … 18.676 [DIN13].
#[test]
fn internal_6h_thread() {
    let src = "(M20x1.5-6H)\nS400 M03\nG00 X18.5 Z2\nG01 Z-40 F0.2\nG00 X17 Z7\nX18.9\nG32 Z-30 F1.5\nG00 X17\nZ7\nX19.4\nG32 Z-30\nG00 X17\nZ7\nX19.8\nG32 Z-30\nG00 X17\nZ7\nX20.1\nG32 Z-30\nG00 X17\nZ7\nM30\n";
    let plan = gsk(src);
    let r = 1.5 * 3f64.sqrt() / 16.0;
    let t = &plan.threads[0];
    assert!(t.internal);
    let g = t.shop.gauge.as_ref().unwrap();
    assert_eq!((g.kind, g.class.as_deref()), (Kind::Internal, Some("6H")));
    near(Some(g.nose_radius), r, 1e-12);
    near(Some(g.pitch_diameter), 20.1 - 1.5 * H60 + 2.0 * r, 1e-9);
    near(g.pitch_diameter_min, 19.026, 1e-9);
    near(g.pitch_diameter_max, 19.216, 1e-9);
    near(g.major_diameter, 20.1, 1e-9);
    near(g.minor_diameter, 18.5, 1e-9);
    assert!(g.ok, "{:?}", g.notes);
    near(g.delta_x, 19.121 - (20.1 - 1.5 * H60 + 2.0 * r), 1e-7);
    // The cut ends 10 mm inside the bore: δ2 is not judged there.
    assert_eq!(plan.with_code(Code::Delta2Speed).count(), 0);
}

/// A two-start thread M30xPh4P2-6g (starts by Q0/Q180°): pitch = lead/starts
/// = 2, so the final X27.4 cuts, with the full-profile insert for P 2 (r =
/// 0.25, the tool not known), d2 = 27.4 − 0.5 + 0.866025·2 = 28.632051 (with
/// the lead, 4, it would be 30.364) within M30x2-6g 28.493 … 28.663 (ISO
/// 965-1: 28.701 − 0.038, Td2(6) = 170 µm for P 2 over 22.4 up to 45 mm).
#[test]
fn multi_start_uses_the_pitch() {
    let pass = |x: &str, q: &str| format!("X{x}\nG32 Z-30 F4 Q{q}\nG00 X40\nZ5\n");
    let src = format!(
        "(M30xPh4P2-6g)\nG00 X40 Z5\n{}{}{}{}",
        pass("29", "0"),
        pass("29", "180000"),
        pass("27.4", "0"),
        pass("27.4", "180000")
    );
    let plan = gsk(&src);
    let t = &plan.threads[0];
    assert_eq!((t.starts, t.lead, t.pitch), (2, 4.0, 2.0));
    let g = t.shop.gauge.as_ref().unwrap();
    near(Some(g.pitch_diameter), 26.9 + 2.0 * H60, 1e-9);
    near(Some(g.nose_radius), 0.25, 1e-12);
    near(g.pitch_diameter_min, 28.493, 1e-9);
    near(g.pitch_diameter_max, 28.663, 1e-9);
    assert!(g.ok);
    // Helix angle with the lead: atan(4/(π·28.632051)) = 2.546°.
    near(t.shop.helix_angle_deg, (4.0 / (std::f64::consts::PI * (26.9 + 2.0 * H60))).atan().to_degrees(), 1e-12);
    // The worst start decides: start 2 left at X27.5 cuts 28.732 > 28.663.
    let src = src.replacen("X27.4\nG32 Z-30 F4 Q180000", "X27.5\nG32 Z-30 F4 Q180000", 1);
    let g = gsk(&src).threads[0].shop.gauge.clone().unwrap();
    near(Some(g.pitch_diameter), 27.0 + 2.0 * H60, 1e-9);
    assert!(!g.ok);
}

/// Alternating infeed: the G78 r = 3 passes keep their outer edges on the
/// final flanks (reference §3), so the envelope is the final pass's V,
/// with the full-profile insert (tool not known, r = 0.25, its virtual
/// sharp tip 0.25 beyond the nose): d2 = 27.4 − 0.5 + 0.866025·2 =
/// 28.632051. A manual G32 whose two last passes start 0.1 apart in Z
/// (Z70.05 and Z69.95) widens the space by 0.1 at every height: it is P/2
/// wide 0.1/(2·tan 30°) lower on each side, so d2 = 45.4 − 0.5 + (1 −
/// 0.1)/tan 30° = 46.458846.
#[test]
fn alternating_infeed_from_the_envelope() {
    let g78 = include_str!("../examples/g78-flank-alternating.nc");
    let plan = gsk(g78);
    let t = &plan.threads[0];
    assert_eq!(t.infeed, screwcut::thread::Infeed::Alternating);
    near(t.shop.gauge.as_ref().unwrap().pitch_diameter.into(), 27.4 - 0.5 + 2.0 * H60, 1e-9);
    let src = "(M48x2-6g)\nG00 X58 Z70\nX46.5\nG32 Z13 F2\nG00 X58\nZ70\nW0.05\nX45.4\nG32 Z13\nG00 X58\nZ69.95\nX45.4\nG32 Z13\nG00 X58\nZ70\n";
    let plan = gsk(src);
    let g = plan.threads[0].shop.gauge.as_ref().unwrap();
    let t30 = 30f64.to_radians().tan();
    near(Some(g.pitch_diameter), 45.4 - 0.5 + 0.9 / t30, 1e-9);
    assert!(!g.ok, "46.4588 is below 46.483");
}

/// Unified, inch program: 1/4-20 UNC-2A ([EFUNDA] pitch diameter 0.2127 …
/// 0.2164). A sharp V at X0.1713 would cut 0.1713 + 0.866025·0.05 = 0.2146013: it
/// gauges; ΔX = 0.21455 − 0.2146013 = −0.0000513 — with the tool not known,
/// a full-profile insert r = 0.125·0.05 = 0.00625, so the final pass is
/// X0.1838: 0.1838 − 0.0125 + 0.866025·0.05 = 0.2146013. 1/2-13 UNC-2B (2B
/// pitch diameter 0.4500 … 0.4565, tests/standards.rs), internal insert r =
/// 0.108253/13 = 0.0083272: X0.5034 cuts 0.5034 − 0.866025/13 + 0.0166544
/// = 0.4534371.
#[test]
fn unified_2a_and_2b() {
    let src = "G20\n(1/4-20 UNC-2A)\nS1000 M03\nG00 X0.4 Z0.2\nX0.2\nG32 Z-1.0 F0.05\nG00 X0.4\nZ0.2\nX0.1838\nG32 Z-1.0\nG00 X0.4\nZ0.2\nM30\n";
    let g = gsk(src).threads[0].shop.gauge.clone().unwrap();
    assert_eq!((g.system, g.class.as_deref()), (System::Unified, Some("2")));
    near(Some(g.pitch_diameter), 0.1838 - 0.0125 + 0.05 * H60, 1e-9);
    near(g.pitch_diameter_min, 0.2127, 1e-9);
    near(g.pitch_diameter_max, 0.2164, 1e-9);
    assert!(g.ok);
    near(g.delta_x, 0.21455 - (0.1838 - 0.0125 + 0.05 * H60), 1e-9);
    let src = "G20\n(1/2-13 UNC-2B)\nG00 X0.4 Z0.2\nX0.47\nG32 Z-1.0 I13\nG00 X0.4\nZ0.2\nX0.5034\nG32 Z-1.0\nG00 X0.4\nZ0.2\nM30\n";
    let g = gsk(src).threads[0].shop.gauge.clone().unwrap();
    assert_eq!(g.kind, Kind::Internal);
    near(Some(g.pitch_diameter), 0.5034 - H60 / 13.0 + 2.0 * 3f64.sqrt() / 16.0 / 13.0, 1e-9);
    near(g.pitch_diameter_min, 0.4500, 1e-9);
    near(g.pitch_diameter_max, 0.4565, 1e-9);
    near(g.major_diameter_min, 0.5, 1e-9);
    assert!(g.ok);
}

/// NPT as far as the taper and diameters go: 1/2-14 NPT, E0 = 0.75843 in
/// ([ALLOYS], tests/standards.rs). The final pass X0.70818 Z0.1 →
/// X0.75193 Z-0.6 tapers 0.04375/0.7 = 0.0625 = 1/16 on diameter; with the
/// tool not known (a full-profile insert, r = 0.125/14 = 0.0089286) its
/// pitch diameter is 0.70818 − 0.0178571 + 0.866025/14 = 0.752182 at Z0.1 and grows
/// 1/16 per unit of Z, so it is E0 at Z = 0.1 − 16·(0.75843 − 0.752179) ≈ 0:
/// the pipe's end must be at Z0 (±1 turn) for the L1 gauge.
#[test]
fn npt_taper_and_gauge_plane() {
    let src = "G20\n(1/2-14 NPT)\nG00 X1.0 Z0.1\nX0.73\nG32 X0.77375 Z-0.6 I14\nG00 X1.0\nZ0.1\nX0.70818\nG32 X0.75193 Z-0.6\nG00 X1.0\nZ0.1\nM30\n";
    let g = gsk(src).threads[0].shop.gauge.clone().unwrap();
    assert_eq!((g.system, g.class.clone()), (System::Npt, None));
    near(g.taper, 0.0625, 1e-9);
    let small = 0.70818 - 0.25 / 14.0 + H60 / 14.0;
    near(Some(g.pitch_diameter), small, 1e-9);
    near(g.gauge_plane_z, 0.1 - 16.0 * (0.75843 - small), 1e-9);
    near(Some(g.basic_pitch), 0.75843, 1e-9);
    assert!(g.ok, "{:?}", g.notes);
    // A 1:12 taper is not NPT.
    let steep = src.replace("X0.77375", "X0.7883").replace("X0.75193", "X0.76651");
    let g = gsk(&steep).threads[0].shop.gauge.clone().unwrap();
    assert!(!g.ok && g.notes.iter().any(|n| n.to_string().contains("not 1/16")), "{:?}", g.notes);
}

// ---- chip load ----

/// [O1006] chip areas with a 60° tool, t = tan 30° = 0.577350: depths 0.45,
/// 0.75, 1.05, 1.25, 1.3 remove t·(h₁² − h₀²) = 0.2025t, 0.36t, 0.54t, 0.46t,
/// 0.1275t; a constant-area schedule of 5 passes to 1.3 removes 1.69t/5 =
/// 0.338t = 0.195144 each at depths 1.3·√(k/5). The first pass is light
/// (0.6 of its share): no advice; the last removes exactly 0.05: not thin.
#[test]
fn o1006_chip_loads() {
    let plan = gsk(O1006);
    let t30 = 30f64.to_radians().tan();
    let chip = &plan.threads[0].shop.chip;
    let want = [0.2025, 0.36, 0.54, 0.46, 0.1275];
    for (k, (c, w)) in chip.iter().zip(want).enumerate() {
        near(c.area, w * t30, 1e-9);
        near(c.even_area, 0.338 * t30, 1e-9);
        near(c.even_depth, 1.3 * ((k + 1) as f64 / 5.0).sqrt(), 1e-9);
    }
    none_of(&plan, &[Code::ChipHeavyFirst, Code::ChipThin, Code::ChipNone]);
    // A tool rated for 0.3 mm² is overloaded by pass 3 (0.54t = 0.3118).
    let plan = plan_with(O1006, Dialect::Gsk980tdc, &["tool.max_chip_area=0.3"]);
    assert!(one(&plan, Code::ChipHeavyFirst).message.contains("pass 3 removes 0.3118"));
}

/// Spring passes remove nothing on purpose: the G78 example's second
/// finishing pass (D2) is not flagged.
#[test]
fn spring_passes_are_not_flagged() {
    let plan = gsk(include_str!("../examples/g78-m30x2.nc"));
    let t = &plan.threads[0];
    assert!(t.passes.iter().any(|p| p.role == screwcut::thread::Role::Spring));
    none_of(&plan, &[Code::ChipNone]);
    let spring = t.passes.iter().position(|p| p.role == screwcut::thread::Role::Spring).unwrap();
    near(t.shop.chip[spring].area, 0.0, 1e-12);
    near(t.shop.chip[spring].even_area, 0.0, 0.0);
}

// ---- incremental planning ----

/// The shop-floor figures of an incremental plan equal those of a full plan.
#[test]
fn incremental_plan_keeps_the_shop_figures() {
    let mut s = Settings::new(Dialect::Gsk980tdc);
    s.assign("tool.nose_radius=0.25").unwrap();
    // One program: the program number once (a second one would start another program).
    let block = o1006_named().replace("N230 M30;\n", "").replace("O1006;\n", "");
    let mut text = block.repeat(70); // 70 threads, past several checkpoints
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    text.push_str("(M30x2-6g)\nS1500\nG00 X40 Z5\nG92 X28 Z-30 F2\nX27.4\nG00 X100\n");
    let inc = p.plan(&text).clone();
    assert!(p.resumed_at() > 1);
    assert_eq!(inc, screwcut::plan(&text, &s));
    let last = inc.threads.last().unwrap();
    assert!(last.shop.gauge.is_some() && last.shop.time_s.is_some());
    near(inc.time_s, inc.threads.iter().map(|t| t.shop.time_s.unwrap()).sum::<f64>(), 1e-9);
}

// ---- the speed between passes ----

/// [REF] §11: O1006 with S400 before its second pass. The axis follows the
/// spindle with a lag, so the second pass starts elsewhere on the helix:
/// warned on its G32 (line 11). With `machine.servo_lag` = 30 ms the start
/// moves lead·Δn/60·T = 2·100/60·0.03 = 0.1 mm, 18° of a turn. Back to S300
/// for the third pass: that pass is on the first pass's helix again, no
/// second warning; O1006 as written: none.
#[test]
fn a_pass_at_another_speed() {
    let src = O1006.replace("N70 X46.5;", "S400\nN70 X46.5;").replace("N110 X45.9;", "S300\nN110 X45.9;");
    let plan = plan_with(&src, Dialect::Gsk980tdc, &["machine.servo_lag=30"]);
    let d = one(&plan, Code::SpeedBetweenPasses);
    assert_eq!(d.line, 11);
    assert!(
        d.message.contains("pass 2 (start 1) is cut at S400") && d.message.contains("moves 0.1 along the axis, 18°"),
        "{}",
        d.message
    );
    assert_eq!(gsk(O1006).with_code(Code::SpeedBetweenPasses).count(), 0);
}

/// A full-profile insert (`16ER 2.0 ISO`, threading.md §11) forms the
/// standard's root: the check takes its radius, 0.125·2 = 0.25, as known —
/// no "not known" note, and no range of radii; a partial-profile insert
/// (`16ER AG60`, 0.5–3 mm) leaves the radius unknown.
#[test]
fn the_insert_gives_the_nose_radius() {
    let plan = plan_with(&o1006_named(), Dialect::Gsk980tdc, &["tool.insert=16ER 2.0 ISO"]);
    let g = plan.threads[0].shop.gauge.as_ref().unwrap();
    assert!(!g.nose_radius_assumed && g.gauges_with_nose.is_none());
    near(Some(g.nose_radius), 0.25, 1e-12);
    assert!(g.notes.iter().any(|n| n.to_string().contains("full-profile insert 16ER 2.0 ISO")), "{:?}", g.notes);
    assert_eq!(plan.with_code(Code::InsertPitch).count() + plan.with_code(Code::InsertSide).count(), 0);
    let plan = plan_with(&o1006_named(), Dialect::Gsk980tdc, &["tool.insert=16ER AG60"]);
    assert!(plan.threads[0].shop.gauge.as_ref().unwrap().nose_radius_assumed);
    assert_eq!(plan.with_code(Code::InsertRange).count(), 0);
}
