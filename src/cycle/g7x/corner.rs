//! The corners a profile's moves ask for at their ends, made before the
//! profile is offset (rs274's `fillet_segment`, `chamfer_segment` and
//! `corner_finish` in `interp_g7x.cc`): the pieces either side are offset
//! by the corner's size towards each other (the other way if that opens a
//! gap along the cut), where they meet is the centre of a circle of that
//! radius touching both, and the pieces are cut back to where it touches
//! them. `A` puts an arc about that centre between the two points, `C` a
//! straight line (so C is the chord of a radius-C round, not a leg). A
//! corner after the last move, or on the lead-in, has a piece on one side
//! only and is dropped.

use super::Fail;
use super::cx::C;
use super::seg::{Seg, Shape, join};

/// Makes every corner of `path` (in the walk's frame) that has a piece either side.
pub fn make(path: &mut [Seg]) -> Result<(), Fail> {
    for h in 1..path.len().saturating_sub(1) {
        let Some(d) = path[h].corner else { continue };
        let (prev, next) = (path[h - 1], path[h + 1]);
        let (mut p, mut n, mut d) = (prev, next, d);
        p.offset(d);
        n.offset(d);
        if (p.e - n.s).re > 1e-2 {
            d = -d;
            (p, n) = (prev, next);
            p.offset(d);
            n.offset(d);
        }
        if (p.e - n.s).re > 1e-2 {
            return Err(Fail::Corner { re: prev.e.re, im: prev.e.im });
        }
        join(&mut p, &mut n)?;
        let c: C = (p.e + n.s).over(2.0);
        p.offset(-d);
        n.offset(-d);
        path[h - 1].e = p.e;
        path[h + 1].s = n.s;
        let k = &mut path[h];
        k.s = p.e;
        k.e = n.s;
        k.corner = None;
        if let Shape::Arc { .. } = k.shape {
            k.shape = Shape::Arc { ccw: (k.s - c).im > 0.0 || (k.e - c).im > 0.0, c };
        }
    }
    Ok(())
}
