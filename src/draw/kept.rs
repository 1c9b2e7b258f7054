//! The fit kept between drawings of one view. Fitting is most of a
//! drawing's cost (it places the labels several times to find the scale),
//! and while a pass is being typed the scene's focus and labels stay what
//! they were: the drawing keeps its transform (it does not move under the
//! typing either) and only the placement runs again. Any change to the
//! focus, a label (its text, place or thread), the page or the view's
//! options fits again.

use std::hash::{Hash, Hasher};

use super::{Transform, View};
use crate::diagram::scene::{Item, Scene, Shape};
use crate::hash::KeyHasher;

/// The last fit of a view and the key of what it was made from.
#[derive(Clone, Copy, Debug, Default)]
pub struct FitMemo {
    last: Option<(u64, Transform)>,
    made: usize,
}

impl FitMemo {
    /// An empty memo: the next drawing fits.
    pub fn new() -> FitMemo {
        FitMemo::default()
    }

    /// The fit of `scene` in `view`: the last one when the scene's focus,
    /// its labels, the page and the view's options are those it was made for.
    pub fn fit(&mut self, scene: &Scene, view: &View) -> Transform {
        let key = fit_key(scene, view);
        if let Some((k, xf)) = self.last
            && k == key
        {
            return xf;
        }
        let xf = super::fit_of(scene, view);
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
/// options that choose and word the labels, and every labelled item.
fn fit_key(scene: &Scene, view: &View) -> u64 {
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
    for item in scene.items.iter().filter(|i| labelled(i)) {
        hash_label_item(&mut h, item);
    }
    h.finish()
}

fn labelled(item: &Item) -> bool {
    matches!(item.shape, Shape::Dim { .. } | Shape::Text { .. })
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
}
