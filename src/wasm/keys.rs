//! Content keys of the parts of a plan the views draw: equal keys mean equal
//! inputs, so a scene or list built from them need not be built or sent again.
//!
//! Every field a drawing reads is hashed, numbers by their bits; the byte
//! span of a motion and a thread's first motion index are not (no drawing
//! reads them, and a comment typed above would change every span). The
//! structs are destructured without `..`, so a field added to a motion, pass
//! or thread does not compile here until it is hashed or named as unread (a
//! missed field would leave a drawing stale).
//! The hash is a fast multiplicative one with a final avalanche: changing one
//! word always changes the state (each step is a bijection), and the
//! finaliser spreads any change over the 52 bits a JavaScript number keeps exactly.

use std::hash::{Hash, Hasher};

pub use crate::hash::KeyHasher;
use std::mem::discriminant;

use crate::figures::{ChipLoad, Gauge, Shop};
use crate::motion::{ArcData, Move, Point};
use crate::plan::Plan;
use crate::planner::Changed;
use crate::thread::{Pass, Thread};

use super::pack::Packed;

/// A key as a JavaScript number: the low 52 bits of a hash, exact as an `f64`.
pub fn js_key(h: u64) -> f64 {
    (h & ((1u64 << 52) - 1)) as f64
}

/// The key of any hashable value.
pub fn key_of<T: Hash + ?Sized>(v: &T) -> u64 {
    let mut h = KeyHasher::default();
    v.hash(&mut h);
    h.finish()
}

/// Combines keys in order.
pub fn combine(keys: &[u64]) -> u64 {
    let mut h = KeyHasher::default();
    keys.iter().for_each(|k| h.write_u64(*k));
    h.finish()
}

fn f(h: &mut KeyHasher, v: f64) {
    h.write_u64(v.to_bits());
}

fn point(h: &mut KeyHasher, p: &Point) {
    let Point { x, z } = *p;
    f(h, x);
    f(h, z);
}

fn opt_point(h: &mut KeyHasher, p: &Option<Point>) {
    match p {
        Some(p) => {
            h.write_u8(1);
            point(h, p);
        }
        None => h.write_u8(0),
    }
}

/// Feeds a motion into `h`.
pub fn hash_move(h: &mut KeyHasher, m: &Move) {
    // The span is not drawn.
    let Move { kind, from, to, line, span: _, arc } = m;
    kind.hash(h);
    point(h, from);
    point(h, to);
    h.write_u32(*line);
    match arc {
        Some(ArcData { center, cw }) => {
            h.write_u8(if *cw { 2 } else { 1 });
            point(h, center);
        }
        None => h.write_u8(0),
    }
}

/// Feeds a pass into `h`.
pub fn hash_pass(h: &mut KeyHasher, p: &Pass) {
    let Pass {
        start,
        index,
        from,
        to,
        depth,
        infeed,
        role,
        lines,
        via,
        segments,
        runout_to,
        screw_in_from,
        shift,
        angle,
        area,
        // Where the motions are in the plan does not change the drawing: the motions themselves are keyed.
        moves: _,
        // The spindle and the shop-floor figures are not drawn.
        spindle: _,
    } = p;
    h.write_u32(*start);
    h.write_u32(*index);
    point(h, from);
    point(h, to);
    f(h, *depth);
    f(h, *infeed);
    discriminant(role).hash(h);
    lines.hash(h);
    via.hash(h);
    h.write_usize(segments.len());
    segments.iter().for_each(|s| point(h, s));
    opt_point(h, runout_to);
    opt_point(h, screw_in_from);
    f(h, *shift);
    f(h, *angle);
    match area {
        Some(a) => {
            h.write_u8(1);
            f(h, *a);
        }
        None => h.write_u8(0),
    }
}

/// The key of a thread with its passes.
pub fn thread_key(t: &Thread) -> u64 {
    let Thread {
        line,
        end_line,
        source,
        units,
        kind,
        long_axis,
        lead,
        pitch,
        starts,
        internal,
        infeed,
        tool_angle,
        crest,
        crest_source,
        turned,
        height,
        taper,
        passes,
        depth_dir,
        first_move: _, // not drawn
        shop,          // not drawn but for the shoulder
    } = t;
    let mut h = KeyHasher::default();
    h.write_u32(*line);
    h.write_u32(*end_line);
    discriminant(source).hash(&mut h);
    discriminant(units).hash(&mut h);
    discriminant(kind).hash(&mut h);
    discriminant(long_axis).hash(&mut h);
    f(&mut h, *lead);
    f(&mut h, *pitch);
    h.write_u32(*starts);
    h.write_u8(u8::from(*internal));
    discriminant(infeed).hash(&mut h);
    f(&mut h, *tool_angle);
    f(&mut h, *crest);
    discriminant(crest_source).hash(&mut h);
    opt(&mut h, *turned);
    f(&mut h, *height);
    f(&mut h, *taper);
    h.write_usize(passes.len());
    passes.iter().for_each(|p| hash_pass(&mut h, p));
    f(&mut h, *depth_dir);
    hash_shoulder(&mut h, shop.shoulder.as_ref());
    h.finish()
}

fn opt(h: &mut KeyHasher, v: Option<f64>) {
    match v {
        Some(v) => {
            h.write_u8(1);
            f(h, v);
        }
        None => h.write_u8(0),
    }
}

/// The key of a thread's shop-floor figures (what its summary and pass list
/// show besides the drawn fields).
pub fn shop_key(s: &Shop) -> u64 {
    let Shop {
        cut_time_s,
        time_s,
        pass_time_s,
        rpm,
        thread_feed,
        rpm_limit,
        lead_in_needed,
        run_out_needed,
        lead_in,
        run_out,
        clearance_source,
        pitch_diameter,
        helix_angle_deg,
        chip,
        gauge,
        shoulder,
        insert,
    } = s;
    let mut h = KeyHasher::default();
    for v in [
        *cut_time_s,
        *time_s,
        *rpm,
        *thread_feed,
        *rpm_limit,
        *lead_in_needed,
        *run_out_needed,
        *lead_in,
        *run_out,
        *pitch_diameter,
        *helix_angle_deg,
    ] {
        opt(&mut h, v);
    }
    h.write_usize(pass_time_s.len());
    pass_time_s.iter().for_each(|t| f(&mut h, *t));
    clearance_source.map(|c| c as u8).hash(&mut h);
    h.write_usize(chip.len());
    for ChipLoad { area, even_area, even_depth } in chip {
        [*area, *even_area, *even_depth].into_iter().for_each(|v| opt(&mut h, v));
    }
    match gauge {
        Some(g) => {
            h.write_u8(1);
            hash_gauge(&mut h, g);
        }
        None => h.write_u8(0),
    }
    hash_shoulder(&mut h, shoulder.as_ref());
    match insert {
        Some(i) => {
            h.write_u8(1);
            i.name.hash(&mut h);
            h.write_u8(u8::from(i.full));
            f(&mut h, i.nose_radius);
        }
        None => h.write_u8(0),
    }
    h.finish()
}

/// A shoulder clash (drawn in the side section: in the thread's key too).
fn hash_shoulder(h: &mut KeyHasher, s: Option<&crate::figures::Shoulder>) {
    match s {
        Some(s) => {
            h.write_u8(1);
            [s.z, s.edge_x, s.tip[0], s.tip[1], s.clearance, s.needed].into_iter().for_each(|v| f(h, v));
            h.write_usize(s.pass);
        }
        None => h.write_u8(0),
    }
}

fn hash_gauge(h: &mut KeyHasher, g: &Gauge) {
    let Gauge {
        designation,
        source,
        line,
        system,
        class,
        kind,
        basic_major,
        basic_pitch,
        basic_minor,
        pitch_diameter,
        pitch_diameter_min,
        pitch_diameter_max,
        major_diameter,
        major_diameter_min,
        major_diameter_max,
        minor_diameter,
        minor_diameter_min,
        minor_diameter_max,
        ok,
        delta_x,
        nose_radius,
        nose_radius_assumed,
        gauges_with_nose,
        taper,
        gauge_plane_z,
        over_wires,
        notes,
    } = g;
    designation.hash(h);
    discriminant(source).hash(h);
    line.hash(h);
    discriminant(system).hash(h);
    class.hash(h);
    discriminant(kind).hash(h);
    [*basic_major, *basic_pitch, *basic_minor, *pitch_diameter].into_iter().for_each(|v| f(h, v));
    for v in [
        *pitch_diameter_min,
        *pitch_diameter_max,
        *major_diameter,
        *major_diameter_min,
        *major_diameter_max,
        *minor_diameter,
        *minor_diameter_min,
        *minor_diameter_max,
        *delta_x,
        *taper,
        *gauge_plane_z,
    ] {
        opt(h, v);
    }
    f(h, *nose_radius);
    for v in over_wires.map_or([None; 4], |o| [Some(o.wire), Some(o.m), o.m_min, o.m_max]) {
        opt(h, v);
    }
    nose_radius_assumed.hash(h);
    opt(h, gauges_with_nose.map(|r| r[0]));
    opt(h, gauges_with_nose.map(|r| r[1]));
    ok.hash(h);
    h.write_usize(notes.len());
    for n in notes {
        n.render(crate::message::Lang::En).hash(h);
    }
}

/// The key of one motion (its span left out, as in [`hash_move`]).
pub fn move_key(m: &Move) -> u64 {
    let mut h = KeyHasher::default();
    hash_move(&mut h, m);
    h.finish()
}

/// The key of a packed scene's content (its view, bounds and focus too).
pub fn packed_key(p: &Packed) -> u64 {
    let mut h = KeyHasher::default();
    h.write_u8(p.view as u8);
    p.bounds.iter().chain(&p.focus).chain(&p.coords).for_each(|c| h.write_u64(c.to_bits()));
    p.items.hash(&mut h);
    p.lines.hash(&mut h);
    p.labels.hash(&mut h);
    h.finish()
}

/// The keys of a plan's drawn parts: each thread's, and the side section's
/// (every motion and thread: all that the side section reads).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlanKeys {
    /// One key per thread, in plan order.
    pub threads: Vec<u64>,
    /// The key of all threads together.
    pub all_threads: u64,
    /// One key per thread for its summary and pass list: the thread's key
    /// with its shop-floor figures (which are listed, not drawn).
    pub listed: Vec<u64>,
    /// The key of all listed threads together.
    pub all_listed: u64,
    /// The key of the side section's inputs.
    pub side: u64,
    /// One key per motion ([`move_key`]), in plan order: what the side
    /// key and the side section's pieces are made of, without reading the
    /// motions again.
    pub motions: Vec<u64>,
}

impl PlanKeys {
    /// The keys of `plan`.
    pub fn of(plan: &Plan) -> PlanKeys {
        PlanKeys::after(None, plan)
    }

    /// The keys of `plan`, taken from `last` (the keys of the plan before
    /// it) for the motions and threads that `Changed` says are that plan's;
    /// without `last`, all worked out.
    pub fn after(last: Option<(&PlanKeys, &Changed)>, plan: &Plan) -> PlanKeys {
        let was = |i: usize| last.and_then(|(k, c)| c.thread_was(i).filter(|&j| j < k.threads.len()).map(|j| (k, j)));
        let (threads, listed): (Vec<u64>, Vec<u64>) = plan
            .threads
            .iter()
            .enumerate()
            .map(|(i, t)| match was(i) {
                Some((k, j)) => (k.threads[j], k.listed[j]),
                None => {
                    let key = thread_key(t);
                    (key, combine(&[key, shop_key(&t.shop)]))
                }
            })
            .unzip();
        let motions = motion_keys(last, plan);
        let all_threads = combine(&threads);
        let side = combine(&[all_threads, combine(&motions), motions.len() as u64]);
        let all_listed = combine(&listed);
        PlanKeys { threads, all_threads, listed, all_listed, side, motions }
    }
}

/// Each motion's key: the last plan's for the motions `Changed` says are
/// its (kept before the resume point, or rejoined after the edit), else
/// worked out.
fn motion_keys(last: Option<(&PlanKeys, &Changed)>, plan: &Plan) -> Vec<u64> {
    let n = plan.moves.len();
    let mut out = Vec::with_capacity(n);
    let (kept, rejoined) = match last {
        Some((k, c)) => {
            let kept = c.moves_kept.min(n).min(k.motions.len());
            out.extend_from_slice(&k.motions[..kept]);
            let rejoined = c.moves_rejoined.filter(|&(new, old)| new >= kept && new <= n && old <= k.motions.len());
            (kept, rejoined.map(|(new, old)| (new, &k.motions[old..])))
        }
        None => (0, None),
    };
    let fresh_to = rejoined.map_or(n, |(new, _)| new);
    out.extend(plan.moves[kept..fresh_to].iter().map(move_key));
    if let Some((_, old)) = rejoined {
        let take = (n - fresh_to).min(old.len());
        out.extend_from_slice(&old[..take]);
        out.extend(plan.moves[fresh_to + take..].iter().map(move_key));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::Dialect;
    use crate::settings::Settings;

    const O1006: &str = include_str!("../../examples/o1006.nc");

    fn plan(text: &str) -> Plan {
        crate::plan(text, &Settings::new(Dialect::Gsk980tdc))
    }

    #[test]
    fn equal_plans_have_equal_keys() {
        assert_eq!(PlanKeys::of(&plan(O1006)), PlanKeys::of(&plan(O1006)));
        // A comment changes no motion and no thread (only byte spans, which are not drawn).
        let commented = O1006.replacen('\n', " (a note)\n", 1);
        assert_ne!(plan(O1006).moves[0].span, plan(&commented).moves[0].span);
        assert_eq!(PlanKeys::of(&plan(O1006)), PlanKeys::of(&plan(&commented)));
    }

    #[test]
    fn a_changed_pass_changes_its_thread_and_the_side_key_only() {
        let first = "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\nZ70\n";
        let text = format!("{first}G00 X40 Z30\nX35.1\nG32 Z5 F1.5\nG00 X40\nZ30\n");
        let a = PlanKeys::of(&plan(&text));
        let b = PlanKeys::of(&plan(&text.replace("X35.1", "X35.2")));
        assert_eq!(a.threads.len(), 2, "two threads");
        assert_eq!(a.threads[0], b.threads[0]);
        assert_ne!(a.threads[1], b.threads[1]);
        assert_ne!((a.all_threads, a.side), (b.all_threads, b.side));
        // A motion that belongs to no thread changes the side key alone.
        let c = PlanKeys::of(&plan(&format!("{text}G00 X60 Z80\n")));
        assert_eq!((c.threads[0], c.all_threads), (a.threads[0], a.all_threads));
        assert_ne!(c.side, a.side);
    }

    #[test]
    fn one_changed_word_changes_the_key() {
        let a: Vec<u64> = (0..64).map(|i| key_of(&[1u64, 2, i, 4])).collect();
        let mut sorted = a.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), a.len());
        assert_ne!(key_of("ab"), key_of("ab\0"));
        assert_ne!(combine(&[1, 2]), combine(&[2, 1]));
        // Keys fit a JS number exactly and use its bits.
        assert!(a.iter().all(|k| js_key(*k) < (1u64 << 52) as f64));
        assert!(a.iter().any(|k| js_key(*k) >= (1u64 << 51) as f64));
    }

    /// After each edit, the keys taken from the last plan's where the
    /// planner kept its motions and threads are the keys worked out anew.
    #[test]
    fn keys_after_an_edit_are_the_keys_of_the_plan() {
        // Threads on their own diameters (13 lines each: checkpoints every 256 blocks fall inside).
        let mut lines: Vec<String> = vec!["G50 X100 Z100".into()];
        for k in 0..60 {
            let d = 30 + k % 9;
            lines.extend([
                format!("G00 X{} Z70", d + 10),
                format!("G01 X{d} F0.2"),
                "Z20".into(),
                format!("X{}", d + 5),
                "G00 Z70".into(),
            ]);
            for x in [0.9, 1.5] {
                lines.extend([
                    format!("X{:.1}", f64::from(d) - x),
                    "G32 Z13 F2".into(),
                    format!("G00 X{}", d + 10),
                    "Z70".into(),
                ]);
            }
        }
        lines.push("M30".into());
        let pool = ["X31.1", "G32 Z14 F2", "Z70", "(M36x2-6g)", "M05", "G00 X60 Z90", "X", "G04 P1", ""];
        let mut planner = crate::planner::Planner::new(Settings::new(Dialect::Gsk980tdc));
        let mut keys = PlanKeys::of(planner.plan(&lines.join("\n")));
        // A designation written before a thread that lies after the join (the
        // checkpoint at line 513 falls between it and its first pass at 514):
        // that thread of the kept rest is finished anew, and its figures change.
        lines[509].push_str(" (M36x2-6g)");
        let plan = planner.plan(&lines.join("\n")).clone();
        let changed = planner.changed().expect("an edit of a plan").clone();
        let (new, _) = changed.threads_rejoined.expect("joined");
        let i = *changed.refinished.iter().find(|&&i| i >= new).expect("a thread after the join finished anew");
        let fresh = PlanKeys::of(&plan);
        assert_ne!(fresh.listed[i], keys.listed[i], "its figures changed");
        assert_eq!(PlanKeys::after(Some((&keys, &changed)), &plan), fresh);
        keys = fresh;
        let mut next = crate::hash::unit_floats(0x51_7cc1);
        let (mut reused, mut rejoined) = (0, 0);
        for round in 0..300 {
            let at = 1 + (next() * (lines.len() - 2) as f64) as usize;
            match round % 10 {
                // A digit typed at the end of a line, most often.
                0..=5 => lines[at].push('1'),
                6 => lines[at] = pool[(next() * pool.len() as f64) as usize].to_string(),
                7 => lines.insert(at, pool[(next() * pool.len() as f64) as usize].to_string()),
                8 => {
                    lines.remove(at);
                }
                _ => {
                    lines[at].pop();
                }
            }
            let plan = planner.plan(&lines.join("\n")).clone();
            let fresh = PlanKeys::of(&plan);
            let changed = planner.changed().expect("an edit of a plan").clone();
            let after = PlanKeys::after(Some((&keys, &changed)), &plan);
            assert_eq!(after, fresh, "round {round}: {changed:?}");
            reused += usize::from(changed.moves_kept > 0);
            rejoined += usize::from(changed.moves_rejoined.is_some());
            keys = after;
        }
        assert!(reused > 100 && rejoined > 100, "kept {reused}, rejoined {rejoined} of 300");
    }
}
