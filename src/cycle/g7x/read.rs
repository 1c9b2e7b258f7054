//! A move of the profile as rs274 reads it for a G70–G72 (`convert_g7x`'s
//! loop over the subroutine in `interp_g7x.cc`): the subroutine's blocks
//! are read, not run; each block in G0, G1, G2 or G3 that goes somewhere
//! adds a piece from where the last one ended: a line, or an arc about the
//! centre its words give — I and K from the start (I a radius, not halved
//! under G7), or R, the centre then on the side G2 or G3 turns to, whatever
//! R's sign (no check that the radius reaches: a chord longer than 2R
//! gives no centre, and the profile is then refused as not monotonic). `A`
//! asks for a fillet at the move's end, `C` for a chamfer.

use super::{Corner, Fail, Step};
use crate::block::Block;
use crate::motion::{ArcData, Point};
use crate::state::Motion;

use super::cx::{C, I};

/// The move of block `b` from `at` in motion mode `motion` (after the
/// block), X a radius when `radius`: `None` when it adds no piece.
pub fn step(b: &Block, motion: Motion, radius: bool, at: Point) -> Result<Option<Step>, Fail> {
    let x = b.get(b'X').map_or(at.x, |w| if radius { 2.0 * w.value() } else { w.value() });
    let z = b.get(b'Z').map_or(at.z, |w| w.value());
    let to = Point::new(x, z);
    if to == at {
        return Ok(None);
    }
    let arc = match motion {
        Motion::None | Motion::Rapid | Motion::Linear => None,
        Motion::ArcCw | Motion::ArcCcw => Some(centre(b, motion == Motion::ArcCcw, at, to)?),
        _ => return Ok(None),
    };
    let corner = match (b.get(b'A'), b.get(b'C')) {
        (Some(_), Some(_)) => return Err(Fail::BothCorners),
        (Some(a), None) => Some(Corner::Fillet(a.value())),
        (None, Some(c)) => Some(Corner::Chamfer(c.value())),
        (None, None) => None,
    };
    Ok(Some(Step { to, arc: arc.map(|(center, ccw)| ArcData { center, cw: !ccw }), corner }))
}

/// The centre of the arc from `at` to `to` that block `b` asks for, and its sense.
fn centre(b: &Block, ccw: bool, at: Point, to: Point) -> Result<(Point, bool), Fail> {
    let (s, e) = (C::new(at.z, at.x / 2.0), C::new(to.z, to.x / 2.0));
    let c = if let Some(r) = b.get(b'R') {
        if b.has(b'I') || b.has(b'K') {
            return Err(Fail::RAndIk);
        }
        let r = r.value();
        let chord = (e - s).norm();
        let d = I.scale(((r * r - chord / 4.0) / chord).sqrt()) * (e - s);
        let mid = (s + e).over(2.0);
        if ccw { mid + d } else { mid - d }
    } else {
        if !(b.has(b'I') || b.has(b'K')) {
            return Err(Fail::NoIk);
        }
        let i = b.get(b'I').map_or(0.0, |w| w.value());
        let k = b.get(b'K').map_or(0.0, |w| w.value());
        C::new(k, i) + s
    };
    Ok((Point::new(2.0 * c.im, c.re), ccw))
}
