//! The wizard's program writers, one per form. Numbers are written by the
//! target controller's [`Writing`] (decimal points where it needs them).
//! Multi-start threads take the start angle `Q` where the form has it (G32,
//! Fanuc G92), `L` starts (GSK G92, G78), else each start begins lead/starts
//! further back along Z (the same helix, reached later).

use super::{Form, Request, Spec};
use crate::args;
use crate::controller::{self, ThreadWords, Writing};
use crate::message::{Remark, tools};
use crate::num::fmt;

struct Out {
    w: &'static Writing,
    text: String,
}

impl Out {
    /// A comment line: parentheses inside would end it, so they become brackets.
    fn comment(&mut self, s: &str) {
        let body: String = s
            .chars()
            .map(|c| match c {
                '(' => '[',
                ')' => ']',
                c if c.is_ascii() => c,
                _ => '?',
            })
            .collect();
        self.line(format!("({body})"));
    }

    fn line(&mut self, s: impl AsRef<str>) {
        self.text.push_str(s.as_ref());
        self.text.push('\n');
    }

    /// A length rounded to the controls' least input increment, 0.001 mm
    /// (IS-B), as the control would read it.
    fn len(&self, v: f64) -> String {
        self.w.length((v * 1e3).round() / 1e3)
    }

    fn x(&self, v: f64) -> String {
        format!("X{}", self.len(v))
    }

    fn z(&self, v: f64) -> String {
        format!("Z{}", self.len(v))
    }

    fn rapid(&self) -> &'static str {
        self.w.motion[0]
    }
}

/// The program of `r` for the thread `s`.
pub fn program(r: &Request, s: &Spec, notes: &mut Vec<Remark>) -> Result<String, Remark> {
    let w = &controller::of(r.dialect).writing;
    let mut o = Out { w, text: String::new() };
    o.comment(&format!("{}: {} for {}, by screwcut generate", s.title, r.form.title(), r.dialect.title()));
    o.comment(&format!(
        "crest X{}; lead {} pitch {} starts {}; last pass X{} at Z{}; depth {} in {} passes",
        fmt(s.crest),
        fmt(s.lead),
        fmt(s.pitch),
        s.starts,
        fmt(s.root),
        fmt(s.z0),
        fmt(s.height),
        s.depths.len()
    ));
    if let Some((_, mm)) = w.units {
        o.line(mm);
    }
    for l in w.preamble {
        o.line(l);
    }
    let spindle = match r.form {
        Form::RenheG33 => s.spindle.min((2300.0 / s.lead - 60.0).floor()),
        _ => s.spindle,
    };
    if spindle < 1.0 {
        return Err(Remark::new(&tools::WZ_RENHE_NO_SPEED, args![lead = s.lead]));
    }
    if spindle < s.spindle {
        notes.push(Remark::new(&tools::WZ_RENHE_SPINDLE, args![s = spindle]));
    }
    o.line(format!("{} S{}", w.spindle_on.unwrap_or("M03"), fmt(spindle)));
    let r0 = o.rapid();
    o.line(format!("{r0} {} {}", o.x(s.clear_x), o.z(s.za)));
    match r.form {
        Form::G32 | Form::G33 => blockwise(&mut o, s),
        Form::RenheG33 => renhe(&mut o, s)?,
        Form::G92 => g92(&mut o, s, notes),
        Form::G76 => g76(&mut o, s),
        Form::G78 => g78(&mut o, s),
        Form::LinuxG76 => linux_g76(&mut o, s, notes)?,
    }
    o.line(format!("{r0} {} {}", o.x(s.clear_x), o.z(s.za)));
    o.line("M30");
    Ok(o.text)
}

/// Start `k` (0-based): its angle, and its start Z moved back along the cut by lead·k/starts.
fn start(s: &Spec, k: u32) -> (f64, f64) {
    let f = k as f64 / s.starts as f64;
    (360.0 * f, s.za - s.sense() * s.lead * f)
}

/// Before start `k` of a thread cut by axial offsets: a comment and a
/// G01 that does not move, which ends the thread before it (its passes are
/// on another helix, not deeper passes of the same one).
fn separate(o: &mut Out, s: &Spec, k: u32) {
    o.comment(&format!("start {} of {}: lead x {k}/{} further back along Z", k + 1, s.starts, s.starts));
    o.line(format!("{} {} F{}", o.w.motion[1], o.z(s.za), o.w.lead(0.2)));
}

/// Blocks per pass: infeed, cut, retract, return (G32 with `Q`, or LinuxCNC's G33).
fn blockwise(o: &mut Out, s: &Spec) {
    let r0 = o.rapid();
    for k in 0..s.starts {
        let (angle, za) = start(s, k);
        let offset = !o.w.start_angle && k > 0;
        if offset {
            separate(o, s, k);
        }
        for &h in &s.depths {
            if offset {
                o.line(format!("{r0} {}", o.z(za)));
            }
            let (za, angle) = if offset { (za, 0.0) } else { (s.za, angle) };
            let (xa, x1) = (s.x_at(h, za), s.x_at(h, s.z1));
            o.line(format!("{r0} {}", o.x(xa)));
            let x = if s.taper != 0.0 { format!("{} ", o.x(x1)) } else { String::new() };
            let cut = match o.w.thread {
                ThreadWords::AlongPath => {
                    let len = ((x1 - xa) / 2.0).hypot(s.z1 - za);
                    format!("G33 {x}{} K{}", o.z(s.z1), o.w.lead(s.lead * len / (s.z1 - za).abs()))
                }
                _ => {
                    let q = if angle != 0.0 { format!(" Q{}", (angle * 1000.0).round() as i64) } else { String::new() };
                    format!("G32 {x}{} F{}{q}", o.z(s.z1), o.w.lead(s.lead))
                }
            };
            o.line(cut);
            o.line(format!("{r0} {}", o.x(s.clear_x)));
            o.line(format!("{r0} {}", o.z(s.za)));
        }
    }
}

/// Renhe: no tail (`G30 U0 W0`), incremental `G33 U W F` (or `G32 W F` in threads per inch).
fn renhe(o: &mut Out, s: &Spec) -> Result<(), Remark> {
    if (s.z1 - s.za).abs() <= 4.0 {
        return Err(Remark::new(&tools::WZ_RENHE_TOO_SHORT, args![]));
    }
    let tpi = 25.4 / s.lead;
    let half = (2.0 * tpi).round();
    let thread = if (3.0..=33.0).contains(&tpi) && (2.0 * tpi - half).abs() < 1e-6 {
        let f = if half % 2.0 == 0.0 { format!("{}", half / 2.0) } else { format!("{}.2", (half / 2.0).floor()) };
        format!("G32 {{}} F{f}")
    } else if (0.25..=12.0).contains(&s.lead) {
        format!("G33 {{}} F{}", o.w.lead(s.lead))
    } else {
        return Err(Remark::new(&tools::WZ_RENHE_PITCH, args![lead = s.lead]));
    };
    o.line("G30 U0 W0");
    for k in 0..s.starts {
        let (_, za) = start(s, k);
        if k > 0 {
            separate(o, s, k);
        }
        for &h in &s.depths {
            if k > 0 {
                o.line(format!("G00 {}", o.z(za)));
            }
            let (xa, x1) = (s.x_at(h, za), s.x_at(h, s.z1));
            o.line(format!("G00 {}", o.x(xa)));
            let u = x1 - xa;
            let uw = if u.abs() > 1e-9 {
                format!("U{} W{}", o.len(u), o.len(s.z1 - za))
            } else {
                format!("W{}", o.len(s.z1 - za))
            };
            o.line(thread.replacen("{}", &uw, 1));
            o.line(format!("G00 {}", o.x(s.clear_x)));
            o.line(format!("G00 {}", o.z(s.za)));
        }
    }
    Ok(())
}

/// Taper R(i) of a cycle starting at `za`: start radius minus end radius.
fn taper_word(o: &Out, s: &Spec, za: f64, z1: f64) -> String {
    let i = (s.x_at(0.0, za) - s.x_at(0.0, z1)) / 2.0;
    if i.abs() > 1e-9 { format!(" R{}", o.len(i)) } else { String::new() }
}

/// G92: one block per pass; GSK without run-out (J0) and with L starts, Fanuc with Q per start.
fn g92(o: &mut Out, s: &Spec, notes: &mut Vec<Remark>) {
    let gsk = o.w.thread == (ThreadWords::G32 { runout: true });
    // Fanuc's chamfer (parameter 5130, one lead at its default) is inside the
    // programmed travel: program one lead further to keep the full depth to the end.
    let z1 = if gsk { s.z1 } else { s.z1 + s.sense() * s.lead };
    if !gsk {
        notes.push(Remark::new(&tools::WZ_G92_CHAMFER, args![z = z1]));
    }
    let starts = if gsk { 1 } else { s.starts };
    for k in 0..starts {
        let (angle, _) = start(s, k);
        let q = if angle != 0.0 { format!(" Q{}", (angle * 1000.0).round() as i64) } else { String::new() };
        for (n, &h) in s.depths.iter().enumerate() {
            let x = o.x(s.x_at(h, z1));
            if n == 0 {
                let extra = if gsk {
                    let l = if s.starts > 1 { format!(" L{}", s.starts) } else { String::new() };
                    format!(" J0{l}")
                } else {
                    String::new()
                };
                let r = taper_word(o, s, s.za, z1);
                o.line(format!("G92 {x} {}{r} F{}{extra}{q}", o.z(z1), o.w.lead(s.lead)));
            } else {
                o.line(format!("{x}{q}"));
            }
        }
    }
}

/// Depth words in least input increments (0.001 mm): k, and Δd for `passes` degressive passes.
fn increments(s: &Spec) -> (i64, i64) {
    let k = (s.height * 1000.0).round().max(1.0) as i64;
    let dd = (s.height / (s.depths.len() as f64).sqrt() * 1000.0).round().clamp(1.0, k as f64) as i64;
    (k, dd)
}

/// G76: two blocks per start (m = 01, no chamfer, 60°); later starts moved back along Z.
fn g76(o: &mut Out, s: &Spec) {
    let (k, dd) = increments(s);
    for n in 0..s.starts {
        let (_, za) = start(s, n);
        if n > 0 {
            o.line(format!("G00 {} {}", o.x(s.clear_x), o.z(za)));
        }
        o.line("G76 P010060 Q20 R0.02");
        let r = taper_word(o, s, za, s.z1);
        o.line(format!("G76 {} {}{r} P{k} Q{dd} F{}", o.x(s.x_at(s.height, s.z1)), o.z(s.z1), o.w.lead(s.lead)));
    }
}

/// G78: degressive, radial, 60°, no run-out (J0), one finishing pass, L starts.
fn g78(o: &mut Out, s: &Spec) {
    let (k, dd) = increments(s);
    let l = if s.starts > 1 { format!(" L{}", s.starts) } else { String::new() };
    o.line(format!("G78 P1060 Q20 R0.02 J0 D1{l}"));
    let r = taper_word(o, s, s.za, s.z1);
    o.line(format!("G78 {} {}{r} P{k} Q{dd} F{}", o.x(s.x_at(s.height, s.z1)), o.z(s.z1), o.w.lead(s.lead)));
}

/// LinuxCNC's G76 in diameter mode (I, J, K diameters): depth degression R2
/// (constant chip area), compound angle Q29.5, one spring pass.
fn linux_g76(o: &mut Out, s: &Spec, notes: &mut Vec<Remark>) -> Result<(), Remark> {
    if s.taper != 0.0 {
        return Err(Remark::new(&tools::WZ_LINUXCNC_TAPER, args![]));
    }
    let i = s.crest - s.clear_x;
    let j = 2.0 * s.height / (s.depths.len() as f64).sqrt();
    notes.push(Remark::new(&tools::WZ_LINUXCNC_G76, args![]));
    for n in 0..s.starts {
        let (_, za) = start(s, n);
        o.line(format!("G0 {} {}", o.x(s.clear_x), o.z(za)));
        o.line(format!(
            "G76 P{} {} I{} J{} K{} R2 Q29.5 H1",
            o.w.lead(s.lead),
            o.z(s.z1),
            o.len(i),
            o.len(j),
            o.len(2.0 * s.height)
        ));
        // The cycle ends on the drive line at the end Z: back out along Z.
        o.line(format!("G0 {}", o.z(s.za)));
    }
    Ok(())
}
