//! Macro calls beyond the plain M98/G65 of `macros.rs`: the modal call
//! G66/G67, the controller's nesting of subprograms, GSK's macro A
//! (`G65 Hm P#i Q#j R#k`), and `expand`, which writes out what a program
//! of calls and loops ran. Each is checked against the same program
//! written out by hand, or against the manual's rule cited at the test.

mod common;
use common::*;
use screwcut::planner::Planner;
use screwcut::{Code, Dialect, Settings, Severity};

/// `G66 P… <arguments>` calls its macro after every later block that moves
/// an axis, until `G67`; the macro's own moves do not call it again; the
/// G66 block itself moves nothing. Each call is a macro level with the
/// arguments as locals (16i-PB B-63684EN ch. 16 p.278: "Calls can be nested
/// to a depth of four levels including simple calls (G65) and modal calls
/// (G66)"; Mitsubishi M700V programming manual §13.5 p.308, a Fanuc-style
/// macro: "called every time the movement command is executed with modal
/// call A", not by the moves in the macro; Yaskawa LX3 §2.8.23: G66 modal
/// call, G67 cancel).
#[test]
fn g66_calls_after_each_move_until_g67() {
    let modal = "\
O0003
G97 S300 M03
G00 X58. Z70.
G66 P9010 A13. B2.
X47.1
X46.5
X45.9
G67
X60.
G00 X100. Z100.
M30
O9010 (ONE PASS FROM HERE TO Z#1)
G32 Z#1 F#2
G00 X58.
Z70.
M99
";
    // The three passes written out, then the move after G67.
    let unrolled = UNROLLED.replace("G00 X100. Z100.", "X60.\nG00 X100. Z100.");
    let plan = fanuc(modal);
    same_cut(&plan, &fanuc(&unrolled));
    assert_eq!(plan.threads[0].passes.len(), 3);
    // Each pass was cut by the macro, called after the move on line 5, 6 and 7.
    let via: Vec<&[u32]> = plan.threads[0].passes.iter().map(|p| &p.via[..]).collect();
    assert_eq!(via, [&[5][..], &[6], &[7]]);
    // A macro that is not in the file: the controller's alarm at the first call, not at G66.
    let missing = fanuc("G00 X58. Z70.\nG66 P9999\nG04 X1.\nX50.\nM30\n");
    let d: Vec<_> = missing.diagnostics.iter().filter(|d| d.code == Code::JumpTarget).collect();
    assert_eq!(d.len(), 1, "{:?}", missing.diagnostics);
    assert_eq!(d[0].line, 2);
}

/// On the G66 block itself, X and the other argument letters are the
/// macro's arguments (#24 …), not a move, while its other G words still
/// run (16i-PB B-63684EN §16.6.3 p.281: argument specification I includes
/// X, Y, Z, U, V, W). The block left to run has no axis words at all:
/// asking it for X or U finds none (no stale position of the words taken).
#[test]
fn g66_block_keeps_its_g_words_and_gives_x_to_the_macro() {
    let modal = "\
O0004
G97 S300 M03
G00 X58. Z70.
G01 G66 P9011 A13. B2. X47.1 U1. F0.2
G00 Z70.
G67
M30
O9011 (ONE PASS AT DIAMETER #24)
G00 X#24
G32 Z#1 F#2
G00 X58.
Z70.
M99
";
    let unrolled = "\
O0004
G97 S300 M03
G00 X58. Z70.
G01
G00 Z70.
G00 X47.1
G32 Z13. F2.
G00 X58.
Z70.
M30
";
    let plan = fanuc(modal);
    same_cut(&plan, &fanuc(unrolled));
    assert_eq!(plan.threads.len(), 1);
    assert_eq!(plan.threads[0].passes.len(), 1);
    assert_eq!(plan.threads[0].passes[0].via, [5]);
    // X and U on the G66 block are arguments: no "X and U together" alarm.
    assert!(plan.diagnostics.iter().all(|d| d.code != Code::AxisConflict), "{:?}", plan.diagnostics);
}

/// M98 nests ten levels on the 0i-D/0i-F (setting `fanuc.sub_nesting`;
/// the 0i-C's four, B-64124EN §12.3 p.136, by setting it to 4): the
/// eleventh call is the controller's alarm, at the call.
#[test]
fn subprogram_nesting_is_the_controllers_setting() {
    let chain = |levels: u32| {
        let mut s = String::from("O0001\nM98 P1001\nM30\n");
        for k in 1..=levels {
            let call = if k < levels { format!("M98 P{}\n", 1001 + k) } else { "G00 X10.\n".to_string() };
            s += &format!("O{}\n{call}M99\n", 1000 + k);
        }
        s
    };
    no_alarm(&fanuc(&chain(10)));
    let deep = fanuc(&chain(11));
    let d: Vec<_> = deep.diagnostics.iter().filter(|d| d.code == Code::CallDepth).collect();
    assert_eq!(d.len(), 1);
    assert!(d[0].message.contains("deeper than 10 (fanuc.sub_nesting)"), "{}", d[0].message);
    let c = plan_with(&chain(5), Dialect::Fanuc0i, &["fanuc.sub_nesting=4"]);
    assert_eq!(c.diagnostics.iter().filter(|d| d.code == Code::CallDepth).count(), 1);
    // GSK980TD family: four.
    assert_eq!(plan_with(&chain(5), Dialect::Gsk980tdc, &[]).with_code(Code::CallDepth).count(), 1);
    no_alarm(&plan_with(&chain(4), Dialect::Gsk980tdc, &[]));
}

/// GSK's macro A: `G65 Hm P#i Q#j R#k` (GSK980TDi user manual ch. 3,
/// "Macro command list": H01 assignment, H02–H05 arithmetic, H11–H13
/// OR/AND/XOR, H21 square root, H22 absolute value, H23 remainder, H26
/// #i×#j÷#k, H27 √(#j²+#k²), H31–H34 trigonometry in degrees, H80 jump,
/// H81–H86 conditional jumps (=, ≠, >, <, ≥, ≤ in the order of Fanuc's
/// macro A; the GSK page's symbols are lost in its text), H99 alarm 500+n).
/// A counting loop written with H codes cuts the passes of the same
/// program unrolled.
#[test]
fn gsk_macro_a_loop_is_the_unrolled_program() {
    let program = "\
O0004
G97 S300 M03
G00 X58 Z70
G65 H01 P#101 Q0
N10 G65 H02 P#101 Q#101 R1
G65 H04 P#102 Q#101 R0.6
G65 H03 P#100 Q47.7 R#102
G00 X#100
G32 Z13 F2
G00 X58
Z70
G65 H84 P10 Q#101 R3
G00 X100 Z100
M30
";
    let gsk = |s: &str| plan_with(s, Dialect::Gsk980tdc, &[]);
    let plan = gsk(program);
    same_cut(&plan, &gsk(UNROLLED));
    assert_eq!(plan.threads[0].passes.len(), 3);
}

/// Each H operation's value, read back through an address (`G00 X#1`).
#[test]
fn gsk_macro_a_operations() {
    let gsk = |s: &str| plan_with(s, Dialect::Gsk980tdc, &[]);
    let x_of = |h: &str| {
        let plan = gsk(&format!("G00 X0 Z0\n#2=3.\n{h}\nG00 X#1 Z1\nM30\n"));
        no_alarm(&plan);
        plan.moves.last().map(|m| m.to).unwrap()
    };
    let at = |x: f64| gsk(&format!("G00 X0 Z0\nG00 X{x:.3} Z1\nM30\n")).moves.last().map(|m| m.to).unwrap();
    for (h, x) in [
        ("G65 H01 P#1 Q12.5", 12.5),
        ("G65 H02 P#1 Q#2 R4.", 7.0),
        ("G65 H03 P#1 Q#2 R4.", -1.0),
        ("G65 H04 P#1 Q#2 R4.", 12.0),
        ("G65 H05 P#1 Q#2 R4.", 0.75),
        ("G65 H11 P#1 Q5 R2", 7.0),
        ("G65 H12 P#1 Q6 R3", 2.0),
        ("G65 H13 P#1 Q6 R3", 5.0),
        ("G65 H21 P#1 Q16.", 4.0),
        ("G65 H22 P#1 Q-2.5", 2.5),
        ("G65 H23 P#1 Q17 R5", 2.0),
        ("#1=10.\nG65 H26 P#1 Q#2 R4.", 7.5),
        ("G65 H27 P#1 Q3. R4.", 5.0),
        ("G65 H31 P#1 Q10. R30.", 5.0),
        ("G65 H32 P#1 Q10. R60.", 5.0),
        ("G65 H33 P#1 Q10. R45.", 10.0),
        ("G65 H34 P#1 Q1. R1.", 45.0),
    ] {
        let got = x_of(h);
        let want = at(x);
        assert!((got.x - want.x).abs() < 1e-9 && (got.z - want.z).abs() < 1e-9, "{h}: {got:?} != {want:?}");
    }
    // Conditional jumps: #2 = 3 against R; the jump skips the X20 move.
    for (h, jumps) in [(81, false), (82, true), (83, true), (84, false), (85, true), (86, false)] {
        let plan = gsk(&format!("G00 X0 Z0\n#2=3.\nG65 H{h} P5 Q#2 R2.\nG00 X20 Z1\nN5 G00 X30 Z2\nM30\n"));
        no_alarm(&plan);
        let xs: Vec<u32> = plan.moves.iter().map(|m| m.line).collect();
        assert_eq!(!xs.contains(&4), jumps, "H{h}: {xs:?}");
    }
    // H99: the program's own alarm 500 + n; an H the manual does not list; a result that is not a variable.
    let alarm = gsk("G65 H99 P7\nM30\n");
    assert!(alarm.diagnostics.iter().any(|d| d.code == Code::MacroAlarm && d.message.contains("alarm 507")));
    let bad = gsk("G65 H07 P#1 Q1\nM30\n");
    assert!(
        bad.diagnostics.iter().any(|d| d.code == Code::MacroSyntax && d.message.contains("H07: not an operation")),
        "{:?}",
        bad.diagnostics
    );
    let no_var = gsk("G65 H01 P1 Q1\nM30\n");
    assert!(no_var.diagnostics.iter().any(|d| d.code == Code::MacroSyntax && d.message.contains("P#i")));
    // Fanuc 0i has no macro A: there G65 is a macro call (P names a program).
    assert!(fanuc("G65 H01 P#1 Q1\nM30\n").diagnostics.iter().any(|d| d.code == Code::JumpTarget));
}

/// `expand` writes what ran: the passes a subprogram cut three times and a
/// macro loop cut are written out as plain blocks, for the program's own
/// controller and for LinuxCNC, and those blocks plan the same passes.
#[test]
fn expand_writes_the_executed_passes() {
    let sub = "O1000\n#1=#1+1\nG00 X[47.7-0.6*#1]\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n";
    let program = format!("O0001\nG97 S300 M03\nG00 X58. Z70.\nM98 P1000 L3\nG00 X100. Z100.\nM30\n{sub}");
    let plan = fanuc(&program);
    for to in [Dialect::Fanuc0i, Dialect::LinuxCnc] {
        let out = screwcut::expand::expand(&plan, to).program;
        assert!(!out.contains("M98") && !out.contains('#') && !out.contains("o1"), "{to:?}:\n{out}");
        let again = plan_with(&out, to, &[]);
        no_alarm(&again);
        let t = &again.threads[0];
        let xs: Vec<f64> = t.passes.iter().map(|p| p.from.x).collect();
        assert_eq!(xs.len(), 3, "{to:?}:\n{out}");
        for (x, want) in xs.iter().zip([47.1, 46.5, 45.9]) {
            eq(*x, want);
        }
    }
}

/// A checkpoint taken inside a subprogram written after the main program
/// moves with an edit of the main program: a later edit inside the
/// subprogram resumes there, at the right byte.
#[test]
fn a_checkpoint_in_a_later_subprogram_moves_with_an_edit() {
    let s = Settings::new(Dialect::Fanuc0i);
    let mut text = String::from("O0001\nG97 S300 M03\nM98 P1000\n");
    for k in 0..400 {
        text.push_str(&format!("(MAIN {k})\nG00 X5{}. Z70.\n", k % 8));
    }
    text.push_str("M30\nO1000\n");
    for k in 0..400 {
        text.push_str(&format!("G00 X4{}. Z70.\n", k % 8));
    }
    text.push_str("G00 X47.1\nG32 Z13. F2.\nG00 X58.\nZ70.\nM99\n");
    let mut p = Planner::new(s.clone());
    p.plan(&text);
    // A longer comment late in the main program: reading resumes near it.
    text = text.replacen("(MAIN 390)", "(MAIN 390, NOW LONGER)", 1);
    assert_eq!(p.plan(&text).clone(), screwcut::plan(&text, &s));
    assert!(p.resumed_at() > 600, "resumed at {}", p.resumed_at());
    // An edit late in the subprogram resumes at the checkpoint inside it.
    text = text.replacen("G00 X47.1\n", "G00 X46.9\n", 1);
    assert_eq!(p.plan(&text).clone(), screwcut::plan(&text, &s));
}

/// A vacant variable number on the left of an assignment is 0, as vacant
/// is in any arithmetic expression, so `#[#1] = …` with #1 vacant writes
/// #0, which cannot be written (Mitsubishi M700V programming manual §13.5
/// p.314, a Fanuc-style macro: "<vacant> in an arithmetic expression is
/// handled in the same way as 0"; "#0 … cannot be defined in the
/// left-side member"). Not "variable number NaN".
#[test]
fn a_vacant_variable_number_writes_hash_zero_which_cannot_be() {
    let plan = fanuc("#[#1]=5.\nM30\n");
    let d: Vec<_> = plan.diagnostics.iter().filter(|d| d.severity == Severity::Error).collect();
    assert_eq!(d.len(), 1, "{:?}", plan.diagnostics);
    assert_eq!(d[0].message, "#0 cannot be written on the Fanuc 0i-TF controller");
    // A number given: written as before.
    assert!(fanuc("#1=2\n#[#1+100]=5.\nM30\n").diagnostics.iter().all(|d| d.severity != Severity::Error));
}
