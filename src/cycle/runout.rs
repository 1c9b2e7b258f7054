//! Run-out (thread chamfer) rules of the cycles.

/// GSK G78/G92 run-out `(J, K)` (both unsigned; J radial): J and K omitted →
/// both from No.019 (tenths of a lead, 45°); J omitted with K ≠ 0 → J from
/// No.019; K omitted or 0 with J ≠ 0 → K = J; J = 0 → none.
pub fn gsk(j: Option<f64>, k: Option<f64>, no019: f64, lead: f64) -> Option<(f64, f64)> {
    let p = no019 * 0.1 * lead;
    let (j, k) = match (j.map(f64::abs), k.map(f64::abs)) {
        (Some(0.0), _) => return None,
        (None, None) => (p, p),
        (None, Some(0.0)) => (p, p),
        (None, Some(k)) => (p, k),
        (Some(j), None) | (Some(j), Some(0.0)) => (j, j),
        (Some(j), Some(k)) => (j, k),
    };
    (j > 0.0 && k > 0.0).then_some((j, k))
}

/// Fanuc thread chamfer: length `r` tenths of a lead along Z at `angle_deg`
/// to the axis (parameters 5130/5131, or G76's r digits).
pub fn fanuc(r: f64, angle_deg: f64, lead: f64) -> Option<(f64, f64)> {
    let k = r * 0.1 * lead;
    (k > 0.0).then(|| (k * angle_deg.to_radians().tan(), k))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No.019 = 10 with lead 2: 10 × 0.1 × 2 = 2 mm.
    #[test]
    fn gsk_rules() {
        assert_eq!(gsk(None, None, 10.0, 2.0), Some((2.0, 2.0))); // note 1
        assert_eq!(gsk(None, Some(3.0), 10.0, 2.0), Some((2.0, 3.0))); // note 2
        assert_eq!(gsk(Some(1.5), None, 10.0, 2.0), Some((1.5, 1.5))); // note 3
        assert_eq!(gsk(Some(1.5), Some(0.0), 10.0, 2.0), Some((1.5, 1.5))); // note 3, K = 0
        assert_eq!(gsk(Some(0.0), Some(3.0), 10.0, 2.0), None); // note 4
        assert_eq!(gsk(Some(1.0), Some(4.0), 10.0, 2.0), Some((1.0, 4.0)));
        assert_eq!(gsk(Some(-1.0), Some(-4.0), 10.0, 2.0), Some((1.0, 4.0))); // unsigned
        assert_eq!(gsk(None, None, 0.0, 2.0), None); // No.019 = 0: none
    }

    /// 5130 = 10, 45°, lead 1.5: K = 1.5, J = 1.5; at 30°: J = 1.5·tan 30° = 0.866025.
    #[test]
    fn fanuc_chamfer() {
        let (j, k) = fanuc(10.0, 45.0, 1.5).unwrap();
        assert!((j - 1.5).abs() < 1e-12 && (k - 1.5).abs() < 1e-12);
        let (j, _) = fanuc(10.0, 30.0, 1.5).unwrap();
        assert!((j - 0.8660254037844386).abs() < 1e-12);
        assert_eq!(fanuc(0.0, 45.0, 1.5), None);
    }
}
