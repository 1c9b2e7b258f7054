//! The readable summary `screwcut plan` prints: the plan's counts, each
//! thread with its pass table and shop-floor lines, and the diagnostics, in
//! English or Chinese (the words from the message catalogue).

use std::fmt::Write;

use screwcut::Plan;
use screwcut::args;
use screwcut::diagnostic::Severity;
use screwcut::message::{Arg, Args, Lang, Phrase, words as w};
use screwcut::num::fmt;
use screwcut::thread::{Role, Source, Thread, ThreadKind};

/// A number, or `missing` when unknown.
fn opt(v: Option<f64>, missing: &'static str) -> Arg {
    v.map_or(Arg::lit(missing), Arg::Num)
}

/// Right-aligns `s` in `width` columns (a CJK character takes two).
fn pad(s: &str, width: usize) -> String {
    let cols: usize = s.chars().map(|c| if c >= '\u{1100}' { 2 } else { 1 }).sum();
    format!("{}{s}", " ".repeat(width.saturating_sub(cols)))
}

/// The summary of `plan` read from `file`, in `lang`.
pub fn summary(plan: &Plan, file: &str, lang: Lang) -> String {
    let say = |p: &Phrase, a: Args| p.render(&a, lang);
    let mut out = String::new();
    let count = |s: Severity| plan.diagnostics.iter().filter(|d| d.severity == s).count();
    let units = units_word(plan.units);
    let time = plan.time_s.map_or(String::new(), |t| say(&w::THREADING_TIME, args![t]));
    let a = args![
        file,
        dialect = plan.dialect.name(),
        units,
        threads = plan.threads.len(),
        moves = plan.moves.len(),
        alarms = count(Severity::Error),
        warnings = count(Severity::Warning),
        notes = count(Severity::Info),
        time
    ];
    let _ = writeln!(out, "{}", say(&w::SUMMARY, a));
    for (i, t) in plan.threads.iter().enumerate() {
        thread(&mut out, i, t, lang);
    }
    if !plan.diagnostics.is_empty() {
        let _ = writeln!(out, "\n{}", w::DIAGNOSTICS_HEADING.text(lang));
        for d in &plan.diagnostics {
            let _ = write!(
                out,
                "  {}:{}: {} [{}] {}",
                d.line,
                d.column,
                d.severity.word().text(lang),
                d.code,
                d.render(lang)
            );
            if !d.via.is_empty() {
                let lines: Vec<String> = d.via.iter().map(u32::to_string).collect();
                let (from, after) = (w::CALLED_FROM.text(lang), w::CALLED_FROM_AFTER.text(lang));
                let _ = write!(out, " ({from} {}{after})", lines.join(" ← "));
            }
            if d.repeats > 1 {
                let _ = write!(out, " ({})", say(&w::RAISED_TIMES, args![n = d.repeats]));
            }
            out.push('\n');
        }
    }
    out
}

/// The word for `units`.
fn units_word(units: screwcut::plan::Units) -> &'static Phrase {
    match units {
        screwcut::plan::Units::Mm => &w::UNITS_MM,
        screwcut::plan::Units::Inch => &w::UNITS_INCH,
    }
}

/// One thread, in its own units: its line, the pass table and the shop-floor lines.
fn thread(out: &mut String, i: usize, t: &Thread, lang: Lang) {
    let kind = match t.kind {
        ThreadKind::Straight => &w::STRAIGHT,
        ThreadKind::Taper => &w::TAPER,
        ThreadKind::Face => &w::FACE,
    };
    let source = match t.source {
        Source::G32 => "G32",
        Source::Renhe => "Renhe G32/G33",
        Source::G78 => "G78",
        Source::G92 => "G92",
        Source::G76 => "G76",
        Source::LinuxG33 => "LinuxCNC G33",
        Source::LinuxG76 => "LinuxCNC G76",
    };
    let crest_source = match t.crest_source {
        screwcut::thread::CrestSource::Cycle => &w::CREST_CYCLE,
        screwcut::thread::CrestSource::Outline => &w::CREST_OUTLINE,
        screwcut::thread::CrestSource::Assumed => &w::CREST_ASSUMED_WORD,
        screwcut::thread::CrestSource::Comment => &w::CREST_COMMENT,
    };
    let a = args![
        i = i + 1,
        from = t.line,
        to = t.end_line,
        kind,
        source = Arg::lit(source),
        units = units_word(t.units),
        lead = t.lead,
        pitch = t.pitch,
        starts = if t.starts == 1 { &w::ONE_START } else { &w::STARTS },
        n = t.starts,
        side = if t.internal { &w::INTERNAL_THREAD } else { &w::EXTERNAL_THREAD },
        axis = Arg::lit(if t.long_axis == screwcut::thread::Axis::Z { "X" } else { "Z" }),
        crest = t.crest,
        crest_source,
        height = t.height
    ];
    let _ = writeln!(out, "\n{}", w::THREAD_LINE.render(&a, lang));
    let widths = [5, 4, 10, 10, 10, 10, 8, 8, 7, 8, 8, 7];
    let heads = [
        &w::COL_START,
        &w::COL_PASS,
        &w::COL_X_FROM,
        &w::COL_Z_FROM,
        &w::COL_X_TO,
        &w::COL_Z_TO,
        &w::COL_DEPTH,
        &w::COL_INFEED,
        &w::COL_ROLE,
        &w::COL_AREA,
        &w::COL_EVEN,
        &w::COL_TIME,
    ];
    let cells: Vec<String> = heads.iter().zip(widths).map(|(h, n)| pad(h.text(lang), n)).collect();
    let _ = writeln!(out, "  {}  {}", cells.join(" "), w::COL_LINES.text(lang));
    for (k, p) in t.passes.iter().enumerate() {
        let lines = p.lines.iter().map(|l| l.to_string()).collect::<Vec<_>>().join(",");
        let chip = t.shop.chip.get(k);
        let o = |v: Option<f64>| v.map_or_else(|| "-".to_string(), fmt);
        let role = match p.role {
            Role::Rough => &w::ROUGH,
            Role::Finish => &w::FINISH,
            Role::Spring => &w::SPRING,
        };
        let row = [
            p.start.to_string(),
            p.index.to_string(),
            fmt(p.from.x),
            fmt(p.from.z),
            fmt(p.to.x),
            fmt(p.to.z),
            fmt(p.depth),
            fmt(p.infeed),
            role.text(lang).to_string(),
            o(chip.and_then(|c| c.area)),
            o(chip.and_then(|c| c.even_area)),
            o(t.shop.pass_time_s.get(k).copied()),
        ];
        let cells: Vec<String> = row.iter().zip(widths).map(|(c, n)| pad(c, n)).collect();
        let _ = writeln!(out, "  {}  {lines}", cells.join(" "));
    }
    shop_section(out, t, lang);
}

/// The shop-floor lines of one thread: time, speed, clearances, helix angle, the thread check.
fn shop_section(out: &mut String, t: &Thread, lang: Lang) {
    let s = &t.shop;
    let line = |out: &mut String, p: &Phrase, a: Args| {
        let _ = writeln!(out, "  {}", p.render(&a, lang));
    };
    match (s.cut_time_s, s.time_s, s.rpm) {
        (Some(cut), Some(total), Some(n)) => {
            let u = Arg::lit(if t.units.is_inch() { "in" } else { "mm" });
            let a = args![cut, total, n, feed = opt(s.thread_feed, "?"), u, limit = opt(s.rpm_limit, "?")];
            line(out, &w::TIME_LINE, a);
        }
        _ => line(out, &w::TIME_UNKNOWN, args![]),
    }
    if let (Some(n1), Some(n2)) = (s.lead_in_needed, s.run_out_needed) {
        let source = match s.clearance_source {
            Some(screwcut::shop::ClearanceSource::Outline) => &w::MEASURED,
            Some(screwcut::shop::ClearanceSource::Assumed) => &w::ASSUMED,
            None => &w::NOT_KNOWN,
        };
        let a = args![d1 = opt(s.lead_in, "?"), source, n1, d2 = opt(s.run_out, "?"), n2];
        line(out, &w::SPEED_LINE, a);
    }
    if let (Some(h), Some(d2)) = (s.helix_angle_deg, s.pitch_diameter) {
        line(out, &w::HELIX_LINE, args![h, d2]);
    }
    if let Some(g) = &s.gauge {
        gauge_lines(out, g, lang);
    }
}

/// The thread check of one thread: verdict, numbers, the fix and the notes.
fn gauge_lines(out: &mut String, g: &screwcut::shop::Gauge, lang: Lang) {
    let line = |out: &mut String, indent: &str, p: &Phrase, a: Args| {
        let _ = writeln!(out, "{indent}{}", p.render(&a, lang));
    };
    let from = match g.line {
        Some(l) => Arg::Text(w::FROM_COMMENT.render(&args![l], lang).into()),
        None => Arg::Phrase(&w::FROM_SETTING),
    };
    let verdict = if g.ok { &w::GAUGES } else { &w::WILL_NOT_GAUGE };
    line(out, "  ", &w::CHECK_LINE, args![designation = g.designation.as_str(), from, verdict]);
    if let Some(taper) = g.taper {
        line(out, "    ", &w::NPT_LINE, args![d2 = g.pitch_diameter, taper, z = opt(g.gauge_plane_z, "?")]);
    } else {
        let a = args![
            d2 = g.pitch_diameter,
            d2_min = opt(g.pitch_diameter_min, "?"),
            d2_max = opt(g.pitch_diameter_max, "?"),
            major = opt(g.major_diameter, "?"),
            major_min = opt(g.major_diameter_min, "?"),
            major_max = opt(g.major_diameter_max, "?"),
            minor = opt(g.minor_diameter, "?"),
            minor_min = opt(g.minor_diameter_min, "?"),
            minor_max = opt(g.minor_diameter_max, "?")
        ];
        line(out, "    ", &w::DIAMETERS_LINE, a);
    }
    if let Some(dx) = g.delta_x {
        line(out, "    ", &w::FIX_LINE, args![dx]);
    }
    if let Some(o) = g.over_wires {
        let a = args![w = o.wire, m = o.m, min = opt(o.m_min, "?"), max = opt(o.m_max, "?")];
        line(out, "    ", &w::WIRES_LINE, a);
    }
    for n in &g.notes {
        line(out, "    ", &w::NOTE_LINE, args![note = n.render(lang)]);
    }
}
