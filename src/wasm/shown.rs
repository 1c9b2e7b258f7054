//! What a view shows — the one place of the "last good drawing" policy.
//!
//! Each plan's scenes are current. A plan that draws something and has no
//! alarm is the candidate; the page says when the user left it (it was on
//! screen a while before the next edit), and it becomes the good drawing.
//! While the text has an alarm, the good drawing is shown greyed (stale)
//! instead of the current scenes; another program (`fresh`) forgets it.

use std::rc::Rc;

use super::keys::{combine, js_key};
use crate::diagram::scene::{Item, Scene};

/// The three views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    /// The side section.
    Side = 0,
    /// The tooth section.
    Tooth = 1,
    /// The starts.
    Starts = 2,
}

impl Which {
    /// `side`, `tooth` or `starts`.
    pub fn parse(name: &str) -> Option<Which> {
        match name {
            "side" => Some(Which::Side),
            "tooth" => Some(Which::Tooth),
            "starts" => Some(Which::Starts),
            _ => None,
        }
    }
}

/// One plan's scenes with their content keys.
#[derive(Clone, Default)]
pub struct Scenes {
    /// Which plan they are of (the session counts its plans).
    pub plan: u64,
    /// The scenes, by [`Which`].
    pub scenes: [Option<Rc<Scene>>; 3],
    /// Their keys (0: none).
    pub keys: [f64; 3],
}

/// The scenes of the current plan, the candidate and the good drawing.
#[derive(Default)]
pub struct Shown {
    current: Scenes,
    candidate: Option<Scenes>,
    good: Option<Scenes>,
    stale: bool,
    /// Another program's passes laid over the side and tooth sections, with its number.
    overlay: Option<(u64, Rc<[Vec<Item>; 2]>)>,
    /// The side and tooth scenes shown with the overlay.
    merged: [Option<Rc<Scene>>; 2],
    /// Scenes no longer shown, freed by [`Shown::tidy`] after the drawing
    /// is on screen (freeing a long program's scene is milliseconds of
    /// work the keystroke need not wait for), else when the next plan arrives.
    retired: Vec<Scenes>,
}

impl Shown {
    /// A plan's scenes arrive. `drawable`: it draws something and has no
    /// alarm; `alarm`: it has one; `fresh`: the text is another program's;
    /// `keep`: the page says the drawing on screen before this edit was left.
    pub fn planned(&mut self, scenes: Scenes, drawable: bool, alarm: bool, fresh: bool, keep: bool) {
        // The scenes retired by the plan before, unless tidied since: at most one plan's wait.
        self.retired.clear();
        if fresh {
            self.retired.extend(self.good.take());
        }
        if keep {
            if let Some(c) = self.candidate.take() {
                self.retired.extend(self.good.replace(c));
            }
        }
        self.retired.extend(self.candidate.take());
        self.retired.push(std::mem::replace(&mut self.current, scenes));
        self.stale = alarm && self.good.is_some();
        if !self.stale && drawable {
            self.candidate = Some(self.current.clone());
        }
        self.merge();
    }

    /// Frees the scenes no longer shown.
    pub fn tidy(&mut self) {
        self.retired.clear();
    }

    /// Lays another program's passes (`items` of its side and tooth sections, numbered `id`) over the drawings; none: takes them off.
    pub fn set_overlay(&mut self, overlay: Option<(u64, [Vec<Item>; 2])>) {
        self.overlay = overlay.map(|(id, items)| (id, Rc::new(items)));
        self.merge();
    }

    /// Whether another program's passes are laid over the drawings.
    pub fn overlaid(&self) -> bool {
        self.overlay.is_some()
    }

    /// The side and tooth scenes with the overlay, when there is one.
    fn merge(&mut self) {
        self.merged = [None, None];
        let Some((_, over)) = self.overlay.clone() else { return };
        for k in 0..2 {
            if let Some(s) = self.showing().scenes[k].as_deref() {
                self.merged[k] = Some(Rc::new(crate::diagram::overlay::merged(s, &over[k])));
            }
        }
    }

    /// Another thread or start: the tooth and starts scenes of the current plan.
    pub fn select(&mut self, tooth: Option<Rc<Scene>>, starts: Option<Rc<Scene>>, keys: [f64; 2]) {
        self.current.scenes[1] = tooth;
        self.current.scenes[2] = starts;
        self.current.keys[1] = keys[0];
        self.current.keys[2] = keys[1];
        self.merge();
    }

    /// Whether the good drawing is shown greyed.
    pub fn stale(&self) -> bool {
        self.stale
    }

    /// The plan of the good drawing, if one is kept (the page keeps that plan's lists to show with it).
    pub fn good_plan(&self) -> Option<u64> {
        self.good.as_ref().map(|g| g.plan)
    }

    fn showing(&self) -> &Scenes {
        match (&self.good, self.stale) {
            (Some(g), true) => g,
            _ => &self.current,
        }
    }

    /// The scene view `w` shows, if any (with the overlay laid on it).
    pub fn scene(&self, w: Which) -> Option<&Scene> {
        let k = w as usize;
        match self.merged.get(k).and_then(Option::as_deref) {
            Some(m) => Some(m),
            None => self.showing().scenes[k].as_deref(),
        }
    }

    /// The keys of the scenes shown (a view redraws when its key or the stale flag changes).
    pub fn keys(&self) -> [f64; 3] {
        let mut keys = self.showing().keys;
        if let Some((id, _)) = &self.overlay {
            for (k, key) in keys.iter_mut().take(2).enumerate() {
                if self.merged[k].is_some() {
                    *key = js_key(combine(&[key.to_bits(), *id]));
                }
            }
        }
        keys
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::scene::ViewKind;

    fn scenes(key: f64) -> Scenes {
        let s = Rc::new(Scene::new(ViewKind::Side));
        Scenes { plan: key as u64, scenes: [Some(s), None, None], keys: [key, 0.0, 0.0] }
    }

    #[test]
    fn the_good_drawing_is_the_one_the_user_left() {
        let mut s = Shown::default();
        s.planned(scenes(1.0), true, false, true, false);
        assert_eq!((s.keys()[0], s.stale()), (1.0, false));
        // An alarm before the page said the drawing was left: nothing to grey, the current plan shows.
        s.planned(scenes(2.0), false, true, false, false);
        assert_eq!((s.keys()[0], s.stale()), (2.0, false));
        // Fixed: a candidate again; left; then an alarm shows it greyed.
        s.planned(scenes(3.0), true, false, false, false);
        s.planned(scenes(4.0), false, true, false, true);
        assert_eq!((s.keys()[0], s.stale(), s.good_plan()), (3.0, true, Some(3)));
        // Still an alarm: still the good drawing, greyed.
        s.planned(scenes(5.0), false, true, false, false);
        assert_eq!((s.keys()[0], s.stale()), (3.0, true));
        // Another program: forgotten.
        s.planned(scenes(6.0), false, true, true, false);
        assert_eq!((s.keys()[0], s.stale(), s.good_plan()), (6.0, false, None));
        assert!(s.scene(Which::Tooth).is_none());
    }

    #[test]
    fn scenes_no_longer_shown_are_freed_by_tidy_or_the_next_plan() {
        let mut s = Shown::default();
        let first = scenes(1.0);
        let weak = Rc::downgrade(first.scenes[0].as_ref().expect("a side scene"));
        s.planned(first, true, false, true, false);
        s.planned(scenes(2.0), true, false, false, false);
        // Kept past the plan that replaced it, freed by tidy.
        assert!(weak.upgrade().is_some());
        s.tidy();
        assert!(weak.upgrade().is_none());
        // Without tidy, the next plan frees it.
        let third = scenes(3.0);
        let weak = Rc::downgrade(third.scenes[0].as_ref().expect("a side scene"));
        s.planned(third, true, false, false, false);
        s.planned(scenes(4.0), true, false, false, false);
        assert!(weak.upgrade().is_some());
        s.planned(scenes(5.0), true, false, false, false);
        assert!(weak.upgrade().is_none());
        // The good drawing is kept while it is shown.
        s.planned(scenes(6.0), false, true, false, true);
        s.tidy();
        assert_eq!((s.keys()[0], s.stale()), (5.0, true));
    }
}
