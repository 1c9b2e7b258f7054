//! Units belong to each thread: a program may switch G20/G21, and each
//! thread's lengths, lead and shop-floor figures are in the units its words
//! were written in. Machine limits are settings in their own units
//! (`machine.max_thread_feed` in mm/min) and never change with the program's.

mod common;
use common::{eq, no_alarm, plan_with};
use screwcut::plan::Units;
use screwcut::{Code, Dialect, Plan};

/// Rounds to 9 decimals (the figures are products of exact decimals).
fn r9(v: f64) -> f64 {
    (v * 1e9).round() / 1e9
}

/// The same Fanuc G76 thread written in inches and in millimetres (every
/// length × 25.4, P/Q in their own least increments: 0.0001 in, 0.001 mm):
/// k 0.05 in = 1.27 mm, Δd 0.01 in = 0.254 mm, Δdmin 0.005 in = 0.127 mm,
/// 16 threads per inch = lead 1.5875 mm.
const INCH: &str = "G80 G20 G40\nG97 S500 M03\nG00 X1.2 Z.2\nG76 P010060 Q50 R.001\n\
                    G76 X.9 Z-1. P500 Q100 F.0625\nG00 X2.\nM30\n";
const MM: &str = "G80 G21 G40\nG97 S500 M03\nG00 X30.48 Z5.08\nG76 P010060 Q127 R.0254\n\
                  G76 X22.86 Z-25.4 P1270 Q254 F1.5875\nG00 X50.8\nM30\n";

/// The machine allows 8000 mm/min of thread feed: floor(8000 / 1.5875) =
/// S5039 for both (it was S128000 for the inch thread, its lead read as
/// 0.0625 mm). Thread feed, lead-in and run-out needed are in the thread's
/// units: 500 × 0.0625 = 31.25 in/min = 793.75 mm/min; δ1 = n·L/500 =
/// 1.5875 mm = 0.0625 in, δ2 = n·L/1800 = 0.441 mm.
#[test]
fn the_same_thread_in_inch_and_mm_has_the_same_limits() {
    let (inch, mm) = (plan_with(INCH, Dialect::Fanuc0i, &[]), plan_with(MM, Dialect::Fanuc0i, &[]));
    no_alarm(&inch);
    no_alarm(&mm);
    let (a, b) = (&inch.threads[0], &mm.threads[0]);
    assert_eq!((a.units, b.units), (Units::Inch, Units::Mm));
    assert_eq!((a.shop.rpm_limit, b.shop.rpm_limit), (Some(5039.0), Some(5039.0)));
    assert_eq!((a.shop.rpm, b.shop.rpm), (Some(500.0), Some(500.0)));
    eq(r9(a.shop.thread_feed.unwrap()), 31.25);
    eq(r9(b.shop.thread_feed.unwrap()), 793.75);
    eq(r9(a.shop.lead_in_needed.unwrap()), 0.0625);
    eq(r9(b.shop.lead_in_needed.unwrap()), 1.5875);
    eq(r9(a.shop.run_out_needed.unwrap() * 25.4), r9(b.shop.run_out_needed.unwrap()));
    // The program's assumed δ1 5 mm and δ2 2 mm are settings in mm: in inches for the inch thread.
    eq(r9(a.shop.lead_in.unwrap() * 25.4), 5.0);
    eq(r9(b.shop.lead_in.unwrap()), 5.0);
    // The same passes, every length × 25.4; the same times.
    assert_eq!(a.passes.len(), b.passes.len());
    for (p, q) in a.passes.iter().zip(&b.passes) {
        eq(r9(p.depth * 25.4), r9(q.depth));
        eq(r9(p.from.x * 25.4), r9(q.from.x));
    }
    eq(r9(a.shop.cut_time_s.unwrap()), r9(b.shop.cut_time_s.unwrap()));
    eq(r9(a.shop.time_s.unwrap()), r9(b.shop.time_s.unwrap()));
    eq(r9(a.shop.helix_angle_deg.unwrap()), r9(b.shop.helix_angle_deg.unwrap()));
    // Chip notes compare the infeed with chip.min_infeed = 0.05 mm in the thread's units: the same passes in both.
    let thin = |p: &Plan| p.with_code(Code::ChipThin).map(|d| d.line).collect::<Vec<_>>();
    assert_eq!(thin(&inch), thin(&mm));
}

/// An inch LinuxCNC G76 followed by G21 keeps its inch figures: the plan
/// ends in mm, the thread is in inches, and it is the thread of the same
/// program without the G21 (lead 0.0625 in, S400: thread feed 25 in/min,
/// δ1 needed 400 × 1.5875 / 500 mm = 0.05 in, limit S5039).
#[test]
fn an_inch_linuxcnc_g76_followed_by_g21_keeps_inch_figures() {
    let inch = "G18 G20 G90 G7\nM3 S400\nG0 X0.55 Z0.1\nG76 P0.0625 Z-0.75 I-0.05 J0.008 K0.0406 R2 Q29.5 H1\nM2\n";
    let switched = inch.replace("M2\n", "G21\nM2\n");
    let (a, b) = (plan_with(inch, Dialect::LinuxCnc, &[]), plan_with(&switched, Dialect::LinuxCnc, &[]));
    no_alarm(&b);
    assert_eq!((a.units, b.units), (Units::Inch, Units::Mm));
    let t = &b.threads[0];
    assert_eq!(t.units, Units::Inch);
    eq(r9(t.shop.thread_feed.unwrap()), 25.0);
    eq(r9(t.shop.lead_in_needed.unwrap()), 0.05);
    assert_eq!(t.shop.rpm_limit, Some(5039.0));
    assert_eq!(&a.threads[0], t);
    // The same diagnostics but the warning that units changed after motion.
    let others = |p: &Plan| p.diagnostics.iter().filter(|d| d.code != Code::UnitsChanged).count();
    assert_eq!(others(&a), others(&b));
    // The JSON says so on the thread.
    assert!(b.to_json().contains(r#""source":"linuxcnc_g76","units":"inch""#), "{}", b.to_json());
}

/// A G32 thread in mm, then G20 and a G92 thread in inches: each thread in
/// its own units. Lead 1.5 mm fits floor(8000 / 1.5) = S5333; 8 threads
/// per inch (0.125 in = 3.175 mm), floor(8000 / 3.175) = S2519.
#[test]
fn a_program_may_switch_units_between_threads() {
    let src = "G21\nG97 S600 M03\nG00 X30 Z5\nX28.8\nG32 Z-20 F1.5\nG00 X30\nZ5\nX28.4\nG32 Z-20\nG00 X30\nZ5\n\
               G20\nG00 X1.5 Z.2\nG92 X1.35 Z-1. F.125\nX1.3\nG00 X2. Z1.\nM30\n";
    let plan = plan_with(src, Dialect::Gsk980tdc, &[]);
    no_alarm(&plan);
    let units: Vec<Units> = plan.threads.iter().map(|t| t.units).collect();
    assert_eq!(units, [Units::Mm, Units::Inch]);
    assert_eq!(plan.threads[0].shop.rpm_limit, Some(5333.0));
    assert_eq!(plan.threads[1].shop.rpm_limit, Some(2519.0));
    eq(r9(plan.threads[1].shop.thread_feed.unwrap()), 75.0);
    // Table 4-3 is for millimetre pitches: the mm thread's pitch 1.5 is in it, and the advice says so.
    let guided: Vec<u32> = plan.with_code(Code::InfeedGuidance).map(|d| d.line).collect();
    assert_eq!(guided, [4]);
}

/// `expand` writes each thread in its own units: the inch G76 followed by
/// G21 is written after a G20 (not read as millimetres under the program's
/// last G21), and planned again it is the same inch thread.
#[test]
fn expand_writes_a_thread_in_its_units() {
    let src = "G18 G20 G90 G7\nM3 S400\nG0 X0.55 Z0.1\nG76 P0.0625 Z-0.75 I-0.05 J0.008 K0.0406 R2 Q29.5 H1\nG21\nM2\n";
    let before = plan_with(src, Dialect::LinuxCnc, &[]);
    let out = screwcut::expand::expand(&before, Dialect::LinuxCnc).program;
    assert!(out.lines().nth(1) == Some("G20") && !out.contains("G21"), "{out}");
    let after = plan_with(&out, Dialect::LinuxCnc, &[]);
    no_alarm(&after);
    let (a, b) = (&before.threads[0], &after.threads[0]);
    assert_eq!(b.units, Units::Inch);
    assert_eq!(a.passes.len(), b.passes.len());
    for (p, q) in a.passes.iter().zip(&b.passes) {
        assert!((p.from.x - q.from.x).abs() < 1e-4 && (p.to.z - q.to.z).abs() < 1e-4, "{out}");
    }
    assert_eq!(b.shop.rpm_limit, Some(5039.0));
}
