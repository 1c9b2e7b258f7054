//! The side section: the X–Z plane, upper half, +Z right, radius up. It
//! shows the part outline (the program's turning moves, or each thread's
//! crest line when the program turns none), every pass as its own path
//! (rapids dashed, cut solid, run-out and screw-in marked), the threaded
//! band between crest and root, the lead-in and run-out zones δ1/δ2 where
//! the work is known, and dimensions of the major and minor diameters, the
//! lead, the pitch of multi-start threads, the threaded length and the taper.

use std::ops::Range;

use crate::motion::{Move, MoveKind, Point};
use crate::plan::Plan;
use crate::thread::{Axis, CrestSource, Pass, Thread};

pub use super::band::{Band, FeedIndex, deltas, work_extent, work_extent_in};
use super::detail::{Detail, side_detail};
use super::scene::{Anchor, Glyph, Item, Label, Pt, Rect, Scene, Shape, Style, ViewKind, num};

/// Most motions drawn; a larger plan is drawn up to here, with a note.
pub const MAX_MOVES_DRAWN: usize = 250_000;

/// World point of a program point: `[Z, radius]`.
pub fn world(p: Point) -> Pt {
    [p.z, p.x / 2.0]
}

fn line(a: Pt, b: Pt) -> Shape {
    Shape::Polyline { points: vec![a, b].into() }
}

pub use crate::motion::arc_points;

/// The motions of one pass, as ranges of `plan.moves` (each pass carries
/// them: [`crate::thread::PassMoves`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PassPath {
    /// Index of the thread in `plan.threads`.
    pub thread: usize,
    /// Index of the pass in the thread's `passes`.
    pub pass: usize,
    /// Rapids before the cut.
    pub lead_in: Range<usize>,
    /// Screw-in, thread segments and run-out.
    pub cut: Range<usize>,
    /// Rapids after the cut.
    pub tail: Range<usize>,
}

impl PassPath {
    /// The motion indices of the pass, approach to return.
    pub fn indices(&self) -> impl Iterator<Item = usize> + '_ {
        self.lead_in.clone().chain(self.cut.clone()).chain(self.tail.clone())
    }

    /// One past the pass's last motion.
    pub fn end(&self) -> usize {
        self.tail.end.max(self.cut.end)
    }
}

/// The passes whose cut is among the plan's motions, in cutting order.
/// (A plan cut short by the move limit may have passes without motions:
/// those are drawn from their own points.)
pub fn pass_paths(plan: &Plan) -> Vec<PassPath> {
    let mut found: Vec<PassPath> = Vec::new();
    for (thread, t) in plan.threads.iter().enumerate() {
        for (pass, p) in t.passes.iter().enumerate() {
            let m = &p.moves;
            if !m.cut.is_empty() && m.retract.end <= plan.moves.len() {
                found.push(PassPath {
                    thread,
                    pass,
                    lead_in: m.approach.clone(),
                    cut: m.cut.clone(),
                    tail: m.retract.clone(),
                });
            }
        }
    }
    crate::order::sort_by_key(&mut found, |p| p.cut.start); // each pass its own motions
    found
}

/// What the side section is drawn from besides the plan: the motions of each
/// pass, which motions are drawn and which belong to a pass, and the feed index.
pub struct Layout {
    /// The passes' motions, by cut start.
    pub paths: Vec<PassPath>,
    /// Motions of no pass are drawn from `moves[..drawn]` (at most
    /// [`MAX_MOVES_DRAWN`] of them); passes are drawn whatever their index.
    pub drawn: usize,
    /// Per motion: whether it belongs to a pass.
    pub owner: Vec<bool>,
    /// Whether the plan has threads (then the outline is not the focus).
    pub has_threads: bool,
    /// The feed motions by radius.
    pub feeds: FeedIndex,
    /// What is drawn of each thread's passes (level of detail).
    pub details: Vec<Detail>,
    /// Per motion: a rapid of a roughing cycle (drawn with its cuts, on demand).
    pub roughing: Vec<bool>,
}

impl Layout {
    /// The layout of `plan`'s side section.
    pub fn of(plan: &Plan) -> Layout {
        let details: Vec<Detail> = plan.threads.iter().map(side_detail).collect();
        let all = pass_paths(plan);
        let mut owner = vec![false; plan.moves.len()];
        // Every pass owns its motions, drawn or left out by the level of detail.
        for p in &all {
            for k in p.indices() {
                if let Some(o) = owner.get_mut(k) {
                    *o = true;
                }
            }
        }
        let paths = all.into_iter().filter(|p| details[p.thread].drawn[p.pass]).collect();
        // The motions of no pass are drawn up to the MAX_MOVES_DRAWN-th of them.
        let mut others = 0;
        let drawn = owner
            .iter()
            .position(|o| {
                others += usize::from(!o);
                others > MAX_MOVES_DRAWN
            })
            .unwrap_or(plan.moves.len());
        Layout {
            paths,
            drawn,
            owner,
            has_threads: !plan.threads.is_empty(),
            feeds: FeedIndex::new(&plan.moves),
            details,
            roughing: roughing_rapids(&plan.moves),
        }
    }

    /// The passes drawn from their own points (their motions are not among the drawn ones):
    /// `(thread, pass)` in plan order.
    pub fn unmatched(&self, plan: &Plan) -> Vec<(usize, usize)> {
        let base: Vec<usize> = plan
            .threads
            .iter()
            .scan(0, |acc, t| {
                let b = *acc;
                *acc += t.passes.len();
                Some(b)
            })
            .collect();
        let mut found = vec![false; base.last().map_or(0, |b| b + plan.threads.last().map_or(0, |t| t.passes.len()))];
        for p in &self.paths {
            found[base[p.thread] + p.pass] = true;
        }
        let mut out = Vec::new();
        for (ti, t) in plan.threads.iter().enumerate() {
            let shown = &self.details[ti].drawn;
            out.extend((0..t.passes.len()).filter(|pi| shown[*pi] && !found[base[ti] + pi]).map(|pi| (ti, pi)));
        }
        out
    }
}

/// Per motion: whether it is a rapid of a roughing cycle — in a run of
/// motions of one block that holds a roughing cut.
pub fn roughing_rapids(moves: &[Move]) -> Vec<bool> {
    let mut out = vec![false; moves.len()];
    // One pass: each run of motions of one line, marked when it ends.
    let (mut start, mut rough) = (0, false);
    for k in 0..=moves.len() {
        if k == moves.len() || moves[k].line != moves[start].line {
            if rough {
                for (o, m) in out[start..k].iter_mut().zip(&moves[start..k]) {
                    *o = m.kind == MoveKind::Rapid;
                }
            }
            if k == moves.len() {
                break;
            }
            (start, rough) = (k, false);
        }
        rough |= moves[k].kind == MoveKind::Rough;
    }
    out
}

/// The item of a motion that belongs to no pass, and whether it is in the focus.
pub fn motion_item(m: &Move, has_threads: bool, roughing: bool) -> (Item, bool) {
    let (shape, style, focus) = match m.kind {
        MoveKind::Rapid if roughing => (line(world(m.from), world(m.to)), Style::Roughing, false),
        MoveKind::Rapid => (line(world(m.from), world(m.to)), Style::OtherRapid, false),
        MoveKind::Feed => (line(world(m.from), world(m.to)), Style::Outline, !has_threads),
        MoveKind::Rough if m.arc.is_some() => {
            (Shape::Polyline { points: arc_points(m).into() }, Style::Roughing, !has_threads)
        }
        MoveKind::Rough => (line(world(m.from), world(m.to)), Style::Roughing, !has_threads),
        MoveKind::Arc => (Shape::Polyline { points: arc_points(m).into() }, Style::Outline, !has_threads),
        MoveKind::Thread | MoveKind::ScrewIn => (line(world(m.from), world(m.to)), Style::Cut, true),
        MoveKind::Runout => (line(world(m.from), world(m.to)), Style::Runout, true),
    };
    (Item::new(shape, style).lines([m.line]), focus)
}

/// The note that the motions of no pass are drawn only up to `moves[..drawn]`
/// (the first [`MAX_MOVES_DRAWN`] of them).
pub fn capped_note(plan: &Plan, drawn: usize) -> Option<Item> {
    let last = plan.moves.get(drawn.checked_sub(1)?)?;
    (drawn < plan.moves.len()).then(|| {
        Item::new(
            Shape::Text {
                at: world(last.to),
                label: Label::new("moves_capped", MAX_MOVES_DRAWN.to_string()),
                anchor: Anchor::Start,
                dx: 6.0,
                dy: 6.0,
            },
            Style::Note,
        )
    })
}

/// The item of a pass drawn from its own points.
pub fn unmatched_item(plan: &Plan, ti: usize, pi: usize) -> Item {
    let p = &plan.threads[ti].passes[pi];
    Item::new(Shape::Polyline { points: pass_points(p).into() }, Style::Cut)
        .lines(p.drawn_lines())
        .of(ti, Some(pi))
        .role(p.role)
}

/// Grows `focus` by the points of the passes' rapids that stay near it (within
/// a quarter of its larger side), so the first fit shows the approach too.
pub fn grow_focus(focus: &mut Rect, rapid_points: impl IntoIterator<Item = Pt>) {
    let Some(near) = near_focus(focus) else { return };
    for p in rapid_points {
        if near.contains(p) {
            focus.add(p);
        }
    }
}

/// [`grow_focus`] by groups of points given with their bounds: a group
/// wholly near the focus adds its bounds, one wholly away adds nothing, and
/// only the others are read point by point (the same focus, fewer points read).
pub fn grow_focus_grouped<'a>(focus: &mut Rect, groups: impl IntoIterator<Item = (Rect, &'a [Pt])>) {
    let Some(near) = near_focus(focus) else { return };
    for (b, points) in groups {
        if b.is_empty() || b.x1 < near.x0 || b.x0 > near.x1 || b.y1 < near.y0 || b.y0 > near.y1 {
            continue;
        }
        if near.contains([b.x0, b.y0]) && near.contains([b.x1, b.y1]) {
            focus.union(&b);
        } else {
            points.iter().filter(|p| near.contains(**p)).for_each(|p| focus.add(*p));
        }
    }
}

/// What counts as near the focus (a rapid's points join it, a label
/// widens the fit): within a quarter of its larger side (none for an empty focus).
pub fn near_focus(focus: &Rect) -> Option<Rect> {
    if focus.is_empty() {
        return None;
    }
    let grow = 0.25 * focus.width().max(focus.height());
    Some(Rect { x0: focus.x0 - grow, y0: focus.y0 - grow, x1: focus.x1 + grow, y1: focus.y1 + grow })
}

/// The spindle axis across `bounds` (with a margin), and `bounds` grown by it.
pub fn axis(bounds: &mut Rect) -> Shape {
    let b = bounds.or_unit();
    let margin = 0.05 * b.width().max(1.0);
    bounds.add([b.x0 - margin, 0.0]);
    bounds.add([b.x1 + margin, 0.0]);
    line([b.x0 - margin, 0.0], [b.x1 + margin, 0.0])
}

/// Builds the side section of a plan.
pub fn side(plan: &Plan) -> Scene {
    let mut scene = Scene::new(ViewKind::Side);
    let layout = Layout::of(plan);
    let drawn = layout.drawn;
    let passes: usize = plan.threads.iter().map(|t| t.passes.len()).sum();
    scene.items.reserve(drawn + 2 * passes + 12 * plan.threads.len() + 2);
    // The spindle axis goes first, behind the rest; its ends are set at the end.
    scene.items.push(Item::new(line([0.0, 0.0], [0.0, 0.0]), Style::Axis));
    let mut back: Vec<(Item, bool)> = Vec::new();
    let mut front: Vec<(Item, bool)> = Vec::new();
    for (ti, t) in plan.threads.iter().enumerate() {
        thread_items(plan, &layout.feeds, ti, t, &mut back, &mut front);
        front.extend(detail_note(ti, t, &layout.details[ti]).map(|i| (i, false)));
    }
    for (item, focus) in back {
        scene.push(item, focus);
    }
    // Motions of no pass: the part outline and other tool paths.
    for (k, m) in plan.moves[..drawn].iter().enumerate() {
        if !layout.owner[k] {
            let (item, focus) = motion_item(m, layout.has_threads, layout.roughing[k]);
            scene.push(item, focus);
        }
    }
    if let Some(note) = capped_note(plan, drawn) {
        front.push((note, false));
    }
    for p in &layout.paths {
        pass_items(plan, p, &mut scene);
    }
    for (ti, pi) in layout.unmatched(plan) {
        scene.push(unmatched_item(plan, ti, pi), true);
    }
    for (item, focus) in front {
        scene.push(item, focus);
    }
    let mut rapids = Vec::new();
    for item in scene.items.iter().filter(|i| i.style == Style::Rapid && i.pass.is_some()) {
        item.each_point(|p| rapids.push(p));
    }
    grow_focus(&mut scene.focus, rapids);
    // The spindle axis across everything, behind the rest.
    scene.items[0].shape = axis(&mut scene.bounds);
    super::section::apply(&mut scene, plan);
    super::radial::apply(&mut scene, plan);
    scene.finish();
    scene
}

/// The points of a pass's cut from its own data (screw-in, segments, run-out).
fn pass_points(p: &Pass) -> Vec<Pt> {
    let mut pts = Vec::new();
    if let Some(s) = p.screw_in_from {
        pts.push(world(s));
    }
    if p.segments.is_empty() {
        pts.push(world(p.from));
        pts.push(world(p.to));
    } else {
        pts.extend(p.segments.iter().map(|s| world(*s)));
    }
    if let Some(r) = p.runout_to {
        pts.push(world(r));
    }
    pts
}

/// The items of one matched pass: its rapids, cut, run-out and screw-in.
pub fn pass_items(plan: &Plan, p: &PassPath, out: &mut Scene) {
    let pass = &plan.threads[p.thread].passes[p.pass];
    for k in p.indices() {
        let m = &plan.moves[k];
        let style = match m.kind {
            MoveKind::Rapid => Style::Rapid,
            MoveKind::ScrewIn => Style::ScrewIn,
            MoveKind::Runout => Style::Runout,
            _ => Style::Cut,
        };
        let shape = if m.kind == MoveKind::Arc {
            Shape::Polyline { points: arc_points(m).into() }
        } else {
            line(world(m.from), world(m.to))
        };
        let item = Item::new(shape, style).lines([m.line]).of(p.thread, Some(p.pass)).role(pass.role);
        out.push(item, style != Style::Rapid);
    }
    let mark = |at: Point| Item::new(Shape::Marker { at: world(at), glyph: Glyph::Bar }, Style::Runout);
    if pass.runout_to.is_some() {
        out.push(mark(pass.to).lines(pass.drawn_lines()).of(p.thread, Some(p.pass)), true);
    }
    if pass.screw_in_from.is_some() {
        let item = Item { style: Style::ScrewIn, ..mark(pass.from) };
        out.push(item.lines(pass.drawn_lines()).of(p.thread, Some(p.pass)), true);
    }
}

/// A note on what the level of detail leaves out of thread `ti`'s drawing, if anything.
pub fn detail_note(ti: usize, t: &Thread, d: &Detail) -> Option<Item> {
    if !d.summarised() {
        return None;
    }
    let band = Band::of(t)?;
    let mut parts = Vec::new();
    if d.merged_starts > 1 {
        parts.push(format!("1/{}", d.merged_starts));
    }
    if d.every > 1 {
        parts.push(format!("{}/{}", d.every, d.per_start));
    }
    let key = match (d.merged_starts > 1, d.every > 1) {
        (true, true) => "detail_starts_passes",
        (true, false) => "detail_starts",
        _ => "detail_passes",
    };
    let label = Label::new(key, parts.join(" "));
    let at = band.pt(band.l1, band.root(band.l1));
    let dy = if band.dir < 0.0 { -14.0 } else { 14.0 };
    Some(
        Item::new(Shape::Text { at, label, anchor: Anchor::End, dx: 0.0, dy }, Style::Note)
            .lines([t.line])
            .of(ti, None),
    )
}

/// The band, crest and root lines, δ zones and dimensions of one thread:
/// `back` goes behind the motions, `front` (dimensions, texts) over them.
pub fn thread_items(
    plan: &Plan,
    feeds: &FeedIndex,
    ti: usize,
    t: &Thread,
    back: &mut Vec<(Item, bool)>,
    front: &mut Vec<(Item, bool)>,
) {
    let Some(band) = Band::of(t) else { return };
    if let Some(sh) = &t.shop.shoulder {
        front.extend(shoulder_items(ti, t, sh).into_iter().map(|i| (i, true)));
    }
    let lines: Vec<u32> = vec![t.line];
    let own = |shape: Shape, style: Style| Item::new(shape, style).lines(lines.clone()).of(ti, None);
    let (lo, hi) = (band.lo, band.hi);
    let zone = vec![
        band.pt(lo, band.crest(lo)),
        band.pt(hi, band.crest(hi)),
        band.pt(hi, band.root(hi)),
        band.pt(lo, band.root(lo)),
    ];
    back.push((own(Shape::Polygon { points: zone.into() }, Style::ThreadZone), true));
    if t.crest_source != CrestSource::Outline {
        back.push((own(line(band.pt(lo, band.crest(lo)), band.pt(hi, band.crest(hi))), Style::Crest), true));
    }
    back.push((own(line(band.pt(lo, band.root(lo)), band.pt(hi, band.root(hi))), Style::Root), true));
    // δ1 before the work, δ2 after it.
    if let Some(work) = work_extent_in(t, &band, &plan.moves, feeds) {
        let (d1, d2) = deltas(&band, work);
        let s = band.sense();
        let zones = [
            (band.l0, band.l0 + s * d1, d1, Style::Delta1, "delta1"),
            (band.l1 - s * d2, band.l1, d2, Style::Delta2, "delta2"),
        ];
        for (a, b, d, style, key) in zones {
            if d <= 1e-9 {
                continue;
            }
            let top = |l: f64| band.crest(l) - band.dir * 0.25 * band.height.max(1e-3);
            let bottom = |l: f64| band.root(l);
            let poly = vec![band.pt(a, bottom(a)), band.pt(b, bottom(b)), band.pt(b, top(b)), band.pt(a, top(a))];
            back.push((own(Shape::Polygon { points: poly.into() }, style), true));
            let mid = (a + b) / 2.0;
            let up = if band.dir < 0.0 { 1.0 } else { -1.0 };
            let label = Label::new(key, num(d));
            front.push((
                own(
                    Shape::Text { at: band.pt(mid, top(mid)), label, anchor: Anchor::Middle, dx: 0.0, dy: 10.0 * up },
                    style,
                ),
                true,
            ));
        }
    }
    // Dimensions, on the side of the crest away from the material.
    let s = band.sense();
    let away = -band.dir; // +1: above the crest in the drawing (external thread)
    if band.long == Axis::Z {
        let (major_r, minor_r) = {
            let (c, r) = (band.crest(band.l1), band.root(band.l1));
            if t.internal { (r, c) } else { (c, r) }
        };
        // Diameters at the cut's end, beyond it: half dimensions from the axis.
        for (r, key, off) in [(minor_r, "dia_minor", 18.0), (major_r, "dia_major", 36.0)] {
            let shape = Shape::Dim {
                a: [band.l1, 0.0],
                b: [band.l1, r],
                offset: -s * off,
                label: Label::new(key, num(2.0 * r)),
            };
            front.push((own(shape, Style::Diameter), false));
        }
    } else {
        let outer = band.l0.max(band.l1);
        let shape = Shape::Dim {
            a: band.pt(outer, band.crest(outer)),
            b: band.pt(outer, band.root(outer)),
            offset: 22.0,
            label: Label::new("height", num(band.height)),
        };
        front.push((own(shape, Style::Dimension), false));
    }
    let along = |l: f64, off: f64, key: &'static str, len: f64| {
        let (a, b) = (band.pt(band.l0, band.crest(band.l0)), band.pt(l, band.crest(l)));
        // Walking from a to b, is the left side the positive short-axis side?
        let left_is_plus = match band.long {
            Axis::Z => s > 0.0,
            Axis::X => s < 0.0,
        };
        let offset = if left_is_plus == (away > 0.0) { off } else { -off };
        Shape::Dim { a, b, offset, label: Label::new(key, num(len)) }
    };
    if t.lead > 0.0 && t.lead.is_finite() {
        front.push((own(along(band.l0 + s * t.lead, 18.0, "lead", t.lead), Style::Dimension), true));
        if t.starts > 1 {
            front.push((own(along(band.l0 + s * t.pitch, 34.0, "pitch", t.pitch), Style::Dimension), true));
        }
    }
    let length = (band.l1 - band.l0).abs();
    front.push((own(along(band.l1, 50.0, "length", length), Style::Dimension), false));
    if t.taper.abs() > 1e-9 && band.long == Axis::Z && length > 0.0 {
        let mid = (band.l0 + band.l1) / 2.0;
        let half_angle = (t.taper.abs() / length).atan().to_degrees();
        let label = Label::new("taper", format!("i={} α/2={}°", num(t.taper), num(half_angle)));
        let at = band.pt(mid, band.crest(mid));
        front.push((
            own(Shape::Text { at, label, anchor: Anchor::Middle, dx: 0.0, dy: 64.0 * away }, Style::Dimension),
            false,
        ));
    }
}

/// The tool at the pass that comes nearest a shoulder: its outline (tip and
/// flanks up to the shoulder's edge) and, where it cuts into the shoulder,
/// the face it cuts in red with the depth; else how far it clears it.
fn shoulder_items(ti: usize, t: &Thread, sh: &crate::figures::Shoulder) -> Vec<Item> {
    let p0 = &t.passes[0];
    let sense = (p0.to.z - p0.from.z).signum();
    let out: f64 = if t.internal { -1.0 } else { 1.0 };
    let tan = (t.tool_angle / 2.0).to_radians().tan();
    let (tz, tr, edge) = (sh.tip[1], sh.tip[0] / 2.0, sh.edge_x / 2.0);
    let reach = ((edge - tr) * tan).abs();
    let lines: Vec<u32> = t.passes.get(sh.pass).map(|p| p.drawn_lines().collect()).unwrap_or_default();
    let own = |shape: Shape, style: Style| Item::new(shape, style).lines(lines.clone()).of(ti, Some(sh.pass));
    let tool = vec![[tz + sense * reach, edge], [tz, tr], [tz - sense * reach, edge]];
    let mut out_items = vec![own(Shape::Polyline { points: tool.into() }, Style::Tool)];
    let label = if sh.clearance < 0.0 {
        let ahead = ((sh.z - tz) * sense).max(0.0);
        let cross = tr + out * ahead / tan;
        out_items.push(own(line([sh.z, cross], [sh.z, edge]), Style::Collision));
        Label::new("shoulder_into", num(-sh.clearance))
    } else {
        Label::new("shoulder_clear", num(sh.clearance))
    };
    let style = if sh.clearance < 0.0 { Style::Collision } else { Style::Note };
    let text = Shape::Text { at: [sh.z, edge], label, anchor: Anchor::Middle, dx: 0.0, dy: 14.0 * out };
    out_items.push(own(text, style));
    out_items
}
