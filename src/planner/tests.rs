//! Tests of the incremental planner.

use super::edit::{common_suffix, first_difference};
use super::*;
use crate::dialect::Dialect;

#[test]
fn first_difference_finds_the_edit() {
    assert_eq!(first_difference("abc", "abc"), 3);
    assert_eq!(first_difference("abc", "abd"), 2);
    assert_eq!(first_difference("", "x"), 0);
    let long = "G01 X1\n".repeat(100);
    let mut edited = long.clone();
    edited.replace_range(500..501, "9");
    assert_eq!(first_difference(&long, &edited), 500);
}

/// The common end, read in chunks, is the one read byte by byte.
#[test]
fn common_suffix_finds_the_common_end() {
    let bytewise = |a: &str, b: &str| a.bytes().rev().zip(b.bytes().rev()).take_while(|(x, y)| x == y).count();
    let long = "G01 X1\n".repeat(100);
    let mut next = crate::hash::unit_floats(0x9e37_79b9);
    for _ in 0..500 {
        let mut edited = long.clone();
        let at = (next() * long.len() as f64) as usize;
        let cut = (next() * 3.0) as usize;
        edited.replace_range(at..(at + cut).min(long.len()), ["", "9", "77"][(next() * 3.0) as usize]);
        let tail = &long[(next() * long.len() as f64) as usize..];
        for (a, b) in [(&long[..], &edited[..]), (&edited[..], &long[..]), (tail, &edited[..]), (&long[..], tail)] {
            assert_eq!(common_suffix(a, b), bytewise(a, b), "{a:?} {b:?}");
        }
    }
    assert_eq!(common_suffix("", "x"), 0);
    assert_eq!(common_suffix("abc", "abc"), 3);
}

/// An edit near the end resumes at the last checkpoint before it and gives the full plan.
#[test]
fn late_edit_resumes_and_matches_a_full_plan() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let pass = "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n";
    let mut text = pass.repeat(300);
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    assert_eq!(p.resumed_at(), 1);
    text.push_str("X46.5\nG32 Z13\nG00 X58\nZ70\n");
    let inc = p.plan(&text).clone();
    // 1500 blocks: checkpoints at 257, 513, ..., 1281; the edit is past 1500.
    assert_eq!(p.resumed_at(), 1281);
    assert_eq!(inc, crate::plan(&text, &s));
    // An edit at the top starts over.
    text.insert_str(0, "G21\n");
    let inc = p.plan(&text).clone();
    assert_eq!(p.resumed_at(), 1);
    assert_eq!(inc, crate::plan(&text, &s));
}

/// An edit near the top that keeps the number of lines reads only up to
/// the first checkpoint past it where the state is the last reading's,
/// keeps the rest, and still gives the full plan.
#[test]
fn early_edit_keeps_the_unchanged_tail() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let pass = "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n";
    let text = format!("G50 X100 Z100 (top)\n{}", pass.repeat(300));
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    // A longer comment on line 1: the same lines, every byte after it moved.
    let edited = text.replacen("(top)", "(the top of the program)", 1);
    let inc = p.plan(&edited).clone();
    assert_eq!(p.resumed_at(), 1);
    assert_eq!(p.stopped_at(), Some(257));
    assert_eq!(inc, crate::plan(&edited, &s));
    // The next edit resumes from the kept checkpoints, moved with the text.
    let again = edited.replacen("X47.1", "X47.2", 1);
    let inc = p.plan(&again).clone();
    assert_eq!(inc, crate::plan(&again, &s));
    // A digit in the first pass changes its depth but not what follows.
    let late = again.replacen("Z70\nX47.1", "Z70\nX47.15", 120);
    assert_eq!(p.plan(&late).clone(), crate::plan(&late, &s));
    // An edit that adds a line reads to the end.
    let longer = late.replacen("(the top", "\n(the top", 1);
    assert_eq!(p.plan(&longer).clone(), crate::plan(&longer, &s));
    assert_eq!(p.stopped_at(), None);
}

/// An early edit that makes one more thread (the first pass cut at another
/// lead) joins the last reading's threads after it, renumbered, and still
/// gives the full plan; so does the edit back.
#[test]
fn early_edit_that_adds_a_thread_keeps_the_rest() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let job = |d: u32| format!("G00 X{} Z70\nX{d}.1\nG32 Z13 F2\nG00 X58\nZ70\n", d + 10);
    let text: String =
        std::iter::once("G50 X100 Z100 (top)\n".to_string()).chain((0..300).map(|k| job(40 + k % 8))).collect();
    let mut p = Planner::new(s.clone());
    let threads = p.plan(&text).threads.len();
    let edited = text.replacen("G32 Z13 F2", "G32 Z13 F3", 1);
    let inc = p.plan(&edited).clone();
    assert_eq!(p.resumed_at(), 1);
    assert!(p.stopped_at().is_some());
    assert_eq!(inc.threads.len(), threads + 1);
    assert_eq!(inc, crate::plan(&edited, &s));
    assert_eq!(p.plan(&text).clone(), crate::plan(&text, &s));
}

/// A LinuxCNC `repeat` open at a checkpoint kept from the last reading
/// (the edit before it kept the lines) goes back to its body where the
/// edit moved it.
#[test]
fn a_repeat_open_in_a_kept_checkpoint_moves_with_the_edit() {
    let s = Settings::new(Dialect::LinuxCnc);
    let mut lines = vec!["(top)".to_string(), "G18 G21 G90 G7".into()];
    lines.extend((0..300).map(|k| format!("G0 X5{} Z70", k % 8)));
    lines.push("o1 repeat [2]".into());
    lines.extend((0..300).map(|k| format!("G1 X4{} Z60 F100", k % 8)));
    lines.extend(["M2", "o1 endrepeat", "G0 X53", "M2"].map(String::from));
    let mut p = Planner::new(s.clone());
    p.plan(&lines.join("\n"));
    // A longer comment: the same lines, the rest of the text moved.
    lines[0] = "(the top of the program)".into();
    p.plan(&lines.join("\n"));
    assert_eq!(p.stopped_at(), Some(257));
    // The first M2 becomes a move: the repeat runs its body again, from the checkpoint inside it.
    let m2 = lines.iter().position(|l| l == "M2").unwrap();
    lines[m2] = "G0 X52".into();
    let text = lines.join("\n");
    let (inc, full) = (p.plan(&text).clone(), crate::plan(&text, &s));
    assert_eq!(p.resumed_at(), 513);
    assert_eq!(inc.moves.len(), full.moves.len());
    assert!(inc == full);
}

/// Edits inside multi-byte characters (a Chinese comment changed to another
/// character that begins with the same bytes, é to è), also right after a
/// settings change: planned, equal to a full plan, no panic.
#[test]
fn an_edit_inside_a_multi_byte_character() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let pass = "G00 X58 Z70 (第1次进刀)\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n";
    let text = format!("(é)\n{}", pass.repeat(120));
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    for (from, to) in [("第1次", "第2次"), ("(é)", "(è)"), ("进刀", "退刀")] {
        let edited = text.replacen(from, to, 1);
        assert_eq!(p.plan(&edited).clone(), crate::plan(&edited, &s), "{from} → {to}");
        p.set_settings(Settings::new(Dialect::Fanuc0i));
        p.set_settings(s.clone());
        assert_eq!(p.plan(&text).clone(), crate::plan(&text, &s));
    }
}

/// With more findings than the plan keeps (`limits.diagnostics`), an edit
/// gives the kept ones, the count of the rest and where it starts exactly
/// as a full plan: the kept advice is copied only as far as the plan keeps it.
#[test]
fn an_edit_past_the_diagnostics_limit_keeps_and_counts_as_a_full_plan() {
    let mut s = Settings::new(Dialect::Gsk980tdc);
    s.set(crate::settings::P::LimitDiagnostics, 7.0);
    // Threads on their own turned diameters at S300, lead-in δ1 = 0: several findings each.
    let mut text = String::from("G50 X100 Z100\nS300 M03 T0101\n");
    for k in 0..40 {
        let d = 30 + k % 20;
        text += &format!("G00 X{} Z70\nG01 X{d} F0.2\nZ20\nX{}\nG00 Z70\n", d + 10, d + 5);
        for x in [0.9, 1.5, 2.1] {
            text += &format!("X{:.1}\nG32 Z13 F2\nG00 X{}\nZ70\n", f64::from(d) - x, d + 10);
        }
    }
    let mut p = Planner::new(s.clone());
    let first = p.plan(&text).clone();
    assert_eq!(first.diagnostics.len(), 8, "seven kept and the note of the rest");
    let more = |plan: &Plan| {
        plan.diagnostics.iter().find(|d| d.code == crate::Code::MoreDiagnostics).map(|d| (d.message.clone(), d.line))
    };
    assert!(more(&first).is_some());
    // A pass of the first thread (line 8), then one near the end.
    for (at, x) in [(7, "29.05"), (640, "40.95")] {
        let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
        lines[at] = format!("X{x}");
        text = lines.join("\n") + "\n";
        let inc = p.plan(&text).clone();
        let full = crate::plan(&text, &s);
        assert_eq!((more(&inc), &inc.diagnostics), (more(&full), &full.diagnostics), "edit at line {}", at + 1);
    }
}

/// The last plan's diagnostics are taken whole (only their lines moved)
/// where an edit left their text alone: every one-character edit of a
/// program with every kind of line end (`\r\n`, a lone `\r`, `\n`), wide
/// characters and findings before and after the edit gives, incrementally,
/// the diagnostics of a full plan, lines and columns included — also where
/// the edit makes or unmakes a `\r\n` next to a finding's line.
#[test]
fn diagnostics_taken_whole_match_a_full_plan() {
    let s = Settings::new(Dialect::Gsk980tdc);
    let text = "O0001\r\nG50 X100 Z100\rS300 M03\nG00 X40 Z70\r\n(第1次) X39.1 Ｂ1\nG32 Z13 F2\r\n\
                G00 X40\rZ70\nX38.5 K1 (é)\r\nG32 Z13 F2\nG00 X40\r\rZ70\nG32 Z13 F2 Q\nM30\n";
    let base = crate::plan(text, &s);
    assert!(base.diagnostics.len() >= 6, "{:?}", base.diagnostics);
    assert!(base.diagnostics.iter().any(|d| d.line >= 12), "findings late in the text");
    let mut p = Planner::new(s.clone());
    p.plan(text);
    let cuts: Vec<usize> = (0..=text.len()).filter(|&i| text.is_char_boundary(i)).collect();
    for w in cuts.windows(2) {
        let (at, next) = (w[0], w[1]);
        for edited in [
            format!("{}\n{}", &text[..at], &text[at..]),
            format!("{}\r{}", &text[..at], &text[at..]),
            format!("{}X{}", &text[..at], &text[at..]),
            format!("{}{}", &text[..at], &text[next..]),
        ] {
            assert_eq!(p.plan(&edited).diagnostics, crate::plan(&edited, &s).diagnostics, "edit at {at}: {edited:?}");
            assert_eq!(p.plan(text).diagnostics, base.diagnostics, "back from the edit at {at}");
        }
    }
}
