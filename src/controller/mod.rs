//! The controllers, one module each: what their words mean, their G codes,
//! unit rules, parameters and alarms. Each is a [`Controller`] table; the
//! interpreter reads every block through the table of the dialect in force
//! and nothing outside these modules asks which dialect it is.
//!
//! GSK980TDc and Fanuc 0i share the G32, G92 and G76 readers ([`g32`],
//! [`g92`], [`g76`]), which take the differences as data ([`ThreadRules`]);
//! G78 is GSK's own, Renhe's G30/G32/G33 are Renhe's, and LinuxCNC's
//! G7/G8, G33 and G76 with its word checks are in [`linuxcnc`].

pub mod fanuc0i;
pub mod g32;
pub mod g76;
pub mod g92;
pub mod gsk980tdc;
pub mod linuxcnc;
pub mod macros;
pub mod reader;
pub mod renhe;
pub mod stock;
pub mod words;

pub use reader::{Reader, Rules};

use crate::block::{Block, Word};
use crate::dialect::Dialect;
use crate::gcode::{G, Group};
use crate::settings::{P, Settings};
use crate::state::{Modal, Motion};

/// A controller: its rules and the commands it reads itself.
pub struct Controller {
    /// Unit rules and addresses.
    pub rules: Rules,
    /// Modal group and meaning of a G code (the number × 10: G12.1 is 121).
    pub g_code: fn(i64) -> Option<(Group, G)>,
    /// Reads a thread or cycle block of this controller.
    pub command: fn(&mut Reader, &Block, Command),
    /// Sets the modal state a program starts in.
    pub init: fn(&mut Modal, &Settings),
    /// Checks a block's words before it runs, given the motion it will make
    /// (its motion-group code, or the modal one when it has axis words, ×10);
    /// false after an alarm: the block is not executed.
    pub check: Option<BlockCheck>,
    /// Checks made when the program has been read (how it ended).
    pub finish: Option<fn(&mut Reader)>,
    /// How programs are written for this controller (`expand`, `generate`).
    pub writing: Writing,
    /// The parameter holding the tool angle of threads cut block by block
    /// (`None`: 60°).
    pub tool_angle: Option<P>,
}

/// How programs are written for a controller (`expand`, `generate`): data
/// the writers read, so that they never ask which controller it is.
#[derive(Debug)]
pub struct Writing {
    /// Lines a program starts with (plane, X mode, distance mode).
    pub preamble: &'static [&'static str],
    /// The inch and metric codes, or `None` when the controller reads millimetres only.
    pub units: Option<(&'static str, &'static str)>,
    /// Motion codes: rapid, feed, clockwise arc, counter-clockwise arc.
    pub motion: [&'static str; 4],
    /// Every length carries a decimal point (Fanuc reads `X20` as 0.02 mm).
    pub points: bool,
    /// The block that starts the spindle, where a thread needs it turning.
    pub spindle_on: Option<&'static str>,
    /// How a synchronised move is written.
    pub thread: ThreadWords,
    /// G32 takes a start angle `Q` in 0.001° (multi-start by start angle).
    pub start_angle: bool,
    /// The threading forms the wizard writes for this controller.
    pub forms: &'static [crate::form::Form],
}

impl Writing {
    /// A length as the controller reads it: four decimals, with a decimal point where it needs one.
    pub fn length(&self, v: f64) -> String {
        let s = crate::num::fmt(v);
        if self.points && !s.contains('.') { s + "." } else { s }
    }

    /// A lead or pitch: six decimals, with a decimal point where the controller needs one.
    pub fn lead(&self, v: f64) -> String {
        let r = (v * 1e6).round() / 1e6;
        let mut s = format!("{r:.6}");
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') && !self.points {
            s.pop();
        }
        if s == "-0" { "0".into() } else { s }
    }
}

/// How a controller writes one synchronised move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThreadWords {
    /// `G32 X Z F`, F the lead along the long axis; with `runout`, a `J K` run-out (GSK).
    G32 {
        /// J/K run-out words.
        runout: bool,
    },
    /// Renhe: `G30 U W` sets the tail, `G33 U W F` (incremental, F the pitch in mm).
    Renhe,
    /// LinuxCNC: `G33 X Z K`, K the distance along the move per revolution.
    AlongPath,
}

/// A controller's check of a block's words before it runs (see [`Controller::check`]).
pub type BlockCheck = fn(&mut Reader, &Block, Option<i64>) -> bool;

/// A block the interpreter hands to its controller.
#[derive(Clone, Copy, Debug)]
pub enum Command<'b> {
    /// A block with axis words in a thread motion mode (G32, G92, Renhe G32/G33, LinuxCNC G33/G76).
    Motion(Motion),
    /// A one-shot thread or cycle code (G76, G78, Renhe G30) and its word.
    OneShot(G, &'b Word),
}

/// Every controller, in [`Dialect::ALL`] order.
const ALL: [&Controller; 4] = [&gsk980tdc::CONTROLLER, &fanuc0i::CONTROLLER, &renhe::CONTROLLER, &linuxcnc::CONTROLLER];

/// The start state of the controllers whose X mode is a parameter (`x_mode`).
pub fn x_mode_parameter(m: &mut Modal, s: &Settings) {
    m.radius = s.radius_x();
}

/// The controller of a dialect.
pub fn of(d: Dialect) -> &'static Controller {
    ALL[d.index()]
}

impl Controller {
    /// The tool angle of threads cut block by block, as the program has it now.
    pub fn tool_angle(&self, r: &Reader) -> f64 {
        self.tool_angle.map_or(60.0, |p| r.param(p))
    }
}

/// G codes every controller reads alike: G00–G03, G04.
pub fn basic_g_code(code10: i64) -> Option<(Group, G)> {
    Some(match code10 {
        0 => (Group::Motion, G::Rapid),
        10 => (Group::Motion, G::Linear),
        20 => (Group::Motion, G::ArcCw),
        30 => (Group::Motion, G::ArcCcw),
        40 => (Group::OneShot, G::Dwell),
        _ => return None,
    })
}

/// G codes GSK980TDc and Fanuc 0i-TF read alike (their own are added by each).
pub fn lathe_g_code(code10: i64) -> Option<(Group, G)> {
    use G::*;
    use Group::*;
    if let Some(found) = basic_g_code(code10) {
        return Some(found);
    }
    let ns = |what, returns| NotSimulated { what, returns };
    Some(match code10 {
        200 => (Units, Inch),
        210 => (Units, Metric),
        280 => (OneShot, RefReturn),
        320 => (Motion, Thread),
        340 => (Motion, ns(&crate::message::NS_G34, false)),
        400 => (NoseComp, CompOff),
        410 | 420 => (NoseComp, CompOn),
        500 => (OneShot, SetCoord),
        650 => (OneShot, ns(&crate::message::NS_G65, true)),
        // G70 P Q: the program flow runs the contour and the rapid back (exec::profile).
        700 => (OneShot, Accepted),
        710 => (OneShot, Rough(crate::cycle::rough::Along::Z)),
        720 => (OneShot, Rough(crate::cycle::rough::Along::X)),
        730 => (OneShot, Pattern),
        740 => (OneShot, ns(&crate::message::NS_G74, true)),
        750 => (OneShot, ns(&crate::message::NS_G75, true)),
        760 => (OneShot, G76),
        900 => (Motion, G90),
        920 => (Motion, G92),
        940 => (Motion, G94),
        960 => (Group::Css, G::Css),
        970 => (Group::Css, CssOff),
        980 => (FeedMode, PerMinute),
        990 => (FeedMode, PerRev),
        300 => (OneShot, ns(&crate::message::NS_G30, false)),
        310 => (OneShot, ns(&crate::message::NS_G31, false)),
        71 | 121 | 131 => (Setup, ns(&crate::message::NS_POLAR, false)),
        _ => return None,
    })
}

/// How the shared G32/G92/G76 readers differ between GSK980TDc and Fanuc 0i.
#[derive(Debug)]
pub struct ThreadRules {
    /// Words G32 takes (besides G, M, S, T, F).
    pub g32_words: &'static [u8],
    /// `I` gives the lead in threads per inch.
    pub tpi_word: bool,
    /// G32 takes a `J`/`K` run-out, modal across consecutive thread blocks.
    pub g32_runout: bool,
    /// Unit of the start angle `Q`.
    pub angle: words::Unit,
    /// Unit of the cycle depths `P(k)`, `Q(Δd)`, `Q(Δdmin)`.
    pub depth: words::Unit,
    /// The G92 form.
    pub g92: g92::Form,
    /// The G76 form.
    pub g76: g76::Form,
}
