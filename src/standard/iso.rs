//! ISO metric threads: ISO 261 coarse pitches and ISO 965-1 tolerance tables.
//!
//! Table values are µm, as published in ISO 965-1:1998 (tables 3 to 7);
//! 0 marks a grade the standard does not define for that pitch.

use super::{Class, Designation, Diameters, Error, IsoZone, Kind, Limit, Limits, System, Tolerances};
use crate::args;
use crate::message as msg;

/// ISO 965-1 pitches, mm; the column order of the pitch-keyed tables.
const PITCHES: [f64; 25] = [
    0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7, 0.75, 0.8, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0,
    5.5, 6.0, 8.0,
];

/// Fundamental deviation magnitude of G (EI = +value) and g (es = −value).
const DEV_G: [u16; 25] =
    [17, 18, 18, 19, 19, 20, 20, 21, 22, 22, 24, 26, 28, 32, 34, 38, 42, 48, 53, 60, 63, 71, 75, 80, 100];
/// Fundamental deviation magnitude of f (es = −value).
const DEV_F: [u16; 25] =
    [0, 0, 0, 34, 34, 35, 36, 36, 38, 38, 38, 40, 42, 45, 48, 52, 58, 63, 70, 75, 80, 85, 90, 95, 118];
/// Fundamental deviation magnitude of e (es = −value).
const DEV_E: [u16; 25] =
    [0, 0, 0, 0, 0, 0, 50, 53, 56, 56, 60, 60, 63, 67, 71, 71, 80, 85, 90, 95, 100, 106, 112, 118, 140];

/// Major-diameter tolerance Td of external threads, grades 4, 6, 8.
const TD: [[u16; 25]; 3] = [
    [36, 42, 48, 53, 60, 63, 67, 80, 90, 90, 95, 112, 132, 150, 170, 180, 212, 236, 265, 300, 315, 335, 355, 375, 450],
    [
        56, 67, 75, 85, 95, 100, 106, 125, 140, 140, 150, 180, 212, 236, 265, 280, 335, 375, 425, 475, 500, 530, 560,
        600, 710,
    ],
    [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 236, 280, 335, 375, 425, 450, 530, 600, 670, 750, 800, 850, 900, 950, 1180],
];

/// Minor-diameter tolerance TD1 of internal threads, grades 4 to 8.
/// (One transcription reads 475 for 5 at P 5.5; 600 from the others.)
const TD1: [[u16; 25]; 5] = [
    [
        38, 45, 53, 63, 71, 80, 90, 100, 112, 118, 125, 150, 170, 190, 212, 236, 280, 315, 355, 375, 425, 450, 475,
        500, 630,
    ],
    [
        0, 56, 67, 80, 90, 100, 112, 125, 140, 150, 160, 190, 212, 236, 265, 300, 355, 400, 450, 475, 530, 560, 600,
        630, 800,
    ],
    [
        0, 0, 85, 100, 112, 125, 140, 160, 180, 190, 200, 236, 265, 300, 335, 375, 450, 500, 560, 600, 670, 710, 750,
        800, 1000,
    ],
    [0, 0, 0, 0, 0, 0, 180, 200, 224, 236, 250, 300, 335, 375, 425, 475, 560, 630, 710, 750, 850, 900, 950, 1000, 1250],
    [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 315, 375, 425, 475, 530, 600, 710, 800, 900, 950, 1060, 1120, 1180, 1250, 1600],
];

/// Basic major diameter ranges (over, up to and including), mm.
const RANGES: [(f64, f64); 9] = [
    (0.99, 1.4),
    (1.4, 2.8),
    (2.8, 5.6),
    (5.6, 11.2),
    (11.2, 22.4),
    (22.4, 45.0),
    (45.0, 90.0),
    (90.0, 180.0),
    (180.0, 355.0),
];

/// A row of the pitch-diameter tables: range index, pitch, Td2 grades 3–9,
/// TD2 grades 4–8.
type PdRow = (u8, f64, [u16; 7], [u16; 5]);

/// ISO 965-1 tables 6 (TD2) and 7 (Td2). Corrections of one public
/// transcription by the other and by the grade series: Td2(4) at
/// 180–355/P4 is 180 (not 198), Td2(9) at 11.2–22.4/P1.25 is 265 (not 365),
/// Td2(9) at 45–90/P2 is 355 (not 335). Rows 5.6–11.2/P0.5 and
/// 11.2–22.4/P0.75 and 45–90/P1 come from the second transcription only
/// and were checked against DIN 13 6g/6H limits (which set TD2(6) at
/// 45–90/P1 to 190); 90–180/P1.5 holds only grade 6, from DIN 13.
const PD_ROWS: [PdRow; 51] = [
    (0, 0.2, [24, 30, 38, 48, 0, 0, 0], [40, 0, 0, 0, 0]),
    (0, 0.25, [26, 34, 42, 53, 0, 0, 0], [45, 56, 0, 0, 0]),
    (0, 0.3, [28, 36, 45, 56, 0, 0, 0], [48, 60, 75, 0, 0]),
    (1, 0.2, [25, 32, 40, 50, 0, 0, 0], [42, 0, 0, 0, 0]),
    (1, 0.25, [28, 36, 45, 56, 0, 0, 0], [48, 60, 0, 0, 0]),
    (1, 0.35, [32, 40, 50, 63, 80, 0, 0], [53, 67, 85, 0, 0]),
    (1, 0.4, [34, 42, 53, 67, 85, 0, 0], [56, 71, 90, 0, 0]),
    (1, 0.45, [36, 45, 56, 71, 90, 0, 0], [60, 75, 95, 0, 0]),
    (2, 0.35, [34, 42, 53, 67, 85, 0, 0], [56, 71, 90, 0, 0]),
    (2, 0.5, [38, 48, 60, 75, 95, 0, 0], [63, 80, 100, 125, 0]),
    (2, 0.6, [42, 53, 67, 85, 106, 0, 0], [71, 90, 112, 140, 0]),
    (2, 0.7, [45, 56, 71, 90, 112, 0, 0], [75, 95, 118, 150, 0]),
    (2, 0.75, [45, 56, 71, 90, 112, 0, 0], [75, 95, 118, 150, 0]),
    (2, 0.8, [48, 60, 75, 95, 118, 150, 190], [80, 100, 125, 160, 200]),
    (3, 0.5, [42, 53, 67, 85, 106, 0, 0], [71, 90, 112, 0, 0]),
    (3, 0.75, [50, 63, 80, 100, 125, 0, 0], [85, 106, 132, 170, 0]),
    (3, 1.0, [56, 71, 90, 112, 140, 180, 224], [95, 118, 150, 190, 236]),
    (3, 1.25, [60, 75, 95, 118, 150, 190, 236], [100, 125, 160, 200, 250]),
    (3, 1.5, [67, 85, 106, 132, 170, 212, 265], [112, 140, 180, 224, 280]),
    (4, 0.75, [53, 67, 85, 106, 132, 0, 0], [90, 112, 140, 180, 0]),
    (4, 1.0, [60, 75, 95, 118, 150, 190, 236], [100, 125, 160, 200, 250]),
    (4, 1.25, [67, 85, 106, 132, 170, 212, 265], [112, 140, 180, 224, 280]),
    (4, 1.5, [71, 90, 112, 140, 180, 224, 280], [118, 150, 190, 236, 300]),
    (4, 1.75, [75, 95, 118, 150, 190, 236, 300], [125, 160, 200, 250, 315]),
    (4, 2.0, [80, 100, 125, 160, 200, 250, 315], [132, 170, 212, 265, 335]),
    (4, 2.5, [85, 106, 132, 170, 212, 265, 335], [140, 180, 224, 280, 355]),
    (5, 1.0, [63, 80, 100, 125, 160, 200, 250], [106, 132, 170, 212, 0]),
    (5, 1.5, [75, 95, 118, 150, 190, 236, 300], [125, 160, 200, 250, 315]),
    (5, 2.0, [85, 106, 132, 170, 212, 265, 335], [140, 180, 224, 280, 335]),
    (5, 3.0, [100, 125, 160, 200, 250, 315, 400], [170, 212, 265, 335, 425]),
    (5, 3.5, [106, 132, 170, 212, 265, 335, 425], [180, 224, 280, 355, 450]),
    (5, 4.0, [112, 140, 180, 224, 280, 355, 450], [190, 236, 300, 375, 475]),
    (5, 4.5, [118, 150, 190, 236, 300, 375, 475], [200, 250, 315, 400, 500]),
    (6, 1.0, [71, 90, 112, 140, 180, 224, 0], [118, 150, 190, 236, 0]),
    (6, 1.5, [80, 100, 125, 160, 200, 250, 315], [132, 170, 212, 265, 335]),
    (6, 2.0, [90, 112, 140, 180, 224, 280, 355], [150, 190, 236, 300, 375]),
    (6, 3.0, [106, 132, 170, 212, 265, 335, 425], [180, 224, 280, 355, 450]),
    (6, 4.0, [118, 150, 190, 236, 300, 375, 475], [200, 250, 315, 400, 500]),
    (6, 5.0, [125, 160, 200, 250, 315, 400, 500], [212, 265, 335, 425, 530]),
    (6, 5.5, [132, 170, 212, 265, 335, 425, 530], [224, 280, 355, 450, 560]),
    (6, 6.0, [140, 180, 224, 280, 355, 450, 560], [236, 300, 375, 475, 600]),
    (7, 1.5, [0, 0, 0, 180, 0, 0, 0], [0, 0, 236, 0, 0]),
    (7, 2.0, [95, 118, 150, 190, 236, 300, 375], [160, 200, 250, 315, 400]),
    (7, 3.0, [112, 140, 180, 224, 280, 355, 450], [190, 236, 300, 375, 475]),
    (7, 4.0, [125, 160, 200, 250, 315, 400, 500], [212, 265, 335, 425, 530]),
    (7, 6.0, [150, 190, 236, 300, 375, 475, 600], [250, 315, 400, 500, 630]),
    (7, 8.0, [170, 212, 265, 335, 425, 530, 670], [280, 355, 450, 560, 710]),
    (8, 3.0, [125, 160, 200, 250, 315, 400, 500], [212, 265, 335, 425, 530]),
    (8, 4.0, [140, 180, 224, 280, 355, 450, 560], [236, 300, 375, 475, 600]),
    (8, 6.0, [160, 200, 250, 315, 400, 500, 630], [265, 335, 425, 530, 670]),
    (8, 8.0, [180, 224, 280, 355, 450, 560, 710], [300, 375, 475, 600, 750]),
];

/// ISO 261 coarse pitch series (nominal diameter, pitch), mm.
const COARSE: [(f64, f64); 40] = [
    (1.0, 0.25),
    (1.1, 0.25),
    (1.2, 0.25),
    (1.4, 0.3),
    (1.6, 0.35),
    (1.8, 0.35),
    (2.0, 0.4),
    (2.2, 0.45),
    (2.5, 0.45),
    (3.0, 0.5),
    (3.5, 0.6),
    (4.0, 0.7),
    (4.5, 0.75),
    (5.0, 0.8),
    (6.0, 1.0),
    (7.0, 1.0),
    (8.0, 1.25),
    (9.0, 1.25),
    (10.0, 1.5),
    (11.0, 1.5),
    (12.0, 1.75),
    (14.0, 2.0),
    (16.0, 2.0),
    (18.0, 2.5),
    (20.0, 2.5),
    (22.0, 2.5),
    (24.0, 3.0),
    (27.0, 3.0),
    (30.0, 3.5),
    (33.0, 3.5),
    (36.0, 4.0),
    (39.0, 4.0),
    (42.0, 4.5),
    (45.0, 4.5),
    (48.0, 5.0),
    (52.0, 5.0),
    (56.0, 5.5),
    (60.0, 5.5),
    (64.0, 6.0),
    (68.0, 6.0),
];

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// ISO 261 coarse pitch of a nominal diameter, if it has one.
pub(super) fn coarse_pitch(d: f64) -> Option<f64> {
    COARSE.iter().find(|(n, _)| same(*n, d)).map(|(_, p)| *p)
}

fn pitch_index(p: f64) -> Option<usize> {
    PITCHES.iter().position(|q| same(*q, p))
}

fn range_index(d: f64) -> Option<usize> {
    RANGES.iter().position(|(lo, hi)| d > *lo && d <= *hi + 1e-9)
}

fn pd_row(d: f64, p: f64) -> Option<&'static PdRow> {
    let r = range_index(d)? as u8;
    PD_ROWS.iter().find(|row| row.0 == r && same(row.1, p))
}

/// Fundamental deviation in µm (es ≤ 0 external, EI ≥ 0 internal).
fn deviation(position: char, pi: usize) -> Option<i32> {
    let v = match position {
        'h' | 'H' => return Some(0),
        'g' => -i32::from(DEV_G[pi]),
        'G' => i32::from(DEV_G[pi]),
        'f' => -i32::from(DEV_F[pi]),
        'e' => -i32::from(DEV_E[pi]),
        _ => return None,
    };
    (v != 0).then_some(v)
}

fn nonzero(v: u16) -> Option<i32> {
    (v != 0).then_some(i32::from(v))
}

/// The µm values a class needs, or what is missing from the tables.
struct Tol {
    pd_dev: i32,
    crest_dev: i32,
    pd_tol: i32,
    crest_tol: i32,
}

fn tolerances(d: f64, p: f64, kind: Kind, pitch: IsoZone, crest: IsoZone) -> Result<Tol, Error> {
    let pi = pitch_index(p).ok_or_else(|| Error::new(&msg::STD_ISO_PITCH, args![p]))?;
    let row = pd_row(d, p).ok_or_else(|| Error::new(&msg::STD_ISO_NO_PITCH_TOLERANCE, args![d, p]))?;
    let missing = |what: &'static msg::Phrase, z: IsoZone| {
        Error::new(&msg::STD_ISO_UNDEFINED, args![what, zone = format!("{}{}", z.grade, z.position), p, d])
    };
    let pd_dev = deviation(pitch.position, pi).ok_or_else(|| missing(&msg::FUNDAMENTAL_DEVIATION, pitch))?;
    let crest_dev = deviation(crest.position, pi).ok_or_else(|| missing(&msg::FUNDAMENTAL_DEVIATION, crest))?;
    let (pd_tol, crest_tol) = match kind {
        Kind::External => {
            let pd = row.2.get(usize::from(pitch.grade).wrapping_sub(3)).copied().and_then(nonzero);
            let cr = match crest.grade {
                4 => nonzero(TD[0][pi]),
                6 => nonzero(TD[1][pi]),
                8 => nonzero(TD[2][pi]),
                _ => None,
            };
            (pd.ok_or_else(|| missing(&msg::TD2, pitch))?, cr.ok_or_else(|| missing(&msg::TD, crest))?)
        }
        Kind::Internal => {
            let pd = row.3.get(usize::from(pitch.grade).wrapping_sub(4)).copied().and_then(nonzero);
            let cr = TD1.get(usize::from(crest.grade).wrapping_sub(4)).map(|t| t[pi]).and_then(nonzero);
            (pd.ok_or_else(|| missing(&msg::TD2_INTERNAL, pitch))?, cr.ok_or_else(|| missing(&msg::TD1, crest))?)
        }
    };
    Ok(Tol { pd_dev, crest_dev, pd_tol, crest_tol })
}

/// µm, rounded, of a length in mm.
fn um(mm: f64) -> i64 {
    (mm * 1000.0).round() as i64
}

fn mm(um: i64) -> f64 {
    um as f64 / 1000.0
}

/// ISO 965-1 limits of an ISO metric designation.
pub(super) fn limits(des: &Designation) -> Result<Limits, Error> {
    let (d, p) = (des.nominal_mm, des.pitch_mm);
    let Some(Class::Iso { pitch, crest }) = des.class else {
        return Err(Error::new(&msg::STD_ISO_NEEDS_CLASS, args![]));
    };
    if d > 1000.0 {
        return Err(Error::new(&msg::STD_ISO_TOO_LARGE, args![d]));
    }
    let t = tolerances(d, p, des.kind, pitch, crest)?;
    let basic_pitch = d - 0.649_519 * p;
    let basic_minor = d - 1.082_532 * p;
    let root = d - 1.226_869 * p;
    let (bd, b2, b1) = (um(d), um(basic_pitch), um(basic_minor));
    let (pd_dev, crest_dev, pd_tol, crest_tol) =
        (i64::from(t.pd_dev), i64::from(t.crest_dev), i64::from(t.pd_tol), i64::from(t.crest_tol));
    let mut notes = Vec::new();
    let diam = match des.kind {
        Kind::External => {
            let d2max = b2 + pd_dev;
            let d2min = d2max - pd_tol;
            // From the unrounded basic d2, as DIN 13 / ISO 965-2 tabulate it (M3.5: 2.635).
            let d3min = (basic_pitch * 1000.0 + (pd_dev - pd_tol) as f64) - 616.025 * p;
            notes.push("external minor: min is d3 min for a root radius of at least 0.125·P (ISO 965-1); max is the flat-root reference D1 + es (ASME B1.13M, DIN 13)".into());
            Diameters {
                major: Limit::both(mm(bd + crest_dev - crest_tol), mm(bd + crest_dev)),
                pitch: Limit::both(mm(d2min), mm(d2max)),
                minor: Limit::both(mm(d3min.round() as i64), mm(b1 + pd_dev)),
                ..Diameters::default()
            }
        }
        Kind::Internal => {
            notes.push("internal major diameter: only the minimum (D + EI) is specified; the maximum is limited by the root form of the tool".into());
            Diameters {
                major: Limit { min: Some(mm(bd + crest_dev)), max: None },
                pitch: Limit::both(mm(b2 + pd_dev), mm(b2 + pd_dev + pd_tol)),
                minor: Limit::both(mm(b1 + crest_dev), mm(b1 + crest_dev + crest_tol)),
                ..Diameters::default()
            }
        }
    };
    if des.starts > 1 {
        notes.push(
            "multi-start: tolerances are those of the pitch; ISO 965-1 leaves lead and flank errors to agreement"
                .into(),
        );
    }
    Ok(Limits {
        system: System::IsoMetric,
        kind: des.kind,
        class: des.class,
        mm: Diameters { basic_major: d, basic_pitch, basic_minor, basic_root: Some(root), ..diam },
        inch: None,
        tolerances: Some(Tolerances { deviation: mm(pd_dev), pitch: mm(pd_tol), crest: mm(crest_tol) }),
        taper: None,
        taper_inch: None,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_consistent() {
        // Each TD2 grade is the Td2 of that grade × 1.32 within the R40 rounding (±6 %),
        // and every row grows with the grade.
        for row in PD_ROWS.iter() {
            let td2 = row.2;
            for w in td2.windows(2) {
                assert!(w[1] == 0 || w[1] > w[0], "{row:?}");
            }
            for (i, &v) in row.3.iter().enumerate() {
                let ext = td2[i + 1];
                if v != 0 && ext != 0 {
                    let ratio = f64::from(v) / (1.32 * f64::from(ext));
                    assert!((0.94..1.06).contains(&ratio), "{row:?} grade {}", i + 4);
                }
            }
        }
        for t in TD.iter().chain(TD1.iter()) {
            let nz: Vec<_> = t.iter().filter(|v| **v != 0).collect();
            assert!(nz.windows(2).all(|w| w[1] >= w[0]));
        }
    }

    #[test]
    fn ranges_are_over_up_to_and_including() {
        assert_eq!(range_index(1.4), Some(0));
        assert_eq!(range_index(5.6), Some(2));
        assert_eq!(range_index(5.61), Some(3));
        assert_eq!(range_index(45.0), Some(5));
        assert_eq!(range_index(0.99), None);
        assert_eq!(range_index(400.0), None);
    }

    #[test]
    fn deviation_formula_rounds_as_tables() {
        // es(g) = −(15 + 11 P) µm before the tables' rounding: P 2 → 37 → table 38.
        let pi = pitch_index(2.0).unwrap();
        assert_eq!(deviation('g', pi), Some(-38));
        assert_eq!(deviation('G', pi), Some(38));
        assert_eq!(deviation('e', pitch_index(0.45).unwrap()), None);
        assert_eq!(deviation('h', 0), Some(0));
        assert_eq!(coarse_pitch(10.0), Some(1.5));
        assert_eq!(coarse_pitch(15.0), None);
    }
}
