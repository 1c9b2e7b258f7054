//! The LinuxCNC dialect's o-words, parameters and expressions against
//! LinuxCNC's own interpreter, `rs274` (Debian `linuxcnc-uspace`
//! 2.9.0~pre1+git20230208.f1270d6ed7): the programs `tests/linuxcnc/oword-*.ngc`
//! (what each shows: `tests/linuxcnc/README.md`; the semantics with their
//! sources: the project note `linuxcnc-owords.md`).
//!
//! Learnt from LinuxCNC's G-code manual, chapter "O Codes"
//! (`docs/src/gcode/o-code.adoc`: sub/endsub/call with up to 30 arguments,
//! return values in `#<_value>`, while, do, repeat, if/elseif/else, break,
//! continue, nesting) and "G-code Overview" (`docs/src/gcode/overview.adoc`:
//! Parameters, Numbered/Subroutine/Named Parameters, Expressions, Binary
//! Operators and their precedence, Functions, Item order: "A parameter
//! setting does not take effect until after all parameter values on the
//! same line have been found"), and from the interpreter itself, read at
//! the packaged commit in `src/emc/rs274ngc/`: `interp_o_word.cc`
//! (`convert_control_functions`, `execute_call`, `execute_return`,
//! `control_back_to`: a call of a sub not yet defined reads ahead for it;
//! `control_save_offset`; `enter_context`: 10 call levels), `interp_read.cc`
//! (`read_o`: labels local to the sub, call arguments, return values read
//! with the line; `read_text`; `read_real_expression`, `read_real_value`,
//! `read_atan`, `read_parameter_setting`), `interp_internal.cc`
//! (`precedence`), `interp_execute.cc` (`execute_binary1/2`,
//! `execute_unary`), `interp_namedparams.cc` (`find_named_param`,
//! `add_named_param`, `store_named_param`: `#<_name>` global, `#<name>`
//! local to its call level) and `rs274ngc_pre.cc` (`Interp::_execute`: the
//! parameter settings of a line are stored after it is read, o-word lines
//! are not executed as blocks; `Interp::_read`).
//!
//! Every program rs274 accepts: no alarm; every synchronised move of the
//! plan (Thread, ScrewIn, Runout) is rs274's synchronised `STRAIGHT_FEED`,
//! in order, within 0.001 (rs274's X is a radius, the plan's a diameter),
//! at the lead rs274 synchronises to, and — when rs274 runs live on the
//! numbered program — made by the same source line (inside a subroutine,
//! the subroutine's block, not the call); the rapids and plain feeds are
//! rs274's traverses and feeds, in order, once the plan knows where the
//! tool is (rs274 starts at X0 Z0), zero-length moves left out on both
//! sides. Every program rs274 refuses: an alarm on the line it names whose
//! message contains rs274's (without the file name rs274 puts in two of
//! them; whitespace ignored, since rs274 quotes the line as written), no
//! alarm on an earlier line, and the synchronised moves rs274 made before
//! refusing are the plan's first ones. The `oword-quirk-*` programs are
//! accepted programs where rs274 does what its source says rather than what
//! the manual suggests (a break's or continue's flag left set, a repeat
//! count left over by a return, `#<_value>` cleared by passing over a
//! definition, a named parameter created by its own line): their own test.
//!
//! rs274 runs live. Without it the test fails when `CI` is set; otherwise it
//! compares with the recordings in `tests/linuxcnc/` and says so.

mod common;
#[path = "common/rs274.rs"]
mod rs274;

use common::plan_with;
use rs274::{Call, Kind, Segment, dir, lines_of_n, live, read, synced_runs};
use screwcut::motion::{Move, MoveKind, Point};
use screwcut::{Dialect, Plan, Severity};
use std::collections::HashMap;

const TOL: f64 = 0.001;

/// The recorded o-word programs whose names start with `prefix`, sorted.
fn programs(prefix: &str) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".ngc").map(str::to_owned))
        .filter(|n| n.starts_with(prefix))
        .collect();
    v.sort();
    v
}

/// The programs rs274 runs to the end, quirks and profile roughing aside.
fn accepted() -> Vec<String> {
    let own = ["oword-err-", "oword-quirk-", "oword-g71-", "oword-g72-"];
    programs("oword-").into_iter().filter(|n| !own.iter().any(|p| n.starts_with(p))).collect()
}

/// rs274's verdict on one program.
struct Verdict {
    /// The calls it made (before the error, if it refused the program).
    calls: Vec<Call>,
    /// Its message and the block it names, if it refused the program.
    refused: Option<(String, String)>,
    /// Each N word's source line, when rs274 ran the numbered program (live).
    lines: Option<HashMap<u64, u32>>,
}

fn split(err: &str) -> (String, String) {
    let (message, block) = err.split_once('\n').unwrap_or((err, ""));
    (message.to_string(), block.to_string())
}

/// rs274 on `text` (the recording `name` when rs274 is not installed);
/// `numbered`: run it with each line's number as its N word.
fn oracle(name: &str, text: &str, numbered: bool) -> Verdict {
    if live() {
        let program = if numbered { rs274::numbered(text) } else { text.to_string() };
        let (calls, err) = rs274::run_keeping(&program).unwrap_or_else(|e| panic!("{name}: {e}"));
        let lines = numbered.then(|| lines_of_n(&program));
        return Verdict { calls, refused: err.as_deref().map(split), lines };
    }
    let calls = rs274::parse(&read(&format!("{name}.out"))).unwrap_or_else(|e| panic!("{name}.out: {e}"));
    let err = read(&format!("{name}.err"));
    let refused = (err.lines().count() > 1).then(|| split(&err.lines().skip(1).collect::<Vec<_>>().join("\n")));
    Verdict { calls, refused, lines: None }
}

fn linuxcnc(program: &str) -> Plan {
    plan_with(program, Dialect::LinuxCnc, &[])
}

fn alarms(plan: &Plan) -> Vec<&screwcut::Diagnostic> {
    plan.diagnostics.iter().filter(|d| d.severity == Severity::Error).collect()
}

fn is_synced(kind: MoveKind) -> bool {
    matches!(kind, MoveKind::Thread | MoveKind::ScrewIn | MoveKind::Runout)
}

/// The plan's synchronised moves, in order, with their index in `plan.moves`.
fn synced_moves(plan: &Plan) -> Vec<(usize, &Move)> {
    plan.moves.iter().enumerate().filter(|(_, m)| is_synced(m.kind)).collect()
}

/// rs274's synchronised moves, in order.
fn synced_segments(calls: &[Call]) -> Vec<Segment> {
    synced_runs(calls).into_iter().flatten().collect()
}

#[track_caller]
fn same_point(what: &str, (x, z): (f64, f64), ours: Point) {
    assert!(
        (ours.x / 2.0 - x).abs() <= TOL && (ours.z - z).abs() <= TOL,
        "{what}: screwcut ({}, {}) (radius, z), rs274 ({x}, {z})",
        ours.x / 2.0,
        ours.z
    );
}

/// The first `theirs.len()` synchronised moves of the plan are rs274's:
/// ends, source lines (`lines`: each N word's line, when rs274 ran live) and leads.
fn same_synced(name: &str, plan: &Plan, theirs: &[Segment], lines: Option<&HashMap<u64, u32>>) {
    let ours = synced_moves(plan);
    assert!(
        ours.len() >= theirs.len(),
        "{name}: {} synchronised moves, rs274 {}: {:?}",
        ours.len(),
        theirs.len(),
        theirs.iter().map(|s| s.to).collect::<Vec<_>>()
    );
    let mut at = HashMap::new();
    for (k, ((i, m), s)) in ours.iter().zip(theirs).enumerate() {
        same_point(&format!("{name}: synchronised move {k} (line {}) start", m.line), s.from, m.from);
        same_point(&format!("{name}: synchronised move {k} (line {}) end", m.line), s.to, m.to);
        if let Some(lines) = lines {
            let theirs = s.n.and_then(|n| lines.get(&n));
            assert_eq!(
                Some(&m.line),
                theirs,
                "{name}: synchronised move {k} to {:?} is line {}'s, rs274's is line {theirs:?}'s",
                s.to,
                m.line
            );
        }
        at.insert(*i, *s);
    }
    // The lead: rs274 synchronises each G33 to K along the move, each G76
    // cut to P (the first cut of a pass; a chain's next blocks have their own).
    for t in &plan.threads {
        for p in &t.passes {
            let first = p.moves.cut.clone().find(|&i| plan.moves[i].kind == MoveKind::Thread);
            if let Some(s) = first.and_then(|i| at.get(&i)) {
                let (dx, dz) = (s.to.0 - s.from.0, s.to.1 - s.from.1);
                let long = dx.abs().max(dz.abs());
                let lead = s.pitch.abs() * long / dx.hypot(dz);
                assert!(
                    (lead - t.lead).abs() < 1e-5,
                    "{name}: line {} pass {}: lead {}, rs274 synchronises to {} ({lead} along the long axis)",
                    t.line,
                    p.index,
                    t.lead,
                    s.pitch
                );
            }
        }
    }
}

/// A rapid or plain feed: (is a rapid, radius, z).
type Plain = (bool, f64, f64);

/// rs274's traverses and unsynchronised feeds, without zero-length moves.
fn plain_theirs(calls: &[Call]) -> Vec<Plain> {
    let (mut out, mut at) = (Vec::new(), (0.0, 0.0));
    for c in calls {
        match *c {
            Call::Move { kind, x, z, .. } => {
                let moved = (x - at.0).abs() > 1e-9 || (z - at.1).abs() > 1e-9;
                match kind {
                    Kind::Traverse if moved => out.push((true, x, z)),
                    Kind::Feed if moved => out.push((false, x, z)),
                    _ => {}
                }
                at = (x, z);
            }
            Call::Arc { x, z, .. } => at = (x, z),
            _ => {}
        }
    }
    out
}

/// The plan's rapids and plain feeds (roughing cuts among them; arcs
/// not), without zero-length moves.
fn plain_ours(plan: &Plan) -> Vec<Plain> {
    plan.moves
        .iter()
        .filter(|m| matches!(m.kind, MoveKind::Rapid | MoveKind::Feed | MoveKind::Rough) && m.arc.is_none())
        .filter(|m| m.from.dist(m.to) > 1e-9)
        .map(|m| (m.kind == MoveKind::Rapid, m.to.x / 2.0, m.to.z))
        .collect()
}

/// The plan's rapids and plain feeds are rs274's, after the (at most two)
/// moves rs274 makes from its start point before the plan knows X and Z.
fn same_plain(name: &str, plan: &Plan, calls: &[Call]) {
    let theirs = plain_theirs(calls);
    let ours = plain_ours(plan);
    let skipped = theirs.len().saturating_sub(ours.len());
    assert!(
        skipped <= 2 && ours.len() <= theirs.len(),
        "{name}: {} rapids and feeds, rs274 {}:\nscrewcut {ours:?}\nrs274 {theirs:?}",
        ours.len(),
        theirs.len()
    );
    for (k, (o, t)) in ours.iter().zip(&theirs[skipped..]).enumerate() {
        assert!(
            o.0 == t.0 && (o.1 - t.1).abs() <= TOL && (o.2 - t.2).abs() <= TOL,
            "{name}: rapid or feed {k}: screwcut {} to ({}, {}) (radius, z), rs274 {} to ({}, {})",
            if o.0 { "rapid" } else { "feed" },
            o.1,
            o.2,
            if t.0 { "traverse" } else { "feed" },
            t.1,
            t.2
        );
    }
}

/// Compares an accepted program with rs274; returns how many synchronised moves were compared.
fn check_accepted(name: &str) -> usize {
    let text = read(&format!("{name}.ngc"));
    let v = oracle(name, &text, true);
    if let Some((message, block)) = &v.refused {
        panic!("{name}: rs274 refuses it: {message} ({block})");
    }
    let plan = linuxcnc(&text);
    let a = alarms(&plan);
    assert!(a.is_empty(), "{name}: rs274 accepts it, screwcut alarms: {a:#?}");
    let theirs = synced_segments(&v.calls);
    assert!(!theirs.is_empty(), "{name}: rs274 cuts nothing synchronised");
    let ours = synced_moves(&plan).len();
    assert_eq!(ours, theirs.len(), "{name}: {ours} synchronised moves, rs274 {}", theirs.len());
    same_synced(name, &plan, &theirs, v.lines.as_ref());
    same_plain(name, &plan, &v.calls);
    theirs.len()
}

/// Runs `check` on every program, then fails naming all that failed (each
/// failure's message is printed as it happens); returns the sum of the results.
fn each(names: &[String], check: fn(&str) -> usize) -> usize {
    let mut failed = Vec::new();
    let mut sum = 0;
    for n in names {
        match std::panic::catch_unwind(|| check(n)) {
            Ok(k) => sum += k,
            Err(_) => failed.push(n.as_str()),
        }
    }
    assert!(failed.is_empty(), "{} of {} programs differ from rs274: {failed:?}", failed.len(), names.len());
    sum
}

#[test]
fn accepted_programs_cut_what_rs274_cuts() {
    let names = accepted();
    assert!(names.len() >= 14, "{names:?}");
    let compared = each(&names, check_accepted);
    assert!(compared >= 150, "{compared} synchronised moves compared");
}

#[test]
fn quirks_are_rs274s() {
    let names = programs("oword-quirk-");
    assert!(names.len() >= 5, "{names:?}");
    each(&names, check_accepted);
}

/// The line rs274's message names ("… from line: 14"), if it names one.
fn line_in_message(message: &str) -> Option<u32> {
    let (_, rest) = message.split_once("from line: ")?;
    rest.split(|c: char| !c.is_ascii_digit()).next()?.parse().ok()
}

fn squash(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// Compares a refused program with rs274; returns 1.
fn check_refused(name: &str) -> usize {
    let text = read(&format!("{name}.ngc"));
    let v = oracle(name, &text, false);
    let (message, block) = v.refused.clone().unwrap_or_else(|| panic!("{name}: rs274 accepts it"));
    let message = rs274::without_file(&message).to_string();
    // A sub sought to the end of the file: rs274 names the call's line
    // in its message and quotes the file's last block. A G70–G72 refused
    // once its profile is read: rs274 quotes the profile's last block, its
    // endsub; the alarm is the cycle's.
    let cycle = text.lines().position(|l| ["G70", "G71", "G72"].iter().any(|g| l.trim_start().starts_with(g)));
    let line = line_in_message(&message).unwrap_or_else(|| {
        let i = match cycle {
            Some(k) if message.starts_with("G7X error") && block.trim().ends_with("endsub") => Some(k),
            _ => text.lines().position(|l| l.trim() == block.trim()),
        };
        i.unwrap_or_else(|| panic!("{name}: rs274's block {block:?} is not a line")) as u32 + 1
    });
    let plan = linuxcnc(&text);
    let a = alarms(&plan);
    assert!(
        a.iter().all(|d| d.line >= line),
        "{name}: an alarm before line {line}, where rs274 stops ({message:?}): {a:#?}"
    );
    assert!(
        a.iter().any(|d| d.line == line && squash(&d.message).contains(&squash(&message))),
        "{name}: no alarm on line {line} saying rs274's {message:?}: {a:#?}"
    );
    // What rs274 cut before it stopped, the plan cuts first.
    same_synced(name, &plan, &synced_segments(&v.calls), None);
    1
}

#[test]
fn refused_programs_alarm_where_rs274_stops() {
    let names = programs("oword-err-");
    assert!(names.len() >= 6, "{names:?}");
    each(&names, check_refused);
}

/// A move that goes somewhere, as both sides print it (to 4 decimals):
/// rapid, feed or arc, to (radius, z), an arc's centre (radius, z) and
/// whether it turns counter-clockwise (G3).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Any {
    rapid: bool,
    to: (f64, f64),
    arc: Option<(f64, f64, bool)>,
}

/// rs274's moves, those that go somewhere.
fn all_theirs(calls: &[Call]) -> Vec<Any> {
    let (mut out, mut at) = (Vec::new(), (0.0, 0.0));
    for c in calls {
        let m = match *c {
            Call::Move { kind, x, z, .. } => Any { rapid: kind == Kind::Traverse, to: (x, z), arc: None },
            Call::Arc { x, z, cx, cz, ccw, .. } => Any { rapid: false, to: (x, z), arc: Some((cx, cz, ccw)) },
            _ => continue,
        };
        if m.to != at {
            out.push(m);
        }
        at = m.to;
    }
    out
}

/// The plan's moves, rounded as rs274 prints them, those that go somewhere.
fn all_ours(plan: &Plan) -> Vec<Any> {
    let r = |v: f64| (v * 1e4).round() / 1e4;
    let (mut out, mut at) = (Vec::new(), None);
    for m in &plan.moves {
        let to = (r(m.to.x / 2.0), r(m.to.z));
        let arc = m.arc.filter(|_| !matches!(m.kind, MoveKind::Rapid));
        if Some(to) != at {
            out.push(Any {
                rapid: m.kind == MoveKind::Rapid,
                to,
                arc: arc.map(|a| (a.center.x / 2.0, a.center.z, !a.cw)),
            });
        }
        at = Some(to);
    }
    out
}

/// Whether two moves agree to rs274's 4 decimals.
fn same_move(a: &Any, b: &Any) -> bool {
    let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() <= 1.5e-4 && (p.1 - q.1).abs() <= 1.5e-4;
    a.rapid == b.rapid
        && near(a.to, b.to)
        && match (a.arc, b.arc) {
            (None, None) => true,
            (Some(p), Some(q)) => near((p.0, p.1), (q.0, q.1)) && p.2 == q.2,
            _ => false,
        }
}

/// Compares a G71/G72 program with rs274 move for move: every traverse,
/// feed and arc in order (after the move rs274 makes from X0 Z0 before the
/// plan knows where the tool is), and the synchronised moves of a thread
/// after it; returns how many moves were compared.
fn check_profile_cycle(name: &str) -> usize {
    let text = read(&format!("{name}.ngc"));
    let v = oracle(name, &text, false);
    if let Some((message, block)) = &v.refused {
        panic!("{name}: rs274 refuses it: {message} ({block})");
    }
    let plan = linuxcnc(&text);
    let a = alarms(&plan);
    assert!(a.is_empty(), "{name}: rs274 accepts it, screwcut alarms: {a:#?}");
    let roughs = text.lines().any(|l| ["G71", "G72"].iter().any(|g| l.contains(g)) && l.contains('Q'));
    assert!(!roughs || plan.moves.iter().any(|m| m.kind == MoveKind::Rough), "{name}: no roughing cut");
    let (theirs, ours) = (all_theirs(&v.calls), all_ours(&plan));
    let skipped = theirs.len().saturating_sub(ours.len());
    assert!(skipped <= 1 && ours.len() <= theirs.len(), "{name}: {} moves, rs274 {}", ours.len(), theirs.len());
    for (k, (o, t)) in ours.iter().zip(&theirs[skipped..]).enumerate() {
        assert!(same_move(o, t), "{name}: move {k}: screwcut {o:?}, rs274 {t:?} (radius, z)");
    }
    let synced = synced_segments(&v.calls);
    assert_eq!(synced_moves(&plan).len(), synced.len(), "{name}: synchronised moves");
    same_synced(name, &plan, &synced, None);
    ours.len()
}

/// LinuxCNC's G70, G71 and G72 (and .1, .2) with their profile in a
/// subroutine, against rs274 move for move (`cycle::g7x`): `oword-g70-*`,
/// `oword-g71-*`, `oword-g72-*`, and `words-g70-g72` (G70 with D, E and P).
#[test]
fn profile_cycles_move_for_move() {
    let mut names = programs("oword-g71-");
    names.extend(programs("oword-g72-"));
    names.extend(programs("oword-g70-"));
    names.push("words-g70-g72".into());
    assert!(names.len() >= 7, "{names:?}");
    let compared = each(&names, check_profile_cycle);
    assert!(compared >= 400, "{compared} moves compared");
}

#[track_caller]
fn approx(ours: &[f64], want: &[f64]) {
    assert!(
        ours.len() == want.len() && ours.iter().zip(want).all(|(a, b)| (a - b).abs() < TOL),
        "{ours:?} != {want:?}"
    );
}

/// A few of the semantics in numbers (rs274's, from the recordings), so
/// that a failure reads without the oracle.
#[test]
fn semantics_in_numbers() {
    let plan = |name: &str| linuxcnc(&read(&format!("{name}.ngc")));
    let cut_x =
        |p: &Plan| -> Vec<f64> { p.moves.iter().filter(|m| m.kind == MoveKind::Thread).map(|m| m.from.x).collect() };
    // Settings on a line take effect after it is read: X#1 #1=… moves to the old #1.
    approx(&cut_x(&plan("oword-same-line")), &[11.4, 11.0, 10.7, 10.4, 10.4]);
    // Arguments not passed are 0 in the sub; #1–#30 come back after the call.
    let p = plan("oword-args-unpassed");
    let z: Vec<f64> = p.moves.iter().filter(|m| m.kind == MoveKind::Thread).map(|m| m.from.z).collect();
    approx(&z, &[3.2, 3.0, 3.5, 3.0]);
    // M2 inside a subroutine ends the program: the G33 after the call never runs.
    assert_eq!(cut_x(&plan("oword-m2-in-sub")).len(), 4);
    // if/elseif/else: M6 1, M8 1.25, M10 1.5, M12 1.75.
    let mut leads: Vec<f64> = plan("oword-if-elseif").threads.iter().map(|t| t.lead).collect();
    leads.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    approx(&leads, &[1.0, 1.25, 1.5, 1.75]);
    // Locals of the subs are not the main program's #<x> (99), and the
    // subs counted 8 passes in #<_passes>: the last rapid goes to X29 Z38.
    let p = plan("oword-named-params");
    let last = p.moves.iter().rev().find(|m| m.kind == MoveKind::Rapid).unwrap();
    common::pt(last.to, 29.0, 38.0);
    // continue skips two passes, break ends the loop: 7 passes, then the full depth.
    assert_eq!(cut_x(&plan("oword-break-continue")).len(), 8);
    // A break leaves a flag that makes the next do/while run once: one spring pass, not three.
    approx(&cut_x(&plan("oword-quirk-break-then-do")), &[11.6, 11.2, 10.8, 10.4, 10.16]);
    // #<_value> is 0 after the reader passes over o<spring>'s endsub: the second pass is at X12.
    approx(&cut_x(&plan("oword-quirk-endsub-value")), &[10.92655, 12.0, 10.5]);
}

/// MOD as rs274 computes it (run here on `G0 X[-7 MOD 3] Z[7 MOD -3]`,
/// `G0 X[7.5 MOD 2]`, `G0 X[1 MOD 0]`: radius 2 and 1.5 at Z1, then
/// "Calculation resulted in 'not a number'"): the remainder is never negative.
/// (The first rapid, from where the tool was unknown, is not a move of the plan.)
#[test]
fn modulo_as_rs274() {
    let plan =
        linuxcnc("G18 G21 G90 G8\nG0 X5 Z5\nG0 X[-7 MOD 3] Z[7 MOD -3]\nG0 X[7.5 MOD 2] Z1\nG0 X[1 MOD 0]\nM2\n");
    let to: Vec<(f64, f64)> = plan.moves.iter().map(|m| (m.to.x / 2.0, m.to.z)).collect();
    assert_eq!(to, [(2.0, 1.0), (1.5, 1.0)]);
    let a = alarms(&plan);
    assert!(
        a.len() == 1 && a[0].line == 5 && a[0].message.contains("Calculation resulted in 'not a number'"),
        "{a:#?}"
    );
}
