//! G codes of each dialect: modal group and what screwcut does with them.

use crate::dialect::Dialect;

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
    /// Known to the controller but not drawn; `returns` says whether the tool ends where it started.
    NotSimulated {
        /// What it is.
        what: &'static str,
        /// The tool ends at the block's start point.
        returns: bool,
    },
}

/// Looks up `code10` (the G number × 10, so G12.1 is 121) for `dialect`.
pub fn lookup(dialect: Dialect, code10: i64) -> Option<(Group, G)> {
    use G::*;
    use Group::*;
    let ns = |what, returns| NotSimulated { what, returns };
    let common = match code10 {
        0 => Some((Motion, Rapid)),
        10 => Some((Motion, Linear)),
        20 => Some((Motion, ArcCw)),
        30 => Some((Motion, ArcCcw)),
        40 => Some((OneShot, Dwell)),
        _ => None,
    };
    if common.is_some() {
        return common;
    }
    match dialect {
        Dialect::Renhe => match code10 {
            300 => Some((RunoutMode, RenheRunout)),
            320 => Some((Motion, RenheInch)),
            330 => Some((Motion, RenheMetric)),
            _ => None,
        },
        Dialect::Gsk980tdc | Dialect::Fanuc0i => {
            let gsk = dialect == Dialect::Gsk980tdc;
            match code10 {
                200 => Some((Units, Inch)),
                210 => Some((Units, Metric)),
                280 => Some((OneShot, RefReturn)),
                320 => Some((Motion, Thread)),
                330 if gsk => Some((Motion, ns("G33 tapping cycle", true))),
                340 => Some((Motion, ns("G34 variable-lead thread", false))),
                400 => Some((NoseComp, CompOff)),
                410 | 420 => Some((NoseComp, CompOn)),
                500 => Some((OneShot, SetCoord)),
                650 => Some((OneShot, ns("G65 macro call", true))),
                700 => Some((OneShot, ns("G70 finishing cycle", true))),
                710 => Some((OneShot, ns("G71 stock removal in turning", true))),
                720 => Some((OneShot, ns("G72 stock removal in facing", true))),
                730 => Some((OneShot, ns("G73 pattern repeating", true))),
                740 => Some((OneShot, ns("G74 face grooving / peck drilling", true))),
                750 => Some((OneShot, ns("G75 grooving cycle", true))),
                760 => Some((OneShot, G76)),
                780 if gsk => Some((OneShot, G78)),
                900 => Some((Motion, G90)),
                920 => Some((Motion, G92)),
                940 => Some((Motion, G94)),
                960 => Some((Group::Css, G::Css)),
                970 => Some((Group::Css, CssOff)),
                980 => Some((FeedMode, PerMinute)),
                990 => Some((FeedMode, PerRev)),
                300 => Some((OneShot, ns("G30 second reference return", false))),
                310 => Some((OneShot, ns("G31 skip", false))),
                71 | 121 | 131 => Some((Setup, ns("polar / cylindrical interpolation", false))),
                540..=590 if !gsk => Some((Setup, ns("work coordinate system", true))),
                180 if !gsk => Some((Setup, ns("plane selection", true))),
                _ => None,
            }
        }
    }
}
