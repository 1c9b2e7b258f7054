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

/// The insert in the tooth section (setting `tool.insert`): a full profile
/// forms the standard's root — its nose, r = 0.125·P = 0.25 for P 2
/// (ISO 965-1's smallest root radius), tangent to the 60° flanks — and the
/// crest (its edges P/8 along the crest line); a partial profile only the
/// root, with its maker's nose (setting `tool.nose_radius`).
#[test]
fn the_tooth_section_draws_the_insert() {
    use screwcut::diagram::{Shape, Style, tooth};
    let o1006 = include_str!("../examples/o1006.nc");
    let full = plan_with(o1006, Dialect::Gsk980tdc, &["tool.insert=16ER 2.0 ISO"]);
    let form = full.threads[0].shop.insert.clone().expect("the insert");
    assert!(form.full && (form.nose_radius - 0.25).abs() < 1e-12, "{form:?}");
    let scene = tooth(&full, 0, 1).unwrap();
    let last = 4; // the finishing pass, depth 1.3
    let tools: Vec<_> = scene.items.iter().filter(|i| i.style == Style::Tool && i.pass == Some(last)).collect();
    // The V of the pass, its tip marker, the insert's outline and its two crest edges.
    assert_eq!(tools.len(), 5, "{tools:#?}");
    let Shape::Polyline { points } = &tools[2].shape else { panic!("the insert's outline") };
    // The nose's lowest point: r/sin 30° − r = 0.25 above the V's apex at −1.3.
    let lowest = points.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    assert!((lowest - (-1.3 + 0.25)).abs() < 1e-9, "{lowest}");
    let notes: Vec<_> = scene
        .items
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Text { label, .. } if label.key == "insert_full" => Some(label.value.to_string()),
            _ => None,
        })
        .collect();
    assert_eq!(notes, ["16ER 2.0 ISO r 0.25"]);
    let partial = plan_with(o1006, Dialect::Gsk980tdc, &["tool.insert=16ER AG60", "tool.nose_radius=0.2"]);
    let form = partial.threads[0].shop.insert.clone().unwrap();
    assert!(!form.full && (form.nose_radius - 0.2).abs() < 1e-12);
    let scene = tooth(&partial, 0, 1).unwrap();
    let tools = scene.items.iter().filter(|i| i.style == Style::Tool && i.pass == Some(last)).count();
    assert_eq!(tools, 3, "the V, the marker and the insert: no crest edges");
    // No insert given: nothing drawn of one.
    let none = plan_with(o1006, Dialect::Gsk980tdc, &[]);
    assert!(none.threads[0].shop.insert.is_none());
}

/// The approach (`approach-into-part`): a thread whose passes start inside
/// the turned part plunges into it in rapid.
#[test]
fn a_thread_starting_inside_the_part_plunges_into_it() {
    let inside =
        "G00 X60 Z2\nG01 X48 F0.2\nZ-40\nG00 X60\nZ-5\nX47.1\nG32 Z-35 F2\nG00 X60\nZ-5\nX46.5\nG32 Z-35\nG00 X60\n";
    let plan = plan_with(inside, Dialect::Gsk980tdc, &[]);
    let d = plan.with_code(Code::ApproachIntoPart).collect::<Vec<_>>();
    assert_eq!(d.len(), 1, "once per thread");
    assert_eq!(d[0].line, 7);
    // Starting before the work (Z5): clear.
    let outside = inside.replace("Z-5", "Z5");
    assert!(plan_with(&outside, Dialect::Gsk980tdc, &[]).with_code(Code::ApproachIntoPart).next().is_none());
}
