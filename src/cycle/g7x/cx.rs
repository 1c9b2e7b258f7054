//! Points of the profile as complex numbers, `re` the cutting axis and `im`
//! the infeed axis (Z and the radius for G71): rs274's `interp_g7x.cc`
//! computes with `std::complex<double>` in this frame, and turning,
//! mirroring and rotating the profile are then one product each. The
//! operations round as C++'s do (the product term by term, the quotient by
//! Smith's method, as libgcc divides), so the cuts land where rs274's do.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// A complex number: `re` along the cut, `im` the depth.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct C {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

/// The imaginary unit.
pub const I: C = C { re: 0.0, im: 1.0 };

impl C {
    /// The number `re + i·im`.
    pub const fn new(re: f64, im: f64) -> C {
        C { re, im }
    }

    /// The complex conjugate (a mirror in the real axis).
    pub fn conj(self) -> C {
        C::new(self.re, -self.im)
    }

    /// The modulus.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// The squared modulus.
    pub fn norm(self) -> f64 {
        self.re * self.re + self.im * self.im
    }

    /// Both parts times `k`.
    pub fn scale(self, k: f64) -> C {
        C::new(self.re * k, self.im * k)
    }

    /// Both parts divided by `k`.
    pub fn over(self, k: f64) -> C {
        C::new(self.re / k, self.im / k)
    }

    /// The imaginary part of `conj(self)·o`: the cross product of the two as vectors.
    pub fn cross(self, o: C) -> f64 {
        self.re * o.im - self.im * o.re
    }

    /// Whether both parts are finite.
    pub fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

impl Add for C {
    type Output = C;
    fn add(self, o: C) -> C {
        C::new(self.re + o.re, self.im + o.im)
    }
}

impl AddAssign for C {
    fn add_assign(&mut self, o: C) {
        *self = *self + o;
    }
}

impl Sub for C {
    type Output = C;
    fn sub(self, o: C) -> C {
        C::new(self.re - o.re, self.im - o.im)
    }
}

impl Neg for C {
    type Output = C;
    fn neg(self) -> C {
        C::new(-self.re, -self.im)
    }
}

impl Mul for C {
    type Output = C;
    fn mul(self, o: C) -> C {
        C::new(self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re)
    }
}

impl Div for C {
    type Output = C;
    /// Smith's quotient: the ratio of the smaller to the larger part of the divisor first.
    fn div(self, o: C) -> C {
        let (a, b, c, d) = (self.re, self.im, o.re, o.im);
        if c.abs() < d.abs() {
            let ratio = c / d;
            let denom = c * ratio + d;
            C::new((a * ratio + b) / denom, (b * ratio - a) / denom)
        } else {
            let ratio = d / c;
            let denom = d * ratio + c;
            C::new((b * ratio + a) / denom, (b - a * ratio) / denom)
        }
    }
}

/// The smaller of `a` and `b` as C++'s `std::min` takes it: `a` unless `b < a`.
pub fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// `v` as C++ streams write a double by default (`%g`, six significant
/// digits), as rs274's messages give points.
pub fn g(v: f64) -> String {
    g_prec(v, 6)
}

/// `v` as C's `%.{digits}g` writes it.
pub fn g_prec(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_nan() { "nan".into() } else { format!("{v}") };
    }
    let digits = digits.max(1);
    let sci = format!("{v:.*e}", (digits - 1) as usize);
    let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |s: &str| s.trim_end_matches('0').trim_end_matches('.').to_string();
    if !(-4..digits).contains(&exp) {
        let sign = if exp < 0 { '-' } else { '+' };
        return format!("{}e{sign}{:02}", trim(mantissa), exp.abs());
    }
    let fixed = format!("{:.*}", (digits - 1 - exp) as usize, v);
    if fixed.contains('.') { trim(&fixed) } else { fixed }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_quotients() {
        let (a, b) = (C::new(3.0, -2.0), C::new(0.5, 4.0));
        assert_eq!(a * b, C::new(9.5, 11.0));
        let q = (a * b) / b;
        assert!((q - a).abs() < 1e-15, "{q:?}");
        assert_eq!(-I * C::new(2.0, 5.0), C::new(5.0, -2.0), "a quarter turn clockwise");
        assert_eq!(C::new(1.0, 1.0).cross(C::new(-1.0, 1.0)), 2.0);
        assert_eq!(min(1.0, f64::NAN), 1.0);
        let shown: Vec<String> = [-2.0, 8.5, 0.70710612, 1234567.0, 0.00001234, -0.0].into_iter().map(g).collect();
        assert_eq!(shown, ["-2", "8.5", "0.707106", "1.23457e+06", "1.234e-05", "-0"]);
        assert_eq!(g_prec(0.44721359, 4), "0.4472");
    }
}
