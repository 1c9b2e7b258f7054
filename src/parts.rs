//! A list held as parts that lists may share: the items of a scene. A
//! side section put together again after a keystroke from the pieces that
//! did not change takes those pieces whole (a reference each) instead of
//! copying their items, and freeing it frees no item still kept.
//!
//! A part shared with another list is copied only when it is changed
//! (`iter_mut`, `get_mut`, `with_vec`): what one scene does to its items
//! never shows in another.

use std::fmt;
use std::sync::Arc;

use serde::Serialize;

/// A list of `T` in shared parts (see the module documentation).
#[derive(Clone)]
pub struct Parts<T> {
    parts: Vec<Arc<Vec<T>>>,
    /// The number of items up to and including each part.
    ends: Vec<usize>,
}

impl<T: Clone> Parts<T> {
    /// No items.
    pub fn new() -> Parts<T> {
        Parts { parts: Vec::new(), ends: Vec::new() }
    }

    /// How many items there are.
    pub fn len(&self) -> usize {
        self.ends.last().copied().unwrap_or(0)
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The items in order.
    pub fn iter(&self) -> impl DoubleEndedIterator<Item = &T> + Clone {
        self.parts.iter().flat_map(|p| p.iter())
    }

    /// The items in order, to change (a part shared with another list is copied first).
    pub fn iter_mut(&mut self) -> impl Iterator<Item = &mut T> {
        self.parts.iter_mut().flat_map(|p| Arc::make_mut(p).iter_mut())
    }

    /// The parts in order, each with the index of its first item.
    pub fn parts(&self) -> impl Iterator<Item = (usize, &Arc<Vec<T>>)> {
        std::iter::once(0).chain(self.ends.iter().copied()).zip(self.parts.iter())
    }

    /// Item `i`.
    pub fn get(&self, i: usize) -> Option<&T> {
        let k = self.ends.partition_point(|&e| e <= i);
        let start = if k == 0 { 0 } else { self.ends[k - 1] };
        self.parts.get(k).and_then(|p| p.get(i - start))
    }

    /// Item `i`, to change (its part is copied first when shared).
    pub fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        let k = self.ends.partition_point(|&e| e <= i);
        let start = if k == 0 { 0 } else { self.ends[k - 1] };
        self.parts.get_mut(k).and_then(|p| Arc::make_mut(p).get_mut(i - start))
    }

    /// The first item.
    pub fn first(&self) -> Option<&T> {
        self.iter().next()
    }

    /// Adds an item at the end.
    pub fn push(&mut self, item: T) {
        match self.parts.last_mut().and_then(Arc::get_mut) {
            Some(last) => {
                last.push(item);
                *self.ends.last_mut().expect("a part has its end") += 1;
            }
            None => {
                self.parts.push(Arc::new(vec![item]));
                self.ends.push(self.len() + 1);
            }
        }
    }

    /// Adds the items of `part` at the end, sharing them (no item is copied).
    pub fn push_shared(&mut self, part: Arc<Vec<T>>) {
        if !part.is_empty() {
            self.ends.push(self.len() + part.len());
            self.parts.push(part);
        }
    }

    /// Room for `n` more items pushed one by one.
    pub fn reserve(&mut self, n: usize) {
        match self.parts.last_mut().and_then(Arc::get_mut) {
            Some(last) => last.reserve(n),
            None => {
                self.parts.push(Arc::new(Vec::with_capacity(n)));
                self.ends.push(self.len());
            }
        }
    }

    /// Changes the items as one vector of this list's own with `f`, in
    /// any way (shared parts are copied into it first).
    pub fn with_vec<R>(&mut self, f: impl FnOnce(&mut Vec<T>) -> R) -> R {
        if self.parts.len() != 1 {
            let all: Vec<T> = self.iter().cloned().collect();
            self.parts = vec![Arc::new(all)];
        }
        let out = f(Arc::make_mut(&mut self.parts[0]));
        self.ends = vec![self.parts[0].len()];
        out
    }

    /// Takes the items out as one vector (copying only shared parts).
    pub fn into_vec(self) -> Vec<T> {
        let len = self.len();
        match <[Arc<Vec<T>>; 1]>::try_from(self.parts) {
            Ok([one]) => Arc::unwrap_or_clone(one),
            Err(parts) => {
                let mut out = Vec::with_capacity(len);
                for p in parts {
                    match Arc::try_unwrap(p) {
                        Ok(own) => out.extend(own),
                        Err(shared) => out.extend(shared.iter().cloned()),
                    }
                }
                out
            }
        }
    }
}

impl<T: Clone> std::ops::Index<usize> for Parts<T> {
    type Output = T;

    fn index(&self, i: usize) -> &T {
        self.get(i).unwrap_or_else(|| panic!("item {i} of {}", self.len()))
    }
}

impl<T: Clone> std::ops::IndexMut<usize> for Parts<T> {
    fn index_mut(&mut self, i: usize) -> &mut T {
        let n = self.len();
        self.get_mut(i).unwrap_or_else(|| panic!("item {i} of {n}"))
    }
}

impl<T: Clone> From<Vec<T>> for Parts<T> {
    fn from(items: Vec<T>) -> Parts<T> {
        let mut out = Parts::new();
        out.push_shared(Arc::new(items));
        // Owned by this list alone: later pushes go into it.
        out
    }
}

impl<T: Clone> FromIterator<T> for Parts<T> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Parts<T> {
        Parts::from(iter.into_iter().collect::<Vec<T>>())
    }
}

impl<T: Clone> Extend<T> for Parts<T> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, iter: I) {
        iter.into_iter().for_each(|i| self.push(i));
    }
}

impl<'a, T: Clone> IntoIterator for &'a Parts<T> {
    type Item = &'a T;
    type IntoIter = Box<dyn Iterator<Item = &'a T> + 'a>;

    fn into_iter(self) -> Self::IntoIter {
        Box::new(self.iter())
    }
}

impl<T: Clone + PartialEq> PartialEq for Parts<T> {
    fn eq(&self, other: &Parts<T>) -> bool {
        self.len() == other.len() && self.iter().eq(other.iter())
    }
}

impl<T: Clone + fmt::Debug> fmt::Debug for Parts<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<T: Clone + Serialize> Serialize for Parts<T> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter())
    }
}

impl<T> Default for Parts<T> {
    fn default() -> Parts<T> {
        Parts { parts: Vec::new(), ends: Vec::new() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shared_parts_read_as_one_list_and_change_only_in_their_own_list() {
        let kept = Arc::new(vec![1, 2]);
        let mut a = Parts::new();
        a.push(0);
        a.push_shared(kept.clone());
        a.push(3);
        a.push_shared(Arc::new(Vec::new()));
        a.reserve(4);
        assert_eq!((a.len(), a.iter().copied().collect::<Vec<_>>()), (4, vec![0, 1, 2, 3]));
        assert_eq!((0..5).map(|i| a.get(i).copied()).collect::<Vec<_>>(), [Some(0), Some(1), Some(2), Some(3), None]);
        assert_eq!(a[2], 2);
        // The kept part is not copied, and a change to this list's items does not reach it.
        assert!(Arc::ptr_eq(&a.parts[1], &kept));
        a.iter_mut().for_each(|x| *x += 10);
        a[0] = 9;
        assert_eq!(a.iter().copied().collect::<Vec<_>>(), [9, 11, 12, 13]);
        assert_eq!(*kept, [1, 2]);
        // As one vector: an insertion anywhere; then pushed to.
        a.with_vec(|v| v.insert(1, 5));
        a.extend([7]);
        assert_eq!((a.len(), a.iter().copied().collect::<Vec<_>>()), (6, vec![9, 5, 11, 12, 13, 7]));
        assert_eq!(a, Parts::from(a.clone().into_vec()));
        assert_eq!(format!("{a:?}"), "[9, 5, 11, 12, 13, 7]");
        assert_eq!(Parts::<i32>::new().first(), None);
        // Out as one vector from parts owned and shared: the shared one is copied, not taken.
        let mut b = Parts::new();
        b.push(7);
        b.push_shared(kept.clone());
        b.push(8);
        assert_eq!(b.into_vec(), [7, 1, 2, 8]);
        assert_eq!((kept.as_slice(), Arc::strong_count(&kept)), (&[1, 2][..], 1));
    }
}
