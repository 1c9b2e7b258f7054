//! Level of detail: which passes a drawing shows one by one. A thread of
//! hundreds of passes, or of many starts on the same path, would draw as
//! one solid block; the drawings then show one start and a thinned set of
//! passes (the first, every k-th roughing pass, the last roughing pass and
//! the finishing passes) and say so, while the pass table keeps every
//! number.

use crate::thread::{Pass, Role, Thread};

/// Most passes of one start drawn one by one; beyond it they are thinned.
pub const MAX_PASSES: usize = 40;

/// The passes of a thread a drawing shows.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Detail {
    /// Per pass of the thread: drawn or not.
    pub drawn: Vec<bool>,
    /// The starts drawn as one (they cut the same path): 1 when every start is drawn.
    pub merged_starts: u32,
    /// Passes per start before thinning (of the start drawn).
    pub per_start: usize,
    /// Every how many roughing passes one is drawn (1: all).
    pub every: usize,
}

impl Detail {
    /// Whether anything is left out.
    pub fn summarised(&self) -> bool {
        self.merged_starts > 1 || self.every > 1
    }
}

/// Whether two passes follow the same path (screw-in, cut, segments, run-out).
fn same_path(a: &Pass, b: &Pass) -> bool {
    let near = |p: crate::motion::Point, q: crate::motion::Point| (p.x - q.x).abs() < 1e-9 && (p.z - q.z).abs() < 1e-9;
    near(a.from, b.from)
        && near(a.to, b.to)
        && a.segments.len() == b.segments.len()
        && a.segments.iter().zip(&b.segments).all(|(p, q)| near(*p, *q))
        && match (a.runout_to, b.runout_to) {
            (Some(p), Some(q)) => near(p, q),
            (None, None) => true,
            _ => false,
        }
}

/// The indices of the passes of start `start` to draw among `idx` (in cutting
/// order), at most about [`MAX_PASSES`]: the first, every k-th roughing pass,
/// the last roughing pass, the first and last finishing passes; and k.
pub fn thin(passes: &[Pass], idx: &[usize]) -> (Vec<usize>, usize) {
    if idx.len() <= MAX_PASSES {
        return (idx.to_vec(), 1);
    }
    let rough: Vec<usize> = idx.iter().copied().filter(|&i| passes[i].role == Role::Rough).collect();
    let finish: Vec<usize> = idx.iter().copied().filter(|&i| passes[i].role != Role::Rough).collect();
    let every = rough.len().div_ceil(MAX_PASSES - 4).max(1);
    let mut keep: Vec<usize> = rough.iter().copied().step_by(every).collect();
    keep.extend(rough.last());
    keep.extend(finish.first());
    keep.extend(finish.last());
    crate::order::sort(&mut keep);
    keep.dedup();
    (keep, every)
}

/// What the side section shows of thread `t`.
pub fn side_detail(t: &Thread) -> Detail {
    let n = t.passes.len();
    if n <= MAX_PASSES {
        // Nothing to thin or merge (what the steps below give, without their lists).
        return Detail { drawn: vec![true; n], merged_starts: 1, per_start: n, every: 1 };
    }
    let start1: Vec<usize> = (0..n).filter(|&i| t.passes[i].start == 1).collect();
    // Starts that repeat start 1's path pass for pass are drawn once when
    // drawing them all would be more than a drawing can show.
    let merged = t.starts > 1 && n > MAX_PASSES && {
        let others: Vec<usize> = (0..n).filter(|&i| t.passes[i].start != 1).collect();
        others.iter().all(|&i| {
            let p = &t.passes[i];
            start1.iter().find(|&&j| t.passes[j].index == p.index).is_some_and(|&j| same_path(&t.passes[j], p))
        })
    };
    let candidates: Vec<usize> = if merged { start1 } else { (0..n).collect() };
    let (keep, every) = if merged || t.starts <= 1 { thin(&t.passes, &candidates) } else { (candidates.clone(), 1) };
    let mut drawn = vec![false; n];
    for i in keep {
        drawn[i] = true;
    }
    Detail { drawn, merged_starts: if merged { t.starts } else { 1 }, per_start: candidates.len(), every }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Dialect, plan::plan_default};

    /// The L99 stress program: 99 starts of 675 passes on the same path.
    #[test]
    fn ninety_nine_starts_of_many_passes_are_summarised() {
        let plan =
            plan_default("G00 X100 Z5\nG78 P1060 Q10 R0.01 L99\nG78 X40 Z-30 P9000 Q300 F2\n", Dialect::Gsk980tdc);
        let t = &plan.threads[0];
        assert_eq!(t.starts, 99);
        let d = side_detail(t);
        assert_eq!(d.merged_starts, 99);
        assert_eq!(d.per_start, t.passes.len() / 99);
        let drawn: Vec<&Pass> = t.passes.iter().zip(&d.drawn).filter(|(_, d)| **d).map(|(p, _)| p).collect();
        assert!(drawn.len() <= MAX_PASSES && drawn.len() > MAX_PASSES / 2, "{} drawn", drawn.len());
        assert!(drawn.iter().all(|p| p.start == 1));
        // The first pass, the last roughing pass and the finishing pass are always drawn.
        assert_eq!(drawn[0].index, 1);
        assert!(drawn.iter().any(|p| p.role == Role::Finish));
        let last_rough = t.passes.iter().rfind(|p| p.start == 1 && p.role == Role::Rough).unwrap();
        assert!(drawn.iter().any(|p| p.index == last_rough.index));
        assert!(d.every > 1);
    }

    /// A few passes of two starts on one path are all drawn (each start's
    /// passes overlap exactly; nothing is hidden).
    #[test]
    fn a_few_starts_are_drawn_whole() {
        let plan = plan_default("G00 X30 Z5\nG92 X23.2 Z-30 F3 L2\nX22.6\nX22.2\nX22.05\n", Dialect::Gsk980tdc);
        let d = side_detail(&plan.threads[0]);
        assert_eq!((plan.threads[0].passes.len(), d.summarised()), (8, false));
    }

    /// O1006: five passes of one start are all drawn.
    #[test]
    fn a_small_thread_is_drawn_whole() {
        let plan = plan_default(include_str!("../../examples/o1006.nc"), Dialect::Gsk980tdc);
        let d = side_detail(&plan.threads[0]);
        assert!(!d.summarised() && d.drawn.iter().all(|d| *d));
    }
}
