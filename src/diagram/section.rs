//! The workpiece in the side section: where the program turns a contour
//! (G01/G02/G03 feeds, the contour G70 runs), the part is drawn as a filled
//! half section from the spindle axis up to that outline, as a manual's
//! figure shows it, behind everything else. A run of consecutive feeds that
//! goes one way along Z is one piece of the part; a run that turns back
//! (a back-turned or undercut form) is left unfilled, as is everything when
//! a thread is internal (the stock's outside is not in the program).

use super::scene::{Item, Pt, Scene, Shape, Style};
use crate::motion::{Move, MoveKind, Point, arc_points};
use crate::plan::Plan;

/// Most points the filled section takes (a huge program's outline is not filled past them).
const MAX_POINTS: usize = 100_000;

/// The filled sections of `plan`'s turned outline, as items (no source lines: hovering the part marks nothing).
pub fn pieces(plan: &Plan) -> Vec<Item> {
    if !filled(plan) {
        return Vec::new();
    }
    let mut total = 0usize;
    let mut out = pieces_from(&plan.moves, 0, plan.moves.len());
    out.retain(|i| within_cap(&mut total, i));
    out
}

/// Counts `item`'s points into `total`, the points of the sections before
/// it: whether it is still drawn (once past [`MAX_POINTS`], no later section is).
pub fn within_cap(total: &mut usize, item: &Item) -> bool {
    if let Shape::Polygon { points } = &item.shape {
        *total += points.len();
    }
    *total <= MAX_POINTS
}

/// Whether `plan` has filled sections at all (an internal thread's part is not filled).
pub fn filled(plan: &Plan) -> bool {
    !plan.threads.iter().any(|t| t.internal)
}

/// Whether `m` is a feed or an arc: what the outline is made of.
pub fn is_feed(m: &Move) -> bool {
    matches!(m.kind, MoveKind::Feed | MoveKind::Arc)
}

/// Whether feed `m` goes on from feed `prev` (it starts where `prev` ends): the same run.
fn continues(prev: &Move, m: &Move) -> bool {
    if !(is_feed(prev) && is_feed(m)) {
        return false;
    }
    // A feed's points end at its end point (`arc_points` ends there too).
    let (p, from) = (world(prev.to), world(m.from));
    !((p[0] - from[0]).abs() > 1e-9 || (p[1] - from[1]).abs() > 1e-9)
}

/// The end of the run of feeds going on at `moves[e]`: the first move from
/// `e` on that does not continue the one before it (`e` when none does).
pub fn run_end(moves: &[Move], e: usize) -> usize {
    let mut k = e;
    while k > 0 && k < moves.len() && continues(&moves[k - 1], &moves[k]) {
        k += 1;
    }
    k
}

/// The filled sections (uncapped) of the runs of feeds that begin among
/// `moves[s..e]`, each read to its end (past `e` when it goes on, up to
/// [`run_end`]); a run begun before `s` is left to the sections before.
/// What it reads is `moves[s - 1..run_end(moves, e)]`.
pub fn pieces_from(moves: &[Move], s: usize, e: usize) -> Vec<Item> {
    let mut out = Vec::new();
    let mut chain: Vec<Pt> = Vec::new();
    let close = |chain: &mut Vec<Pt>, out: &mut Vec<Item>| {
        if let Some(poly) = polygon(chain) {
            out.push(Item::new(Shape::Polygon { points: poly.into() }, Style::Material));
        }
        chain.clear();
    };
    let mut k = s;
    while k < e && k > 0 && continues(&moves[k - 1], &moves[k]) {
        k += 1;
    }
    if k >= e {
        return out; // no run begins here
    }
    while k < moves.len() {
        let m = &moves[k];
        if !(k > 0 && continues(&moves[k - 1], m)) {
            close(&mut chain, &mut out);
            if k >= e {
                break;
            }
        }
        if is_feed(m) {
            if chain.is_empty() {
                chain.push(world(m.from));
            }
            extend(&mut chain, m);
        }
        k += 1;
    }
    close(&mut chain, &mut out);
    out
}

/// The drawing's point of a plan point: (Z, radius).
fn world(p: Point) -> Pt {
    [p.z, p.x / 2.0]
}

/// Adds the points of feed `m` after its start.
fn extend(chain: &mut Vec<Pt>, m: &Move) {
    if m.kind == MoveKind::Arc {
        chain.extend(arc_points(m).into_iter().skip(1));
    } else {
        chain.push(world(m.to));
    }
}

/// The half section under `chain` down to the axis, when the chain goes one way along Z and spans some of it.
fn polygon(chain: &[Pt]) -> Option<Vec<Pt>> {
    let (first, last) = (chain.first()?, chain.last()?);
    let dir = (last[0] - first[0]).signum();
    if (last[0] - first[0]).abs() < 1e-6 || chain.iter().any(|p| !p[0].is_finite() || !p[1].is_finite() || p[1] < -1e-9)
    {
        return None;
    }
    if chain.windows(2).any(|w| (w[1][0] - w[0][0]) * dir < -1e-9) {
        return None;
    }
    let mut poly = Vec::with_capacity(chain.len() + 2);
    poly.push([first[0], 0.0]);
    poly.extend_from_slice(chain);
    poly.push([last[0], 0.0]);
    Some(poly)
}

/// Puts the part's filled sections of `plan` behind everything in its side section `scene` (after the axis).
pub fn apply(scene: &mut Scene, plan: &Plan) {
    let items = pieces(plan);
    if items.is_empty() {
        return;
    }
    for it in &items {
        it.each_point(|p| scene.bounds.add(p));
    }
    let at = usize::from(scene.items.first().is_some_and(|i| i.style == Style::Axis));
    scene.items.with_vec(|v| drop(v.splice(at..at, items)));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_way_runs_are_filled_down_to_the_axis() {
        let chain = [[-2.0, 13.0], [0.0, 15.0], [-40.0, 15.0]];
        assert!(polygon(&chain).is_none(), "turns back along Z");
        let chain = [[2.0, 13.0], [-2.0, 15.0], [-40.0, 15.0], [-40.0, 22.0], [-60.0, 22.0]];
        let p = polygon(&chain).expect("a section");
        assert_eq!(p.first(), Some(&[2.0, 0.0]));
        assert_eq!(p.last(), Some(&[-60.0, 0.0]));
        assert_eq!(p.len(), 7);
        assert!(polygon(&[[0.0, 10.0], [0.0, 20.0]]).is_none(), "a face alone has no length");
    }
}
