//! The LinuxCNC dialect against LinuxCNC's own interpreter, `rs274`
//! (Debian `linuxcnc-uspace`; `cargo xtask test` installs it): every
//! synchronised move of the plan (G33 cuts, G76 in-moves, tapers and cuts)
//! equals rs274's `STRAIGHT_FEED` between `START_SPEED_FEED_SYNC` and
//! `STOP_SPEED_FEED_SYNCH` within 0.001 (X there is a radius), every G76
//! pass is one of rs274's synchronised runs, the G76 rapids are rs274's
//! traverses, and every program rs274 refuses gives an alarm with its
//! message on the block it names.
//!
//! rs274 runs live. Without it the test fails when `CI` is set; otherwise it
//! compares with the recordings in `tests/linuxcnc/` and says so.

mod common;
#[path = "common/rs274.rs"]
mod rs274;

use common::plan_with;
use rs274::{Call, Kind, Segment, dir, lines_of_n, live, read, synced_runs};
use screwcut::motion::{Move, MoveKind};
use screwcut::thread::{Role, Source};
use screwcut::{Code, Dialect, Plan};

const TOL: f64 = 0.001;

/// rs274's verdict on `program`: its calls, or its message and block.
/// `recorded` names the recording to use when rs274 is not installed.
fn oracle(program: &str, recorded: Option<&str>) -> Option<Result<Vec<Call>, String>> {
    if live() {
        return Some(rs274::run(program));
    }
    let name = recorded?;
    let err = read(&format!("{name}.err"));
    Some(if err.lines().count() > 1 {
        Err(err.lines().skip(1).collect::<Vec<_>>().join("\n"))
    } else {
        rs274::parse(&read(&format!("{name}.out")))
    })
}

fn linuxcnc(program: &str) -> Plan {
    plan_with(program, Dialect::LinuxCnc, &[])
}

/// The synchronised moves of the plan, in order, as (radius, z) pairs.
fn synced_moves(plan: &Plan) -> Vec<&Move> {
    plan.moves.iter().filter(|m| matches!(m.kind, MoveKind::Thread | MoveKind::ScrewIn | MoveKind::Runout)).collect()
}

#[track_caller]
fn same_point(what: &str, (x, z): (f64, f64), ours: screwcut::motion::Point) {
    assert!(
        (ours.x / 2.0 - x).abs() <= TOL && (ours.z - z).abs() <= TOL,
        "{what}: screwcut ({}, {}) (radius, z), rs274 ({x}, {z})",
        ours.x / 2.0,
        ours.z
    );
}

/// rs274's calls with each N word replaced by the source line it names.
fn by_line(program: &str, calls: &[Call]) -> Vec<Call> {
    let map = lines_of_n(program);
    let line = |n: Option<u64>| n.and_then(|n| map.get(&n)).map(|l| *l as u64);
    calls
        .iter()
        .map(|c| match c.clone() {
            Call::Move { kind, x, z, n } => Call::Move { kind, x, z, n: line(n) },
            Call::SyncStart { pitch, n } => Call::SyncStart { pitch, n: line(n) },
            Call::SyncStop { n } => Call::SyncStop { n: line(n) },
            other => other,
        })
        .collect()
}

/// Compares every synchronised move, the G76 passes run by run, the pitch
/// and the G76 rapids; returns how many synchronised moves were compared.
fn compare(name: &str, program: &str, calls: &[Call]) -> usize {
    let calls = &by_line(program, calls);
    let plan = linuxcnc(program);
    let alarms: Vec<_> = plan.diagnostics.iter().filter(|d| d.code.severity() == screwcut::Severity::Error).collect();
    assert!(alarms.is_empty(), "{name}: rs274 accepts it, screwcut alarms: {alarms:#?}");
    let runs = synced_runs(calls);
    let theirs: Vec<&Segment> = runs.iter().flatten().collect();
    let ours = synced_moves(&plan);
    assert_eq!(ours.len(), theirs.len(), "{name}: {} synchronised moves, rs274 {}", ours.len(), theirs.len());
    for (k, (m, s)) in ours.iter().zip(&theirs).enumerate() {
        same_point(&format!("{name}: synchronised move {k} start"), s.from, m.from);
        same_point(&format!("{name}: synchronised move {k} end"), s.to, m.to);
    }
    for t in &plan.threads {
        match t.source {
            Source::LinuxG76 => g76_passes(name, &plan, t, &runs),
            Source::LinuxG33 => g33_lead(name, &plan, t, &theirs),
            other => panic!("{name}: a {other:?} thread in a LinuxCNC plan"),
        }
    }
    rapids(name, &plan, calls);
    theirs.len()
}

/// Each G76 pass is one synchronised run: the same moves, in order, and the
/// main cut at the thread's lead.
fn g76_passes(name: &str, plan: &Plan, t: &screwcut::thread::Thread, runs: &[Vec<Segment>]) {
    let n = runs.iter().filter(|r| r.first().and_then(|s| s.n) == Some(t.line as u64)).count();
    assert_eq!(t.passes.len(), n, "{name}: {} passes, rs274 {n} runs of line {}", t.passes.len(), t.line);
    let mine: Vec<&Vec<Segment>> = runs.iter().filter(|r| r[0].n == Some(t.line as u64)).collect();
    for (p, run) in t.passes.iter().zip(mine) {
        let cut = &plan.moves[p.moves.cut.clone()];
        assert_eq!(
            cut.len(),
            run.len(),
            "{name}: pass {} has {} synchronised moves, rs274 {}",
            p.index,
            cut.len(),
            run.len()
        );
        for (m, s) in cut.iter().zip(run) {
            same_point(&format!("{name}: pass {}", p.index), s.to, m.to);
            if m.kind == MoveKind::Thread {
                assert!(
                    (s.pitch.abs() - t.lead).abs() < 1e-6,
                    "{name}: lead {} against rs274's pitch {}",
                    t.lead,
                    s.pitch
                );
            }
        }
        if let Some(i) = cut.iter().position(|m| m.kind == MoveKind::Thread) {
            same_point(&format!("{name}: pass {} from", p.index), run[i].from, p.from);
        }
    }
}

/// G33 K is along the move: the lead along the long axis is K times the
/// long axis's share of the length.
fn g33_lead(name: &str, plan: &Plan, t: &screwcut::thread::Thread, theirs: &[&Segment]) {
    for p in &t.passes {
        let m = &plan.moves[p.moves.cut.start];
        let s = theirs.iter().find(|s| (s.to.1 - m.to.z).abs() <= TOL && (s.to.0 - m.to.x / 2.0).abs() <= TOL).unwrap();
        let (dx, dz) = (s.to.0 - s.from.0, s.to.1 - s.from.1);
        let long = if dz.abs() >= dx.abs() { dz.abs() } else { dx.abs() };
        let lead = s.pitch.abs() * long / dx.hypot(dz);
        // K is written to six decimals: the passes of one thread give its lead
        // to a millionth (the grouping's `same_lead`), not closer.
        assert!(
            (lead - t.lead).abs() <= 1e-6 * lead,
            "{name}: lead {} against K {} along the move ({lead})",
            t.lead,
            s.pitch
        );
    }
}

/// Every rapid the plan draws for a G76 block is one of rs274's traverses of that block.
fn rapids(name: &str, plan: &Plan, calls: &[Call]) {
    let lines: Vec<u32> = plan.threads.iter().filter(|t| t.source == Source::LinuxG76).map(|t| t.line).collect();
    let theirs: Vec<(f64, f64)> = calls
        .iter()
        .filter_map(|c| match *c {
            Call::Move { kind: Kind::Traverse, x, z, n: Some(n) } if lines.contains(&(n as u32)) => Some((x, z)),
            _ => None,
        })
        .collect();
    let ours: Vec<&Move> = plan.moves.iter().filter(|m| m.kind == MoveKind::Rapid && lines.contains(&m.line)).collect();
    let mut at = 0;
    for m in ours {
        let k = theirs[at..].iter().position(|p| (p.0 - m.to.x / 2.0).abs() <= TOL && (p.1 - m.to.z).abs() <= TOL);
        let k = k.unwrap_or_else(|| {
            panic!("{name}: rapid to ({}, {}) is not among rs274's traverses {:?}", m.to.x / 2.0, m.to.z, &theirs[at..])
        });
        at += k + 1;
    }
}

/// The programs rs274 accepts: every recorded one, and a few more.
fn accepted() -> Vec<(String, String, bool)> {
    let mut v: Vec<(String, String, bool)> = std::fs::read_dir(dir())
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".ngc").map(str::to_owned))
        // The o-word programs have their own test (tests/linuxcnc_owords.rs).
        .filter(|n| !n.starts_with("err-") && !n.starts_with("oword-") && !n.starts_with("words-"))
        .map(|n| {
            let text = read(&format!("{n}.ngc"));
            (n, text, true)
        })
        .collect();
    v.sort();
    for (name, text) in MORE {
        v.push((name.to_string(), text.to_string(), false));
    }
    v
}

/// Programs beyond the recordings (numbered, so that rs274's N column gives the line).
const MORE: &[(&str, &str)] = &[
    (
        "g33-passes-g7",
        "G18 G21 G90 G7\nM3 S400\nG0 X22 Z3\nX19.2\nG33 Z-25 K1.5\nG0 X22\nZ3\nX18.6\nG33 Z-25 K1.5\nG0 X22\nZ3\nX18.16\nG33 Z-25 K1.5\nG0 X22\nZ3\nM30\n",
    ),
    ("g33-taper-inch-g91", "G18 G20 G8\nM4 S200\nG0 X0.6 Z0.2\nG91\nG33 X0.05 Z-1.2 K0.0714\nG0 X0.1\nZ1.2\nG90\nM2\n"),
    (
        "g76-internal-g7-q-tapers",
        "G18 G21 G90 G7\nM3 S300\nG0 X20 Z4\nG76 P2 Z-30 I2 J0.3 K2.4 R1.5 Q30 H2 E3 L3\nG0 Z10\nM2\n",
    ),
    (
        "g76-inch-g7-r2",
        "G18 G20 G90 G7\nM3 S300\nG0 X0.55 Z0.1\nG76 P0.0625 Z-0.75 I-0.05 J0.008 K0.0812 R2 Q29.5 H1 E0.06 L1\nM2\n",
    ),
    (
        "g76-two-threads",
        "G18 G21 G90 G8\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1 Q29.5 L2 E1.5\nG0 X15 Z0\nG76 P1 Z-10 I-0.5 J0.1 K0.65 R2\nM2\n",
    ),
];

#[test]
fn synchronised_moves_equal_rs274s() {
    let mut compared = 0;
    let mut programs = 0;
    for (name, text, recorded) in accepted() {
        let numbered = rs274::numbered(&text);
        let Some(calls) = oracle(&numbered, recorded.then_some(name.as_str())) else { continue };
        let calls = calls.unwrap_or_else(|e| panic!("{name}: rs274 refuses it: {e}"));
        let n = compare(&name, &numbered, &calls);
        compared += n;
        programs += 1;
        assert!(n > 0, "{name}: nothing synchronised");
    }
    assert!(programs >= 35, "{programs} programs compared");
    assert!(compared >= 280, "{compared} synchronised moves compared");
}

#[test]
fn g76_passes_follow_linuxcnc() {
    // g76-h2: three full-depth passes; g76-h-minus1: none; g76-float-extra-pass: two at K.
    let roles = |name: &str| -> Vec<Role> {
        linuxcnc(&read(&format!("{name}.ngc"))).threads[0].passes.iter().map(|p| p.role).collect()
    };
    assert_eq!(
        roles("g76-h2"),
        [Role::Rough, Role::Rough, Role::Rough, Role::Rough, Role::Finish, Role::Spring, Role::Spring]
    );
    assert!(roles("g76-h-minus1").iter().all(|r| *r == Role::Rough));
    let plan = linuxcnc(&read("g76-float-extra-pass.ngc"));
    let depths: Vec<f64> = plan.threads[0].passes.iter().map(|p| (p.depth * 1e9).round() / 1e9).collect();
    assert_eq!(depths, [0.3, 0.6, 0.9, 0.9]);
    assert_eq!(plan.with_code(Code::FloatExtraPass).count(), 1);
    // Compound angle: every pass has the same length; only full-depth passes reach Z1.
    let t = &linuxcnc(&read("g76-q29.5.ngc")).threads[0];
    let len = |p: &screwcut::thread::Pass| p.to.z - p.from.z;
    assert!(t.passes.iter().all(|p| (len(p) - len(&t.passes[0])).abs() < 1e-9));
    assert!((t.passes[0].to.z + 19.547382).abs() < 1e-6 && (t.passes[4].to.z + 20.0).abs() < 1e-12);
    assert_eq!(t.infeed, screwcut::thread::Infeed::Right);
}

/// Each error program: (name, code screwcut gives).
const ERRORS: &[(&str, Code)] = &[
    ("err-g33-after-m6", Code::SpindleNotTurning),
    ("err-g33-f-word", Code::UnexpectedWord),
    ("err-g33-h-word", Code::UnexpectedWord),
    ("err-g33-i-word", Code::UnexpectedWord),
    ("err-g33-j-word", Code::UnexpectedWord),
    ("err-g33-l-word", Code::UnexpectedWord),
    ("err-g33-modal", Code::MissingLead),
    ("err-g33-no-axis", Code::MissingWord),
    ("err-g33-no-k", Code::MissingLead),
    ("err-g33-no-spindle", Code::SpindleNotTurning),
    ("err-g33-p-word", Code::UnexpectedWord),
    ("err-g33-q-word", Code::UnexpectedWord),
    ("err-g33-r-word", Code::UnexpectedWord),
    ("err-g33-spindle-number", Code::ValueOutOfRange),
    ("err-g70-r-word", Code::UnexpectedWord),
    ("err-g71-e-word", Code::UnexpectedWord),
    ("err-g72-j-word", Code::UnexpectedWord),
    ("err-g76-after-m6", Code::SpindleNotTurning),
    ("err-g76-cutter-comp-radius", Code::CutterCompActive),
    ("err-g76-cutter-comp", Code::CutterCompActive),
    ("err-g76-d-word", Code::UnexpectedWord),
    ("err-g76-g41", Code::CutterCompActive),
    ("err-g76-h-fraction", Code::ValueOutOfRange),
    ("err-g76-i0", Code::ValueOutOfRange),
    ("err-g76-j-above-k", Code::ValueOutOfRange),
    ("err-g76-j-negative", Code::ValueOutOfRange),
    ("err-g76-j0", Code::ValueOutOfRange),
    ("err-g76-k-equals-j", Code::ValueOutOfRange),
    ("err-g76-l-fraction", Code::ValueOutOfRange),
    ("err-g76-l-negative", Code::ValueOutOfRange),
    ("err-g76-modal", Code::MissingLead),
    ("err-g76-no-k", Code::MissingThreadHeight),
    ("err-g76-no-p", Code::MissingLead),
    ("err-g76-no-spindle", Code::SpindleNotTurning),
    ("err-g76-no-z", Code::MissingWord),
    ("err-g76-p-minus1", Code::MissingLead),
    ("err-g76-rotary", Code::UnexpectedWord),
    ("err-g76-spindle-number", Code::ValueOutOfRange),
];

#[test]
fn refused_programs_give_linuxcncs_alarm() {
    let names: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".ngc").filter(|n| n.starts_with("err-")).map(str::to_owned))
        .collect();
    assert_eq!(names.len(), ERRORS.len(), "every error program has a case");
    for &(name, code) in ERRORS {
        let text = read(&format!("{name}.ngc"));
        let Some(verdict) = oracle(&text, Some(name)) else { continue };
        let err = verdict.expect_err(name);
        let (message, block) = err.split_once('\n').unwrap_or((&err, ""));
        let line = text.lines().position(|l| l.trim() == block.trim()).map(|i| i as u32 + 1);
        let plan = linuxcnc(&text);
        let alarms: Vec<_> =
            plan.diagnostics.iter().filter(|d| d.code.severity() == screwcut::Severity::Error).collect();
        assert_eq!(alarms.len(), 1, "{name}: {alarms:#?}");
        let d = alarms[0];
        assert_eq!(d.code, code, "{name}: {d:#?}");
        assert!(d.message.contains(message), "{name}: {:?} does not say rs274's {message:?}", d.message);
        assert_eq!(Some(d.line), line, "{name}: alarm on line {}, rs274 names {block:?} ({err:?})", d.line);
        // Nothing of the refused block is cut.
        assert!(plan.threads.iter().all(|t| !t.passes.iter().any(|p| p.lines.contains(&d.line))), "{name}");
    }
}

/// rs274 reads D, I, R and Q with the roughing cycles G71/G72 and D, E, P,
/// Q with G70 (its D message names only G71): `words-g70-g72` runs to its
/// end in rs274, and none of its profile-cycle blocks is an alarm here: G71
/// and G72 rough, G70 with D, E and P runs two passes off the profile (the
/// program's moves are compared with rs274's in tests/linuxcnc_owords.rs).
/// The words each of them does not take are refused with rs274's message
/// (`err-g70-r-word`, `err-g71-e-word`, `err-g72-j-word`, in the errors above).
#[test]
fn profile_cycles_take_the_words_rs274_takes() {
    let text = read("words-g70-g72.ngc");
    if let Some(verdict) = oracle(&text, Some("words-g70-g72")) {
        let calls = verdict.unwrap_or_else(|e| panic!("rs274 refuses words-g70-g72: {e}"));
        // Each cycle feeds: rs274 ran the profile, not only the word checks.
        assert!(calls.iter().filter(|c| matches!(c, Call::Move { kind: Kind::Feed, .. })).count() >= 10);
    }
    let plan = linuxcnc(&text);
    let cycles: Vec<u32> = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.starts_with('N') && [" G70 ", " G71 ", " G72 "].iter().any(|g| l.contains(g)))
        .map(|(i, _)| i as u32 + 1)
        .collect();
    assert_eq!(cycles, [10, 12, 14]);
    for line in cycles {
        let on_line: Vec<_> = plan.diagnostics.iter().filter(|d| d.line == line).collect();
        assert!(on_line.iter().all(|d| d.code.severity() != screwcut::Severity::Error), "line {line}: {on_line:#?}");
        assert!(plan.moves.iter().any(|m| m.line == line && m.kind == MoveKind::Rough), "line {line}");
        assert!(on_line.iter().all(|d| d.code != Code::NotSimulated), "line {line}: {on_line:#?}");
    }
}

/// A tool change (M6) stops the spindle in rs274, before the M3 of its own
/// block runs: a thread after `T1 M6` with no new M3 is LinuxCNC's alarm
/// (`err-g76-after-m6`, `err-g33-after-m6` above), and `g76-m6-m3` (M3 in
/// the tool change's block, then M3 alone after a second M6) cuts both threads.
#[test]
fn a_tool_change_stops_the_spindle() {
    let plan = linuxcnc(&read("g76-m6-m3.ngc"));
    assert!(!plan.has_alarm(), "{:#?}", plan.diagnostics);
    let sources: Vec<Source> = plan.threads.iter().map(|t| t.source).collect();
    assert_eq!(sources, [Source::LinuxG76, Source::LinuxG33]);
    assert_eq!(plan.threads[0].passes.len(), 5);
    // Without the M3 after the second tool change the G33 is refused.
    let without = read("g76-m6-m3.ngc").replace("N40 M3\n", "");
    let plan = linuxcnc(&without);
    assert_eq!(common::one(&plan, Code::SpindleNotTurning).line, 8);
    assert_eq!(plan.threads.len(), 1);
}

#[test]
fn warnings_where_linuxcnc_is_silent() {
    let warned = |name: &str, code: Code| {
        let plan = linuxcnc(&read(&format!("{name}.ngc")));
        assert!(plan.with_code(code).count() >= 1, "{name}: no {code}: {:#?}", plan.diagnostics);
    };
    warned("g76-r-below-1", Code::ValueReadAs);
    warned("g76-q-minus1", Code::ValueReadAs);
    warned("g76-e-negative", Code::ValueReadAs);
    warned("g76-taper-l5", Code::ValueReadAs);
    warned("g76-taper-l0", Code::ValueReadAs);
    warned("g76-p-odd", Code::OddPitch);
    warned("g33-k-odd", Code::OddPitch);
    warned("g76-h-minus1", Code::FullDepthSkipped);
    warned("g76-e-long", Code::BackwardCut);
    warned("g76-g17", Code::PlaneNotXz);
    warned("g76-x-word", Code::DriveLineKept);
    warned("g76-y-word", Code::DriveLineKept);
    warned("g33-taper", Code::LeadAlongPath);
    // Q-1 runs as Q0 and Q-2 the other way (g76-q-minus1).
    let plan = linuxcnc(&read("g76-q-minus1.ngc"));
    assert_eq!(plan.threads[0].infeed, screwcut::thread::Infeed::Radial);
    assert_eq!(plan.threads[1].infeed, screwcut::thread::Infeed::Left);
}

#[test]
fn diameter_and_radius_mode_and_distance_mode() {
    // g76-g7 and g76-straight cut the same path; g76-g91 too (Z-25 from Z5).
    let moves = |name: &str| {
        let plan = linuxcnc(&read(&format!("{name}.ngc")));
        plan.moves.iter().map(|m| (m.kind, m.from, m.to)).collect::<Vec<_>>()
    };
    let straight = moves("g76-straight");
    assert_eq!(straight.len(), 20);
    assert_eq!(moves("g76-g7"), straight);
    // g76-g91 has no N10 rapid from an unknown position either, and the same cycle.
    assert_eq!(moves("g76-g91"), straight);
    // The program starts in G8 (rs274's default) unless the setting says G7.
    let p = "G18\nM3 S300\nG0 X10 Z5\nG33 Z-20 K1.5\nG0 X12\nM2\n";
    assert_eq!(linuxcnc(p).threads[0].passes[0].from.x, 20.0);
    let g7 = plan_with(p, Dialect::LinuxCnc, &["linuxcnc.startup_x=diameter"]);
    assert_eq!(g7.threads[0].passes[0].from.x, 10.0);
}

#[test]
fn program_end_and_snippets() {
    let p = "G18\nM3 S300\nG0 X10 Z5\nG33 Z-20 K1.5\n";
    let plan = linuxcnc(p);
    assert_eq!(common::one(&plan, Code::NoProgramEnd).line, 4);
    assert_eq!(linuxcnc(&format!("%\n{p}%\n")).with_code(Code::NoProgramEnd).count(), 0);
    assert_eq!(plan_with(p, Dialect::LinuxCnc, &["linuxcnc.require_end=0"]).with_code(Code::NoProgramEnd).count(), 0);
    if let Some(v) = oracle(p, None) {
        assert!(v.unwrap_err().starts_with("File ended with no percent sign or program end"));
    }
}

/// What screwcut writes for LinuxCNC — the wizard's G33 and G76 programs and
/// expansions of other controllers' programs — rs274 runs, cutting the same
/// synchronised moves.
#[test]
fn written_programs_run_in_rs274() {
    use screwcut::wizard::{Form, Request, generate};
    let mut programs = Vec::new();
    for d in ["M10x1.5-6g", "M20x1.5-6H", "1/2-13 UNC-2A", "1/2-14 NPT", "M24xPh3P1.5"] {
        for form in [Form::G33, Form::LinuxG76] {
            let r = Request {
                designation: Some(d.into()),
                length: Some(20.0),
                dialect: Dialect::LinuxCnc,
                form,
                ..Request::default()
            };
            match generate(&r) {
                Ok(g) => programs.push((format!("{d} {form:?}"), g.program)),
                Err(e) => assert!(d.contains("NPT") && form == Form::LinuxG76, "{d} {form:?}: {e}"),
            }
        }
    }
    for (name, src, from) in [
        ("g76-fanuc", include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i),
        ("g92-two-start", include_str!("../examples/g92-two-start.nc"), Dialect::Gsk980tdc),
        ("g78-flank-alternating", include_str!("../examples/g78-flank-alternating.nc"), Dialect::Gsk980tdc),
        ("renhe-tails", include_str!("../examples/renhe-tails.nc"), Dialect::Renhe),
    ] {
        let plan = plan_with(src, from, &[]);
        programs.push((format!("{name} expanded"), screwcut::expand::expand(&plan, Dialect::LinuxCnc).program));
    }
    for (name, text) in programs {
        let numbered = rs274::numbered(&text);
        let Some(calls) = oracle(&numbered, None) else { return };
        let calls = calls.unwrap_or_else(|e| panic!("{name}: rs274 refuses it: {e}\n{text}"));
        assert!(compare(&name, &numbered, &calls) > 0, "{name}");
    }
}
