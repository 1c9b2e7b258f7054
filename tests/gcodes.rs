//! The controllers' G code tables: a code the controller has is never an
//! alarm, and the rest of its block (a G20 on the same line) is applied as
//! the controller applies it; what the preview does not draw gets a note,
//! once per code and program.
//!
//! Sources:
//! - FANUC Series 0i-F Operator's Manual (lathe system), chapter
//!   "Preparatory function (G function)", the G code list, G code system A:
//!   group 00 G04 G07.1 G08 G09 G10 G10.6 G11 G27 G28 G29 G30 G30.1 G31
//!   G36 G37 G39 G50 G50.3 G52 G53 G65 G70–G76; 01 G00–G03 G32 G34 G35
//!   G90 G92 G94; 02 G96 G97; 04 G68 G69; 05 G98 G99; 06 G20 G21; 07
//!   G40–G42; 08 G25 G26; 09 G22 G23; 10 G80 G83–G85 G87–G89; 12 G66
//!   G66.1 G67; 14 G54–G59; 15 G61 G63 G64; 16 G17–G19; 20 G50.2 G51.2;
//!   21 G12.1 G13.1 (also G107, G112, G113, G250, G251). The stored copies
//!   searched for this test did not hold the manual's page itself, so no
//!   page number is given; the codes and groups are the list's.
//! - The same manual's alarm list: PS0010 "IMPROPER G-CODE" for a G code
//!   the controller does not have; the block is not executed.
//! - GSK980TD-family user manual, §3.1 "G commands": "The system alarms
//!   when G words do not belong to Table 3-1 or they are optional functions
//!   without being supplied" (read in the TOMATECH TAC-100XT edition of that
//!   manual, p.65, easymanua.ls/tomatech/tac-100xt/manual?p=65). The
//!   GSK980TDc's own Table 3-1 was not found in the stored copies searched:
//!   its table here is unchanged.

mod common;
use common::{eq, fanuc, no_alarm, one, plan_with};
use screwcut::motion::MoveKind;
use screwcut::plan::Units;
use screwcut::{Code, Dialect};

/// Every code of the system A list that the lathe reads, on a line of its
/// own after a thread, and with G20 on the same line: no alarm, and G20 applies.
#[test]
fn fanuc_codes_of_the_list_are_not_alarms() {
    let codes = [
        "G04 P100",
        "G07.1",
        "G08 P1",
        "G09",
        "G10 P1 X0 Z0",
        "G10.6",
        "G11",
        "G12.1",
        "G13.1",
        "G17",
        "G18",
        "G19",
        "G22 X100. Z100. I-100. K-100.",
        "G23",
        "G25",
        "G26",
        "G27 X80. Z60.",
        "G28 U0 W0",
        "G29",
        "G30 U0 W0",
        "G30.1",
        "G31",
        "G36",
        "G37",
        "G39",
        "G40",
        "G41",
        "G42",
        "G50 S2000",
        "G50.2",
        "G50.3",
        "G51.2",
        "G52",
        "G53",
        "G54",
        "G55",
        "G56",
        "G57",
        "G58",
        "G59",
        "G61",
        "G63",
        "G64",
        // G65 calls its program (tests/macros.rs): O9000 missing is the controller's alarm.
        "G66 P9000",
        "G66.1 P9000",
        "G67",
        "G68",
        "G69",
        // G70 P Q runs its contour N(P) … N(Q) (tests/profile.rs): here there is none.
        "G71 U1. R.5",
        "G72 W1. R.5",
        "G73 U1. R1",
        "G74 R1.",
        "G75 R1.",
        "G80",
        "G83",
        "G84",
        "G85",
        "G87",
        "G88",
        "G89",
        "G96 S100",
        "G97 S500",
        "G98",
        "G99",
        "G107",
        "G112",
        "G113",
        "G250",
        "G251",
    ];
    for code in codes {
        let src = format!("G97 S500 M03\nG00 X80. Z60.\n{code} G20\nM30\n");
        let plan = fanuc(&src);
        no_alarm(&plan);
        assert_eq!(plan.units, Units::Inch, "{code}: the G20 on its line");
    }
    // G35 (circular threading) is group 01: G20 goes on the line before it.
    let plan = fanuc("G20\nG00 X3. Z2.\nG35 X2. Z1. R1. F.1\nM30\n");
    no_alarm(&plan);
    assert_eq!(plan.with_code(Code::NotSimulated).count(), 1);
}

/// The header CAM programs write (`G80 G20 G40 …`) and a G53 tool change
/// position: the inch thread is read in inches. The G76 P(k) and Q(Δd) are
/// integers in 0.0001 in (IS-B inch), so k = 0.0386 in and the crest is
/// 0.923 + 2 × 0.0386 = X1.0002; F0.0625 is 16 threads per inch.
#[test]
fn an_inch_program_with_g80_and_g53_is_read_in_inches() {
    let src = "O0001\nG80 G20 G40 G99\nG53 X0 Z0\nT0101\nG54\nG97 S500 M03\nG00 X1.2 Z.2\n\
               G76 P010060 Q40 R.001\nG76 X.923 Z-1. P386 Q100 F.0625\nG00 X2.\nG53 X0 Z0\nG54\nM30\n";
    let plan = fanuc(src);
    no_alarm(&plan);
    assert_eq!(plan.units, Units::Inch);
    let t = &plan.threads[0];
    eq(t.lead, 0.0625);
    eq((t.height * 1e9).round() / 1e9, 0.0386);
    eq((t.crest * 1e9).round() / 1e9, 1.0002);
    // Each code not simulated is said once, however often it is written.
    let notes: Vec<String> = plan.with_code(Code::NotSimulated).map(|d| d.message.clone()).collect();
    assert_eq!(notes.len(), 2, "{notes:#?}");
    assert!(notes[0].starts_with("G53: G53 move in machine coordinates") && notes[1].starts_with("G54:"), "{notes:#?}");
    // G53 moves in machine coordinates: not drawn, and the tool's position is unknown after it.
    assert!(plan.moves.iter().all(|m| m.line != 3 && m.line != 11));
    assert_eq!(plan.moves.last().map(|m| m.line), Some(10));
}

/// A code the 0i-TF does not have (G45, tool offset increase, is a machining
/// centre's) is PS0010: the block, its G20 included, is not executed.
#[test]
fn fanuc_alarms_on_a_code_it_does_not_have() {
    let plan = fanuc("G45 G20\nG00 X30. Z5.\nM30\n");
    let d = one(&plan, Code::UnsupportedGCode);
    assert_eq!((d.line, d.column), (1, 1));
    assert_eq!(plan.units, Units::Mm);
}

/// GSK alarms for a G word not in its table, and does not run the block.
#[test]
fn gsk_alarms_on_a_code_not_in_its_table() {
    let plan = plan_with("G45 G20\nG00 X30 Z5\nM30\n", Dialect::Gsk980tdc, &[]);
    let d = one(&plan, Code::UnsupportedGCode);
    assert_eq!((d.line, d.column), (1, 1));
    assert_eq!(plan.units, Units::Mm);
}

/// G83–G89 (group 10) drill at every block with axis words until G80, and
/// G80 leaves the motion mode of group 01 as it was: the X block after it is
/// a G00 rapid. The holes are not drawn (one note).
#[test]
fn fanuc_drilling_cycles_end_at_g80() {
    let src = "G00 X50. Z5.\nG83 X0 Z-10. Q2000 F.1\nZ-20.\nG80\nX40. Z5.\nX30.\nM30\n";
    let plan = fanuc(src);
    no_alarm(&plan);
    assert_eq!(one(&plan, Code::NotSimulated).line, 2);
    assert!(plan.moves.iter().all(|m| !(2..=4).contains(&m.line)));
    let last = plan.moves.last().unwrap();
    assert_eq!((last.kind, last.line), (MoveKind::Rapid, 6));
    common::pt(last.from, 40.0, 5.0);
    common::pt(last.to, 30.0, 5.0);
    // A group 01 code ends the cycle as G80 does.
    let plan = fanuc("G00 X50. Z5.\nG83 X0 Z-10. Q2000 F.1\nG01 X40. Z5.\nX30.\nM30\n");
    let last = plan.moves.last().unwrap();
    assert_eq!((last.kind, last.line), (MoveKind::Feed, 4));
}

/// G27 checks the reference position after a rapid to the point it gives:
/// the rapid is drawn and the tool is there after it.
#[test]
fn fanuc_g27_is_a_rapid_to_its_point() {
    let plan = fanuc("G00 X50. Z5.\nG27 X80. Z60.\nG00 W-10.\nM30\n");
    no_alarm(&plan);
    let m = &plan.moves[0];
    assert_eq!((m.kind, m.line), (MoveKind::Rapid, 2));
    common::pt(m.from, 50.0, 5.0);
    common::pt(m.to, 80.0, 60.0);
    common::pt(plan.moves[1].to, 80.0, 50.0);
}
