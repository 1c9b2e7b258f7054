//! Numbers of words, read digit by digit while the line is scanned: exact
//! (the mantissa is an integer, the value one correctly rounded division)
//! and bounded by the digit limit.

use crate::block::Number;

/// Why a number could not be read.
pub(super) enum NumError {
    /// Misplaced signs or points, or no digit.
    Malformed,
    /// More significant digits than allowed (how many).
    TooManyDigits(usize),
}

const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
    1e21, 1e22,
];

/// A number being read digit by digit: the mantissa is an integer and the
/// value one correctly rounded division, so `27.4286` reads as the same
/// `f64` Rust's parser gives.
#[derive(Default)]
pub(super) struct NumAcc {
    pub(super) neg: bool,
    mantissa: u64,
    /// Digits read, before and after the point.
    digits: usize,
    /// `digits` when the point was read.
    point_at: Option<usize>,
    pub(super) malformed: bool,
}

impl NumAcc {
    /// Takes one more character if it continues the number.
    #[inline]
    pub(super) fn push(&mut self, c: u8) -> bool {
        let d = c.wrapping_sub(b'0');
        if d < 10 {
            // Wraps only past 19 digits, which `finish` refuses anyway.
            self.mantissa = self.mantissa.wrapping_mul(10).wrapping_add(d as u64);
            self.digits += 1;
            true
        } else if c == b'.' && self.point_at.is_none() {
            self.point_at = Some(self.digits);
            true
        } else {
            false
        }
    }

    /// The number, or why it is not one. Significant digits exclude leading
    /// zeros and trailing zeros of the fraction.
    #[inline(always)]
    pub(super) fn finish(self, max_digits: usize) -> Result<Number, NumError> {
        let digits = self.digits;
        if self.malformed || digits == 0 {
            return Err(NumError::Malformed);
        }
        let int_digits = self.point_at.unwrap_or(digits);
        let frac = digits - int_digits;
        if digits > max_digits {
            if digits > 19 {
                return Err(NumError::TooManyDigits(digits));
            }
            let (mut m, mut f) = (self.mantissa, frac);
            while f > 0 && m != 0 && m % 10 == 0 {
                m /= 10;
                f -= 1;
            }
            let sig = if m == 0 { 0 } else { m.ilog10() as usize + 1 };
            if sig > max_digits {
                return Err(NumError::TooManyDigits(sig));
            }
        }
        let mut value = if frac < POW10.len() {
            self.mantissa as f64 / POW10[frac]
        } else {
            self.mantissa as f64 / 10f64.powi(frac as i32)
        };
        if self.neg {
            value = -value;
        }
        if value == 0.0 {
            value = 0.0; // no negative zero
        }
        Ok(Number {
            value,
            has_point: self.point_at.is_some(),
            int_digits: int_digits.min(255) as u8,
            frac_digits: frac.min(255) as u8,
        })
    }
}

/// Parses `[+-]digits[.digits]` (the lexer reads numbers the same way, in its stream).
#[cfg(test)]
pub(super) fn parse_number(raw: &[u8], max_digits: usize) -> Result<Number, NumError> {
    let mut acc = NumAcc::default();
    let mut body = raw;
    if let Some(&c @ (b'-' | b'+')) = raw.first() {
        acc.neg = c == b'-';
        body = &raw[1..];
    }
    for &c in body {
        if !acc.push(c) {
            acc.malformed = true;
        }
    }
    acc.finish(max_digits)
}
