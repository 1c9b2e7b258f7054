//! Two plans compared pass by pass (`screwcut compare`): the threads in
//! order, each thread's lead and starts, and each pass's start, its
//! synchronised path (screw-in, cut and run-out points: X and Z), its depth
//! below the crest and its time. The infeed side is in the path: a flank
//! infeed moves each pass along Z (a cycle's passes and the same passes
//! written block by block have the same path); a start angle is read as the
//! axial start it equals (lead·θ/360° back). Two
//! programs cut the same passes when nothing differs beyond the tolerance
//! (0.001 in program units, 1% of a pass's time). A pure function of two plans.

use serde::Serialize;

use crate::motion::Point;
use crate::plan::Plan;
use crate::thread::{Axis, Pass, Thread};

/// Lengths closer than this are the same.
pub const TOL: f64 = 0.001;
/// Times closer than this share of the longer are the same.
pub const TIME_SHARE: f64 = 0.01;

/// One difference: where, what, and the two values (absent: the other has none).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Difference {
    /// 1-based thread.
    pub thread: usize,
    /// 1-based pass in the thread (none: the thread itself).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pass: Option<usize>,
    /// The pass's start (multi-start threads).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub start: Option<u32>,
    /// What differs: `threads`, `passes`, `lead`, `starts`, `start`, `points`, `x`, `z` (of the first point of the path that differs), `depth`, `time`.
    pub what: &'static str,
    /// The first plan's value.
    pub a: Option<f64>,
    /// The second plan's value.
    pub b: Option<f64>,
}

/// What differs between two plans; none: they cut the same passes.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Comparison {
    /// Threads and passes of each plan.
    pub threads: [usize; 2],
    /// Passes of each plan.
    pub passes: [usize; 2],
    /// The differences, thread by thread, pass by pass.
    pub differences: Vec<Difference>,
}

impl Comparison {
    /// Whether the two plans cut the same passes.
    pub fn same(&self) -> bool {
        self.differences.is_empty()
    }
}

/// Compares plan `a` with plan `b` pass by pass.
pub fn compare(a: &Plan, b: &Plan) -> Comparison {
    let count = |p: &Plan| p.threads.iter().map(|t| t.passes.len()).sum();
    let mut c = Comparison {
        threads: [a.threads.len(), b.threads.len()],
        passes: [count(a), count(b)],
        differences: Vec::new(),
    };
    if a.threads.len() != b.threads.len() {
        c.differences.push(diff(0, None, None, "threads", Some(a.threads.len() as f64), Some(b.threads.len() as f64)));
    }
    for (k, (ta, tb)) in a.threads.iter().zip(&b.threads).enumerate() {
        thread(k + 1, (a, ta), (b, tb), &mut c.differences);
    }
    c
}

fn diff(
    thread: usize,
    pass: Option<usize>,
    start: Option<u32>,
    what: &'static str,
    a: Option<f64>,
    b: Option<f64>,
) -> Difference {
    Difference { thread, pass, start, what, a, b }
}

fn thread(k: usize, (pa, a): (&Plan, &Thread), (pb, b): (&Plan, &Thread), out: &mut Vec<Difference>) {
    let mut num = |what, x: f64, y: f64| {
        if (x - y).abs() > TOL {
            out.push(diff(k, None, None, what, Some(x), Some(y)));
        }
    };
    num("lead", a.lead, b.lead);
    num("starts", f64::from(a.starts), f64::from(b.starts));
    if a.passes.len() != b.passes.len() {
        out.push(diff(k, None, None, "passes", Some(a.passes.len() as f64), Some(b.passes.len() as f64)));
    }
    let time = |t: &Thread, i: usize| t.shop.pass_time_s.get(i).copied();
    for (i, (x, y)) in a.passes.iter().zip(&b.passes).enumerate() {
        pass(k, i + 1, (pa, a, x), (pb, b, y), out);
        if let (Some(x), Some(y)) = (time(a, i), time(b, i)) {
            if (x - y).abs() > TIME_SHARE * x.abs().max(y.abs()) {
                out.push(diff(k, Some(i + 1), Some(a.passes[i].start), "time", Some(x), Some(y)));
            }
        }
    }
}

/// The synchronised path of a pass: where its first synchronised motion
/// starts and where each ends (screw-in, cut, run-out), from its motions,
/// else from its own points. A start angle θ is read as the start it
/// equals at angle 0: lead·θ/360° further back along the first motion (the
/// same helix; how a program for a controller without the word cuts that
/// start, `expand`).
fn path(plan: &Plan, t: &Thread, p: &Pass) -> Vec<Point> {
    let cut = plan.moves.get(p.moves.cut.clone()).unwrap_or(&[]);
    let mut path: Vec<Point> = if cut.is_empty() {
        p.screw_in_from.into_iter().chain([p.from, p.to]).chain(p.runout_to).collect()
    } else {
        cut.first().map(|m| m.from).into_iter().chain(cut.iter().map(|m| m.to)).collect()
    };
    if path.len() > 1
        && let Some(back) = crate::helix::start_back(path[0], path[1], p.angle, t.lead, t.long_axis)
    {
        path[0] = Point::from_zr(path[0].zr() + back);
    }
    path
}

/// How deep a pass cuts below its thread's crest (radius), from its path: the
/// same whichever program wrote the pass (a cycle's screw-in or a G32 block).
fn depth(t: &Thread, path: &[Point]) -> Option<f64> {
    if t.long_axis != Axis::Z || path.is_empty() {
        return None;
    }
    let xs = path.iter().map(|p| p.x);
    let deepest = if t.internal { xs.fold(f64::MIN, f64::max) } else { xs.fold(f64::MAX, f64::min) };
    Some(((deepest - t.crest) / 2.0).abs())
}

fn pass(
    k: usize,
    i: usize,
    (pa, ta, a): (&Plan, &Thread, &Pass),
    (pb, tb, b): (&Plan, &Thread, &Pass),
    out: &mut Vec<Difference>,
) {
    let mut num = |what, x: Option<f64>, y: Option<f64>| {
        let differs = match (x, y) {
            (Some(x), Some(y)) => (x - y).abs() > TOL,
            (None, None) => false,
            _ => true,
        };
        if differs {
            out.push(diff(k, Some(i), Some(a.start), what, x, y));
        }
    };
    num("start", Some(f64::from(a.start)), Some(f64::from(b.start)));
    let (qa, qb) = (path(pa, ta, a), path(pb, tb, b));
    if qa.len() != qb.len() {
        num("points", Some(qa.len() as f64), Some(qb.len() as f64));
    }
    // The first point that differs, if any: its X and its Z.
    if let Some((x, y)) = qa.iter().zip(&qb).find(|(x, y)| (x.x - y.x).abs() > TOL || (x.z - y.z).abs() > TOL) {
        num("x", Some(x.x), Some(y.x));
        num("z", Some(x.z), Some(y.z));
    }
    num("depth", depth(ta, &qa), depth(tb, &qb));
}
