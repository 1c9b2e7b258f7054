//! American taper pipe threads (NPT), ASME B1.20.1 basic dimensions.

use super::{Designation, Diameters, Error, Limit, Limits, MM_PER_INCH, System, Taper, round_to};
use crate::args;
use crate::message as msg;

/// Nominal size (in, as a number), outside diameter D (in), threads per
/// inch, hand-tight engagement L1 (in): ASME B1.20.1 table 2.
const SIZES: [(f64, f64, f64, f64); 19] = [
    (0.0625, 0.3125, 27.0, 0.160),
    (0.125, 0.405, 27.0, 0.1615),
    (0.25, 0.540, 18.0, 0.2278),
    (0.375, 0.675, 18.0, 0.240),
    (0.5, 0.840, 14.0, 0.320),
    (0.75, 1.050, 14.0, 0.339),
    (1.0, 1.315, 11.5, 0.400),
    (1.25, 1.660, 11.5, 0.420),
    (1.5, 1.900, 11.5, 0.420),
    (2.0, 2.375, 11.5, 0.436),
    (2.5, 2.875, 8.0, 0.682),
    (3.0, 3.500, 8.0, 0.766),
    (3.5, 4.000, 8.0, 0.821),
    (4.0, 4.500, 8.0, 0.844),
    (5.0, 5.563, 8.0, 0.937),
    (6.0, 6.625, 8.0, 0.958),
    (8.0, 8.625, 8.0, 1.063),
    (10.0, 10.750, 8.0, 1.210),
    (12.0, 12.750, 8.0, 1.360),
];

/// Outside diameter and threads per inch of a nominal pipe size.
pub(super) fn size(nominal_in: f64) -> Option<(f64, f64)> {
    SIZES.iter().find(|s| (s.0 - nominal_in).abs() < 1e-6).map(|s| (s.1, s.2))
}

fn l1_of(od: f64) -> Option<f64> {
    SIZES.iter().find(|s| (s.1 - od).abs() < 1e-6).map(|s| s.3)
}

/// Basic NPT dimensions; there are no class limits.
pub(super) fn limits(des: &Designation) -> Result<Limits, Error> {
    let d = des.nominal_in.unwrap_or(des.nominal_mm / MM_PER_INCH);
    let l1 = l1_of(d).ok_or_else(|| Error::new(&msg::STD_NO_NPT_SIZE, args![d]))?;
    let p = 1.0 / des.tpi.unwrap_or(MM_PER_INCH / des.pitch_mm);
    let e0 = round_to(d - (0.05 * d + 1.1) * p, 5);
    let l2 = round_to((0.8 * d + 6.8) * p, 4);
    let t = Taper {
        taper_on_diameter: 1.0 / 16.0,
        e0,
        e1: round_to(e0 + l1 / 16.0, 5),
        l1,
        l2,
        e2: round_to(e0 + l2 / 16.0, 5),
        height: round_to(0.8 * p, 5),
    };
    let inch = Diameters {
        basic_major: d,
        basic_pitch: e0,
        basic_minor: e0 - t.height,
        basic_root: None,
        major: Limit::default(),
        pitch: Limit::default(),
        minor: Limit::default(),
    };
    let k = MM_PER_INCH;
    let notes = vec![
        "NPT has no pitch-diameter class tolerance: the thread is gauged by L1 gauges, ±1 turn from the gauge plane (ASME B1.20.1)".into(),
        "basic diameters are at the small end of the external thread (E0); the taper is 1:16 on diameter".into(),
        "basic minor here is E0 − 0.8·p (sharp-V height 0.866·p truncated to 0.8·p)".into(),
    ];
    Ok(Limits {
        system: System::Npt,
        kind: des.kind,
        class: None,
        mm: inch.scaled(k),
        inch: Some(inch),
        tolerances: None,
        taper: Some(Taper {
            taper_on_diameter: t.taper_on_diameter,
            e0: t.e0 * k,
            e1: t.e1 * k,
            l1: t.l1 * k,
            l2: t.l2 * k,
            e2: t.e2 * k,
            height: t.height * k,
        }),
        taper_inch: Some(t),
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(size(0.5), Some((0.84, 14.0)));
        assert_eq!(size(0.3), None);
        assert_eq!(l1_of(1.315), Some(0.4));
    }
}
