//! Small numeric helpers shared by the planner and the serialisers.

use serde::Serializer;

/// Tolerance for comparing lengths in program units (well below IS-C's 0.0001).
pub const EPS: f64 = 1e-9;

/// Rounds a value for output: six decimals, enough for IS-C inch (0.00001) and
/// free of binary noise such as `0.44999999999999574`.
pub fn round_out(v: f64) -> f64 {
    if !v.is_finite() {
        return v;
    }
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 { 0.0 } else { r }
}

/// `serialize_with` helper that writes a rounded `f64`.
pub fn ser_round<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(round_out(*v))
}

/// `serialize_with` helper for an optional rounded `f64`.
pub fn ser_round_opt<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(v) => s.serialize_some(&round_out(*v)),
        None => s.serialize_none(),
    }
}

/// Approximate equality within [`EPS`] scaled to the magnitude of the inputs.
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= EPS * (1.0 + a.abs().max(b.abs()))
}

/// Whether two leads are one: equal to a millionth. A lead read from a
/// word along a taper's path (LinuxCNC's K, six decimals) gives the lead
/// along the axis to a few parts in 10⁸ only; a millionth of a 2 mm lead
/// drifts 2 µm over a thousand turns.
pub fn same_lead(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-6 * a.abs().max(b.abs()) + EPS
}

/// Formats a length for messages: up to four decimals, trailing zeros trimmed.
pub fn fmt(v: f64) -> String {
    // Integer arithmetic for the usual range: exact-decimal float formatting is slow.
    let r = (v * 1e4).round();
    if r.abs() < 9.0e15 {
        let r = r as i64;
        let (int, frac) = ((r / 10000).unsigned_abs(), (r % 10000).unsigned_abs());
        let sign = if r < 0 { "-" } else { "" };
        if frac == 0 {
            return format!("{sign}{int}");
        }
        let mut f = format!("{frac:04}");
        while f.ends_with('0') {
            f.pop();
        }
        return format!("{sign}{int}.{f}");
    }
    let s = format!("{:.4}", round_out(v));
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.to_string() }
}

/// Serialises a pair of numbers rounded for output.
pub fn ser_round_pair<S: Serializer>(v: &[f64; 2], s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeTuple;
    let mut t = s.serialize_tuple(2)?;
    t.serialize_element(&round_out(v[0]))?;
    t.serialize_element(&round_out(v[1]))?;
    t.end()
}

/// `x.round() as i64` (halves away from zero, saturating, NaN as 0) by a
/// cast and a comparison: natively on a baseline x86-64 `round` is a
/// library call, and every G code and whole-number word is rounded.
#[inline]
pub fn round_i64(x: f64) -> i64 {
    let t = x as i64; // toward zero, saturating; NaN → 0
    // Exact: below 2^52 `t` is `x`'s whole part; above, `x` is whole or `t` saturated.
    let f = x - t as f64;
    if f >= 0.5 {
        t.saturating_add(1)
    } else if f <= -0.5 {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// `x.round()` for `x` below 2^52 in size by [`round_i64`], else `x` (whole already, or NaN).
#[inline]
pub fn round(x: f64) -> f64 {
    if x.abs() < 4_503_599_627_370_496.0 { round_i64(x) as f64 } else { x }
}

/// The lesser of `x` and `y`, the other when one is NaN: `f64::min` by
/// comparison. In wasm, `f64::min` is a call (wasm's own `min` treats NaN
/// otherwise), and the side section takes several per thread at every
/// keystroke; this is the same number as that call gives.
#[inline]
pub fn min(x: f64, y: f64) -> f64 {
    if y.is_nan() || x < y { x } else { y }
}

/// The greater of `x` and `y`, the other when one is NaN ([`min`]'s twin).
#[inline]
pub fn max(x: f64, y: f64) -> f64 {
    if y.is_nan() || x > y { x } else { y }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_removes_binary_noise() {
        assert_eq!(round_out(0.44999999999999574), 0.45);
        assert_eq!(round_out(-0.0000001), 0.0);
        assert_eq!(fmt(27.42860), "27.4286");
        assert_eq!(fmt(2.0), "2");
        assert_eq!(fmt(-0.00001), "0");
        assert_eq!(fmt(-2.5), "-2.5");
        assert_eq!(fmt(-0.25), "-0.25");
        assert_eq!(fmt(1090.0), "1090");
        assert_eq!(fmt(0.0013), "0.0013");
        assert_eq!(fmt(48.85714), "48.8571");
        assert_eq!(fmt(1e20), "100000000000000000000");
    }

    /// `min`/`max` are `f64::min`/`f64::max` on ordinary numbers, infinities and NaN.
    #[test]
    fn min_and_max_are_the_standard_ones() {
        let xs = [-2.5, -1.0, 0.5, 3.0, 1e300, -1e-300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        for x in xs {
            for y in xs {
                let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
                assert!(same(min(x, y), x.min(y)) && same(max(x, y), x.max(y)), "{x} {y}");
            }
        }
    }

    /// `round_i64`/`round` are `f64::round` (halves away from zero) on halves,
    /// the numbers next to them, whole numbers, the largest and smallest, and NaN.
    #[test]
    fn rounding_by_cast_is_the_standard_one() {
        let mut xs = vec![0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, f64::MAX, f64::MIN, 1e-300];
        for k in
            [0.5f64, 1.5, 2.5, 320.0, 331.0, 4_503_599_627_370_495.5, 4_503_599_627_370_496.0, 9.0e15, 9.2e18, 1e19]
        {
            for x in [k, k.next_up(), k.next_down()] {
                xs.extend([x, -x]);
            }
        }
        xs.extend([0.49999999999999994, 32.0 * 10.0, 33.1 * 10.0, 76.1 * 10.0, 2f64.powi(63), -(2f64.powi(63))]);
        for x in xs {
            assert_eq!(round_i64(x), x.round() as i64, "{x:e}");
            let (a, b) = (round(x), x.round());
            assert!(a == b || (a.is_nan() && b.is_nan()), "{x:e}: {a} {b}");
        }
    }
}
