//! A threading insert's designation, as tool makers write it (reference
//! threading.md §11): `16ER 1.5 ISO`, `16IR 2.0 ISO`, `22ER 3.0 ISO` —
//! size, E(xternal) or I(nternal), R or L hand, then a full profile (its
//! pitch and standard; `16ER 16 UN` in threads per inch) — or a partial
//! profile, `16ER A60`, which cuts a range of pitches and forms only the
//! root. The checks against a thread are in `shop::insert`.
//!
//! Partial-profile pitch ranges (60°): A60 0.5–1.5 mm, AG60 0.5–3.0 mm,
//! G60 1.75–3.0 mm (Kyocera cutting tools catalogue 2021–2022, threading:
//! "60° type (partial profile)"; other makers' ranges are the same or close).

use crate::message as msg;

/// What an insert cuts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    /// Full profile: the standard's crest and root for one pitch (mm).
    Full {
        /// Pitch, mm.
        pitch_mm: f64,
    },
    /// Partial profile: the root only, for a range of pitches (mm).
    Partial {
        /// Its name (A60, AG60, G60).
        name: &'static str,
        /// Finest pitch, mm.
        min_mm: f64,
        /// Coarsest pitch, mm.
        max_mm: f64,
    },
}

/// A threading insert read from its designation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Insert {
    /// For internal threads (I), else external (E).
    pub internal: bool,
    /// Left-hand (L), else right-hand (R).
    pub left: bool,
    /// What it cuts.
    pub profile: Profile,
}

const PARTIAL: &[(&str, f64, f64)] = &[("A60", 0.5, 1.5), ("AG60", 0.5, 3.0), ("G60", 1.75, 3.0)];

/// Reads an insert designation; `Err` says what was expected.
pub fn parse(s: &str) -> Result<Insert, &'static msg::Phrase> {
    let up = s.trim().to_ascii_uppercase();
    let mut parts = up.split_whitespace();
    let head = parts.next().ok_or(&msg::X_INSERT_HEAD)?;
    let digits = head.chars().take_while(|c| c.is_ascii_digit()).count();
    let rest = &head[digits..];
    let (side, hand) = (rest.chars().next(), rest.chars().nth(1));
    if digits == 0 || rest.len() != 2 || !matches!(side, Some('E' | 'I')) || !matches!(hand, Some('R' | 'L')) {
        return Err(&msg::X_INSERT_HEAD);
    }
    let (internal, left) = (side == Some('I'), hand == Some('L'));
    let what = parts.next().ok_or(&msg::X_INSERT_PROFILE)?;
    let system = parts.next();
    if parts.next().is_some() {
        return Err(&msg::X_INSERT_PROFILE);
    }
    let profile = if let Some(&(name, min_mm, max_mm)) = PARTIAL.iter().find(|p| p.0 == what) {
        if system.is_some() {
            return Err(&msg::X_INSERT_PROFILE);
        }
        Profile::Partial { name, min_mm, max_mm }
    } else {
        let v: f64 = what.parse().map_err(|_| &msg::X_INSERT_PROFILE)?;
        let pitch_mm = match system {
            Some("ISO") if v > 0.0 && v <= 10.0 => v,
            Some("UN") if (2.0..=80.0).contains(&v) => 25.4 / v,
            _ => return Err(&msg::X_INSERT_PROFILE),
        };
        Profile::Full { pitch_mm }
    };
    Ok(Insert { internal, left, profile })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn designations() {
        assert_eq!(
            parse("16ER 1.5 ISO"),
            Ok(Insert { internal: false, left: false, profile: Profile::Full { pitch_mm: 1.5 } })
        );
        assert_eq!(
            parse(" 16ir 2.0 iso ").map(|i| (i.internal, i.profile)),
            Ok((true, Profile::Full { pitch_mm: 2.0 }))
        );
        assert_eq!(parse("16ER 16 UN").map(|i| i.profile), Ok(Profile::Full { pitch_mm: 25.4 / 16.0 }));
        assert_eq!(
            parse("16EL A60").map(|i| (i.left, i.profile)),
            Ok((true, Profile::Partial { name: "A60", min_mm: 0.5, max_mm: 1.5 }))
        );
        for bad in ["", "16XR 1.5 ISO", "ER 1.5 ISO", "16ER", "16ER 1.5", "16ER 1.5 DIN", "16ER A60 ISO", "16ER Z99"] {
            assert!(parse(bad).is_err(), "{bad}");
        }
    }
}
