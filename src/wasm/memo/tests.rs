//! The side section from kept pieces against the whole one.

use super::*;
use crate::diagram::side;
use crate::dialect::Dialect;
use crate::settings::Settings;
use crate::wasm::keys::PlanKeys;

/// `header`, then `threads` O1006-style threads of two passes, each turned
/// first on its own diameter (Ø30 up, `diameters` of them, then again from
/// Ø30): 13 lines each; then M30. (The binding's tests plan it too.)
pub(crate) fn turned_threads(header: &str, threads: usize, diameters: usize) -> String {
    let mut out = String::from(header);
    for k in 0..threads {
        let d = 30 + (k % diameters) as u32;
        out += &format!("G00 X{} Z70\nG01 X{d} F0.2\nZ20\nX{}\nG00 Z70\n", d + 10, d + 5);
        for x in [0.9, 1.5] {
            out += &format!("X{:.1}\nG32 Z13 F2\nG00 X{}\nZ70\n", f64::from(d) - x, d + 10);
        }
    }
    out + "M30\n"
}

/// Threads turned on their own diameters (13 lines each), as an editor
/// would hold them; every seventh repeats the first.
fn program(threads: usize) -> String {
    turned_threads("G50 X100 Z100\n", threads, 7)
}

fn check(memo: &mut SideMemo, text: &str, settings: &Settings) -> (usize, usize) {
    let plan = crate::plan(text, settings);
    let keys = PlanKeys::of(&plan);
    let got = memo.side(&plan, &keys);
    assert_eq!(got, side(&plan), "{text}");
    memo.counts()
}

/// Paths drawn again (the program repeats every seventh thread) share
/// their points, before and after an edit, and draw exactly as unshared.
#[test]
fn repeated_paths_share_their_points_and_draw_as_unshared() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let mut memo = SideMemo::new();
    let base = program(40);
    let edited = base.replacen("X29.1", "X29.15", 1);
    for text in [&base, &edited, &base] {
        let plan = crate::plan(text, &s);
        let got = memo.side(&plan, &PlanKeys::of(&plan));
        let paths: Vec<usize> = got
            .items
            .iter()
            .filter_map(|i| match &i.shape {
                Shape::Polyline { points } | Shape::Polygon { points } => Some(points.as_ptr() as usize),
                _ => None,
            })
            .collect();
        let mut held = paths.clone();
        held.sort_unstable();
        held.dedup();
        assert!(held.len() * 4 < paths.len(), "{} points held by {} paths", held.len(), paths.len());
        let whole = side(&plan);
        for width in [936.0, 390.0] {
            let view = crate::draw::View { width, height: 420.0, ..Default::default() };
            assert_eq!(crate::draw::display(&got, &view), crate::draw::display(&whole, &view));
        }
    }
}

/// The part's filled sections kept by blocks of motions: runs of feeds
/// across the blocks, a feed that does not start where the last ended,
/// arcs, and more points than the section draws (`section::pieces`
/// stops at its cap, within a block): as `side(plan)`, before and after
/// an edit of one feed.
#[test]
fn sections_by_blocks_are_the_whole_outline_up_to_the_cap() {
    use crate::motion::{ArcData, MoveKind, Point};
    let mut plan = crate::plan("G00 X40 Z10\n", &Settings::new(Dialect::Gsk980tdc));
    plan.threads.clear();
    let mut moves = Vec::new();
    let mv = |kind, from: Point, to: Point, arc| Move { kind, from, to, line: 1, span: Default::default(), arc };
    let mut at = Point { x: 40.0, z: 10.0 };
    for r in 0..480usize {
        let x = 20.0 + (r % 5) as f64;
        let start = Point { x, z: 10.0 };
        moves.push(mv(MoveKind::Rapid, at, start, None));
        at = start;
        let n = [3, 300, 700, 1, 256, 40][r % 6];
        for k in 0..n {
            let mut to = Point { x, z: at.z - 0.05 };
            if k == n / 2 && r % 4 == 1 {
                at.z -= 0.01; // the next feed starts elsewhere: another run
            }
            let arc = (k == 1 && r % 3 == 0).then(|| {
                to.x += 2.0;
                ArcData { center: Point { x: at.x + 2.0, z: at.z }, cw: true }
            });
            moves.push(mv(if arc.is_some() { MoveKind::Arc } else { MoveKind::Feed }, at, to, arc));
            at = to;
        }
    }
    plan.moves = moves;
    let (drawn, all) = (section::pieces(&plan).len(), section::pieces_from(&plan.moves, 0, plan.moves.len()).len());
    assert!(drawn > 100 && drawn < all, "{drawn} of {all} sections drawn");
    let mut memo = SideMemo::new();
    let mut edited = plan.clone();
    edited.moves[5000].to.x += 0.5;
    edited.moves[5001].from.x += 0.5;
    for p in [&plan, &edited, &plan] {
        assert_eq!(memo.side(p, &PlanKeys::of(p)), side(p));
    }
}

#[test]
fn reused_pieces_give_the_whole_scene() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let mut memo = SideMemo::new();
    let base = program(40);
    let (built, reused) = check(&mut memo, &base, &s);
    assert_eq!(reused, 0);
    assert!(built > 80, "{built} pieces");
    // The same program again: nothing is built.
    assert_eq!(check(&mut memo, &base, &s), (0, built));
    // One pass of the last thread: its band, dimensions and passes only.
    let lines: Vec<&str> = base.lines().collect();
    let n = lines.len();
    let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    edited[n - 9] = format!("{}1", edited[n - 9]);
    let edited = edited.join("\n") + "\n";
    let (b, r) = check(&mut memo, &edited, &s);
    assert_eq!(b, 3, "band, dimensions and the passes of one thread");
    assert_eq!(b + r, built);
    // Edits of every kind, one after the other on one memo.
    let edits = [
        base.replacen("Z20", "Z21", 1),
        base.replacen("G50 X100 Z100", "G50 X100 Z100 (a comment)", 1),
        base.replacen("X29.1", "X29.1\nG00 X80", 1),
        base[..base.len() / 3].to_string(),
        format!("G00 X90 Z90\n{base}"),
        base.replace("G32 Z13 F2", "G32 Z13 F2.5"),
        // A thread of a larger crest after the others: the radial break moves
        // while their pieces are reused (drawn again through the new break).
        base.replacen("M30\n", "G00 X48 Z70\nG01 X38 F0.2\nZ20\nX43\nG00 Z70\nX37.1\nG32 Z13 F2\nG00 X48\nZ70\nX36.5\nG32 Z13 F2\nG00 X48\nZ70\nM30\n", 1),
        base.clone(),
        String::new(),
        base.clone(),
        include_str!("../../../examples/g78-flank-alternating.nc").to_string(),
        include_str!("../../../examples/g92-two-start.nc").to_string(),
        include_str!("../../../examples/o0009.nc").to_string(),
        include_str!("../../../examples/g32-continuous.nc").to_string(),
    ];
    for text in &edits {
        check(&mut memo, text, &s);
    }
    for text in [include_str!("../../../examples/renhe-tails.nc"), "G33 W-40 F1.5\n"] {
        check(&mut memo, text, &Settings::new(Dialect::Renhe));
    }
    // A plan cut short by the motion limit; and one whose last passes
    // lost their motions, drawn from their own points.
    let mut few = Settings::new(Dialect::Fanuc0i);
    few.assign("limits.moves=12").unwrap();
    let g76 = include_str!("../../../examples/g76-fanuc.nc");
    check(&mut memo, g76, &few);
    let mut plan = crate::plan(g76, &Settings::new(Dialect::Fanuc0i));
    plan.moves.truncate(plan.moves.len() / 2);
    assert!(!Layout::of(&plan).unmatched(&plan).is_empty(), "some passes have no motions");
    let keys = PlanKeys::of(&plan);
    assert_eq!(memo.side(&plan, &keys), side(&plan));
}
