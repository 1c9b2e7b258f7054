//! The controller's modal state while a program is read: one cloneable
//! value ([`Modal`]). The interpreter changes it block by block; the rest
//! of a plan (motions, threads, diagnostics) is output and kept apart, so a
//! snapshot of the reading is a clone of this value plus output lengths.

use crate::motion::Point;
use crate::settings::{P, Settings};

/// Modal motion (group 01).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// No motion command yet.
    None,
    /// G00.
    Rapid,
    /// G01.
    Linear,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// G32 (GSK/Fanuc).
    Thread,
    /// Renhe G32 inch thread.
    RenheInch,
    /// Renhe G33 metric thread.
    RenheMetric,
    /// LinuxCNC G33: spindle-synchronised move, K along the move.
    SyncThread,
    /// LinuxCNC G76 threading cycle (modal, but each block must give P I J K).
    ThreadCycle,
    /// G90 turning cycle.
    G90,
    /// G92 threading cycle.
    G92,
    /// G94 facing cycle.
    G94,
    /// A motion-group code that is not drawn.
    NotSimulated(&'static crate::message::Phrase, bool),
}

impl Motion {
    /// Whether blocks in this mode cut a thread block by block (continuous threads).
    pub fn is_thread_block(self) -> bool {
        matches!(self, Motion::Thread | Motion::RenheInch | Motion::RenheMetric | Motion::SyncThread)
    }
}

/// A position with per-axis knowledge: before any absolute word or G50 the
/// machine position is unknown, and nothing is drawn from it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Position {
    /// The point (valid where known).
    pub p: Point,
    /// X is known.
    pub kx: bool,
    /// Z is known.
    pub kz: bool,
}

/// The end point of a block's axis words.
#[derive(Clone, Copy, Debug)]
pub struct Target {
    /// End point.
    pub p: Point,
    /// An X or U word was given.
    pub has_x: bool,
    /// A Z or W word was given.
    pub has_z: bool,
}

/// The thread tail mode set by Renhe's G30.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Tail {
    /// Standard run-out (G30 alone, or no G30).
    #[default]
    Standard,
    /// No run-out (`G30 U0 W0`).
    None,
    /// Spiral tail: retract `u` (diameter) over the last `w` of Z.
    Spiral {
        /// Diameter retract.
        u: f64,
        /// Axial length.
        w: f64,
    },
}

/// The words of the last G76 first block (`P(m)(r)(a) Q(Δdmin) R(d)`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct G76First {
    /// Finishing passes m.
    pub m: u32,
    /// Chamfer r, tenths of a lead.
    pub r: u32,
    /// Tool angle a.
    pub a: u32,
    /// Δdmin.
    pub dmin: Option<f64>,
    /// Finishing allowance d.
    pub d: Option<f64>,
    /// Line of the block.
    pub line: u32,
}

/// The first G78 block: what it gave (None: take the parameter or default).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct G78First {
    /// Depth mode m (0 equal, 1 degressive).
    pub m: Option<u32>,
    /// Infeed mode r (0 radial, 1 left, 2 right, 3 alternating).
    pub r: Option<u32>,
    /// Tool angle a.
    pub a: Option<u32>,
    /// Δdmin.
    pub dmin: Option<f64>,
    /// Finishing allowance d.
    pub d: Option<f64>,
    /// Run-out J (non-modal: used by the next cycle only).
    pub j: Option<f64>,
    /// Run-out K (non-modal).
    pub k: Option<f64>,
    /// Finishing passes D.
    pub count: Option<u32>,
    /// Starts L.
    pub starts: Option<u32>,
    /// Screw-in E.
    pub e: Option<f64>,
    /// Line of the block.
    pub line: u32,
}

/// Values a G92 pass block keeps from the one before it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G92Modal {
    /// Absolute end Z.
    pub z: f64,
    /// Taper R(i).
    pub r: f64,
    /// Run-out J.
    pub j: Option<f64>,
    /// Run-out K.
    pub k: Option<f64>,
    /// Starts L.
    pub starts: u32,
}

/// The cycles' memory between blocks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CycleMemory {
    /// The last G78 first block.
    pub g78: Option<G78First>,
    /// The last G76 first block.
    pub g76: Option<G76First>,
    /// G92 modal values for the following pass blocks.
    pub g92: Option<G92Modal>,
}

/// Diagnostics said once per program (bit flags).
pub mod once {
    /// The start position was assumed.
    pub const START: u32 = 1;
    /// Blocks after M30.
    pub const AFTER_END: u32 = 2;
    /// Tool-nose compensation.
    pub const COMP: u32 = 8;
    /// A thread outside the XZ plane (LinuxCNC).
    pub const PLANE: u32 = 16;
    /// G33 K along a taper move (LinuxCNC).
    pub const LEAD_ALONG_PATH: u32 = 32;
    /// A length written finer than the least input increment.
    pub const FINER: u32 = 64;
}

/// The modal state of the controller between blocks.
#[derive(Clone, Debug, PartialEq)]
pub struct Modal {
    /// Current tool position.
    pub pos: Position,
    /// Modal motion.
    pub motion: Motion,
    /// G20 in force.
    pub inch: bool,
    /// Feed register (non-thread F).
    pub feed: Option<f64>,
    /// Line where the feed register was last set.
    pub feed_line: u32,
    /// Lead register (thread F/I), program units per revolution.
    pub lead: Option<f64>,
    /// With a single F register for feed and lead: the line of the non-thread
    /// block whose F the lead register holds.
    pub lead_from_feed: Option<u32>,
    /// G32 modal run-out J and K (cancelled by a non-thread motion block).
    pub jk: (Option<f64>, Option<f64>),
    /// Spindle speed S (rev/min under G97, m/min under G96).
    pub spindle: Option<f64>,
    /// G96 constant surface speed in force.
    pub css: bool,
    /// Spindle clamp of the last G50 S (rev/min).
    pub clamp: Option<f64>,
    /// A continuous thread is being cut: the next thread block joins it.
    pub chain: bool,
    /// Thread pieces or G92 passes were given since the last `Close`: the
    /// threads being grouped may not be complete.
    pub grouping: bool,
    /// The cycles' memory between blocks.
    pub cycle: CycleMemory,
    /// Parameters the program has rewritten (a G76 first block), by id.
    pub params: Vec<(P, f64)>,
    /// The thread tail mode (Renhe G30).
    pub tail: Tail,
    /// Direction (−1/+1) and line of the last G00/G01 move in X (Renhe's run-out goes the other way).
    pub last_x_feed: Option<(f64, u32)>,
    /// The last spindle advice given (S, pitch as bits), to say it once.
    pub spindle_warned: Option<(u64, u64)>,
    /// Direction of the last X motion (−1, 0, +1) and its line.
    pub last_x: (f64, u32),
    /// M30/M02 seen.
    pub ended: bool,
    /// A motion block has been read.
    pub motion_seen: bool,
    /// X words are radii (G8, or the `x_mode` parameter); otherwise diameters.
    pub radius: bool,
    /// Axis words are incremental (LinuxCNC G91).
    pub incremental: bool,
    /// Plane in force: 17, 18 or 19.
    pub plane: u8,
    /// The spindle turns (M3/M4 given, no M5 since).
    pub spindle_on: bool,
    /// Cutter radius compensation in force, with its radius when the program gives it (0 otherwise).
    pub comp: Option<f64>,
    /// The last motion-group G code read, times 10 (G33.1 is 331).
    pub motion_code: Option<i64>,
    /// A `%` line was read.
    pub percent: bool,
    /// Span of the last block read (where an end-of-program finding goes).
    pub last_span: crate::span::Span,
    /// Diagnostics said once ([`once`] flags).
    pub said: u32,
    /// A canned cycle for drilling is in force (Fanuc G83–G89 until G80 or a
    /// group 01 code): blocks with axis words drill, and are not drawn.
    pub drilling: bool,
    /// The G codes (×10) whose "not simulated" note was given: once per code.
    pub noted: Vec<i64>,
    /// The depth of cut and escape of G71 and G72 (their first blocks), in program units.
    pub rough_regs: [Option<(f64, f64)>; 2],
    /// A G71/G72 with P and Q just read: its cycle, for the program flow to rough over the contour.
    pub rough_call: Option<crate::cycle::rough::Rough>,
    /// G73's relief and divisions as its first blocks set them.
    pub pattern_regs: PatternRegs,
    /// A G73 with P and Q just read: its cycle, for the program flow to cut the contour d times.
    pub pattern_call: Option<crate::cycle::pattern::Pattern>,
    /// A LinuxCNC G70–G72 just read: the subroutine of its profile (`Q`) and
    /// the cycle, for the program flow to read the profile.
    pub profile_call: Option<crate::cycle::g7x::Call>,
}

/// What the first blocks `G73 U(Δi) W(Δk) R(d)` set, in program units
/// (each word kept until another first block gives it again).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PatternRegs {
    /// Relief across Δi (a radius); 0 until given.
    pub di: f64,
    /// Relief along Z Δk; 0 until given.
    pub dk: f64,
    /// The number of divisions d: `None` until given, `Some(0)` after a refused R.
    pub d: Option<u32>,
}

impl Default for Modal {
    fn default() -> Modal {
        Modal {
            pos: Position::default(),
            motion: Motion::None,
            inch: false,
            feed: None,
            feed_line: 0,
            lead: None,
            lead_from_feed: None,
            jk: (None, None),
            spindle: None,
            css: false,
            clamp: None,
            chain: false,
            grouping: false,
            cycle: CycleMemory::default(),
            params: Vec::new(),
            tail: Tail::Standard,
            last_x_feed: None,
            spindle_warned: None,
            last_x: (0.0, 0),
            ended: false,
            motion_seen: false,
            radius: false,
            incremental: false,
            plane: 18,
            spindle_on: false,
            comp: None,
            motion_code: None,
            percent: false,
            last_span: crate::span::Span::default(),
            said: 0,
            drilling: false,
            noted: Vec::new(),
            rough_regs: [None, None],
            rough_call: None,
            pattern_regs: PatternRegs::default(),
            pattern_call: None,
            profile_call: None,
        }
    }
}

impl Modal {
    /// A parameter's value in force: as the program rewrote it, else the setting.
    pub fn param(&self, s: &Settings, p: P) -> f64 {
        self.params.iter().rev().find(|(q, _)| *q == p).map_or_else(|| s.get(p), |(_, v)| *v)
    }

    /// Rewrites a parameter for the rest of the program.
    pub fn rewrite(&mut self, p: P, v: f64) {
        match self.params.iter_mut().find(|(q, _)| *q == p) {
            Some(slot) => slot.1 = v,
            None => self.params.push((p, v)),
        }
    }

    /// True the first time `flag` is asked for.
    pub fn first(&mut self, flag: u32) -> bool {
        let first = self.said & flag == 0;
        self.said |= flag;
        first
    }
}
