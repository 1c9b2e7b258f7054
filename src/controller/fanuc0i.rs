//! Fanuc 0i-TF, G-code system A: G32 with a Q start angle, G92 with the
//! thread chamfer of parameters 5130/5131, G76. A length without a decimal
//! point is in least input increments unless parameter 3401#0 (DPI) is
//! set; Q and the cycle depths are integers in increments. One F register
//! serves feed and thread lead.

use super::words::Unit;
use super::{Command, Controller, Reader, Rules, ThreadRules, ThreadWords, Writing, g32, g76, g92, lathe_g_code};
use crate::block::Block;
use crate::dialect::{Dialect, letters};
use crate::form::Form;
use crate::gcode::{G, Group};
use crate::settings::P;
use crate::state::Motion;

/// The Fanuc 0i-TF.
pub static CONTROLLER: Controller = Controller {
    rules: Rules {
        dialect: Dialect::Fanuc0i,
        // 0i-TF, two axes, G-code system A.
        addresses: letters(b"ABCDEFGHIJKLMNOPQRSTUWXZ"),
        increments_without_point: Some(P::Fanuc3401_0),
        shared_f_register: true,
        axis_words: letters(b"XZUW"),
        free_words: 0,
        spindle_word: false,
        spindle_stops: &[],
    },
    g_code,
    command,
    init: super::x_mode_parameter,
    check: None,
    finish: None,
    writing: Writing {
        preamble: &[],
        units: Some(("G20", "G21")),
        motion: ["G00", "G01", "G02", "G03"],
        points: true,
        spindle_on: None,
        thread: ThreadWords::G32 { runout: false },
        start_angle: true,
        forms: &[Form::G32, Form::G92, Form::G76],
    },
    tool_angle: Some(P::Fanuc5143),
};

/// How the shared thread readers read Fanuc programs.
static THREADS: ThreadRules = ThreadRules {
    g32_words: b"XZUWQ",
    tpi_word: false,
    g32_runout: false,
    angle: Unit::IncrementsNoPoint,
    depth: Unit::IncrementsNoPoint,
    g92: g92::Form::ChamferAndAngle { words: b"XZUWRQ", length: P::Fanuc5130, angle: P::Fanuc5131 },
    g76: g76::Form {
        words: b"XZUWRPQF",
        m: P::Fanuc5142,
        r: P::Fanuc5130,
        a: P::Fanuc5143,
        dmin: P::Fanuc5140,
        d: P::Fanuc5141,
        angles: Some(&[80, 60, 55, 30, 29, 0]),
        chamfer_angle: Some(P::Fanuc5131),
        m_min: 1,
        rewrites_depths: true,
    },
};

fn g_code(code10: i64) -> Option<(Group, G)> {
    let ns = |what| G::NotSimulated { what, returns: true };
    match code10 {
        540..=590 => Some((Group::Setup, ns(&crate::message::NS_WORK_OFFSET))),
        180 => Some((Group::Setup, ns(&crate::message::NS_PLANE))),
        _ => lathe_g_code(code10),
    }
}

fn command(r: &mut Reader, b: &Block, c: Command) {
    let angle = CONTROLLER.tool_angle(r);
    match c {
        Command::Motion(Motion::Thread) => g32::block(r, &THREADS, b, angle),
        Command::Motion(Motion::G92) => g92::block(r, &THREADS, b, angle),
        Command::OneShot(G::G76, w) => g76::block(r, &THREADS, b, w),
        _ => {}
    }
}
