//! One sort for the whole core. The standard library's sort is generic over
//! the element and the comparison, so each call site put its own copy of
//! it (quicksort, small-sort networks, heapsort) in the wasm: 94 functions,
//! 125 KB of code for 24 sites. Here every sort orders indices with one
//! comparison type ([`order`]) and then moves the elements ([`permute`]),
//! so the wasm carries the sort once.

use std::cmp::Ordering;

/// The indices `0..n` ordered by `cmp`; equal ones keep their order (the
/// sort is stable).
pub fn order(n: usize, cmp: &mut dyn FnMut(usize, usize) -> Ordering) -> Vec<u32> {
    let mut idx: Vec<u32> = (0..n as u32).collect();
    idx.sort_unstable_by(|&a, &b| cmp(a as usize, b as usize).then(a.cmp(&b)));
    idx
}

/// Puts `v[perm[i]]` at `i` for every `i`, in place (`perm` a permutation
/// of `0..v.len()`).
pub fn permute<T>(v: &mut [T], perm: &[u32]) {
    let mut done = vec![false; v.len()];
    for start in 0..v.len() {
        let mut i = start;
        while !done[i] {
            done[i] = true;
            let k = perm[i] as usize;
            if k == start {
                break;
            }
            v.swap(i, k);
            i = k;
        }
    }
}

/// Sorts `v` by `cmp`, stably.
pub fn sort_by<T>(v: &mut [T], mut cmp: impl FnMut(&T, &T) -> Ordering) {
    // Many lists come in order already (passes, lines, labels): one look then.
    if v.windows(2).all(|w| cmp(&w[0], &w[1]) != Ordering::Greater) {
        return;
    }
    let perm = order(v.len(), &mut |a, b| cmp(&v[a], &v[b]));
    permute(v, &perm);
}

/// Sorts `v` by the key `key` gives each element, stably.
pub fn sort_by_key<T, K: Ord>(v: &mut [T], mut key: impl FnMut(&T) -> K) {
    sort_by(v, |a, b| key(a).cmp(&key(b)));
}

/// Sorts `v` in its own order, stably.
pub fn sort<T: Ord>(v: &mut [T]) {
    sort_by(v, T::cmp);
}

/// Sorts numbers ascending by `f64::total_cmp`.
pub fn sort_floats(v: &mut [f64]) {
    sort_by(v, f64::total_cmp);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorts_as_the_standard_library_does_and_keeps_ties_in_order() {
        let mut seed = 7u64;
        for n in [0usize, 1, 2, 3, 17, 100, 1000] {
            let v: Vec<(u8, u32)> = (0..n as u32)
                .map(|i| {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    ((seed >> 59) as u8, i)
                })
                .collect();
            let mut ours = v.clone();
            sort_by_key(&mut ours, |p| p.0);
            let mut theirs = v.clone();
            theirs.sort_by_key(|p| p.0);
            assert_eq!(ours, theirs, "n = {n}");
            // In order already, and in order but for the last: as the standard library's.
            for mut w in [theirs.clone(), [&theirs[..n.saturating_sub(1)], &v[..n.min(1)]].concat()] {
                let mut std_sorted = w.clone();
                std_sorted.sort_by_key(|p| p.0);
                sort_by_key(&mut w, |p| p.0);
                assert_eq!(w, std_sorted, "n = {n}, nearly in order");
            }
        }
    }

    #[test]
    fn permute_moves_each_element_once() {
        let mut v = vec!['a', 'b', 'c', 'd', 'e'];
        permute(&mut v, &[3, 0, 4, 1, 2]);
        assert_eq!(v, vec!['d', 'a', 'e', 'b', 'c']);
        let mut f = vec![2.5, -1.0, f64::INFINITY, 0.0];
        sort_floats(&mut f);
        assert_eq!(f, vec![-1.0, 0.0, 2.5, f64::INFINITY]);
    }
}
