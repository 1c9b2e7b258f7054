//! Shop-floor truths about each thread: how long it takes, whether the
//! machine can cut it at the programmed speed, whether the lead-in and
//! run-out suit that speed, what each pass loads the tool with, and whether
//! the finished thread will gauge (reference threading.md §9).
//!
//! A pure function of a finished thread (its passes and their motions), the
//! motions before it (the turned work), the settings and the program text
//! before it (a comment naming the thread): [`finish_thread`] fills the
//! thread's [`Shop`] and gives its diagnostics. The plan calls it for every
//! thread after the textbook advice ([`crate::advice`]); the incremental
//! planner calls it for the threads it reads again, so both give the same plan.
//!
//! - [`time`]: cut time (every synchronised motion at lead × n) and time
//!   with the rapids, per thread.
//! - [`limits`]: thread feed against the machine, spindle limit, G96, and
//!   δ1/δ2 from the speed.
//! - [`load`]: chip area per pass against a constant-area schedule.
//! - [`gauge`]: the pitch diameter the passes cut, compared with the
//!   designation's limits.

pub mod designation;
pub mod gauge;
pub mod insert;
pub mod limits;
pub mod load;
pub mod shim;
pub mod shoulder;
mod speed;
pub mod time;

use crate::diagnostic::Diagnostics;
use crate::motion::Move;
use crate::settings::Settings;
use crate::span::Span;
use crate::thread::{Axis, Thread};

pub use crate::figures::{ChipLoad, ClearanceSource, DesignationSource, Gauge, Shop};

/// Millimetres per inch.
const MM_PER_INCH: f64 = 25.4;

/// What the shop-floor step reads besides the threads.
pub struct Context<'a> {
    /// Every motion of the plan.
    pub moves: &'a [Move],
    /// Settings in force.
    pub settings: &'a Settings,
    /// The program is in inches (G20).
    pub inch: bool,
    /// The program text.
    pub text: &'a str,
    /// The byte span of a 1-based line.
    pub spans: &'a dyn Fn(u32) -> Span,
}

impl Context<'_> {
    /// Millimetres per program unit.
    pub fn mm(&self) -> f64 {
        if self.inch { MM_PER_INCH } else { 1.0 }
    }
}

/// Fills the [`Shop`] of thread `i` and gives its diagnostics to `diags`.
pub fn finish_thread(threads: &mut [Thread], i: usize, ctx: &Context, diags: &mut Diagnostics) {
    let Some(t) = threads.get(i) else { return };
    if t.passes.is_empty() || !(t.lead.is_finite() && t.lead > 0.0) {
        return;
    }
    let mut shop = Shop::default();
    if let Some(times) = time::thread_times(t, ctx) {
        shop.cut_time_s = Some(times.cut);
        shop.time_s = Some(times.total);
        shop.pass_time_s = times.passes;
    }
    limits::check(threads, i, ctx, &mut shop, diags);
    let t = &threads[i];
    speed::check(t, ctx, diags);
    insert::check(t, ctx, diags);
    shop.insert = insert::form(t, ctx);
    shop.chip = load::chip_loads(t, ctx, diags);
    let lower = i.checked_sub(1).map(|p| threads[p].end_line);
    shop.gauge = gauge::check(t, lower, ctx, diags);
    shop.pitch_diameter = match &shop.gauge {
        Some(g) => Some(g.pitch_diameter),
        None => gauge::cut_pitch_diameter(t, t.pitch, ctx),
    };
    shop.helix_angle_deg = helix_angle(t, shop.pitch_diameter);
    shim::check(t, shop.helix_angle_deg, ctx, diags);
    shop.shoulder = shoulder::check(threads, i, ctx, diags);
    shoulder::approach(threads, i, ctx, diags);
    threads[i].shop = shop;
}

/// Helix angle atan(lead / (π·d2)) in degrees of a thread along Z, with d2
/// the pitch diameter cut, else the mean of crest and deepest pass.
fn helix_angle(t: &Thread, d2: Option<f64>) -> Option<f64> {
    if t.long_axis != Axis::Z {
        return None;
    }
    let d = d2.or_else(|| {
        let root =
            t.passes.iter().map(|p| p.from.x).fold(if t.internal { f64::MIN } else { f64::MAX }, |a, x| {
                if t.internal { a.max(x) } else { a.min(x) }
            });
        Some((t.crest + root) / 2.0)
    })?;
    let d = d.abs();
    (d > 0.0 && d.is_finite()).then(|| (t.lead / (std::f64::consts::PI * d)).atan().to_degrees())
}

/// The program's threading time: the sum of the threads' `time_s`, `None`
/// when one of them is not known.
pub fn total_time(threads: &[Thread]) -> Option<f64> {
    threads.iter().try_fold(0.0, |sum, t| t.shop.time_s.map(|s| sum + s))
}
