//! The views' side of a session: each view asks for its display list
//! ([`crate::draw`]) at its size, transform and mark, for the item under
//! the pointer, and for its SVG. The scenes are the session's ([`super::shown`]).

use js_sys::{Array, Float64Array, Object, Uint32Array};
use wasm_bindgen::prelude::*;

use super::compared::{comparison_js, overlay_items};
use super::js::{err, set, to_js};
use super::session::Session;
use super::shown::Which;
use crate::diagram::scene::{Anchor, Scene, Shape};
use crate::draw::pick::LineRanges;
use crate::draw::{self, DisplayList, FONT_FAMILY, FONT_SIZE, Mark, Op, Transform, View};

#[wasm_bindgen]
impl Session {
    /// View `view`'s display list at `width × height` CSS px: with transform
    /// `xf` (`[sx, sy, tx, ty]`; omitted: fitted, and the fit is in the answer),
    /// the radial `stretch` of a fit, and the mark — pass `mark_pass` of
    /// thread `mark_thread` (both ≥ 0), else the items of `mark_lines` (`light`:
    /// the cursor line's lighter mark). Null when the view has nothing to show.
    ///
    /// `{width, height, transform: [sx, sy, tx, ty], stale, font, pens: [{stroke,
    /// width, dash, fill, alpha}], ops: Uint32Array (7 per operation: kind 0
    /// paths [0, pen, closed, first number, numbers, first span, spans], 1
    /// circle [1, pen, 0, first number (x, y, r)], 2 text [2, pen, anchor (0
    /// start, 1 middle, 2 end), first number (x, y, angle), 3, halo pen, text
    /// index]), nums: Float64Array, spans: Uint32Array (subpath starts, as
    /// indices of numbers), texts, labels (as placed), dropped (labels left out), anchor (where a
    /// zoom without a pointer centres)}`.
    #[allow(clippy::too_many_arguments)] // the JavaScript call's positional arguments
    pub fn draw(
        &self,
        view: &str,
        width: f64,
        height: f64,
        xf: Option<Vec<f64>>,
        stretch: bool,
        mark_thread: i32,
        mark_pass: i32,
        mark_lines: Vec<u32>,
        light: bool,
    ) -> Result<JsValue, JsValue> {
        let which = which(view)?;
        let (lang, roughing) = (self.lang(), self.roughing());
        self.with_state_mut(|st| {
            let Some(scene) = st.shown.scene(which) else { return Ok(JsValue::NULL) };
            let ranges = &mut st.line_ranges[which as usize];
            let mark = mark_of(scene, ranges, mark_thread, mark_pass, &mark_lines, light);
            let v = View {
                width,
                height,
                stretch,
                thread: st.thread,
                lang,
                transform: transform(xf.as_deref())?,
                stale: st.shown.stale(),
                mark,
                roughing,
            };
            v.validate().map_err(err)?;
            list_to_js(&draw::display_kept(scene, &v, &mut st.fits[which as usize]))
        })
    }

    /// The item of view `view` under page point (`x`, `y`) at transform `xf`:
    /// `{thread, pass, lines, style}` (−1: none), or null (nothing there, or a stale drawing).
    pub fn pick(&self, view: &str, xf: Vec<f64>, x: f64, y: f64) -> Result<JsValue, JsValue> {
        let which = which(view)?;
        let xf = transform(Some(&xf))?.ok_or_else(|| err("a transform is needed"))?;
        self.with_state(|st| {
            let Some(scene) = st.shown.scene(which).filter(|_| !st.shown.stale()) else { return Ok(JsValue::NULL) };
            let Some(i) = draw::pick::pick(scene, &xf, [x, y]) else { return Ok(JsValue::NULL) };
            let item = &scene.items[i];
            let o = Object::new();
            set(&o, "thread", &item.thread.map_or(-1, |t| t as i32).into());
            set(&o, "pass", &item.pass.map_or(-1, |p| p as i32).into());
            set(&o, "lines", &item.lines.iter().map(|&l| JsValue::from(l)).collect::<Array>().into());
            set(&o, "style", &JsValue::from_str(item.style.name()));
            Ok(o.into())
        })
    }

    /// Where the first item of style `style` (`cut`, `rapid`, …) of view
    /// `view` is drawn at transform `xf`: the page point of the middle of its
    /// first segment, or null (for tests that point at a drawing).
    pub fn locate(&self, view: &str, style: &str, xf: Vec<f64>) -> Result<Option<Vec<f64>>, JsValue> {
        let which = which(view)?;
        let xf = transform(Some(&xf))?.ok_or_else(|| err("a transform is needed"))?;
        self.with_state(|st| {
            let Some(scene) = st.shown.scene(which) else { return Ok(None) };
            let Some(item) = scene.items.iter().find(|i| i.style.name() == style) else { return Ok(None) };
            let mut pts = Vec::new();
            item.each_point(|p| pts.push(p));
            let (a, b) = (pts[0], *pts.get(1).unwrap_or(&pts[0]));
            Ok(Some(xf.at([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]).to_vec()))
        })
    }

    /// The items of style `style` (`*`: every item) of the scene view `view`
    /// shows, in world coordinates: `[{style, thread, pass (−1: none), lines,
    /// points: [z, r, z, r…], key (a label's key, else empty)}]` (for tests
    /// that check what a view draws).
    pub fn items_of_style(&self, view: &str, style: &str) -> Result<JsValue, JsValue> {
        let which = which(view)?;
        self.with_state(|st| {
            let out = Array::new();
            let Some(scene) = st.shown.scene(which) else { return Ok(out.into()) };
            for item in scene.items.iter().filter(|i| style == "*" || i.style.name() == style) {
                let o = Object::new();
                let key = match &item.shape {
                    Shape::Dim { label, .. } | Shape::Text { label, .. } => label.key,
                    _ => "",
                };
                set(&o, "style", &JsValue::from_str(item.style.name()));
                set(&o, "key", &JsValue::from_str(key));
                let mut pts = Vec::new();
                item.each_point(|p| pts.extend(p));
                set(&o, "thread", &item.thread.map_or(-1, |t| t as i32).into());
                set(&o, "pass", &item.pass.map_or(-1, |p| p as i32).into());
                set(&o, "lines", &item.lines.iter().map(|&l| JsValue::from(l)).collect::<Array>().into());
                set(&o, "points", &Float64Array::from(&pts[..]).into());
                out.push(&o);
            }
            Ok(out.into())
        })
    }

    /// Compares the last plan with program `text` (`dialect_name`, settings
    /// lines `settings`) pass by pass ([`crate::compare`]) and lays its passes
    /// over the side and tooth sections (until [`Session::compare_off`]; each
    /// later plan is compared again and answers with its `comparison`):
    /// `{comparison: {same, threads, passes, differences: [{thread, pass,
    /// start, what, a, b}]}, shown, stale}`.
    pub fn compare(&self, text: &str, dialect_name: &str, settings: &str) -> Result<JsValue, JsValue> {
        let d = super::js::dialect(dialect_name)?;
        let (s, _) = super::js::settings_from(d, settings);
        let b = crate::plan(text, &s);
        self.with_state_mut(|st| {
            let a = st.planner.last().ok_or_else(|| err("nothing planned yet"))?;
            let c = crate::compare::compare(a, &b);
            let id = st.compare.as_ref().map_or(1, |(_, id)| id + 1);
            st.shown.set_overlay(Some((id, overlay_items(&b, st.thread))));
            st.compare = Some((b, id));
            let o = Object::new();
            set(&o, "comparison", &comparison_js(&c));
            set(&o, "shown", &Float64Array::from(&st.shown.keys()[..]).into());
            set(&o, "stale", &st.shown.stale().into());
            Ok(o.into())
        })
    }

    /// Takes the compared program's passes off the drawings: `{shown, stale}`.
    pub fn compare_off(&self) -> Result<JsValue, JsValue> {
        self.with_state_mut(|st| {
            st.compare = None;
            st.shown.set_overlay(None);
            let o = Object::new();
            set(&o, "shown", &Float64Array::from(&st.shown.keys()[..]).into());
            set(&o, "stale", &st.shown.stale().into());
            Ok(o.into())
        })
    }

    /// View `view` as the SVG document of what it shows (the same display
    /// list as [`Session::draw`] without the mark): at `width × height` px,
    /// transform `xf` (omitted: fitted, with `stretch`). The same as
    /// `screwcut svg` of the program at that size and transform.
    pub fn svg(
        &self,
        view: &str,
        width: f64,
        height: f64,
        xf: Option<Vec<f64>>,
        stretch: bool,
    ) -> Result<String, JsValue> {
        let which = which(view)?;
        let (lang, roughing) = (self.lang(), self.roughing());
        self.with_state(|st| {
            let scene = st.shown.scene(which).ok_or_else(|| err(format!("the {view} view shows nothing")))?;
            let v = View {
                width,
                height,
                stretch,
                thread: st.thread,
                lang,
                transform: transform(xf.as_deref())?,
                stale: st.shown.stale(),
                mark: Mark::default(),
                roughing,
            };
            v.validate().map_err(err)?;
            Ok(crate::svg::svg(scene, &v))
        })
    }
}

fn which(view: &str) -> Result<Which, JsValue> {
    Which::parse(view).ok_or_else(|| err(format!("unknown view '{view}': side, tooth or starts")))
}

/// A transform from `[sx, sy, tx, ty]`; none for no numbers.
fn transform(xf: Option<&[f64]>) -> Result<Option<Transform>, JsValue> {
    match xf {
        None | Some([]) => Ok(None),
        Some(&[sx, sy, tx, ty]) => {
            let t = Transform { sx, sy, tx, ty };
            if t.is_valid() {
                Ok(Some(t))
            } else {
                Err(err(format!("the transform {xf:?} needs finite numbers and positive scales")))
            }
        }
        Some(v) => Err(err(format!("a transform is [sx, sy, tx, ty], not {} numbers", v.len()))),
    }
}

/// The items a mark names: a pass, else source lines (at most 64).
fn mark_of(scene: &Scene, ranges: &mut LineRanges, thread: i32, pass: i32, lines: &[u32], light: bool) -> Mark {
    let items = if thread >= 0 && pass >= 0 {
        draw::pick::items_of_pass(scene, thread as u32, pass as u32)
    } else {
        ranges.items_of_lines(scene, &lines[..lines.len().min(64)])
    };
    Mark { items, light }
}

/// A display list as typed arrays (see [`Session::draw`]).
fn list_to_js(list: &DisplayList) -> Result<JsValue, JsValue> {
    let (mut ops, mut nums, mut spans) = (Vec::new(), Vec::new(), Vec::new());
    let texts = Array::new();
    for op in &list.ops {
        let n = nums.len() as u32;
        match op {
            Op::Paths { pen, closed, points, starts } => {
                let first_span = spans.len() as u32;
                spans.extend(starts.iter().map(|&s| n + 2 * s as u32));
                nums.extend(points.iter().flatten());
                ops.extend([
                    0,
                    *pen as u32,
                    u32::from(*closed),
                    n,
                    2 * points.len() as u32,
                    first_span,
                    starts.len() as u32,
                ]);
            }
            Op::Circle { pen, center, r } => {
                nums.extend([center[0], center[1], *r]);
                ops.extend([1, *pen as u32, 0, n, 3, 0, 0]);
            }
            Op::Text { pen, halo, at, text, anchor, angle } => {
                nums.extend([at[0], at[1], *angle]);
                let a = match anchor {
                    Anchor::Start => 0,
                    Anchor::Middle => 1,
                    Anchor::End => 2,
                };
                ops.extend([2, *pen as u32, a, n, 3, *halo as u32, texts.length()]);
                texts.push(&JsValue::from_str(text));
            }
        }
    }
    let o = Object::new();
    let t = list.transform;
    set(&o, "width", &list.width.into());
    set(&o, "height", &list.height.into());
    set(&o, "transform", &Float64Array::from(&[t.sx, t.sy, t.tx, t.ty][..]).into());
    set(&o, "stale", &list.stale.into());
    set(&o, "font", &JsValue::from_str(&format!("{FONT_SIZE}px {FONT_FAMILY}")));
    set(&o, "pens", &to_js(&list.pens)?);
    set(&o, "ops", &Uint32Array::from(&ops[..]).into());
    set(&o, "nums", &Float64Array::from(&nums[..]).into());
    set(&o, "spans", &Uint32Array::from(&spans[..]).into());
    set(&o, "texts", &texts.into());
    set(&o, "labels", &to_js(&list.labels)?);
    set(&o, "dropped", &(list.dropped.len() as u32).into());
    set(&o, "anchor", &Float64Array::from(&list.anchor[..]).into());
    Ok(o.into())
}
