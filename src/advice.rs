//! Depths, crest and the textbook's advice for threads cut block by block.
//!
//! A G32/G33 program does not say how deep the thread is, only where each
//! pass runs. The crest (major diameter of an external thread, minor of an
//! internal one) is what a comment before the thread states (`(crest X68.)`,
//! as `expand` writes for a cycle's thread), else the part outline when the
//! program turned it, otherwise it is assumed from the deepest pass and the
//! 60° rule d = D − 1.3·P (setting `textbook.depth_factor`). Depths, infeeds, roles
//! and chip areas follow, and the advice of the textbook chapter: total
//! depth against 1.3·P, infeeds against table 4-3, and the δ1/δ2
//! acceleration clearances.

use crate::args;
use crate::diagnostic::Diagnostics;
use crate::geom::Frame;
use crate::message::{self as msg, Arg};
use crate::motion::{Move, MoveKind, Point};
use crate::num::EPS;
use crate::settings::{P, Settings};
use crate::span::Span;
use crate::thread::{Axis, CrestSource, Role, Source, Thread, v_area};

/// Table 4-3 of the textbook: usual diameter infeeds per pass by pitch (mm).
pub const TABLE_4_3: &[(f64, &[f64])] = &[
    (1.0, &[0.7, 0.4, 0.2]),
    (1.5, &[0.8, 0.6, 0.4, 0.16]),
    (2.0, &[0.9, 0.6, 0.6, 0.4, 0.1]),
    (2.5, &[1.0, 0.7, 0.6, 0.4, 0.4, 0.15]),
    (3.0, &[1.2, 0.7, 0.6, 0.4, 0.4, 0.4, 0.2]),
    (3.5, &[1.5, 0.7, 0.6, 0.6, 0.4, 0.4, 0.2, 0.15]),
    (4.0, &[1.5, 0.8, 0.6, 0.6, 0.4, 0.4, 0.4, 0.3, 0.2]),
];

/// Table 4-3's infeeds for `pitch` (mm), if the table lists it.
pub fn table_4_3(pitch: f64) -> Option<&'static [f64]> {
    TABLE_4_3.iter().find(|(p, _)| (p - pitch).abs() < 1e-6).map(|(_, v)| *v)
}

/// A straight outline piece (a turning feed move) in (long, short) terms.
struct Piece {
    idx: usize,
    from: Point,
    to: Point,
}

/// What the program says of a thread besides its moves: the crest a
/// comment before it states (in program units, X a diameter; Z for a face
/// thread), with the comment's line.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stated {
    /// The stated crest and its line.
    pub crest: Option<(f64, u32)>,
}

impl Stated {
    /// What the comments from the line after `lower` (the previous thread's
    /// last line) to `t`'s first line state about `t`.
    pub fn of(t: &Thread, lower: Option<u32>, text: &str, spans: &dyn Fn(u32) -> Span) -> Stated {
        let first = t.line.max(1);
        let stop = lower.map_or(1, |l| (l + 1).min(first));
        let axis = if t.long_axis == Axis::Z { b'X' } else { b'Z' };
        let crest = crate::comment::find_back(text, spans, stop, first, |line, c| {
            crate::comment::crest(c, axis).map(|v| (v, line))
        });
        Stated { crest }
    }
}

/// Fills depths, crest, roles and areas of the block-by-block threads and
/// adds the textbook advice, each in its thread's units. `spans` gives each
/// line's span for diagnostics.
pub fn finish_manual(
    threads: &mut [Thread],
    moves: &[Move],
    s: &Settings,
    text: &str,
    diags: &mut Diagnostics,
    spans: &dyn Fn(u32) -> Span,
) {
    for i in 0..threads.len() {
        let lower = i.checked_sub(1).map(|p| threads[p].end_line);
        let stated = Stated::of(&threads[i], lower, text, spans);
        finish_thread(threads, i, moves, s, stated, diags, spans);
    }
}

/// Finishes thread `i` of `threads` (see [`finish_manual`]), with what the
/// program `stated` about it. The outline a thread is cut on is turned
/// before it: only the moves since the previous thread are looked at, so
/// the work stays linear in the program and a thread's result depends on
/// nothing after its first motion.
pub fn finish_thread(
    threads: &mut [Thread],
    i: usize,
    moves: &[Move],
    s: &Settings,
    stated: Stated,
    diags: &mut Diagnostics,
    spans: &dyn Fn(u32) -> Span,
) {
    let window_start = if i == 0 { 0 } else { threads[i - 1].first_move };
    let t = &mut threads[i];
    let end = t.first_move.min(moves.len());
    let window = &moves[window_start.min(end)..end];
    if !matches!(t.source, Source::G32 | Source::Renhe | Source::G92 | Source::LinuxG33) {
        // A cycle's crest is its own; the surface the program turned for it is measured apart.
        t.turned = turned_by_program(t, window, s);
        return;
    }
    finish_one(t, window, s, stated, s.flag(P::Advice), diags, spans);
}

/// Depths, crest, roles and advice of one block-by-block thread; `moves` is the
/// window of motions before it where its turned outline may be.
fn finish_one(
    t: &mut Thread,
    moves: &[Move],
    s: &Settings,
    stated: Stated,
    advice: bool,
    diags: &mut Diagnostics,
    spans: &dyn Fn(u32) -> Span,
) {
    let long = t.long_axis;
    let dir = t.depth_dir;
    let h = s.get(P::DepthFactor) * t.pitch / 2.0; // radial thread depth
    let mm = t.units.mm();
    let deepest = deepest_pass(t).cloned().expect("a thread has passes");
    // A stated crest is the programmer's word: it comes before the outline.
    let said = stated.crest.map(|(c, _)| if long == Axis::Z { c / 2.0 } else { c });
    let outline = if said.is_some() { None } else { outline_crest(t, moves, &deepest, h) };
    let crest_at = |p: Point| -> f64 {
        let l = Frame(long).long(p);
        match (said, &outline) {
            (Some(c), _) => c,
            (None, Some(o)) => Frame(long).line_at(o.from, o.to, l),
            (None, None) => Frame(long).line_at(deepest.from, deepest.to, l) - dir * h,
        }
    };
    t.crest_source = match (said, &outline) {
        (Some(_), _) => CrestSource::Comment,
        (None, Some(_)) => CrestSource::Outline,
        (None, None) => CrestSource::Assumed,
    };
    let c0 = crest_at(t.passes[0].from);
    t.crest = match long {
        Axis::Z => 2.0 * c0,
        Axis::X => c0,
    };
    // Depths per start.
    let mut prev: Vec<f64> = vec![0.0; t.starts as usize];
    let mut max_depth = 0.0f64;
    for p in t.passes.iter_mut() {
        let d = (Frame(long).short(p.from) - crest_at(p.from)) * dir;
        let si = p.start as usize - 1;
        p.depth = d;
        p.infeed = d - prev[si];
        p.area = v_area(t.tool_angle, prev[si].max(0.0), d.max(0.0));
        prev[si] = d;
        max_depth = max_depth.max(d);
    }
    t.height = max_depth;
    // Roles: per start, the first pass at full depth finishes, later ones are spring passes.
    let mut finished = vec![false; t.starts as usize];
    for p in t.passes.iter_mut() {
        let si = p.start as usize - 1;
        if (p.depth - max_depth).abs() < 1e-6 {
            p.role = if finished[si] { Role::Spring } else { Role::Finish };
            finished[si] = true;
        } else {
            p.role = Role::Rough;
        }
    }
    if !advice {
        return;
    }
    let span = spans(t.line);
    let pitch_mm = t.pitch * mm;
    let std_depth = s.get(P::DepthFactor) * pitch_mm; // diameter, mm
    match &outline {
        None if said.is_some() => {}
        None => diags.push_with(&msg::CREST_ASSUMED, span, || {
            // A face thread's crest is a face (a Z), not a diameter.
            let (what, axis) = match (t.long_axis, t.internal) {
                (crate::thread::Axis::X, _) => (&msg::FACE_CREST, "Z"),
                (_, true) => (&msg::TURN_MINOR, "X"),
                (_, false) => (&msg::TURN_MAJOR, "X"),
            };
            args![what, axis = Arg::lit(axis), crest = t.crest, factor = s.get(P::DepthFactor)]
        }),
        Some(_) => {
            let programmed = 2.0 * max_depth * mm;
            if (programmed - std_depth).abs() > 0.02 * std_depth.max(0.05) {
                diags.push_with(&msg::DEPTH_VS_STANDARD, span, || {
                    let verdict = if programmed < std_depth { &msg::NOT_FULL_DEPTH } else { &msg::TOO_DEEP };
                    let factor = s.get(P::DepthFactor);
                    args![total = programmed / mm, factor, standard = std_depth / mm, pitch = t.pitch, verdict]
                });
            }
        }
    }
    if t.starts == 1 && long == Axis::Z {
        if let Some(table) = table_4_3(pitch_mm) {
            let infeeds: Vec<f64> = t.passes.iter().map(|p| 2.0 * p.infeed * mm).collect();
            let matches = infeeds.len() == table.len() && infeeds.iter().zip(table).all(|(a, b)| (a - b).abs() < 1e-3);
            diags.push_with(&msg::INFEED_GUIDANCE, span, || {
                let same = if matches { &msg::AS_THE_TABLE } else { &msg::NOTHING };
                args![
                    pitch = pitch_mm,
                    n = table.len(),
                    table = Arg::Nums(table.to_vec()),
                    count = infeeds.len(),
                    infeeds = Arg::Nums(infeeds),
                    same
                ]
            });
            let largest = table[0];
            // The first infeed is only known when the crest is (from the outline).
            let known = |p: &&crate::thread::Pass| p.index > 1 || outline.is_some();
            for p in t.passes.iter().filter(known) {
                let inf = 2.0 * p.infeed * mm;
                if inf > largest + 1e-3 {
                    diags.push_with(
                        &msg::INFEED_TOO_LARGE,
                        spans(p.lines.iter().copied().find(|l| *l >= t.line).unwrap_or(t.line)),
                        || args![n = p.index, infeed = inf, pitch = pitch_mm, largest],
                    );
                }
            }
        }
    }
    if let Some(o) = &outline {
        clearance(t, o, moves, &deepest, mm, diags, span);
    }
}

/// The deepest pass: furthest along the depth direction at its start.
fn deepest_pass(t: &Thread) -> Option<&crate::thread::Pass> {
    let (long, dir) = (t.long_axis, t.depth_dir);
    t.passes.iter().max_by(|a, b| (Frame(long).short(a.from) * dir).total_cmp(&(Frame(long).short(b.from) * dir)))
}

/// The lead-in δ1 and run-out δ2 of thread `i` (program units along its
/// long axis) measured against the work the program turned before it, as
/// the textbook's advice measures them; `None` when the program did not
/// turn the surface the thread is cut on.
pub fn measured_clearances(threads: &[Thread], i: usize, moves: &[Move], s: &Settings) -> Option<(f64, f64)> {
    let t = threads.get(i)?;
    let window_start = if i == 0 { 0 } else { threads[i - 1].first_move };
    let end = t.first_move.min(moves.len());
    let window = &moves[window_start.min(end)..end];
    let deepest = deepest_pass(t)?;
    let h = s.get(P::DepthFactor) * t.pitch / 2.0;
    let crest = outline_crest(t, window, deepest, h)?;
    Some(work_clearances(t, &crest, window, deepest))
}

/// The diameter (a face thread's Z) of the surface the program turned for
/// cycle thread `t` among `moves`, at its first pass, if it turned one.
fn turned_by_program(t: &Thread, moves: &[Move], s: &Settings) -> Option<f64> {
    let deepest = deepest_pass(t)?;
    let h = s.get(P::DepthFactor) * t.pitch / 2.0;
    let piece = outline_crest(t, moves, deepest, h)?;
    let long = t.long_axis;
    let c = Frame(long).line_at(piece.from, piece.to, Frame(long).long(t.passes[0].from));
    Some(if long == Axis::Z { 2.0 * c } else { c })
}

/// The turned surface a thread is cut on, when the program turned it.
fn outline_crest(t: &Thread, moves: &[Move], deepest: &crate::thread::Pass, h: f64) -> Option<Piece> {
    let long = t.long_axis;
    let dir = t.depth_dir;
    let p0 = &t.passes[0];
    let (lo, hi) = {
        let (a, b) = (Frame(long).long(p0.from), Frame(long).long(p0.to));
        if a <= b { (a, b) } else { (b, a) }
    };
    let mut best: Option<(f64, Piece)> = None;
    for (idx, m) in moves.iter().enumerate() {
        if m.kind != MoveKind::Feed {
            continue;
        }
        let (a, b) = (Frame(long).long(m.from), Frame(long).long(m.to));
        let (ma, mb) = if a <= b { (a, b) } else { (b, a) };
        // Must run along the thread (not a facing move) and overlap it.
        if mb - ma < EPS || mb.min(hi) - ma.max(lo) < EPS {
            continue;
        }
        let mid = (ma.max(lo) + mb.min(hi)) / 2.0;
        let v = Frame(long).line_at(m.from, m.to, mid);
        // The crest is the outermost surface against the depth direction.
        let score = -v * dir;
        if best.as_ref().is_none_or(|(s, _)| score > *s) {
            best = Some((score, Piece { idx, from: m.from, to: m.to }));
        }
    }
    let (_, piece) = best?;
    // Plausible only if the first pass is below it and the deepest within twice the standard depth.
    let c_first = Frame(long).line_at(piece.from, piece.to, Frame(long).long(p0.from));
    let d_first = (Frame(long).short(p0.from) - c_first) * dir;
    let c_deep = Frame(long).line_at(piece.from, piece.to, Frame(long).long(deepest.from));
    let d_deep = (Frame(long).short(deepest.from) - c_deep) * dir;
    if d_first < -EPS || d_deep > 2.0 * h + EPS {
        return None;
    }
    Some(piece)
}

/// δ1 (lead-in before the work) and δ2 (run-out after it), checked against the textbook.
fn clearance(
    t: &Thread,
    crest: &Piece,
    moves: &[Move],
    deepest: &crate::thread::Pass,
    mm: f64,
    diags: &mut Diagnostics,
    span: Span,
) {
    let (d1, d2) = work_clearances(t, crest, moves, deepest);
    if d1 * mm < 2.0 - 1e-9 {
        if d1 < 0.0 {
            diags.push_with(&msg::CLEARANCE_INSIDE, span, || args![d = -d1]);
        } else {
            diags.push_with(&msg::CLEARANCE_LEAD_IN, span, || args![d = d1]);
        }
    }
    if d2 > 0.0 && d1 > 0.0 && d2 < d1 / 4.0 - 1e-9 {
        diags.push_with(&msg::CLEARANCE_RUN_OUT, span, || args![d2, quarter = d1 / 4.0]);
    }
}

/// δ1 and δ2 of `t` against the turned surface `crest` (and the turning
/// moves contiguous with it that the thread passes through).
fn work_clearances(t: &Thread, crest: &Piece, moves: &[Move], deepest: &crate::thread::Pass) -> (f64, f64) {
    let long = t.long_axis;
    let dir = t.depth_dir;
    let deep = |p: Point| Frame(long).short(p) * dir;
    let above = |m: &Move| (deep(m.from) <= deep(deepest.from) + EPS) && (deep(m.to) <= deep(deepest.from) + EPS);
    // Extend the crest piece through contiguous turning moves the thread passes through.
    let (mut first, mut last) = (crest.idx, crest.idx);
    while first > 0
        && moves[first - 1].kind == MoveKind::Feed
        && moves[first - 1].to == moves[first].from
        && above(&moves[first - 1])
    {
        first -= 1;
    }
    while last + 1 < moves.len()
        && moves[last + 1].kind == MoveKind::Feed
        && moves[last + 1].from == moves[last].to
        && above(&moves[last + 1])
    {
        last += 1;
    }
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for m in &moves[first..=last] {
        for p in [m.from, m.to] {
            lo = lo.min(Frame(long).long(p));
            hi = hi.max(Frame(long).long(p));
        }
    }
    let p0 = &t.passes[0];
    let (a, b) = (Frame(long).long(p0.from), Frame(long).long(p0.to));
    let toward_minus = b < a;
    if toward_minus { (a - hi, lo - b) } else { (lo - a, b - hi) }
}
