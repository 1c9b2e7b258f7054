//! Scene tests on real programs and on a cycle-shaped plan.

use super::scene::{Item, Scene, Shape, Style};
use super::side::pass_paths;
use super::side::{Band, FeedIndex, deltas, work_extent, work_extent_in};
use super::starts::{RULER_LEN, RULER_X, starts_of};
use super::tooth::cuts;
use super::*;
use crate::motion::{Move, MoveKind, Point};
use crate::plan::{Plan, Units, plan_default};
use crate::thread::{Axis, CrestSource, Infeed, Pass, PassMoves, Role, Source, Thread, ThreadKind};
use crate::{Dialect, Settings};

const O1006: &str = include_str!("../../examples/o1006.nc");
const O0009: &str = include_str!("../../examples/o0009.nc");

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

fn polyline(item: &Item) -> &[[f64; 2]] {
    match &item.shape {
        Shape::Polyline { points } | Shape::Polygon { points } => points,
        _ => &[],
    }
}

fn dims(scene: &Scene) -> Vec<(&'static str, String)> {
    scene
        .items
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Dim { label, .. } => Some((label.key, label.value.to_string())),
            _ => None,
        })
        .collect()
}

fn texts(scene: &Scene) -> Vec<(&'static str, String)> {
    scene
        .items
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Text { label, .. } => Some((label.key, label.value.to_string())),
            _ => None,
        })
        .collect()
}

#[test]
fn o1006_side_has_five_pass_paths_from_z70_to_z13() {
    let plan = plan_default(O1006, Dialect::Gsk980tdc);
    let scene = side(&plan);
    let cuts: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Cut).collect();
    assert_eq!(cuts.len(), 5);
    let xs = [47.1, 46.5, 45.9, 45.5, 45.4];
    let lines = [6, 10, 14, 18, 22];
    for (k, c) in cuts.iter().enumerate() {
        assert_eq!(c.thread, Some(0));
        assert_eq!(c.pass, Some(k as u32));
        assert_eq!(c.lines.to_vec(), vec![lines[k]]);
        let r = xs[k] / 2.0;
        assert_eq!(polyline(c), &[[70.0, r], [13.0, r]], "pass {k}");
    }
    // Each pass is its own path: infeed, cut, retract, return.
    for (k, x) in xs.iter().enumerate() {
        let items: Vec<&Item> = scene.of_pass(0, k).collect();
        let styles: Vec<Style> = items.iter().map(|i| i.style).collect();
        assert_eq!(styles, vec![Style::Rapid, Style::Cut, Style::Rapid, Style::Rapid], "pass {k}");
        // The infeed from the retract at X58: beyond half a thread height over
        // the crest (r 24 + 0.65) the radial scale is broken (diagram::radial):
        // r 29 is drawn at 24.65 + 0.975·ln(1 + 4.35/0.975) = 26.305.
        let infeed = polyline(items[0]);
        assert_eq!(infeed.len(), 3, "{infeed:?}");
        assert!((infeed[0][1] - 26.3053).abs() < 1e-4 && infeed[1] == [70.0, 24.65], "{infeed:?}");
        assert_eq!(infeed[2], [70.0, x / 2.0]);
    }
    // The approach from G50 X0 Z0 belongs to no pass.
    let other: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::OtherRapid).collect();
    assert_eq!(other.len(), 1);
    let approach = polyline(other[0]);
    assert_eq!((approach[0], approach.len()), ([0.0, 0.0], 3));
    assert!((approach[1][0] - 70.0 * 24.65 / 29.0).abs() < 1e-9 && approach[1][1] == 24.65, "{approach:?}");
    assert_eq!(other[0].lines.to_vec(), vec![4]);
    // Dimensions: major 48 (assumed crest), minor 45.4, lead 2, length 57.
    let d = dims(&scene);
    assert!(d.contains(&("dia_major", "48".into())), "{d:?}");
    assert!(d.contains(&("dia_minor", "45.4".into())), "{d:?}");
    assert!(d.contains(&("lead", "2".into())), "{d:?}");
    assert!(d.contains(&("length", "57".into())), "{d:?}");
    assert!(!d.iter().any(|(k, _)| *k == "pitch"), "single start: no pitch dimension");
    // No outline: the crest line is drawn at the assumed major diameter.
    let crest: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Crest).collect();
    assert_eq!(crest.len(), 1);
    assert_eq!(polyline(crest[0]), &[[13.0, 24.0], [70.0, 24.0]]);
    let root = scene.items.iter().find(|i| i.style == Style::Root).unwrap();
    assert!(polyline(root).iter().all(|p| close(p[1], 22.7)));
    // Focus: the cuts and the nearby rapids, not the G50 origin nor the final retract to X100 Z100.
    let f = scene.focus;
    // The retract at r 29 is drawn at 26.305 (the broken scale): the passes take a third of the focus's height, not a fifth.
    assert!(close(f.x0, 13.0) && close(f.x1, 70.0) && close(f.y0, 22.7) && (f.y1 - 26.3053).abs() < 1e-4, "{f:?}");
    // The break line crosses the focus, with its note.
    let brk: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Break).collect();
    assert_eq!(brk.len(), 2);
    assert!(close(scene.bounds.y0, 0.0));
    // The axis is the first item and spans the drawing.
    assert_eq!(scene.items[0].style, Style::Axis);
}

#[test]
fn o0009_side_is_a_taper_with_its_dimension() {
    let plan = plan_default(O0009, Dialect::Gsk980tdc);
    let scene = side(&plan);
    let cuts: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Cut).collect();
    assert_eq!(cuts.len(), 2);
    assert_eq!(polyline(cuts[0]), &[[3.0, 27.4286 / 2.0], [-72.0, 48.8571 / 2.0]]);
    let t = texts(&scene);
    let taper = t.iter().find(|(k, _)| *k == "taper").expect("taper label");
    assert!(taper.1.starts_with("i=-10.714") && taper.1.ends_with("α/2=8.1301°"), "{taper:?}");
    // The crest follows the taper: 29.0286 at Z3, 50.4571 at Z-72.
    let crest = scene.items.iter().find(|i| i.style == Style::Crest).unwrap();
    let pts = polyline(crest);
    assert!(close(pts[0][0], -72.0) && (pts[0][1] - 50.4571 / 2.0).abs() < 1e-6, "{pts:?}");
    assert!(close(pts[1][0], 3.0) && (pts[1][1] - 29.0286 / 2.0).abs() < 1e-6, "{pts:?}");
}

#[test]
fn turned_outline_gives_delta_zones() {
    let text = "G00 X52 Z67\nG01 X48 F0.2\nZ15\nX52\nG00 Z70\nX47.1\nG32 Z13 F2\nG00 X52\nZ70\nX46.5\nG32 Z13 F2\nG00 X52\nZ70\nM30\n";
    let plan = plan_default(text, Dialect::Gsk980tdc);
    let t = &plan.threads[0];
    assert_eq!(t.crest_source, CrestSource::Outline);
    let band = Band::of(t).unwrap();
    let work = work_extent(t, &band, &plan.moves).unwrap();
    assert_eq!(work, (15.0, 67.0));
    assert_eq!(deltas(&band, work), (3.0, 2.0));
    let scene = side(&plan);
    let t = texts(&scene);
    assert!(t.contains(&("delta1", "3".into())), "{t:?}");
    assert!(t.contains(&("delta2", "2".into())), "{t:?}");
    let z1 = scene.items.iter().find(|i| i.style == Style::Delta1).unwrap();
    let xs: Vec<f64> = polyline(z1).iter().map(|p| p[0]).collect();
    assert_eq!(
        (xs.iter().cloned().fold(f64::INFINITY, f64::min), xs.iter().cloned().fold(0.0, f64::max)),
        (67.0, 70.0)
    );
    // The turning moves are the outline, not a crest line.
    assert_eq!(scene.items.iter().filter(|i| i.style == Style::Outline).count(), 3);
    assert!(!scene.items.iter().any(|i| i.style == Style::Crest));
}

/// A plan shaped as the cycles produce it: every motion on one line, a
/// screw-in and a run-out per pass, flank shifts and two starts.
fn cycle_plan() -> Plan {
    let line = 3;
    let a = Point::new(60.0, 75.0);
    let mut moves =
        vec![Move { kind: MoveKind::Rapid, from: Point::new(100.0, 100.0), to: a, line: 2, ..Move::default() }];
    let mut passes = Vec::new();
    let t60 = 30f64.to_radians().tan();
    let crest = 48.0;
    let depths = [0.5, 0.8, 1.0, 1.1];
    for start in 1..=2u32 {
        let dz = if start == 2 { 1.5 } else { 0.0 }; // lead 3, two starts
        let mut prev = 0.0;
        for (i, &d) in depths.iter().enumerate() {
            let shift = -(1.1 - d) * t60; // left flank
            let x = crest - 2.0 * d;
            let z0 = 70.0 + shift + dz;
            let screw = Point::new(x + 2.0 * 0.4, z0);
            let from = Point::new(x, z0 - 3.0);
            let to = Point::new(x, 20.0 + shift + dz);
            let run = Point::new(x + 2.0, 17.0 + shift + dz);
            let seq = [
                (MoveKind::Rapid, a, screw),
                (MoveKind::ScrewIn, screw, from),
                (MoveKind::Thread, from, to),
                (MoveKind::Runout, to, run),
                (MoveKind::Rapid, run, Point::new(a.x, run.z)),
                (MoveKind::Rapid, Point::new(a.x, run.z), a),
            ];
            let base = moves.len();
            for (kind, f, t) in seq {
                moves.push(Move { kind, from: f, to: t, line, ..Move::default() });
            }
            let pass_moves =
                PassMoves { approach: base..base + 1, cut: base + 1..base + 4, retract: base + 4..base + 6 };
            passes.push(Pass {
                start,
                index: i as u32 + 1,
                from,
                to,
                depth: d,
                infeed: d - prev,
                role: if i + 1 == depths.len() { Role::Finish } else { Role::Rough },
                lines: vec![2, 3],
                via: Vec::new(),
                segments: Vec::new(),
                runout_to: Some(run),
                screw_in_from: Some(screw),
                shift,
                angle: 180.0 * (start - 1) as f64,
                area: crate::thread::v_area(60.0, prev, d),
                moves: pass_moves,
                spindle: Default::default(),
            });
            prev = d;
        }
    }
    let thread = Thread {
        line: 2,
        end_line: 3,
        source: Source::G78,
        units: Units::Mm,
        kind: ThreadKind::Straight,
        long_axis: Axis::Z,
        lead: 3.0,
        pitch: 1.5,
        starts: 2,
        internal: false,
        infeed: Infeed::Left,
        tool_angle: 60.0,
        crest,
        crest_source: CrestSource::Cycle,
        turned: None,
        height: 1.1,
        taper: 0.0,
        passes,
        depth_dir: -1.0,
        first_move: 1,
        shop: Default::default(),
    };
    Plan {
        dialect: Dialect::Gsk980tdc,
        units: Units::Mm,
        diagnostics: Vec::new(),
        moves,
        threads: vec![thread],
        time_s: None,
    }
}

#[test]
fn cycle_passes_are_drawn_from_their_own_motions() {
    let plan = cycle_plan();
    let paths = pass_paths(&plan);
    assert_eq!(paths.len(), 8);
    for (k, p) in paths.iter().enumerate() {
        assert_eq!((p.thread, p.pass), (0, k));
        let base = 1 + 6 * k;
        assert_eq!(
            (p.lead_in.clone(), p.cut.clone(), p.tail.clone()),
            (base..base + 1, base + 1..base + 4, base + 4..base + 6)
        );
    }
    let scene = side(&plan);
    let styles: Vec<Style> = scene.of_pass(0, 1).map(|i| i.style).collect();
    assert_eq!(
        styles,
        vec![
            Style::Rapid,
            Style::ScrewIn,
            Style::Cut,
            Style::Runout,
            Style::Rapid,
            Style::Rapid,
            Style::Runout,
            Style::ScrewIn
        ]
    );
    let d = dims(&scene);
    assert!(d.contains(&("lead", "3".into())) && d.contains(&("pitch", "1.5".into())), "{d:?}");
    assert!(d.contains(&("dia_major", "48".into())) && d.contains(&("dia_minor", "45.8".into())), "{d:?}");
}

#[test]
fn tooth_areas_match_the_plan_and_follow_the_flank() {
    let plan = cycle_plan();
    let scene = tooth(&plan, 0, 1).unwrap();
    let t = &plan.threads[0];
    let passes: Vec<(usize, &Pass)> = t.passes.iter().enumerate().filter(|(_, p)| p.start == 1).collect();
    let tool = tooth::tool_of(t, t.pitch);
    let (list, surface) = cuts(tool, &passes, -4.0, 4.0);
    for (c, (_, p)) in list.iter().zip(&passes) {
        // A left-flank infeed keeps the left edge on the flank: each pass removes
        // exactly the V area between its depth and the previous one.
        assert!((c.area - p.area.unwrap()).abs() < 1e-9, "pass {}: {} vs {:?}", p.index, c.area, p.area);
    }
    // The finished space: root at depth 1.1, crest width 2·1.1·tan 30°.
    assert!((surface.at(0.0) + 1.1).abs() < 1e-9);
    let w = 2.0 * 1.1 * 30f64.to_radians().tan();
    assert!(surface.at(-w / 2.0 - 1e-6) > -1e-12 && surface.at(w / 2.0 - 1e-3) < 0.0, "{:?}", surface.pts);
    // Scene: one area and one tool per pass of start 1, a start caption, an infeed arrow along the flank.
    assert_eq!(scene.items.iter().filter(|i| i.style == Style::Area).count(), 4);
    assert_eq!(
        scene.items.iter().filter(|i| i.style == Style::Tool && matches!(i.shape, Shape::Polyline { .. })).count(),
        4
    );
    let tx = texts(&scene);
    assert!(tx.contains(&("start_of", "1/2".into())), "{tx:?}");
    assert!(tx.contains(&("pass_depth_finish", "4: 1.1".into())), "{tx:?}");
    assert!(tx.contains(&("pass_depth", "1: 0.5 ↔-0.3464".into())), "the shift is written: {tx:?}");
    assert!(tx.contains(&("infeed_left", String::new())), "{tx:?}");
    let arrow = scene
        .items
        .iter()
        .find_map(|i| match i.shape {
            Shape::Arrow { from, to } => Some((from, to)),
            _ => None,
        })
        .unwrap();
    let slope = (arrow.1[0] - arrow.0[0]) / (arrow.0[1] - arrow.1[1]);
    assert!((slope - 30f64.to_radians().tan()).abs() < 1e-9, "along the left flank: {slope}");
    assert_eq!(dims(&scene), vec![("height", "1.1".into()), ("pitch", "1.5".into())]);
    assert!(tooth(&plan, 0, 3).is_none());
    assert!(tooth(&plan, 1, 1).is_none());
}

#[test]
fn o1006_tooth_shows_radial_chevrons() {
    let plan = plan_default(O1006, Dialect::Gsk980tdc);
    let scene = tooth(&plan, 0, 1).unwrap();
    let areas: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Area).collect();
    assert_eq!(areas.len(), 5);
    let t = &plan.threads[0];
    for a in &areas {
        let p = &t.passes[a.pass.unwrap() as usize];
        let pts: Vec<(f64, f64)> = polyline(a).iter().map(|q| (q[0], q[1])).collect();
        let got = crate::chip::area(&pts);
        assert!((got - p.area.unwrap()).abs() < 1e-5, "pass {}: {got} vs {:?}", p.index, p.area);
        assert_eq!(a.lines.to_vec(), p.lines);
    }
    let tx = texts(&scene);
    assert!(
        tx.contains(&("pass_depth", "1: 0.45".into())) && tx.contains(&("pass_depth_finish", "5: 1.3".into())),
        "{tx:?}"
    );
    assert!(tx.contains(&("infeed_programmed", String::new())), "{tx:?}");
    assert!(tx.contains(&("tool_angle", "60°".into())), "{tx:?}");
    // External thread: the space opens upward, the root is 1.3 below the crest.
    let prof = scene.items.iter().find(|i| i.style == Style::Profile).unwrap();
    let low = polyline(prof).iter().map(|p| p[1]).fold(0.0, f64::min);
    assert!(close(low, -1.3), "{low}");
}

#[test]
fn starts_view_places_angles_and_offsets() {
    let text = "G00 X58 Z70\nX47.1\nG32 Z13 F2 Q0\nG00 X58\nZ70\nX47.1\nG32 Z13 F2 Q180000\nG00 X58\nZ70\nM30\n";
    let plan = plan_default(text, Dialect::Gsk980tdc);
    assert_eq!(plan.threads[0].starts, 2);
    let list = starts_of(&plan, 0);
    assert_eq!(list.len(), 2);
    assert_eq!((list[1].number, list[1].angle, list[1].offset), (2, 180.0, 1.0));
    let scene = starts(&plan, 0).unwrap();
    let spokes: Vec<&Item> =
        scene.items.iter().filter(|i| i.style == Style::Start && polyline(i).first() == Some(&[0.0, 0.0])).collect();
    assert_eq!(spokes.len(), 2);
    let end = polyline(spokes[1])[1];
    assert!(end[0].abs() < 1e-12 && close(end[1], -1.0), "180° points down: {end:?}");
    assert_eq!(spokes[1].lines.to_vec(), vec![6, 7, 8, 9]);
    // Start 2's tick sits half way along the one-lead ruler.
    let tick = scene.items.iter().filter(|i| i.style == Style::Start && i.pass == Some(1)).nth(2).unwrap();
    assert!(close(polyline(tick)[0][0], RULER_X + RULER_LEN / 2.0));
    let tx = texts(&scene);
    assert!(tx.contains(&("start_angle", "2: 180°".into())) && tx.contains(&("", "2: 1".into())), "{tx:?}");
    assert!(dims(&scene).contains(&("pitch", "1".into())));
}

#[test]
fn scenes_of_bad_input_are_empty_but_usable() {
    for text in ["", "G32 Z10\n", "G00 X1e999\n", "\u{0}\u{ffff}", "G02 X10 Z10 R1\n"] {
        for d in Dialect::ALL {
            let plan = crate::plan(text, &Settings::new(d));
            let s = side(&plan);
            assert!(!s.bounds.is_empty() && s.bounds.width() > 0.0 && s.bounds.height() > 0.0, "{text:?}");
            assert!(tooth(&plan, 5, 1).is_none() && starts(&plan, 5).is_none());
        }
    }
}

#[test]
fn arcs_are_tessellated_on_their_circle() {
    let text = "G00 X40 Z10\nG01 X40 Z0 F0.2\nG02 X60 Z-10 R10\nM30\n";
    let plan = plan_default(text, Dialect::Gsk980tdc);
    let arc = plan.moves.iter().find(|m| m.kind == MoveKind::Arc).expect("an arc");
    let pts = side::arc_points(arc);
    let c = side::world(arc.arc.unwrap().center);
    assert!(pts.len() > 10);
    for p in &pts {
        let r = ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2)).sqrt();
        assert!((r - 10.0).abs() < 1e-9, "{p:?}");
    }
    assert_eq!(*pts.last().unwrap(), side::world(arc.to));
}

#[test]
fn g78_alternating_example_draws_screw_in_run_out_and_true_areas() {
    let text = include_str!("../../examples/g78-flank-alternating.nc");
    let plan = plan_default(text, Dialect::Gsk980tdc);
    let t = &plan.threads[0];
    assert_eq!((t.passes.len(), t.infeed), (5, Infeed::Alternating));
    let paths = pass_paths(&plan);
    assert_eq!(paths.len(), 5);
    // Pass 1: the rapid from A (35, 5), then screw-in, thread and run-out, then retract and return.
    assert_eq!((paths[0].lead_in.clone(), paths[0].cut.clone(), paths[0].tail.clone()), (0..1, 1..4, 4..6));
    for (k, p) in paths.iter().enumerate().skip(1) {
        assert_eq!(p.lead_in.len(), 1, "pass {k}: one infeed rapid");
        assert_eq!(p.cut.len(), 3, "pass {k}: screw-in, thread, run-out");
    }
    let scene = side(&plan);
    let styles: Vec<Style> = scene.of_pass(0, 0).map(|i| i.style).collect();
    assert_eq!(
        styles,
        vec![
            Style::Rapid,
            Style::ScrewIn,
            Style::Cut,
            Style::Runout,
            Style::Rapid,
            Style::Rapid,
            Style::Runout,
            Style::ScrewIn
        ]
    );
    let screw = scene.of_pass(0, 0).find(|i| i.style == Style::ScrewIn).unwrap();
    let pts = polyline(screw);
    let want = [[4.42265, 15.0], [2.42265, 14.7]];
    assert!(pts.iter().zip(&want).all(|(a, b)| (a[0] - b[0]).abs() < 1e-5 && (a[1] - b[1]).abs() < 1e-9), "{pts:?}");
    // Tooth: each pass's area is what it removes beyond the earlier passes. Passes
    // 1 and 2 sit on opposite flanks and do not overlap: each removes a whole V.
    let tool = tooth::tool_of(t, t.pitch);
    let passes: Vec<(usize, &Pass)> = t.passes.iter().enumerate().collect();
    let (list, _) = cuts(tool, &passes, -4.0, 4.0);
    let tan30 = 30f64.to_radians().tan();
    assert!((list[0].area - tan30 * 0.09).abs() < 1e-5, "{}", list[0].area);
    assert!((list[1].area - tan30 * 0.36).abs() < 1e-5, "{}", list[1].area);
    let total: f64 = list.iter().map(|c| c.area).sum();
    assert!((total - tan30 * 1.69).abs() < 1e-5, "all passes remove the full space: {total}");
    let scene = tooth(&plan, 0, 1).unwrap();
    let arrows = scene.items.iter().filter(|i| matches!(i.shape, Shape::Arrow { .. })).count();
    assert_eq!(arrows, 2, "alternating: one arrow per flank");
}

#[test]
fn face_thread_is_drawn_along_x() {
    let text = "G00 X62 Z5\nZ-0.5\nG32 X20 F2\nG00 Z5\nX62\nZ-1\nG32 X20 F2\nG00 Z5\nX62\nM30\n";
    let plan = plan_default(text, Dialect::Gsk980tdc);
    assert_eq!(plan.threads[0].kind, ThreadKind::Face);
    let scene = side(&plan);
    let cuts: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Cut).collect();
    assert_eq!(polyline(cuts[1]), &[[-1.0, 31.0], [-1.0, 10.0]]);
    // The crest is a face at Z0.3 (assumed), the root at Z-1, both from radius 10 to 31.
    let crest = scene.items.iter().find(|i| i.style == Style::Crest).unwrap();
    assert!(
        polyline(crest).iter().zip([[0.3, 10.0], [0.3, 31.0]]).all(|(p, q)| close(p[0], q[0]) && close(p[1], q[1]))
    );
    let root = scene.items.iter().find(|i| i.style == Style::Root).unwrap();
    assert!(polyline(root).iter().all(|p| close(p[0], -1.0)));
    let d = dims(&scene);
    assert!(d.contains(&("height", "1.3".into())) && d.contains(&("lead", "2".into())), "{d:?}");
    assert!(!d.iter().any(|(k, _)| k.starts_with("dia_")), "no diameters on a face thread: {d:?}");
    assert!(tooth(&plan, 0, 1).is_some());
}

/// The definition of the work's extent: every feed motion tested.
fn work_extent_by_scan(t: &Thread, band: &Band, moves: &[Move]) -> Option<(f64, f64)> {
    if t.crest_source != CrestSource::Outline || band.long != Axis::Z {
        return None;
    }
    let on_crest = |p: Point| {
        let c = band.crest(p.z);
        (p.r() - c).abs() <= 1e-4 + 1e-6 * c.abs()
    };
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for m in moves.iter().filter(|m| m.kind == MoveKind::Feed) {
        let (a, b) = (m.from.z.min(m.to.z), m.from.z.max(m.to.z));
        if b - a > 1e-9 && on_crest(m.from) && on_crest(m.to) && b > band.lo && a < band.hi {
            lo = lo.min(a);
            hi = hi.max(b);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

#[test]
fn indexed_work_extent_equals_the_scan() {
    // Straight threads turned on diameters that repeat, turning moves just
    // inside and just outside the crest tolerance, work away from the cut,
    // and a tapered thread on a turned taper.
    let mut text = String::from("G00 X120 Z100\n");
    for k in 0..24 {
        let d = 40 + 2 * (k as u32 % 6);
        let z0 = 70 + 5 * (k % 4);
        let near = ["", ".00015", ".001", "", ".0001"][k % 5];
        text += &format!(
            "G00 X{} Z{z0}\nG01 X{d}{near} F0.2\nZ{}\nX{d} Z10\nG00 X{}\nZ{}\n",
            d + 4,
            z0 - 50,
            d + 4,
            z0 + 2
        );
        text += &format!("G01 X{d} Z200\nZ150\nG00 X{}\n", d + 4);
        for x in [0.9, 1.5] {
            text +=
                &format!("G00 X{} Z{}\nX{:.1}\nG32 Z{} F2\nG00 X{}\n", d + 4, z0 + 2, f64::from(d) - x, z0 - 45, d + 4);
        }
    }
    text += "G00 X60 Z5\nG01 X30 Z0\nG01 X40 Z-70\nG00 X60\nZ5\nX29.1 Z0\nG32 X39.1 Z-65 F2\nG00 X60\nZ5\nM30\n";
    let plan = plan_default(&text, Dialect::Gsk980tdc);
    let outline = plan.threads.iter().filter(|t| t.crest_source == CrestSource::Outline).count();
    assert!(plan.threads.len() >= 20 && outline >= 10, "{} threads, {outline} on a turned crest", plan.threads.len());
    let index = FeedIndex::new(&plan.moves);
    let mut found = 0;
    for t in &plan.threads {
        let Some(band) = Band::of(t) else { continue };
        let want = work_extent_by_scan(t, &band, &plan.moves);
        assert_eq!(work_extent_in(t, &band, &plan.moves, &index), want, "thread at line {}", t.line);
        assert_eq!(work_extent(t, &band, &plan.moves), want);
        found += usize::from(want.is_some());
    }
    assert!(found >= 10, "{found} threads with work");
}

/// The diameters of a thread along Z are half dimensions from the axis (one
/// arrowhead, at the diameter): style `Diameter`, first end on the axis; the
/// other dimensions keep the `Dimension` style.
#[test]
fn diameters_are_half_dimensions_from_the_axis() {
    let plan = plan_default(O1006, Dialect::Gsk980tdc);
    let scene = side(&plan);
    let dias: Vec<&Item> = scene.items.iter().filter(|i| i.style == Style::Diameter).collect();
    let keys: Vec<&str> = dias
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Dim { a, b, label, .. } => {
                assert!(a[1] == 0.0 && a[0] == b[0] && b[1] > 0.0, "{:?}", i.shape);
                Some(label.key)
            }
            _ => None,
        })
        .collect();
    assert_eq!(keys, ["dia_minor", "dia_major"]);
    let others: Vec<&'static str> = dims(&scene).iter().map(|(k, _)| *k).filter(|k| !k.starts_with("dia_")).collect();
    assert_eq!(others, ["lead", "length"]);
}

#[test]
fn the_focus_grown_by_groups_of_rapids_is_the_focus_grown_point_by_point() {
    use super::scene::Rect;
    use super::side::{grow_focus, grow_focus_grouped};
    let mut next = crate::hash::unit_floats(0x2545_f491_4f6c_dd1d);
    for round in 0..200 {
        let core = Rect { x0: 10.0, y0: 20.0, x1: 60.0, y1: 40.0 };
        // Groups near the focus, far from it and across its edge of reach (12.5 around it).
        let groups: Vec<Vec<[f64; 2]>> = (0..6)
            .map(|g| {
                let (cx, cy, r) = (next() * 120.0 - 30.0, next() * 80.0 - 20.0, 2.0 + 20.0 * f64::from(g % 3));
                (0..1 + round % 5).map(|_| [cx + (next() - 0.5) * r, cy + (next() - 0.5) * r]).collect()
            })
            .collect();
        let (mut a, mut b) = (core, core);
        grow_focus(&mut a, groups.iter().flatten().copied());
        let boxes: Vec<Rect> = groups
            .iter()
            .map(|g| {
                let mut r = Rect::EMPTY;
                g.iter().for_each(|p| r.add(*p));
                r
            })
            .collect();
        grow_focus_grouped(&mut b, boxes.iter().copied().zip(groups.iter().map(Vec::as_slice)));
        assert_eq!(a, b, "round {round}");
    }
}

/// The rapids of a roughing cycle are those of a run of one line's motions
/// that holds a roughing cut; a line read again later is another run.
#[test]
fn roughing_rapids_are_the_rapids_of_a_line_that_roughs() {
    use MoveKind::{Feed, Rapid, Rough};
    let p = Point { x: 0.0, z: 0.0 };
    let mv = |kind, line| Move { kind, from: p, to: p, line, span: Default::default(), arc: None };
    let moves = [(Rapid, 1), (Rough, 1), (Rapid, 1), (Rapid, 2), (Feed, 2), (Rapid, 1), (Rapid, 3), (Rough, 3)]
        .map(|(k, l)| mv(k, l));
    let got = super::side::roughing_rapids(&moves);
    assert_eq!(got, [true, false, true, false, false, false, true, false]);
    assert!(super::side::roughing_rapids(&[]).is_empty());
}
