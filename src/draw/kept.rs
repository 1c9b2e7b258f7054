//! The fit kept between drawings of one view (and what was read of the
//! last scene's parts, [`Held`]). Fitting is most of a
//! drawing's cost (it places the labels several times to find the scale),
//! and while a pass is being typed the scene's focus and labels stay what
//! they were: the drawing keeps its transform (it does not move under the
//! typing either) and only the placement runs again. Any change to the
//! focus, a label (its text, place or thread), the page or the view's
//! options fits again.

use std::hash::{Hash, Hasher};

use super::held::Held;
use super::labels::{annotated, labelled_in};
use super::visit::PartPaint;
use super::{Read, Transform, View};
use crate::diagram::scene::{Item, Scene, Shape};
use crate::hash::KeyHasher;

/// The last fit of a view and the key of what it was made from; what was read of its last scene's parts.
#[derive(Default)]
pub struct FitMemo {
    last: Option<(u64, Transform)>,
    made: usize,
    /// What was read of the parts of the last scene.
    held: Held,
}

impl FitMemo {
    /// An empty memo: the next drawing fits.
    pub fn new() -> FitMemo {
        FitMemo::default()
    }

    /// The fit of `scene` in `view`: the last one when the scene's focus,
    /// its labels, the page and the view's options are those it was made for.
    pub fn fit(&mut self, scene: &Scene, view: &View) -> Transform {
        let read = self.read(scene);
        self.fit_with(scene, view, &read)
    }

    /// What a drawing reads of `scene` ([`Read`]), its parts shared with the last scene not read again.
    pub(super) fn read<'s>(&mut self, scene: &'s Scene) -> Read<'s> {
        self.held.update(scene);
        Read { lines: self.held.lines(scene), labelled: self.held.labelled(scene) }
    }

    /// The parts of `scene` (the last read) as the painter visits them.
    pub(super) fn visit<'a, 's: 'a>(&'a self, scene: &'s Scene) -> Vec<(usize, &'s [Item], &'a PartPaint)> {
        self.held.visit(scene)
    }

    /// [`FitMemo::fit`] with what was read of the scene given.
    pub(super) fn fit_with(&mut self, scene: &Scene, view: &View, read: &Read) -> Transform {
        let key = fit_key(scene, &read.labelled, view);
        if let Some((k, xf)) = self.last
            && k == key
        {
            return xf;
        }
        let xf = super::fit::fit(scene, view, view.page(), read);
        self.last = Some((key, xf));
        self.made += 1;
        xf
    }

    /// How many fits it has made (the others were kept).
    pub fn made(&self) -> usize {
        self.made
    }
}

/// What a fit depends on, hashed: the view kind, focus and page, the
/// options that choose and word the labels, and every item the labels drawn
/// come from (with many threads annotated, the chosen thread's and those of no thread).
fn fit_key(scene: &Scene, labelled: &[(usize, &Item)], view: &View) -> u64 {
    let mut h = KeyHasher::default();
    (scene.view as u8).hash(&mut h);
    let (w, hgt) = view.page();
    let f = scene.focus;
    for v in [f.x0, f.y0, f.x1, f.y1, w, hgt] {
        h.write_u64(v.to_bits());
    }
    h.write_u8(u8::from(view.stretch) | (u8::from(view.roughing) << 1));
    h.write_usize(view.thread);
    view.lang.hash(&mut h);
    let annotated = annotated(labelled);
    h.write_usize(annotated);
    for (_, item) in labelled.iter().filter(|(_, i)| labelled_in(i, annotated, view.thread)) {
        hash_label_item(&mut h, item);
    }
    h.finish()
}

fn hash_label_item(h: &mut KeyHasher, item: &Item) {
    (item.style as u8).hash(h);
    item.thread.hash(h);
    item.pass.hash(h);
    let pt = |h: &mut KeyHasher, p: [f64; 2]| p.iter().for_each(|v| h.write_u64(v.to_bits()));
    match &item.shape {
        Shape::Dim { a, b, offset, label } => {
            pt(h, *a);
            pt(h, *b);
            h.write_u64(offset.to_bits());
            label.key.hash(h);
            label.value.hash(h);
        }
        Shape::Text { at, label, anchor, dx, dy } => {
            pt(h, *at);
            (*anchor as u8).hash(h);
            h.write_u64(dx.to_bits());
            h.write_u64(dy.to_bits());
            label.key.hash(h);
            label.value.hash(h);
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::scene::{Label, Style};
    use crate::dialect::Dialect;
    use crate::settings::Settings;

    fn o1006() -> Scene {
        let plan = crate::plan(include_str!("../../examples/o1006.nc"), &Settings::new(Dialect::Gsk980tdc));
        crate::diagram::side::side(&plan)
    }

    #[test]
    fn a_scene_whose_focus_and_labels_stay_keeps_its_fit() {
        let view = View::default();
        let scene = o1006();
        let mut memo = FitMemo::new();
        let first = memo.fit(&scene, &view);
        assert_eq!(first, super::super::fit_of(&scene, &view), "the first drawing fits");
        // A pass moved inside the focus (a digit typed in its X): the drawing stays put.
        let mut typed = scene.clone();
        let cut = typed.items.iter_mut().find(|i| i.style == Style::Cut).expect("a cut");
        if let Shape::Polyline { points } = &mut cut.shape {
            let mut p = points.to_vec();
            p.iter_mut().for_each(|q| q[1] -= 0.01);
            *points = p.into();
        }
        assert_eq!(memo.fit(&typed, &view), first);
        assert_eq!(memo.made(), 1, "kept, not fitted again");
        // A label that changes (the minor diameter's value) fits again.
        let mut relabelled = typed.clone();
        let dim = relabelled.items.iter_mut().find(|i| matches!(i.shape, Shape::Dim { .. })).expect("a dimension");
        if let Shape::Dim { label, .. } = &mut dim.shape {
            *label = Label::new(label.key, "123456.789");
        }
        let refit = memo.fit(&relabelled, &view);
        assert_eq!(refit, super::super::fit_of(&relabelled, &view));
        assert_ne!(refit, first, "a wider label asks for another scale");
        assert_eq!(memo.made(), 2);
        // So does another page size.
        let narrow = View { width: 390.0, ..View::default() };
        assert_eq!(memo.fit(&relabelled, &narrow), super::super::fit_of(&relabelled, &narrow));
        assert_eq!(memo.made(), 3);
    }

    /// Eight threads of two passes each at 30 + 2k mm, each after turning its diameter.
    fn eight_threads() -> Scene {
        let mut text = String::from("G50 X100 Z100\nS300 M03\n");
        for k in 0..8 {
            let d = 30 + 2 * k;
            text += &format!("G00 X{} Z70\nG01 X{d} F0.2\nZ20\nX{}\nG00 Z70\n", d + 10, d + 5);
            for x in [0.9, 1.3] {
                text += &format!("X{:.1}\nG32 Z13 F2\nG00 X{}\nZ70\n", d as f64 - x, d + 10);
            }
        }
        let plan = crate::plan(&text, &Settings::new(Dialect::Gsk980tdc));
        assert_eq!(plan.threads.len(), 8);
        crate::diagram::side::side(&plan)
    }

    /// A dimension of thread `t` with another value.
    fn relabel(scene: &mut Scene, t: u32) {
        let dim = scene
            .items
            .iter_mut()
            .find(|i| i.thread == Some(t) && matches!(i.shape, Shape::Dim { .. }))
            .expect("a dimension of the thread");
        if let Shape::Dim { label, .. } = &mut dim.shape {
            *label = Label::new(label.key, "123456.789");
        }
    }

    #[test]
    fn with_many_threads_only_the_chosen_threads_labels_decide_the_fit() {
        // Above MAX_ANNOTATED threads only the chosen thread's labels are drawn, so only they fit.
        let scene = eight_threads();
        let view = View { thread: 2, ..View::default() };
        let mut memo = FitMemo::new();
        let first = memo.fit(&scene, &view);
        let mut other = scene.clone();
        relabel(&mut other, 5);
        assert_eq!(memo.fit(&other, &view), first);
        assert_eq!(memo.made(), 1, "another thread's label: kept");
        assert_eq!(first, super::super::fit_of(&other, &view), "and a fit from scratch agrees");
        let mut chosen = other.clone();
        relabel(&mut chosen, 2);
        assert_eq!(memo.fit(&chosen, &view), super::super::fit_of(&chosen, &view));
        assert_eq!(memo.made(), 2, "the chosen thread's label: fitted again");
        // Choosing another thread fits again.
        let view5 = View { thread: 5, ..view };
        assert_eq!(memo.fit(&chosen, &view5), super::super::fit_of(&chosen, &view5));
        assert_eq!(memo.made(), 3);
    }
}
