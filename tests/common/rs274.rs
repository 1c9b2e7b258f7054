//! Reader for the canonical output of LinuxCNC's stand-alone interpreter
//! `rs274` (Debian package `linuxcnc-uspace`), the oracle for the LinuxCNC
//! dialect. See `/work/notes/linuxcnc.md` and `tests/linuxcnc/`.
//!
//! `rs274 -g prog.ngc` prints one canonical call a line, e.g.
//! `   13 N20    STRAIGHT_FEED(8.8000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)`:
//! a call counter, the block's `N` word (`N.....` when it has none; six or
//! more digits run into the name: `N123456SELECT_PLANE(…)`), the call. Moves
//! give X Y Z A B C; **X is always a radius** (G7 halves X, I, J, K before
//! this), lengths are in the program's units (`USE_LENGTH_UNITS`). rs274
//! prints no file line numbers: [`numbered`] makes each block's N its line.
#![allow(dead_code)]

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

/// How a straight move is made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// `STRAIGHT_TRAVERSE`: rapid.
    Traverse,
    /// `STRAIGHT_FEED` without spindle synchronisation.
    Feed,
    /// `STRAIGHT_FEED` under `START_SPEED_FEED_SYNC`: distance along the
    /// move per spindle revolution (G33 K, G76 P, or G76's taper pitch).
    Synced(f64),
}

/// One canonical call that matters to a thread preview; others are skipped.
#[derive(Clone, Debug, PartialEq)]
pub enum Call {
    /// A straight move to radius `x`, axial `z`; `n` is the block's N word.
    Move { kind: Kind, x: f64, z: f64, n: Option<u64> },
    /// `ARC_FEED` in the XZ plane (Z is its first axis, X its second): to
    /// radius `x`, axial `z`, about radius `cx`, axial `cz`; `ccw` for a
    /// positive rotation (G3).
    Arc { x: f64, z: f64, cx: f64, cz: f64, ccw: bool, n: Option<u64> },
    /// `START_SPEED_FEED_SYNC(pitch, velocity_mode)`. G76 tapers change the
    /// pitch with a second start and no stop in between.
    SyncStart { pitch: f64, n: Option<u64> },
    /// `STOP_SPEED_FEED_SYNCH()`.
    SyncStop { n: Option<u64> },
    /// `SET_FEED_RATE(f)`.
    FeedRate(f64),
    /// `USE_LENGTH_UNITS(CANON_UNITS_INCHES)` is `true`, `…_MM` `false`.
    Inches(bool),
}

/// A synchronised move from `from` to `to` (radius, z) at `pitch`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub from: (f64, f64),
    pub to: (f64, f64),
    pub pitch: f64,
    pub n: Option<u64>,
}

/// Parses rs274's standard output; a line that is not a call is an error.
pub fn parse(text: &str) -> Result<Vec<Call>, String> {
    let mut calls = Vec::new();
    let mut sync = None;
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let bad = || format!("line {}: not a canonical call: {line:?}", i + 1);
        let rest = line.trim_start();
        let rest = rest.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start();
        let rest = rest.strip_prefix('N').ok_or_else(bad)?;
        let (n, rest) = match rest.strip_prefix(".....") {
            Some(r) => (None, r),
            None => {
                let d = rest.find(|c: char| !c.is_ascii_digit()).unwrap_or(rest.len());
                (Some(rest[..d].parse().map_err(|_| bad())?), &rest[d..])
            }
        };
        let (name, args) = rest.trim().strip_suffix(')').and_then(|r| r.split_once('(')).ok_or_else(bad)?;
        let nums = || -> Result<Vec<f64>, String> {
            args.split([',', ' ']).filter(|a| !a.is_empty()).map(|a| a.parse().map_err(|_| bad())).collect()
        };
        let call = match name {
            "STRAIGHT_TRAVERSE" | "STRAIGHT_FEED" => {
                let v = nums()?;
                let kind = match (name, sync) {
                    ("STRAIGHT_TRAVERSE", _) => Kind::Traverse,
                    (_, Some(p)) => Kind::Synced(p),
                    _ => Kind::Feed,
                };
                Call::Move { kind, x: *v.first().ok_or_else(bad)?, z: *v.get(2).ok_or_else(bad)?, n }
            }
            "ARC_FEED" => {
                let v = nums()?;
                let at = |k: usize| v.get(k).copied().ok_or_else(bad);
                Call::Arc { z: at(0)?, x: at(1)?, cz: at(2)?, cx: at(3)?, ccw: at(4)? > 0.0, n }
            }
            "START_SPEED_FEED_SYNC" => {
                let pitch = *nums()?.first().ok_or_else(bad)?;
                sync = Some(pitch);
                Call::SyncStart { pitch, n }
            }
            "STOP_SPEED_FEED_SYNCH" => {
                sync = None;
                Call::SyncStop { n }
            }
            "SET_FEED_RATE" => Call::FeedRate(*nums()?.first().ok_or_else(bad)?),
            "USE_LENGTH_UNITS" => Call::Inches(args == "CANON_UNITS_INCHES"),
            _ => continue,
        };
        calls.push(call);
    }
    Ok(calls)
}

/// The synchronised runs: each `Vec` is the moves from a `SyncStart` made
/// while not synchronised to the `SyncStop` (a G33 block, or one G76 pass's
/// cut with its tapers), each starting where the move before it ended.
pub fn synced_runs(calls: &[Call]) -> Vec<Vec<Segment>> {
    let (mut runs, mut at, mut open) = (Vec::new(), (0.0, 0.0), false);
    for c in calls {
        match *c {
            Call::SyncStart { .. } if !open => {
                runs.push(Vec::new());
                open = true;
            }
            Call::SyncStop { .. } => open = false,
            Call::Move { kind, x, z, n } => {
                if let (Kind::Synced(pitch), true) = (kind, open) {
                    runs.last_mut().unwrap().push(Segment { from: at, to: (x, z), pitch, n });
                }
                at = (x, z);
            }
            Call::Arc { x, z, .. } => at = (x, z),
            _ => {}
        }
    }
    runs
}

/// `program` with `N<line>` put before every block that has no N word, so
/// that rs274's N column gives the 1-based source line. Blank and `%`
/// lines are left alone; a leading `/` (block delete) stays first.
pub fn numbered(program: &str) -> String {
    let mut out = String::new();
    for (i, line) in program.lines().enumerate() {
        let t = line.trim_start();
        let (slash, body) = t.strip_prefix('/').map_or(("", t), |b| ("/", b.trim_start()));
        if t.is_empty() || t.starts_with('%') || body.starts_with(['N', 'n']) {
            out.push_str(line);
        } else {
            out.push_str(&format!("{slash}N{} {body}", i + 1));
        }
        out.push('\n');
    }
    out
}

/// Two rs274 at once sometimes die of SIGBUS with nothing printed (a
/// resource they share): the tests of one binary run it one at a time.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Whether `rs274` can be started (it is on PATH).
pub fn available() -> bool {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    Command::new("rs274").arg("-h").stdin(Stdio::null()).output().is_ok()
}

/// Runs `rs274 -g` on `program` (a temporary file; no INI, tool table or
/// var file is needed; standard input closed) and parses what it prints.
/// Err: rs274's message and offending block (e.g. "In G76, I must not be
/// 0\nG76 …"), or why it could not run. A program must end with M2/M30 or
/// `%`, else rs274 fails with "File ended with no percent sign or program end".
pub fn run(program: &str) -> Result<Vec<Call>, String> {
    match run_keeping(program)? {
        (calls, None) => Ok(calls),
        (_, Some(err)) => Err(err),
    }
}

/// [`run`], keeping the calls rs274 made before it refused the program:
/// (the calls, rs274's message and offending block if it refused it).
/// Err: why rs274 could not run.
pub fn run_keeping(program: &str) -> Result<(Vec<Call>, Option<String>), String> {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    static SEQ: AtomicUsize = AtomicUsize::new(0);
    let k = SEQ.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("screwcut-rs274-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let file = dir.join("prog.ngc");
    let written = std::fs::write(&file, program).map_err(|e| format!("{}: {e}", file.display()));
    // An rs274 killed by a signal (SIGBUS, when another one runs at the same
    // moment elsewhere on the machine) printed nothing: run it again.
    let mut out = None;
    for _ in 0..3 {
        if written.is_err() {
            break;
        }
        let o = Command::new("rs274").arg("-g").arg(&file).current_dir(&dir).stdin(Stdio::null()).output();
        let killed = o.as_ref().is_ok_and(|o| o.status.code().is_none());
        out = Some(o);
        if !killed {
            break;
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    written?;
    let out = out
        .ok_or("rs274 did not run")?
        .map_err(|e| format!("cannot run rs274 (apt-get install linuxcnc-uspace): {e}"))?;
    if out.status.code().is_none() {
        return Err(format!("rs274 was killed ({}) three times", out.status));
    }
    let calls = parse(&String::from_utf8_lossy(&out.stdout));
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let err = err.lines().filter(|l| *l != "executing").collect::<Vec<_>>().join("\n");
        return Ok((calls.unwrap_or_default(), Some(err)));
    }
    Ok((calls?, None))
}

/// rs274's message without the file name that two of its o-word messages
/// carry (`EOF in file:NAME seeking o-word: …`, `File:NAME line:N sub: …`),
/// which is the temporary file when it runs live and the recording's name in
/// `tests/linuxcnc/`: the text after the name, else the message unchanged.
pub fn without_file(message: &str) -> &str {
    for key in ["in file:", "File:"] {
        if let Some(i) = message.find(key) {
            let rest = &message[i + key.len()..];
            return rest.split_once(' ').map_or(rest, |(_, after)| after.trim_start());
        }
    }
    message
}

/// The folder of the recorded programs and outputs (`tests/linuxcnc/`).
pub fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/linuxcnc")
}

/// A recorded file of [`dir`].
pub fn read(name: &str) -> String {
    std::fs::read_to_string(dir().join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Whether rs274 runs here; fails under CI when it does not.
pub fn live() -> bool {
    static LIVE: OnceLock<bool> = OnceLock::new();
    *LIVE.get_or_init(|| {
        if available() {
            return true;
        }
        if std::env::var_os("CI").is_some() {
            panic!(
                "rs274 (LinuxCNC's interpreter) is not installed, and CI is set: the LinuxCNC oracle tests need it. Install it with `apt-get install linuxcnc-uspace` (cargo xtask test does)"
            );
        }
        eprintln!(
            "note: rs274 is not installed (apt-get install linuxcnc-uspace): comparing with the recordings in tests/linuxcnc/ only"
        );
        false
    })
}

/// The source line of each N word ([`numbered`] gives every block one).
pub fn lines_of_n(program: &str) -> HashMap<u64, u32> {
    let mut map = HashMap::new();
    for (i, l) in program.lines().enumerate() {
        let t = l.trim_start().trim_start_matches('/').trim_start();
        if let Some(rest) = t.strip_prefix(['N', 'n']) {
            let d: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
            if let Ok(n) = d.parse() {
                map.insert(n, i as u32 + 1);
            }
        }
    }
    map
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_n_words_and_sync() {
        let t = "   12 N..... START_SPEED_FEED_SYNC(1.500000,0)\n   13 N20    STRAIGHT_FEED(8.8000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n   14 N123456STOP_SPEED_FEED_SYNCH()\n   15 N7     STRAIGHT_FEED(9.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000)\n";
        let c = parse(t).unwrap();
        assert_eq!(c[0], Call::SyncStart { pitch: 1.5, n: None });
        assert_eq!(c[1], Call::Move { kind: Kind::Synced(1.5), x: 8.8, z: -20.0, n: Some(20) });
        assert_eq!(c[2], Call::SyncStop { n: Some(123456) });
        assert_eq!(c[3], Call::Move { kind: Kind::Feed, x: 9.0, z: 1.0, n: Some(7) });
        assert!(parse("executing\n").is_err());
        let arc = "  104 N..... ARC_FEED(-2.0000, 9.0000, -2.0000, 8.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)\n";
        assert_eq!(parse(arc).unwrap(), [Call::Arc { x: 9.0, z: -2.0, cx: 8.0, cz: -2.0, ccw: true, n: None }]);
    }

    #[test]
    fn drops_file_names() {
        assert_eq!(
            without_file("EOF in file:/tmp/x/prog.ngc seeking o-word: o<a> from line: 3"),
            "seeking o-word: o<a> from line: 3"
        );
        assert_eq!(
            without_file("File:a.ngc line:8 sub: o|a| found in illegal location"),
            "line:8 sub: o|a| found in illegal location"
        );
        assert_eq!(without_file("Attempt to divide by zero"), "Attempt to divide by zero");
    }

    #[test]
    fn numbers_lines() {
        assert_eq!(numbered("%\nG0 X1\n\nN5 G1\n/ G0 Z1\n"), "%\nN2 G0 X1\n\nN5 G1\n/N5 G0 Z1\n");
    }
}
