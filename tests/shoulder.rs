//! The tool against a shoulder (`tool-shoulder`): a 60° insert's leading
//! flank lies y·tan 30° ahead of its tip at height y, so a tip at the root
//! of M48×2 (r 22.7) must stay (28 − 22.7)·tan 30° = 3.060 from a shoulder
//! turned up to X56 (r 28). A thread ending 0.3 before it cuts 2.76 into it;
//! 4 before clears it by 0.94 (the two cases).

mod common;
use common::plan_with;
use screwcut::{Code, Dialect};

/// M48×2 by G32, ending `gap` before the shoulder face at Z-40 (turned up to X56).
fn program(gap: f64) -> String {
    let end = -40.0 + gap;
    let mut out = String::from("G00 X60 Z2\nG01 X48 F0.2\nZ-40\nX56\nZ-60\nG00 X60\nZ5\n");
    for x in [47.1, 46.5, 45.9, 45.5, 45.4] {
        out += &format!("X{x}\nG32 Z{end} F2\nG00 X60\nZ5\n");
    }
    out
}

#[test]
fn a_thread_ending_by_a_shoulder_cuts_into_it_unless_the_flank_clears() {
    let near = plan_with(&program(0.3), Dialect::Gsk980tdc, &[]);
    let s = near.threads[0].shop.shoulder.expect("the shoulder at Z-40");
    assert_eq!((s.z, s.edge_x, s.pass), (-40.0, 56.0, 4), "the deepest pass comes nearest");
    assert!((s.needed - 5.3 * 30f64.to_radians().tan()).abs() < 1e-9, "{}", s.needed);
    assert!((s.clearance - (0.3 - 3.0600)).abs() < 1e-3, "{}", s.clearance);
    let d = near.with_code(Code::ToolShoulder).next().expect("a warning");
    assert_eq!(d.line, 25, "at the deepest pass's G32");
    assert!(d.message.contains("cuts 2.76 into the shoulder at Z-40 (up to X56)"), "{}", d.message);
    let far = plan_with(&program(4.0), Dialect::Gsk980tdc, &[]);
    let s = far.threads[0].shop.shoulder.expect("the shoulder is still there");
    assert!((s.clearance - (4.0 - 3.0600)).abs() < 1e-3, "{}", s.clearance);
    assert!(far.with_code(Code::ToolShoulder).next().is_none());
    // No shoulder (O1006 turns nothing): nothing to say.
    let o1006 = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    assert!(o1006.threads[0].shop.shoulder.is_none());
}
