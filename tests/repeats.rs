#![cfg(not(target_arch = "wasm32"))]
//! A diagnostic said again, the same at the same place after the same
//! calls, is listed once with how many times it was raised.
//!
//! A controller halts at an alarm until the operator resets it (as for a
//! macro's own alarm, `#3000`: https://zappettiniconsulting.com/wiki/alarms-timers).
//! The preview goes on past an alarm to show the rest of the program (our
//! decision, `src/interp.rs`), so a loop that runs a bad block fifty times
//! raises it fifty times. Listing it fifty times buries every other
//! diagnostic; one row with the count keeps what was found.

mod common;
use common::*;
use screwcut::Code;

/// A Fanuc macro loop that runs the same two blocks `n` times: a cut of
/// 1 mm and a G01 with a Q word G01 does not take.
fn loop_of(n: u32) -> String {
    format!(
        "O0001\nG99 S500 M03\nG00 X40. Z5.\n#1=0\nWHILE[#1LT{n}]DO1\nG01 W-1. F0.2\nG01 X40. Q3\n#1=#1+1\nEND1\nM30\n"
    )
}

#[test]
fn a_loop_lists_its_alarm_once_with_the_count() {
    let p = fanuc(&loop_of(50));
    // The loop ran fifty times: fifty cuts of 1 mm (the G00 from an
    // unknown place is no motion).
    assert_eq!(p.moves.len(), 50);
    let d = one(&p, Code::UnexpectedWord);
    assert_eq!((d.line, d.column, d.repeats), (7, 10, 50), "{d:#?}");
    // Raised once: no count.
    assert_eq!(one(&fanuc(&loop_of(1)), Code::UnexpectedWord).repeats, 1);
    // The JSON says it only when more than once.
    assert!(p.to_json().contains("\"repeats\":50"), "{}", p.to_json());
    assert!(!fanuc(&loop_of(1)).to_json().contains("repeats"));
}

#[test]
fn calls_from_two_places_stay_two_rows() {
    // The same subprogram called three times from line 3 and twice from
    // line 4: its alarm after two call chains is two rows (a row names its
    // calls), each counting its own.
    let p = fanuc("O0001\nG00 X40. Z5.\nM98 P1000 L3\nM98 P1000 L2\nM30\nO1000\nG01 X40. Q3 F0.2\nM99\n");
    let rows: Vec<_> = p.with_code(Code::UnexpectedWord).map(|d| (d.line, d.via.clone(), d.repeats)).collect();
    assert_eq!(rows, vec![(7, vec![3], 3), (7, vec![4], 2)], "{:#?}", p.diagnostics);
}

#[test]
fn another_message_at_the_same_place_is_another_row() {
    // G#1 is G13, G14 and G15 on the same block: three codes, three messages.
    let p = fanuc("O0001\n#1=13\nWHILE[#1LT16]DO1\nG#1 X40.\n#1=#1+1\nEND1\nM30\n");
    let rows: Vec<_> = p.with_code(Code::UnsupportedGCode).map(|d| (d.line, d.message.clone(), d.repeats)).collect();
    assert_eq!(rows.len(), 3, "{:#?}", p.diagnostics);
    assert!(rows.iter().all(|r| r.0 == 4 && r.2 == 1), "{rows:#?}");
    assert!(rows[0].1.starts_with("G13 ") && rows[2].1.starts_with("G15 "), "{rows:#?}");
}

#[test]
fn the_command_line_says_how_many_times() {
    use std::io::Write;
    let run = |lang: &str| {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_screwcut"))
            .args(["plan", "-d", "fanuc0i", "--lang", lang, "-"])
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .expect("screwcut runs");
        child.stdin.take().expect("stdin").write_all(loop_of(50).as_bytes()).expect("program written");
        String::from_utf8(child.wait_with_output().expect("output").stdout).expect("UTF-8")
    };
    let en = run("en");
    assert!(en.contains("7:10: alarm [unexpected-word] G01 does not take Q3 (raised 50 times)\n"), "{en}");
    assert!(en.contains("; 1 alarm(s),"), "{en}");
    let zh = run("zh");
    assert!(zh.contains("(出现 50 次)\n"), "{zh}");
}

/// A loop of `n` runs of a bad block, then one more alarm after it (a G01
/// with a P word) on line 11.
fn loop_then_alarm(n: u32) -> String {
    loop_of(n).replace("END1\nM30\n", "END1\nG00 X50.\nG01 X40. P2\nM30\n")
}

#[test]
fn a_loops_repeats_take_no_room_from_what_follows() {
    // 2,000 runs of the alarm against the limit of 1,000 diagnostics: all
    // counted in one row, and the alarm after the loop still listed.
    let p = fanuc(&loop_then_alarm(2000));
    let rows: Vec<_> = p.with_code(Code::UnexpectedWord).map(|d| (d.line, d.message.as_str(), d.repeats)).collect();
    assert_eq!(rows, vec![(7, "G01 does not take Q3", 2000), (11, "G01 does not take P2", 1)]);
    assert!(p.with_code(Code::MoreDiagnostics).next().is_none(), "{:#?}", p.diagnostics);
    assert_eq!(p.moves.len(), 2000 + 1);
}

#[test]
fn repeats_are_kept_to_sixteen_times_the_limit() {
    // With room for 10 diagnostics, 160 runs of the alarm are kept (and
    // counted); the other 340 are dropped and said to be (a last note),
    // and so is the alarm after the loop.
    let p = plan_with(&loop_then_alarm(500), screwcut::Dialect::Fanuc0i, &["limits.diagnostics=10"]);
    let rows: Vec<_> = p.with_code(Code::UnexpectedWord).map(|d| (d.line, d.repeats)).collect();
    assert_eq!(rows, vec![(7, 160)]);
    let more = one(&p, Code::MoreDiagnostics);
    assert!(more.message.contains("341"), "{}", more.message);
}
