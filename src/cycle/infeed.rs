//! Infeed geometry: where each pass of a cycle sits axially.
//!
//! The tool tip of a flank infeed runs along a flank line of the final
//! thread space, so its non-cutting edge stays on that flank: at depth h the
//! tip is (k − h)·tan(a/2) from the thread middle, on that flank's side;
//! consecutive passes shift by Δdepth·tan(a/2). At full depth every mode is
//! at the middle, so the finished thread sits where it was programmed.

use crate::thread::Infeed;

/// Axial shift of a pass at depth `h` of a thread of height `k`, tool angle
/// `angle_deg`. `n` is the pass number (1-based) for alternating infeed;
/// `left_side` is the Z direction of the left flank (−1: the −Z side).
pub fn shift(infeed: Infeed, n: u32, h: f64, k: f64, angle_deg: f64, left_side: f64) -> f64 {
    if angle_deg <= 0.0 {
        return 0.0;
    }
    let off = (k - h).max(0.0) * (angle_deg.to_radians() / 2.0).tan();
    let side = match infeed {
        Infeed::Radial | Infeed::Programmed => return 0.0,
        Infeed::Left => left_side,
        Infeed::Right => -left_side,
        Infeed::Alternating => {
            if n % 2 == 1 {
                left_side
            } else {
                -left_side
            }
        }
    };
    side * off
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 60° tool, k = 1.3: at h = 0.5 the tip is (1.3 − 0.5)·tan 30° = 0.461880 from the middle.
    #[test]
    fn flank_shifts() {
        let t = (30f64).to_radians().tan();
        assert!((shift(Infeed::Left, 1, 0.5, 1.3, 60.0, -1.0) - (-0.8 * t)).abs() < 1e-12);
        assert!((shift(Infeed::Right, 1, 0.5, 1.3, 60.0, -1.0) - (0.8 * t)).abs() < 1e-12);
        assert!((shift(Infeed::Alternating, 2, 0.5, 1.3, 60.0, -1.0) - (0.8 * t)).abs() < 1e-12);
        assert!((shift(Infeed::Alternating, 3, 0.5, 1.3, 60.0, -1.0) - (-0.8 * t)).abs() < 1e-12);
        assert_eq!(shift(Infeed::Radial, 1, 0.5, 1.3, 60.0, -1.0), 0.0);
        // a = 0: no shift; full depth: no shift.
        assert_eq!(shift(Infeed::Left, 1, 0.5, 1.3, 0.0, -1.0), 0.0);
        assert_eq!(shift(Infeed::Left, 1, 1.3, 1.3, 60.0, -1.0).abs(), 0.0);
    }
}
