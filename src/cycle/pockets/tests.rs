use super::*;
use crate::cycle::rough::Along;

fn p(x: f64, z: f64) -> Point {
    Point { x, z }
}

fn r6(v: f64) -> f64 {
    (v * 1e6).round() / 1e6
}

/// (X, Z from, Z to) of the cuts along a depth: roughing moves along Z at a diameter of the depths.
fn level_cuts(m: &[Move], diameters: &[f64]) -> Vec<(f64, f64, f64)> {
    m.iter()
        .filter(|m| m.kind == MoveKind::Rough && (m.from.x - m.to.x).abs() < 1e-9)
        .filter(|m| diameters.iter().any(|d| (m.from.x - d).abs() < 1e-9))
        .map(|m| (r6(m.from.x), r6(m.from.z), r6(m.to.z)))
        .collect()
}

/// The shape of the integration test (tests/profile.rs), allowances 0.4/0.1:
/// shifted r15.2 Z2.1 → Z-9.9 → r25.2 Z-19.9 → Z-24.9 → r20.2 Z-29.9 → Z-39.9 → r28.2 Z-44.9 → Z-54.9 → r31.2.
fn pocket_shape() -> Vec<Point> {
    [
        (30.0, 2.0),
        (30.0, -10.0),
        (50.0, -20.0),
        (50.0, -25.0),
        (40.0, -30.0),
        (40.0, -40.0),
        (56.0, -45.0),
        (56.0, -55.0),
        (62.0, -55.0),
    ]
    .into_iter()
    .map(|(x, z)| p(x, z))
    .collect()
}

#[test]
fn one_pocket_is_roughed_after_the_cuts_from_the_start() {
    let r = Rough { along: Along::Z, depth: 2.0, escape: 0.5, du: 0.4, dw: 0.1, pockets: true };
    let m = passes(&r, p(62.0, 2.0), &pocket_shape(), 5, Span::default());
    // Radius 31 down by 2: 29 … 17, then A′'s 15.2. From Z2 each cut ends at the first rise:
    // 29 at the last wall (Z-54.9); 27 on the rise r20.2 → r28.2 (Z-39.9 − 5·6.8/8 = -44.15); 25 … 17 on
    // the rise r15.2 → r25.2 (Z-9.9 − 10·(r − 15.2)/10); 15.2 to Z-9.9. Then the pocket between the
    // rise's top r25.2 and the last wall: at 25 from Z-25.1 (Z-24.9 − 5·0.2/5) to Z-42.9 (Z-39.9 − 5·4.8/8),
    // at 23 from -27.1 to -41.65, at 21 from -29.1 to -40.4 (its bottom r20.2 is above 19).
    let diameters = [58.0, 54.0, 50.0, 46.0, 42.0, 38.0, 34.0, 30.4];
    assert_eq!(
        level_cuts(&m, &diameters),
        [
            (58.0, 2.0, -54.9),
            (54.0, 2.0, -44.15),
            (50.0, 2.0, -19.7),
            (46.0, 2.0, -17.7),
            (42.0, 2.0, -15.7),
            (38.0, 2.0, -13.7),
            (34.0, 2.0, -11.7),
            (30.4, 2.0, -9.9),
            (50.0, -25.1, -42.9),
            (46.0, -27.1, -41.65),
            (42.0, -29.1, -40.4),
            // The last cut along the shifted shape starts with its flat at r15.2.
            (30.4, 2.1, -9.9),
        ]
    );
    // After the cut at r27 the tool follows the shape up to r29: along r28.2 from Z-44.9 to Z-54.9,
    // up the wall to r29, escapes 0.5 to r29.5 and returns to Z2.
    let k = m.iter().position(|m| m.kind == MoveKind::Rough && r6(m.to.z) == -44.15 && m.to.x == 54.0).unwrap();
    let next: Vec<(MoveKind, f64, f64)> = m[k + 1..k + 6].iter().map(|m| (m.kind, r6(m.to.x), r6(m.to.z))).collect();
    assert_eq!(
        next,
        [
            (MoveKind::Rough, 56.4, -44.9),
            (MoveKind::Rough, 56.4, -54.9),
            (MoveKind::Rough, 58.0, -54.9),
            (MoveKind::Rapid, 59.0, -54.9),
            (MoveKind::Rapid, 59.0, 2.0),
        ]
    );
    // The pocket is entered from above the top of the rise (r25.2 at Z-19.9): out to A's X62, along,
    // down to r27 (the depth cut there), onto the shape and along it down the wall to r25.
    let k = m.iter().position(|m| m.to.x == 50.0 && r6(m.to.z) == -25.1).unwrap();
    let entry: Vec<(MoveKind, f64, f64)> = m[k - 5..=k].iter().map(|m| (m.kind, r6(m.to.x), r6(m.to.z))).collect();
    assert_eq!(
        entry,
        [
            (MoveKind::Rapid, 62.0, 2.0),
            (MoveKind::Rapid, 62.0, -19.9),
            (MoveKind::Rapid, 54.0, -19.9),
            (MoveKind::Rough, 50.4, -19.9),
            (MoveKind::Rough, 50.4, -24.9),
            (MoveKind::Rough, 50.0, -25.1),
        ]
    );
    // The next depth of the pocket goes down its wall from where the last one started.
    let k = m.iter().position(|m| m.to.x == 46.0 && r6(m.to.z) == -27.1).unwrap();
    assert_eq!((m[k].kind, r6(m[k].from.x), r6(m[k].from.z)), (MoveKind::Rough, 50.0, -25.1));
    // The end: back to A.
    assert_eq!(m.last().map(|m| (m.kind, m.to)), Some((MoveKind::Rapid, p(62.0, 2.0))));
}

#[test]
fn a_monotone_shape_cuts_as_type_one_does() {
    let shape = [p(26.0, 2.0), p(30.0, -2.0), p(30.0, -40.0), p(44.0, -40.0), p(44.0, -60.0), p(52.0, -60.0)];
    let r = Rough { along: Along::Z, depth: 1.5, escape: 0.5, du: 0.4, dw: 0.1, pockets: true };
    let two = passes(&r, p(52.0, 2.0), &shape, 1, Span::default());
    let one = crate::cycle::rough::passes(&r, p(52.0, 2.0), &shape, 1, Span::default());
    let ends = |m: &[Move]| -> Vec<(f64, f64, f64)> {
        m.iter()
            .filter(|m| m.kind == MoveKind::Rough && m.from.z == 2.0)
            .map(|m| (m.from.x, r6(m.to.x), r6(m.to.z)))
            .collect()
    };
    assert_eq!(ends(&two), ends(&one));
    assert_eq!(ends(&two).len(), 8);
}

#[test]
fn g72_pockets_and_bad_input_end() {
    // G72 (cuts along X at Z depths): a face with a groove; nothing panics or runs on.
    let shape = [p(80.0, -8.0), p(60.0, -8.0), p(60.0, -2.0), p(50.0, -5.0), p(40.0, -5.0), p(30.0, 0.0), p(20.0, 0.0)];
    let r = Rough { along: Along::X, depth: 1.0, escape: 0.3, du: 0.0, dw: 0.0, pockets: true };
    let m = passes(&r, p(82.0, 1.0), &shape, 1, Span::default());
    let groove = m.iter().filter(|m| m.kind == MoveKind::Rough && (m.from.z - m.to.z).abs() < 1e-12 && m.from.x < 60.0);
    // The groove Z-2 … Z-5 between X60 and X30: cut at Z-3 and Z-4 (and its floor by the last cut).
    let zs: Vec<f64> = groove.filter(|m| m.to.x > 30.0 && m.from.x > m.to.x).map(|m| r6(m.from.z)).collect();
    assert!(zs.contains(&-3.0) && zs.contains(&-4.0), "{zs:?}");
    let tiny = Rough { depth: 1e-9, ..r };
    assert!(passes(&tiny, p(82.0, 1.0), &shape, 1, Span::default()).len() <= 9 * MAX_MOVES);
    assert!(passes(&r, p(82.0, 1.0), &shape[..1], 1, Span::default()).is_empty());
}

/// 500 contours rising and falling at random along X (monotone along Z,
/// some vertical walls), roughed by type II from a start point above them:
/// no panic, every motion finite, the bound on motions kept, every cut
/// along a depth starts at the start point's Z or on the shape and passes
/// over no point of the shifted shape that lies above its depth.
#[test]
fn random_pocketed_shapes_rough_within_the_shape() {
    let mut next = crate::hash::unit_floats(0x2545_f491_4f6c_dd1d);
    for _ in 0..500 {
        let n = 2 + (next() * 12.0) as usize;
        let mut z = 0.0;
        let mut shape = vec![p(10.0 + 20.0 * next(), z)];
        for _ in 1..n {
            z -= if next() < 0.2 { 0.0 } else { 1.0 + 10.0 * next() };
            shape.push(p(10.0 + 40.0 * next(), z));
        }
        let depth = 0.3 + 3.0 * next();
        let r = Rough { along: Along::Z, depth, escape: 0.5, du: 0.0, dw: 0.0, pockets: true };
        let a = p(60.0, 2.0);
        let m = passes(&r, a, &shape, 1, Span::default());
        assert!(m.len() <= MAX_MOVES + 2 * n + 40, "{}", m.len());
        assert!(m.iter().all(|m| m.to.x.is_finite() && m.to.z.is_finite()));
        for c in m.iter().filter(|m| m.kind == MoveKind::Rough && m.from.x == m.to.x && m.from.z > m.to.z + 1e-9) {
            let (z0, z1, x) = (c.from.z, c.to.z, c.from.x);
            let over = shape.iter().any(|q| q.z < z0 - 1e-6 && q.z > z1 + 1e-6 && q.x > x + 1e-6);
            assert!(!over, "the cut at X{x} from Z{z0} to Z{z1} passes through the shape {shape:?}");
        }
    }
}
