//! The profile offset by the finishing distance D, as rs274 offsets it
//! (`g7x::add_distance` in `interp_g7x.cc`): the lead-in from the start
//! point is set aside; the pieces move in steps of at most half the
//! smallest piece (so none turns over), an arc closing each gap an outside
//! corner opens and each pair of pieces meeting again where they cross;
//! pieces that shrink below 0.001 go. The lead-in then ends where the
//! offset profile starts.

use super::Fail;
use super::cx::{self, C};
use super::seg::{Seg, join};

/// Most offset steps (a profile of tiny pieces offset far); rs274 would
/// take more, or never stop when its steps stop adding up to D.
const MAX_STEPS: usize = 10_000;

/// Offsets `path` (lead-in first) by `distance` away from the material:
/// to the side of the start point that the lead-in turns from.
pub fn add_distance(path: &mut Vec<Seg>, distance: f64) -> Result<(), Fail> {
    if path.len() < 2 {
        return Ok(());
    }
    let v1 = path[0].e - path[0].s;
    let v2 = path[path.len() - 1].s - path[0].s;
    let distance = if (v1 / v2).im < 0.0 { -distance } else { distance };
    let mut lead = path.remove(0);
    let mut done = 0.0;
    let mut steps = 0;
    while done != distance {
        steps += 1;
        if steps > MAX_STEPS || path.is_empty() || !distance.is_finite() {
            return Err(Fail::Offset);
        }
        let mut step = path.iter().fold(1e9, |m, s| cx::min(m, s.size() / 2.0));
        step = cx::min(step, (distance - done).abs());
        if distance < 0.0 {
            step = -step;
        }
        path.iter_mut().for_each(|s| s.offset(step));
        path.retain(|s| !s.tiny());
        bridge(path, step, distance > 0.0);
        rejoin(path)?;
        done += step;
    }
    for k in 1..path.len() {
        let mid = (path[k - 1].e + path[k].s).over(2.0);
        path[k - 1].e = mid;
        path[k].s = mid;
    }
    let first = path.first().ok_or(Fail::Offset)?;
    lead.e = first.s;
    path.insert(0, lead);
    Ok(())
}

/// Closes with an arc each gap along the cut between one piece's end and
/// the next one's start (an outside corner offset by `step`), about the
/// corner; `ccw` the arcs' sense.
fn bridge(path: &mut Vec<Seg>, step: f64, ccw: bool) {
    let mut k = 0;
    while k + 1 < path.len() {
        let (p, n) = (path[k], path[k + 1]);
        if (p.e - n.s).re > 1e-2 {
            let (mut a, mut b) = (p, n);
            a.offset(-step);
            b.offset(-step);
            let c: C = (a.e + b.s).over(2.0);
            path.insert(k + 1, Seg::arc(ccw, p.e, c, n.s));
            k += 1;
        }
        k += 1;
    }
}

/// Makes each piece end where the next starts; a piece that turned back
/// along the cut, or shrank to nothing, goes (the smaller of it and the one
/// before), and the pass starts over from the first piece.
fn rejoin(path: &mut Vec<Seg>) -> Result<(), Fail> {
    let mut k = 0;
    let mut rounds = 0;
    while k + 1 < path.len() {
        rounds += 1;
        if rounds > MAX_STEPS {
            return Err(Fail::Offset);
        }
        if !path[k].monotone() {
            // rs274 prints "Oops" here; the first piece has none before it.
            let gone = if k > 0 && path[k].size() >= path[k - 1].size() { k - 1 } else { k };
            path.remove(gone);
            k = 0;
            if path.len() < 2 {
                break;
            }
        }
        if path[k].tiny() {
            path.remove(k);
            k = 0;
        } else {
            let (head, tail) = path.split_at_mut(k + 1);
            join(&mut head[k], &mut tail[0])?;
        }
        k += 1;
    }
    Ok(())
}
