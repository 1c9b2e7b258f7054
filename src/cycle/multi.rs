//! The plan of a multi-pass cycle (G76, G78): every pass of every start.

use super::{Geometry, PassPath, infeed, schedule};
use crate::args;
use crate::diagnostic::Finding;
use crate::message::{self as msg, Arg, Message};
use crate::num::EPS;
use crate::settings::{P, Settings};
use crate::span::Span;
use crate::thread::{Axis, CrestSource, Infeed, Pass, PassMoves, Source, Spindle, Thread};

/// A multi-pass cycle (G76, G78) as its blocks gave it, ready to plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Multi {
    /// Which cycle.
    pub source: Source,
    /// Lines of its blocks.
    pub lines: Vec<u32>,
    /// Span of the second block's G word.
    pub span: Span,
    /// Geometry.
    pub geom: Geometry,
    /// Lead.
    pub lead: f64,
    /// Starts (L).
    pub starts: u32,
    /// Depth schedule inputs.
    pub schedule: schedule::Spec,
    /// Infeed mode.
    pub infeed: Infeed,
    /// Tool angle a.
    pub angle: f64,
    /// Z direction of the "left" flank (−1: the −Z side).
    pub left_side: f64,
    /// Where single-flank passes are anchored.
    pub anchor: Anchor,
    /// The spindle when the cycle was read.
    pub spindle: Spindle,
}

/// Where the passes of a single-flank infeed sit along Z.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Anchor {
    /// Depth 0 at the start point's Z: each pass starts depth·tan(a/2)
    /// further along its flank (G76, GSK980TDc §3.21.7; G78 by default).
    #[default]
    Start,
    /// The finished thread at the start point's Z: each pass (k −
    /// depth)·tan(a/2) off it (alternating infeed always).
    Thread,
}

/// The planned passes of a cycle: the depth schedule of one start with the
/// axial shifts and chip area of each pass (every start has the same).
#[derive(Clone, Debug, PartialEq)]
pub struct MultiPlan<'a> {
    m: &'a Multi,
    sched: schedule::Schedule,
    /// Depth and shift from the finished thread's middle, per pass.
    shifts: Vec<(f64, f64)>,
    /// Where each pass's line is along Z, from the start point.
    lines: Vec<f64>,
    areas: Vec<Option<f64>>,
}

/// Plans the cycle `m`: an alarm when its schedule needs more passes than
/// `limits.passes_per_start`, it has more starts than `limits.starts`, or
/// its run-out and screw-in do not fit; otherwise the plan and its warnings.
pub fn plan<'a>(m: &'a Multi, s: &Settings) -> Result<(MultiPlan<'a>, Vec<Finding>), Finding> {
    let limit = s.int(P::LimitPasses).max(1) as usize;
    let sched = schedule::plan(&m.schedule, limit).map_err(|needed| {
        let sp = &m.schedule;
        let needed = if needed == u64::MAX { Arg::Phrase(&msg::TOO_MANY) } else { Arg::from(needed) };
        let a = args![needed, k = sp.k, dd = sp.first, dmin = sp.min, d = sp.allowance, limit];
        Message::new(&msg::PASS_LIMIT, a)
    })?;
    let max_starts = s.int(P::LimitStarts).max(1) as u32;
    if m.starts > max_starts {
        return Err(Message::new(&msg::CYCLE_TOO_MANY_STARTS, args![n = m.starts, limit = max_starts]));
    }
    let k = m.schedule.k;
    let shifts: Vec<(f64, f64)> = sched
        .iter()
        .enumerate()
        .map(|(n, &(h, _))| (h, infeed::shift(m.infeed, n as u32 + 1, h, k, m.angle, m.left_side)))
        .collect();
    let lines: Vec<f64> = shifts
        .iter()
        .enumerate()
        .map(|(n, &(_, shift))| match (m.anchor, m.infeed) {
            (Anchor::Start, Infeed::Left | Infeed::Right) => {
                shift - infeed::shift(m.infeed, n as u32 + 1, 0.0, k, m.angle, m.left_side)
            }
            _ => shift,
        })
        .collect();
    let along = lines.iter().map(|l| l * m.geom.sense()).fold(0.0, f64::max);
    m.geom.check_ends(along)?;
    let mut warnings = Vec::new();
    let crest_r = m.geom.root_start.r() + m.geom.out * m.schedule.k;
    if (m.geom.a.r() - crest_r) * m.geom.out < -EPS {
        warnings.push(Message::new(&msg::START_INSIDE_THREAD, args![x = m.geom.a.x, crest = 2.0 * crest_r]));
    }
    let areas = crate::chip::pass_areas(m.angle, &shifts);
    Ok((MultiPlan { m, sched, shifts, lines, areas }, warnings))
}

impl MultiPlan<'_> {
    /// Passes per start.
    pub fn per_start(&self) -> usize {
        self.sched.len()
    }

    /// Pass `n` (0-based) of start `s` (0-based), and its motions.
    pub fn pass(&self, s: u32, n: usize) -> (Pass, PassPath) {
        let m = self.m;
        let (h, role) = self.sched[n];
        let prev = if n == 0 { 0.0 } else { self.sched[n - 1].0 };
        let shift = self.shifts[n].1;
        let pts = m.geom.pass(h, m.schedule.k, self.lines[n]);
        let line = *m.lines.last().unwrap_or(&0);
        let path = m.geom.path(&pts, line, m.span);
        let pass = Pass {
            start: s + 1,
            index: n as u32 + 1,
            from: pts.from,
            to: pts.to,
            depth: h,
            infeed: h - prev,
            role,
            lines: m.lines.clone(),
            via: Vec::new(),
            segments: Vec::new(),
            runout_to: pts.runout_to,
            screw_in_from: pts.screw_in_from,
            shift,
            angle: 360.0 * s as f64 / m.starts as f64,
            area: self.areas[n],
            moves: PassMoves::default(),
            spindle: m.spindle,
        };
        (pass, path)
    }

    /// The thread of the planned `passes`, whose first motion is `first_move`.
    pub fn thread(&self, passes: Vec<Pass>, first_move: usize) -> Thread {
        let m = self.m;
        let g = &m.geom;
        let k = m.schedule.k;
        Thread {
            line: m.lines[0],
            end_line: *m.lines.last().unwrap_or(&0),
            source: m.source,
            units: Default::default(),
            kind: g.kind,
            long_axis: Axis::Z,
            lead: m.lead,
            pitch: m.lead / m.starts as f64,
            starts: m.starts,
            internal: g.out < 0.0,
            infeed: m.infeed,
            tool_angle: m.angle,
            crest: 2.0 * (g.root_start.r() + g.out * k),
            crest_source: CrestSource::Cycle,
            turned: None,
            height: k,
            taper: g.root_start.r() - g.root_end.r(),
            passes,
            depth_dir: -g.out,
            first_move,
            shop: Default::default(),
        }
    }
}
