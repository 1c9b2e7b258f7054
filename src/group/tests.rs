//! The chains' chunks shared with snapshots (`Cuts`): what a snapshot holds
//! never changes, and what is shared is not copied.

use super::*;
use crate::motion::Point;
use crate::thread::ThreadKind;

/// A chain of one piece whose first motion is `k` (what tells chains apart here).
fn chain(k: usize) -> Chain {
    let seg = Seg {
        from: Point::new(47.1, 70.0),
        to: Point::new(47.1, 13.0),
        runout_to: None,
        kind: ThreadKind::Straight,
        long: Axis::Z,
    };
    Chain {
        source: Source::G32,
        units: Units::Mm,
        lead: 2.0,
        segs: vec![seg],
        angle: 0.0,
        lines: vec![k as u32 + 1],
        approach: -1.0,
        span: Span::default(),
        first_move: k,
        tool_angle: 60.0,
        moves: PassMoves::default(),
        spindle: Spindle::default(),
        pending: None,
        via: None,
    }
}

fn firsts(c: &Cuts) -> Vec<usize> {
    c.iter().map(|c| c.first_move).collect()
}

/// A snapshot taken in the middle of a chunk keeps its chains as they were
/// while the reading pushes on and changes its last chain; the reading
/// copies neither the snapshot's chunks nor more than its last chain.
#[test]
fn a_snapshot_keeps_its_chains_and_shares_them() {
    let mut live: Cuts = (0..10).map(chain).collect();
    let snapshot = live.clone();
    assert!(snapshot == live);
    // A push after the snapshot begins a chunk of its own.
    live.push(chain(10));
    assert_eq!(live.chunks.len(), 2);
    assert!(Rc::ptr_eq(&live.chunks[0].0, &snapshot.chunks[0].0), "the first chunk is shared, not copied");
    // The last chain changed: the new chunk is the reading's alone, changed in place.
    live.last_mut().expect("a chain").first_move = 100;
    assert_eq!(live.chunks.len(), 2);
    assert_eq!(firsts(&live), [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 100]);
    assert_eq!(firsts(&snapshot), (0..10).collect::<Vec<_>>());
    // Another snapshot, then a change to the last chain: that chain alone is copied.
    let second = live.clone();
    live.last_mut().expect("a chain").first_move = 200;
    assert_eq!(firsts(&second), [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 100]);
    // The same chunks but the last: equal as far as the chains are.
    assert!(second != live);
    live.last_mut().expect("a chain").first_move = 100;
    assert!(second == live);
    live.last_mut().expect("a chain").first_move = 200;
    assert_eq!(firsts(&live), [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 200]);
    assert!(Rc::ptr_eq(&live.chunks[0].0, &snapshot.chunks[0].0));
    assert_eq!(live.chunks.last().map(|(c, n)| (c.len(), *n)), Some((1, 1)));
    assert_eq!((live.len, live.iter().count()), (11, 11));
}

/// Chains a dropped snapshot left past the reading's view of a chunk are
/// not the reading's: changing its last chain or pushing drops them.
#[test]
fn a_dropped_snapshots_chains_are_not_the_readings() {
    let mut live: Cuts = (0..3).map(chain).collect();
    let mut snapshot = live.clone();
    snapshot.push(chain(3)); // begins a chunk: the shared one keeps three chains
    // The reading changes its last chain (copied: still shared), then the snapshot goes.
    live.last_mut().expect("a chain").first_move = 20;
    drop(snapshot);
    live.push(chain(4));
    assert_eq!(firsts(&live), [0, 1, 20, 4]);
    let mut each = live.clone();
    each.each_mut(|c| c.first_move += 1000);
    assert_eq!(firsts(&each), [1000, 1001, 1020, 1004]);
    assert_eq!(firsts(&live), [0, 1, 20, 4], "a list sharing the chunks is left as it was");
    // Equal to the same chains pushed into one list (the chunks differ, not the chains).
    let third = Chain { first_move: 20, ..chain(2) };
    assert_eq!(live, (0..2).map(chain).chain([third, chain(4)]).collect::<Cuts>());
}
