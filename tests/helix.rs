//! A pass that cuts another helix on the surface the other passes thread:
//! another lead, a start angle Q or a start Z that is not a whole number of
//! leads from theirs. The controller cuts what it is told, so the part is
//! cross-threaded; the preview warns on that pass (`cross-thread`). Passes
//! split evenly between helices are a multi-start thread and are not
//! warned about.
//!
//! The helix a block-by-block pass cuts is fixed by where and at which
//! spindle angle the synchronised move starts (the one-revolution signal,
//! threading.md §1: "the spindle encoder's one-rev signal starts every
//! pass, so each pass follows the same helix"; GSK980TDc manual §3.21.1,
//! seed 001: Q is the start angle, 0.001°).

mod common;
use common::*;
use screwcut::{Code, Dialect, Plan};

const O1006: &str = include_str!("../examples/o1006.nc");

fn gsk(src: &str) -> Plan {
    plan_with(src, Dialect::Gsk980tdc, &[])
}

fn cross(plan: &Plan) -> Vec<(u32, String)> {
    plan.with_code(Code::CrossThread).map(|d| (d.line, d.message.clone())).collect()
}

/// O1006 with the third pass at F2.5: three threads, and that pass warned
/// about (line 14, N120), naming both leads.
#[test]
fn another_lead_on_the_same_surface() {
    let plan = gsk(&O1006.replace("N120 G32 Z13.0 F2.0;", "N120 G32 Z13.0 F2.5;"));
    assert_eq!(plan.threads.len(), 3);
    let c = cross(&plan);
    assert_eq!(c.len(), 1, "{c:?}");
    assert_eq!(c[0].0, 14);
    assert!(c[0].1.contains("lead of 2.5") && c[0].1.contains("cut 2:"), "{}", c[0].1);
    // The textbook program as written: no warning.
    assert!(cross(&gsk(O1006)).is_empty());
}

/// The third pass starts 0.7 mm nearer (Z69.3): 0.35 of a lead of 2, a
/// helix 126° off; a start two leads further (Z74) is the same helix.
#[test]
fn another_axial_start() {
    let plan = gsk(&O1006.replace("N100 Z70.0;", "N100 Z69.3;"));
    let c = cross(&plan);
    assert_eq!(c.len(), 1, "{c:?}");
    assert_eq!(c[0].0, 14);
    assert!(c[0].1.contains("126°") && c[0].1.contains("Z 69.3"), "{}", c[0].1);
    assert!(cross(&gsk(&O1006.replace("N100 Z70.0;", "N100 Z74.0;"))).is_empty());
}

/// One pass with a start angle among passes without: a second helix. Two
/// starts with a pass each per depth (the example program): none.
#[test]
fn a_lone_start_angle_but_not_a_two_start_thread() {
    let lone = O1006.replace("N120 G32 Z13.0 F2.0;", "N120 G32 Z13.0 F2.0 Q90000;");
    let c = cross(&gsk(&lone));
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(c[0].1.contains("90°") && c[0].1.contains("Q 90°"), "{}", c[0].1);
    let two = gsk(include_str!("../examples/g32-multistart-q.nc"));
    assert_eq!(two.threads[0].starts, 2);
    assert!(cross(&two).is_empty());
}

/// A two-start thread cut by moving the start half a lead (LinuxCNC's G33
/// has no start angle: lead 3, the second start's passes begin 1.5 mm
/// further): passes split evenly, no warning, and they are read as the
/// thread's two starts (a start angle θ is the helix of an axial shift
/// lead·θ/360°, GSK980TDc manual §3.24.1); one pass of the second start
/// alone is a mistake. In Chinese the warning names both leads.
#[test]
fn a_two_start_thread_by_axial_offset_and_the_chinese_text() {
    let program = |xs: &[f64], second: usize| {
        let mut src = String::from("G18 G21 G90\nM3 S300\nG0 X40 Z5\n");
        for (k, x) in xs.iter().enumerate() {
            src += &format!("G0 X{x}\nG33 Z-30 K3\nG0 X42\nZ5\n");
            if k < second {
                src += &format!("G0 X{x} Z6.5\nG33 Z-30 K3\nG0 X42\nZ5\n");
            }
        }
        src + "M2\n"
    };
    let even = plan_with(&program(&[38.8, 38.2, 37.8], 3), Dialect::LinuxCnc, &[]);
    no_alarm(&even);
    assert_eq!(even.threads.iter().map(|t| t.passes.len()).sum::<usize>(), 6);
    assert!(cross(&even).is_empty(), "{:?}", cross(&even));
    // They are one thread of two starts, lead 3, pitch 1.5, the second start
    // at 180° (its axial offset 1.5, half the lead), alternating pass by pass.
    let t = &even.threads[0];
    assert_eq!((even.threads.len(), t.starts), (1, 2));
    assert!((t.pitch - 1.5).abs() < 1e-9 && (t.lead - 3.0).abs() < 1e-9);
    assert_eq!(t.passes.iter().map(|p| p.start).collect::<Vec<_>>(), [1, 2, 1, 2, 1, 2]);
    let starts = screwcut::diagram::starts::starts_of(&even, 0);
    let seen: Vec<(u32, f64, f64)> = starts.iter().map(|s| (s.number, s.angle, s.offset)).collect();
    assert_eq!(seen.len(), 2);
    assert!((seen[1].1 - 180.0).abs() < 1e-6 && (seen[1].2 - 1.5).abs() < 1e-9, "{seen:?}");
    // Each start's depths are its own: the second start's first pass is its first cut.
    assert!(
        (t.passes[1].depth - t.passes[0].depth).abs() < 1e-9 && (t.passes[1].infeed - t.passes[1].depth).abs() < 1e-9
    );
    let lone = plan_with(&program(&[38.8, 38.2, 37.8, 37.6], 1), Dialect::LinuxCnc, &[]);
    let c = cross(&lone);
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(c[0].1.contains("180°"), "{}", c[0].1);
    // A stray pass is no start: the passes it joins keep one.
    assert!(lone.threads.iter().all(|t| t.starts == 1));
    let plan = gsk(&O1006.replace("N120 G32 Z13.0 F2.0;", "N120 G32 Z13.0 F2.5;"));
    let d = plan.with_code(Code::CrossThread).next().unwrap();
    let zh = d.render(screwcut::message::Lang::Zh);
    assert!(zh.contains("导程是 2.5") && zh.contains("导程是 2："), "{zh}");
}

/// A flank infeed written block by block: each of 2,000 passes starts
/// 0.013 further along Z (lead 2), so every pass cuts a helix of its own.
/// No two are starts of one thread and none is a stray against a main
/// helix: one thread, one start, no warning — sorted in time linear in the
/// passes (past 360 helices the sorting stops).
#[test]
fn passes_drifting_along_the_axis_are_one_start() {
    let mut src = String::from("G00 X60 Z70\n");
    for k in 0..2000 {
        let z = 70.0 + 0.013 * f64::from(k);
        src += &format!("G00 X47.1 Z{z:.3}\nG32 Z13 F2\nG00 X60\n");
    }
    src += "M30\n";
    let plan = gsk(&src);
    assert_eq!(plan.threads.len(), 1);
    assert_eq!((plan.threads[0].starts, plan.threads[0].passes.len()), (1, 2000));
    assert!(cross(&plan).is_empty(), "{:?}", &cross(&plan)[..3.min(cross(&plan).len())]);
}
