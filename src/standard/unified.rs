//! Unified inch screw threads: ASME B1.1 limits of size by its formulas,
//! rounded as its tables are, and the standard series pitches.

use super::{
    Class, Designation, Diameters, Error, Kind, Limit, Limits, MM_PER_INCH, Series, System, Tolerances, round_to,
};
use crate::args;
use crate::message as msg;

/// Threads per inch of the coarse (UNC), fine (UNF) and extra-fine (UNEF)
/// series by basic major diameter, inches (ASME B1.1 table 1); 0 = none.
const SERIES_TPI: [(f64, u8, u8, u8); 36] = [
    (0.060, 0, 80, 0),
    (0.073, 64, 72, 0),
    (0.086, 56, 64, 0),
    (0.099, 48, 56, 0),
    (0.112, 40, 48, 0),
    (0.125, 40, 44, 0),
    (0.138, 32, 40, 0),
    (0.164, 32, 36, 0),
    (0.190, 24, 32, 0),
    (0.216, 24, 28, 32),
    (0.2500, 20, 28, 32),
    (0.3125, 18, 24, 32),
    (0.3750, 16, 24, 32),
    (0.4375, 14, 20, 28),
    (0.5000, 13, 20, 28),
    (0.5625, 12, 18, 24),
    (0.6250, 11, 18, 24),
    (0.7500, 10, 16, 20),
    (0.8750, 9, 14, 20),
    (1.0000, 8, 12, 20),
    (1.1250, 7, 12, 18),
    (1.2500, 7, 12, 18),
    (1.3750, 6, 12, 18),
    (1.5000, 6, 12, 18),
    (1.7500, 5, 0, 0),
    (2.0000, 0, 0, 0),
    (2.2500, 0, 0, 0),
    (2.5000, 4, 0, 0),
    (2.7500, 4, 0, 0),
    (3.0000, 4, 0, 0),
    (3.2500, 4, 0, 0),
    (3.5000, 4, 0, 0),
    (3.7500, 4, 0, 0),
    (4.0000, 4, 0, 0),
    (0.6875, 0, 0, 24),
    (0.8125, 0, 0, 20),
];

/// Number sizes #0 … #12 → basic major diameter (0.060 + 0.013·N in).
pub(super) fn number_size(n: u32) -> Option<f64> {
    (n <= 12 && n != 11 && n != 9 && n != 7).then(|| 0.060 + 0.013 * f64::from(n))
}

fn series_row(d_in: f64) -> Option<&'static (f64, u8, u8, u8)> {
    SERIES_TPI.iter().find(|r| (r.0 - d_in).abs() < 5e-5)
}

/// Threads per inch of a standard series at a size, if the series has it.
/// UNC 2 and 2-1/4 in are 4.5 tpi.
pub(super) fn series_tpi(series: Series, d_in: f64) -> Option<f64> {
    if series == Series::Unc && ((d_in - 2.0).abs() < 5e-5 || (d_in - 2.25).abs() < 5e-5) {
        return Some(4.5);
    }
    let r = series_row(d_in)?;
    let t = match series {
        Series::Unc => r.1,
        Series::Unf => r.2,
        Series::Unef => r.3,
        _ => 0,
    };
    (t != 0).then_some(f64::from(t))
}

/// Whether a number size with this pitch exists (to read `10-32` as #10).
pub(super) fn is_number_size_pitch(n: u32, tpi: f64) -> bool {
    number_size(n).and_then(series_row).is_some_and(|r| [r.1, r.2, r.3].iter().any(|t| f64::from(*t) == tpi))
}

/// Length of engagement the tolerances are based on (ASME B1.1 §5.1):
/// the basic diameter for UNC, UNF and the 4-, 6-, 8-UN series, nine
/// pitches for UNEF, the 12- to 32-UN series and UNS.
fn engagement(series: Series, d: f64, tpi: f64, p: f64) -> f64 {
    match series {
        Series::Unc | Series::Unf => d,
        Series::Un if [4.0, 6.0, 8.0].contains(&tpi) => d,
        _ => 9.0 * p,
    }
}

fn r4(v: f64) -> f64 {
    round_to(v, 4)
}

/// Internal minor-diameter tolerance, inches (ASME B1.1 §5.8.2).
fn minor_tolerance(grade: u8, d: f64, p: f64, tpi: f64) -> f64 {
    let base = 0.05 * p.powf(2.0 / 3.0) + 0.03 * p / d - 0.002;
    let cap = 0.394 * p;
    if grade < 3 {
        let floor = 0.25 * p - 0.4 * p * p;
        if d >= 0.25 - 1e-9 { floor } else { base.min(cap).max(floor) }
    } else {
        let floor = if tpi >= 13.0 { 0.23 * p - 1.5 * p * p } else { 0.12 * p };
        base.min(cap).max(floor)
    }
}

/// Inputs shared by the external and internal limits, inches.
struct Sizes {
    d: f64,
    p: f64,
    tpi: f64,
    td2_2a: f64,
    bd: f64,
    b2: f64,
    b1: f64,
}

/// Classes 1A–3A.
fn external(s: &Sizes, grade: u8, notes: &mut Vec<String>) -> (Diameters, Tolerances) {
    let Sizes { p, td2_2a, bd, b2, .. } = *s;
    let k = [1.5, 1.0, 0.75][usize::from(grade - 1)];
    let td2 = r4(k * td2_2a);
    let allowance = if grade < 3 { r4(0.3 * td2_2a) } else { 0.0 };
    let td = r4(if grade == 1 { 0.090 } else { 0.060 } * p.powf(2.0 / 3.0));
    let (dmax, d2max) = (bd - allowance, b2 - allowance);
    notes.push("external minor: max is the UNR reference (d2 max − 0.541266·P); UN flat roots are not limited".into());
    let diam = Diameters {
        major: Limit::both(r4(dmax - td), r4(dmax)),
        pitch: Limit::both(r4(d2max - td2), r4(d2max)),
        minor: Limit { min: None, max: Some(r4(d2max - 0.541_266 * p)) },
        ..Diameters::default()
    };
    (diam, Tolerances { deviation: -allowance, pitch: td2, crest: td })
}

/// Classes 1B–3B.
fn internal(s: &Sizes, grade: u8, notes: &mut Vec<String>) -> (Diameters, Tolerances) {
    let Sizes { d, p, tpi, td2_2a, bd, b2, b1 } = *s;
    let k = [1.95, 1.3, 0.975][usize::from(grade - 1)];
    let td2 = r4(k * td2_2a);
    let td1 = r4(minor_tolerance(grade, d, p, tpi));
    let coarse_minor = grade < 3 && d >= 0.138 - 1e-9;
    let minor = if coarse_minor {
        notes.push("class 1B/2B minor diameter limits are rounded to 0.001 in from 0.138 in up".into());
        Limit::both(round_to(b1, 3), round_to(b1 + td1, 3))
    } else {
        Limit::both(b1, r4(b1 + td1))
    };
    notes.push("internal major diameter: only the minimum (basic) is a product limit".into());
    let diam = Diameters {
        major: Limit { min: Some(bd), max: None },
        pitch: Limit::both(b2, r4(b2 + td2)),
        minor,
        ..Diameters::default()
    };
    (diam, Tolerances { deviation: 0.0, pitch: td2, crest: td1 })
}

/// ASME B1.1 limits of a Unified designation.
pub(super) fn limits(des: &Designation) -> Result<Limits, Error> {
    let Some(Class::Unified { grade }) = des.class else {
        return Err(Error::new(&msg::STD_UNIFIED_NEEDS_CLASS, args![]));
    };
    if !(1..=3).contains(&grade) {
        return Err(Error::new(&msg::STD_UNIFIED_NO_GRADE, args![grade]));
    }
    let d = des.nominal_in.unwrap_or(des.nominal_mm / MM_PER_INCH);
    let tpi = des.tpi.unwrap_or(MM_PER_INCH / des.pitch_mm);
    let p = 1.0 / tpi;
    let le = engagement(des.series, d, tpi, p);
    // Each term carried to 0.000001 in: 1/4-20 2B then gives 1.3 × 0.003731 =
    // 0.0048503 → 0.0049 as published, where full precision (0.00484998) gives 0.0048.
    let term = |v: f64| round_to(v, 6);
    let td2_2a = term(0.0015 * d.cbrt()) + term(0.0015 * le.sqrt()) + term(0.015 * p.powf(2.0 / 3.0));
    let basic_pitch = d - 0.649_519 * p;
    let basic_minor = d - 1.082_532 * p;
    let (bd, b2, b1) = (r4(d), r4(basic_pitch), r4(basic_minor));
    let mut notes = vec![format!(
        "ASME B1.1 formulas, length of engagement {} in; values rounded to 0.0001 in as the tables are",
        round_to(le, 4)
    )];
    let sizes = Sizes { d, p, tpi, td2_2a, bd, b2, b1 };
    let (diam, tol) = match des.kind {
        Kind::External => external(&sizes, grade, &mut notes),
        Kind::Internal => internal(&sizes, grade, &mut notes),
    };
    if des.starts > 1 {
        notes.push("multi-start: ASME B1.1 tolerances are those of the pitch".into());
    }
    let inch = Diameters { basic_major: d, basic_pitch, basic_minor, basic_root: None, ..diam };
    let t = Tolerances {
        deviation: tol.deviation * MM_PER_INCH,
        pitch: tol.pitch * MM_PER_INCH,
        crest: tol.crest * MM_PER_INCH,
    };
    Ok(Limits {
        system: System::Unified,
        kind: des.kind,
        class: des.class,
        mm: inch.scaled(MM_PER_INCH),
        inch: Some(inch),
        tolerances: Some(t),
        taper: None,
        taper_inch: None,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_lookups() {
        assert_eq!(series_tpi(Series::Unc, 0.25), Some(20.0));
        assert_eq!(series_tpi(Series::Unf, 0.375), Some(24.0));
        assert_eq!(series_tpi(Series::Unc, 2.0), Some(4.5));
        assert_eq!(series_tpi(Series::Unef, 0.19), None);
        assert_eq!(number_size(10), Some(0.19));
        assert_eq!(number_size(11), None);
        assert!(is_number_size_pitch(10, 32.0));
        assert!(!is_number_size_pitch(1, 8.0));
    }

    #[test]
    fn engagement_by_series() {
        assert_eq!(engagement(Series::Unc, 0.25, 20.0, 0.05), 0.25);
        assert_eq!(engagement(Series::Un, 1.0, 8.0, 0.125), 1.0);
        assert!((engagement(Series::Un, 1.0, 12.0, 1.0 / 12.0) - 0.75).abs() < 1e-12);
        assert!((engagement(Series::Unef, 0.25, 32.0, 1.0 / 32.0) - 0.28125).abs() < 1e-12);
    }

    #[test]
    fn minor_tolerance_bounds() {
        // 1/4-20 2B: 0.25·P − 0.4·P² = 0.0115.
        assert!((minor_tolerance(2, 0.25, 0.05, 20.0) - 0.0115).abs() < 1e-12);
        // 0-80 2B: the formula (0.0069) is capped at 0.394·P = 0.004925.
        assert!((minor_tolerance(2, 0.06, 0.0125, 80.0) - 0.004925).abs() < 1e-12);
    }
}
