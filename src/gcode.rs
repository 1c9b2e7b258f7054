//! The G codes screwcut knows: their modal group and what they do. Which
//! numbers a controller gives them is in its own module (`controller`).

/// Modal group of a G code (numbering as on Fanuc/GSK where it exists).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Group {
    /// 00: one-shot.
    OneShot,
    /// 01: motion.
    Motion,
    /// 02: constant surface speed.
    Css,
    /// 05: feed per minute / revolution.
    FeedMode,
    /// 06: inch / metric.
    Units,
    /// 07: tool-nose radius compensation.
    NoseComp,
    /// Renhe G30 run-out mode.
    RunoutMode,
    /// Work coordinate selection and other setup.
    Setup,
    /// Distance mode: absolute / incremental axis words (LinuxCNC G90/G91).
    Distance,
    /// Lathe X mode: diameter / radius (LinuxCNC G7/G8).
    LatheMode,
    /// Plane selection (G17/G18/G19).
    Plane,
    /// Canned cycles for drilling and their cancel (Fanuc lathe group 10:
    /// G80, G83–G89), apart from the motion group: G80 leaves G00/G01 as it was.
    Drilling,
}

/// What a G code does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum G {
    /// G00.
    Rapid,
    /// G01.
    Linear,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// G32 on GSK/Fanuc: constant-lead thread.
    Thread,
    /// Renhe G32: inch thread (F in threads per inch).
    RenheInch,
    /// Renhe G33: metric thread.
    RenheMetric,
    /// Renhe G30: run-out mode.
    RenheRunout,
    /// G04 dwell.
    Dwell,
    /// G50 coordinate setting / spindle clamp.
    SetCoord,
    /// G28 reference return.
    RefReturn,
    /// G27 reference position return check: a rapid to the point given.
    RefCheck,
    /// G80: cancels the canned cycle for drilling (group [`Group::Drilling`]).
    CycleCancel,
    /// G20.
    Inch,
    /// G21.
    Metric,
    /// G98.
    PerMinute,
    /// G99.
    PerRev,
    /// G96.
    Css,
    /// G97.
    CssOff,
    /// G40.
    CompOff,
    /// G41/G42.
    CompOn,
    /// G90 turning cycle.
    G90,
    /// G94 facing cycle.
    G94,
    /// G92 threading cycle.
    G92,
    /// G76 multiple threading cycle.
    G76,
    /// G78 enhanced threading cycle (GSK).
    G78,
    /// Absolute axis words (LinuxCNC G90).
    Absolute,
    /// Incremental axis words (LinuxCNC G91).
    Incremental,
    /// X as a diameter (LinuxCNC G7).
    DiameterMode,
    /// X as a radius (LinuxCNC G8).
    RadiusMode,
    /// Plane selection: 17 (XY), 18 (XZ) or 19 (YZ).
    Plane(u8),
    /// Cutter compensation with the diameter in the block's D word (LinuxCNC G41.1/G42.1).
    CompOnDynamic,
    /// Spindle-synchronised motion, K = distance along the move per revolution (LinuxCNC G33).
    SyncThread,
    /// LinuxCNC's G76 threading cycle (motion group: drive line, I J K R Q H E L).
    ThreadCycle,
    /// Known to the controller and without effect on the drawing (work offsets, path control, tool length).
    Accepted,
    /// A stock-removal cycle, G71 (cuts along Z) or G72 (along X): its first
    /// block sets the depth of cut and the escape, its second (with P and Q)
    /// roughs over the contour N(P) … N(Q).
    Rough(crate::cycle::rough::Along),
    /// The pattern repeating cycle G73: its first block sets the relief
    /// U(Δi) W(Δk) and the number of divisions R(d), its second (with P and
    /// Q) cuts the contour N(P) … N(Q) d times.
    Pattern,
    /// LinuxCNC's G70–G72 `Q- X- Z- …` (the code ×10: 700, 710–712,
    /// 720–722): a rapid to X/Z, then the profile of subroutine o(Q), read
    /// by the program flow, run as the finishing passes (G70) or roughed
    /// over (G71, G72 and their .1/.2 forms).
    LinuxProfile(i64),
    /// Known to the controller but not drawn; `returns` says whether the tool ends where it started.
    NotSimulated {
        /// What it is.
        what: &'static crate::message::Phrase,
        /// The tool ends at the block's start point.
        returns: bool,
    },
}
