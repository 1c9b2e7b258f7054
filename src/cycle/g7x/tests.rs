//! The roughing against what rs274 (LinuxCNC 2.9) printed for small profiles.

use super::*;
use crate::motion::MoveKind;

fn words(code10: i64, d: f64, i: f64, r: f64) -> Words {
    let (along, pockets) = Words::kind(code10).unwrap();
    Words { code10, along, pockets, d, i, r, i_span: Span::default(), inch: false }
}

fn line(x: f64, z: f64) -> Step {
    Step { to: Point::new(x, z), arc: None, corner: None }
}

/// (rapid, radius, z) of each move, rounded as rs274 prints them.
fn ends(r: &Roughing) -> Vec<(bool, f64, f64)> {
    let q = |v: f64| (v * 1e4).round() / 1e4 + 0.0;
    r.moves.iter().map(|m| (m.kind == MoveKind::Rapid, q(m.to.x / 2.0), q(m.to.z))).collect()
}

/// The turned pin of `tests/linuxcnc/oword-g71-*`'s kind: chamfer X12 Z0 →
/// X16 Z-2, Z-20, shoulder to X24, Z-30; start X30 Z3 (G7: diameters).
fn pin() -> Vec<Step> {
    vec![line(12.0, 0.0), line(16.0, -2.0), line(16.0, -20.0), line(24.0, -20.0), line(24.0, -30.0)]
}

#[test]
fn g71_cuts_each_depth_from_the_lead_in_and_follows_the_profile_last() {
    // rs274: G71 Q100 X30 Z3 D0 I1 R0.5.
    let r = plan(&words(710, 0.0, 1.0, 0.5), Point::new(30.0, 3.0), &pin(), 7, Span::default());
    assert_eq!(r.fail, None);
    let e = ends(&r);
    // The first depth is the start's own: cut to the end Z, out 0.5 at 45°, back, down the lead-in.
    assert_eq!(
        e[..8],
        [
            (false, 15.0, -30.0),
            (true, 15.5, -29.5),
            (true, 15.5, 2.5),
            (true, 15.0, 3.0),
            (true, 14.0, 2.6667),
            (false, 14.0, -30.0),
            (true, 14.5, -29.5),
            (true, 14.5, 2.1667)
        ]
    );
    // Depth 12 meets the shoulder; depth 7 the chamfer at Z-1, whose retract is cut short by the lead-in.
    assert!(e.contains(&(false, 12.0, -20.0)) && e.contains(&(false, 7.0, -1.0)));
    // Last, the profile from its first point, then up to the start's depth; the tool stays there.
    let tail: Vec<_> = e[e.len() - 6..].to_vec();
    assert_eq!(
        tail,
        [
            (true, 6.0, 0.0),
            (false, 8.0, -2.0),
            (false, 8.0, -20.0),
            (false, 12.0, -20.0),
            (false, 12.0, -30.0),
            (false, 15.0, -30.0)
        ]
    );
    assert_eq!(r.moves.len(), 50, "rs274 makes 50 moves after the first rapid");
    // D0: the profile pass is the part's outline; the depth cuts are roughing.
    let last = &r.moves[r.moves.len() - 5..];
    assert!(last.iter().all(|m| m.kind == MoveKind::Feed));
    assert_eq!(r.moves[0].kind, MoveKind::Rough);
    assert!(r.moves.iter().all(|m| m.line == 7));
}

#[test]
fn d_offsets_the_profile_with_arcs_at_outside_corners() {
    // rs274: G71 Q100 X30 Z3 D1 I0.5 R0.5: the chamfer offset by 1 starts at
    // X6.7071 Z0.7071, the corner at Z-2 is an arc about X8 Z-2 (G3), the
    // shoulder comes 1 nearer, its corner an arc about X12 Z-20.
    let r = plan(&words(710, 1.0, 0.5, 0.5), Point::new(30.0, 3.0), &pin(), 7, Span::default());
    let arcs: Vec<(f64, f64, f64, f64, bool)> = r
        .moves
        .iter()
        .filter_map(|m| m.arc.map(|a| (m.to.x / 2.0, m.to.z, a.center.x / 2.0, a.center.z, a.cw)))
        .collect();
    assert_eq!(arcs, [(9.0, -2.0, 8.0, -2.0, false), (13.0, -20.0, 12.0, -20.0, false)]);
    let e = ends(&r);
    assert!(e.contains(&(false, 12.5, -19.134)), "a depth meets the offset corner's arc");
    assert!(e.contains(&(true, 7.1869, 0.6012)), "a retract cut short by the lead-in");
    // The offset profile starts 1 out from X12 Z0 square to the chamfer: as far out as along.
    let first = e[e.len() - 8];
    assert_eq!((first.0, first.1), (true, 6.7071));
    assert_eq!(((first.1 - 6.0) * 1e4).round(), (first.2 * 1e4).round());
    assert_eq!(e.last(), Some(&(false, 15.0, -30.0)));
    // D1: every feed is roughing, the arcs too.
    assert!(r.moves.iter().all(|m| m.kind != MoveKind::Feed && m.kind != MoveKind::Arc));
}

#[test]
fn a_pocket_is_roughed_down_its_wall_depth_by_depth() {
    // rs274: a groove from Z-10 to Z-20 down to X12, G71 D0 I1 R0.5.
    let mut steps = pin()[..2].to_vec();
    steps.extend([line(16.0, -10.0), line(12.0, -14.0), line(12.0, -18.0), line(16.0, -20.0), line(16.0, -24.0)]);
    steps.extend([line(24.0, -24.0), line(24.0, -30.0)]);
    let r = plan(&words(710, 0.0, 1.0, 0.5), Point::new(30.0, 3.0), &steps, 7, Span::default());
    let e = ends(&r);
    let k = e.iter().position(|m| *m == (false, 8.0, -10.0)).unwrap();
    assert_eq!(
        e[k..k + 11],
        [
            (false, 8.0, -10.0),
            (false, 8.0, -20.0),
            (true, 8.5, -19.5),
            (true, 8.5, -10.5),
            (false, 8.0, -10.0),
            (false, 7.0, -12.0),
            (false, 7.0, -19.0),
            (true, 7.5, -18.5),
            (true, 7.5, -12.5),
            (false, 7.0, -12.0),
            (false, 6.0, -14.0)
        ]
    );
    // G71.1 rough over the pocket: the profile pass crosses it at depth 8.
    let r = plan(&words(711, 0.0, 1.0, 0.5), Point::new(30.0, 3.0), &steps, 7, Span::default());
    assert!(!ends(&r).contains(&(false, 7.0, -12.0)));
    // G71.2 roughs only the pocket: down the profile first, no depth cut before it.
    let r = plan(&words(712, 0.0, 1.0, 0.5), Point::new(30.0, 3.0), &steps, 7, Span::default());
    assert_eq!(ends(&r)[..3], [(true, 6.0, 0.0), (false, 8.0, -2.0), (false, 8.0, -10.0)]);
}

#[test]
fn g72_faces_along_x_at_depths_along_z() {
    // rs274: G72 Q100 X40 Z2 D0 I1 R0.5 over X36 Z-6, X24, Z-3, X14 Z-1, X0.
    let steps = [line(36.0, -6.0), line(24.0, -6.0), line(24.0, -3.0), line(14.0, -1.0), line(0.0, -1.0)];
    let r = plan(&words(720, 0.0, 1.0, 0.5), Point::new(40.0, 2.0), &steps, 7, Span::default());
    let e = ends(&r);
    assert_eq!(e[..5], [(false, 0.0, 2.0), (true, 0.5, 2.5), (true, 19.5, 2.5), (true, 20.0, 2.0), (true, 19.75, 1.0)]);
    assert!(e.contains(&(false, 7.0, -1.0)) && e.contains(&(false, 12.0, -6.0)));
    assert_eq!(e.last(), Some(&(false, 0.0, 2.0)), "the profile closed up to the start's Z");
}

#[test]
fn what_rs274_refuses() {
    let at = Point::new(30.0, 3.0);
    let r = plan(&words(710, 0.0, 0.0, 0.5), at, &pin(), 7, Span::default());
    assert_eq!((r.fail, r.moves.len()), (Some(Fail::IZero), 0));
    // Back along Z.
    let back = [line(12.0, 0.0), line(16.0, -20.0), line(20.0, -15.0), line(24.0, -30.0)];
    let r = plan(&words(710, 0.0, 1.0, 0.5), at, &back, 7, Span::default());
    assert_eq!(r.fail, Some(Fail::NotMonotone));
    // A profile of one move is only a lead-in: nothing is cut, and I is not looked at.
    let r = plan(&words(710, 0.0, 0.0, 0.5), at, &[line(12.0, 0.0)], 7, Span::default());
    assert_eq!(r, Roughing::default());
}

#[test]
fn the_cuts_are_bounded() {
    // I of 1e-9 is read as 2e-6: 7.5 million depths, stopped after MAX_CUTS steps.
    let r = plan(&words(710, 0.0, 1e-9, 0.5), Point::new(30.0, 3.0), &pin(), 7, Span::default());
    assert_eq!(r.fail, Some(Fail::TooMany { limit: MAX_CUTS }));
    assert!(r.moves.len() <= 5 * MAX_CUTS, "{}", r.moves.len());
}

#[test]
fn a_cut_that_never_ends_in_rs274_stops_the_plan() {
    // rs274 (2.9.0~pre1) prints these moves, then loops for ever on the
    // depth X10: the offset profile's first arc climbs back to it, and no
    // piece after it crosses it (G71.1 Q X24 Z2 D1 I0.7 R0.5, G7).
    let arc = |x: f64, z: f64, cx: f64, cz: f64| Step {
        to: Point::new(x, z),
        arc: Some(ArcData { center: Point::new(cx, cz), cw: true }),
        corner: None,
    };
    let steps = [line(8.0, 0.0), arc(12.0, -2.0, 12.0, 0.0), line(12.0, -4.0), arc(18.0, -7.0, 18.0, -4.0)];
    let steps = [&steps[..], &[line(20.0, -9.0), line(20.0, -13.0)]].concat();
    let r = plan(&words(711, 1.0, 0.7, 0.5), Point::new(24.0, 2.0), &steps, 7, Span::default());
    let Some(Fail::Endless { x, z }) = r.fail else { panic!("{:?}", r.fail) };
    assert!((x - 10.0).abs() < 1e-6 && z.abs() < 1e-6, "X{x} Z{z}");
    // The moves rs274 printed before it looped, the last the rapid to the offset profile's start.
    assert_eq!(ends(&r).len(), 50);
    assert_eq!(ends(&r).last(), Some(&(true, 5.0, 0.0)));
}

#[test]
fn an_arc_rs274_would_not_make_stops_the_plan() {
    // G72.1 Q X44 Z1 D1 I0.5 R0.5 over X40 Z-4, X38 Z-4.5, G3 X36 Z-5.5 R1,
    // X33 Z-7, X29 Z-7 (G7): following the profile across a pocket, the
    // tool reaches the offset arc away from its start; rs274 refuses it
    // with this message after two moves that go somewhere.
    let g3 = |x: f64, z: f64, cx: f64, cz: f64| Step {
        to: Point::new(x, z),
        arc: Some(ArcData { center: Point::new(cx, cz), cw: false }),
        corner: None,
    };
    let steps = [line(40.0, -4.0), line(38.0, -4.5), g3(36.0, -5.5, 36.0, -4.5), line(33.0, -7.0), line(29.0, -7.0)];
    let r = plan(&words(721, 1.0, 0.5, 0.5), Point::new(44.0, 1.0), &steps, 7, Span::default());
    let Some(Fail::Arc { zero: false, from, c, to }) = r.fail else { panic!("{:?}", r.fail) };
    assert_eq!(
        emit::arc_message(false, from, c, to),
        "Radius to end of arc differs from radius to start: start=(Z-4.2056,X17.3528) center=(Z-5.5000,X18.0000) \
         end=(Z-4.7929,X17.2929) r1=1.4472 r2=1.0000 abs_err=0.4472 rel_err=30.9017%"
    );
    assert_eq!(ends(&r), [(false, 19.5528, -3.1056), (false, 17.3528, -4.2056)]);
}

#[test]
fn g70_runs_p_passes_from_d_to_e() {
    // rs274: G70 Q X28 Z2 D1 E0.2 P2.5 runs two passes, at (2 − 1)·0.8/2.5 + 0.2 = 0.52 and at 0.2.
    let w = finish::Passes { d: 1.0, e: 0.2, p: 2.5, inch: false };
    let r = finish::plan(&w, Point::new(28.0, 2.0), &pin(), 7, Span::default());
    assert_eq!(r.fail, None);
    let starts: Vec<_> = ends(&r).into_iter().filter(|m| m.0).collect();
    // Each pass: a rapid to the start (the first is there already), a rapid to the offset chamfer's start.
    let first = |d: f64| (true, 6.0 + d * std::f64::consts::FRAC_1_SQRT_2, d * std::f64::consts::FRAC_1_SQRT_2);
    let q = |(k, x, z): (bool, f64, f64)| (k, (x * 1e4).round() / 1e4, (z * 1e4).round() / 1e4);
    assert_eq!(starts, [q(first(0.52)), (true, 14.0, 2.0), q(first(0.2))]);
    // Thousands of passes: the first thousand rs274 runs, the farthest from the profile, and an alarm.
    let many = finish::Passes { d: 1.0, e: 0.0, p: 5000.0, inch: false };
    let r = finish::plan(&many, Point::new(28.0, 2.0), &pin(), 7, Span::default());
    assert_eq!(r.fail, Some(Fail::TooMany { limit: 1000 }));
    assert_eq!(r.moves.iter().filter(|m| m.kind == MoveKind::Feed).count(), 0, "none on the profile itself");
}
