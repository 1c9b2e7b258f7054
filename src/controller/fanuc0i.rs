//! Fanuc 0i-TF, G-code system A: G32 with a Q start angle, G92 with the
//! thread chamfer of parameters 5130/5131, G76. A length without a decimal
//! point is in least input increments unless parameter 3401#0 (DPI) is
//! set; Q and the cycle depths are integers in increments. One F register
//! serves feed and thread lead.

use super::macros::{Depth, Flavor, Macros};
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
        // Custom macro B, M98/M99 and G65 (0i-F operator's manual B-64604EN,
        // custom macro and subprogram chapters): subprograms nest 10 deep,
        // macro calls 5 (0i-C B-64124EN §12.3: four levels of M98).
        macros: Some(Macros {
            flavor: Flavor::Fanuc,
            subprograms: true,
            macro_calls: true,
            sub_depth: Depth::Setting(P::FanucSubNesting),
            macro_depth: Depth::Setting(P::FanucMacroNesting),
            max_loop: 3,
            h_codes: false,
            source: "Fanuc 0i",
        }),
        spindle_stops: &[],
        // G71/G72 type II when the contour's first block moves both axes (W0 for no Z move).
        pockets: true,
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

/// The G code list of the 0i-TF operator's manual (lathe system, G code
/// system A), beyond the codes GSK shares ([`lathe_g_code`]). A code the
/// controller has is never an alarm; what the preview does not draw gets a
/// note. Option functions (polygon turning, circular threading, automatic
/// tool offset) are read as the list gives them.
fn g_code(code10: i64) -> Option<(Group, G)> {
    use crate::message as m;
    use G::{Accepted, NotSimulated};
    use Group::{Drilling, Motion, OneShot, Setup};
    // `returns`: the tool ends where it started (else its position is unknown after the block).
    let ns = |what, returns| NotSimulated { what, returns };
    Some(match code10 {
        // 00: advanced preview control, exact stop, corner circular interpolation
        // (part of tool-nose compensation, which is not simulated).
        80 | 90 | 390 => (Setup, Accepted),
        // 00: programmable data input (offsets, parameters: G10 L50 … G11);
        // its X/Z words are data, not a motion.
        100 => (OneShot, ns(&m::NS_G10, true)),
        106 => (OneShot, ns(&m::NS_G10_6, true)),
        110 => (Setup, Accepted),
        // 21/00: polar coordinate and cylindrical interpolation, also as G112, G113, G107.
        1070 | 1120 | 1130 => (Setup, ns(&m::NS_POLAR, false)),
        // 16: plane selection.
        170 | 180 | 190 => (Setup, ns(&m::NS_PLANE, true)),
        // 09: stored stroke check; G22's X Z I K are the limits, not a motion.
        220 => (OneShot, ns(&m::NS_G22, true)),
        230 => (Setup, Accepted),
        // 08: spindle speed fluctuation detection.
        250 | 260 => (Setup, Accepted),
        // 00: reference position return check (a rapid to the point), movement
        // from the reference position, floating reference position return.
        270 => (OneShot, G::RefCheck),
        290 => (OneShot, ns(&m::NS_G29, false)),
        301 => (OneShot, ns(&m::NS_G30_1, false)),
        // 01: circular threading CW; 00: automatic tool offset X, Z (G36 is
        // circular threading CCW only with parameter 3405#3).
        350 => (Motion, ns(&m::NS_G35, false)),
        360 | 370 => (OneShot, ns(&m::NS_G36, false)),
        // 20: polygon turning (also G250/G251); 00: workpiece coordinate system preset.
        502 | 512 | 2500 | 2510 => (Setup, ns(&m::NS_POLYGON, true)),
        503 => (OneShot, ns(&m::NS_G50_3, false)),
        // 00: local and machine coordinate systems; 14: workpiece coordinate systems.
        520 => (OneShot, ns(&m::NS_G52, false)),
        530 => (OneShot, ns(&m::NS_G53, false)),
        540..=590 if code10 % 10 == 0 => (Setup, ns(&m::NS_WORK_OFFSET, true)),
        // 15: exact stop, tapping and cutting modes.
        610 | 630 | 640 => (Setup, Accepted),
        // 12: macro modal call A/B and its cancel (the call's words are arguments).
        660 | 661 => (OneShot, ns(&m::NS_G66, true)),
        670 => (Setup, Accepted),
        // 04: mirror image for double turrets.
        680 | 690 => (Setup, ns(&m::NS_MIRROR, true)),
        // 10: canned cycles for drilling (face and side drilling, tapping, boring) and their cancel.
        800 => (Drilling, G::CycleCancel),
        830 | 840 | 850 | 870 | 880 | 890 => (Drilling, ns(&m::NS_DRILLING, false)),
        _ => return lathe_g_code(code10),
    })
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
