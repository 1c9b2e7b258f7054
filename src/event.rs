//! What the interpreter says about each block: motions, thread pieces,
//! cycle calls and the ends of threads. Grouping passes and planning cycles
//! are functions of these events (and the settings); diagnostics go to
//! their own collector.

use crate::cycle::{Geometry, Multi, PassPoints};
use crate::geom::Frame;
use crate::motion::{Move, Point};
use crate::span::Span;
use crate::thread::{Axis, Source, Spindle, ThreadKind};

/// One event of one block.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A rapid (G00): its motion when the tool moved, and which axis words it had.
    Rapid {
        /// The motion (none when the position was unknown or did not change).
        mv: Option<Move>,
        /// An X or U word was given.
        x: bool,
        /// A Z or W word was given.
        z: bool,
        /// Source line.
        line: u32,
    },
    /// A feed, arc or turning-cycle motion (not part of a thread).
    Motion(Move),
    /// A synchronised piece of a thread cut block by block (G32, Renhe G32/G33).
    Piece(Piece),
    /// A G92 pass block: one pass per start.
    G92(Box<G92Pass>),
    /// A multi-pass cycle (G76, G78).
    Multi(Box<Multi>),
    /// LinuxCNC's G76 cycle.
    LinuxG76(Box<crate::cycle::linuxcnc::G76>),
    /// The continuous thread being cut ends (a block that is not a thread block).
    Break,
    /// The block-by-block threads being grouped are complete (a feed, a cycle, the end).
    Close,
}

/// One straight piece of a continuous thread.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    /// Start of the synchronised cut.
    pub from: Point,
    /// End of the synchronised cut (run-out excluded).
    pub to: Point,
    /// End of the run-out, when the block has one.
    pub runout_to: Option<Point>,
    /// Shape of this piece.
    pub kind: ThreadKind,
    /// Long axis of this piece.
    pub long: Axis,
}

impl Seg {
    /// The long/short frame of this piece.
    pub fn frame(&self) -> Frame {
        Frame(self.long)
    }

    /// Travel along the long axis (radial for X).
    pub fn long_travel(&self) -> f64 {
        self.frame().travel(self.from, self.to)
    }

    /// Long-axis coordinate of a point (radius for X).
    pub fn long_of(&self, p: Point) -> f64 {
        self.frame().long(p)
    }

    /// Short-axis coordinate of a point (radius for X).
    pub fn short_of(&self, p: Point) -> f64 {
        self.frame().short(p)
    }
}

/// A block-by-block thread piece: the cut, its run-out, and what grouping needs.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// Command family.
    pub source: Source,
    /// Lead (program units per revolution).
    pub lead: f64,
    /// Start angle in degrees (Q of the first block of a continuous thread).
    pub angle: f64,
    /// The geometry.
    pub seg: Seg,
    /// Source line.
    pub line: u32,
    /// Span of the block.
    pub span: Span,
    /// Direction of the last X motion before the cut (−1 inward, +1 outward, 0 unknown).
    pub approach: f64,
    /// Tool angle in force (degrees).
    pub tool_angle: f64,
    /// The spindle in force.
    pub spindle: Spindle,
}

/// A G92 block: the same pass for every start, the starts `360°/starts` apart.
#[derive(Clone, Debug, PartialEq)]
pub struct G92Pass {
    /// The cycle's geometry (start point A, root line, run-out).
    pub geom: Geometry,
    /// The pass.
    pub pts: PassPoints,
    /// Lead.
    pub lead: f64,
    /// Start angle of the first start (Fanuc Q).
    pub angle: f64,
    /// Starts (GSK L).
    pub starts: u32,
    /// Source line.
    pub line: u32,
    /// Span of the block.
    pub span: Span,
    /// Tool angle in force (degrees).
    pub tool_angle: f64,
    /// The spindle in force.
    pub spindle: Spindle,
}
