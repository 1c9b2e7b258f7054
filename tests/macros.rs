//! Subprograms and custom macro B (Fanuc 0i; GSK980TDc's M98/M99): each
//! program here is planned and compared, pass for pass and move for move,
//! with the same program unrolled by hand.
//!
//! Rules followed (see the project's notes on the manuals): M98 P L and the
//! packed `M98 P□□□□○○○○` (count before a four-digit program number; Fanuc
//! 0i-C operator's manual B-64124EN §12.3 p.136 gives `M98 P51002` = O1002
//! five times), M99 returns, `M99 Pn` to sequence n of the caller; custom
//! macro B: vacant variables (an address with a vacant variable is left
//! out, `#2=#1` stays vacant, arithmetic reads vacant as 0, EQ tells
//! vacant from 0), `[ ]` with functions before `* / AND MOD` before
//! `+ - OR XOR` before the relations, `WHILE[…]DOm … ENDm`, `IF[…]GOTOn`,
//! `IF[…]THEN`, `G65 P… L…` with argument specification I (A→#1, B→#2,
//! I→#4, K→#6, …) and a new level of local variables per macro call
//! (16i-PB operator's manual B-63684EN ch. 16 p.278).

mod common;
use common::*;
use screwcut::planner::Planner;
use screwcut::{Code, Dialect, Settings};

/// M98 with L, the packed count, and the same passes written out.
#[test]
fn subprogram_called_three_times_is_the_unrolled_program() {
    let sub = "%\nO1000 (ONE PASS)\n#1=#1+1\nG00 X[47.7-0.6*#1]\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n%\n";
    let main = |call: &str| format!("O0001\nG97 S300 M03\nG00 X58. Z70.\n{call}\nG00 X100. Z100.\nM30\n{sub}");
    let unrolled = fanuc(UNROLLED);
    let with_l = fanuc(&main("M98 P1000 L3"));
    same_cut(&with_l, &unrolled);
    // The passes point at the subprogram's lines.
    assert_eq!(with_l.threads[0].passes[0].lines, vec![10, 11, 12, 13]);
    // … and at the call that made them.
    assert!(with_l.threads[0].passes.iter().all(|p| p.via == [4]));
    assert!(unrolled.threads[0].passes.iter().all(|p| p.via.is_empty()));
    same_cut(&fanuc(&main("M98 P31000")), &unrolled);
    same_cut(&fanuc(&main("M98 P00031000")), &unrolled);
    // GSK980TDc reads the same M98 forms; its lengths take no decimal point rule.
    same_cut(&plan_with(&main("M98 P31000"), Dialect::Gsk980tdc, &[]), &plan_with(UNROLLED, Dialect::Gsk980tdc, &[]));
}

/// A WHILE loop writes the passes of a degressive schedule (depth Δd·√n).
#[test]
fn while_loop_writes_the_passes() {
    let program = "\
O0002 (M48X2 BY MACRO)
G97 S300 M03
G00 X58. Z70.
#1=1 (PASS)
#2=0.45 (FIRST DEPTH, RADIAL)
#3=1.3 (THREAD DEPTH)
WHILE[#1 LE 4]DO1
#4=#2*SQRT[#1]
IF[#4 LT #3]GOTO 20
#4=#3
N20 G00 X[48.-2*#4]
G32 Z13. F2.
G00 X58.
Z70.
#1=#1+1
END1
M30
";
    let depths: Vec<f64> = (1..=4).map(|n: i32| (0.45 * f64::from(n).sqrt()).min(1.3)).collect();
    let mut unrolled = String::from("O0002\nG97 S300 M03\nG00 X58. Z70.\n");
    for d in &depths {
        let x = ((48.0 - 2.0 * d) * 1000.0).round() / 1000.0;
        unrolled.push_str(&format!("G00 X{x:.3}\nG32 Z13. F2.\nG00 X58.\nZ70.\n"));
    }
    unrolled.push_str("M30\n");
    let p = fanuc(program);
    same_cut(&p, &fanuc(&unrolled));
    // X rounded to the least input increment: 48 − 2·0.45·√3 = 46.44115… → 46.441.
    pt(p.threads[0].passes[2].from, 46.441, 70.0);
}

/// G65 passes arguments into a new level of locals; M99 returns.
#[test]
fn g65_arguments_and_local_levels() {
    let program = "\
O0003
G97 S300 M03
#1=99.
G00 X58. Z70.
G65 P9010 A47.1 B2. K13.
G65 P9010 A46.5 B2. K13.
G00 X[#1+1.]
M30
O9010 (A: X, B: LEAD, K: END Z)
G00 X#1
G32 Z#6 F#2
G00 X58.
Z70.
M99
";
    let unrolled = "O0003\nG97 S300 M03\nG00 X58. Z70.\nX47.1\nG32 Z13. F2.\nG00 X58.\nZ70.\nX46.5\nG32 Z13. F2.\nG00 X58.\nZ70.\nG00 X100.\nM30\n";
    // The main program's #1 (99) is back after the calls: X100.
    same_cut(&fanuc(program), &fanuc(unrolled));
}

/// Vacant variables: an address with one is left out; EQ tells vacant from 0.
#[test]
fn vacant_variables() {
    let program = "\
G97 S300 M03
G00 X58. Z70.
#2=#1 (STAYS VACANT)
#3=#1+#1 (ZERO)
IF[#2 EQ 0]GOTO 90
IF[#3 NE 0]GOTO 90
G00 X47.1 Z#2
G32 Z13. F2.
G00 X58.
Z70.
N90 M30
";
    let p = fanuc(program);
    no_alarm(&p);
    assert_eq!(p.threads.len(), 1, "neither jump taken: #2 is vacant, #3 is 0");
    // Z#2 (vacant) was left out: the tool stayed at Z70.
    pt(p.threads[0].passes[0].from, 47.1, 70.0);
}

/// Precedence: functions, then * / AND MOD, then + - OR XOR.
#[test]
fn precedence_and_functions() {
    let program = "\
G00 X0. Z0.
G00 X[2+3*4] Z[10-8/2-1]
G00 X[ABS[-3]+SQRT[16]*2] Z[ROUND[2.5]+FIX[-1.7]+FUP[1.2]]
G00 X[ATAN[1]/[1]] Z[ATAN[0]/[-1]]
G00 X[SIN[30]*10] Z[[6 OR 1] AND 3]
";
    let p = fanuc(program);
    no_alarm(&p);
    // The first rapid, from an unknown position, is not a move of the plan.
    let to: Vec<(f64, f64)> = p.moves.iter().map(|m| (m.to.x, m.to.z)).collect();
    assert_eq!(to.len(), 4);
    // 2+3*4 = 14; 10-4-1 = 5; 3+4·2 = 11; 3 + (−1) + 2 = 4; ATAN 45°, 180°;
    // SIN 30° × 10 = 5; (6 OR 1) AND 3 = 7 AND 3 = 3.
    let want = [(14.0, 5.0), (11.0, 4.0), (45.0, 180.0), (5.0, 3.0)];
    for (got, want) in to.iter().zip(want) {
        eq(got.0, want.0);
        eq(got.1, want.1);
    }
}

/// M99 P returns to a sequence number of the caller.
#[test]
fn m99_p_returns_to_a_sequence_number() {
    let program = "\
O0004
G97 S300 M03
G00 X58. Z70.
M98 P2000
G00 X47.1 (SKIPPED BY M99 P30)
N30 G00 X46.5
G32 Z13. F2.
G00 X58.
M30
O2000
G00 X60.
M99 P30
";
    let p = fanuc(program);
    no_alarm(&p);
    pt(p.threads[0].passes[0].from, 46.5, 70.0);
    assert!(p.moves.iter().all(|m| (m.to.x - 47.1).abs() > 1e-9), "line 5 is never run");
}

/// M99 in the main program repeats it; the preview runs it `program.main_repeats` times.
#[test]
fn m99_in_the_main_program() {
    let program = "G97 S300 M03\nG00 X58. Z70.\nX47.1\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n";
    let once = fanuc(program);
    at(&once, Code::MainRepeats, 7, 1);
    assert_eq!(once.threads[0].passes.len(), 1);
    let twice = plan_with(program, Dialect::Fanuc0i, &["program.main_repeats=2"]);
    assert_eq!(twice.threads[0].passes.len(), 2);
}

/// A program as a shop writes it: header, tool call, G50 clamp, G96/G97,
/// comments, a threading subprogram called with L and a macro loop: no alarm.
#[test]
fn a_shop_program_plans_without_alarm() {
    let program = "\
%
O0100 (SHAFT M30X2 - THREAD)
(T0303 60 DEG EXTERNAL THREADING INSERT)
N10 G21 G40 G99
N20 G50 S2000
N30 T0303
N40 G96 S150 M03
N50 G00 X32. Z5.
N60 G97 S600
#100=0 (PASS COUNTER)
N70 M98 P8001 L4
N80 G00 X100. Z100.
N90 M05
N100 M30
%
O8001 (ONE PASS OF M30X2)
#100=#100+1
#101=0.5*SQRT[#100]
IF[#101 GT 1.3]THEN #101=1.3
G00 X[30.-2*#101]
G32 Z-25. F2.
G00 X32.
Z5.
M99
%
";
    let p = fanuc(program);
    no_alarm(&p);
    assert_eq!(p.threads.len(), 1);
    let t = &p.threads[0];
    assert_eq!(t.passes.len(), 4);
    // Depths 0.5·√n: 0.5, 0.7071, 0.866, 1.0 (radial).
    pt(t.passes[3].from, 28.0, 5.0);
    pt(t.passes[1].from, 28.586, 5.0);
}

/// Loops without end and jumps nowhere are alarms with the line; work is bounded.
#[test]
fn bounded_and_diagnosed() {
    let p = plan_with("N1 G00 X10. Z5.\nGOTO 1\n", Dialect::Fanuc0i, &["limits.blocks=1000"]);
    let d = one(&p, Code::BlockLimit);
    assert_eq!(d.line, 1.max(d.line));
    let p = fanuc("WHILE[1 EQ 2]DO1\nG00 X10.\n");
    // At the loop number of DO1.
    at(&p, Code::JumpTarget, 1, 16);
    let p = fanuc("M98 P7777\n");
    let d = one(&p, Code::JumpTarget);
    assert!(d.message.contains("O7777"), "{}", d.message);
    let p = fanuc("#1=1\nM98 P1000\nM30\nO1000\n#1=#1+1\nM98 P1000\nM99\n");
    let d = one(&p, Code::CallDepth);
    assert!(d.message.contains("10"), "{}", d.message);
}

/// Blocks read once count nothing against `limits.blocks`, however the
/// reading got to them: after a call of a subprogram written after the
/// main program, after a forward jump, after a LinuxCNC subroutine defined
/// at the end; a loop counts each block it runs again.
#[test]
fn only_blocks_run_again_count() {
    let plain = |n: usize| (0..n).map(|k| format!("G00 X5{}. Z70.\n", k % 8)).collect::<String>();
    let called = format!("O0001\nG00 X58. Z70.\nM98 P1000\n{}M30\nO1000\nG00 X47.\nM99\n", plain(50));
    let jumped = format!("G00 X58. Z70.\n#1=1\nIF[#1 EQ 1]GOTO10\n{}N10 G00 X50.\n{}M30\n", plain(5), plain(50));
    for (text, d) in [(called, Dialect::Fanuc0i), (jumped.clone(), Dialect::Fanuc0i), (jumped, Dialect::Gsk980tdc)] {
        let p = plan_with(&text, d, &["limits.blocks=10"]);
        assert_eq!(p.with_code(Code::BlockLimit).count(), 0, "{text}");
    }
    let sub = format!("G18 G21 G90 G7\nG0 X58 Z70\no<a> call\n{}M2\no<a> sub\nG0 X47\no<a> endsub\n", plain(50));
    let p = plan_with(&sub.replace("G00", "G0").replace(". ", " "), Dialect::LinuxCnc, &["limits.blocks=10"]);
    assert_eq!(p.with_code(Code::BlockLimit).count(), 0);
    // Twice the eight blocks of the body, and the WHILE once more: 17.
    let looped = format!("G00 X58. Z70.\n#1=0\nWHILE[#1 LT 3]DO1\n{}#1=#1+1\nEND1\nM30\n", plain(5));
    let p = plan_with(&looped, Dialect::Fanuc0i, &["limits.blocks=16"]);
    at(&p, Code::BlockLimit, 3, 1);
    let p = plan_with(&looped, Dialect::Fanuc0i, &["limits.blocks=17"]);
    assert_eq!(p.with_code(Code::BlockLimit).count(), 0);
}

/// Editing a program with loops and calls: the incremental plan is the full plan.
#[test]
fn incremental_planning_follows_the_flow() {
    let s = Settings::new(Dialect::Fanuc0i);
    let mut text = String::from("O0001\nG97 S300 M03\nG00 X58. Z70.\n");
    for _ in 0..300 {
        text.push_str("G00 X58. Z70.\n");
    }
    text.push_str("M98 P1000 L3\nM30\nO1000\n#1=#1+1\nG00 X[47.7-0.6*#1]\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n");
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    for (from, to) in [("0.6*#1", "0.5*#1"), ("L3", "L2"), ("Z13.", "Z14."), ("O1000\n#1", "O1000\n#2=1\n#1")] {
        text = text.replacen(from, to, 1);
        let inc = p.plan(&text).clone();
        assert_eq!(inc, screwcut::plan(&text, &s), "after {from} → {to}");
    }
}

/// A program that calls its subprograms (written after M30) from all over
/// the main program: an edit in the main program reads on only until the
/// reading is back in the last reading's state, and keeps the rest — the
/// subprograms it calls later were not edited; an edit in a subprogram, or
/// one that changes a label, reads on to the end. Each gives the full plan.
#[test]
fn an_edit_between_calls_keeps_the_rest() {
    let s = Settings::new(Dialect::Fanuc0i);
    let mut text = String::from("O0001\nG97 S300 M03\n");
    for k in 0..120 {
        text.push_str(&format!("(JOB {k})\nG00 X58. Z70.\n#1=0\nM98 P1000 L3\nG00 X80. Z90.\nG04 X0.5\n"));
    }
    text.push_str("M30\nO1000\n#1=#1+1\nG00 X[47.7-0.6*#1]\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n");
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    let edits: [(&str, &str, bool); 5] = [
        ("(JOB 3)", "(JOB 3 OF MANY)", true),
        ("G04 X0.5\n(JOB 7)", "G04 X0.7\n(JOB 7)", true),
        ("Z13. F2.", "Z14. F2.", false),
        ("(JOB 9)", "N5 (JOB 9)", false),
        ("N5 (JOB 9)", "(JOB 9)", false),
    ];
    for (from, to, kept) in edits {
        text = text.replacen(from, to, 1);
        let inc = p.plan(&text).clone();
        assert_eq!(inc, screwcut::plan(&text, &s), "after {from} → {to}");
        assert_eq!(p.stopped_at().is_some(), kept, "{from} → {to}: stopped at {:?}", p.stopped_at());
    }
    // Late in the main program: reading resumes near the edit, although what was read
    // before it (the subprogram, written after it) lies past the edit and moves with it.
    text = text.replacen("(JOB 110)", "(JOB 110 AND A LONGER COMMENT)", 1);
    let inc = p.plan(&text).clone();
    assert_eq!(inc, screwcut::plan(&text, &s));
    assert!(p.resumed_at() > 500, "resumed at {}", p.resumed_at());
}

/// The comment that names a thread is looked for back to the start of the
/// thread's own program: a thread cut in a subprogram is not named by a
/// comment of the main program before the call.
#[test]
fn a_subprograms_thread_is_named_in_its_own_program() {
    let sub = "O1000\n#1=#1+1\nG00 X[47.7-0.6*#1]\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n";
    let named_in_main = format!("O0001\n(M48x2-6g)\nG97 S300 M03\nG00 X58. Z70.\nM98 P1000 L3\nM30\n{sub}");
    assert!(fanuc(&named_in_main).threads[0].shop.gauge.is_none());
    let named_in_sub = named_in_main.replace("(M48x2-6g)\n", "").replace("O1000\n", "O1000 (M48x2-6g)\n");
    assert_eq!(fanuc(&named_in_sub).threads[0].shop.gauge.as_ref().map(|g| g.designation.as_str()), Some("M48x2-6g"));
}

/// MOD takes the remainder of whole numbers; a divisor that rounds to 0 is
/// a division by zero (Fanuc alarm PS0112, "divided by zero").
#[test]
fn modulo_of_whole_numbers() {
    let p = fanuc("G00 X0. Z0.\nG00 X[7 MOD 3] Z[17 MOD 5]\n#1=[5 MOD 0.4]\n");
    eq(p.moves[0].to.x, 1.0);
    eq(p.moves[0].to.z, 2.0);
    at(&p, Code::MacroValue, 3, 5);
}

/// A diagnostic inside a subprogram names its line there and the chain of
/// calls that led to it; a cycle's passes carry the chain too.
#[test]
fn diagnostics_and_passes_carry_the_call_chain() {
    let text = "\
O0001
G97 S300 M03
G00 X58. Z70.
M98 P1000
M30
O1000
G00 X50.
M98 P2000
M99
O2000
G92 X47.1 Z13. F2.
X46.5
G00 X60. Z70. Q7
M99
";
    let plan = fanuc(text);
    let t = &plan.threads[0];
    assert_eq!(t.passes.len(), 2);
    assert!(t.passes.iter().all(|p| p.via == [8, 4]), "{:?}", t.passes.iter().map(|p| &p.via).collect::<Vec<_>>());
    // The Q word is not Fanuc G00's: an alarm at line 13, reached through line 8 and line 4.
    let d = plan.diagnostics.iter().find(|d| d.line == 13).expect("a diagnostic at line 13");
    assert_eq!(d.via, [8, 4], "{d:?}");
    assert!(plan.to_json().contains("\"via\":[8,4]"));
    // Found by the lexer on a subprogram's first line: the chain is already the new one.
    let nested = fanuc("O0001\nM98 P1000\nM30\nO1000\n((X)) G00 X50.\nM99\n");
    let d = nested.diagnostics.iter().find(|d| d.line == 5).expect("a diagnostic at line 5");
    assert_eq!(d.via, [2], "{d:?}");
    // Outside the calls nothing is added.
    let main_only = fanuc("G00 X58. Z70. Q7\nM30\n");
    assert!(main_only.diagnostics.iter().all(|d| d.via.is_empty()));
}
