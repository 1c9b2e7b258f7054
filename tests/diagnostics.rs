//! Every diagnostic code, triggered by a program, at its line and column.
//! The coverage test fails when a code has no case here.

mod common;
use common::*;
use screwcut::{Code, Dialect};

use Dialect::{Fanuc0i as F, Gsk980tdc as G, LinuxCnc as L, Renhe as R};

/// (code, dialect, settings, program, line, column, text the message must contain)
type Case = (Code, Dialect, &'static [&'static str], &'static str, u32, u32, &'static str);

const TURNED_48: &str = "G00 X48 Z67\nG01 Z15 F0.2\nG00 X58 Z70\n";

const CASES: &[Case] = &[
    (Code::FullWidth, G, &[], "Ｇ００ Ｘ１０ Ｚ５；\n", 1, 1, "'G00 X10 Z5;'"),
    (Code::MalformedNumber, G, &[], "G00 X1.2.3\n", 1, 6, "'1.2.3'"),
    (Code::MissingValue, G, &[], "G00 X Z5\n", 1, 5, "'X'"),
    (Code::UnknownAddress, G, &[], "G00 Y10\n", 1, 5, "GSK980TDc"),
    (Code::UnexpectedCharacter, G, &[], "G00 X10 @\n", 1, 9, "'@'"),
    (Code::RepeatedWord, G, &[], "G00 X10 X20\n", 1, 9, "X10 and X20"),
    (Code::BlockTooLong, G, &["limits.block_chars=8"], "G00 X10 Z20\n", 1, 1, "11 characters"),
    (Code::TooManyDigits, G, &[], "G00 X123456789\n", 1, 6, "9 significant digits"),
    (Code::UnclosedComment, G, &[], "G00 X10 (oops\n", 1, 9, "not closed"),
    (Code::UnmatchedParen, G, &[], "G00 X10 )\n", 1, 9, "')'"),
    (Code::NestedComment, G, &[], "G00 X10 (a (b))\n", 1, 12, "do not nest"),
    (Code::CodeAfterSemicolon, G, &[], "G00 X10; G01 Z5\n", 1, 10, "'G01 Z5'"),
    (Code::UnsupportedMacro, R, &[], "#1=10\n", 1, 1, "'#'"),
    (Code::MalformedProgramNumber, G, &[], "O12.5\n", 1, 1, "'O12.5'"),
    (Code::ProgramTooLarge, G, &["limits.program_bytes=10"], "G00 X10 Z20\n", 1, 1, "12 bytes"),
    (Code::UnsupportedGCode, G, &[], "G07 X10\n", 1, 1, "G7"),
    (Code::NotSimulated, G, &[], "G74 R1.\n", 1, 1, "G74"),
    (Code::ConflictingGCodes, G, &[], "G00 G01 X10\n", 1, 5, "G0 and G1"),
    (
        Code::ContourNotMonotone,
        F,
        &[],
        "G00 X62. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F0.2\nN10 G00 X30.\nG01 Z-10. F0.1\nX50. Z-20.\nX40. Z-30.\nN20 X62. Z-45.\n",
        3,
        1,
        "type I",
    ),
    (Code::AxisConflict, G, &[], "G00 X10 U5\n", 1, 5, "X10 and U5"),
    (Code::NoDecimalPoint, F, &[], "G00 X75\n", 1, 5, "0.075 mm"),
    (Code::MissingFeed, G, &[], "G00 X10 Z5\nG01 Z0\n", 2, 1, "no F"),
    (Code::ArcRadiusTooSmall, G, &[], "G00 X0 Z0\nG02 X20 Z-20 R5 F0.1\n", 2, 14, "half the chord"),
    (Code::ArcRadiusMismatch, G, &[], "G00 X0 Z0\nG03 X20 Z-10 I0 K-5 F0.1\n", 2, 14, "from the end"),
    (Code::ArcMissingCenter, G, &[], "G00 X0 Z0\nG02 X20 Z-10 F0.1\n", 2, 1, "R or I/K"),
    (Code::UnexpectedWord, G, &[], "G00 X10 Q5\n", 1, 9, "G00 does not take Q5"),
    (Code::ValueOutOfRange, G, &[], "G00 X40 Z5\nG32 Z-30 F600\n", 2, 10, "F600"),
    (Code::AfterEnd, G, &[], "M30\nG00 X10\n", 2, 1, "never executed"),
    (Code::UnitsChanged, G, &[], "G00 X10 Z5\nG20\n", 2, 1, "units changed"),
    (Code::MissingWord, G, &[], "G04\n", 1, 1, "dwell time"),
    (Code::DecimalPointNotAllowed, F, &[], "G00 X40. Z5.\nG32 Z-30. F2. Q180.\n", 2, 15, "Q180000"),
    (Code::StartAssumed, G, &[], "G00 U10\n", 1, 5, "X0 Z0"),
    (Code::MoveLimit, G, &["limits.moves=1"], "G00 X10 Z5\nG00 X20\nG00 X30\n", 3, 1, "limits.moves"),
    (Code::MacroSyntax, F, &[], "#1=[2+\n", 1, 7, "expected a value"),
    (Code::MacroValue, F, &[], "#1=1/0\n", 1, 4, "division by zero"),
    (Code::MacroVariable, F, &[], "#1=#40\n", 1, 4, "#40 is not a variable of the Fanuc 0i"),
    (Code::JumpTarget, F, &[], "GOTO 99\n", 1, 1, "N99"),
    (
        Code::CallDepth,
        F,
        &["limits.call_depth=1"],
        "M98 P1000\nM30\nO1000\nM98 P1000\nM99\n",
        4,
        1,
        "limits.call_depth",
    ),
    (
        Code::CallDepth,
        F,
        &["fanuc.sub_nesting=2"],
        "M98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nM98 P3000\nM99\nO3000\nM99\n",
        7,
        1,
        "M98: calls nested deeper than 2 (fanuc.sub_nesting)",
    ),
    (Code::BlockLimit, F, &["limits.blocks=5"], "N1 #1=1\nGOTO 1\n", 2, 1, "limits.blocks"),
    (Code::MacroAlarm, F, &[], "#3000=7\n", 1, 1, "alarm 7"),
    (Code::MainRepeats, F, &[], "G00 X10. Z5.\nM99\n", 2, 1, "program.main_repeats"),
    (Code::SubprogramEnd, F, &[], "M98 P1000\nM30\nO1000\nG00 X10.\nO2000\nM99\n", 5, 1, "without M99"),
    (Code::MissingLead, G, &[], "G00 X40 Z5\nG32 Z-30\n", 2, 1, "without a lead"),
    (Code::LeadFromFeed, F, &[], "G00 X40. Z5.\nG01 X39. F0.2\nG32 Z-30.\n", 3, 1, "lead of 0.2"),
    (Code::ZeroLengthThread, G, &[], "G00 X40 Z5\nG32 Z5 F2\n", 2, 5, "does not move"),
    (Code::RunoutTooLong, G, &[], "G00 X40 Z5\nG32 W-10 F2 J1 K12\n", 2, 16, "K = 12"),
    (Code::QIgnored, G, &[], "G00 X40 Z5\nG32 W-10 F2 Q90000\nG32 W-10 Q180000\n", 3, 10, "ignored"),
    (Code::RunoutSpeed, G, &["No.107=400"], "G00 X40 Z5\nS300\nG32 Z-30 F2 J2\n", 3, 13, "No.107"),
    (
        Code::TooManyStarts,
        G,
        &["limits.starts=1"],
        "G00 X40 Z5\nG32 Z-30 F4\nG00 X50\nZ5\nX40\nG32 Z-30 Q180000\n",
        6,
        1,
        "2 starts",
    ),
    // ---- shop floor ----
    // Lead 6 at S3000: 18000 mm/min against machine.max_thread_feed 8000; 8000/6 = 1333.3 → S1333.
    (Code::ThreadFeedLimit, G, &[], "S3000 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F6\nG00 X58\nZ70\n", 4, 1, "at most S1333"),
    (
        Code::SpindleLimit,
        G,
        &[],
        "S5000 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F1\nG00 X58\nZ70\n",
        4,
        1,
        "S5000 is above the machine's highest spindle speed of 4000",
    ),
    // G96 S150 at X47.1: 1000·150/(π·47.1) = 1013.7 rev/min.
    (
        Code::ThreadCss,
        G,
        &[],
        "G96 S150 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n",
        4,
        1,
        "1014 rev/min at X47.1",
    ),
    // S1500, lead 2: δ1 ≈ 1500·2/500 = 6 against the assumed 5 (O1006's lead-in).
    (
        Code::Delta1Speed,
        G,
        &[],
        "S1500 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n",
        3,
        1,
        "n·L/500 = 6 at S1500",
    ),
    // Work turned Z15…Z67, pass Z70 → Z13: δ2 = 2 against 2000·2/1800 = 2.2222.
    (
        Code::Delta2Speed,
        G,
        &[],
        concat!("S2000 M03\n", "G00 X48 Z67\nG01 Z15 F0.2\nG00 X58 Z70\n", "X45.4\nG32 Z13 F2\nG00 X58\nZ70\n"),
        5,
        1,
        "n·L/1800 = 2.2222",
    ),
    // Crest assumed at 45.4 + 2.6 = 48: depths 1.2 and 1.3, areas 1.44·t and 0.25·t against
    // an even 1.69·t/2: 1.44/0.845 = 1.7041 > 1.5.
    (
        Code::ChipHeavyFirst,
        G,
        &[],
        "G00 X58 Z70\nX45.6\nG32 Z13 F2\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\n",
        2,
        1,
        "1.7041×",
    ),
    // 46 → 45.95: 0.025 radial, under chip.min_infeed 0.05.
    (
        Code::ChipThin,
        G,
        &[],
        "G00 X58 Z70\nX46\nG32 Z13 F2\nG00 X58\nZ70\nX45.95\nG32 Z13\nG00 X58\nZ70\n",
        6,
        1,
        "by only 0.025",
    ),
    // The second pass repeats the first at X46, short of full depth.
    (
        Code::ChipNone,
        G,
        &[],
        "G00 X58 Z70\nX46\nG32 Z13 F2\nG00 X58\nZ70\nX46\nG32 Z13\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\n",
        6,
        1,
        "pass 2 removes nothing",
    ),
    // d2 = 45.4 − 2·0.25 + 0.866025·2 = 46.6321 within 46.483 … 46.663.
    (
        Code::GaugeOk,
        G,
        &["tool.nose_radius=0.25"],
        "(M48x2-6g)\nG00 X58 Z70\nX45.4\nG32 Z13 F2\nG00 X58\nZ70\n",
        3,
        1,
        "pitch diameter 46.6321 (46.483 … 46.663, 6g): it gauges",
    ),
    // The tool not known, a full-profile insert r = 0.25: d2 = 45.9 − 0.5 + 1.7321 = 47.1321 > 46.663.
    (
        Code::GaugeFail,
        G,
        &[],
        "(M48x2-6g)\nG00 X58 Z70\nX45.9\nG32 Z13 F2\nG00 X58\nZ70\n",
        3,
        1,
        "47.1321 is too large",
    ),
    (
        Code::BadDesignation,
        G,
        &["thread.designation=M48x2-6k"],
        "G00 X58 Z70\nX45.4\nG32 Z13 F2\nG00 X58\nZ70\n",
        2,
        1,
        "is not a thread designation",
    ),
    (Code::CrestAssumed, G, &[], include_str!("../examples/o1006.nc"), 5, 1, "crest assumed at X48"),
    (
        Code::DepthVsStandard,
        G,
        &[],
        // Turned to X48, threaded to X46.5 only: 1.5 of diameter against 1.3·2 = 2.6.
        concat!(
            "G00 X48 Z67\nG01 Z15 F0.2\nG00 X58 Z70\n",
            "X47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\nZ70\n"
        ),
        4,
        1,
        "not cut to full depth",
    ),
    (
        Code::MoreDiagnostics,
        G,
        &["limits.diagnostics=1"],
        "G00 X1 Y2\nG00 X1 Y2\n",
        2,
        8,
        "1 more diagnostics from here",
    ),
    (Code::InfeedGuidance, G, &[], include_str!("../examples/o1006.nc"), 5, 1, "table 4-3 for pitch 2"),
    (
        Code::InfeedTooLarge,
        G,
        &[],
        "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\n",
        6,
        1,
        "pass 2 takes 1.7",
    ),
    (
        Code::Clearance,
        G,
        &[],
        // The work ends at Z67 and the pass starts at Z68: δ1 = 1 < 2.
        concat!("G00 X48 Z67\nG01 Z15 F0.2\nG00 X58 Z68\n", "X45.4\nG32 Z13 F2\nG00 X58\nZ68\n"),
        4,
        1,
        "δ1 = 1",
    ),
    (Code::MissingThreadHeight, G, &[], "G00 X35 Z5\nG78 X27.4 Z-30 Q400 F2\n", 2, 1, "P(k)"),
    (Code::MissingFirstDepth, G, &[], "G00 X35 Z5\nG78 X27.4 Z-30 P1300 F2\n", 2, 1, "Q(Δd)"),
    (Code::FaceThreadNotAllowed, G, &[], "G00 X35 Z5\nG78 X60 P1300 Q400 F2\n", 2, 1, "face thread"),
    (
        Code::PassLimit,
        G,
        &[],
        "G00 X35 Z5\nG78 P1060 Q0 R0.05 D1\nG78 X27.4 Z-30 P1300 Q1 F2\n",
        3,
        1,
        "1562501 passes",
    ),
    (Code::DecimalPointIgnored, G, &[], "G00 X35 Z5\nG78 X27.4 Z-30 P1.3 Q400 F2\n", 2, 16, "0.0013 mm"),
    (Code::StartInsideThread, G, &[], "G00 X29 Z5\nG78 X27.4 Z-30 P1300 Q400 F2\n", 2, 1, "X30"),
    (Code::TaperBeyondStart, G, &[], "G00 X50 Z5\nG92 X43.2 Z-30 R5 F2\n", 2, 1, "|R| > |U/2|"),
    (Code::E18_03, R, &[], "G00 X40 Z5\nG00 U-10\nG33 Z-40 F1.5\n", 3, 5, "incremental"),
    (Code::E18_04, R, &[], "G00 X40 Z5\nG00 U-10\nG33 W-3 F1\n", 3, 5, "4 mm"),
    (Code::E18_05, R, &[], "G00 X40 Z5\nG33 W-40 F1.5\n", 2, 1, "X feed"),
    (
        Code::CrossThread,
        G,
        &[],
        "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13 F2.5\nG00 X58\nZ70\nX45.9\nG32 Z13 F2\nG00 X58\nZ70\nX45.5\nG32 Z13 F2\n",
        7,
        1,
        "a lead of 2.5",
    ),
    // Pasted LinuxCNC code under Fanuc: its G76 P I J K R Q H E L alarms; LinuxCNC reads it.
    (
        Code::DialectHint,
        F,
        &[],
        "G18 G21 G90\nM3 S500\nG0 X30 Z5\nG76 P2 Z-30 I-1 J0.3 K1.23\nM2\n",
        4,
        13,
        "reads as LinuxCNC without an alarm",
    ),
    // Fanuc IS-B: 0.001 mm; X20.0953 has a fourth decimal (noted once).
    (Code::FinerThanIncrement, F, &[], "G00 X20.0953 Z5.\nG00 X20.0954\n", 1, 5, "0.001 mm"),
    // S300 for the first pass, S400 for the second: 2·100/60·0.03 = 0.1 mm with a 30 ms lag.
    (
        Code::SpeedBetweenPasses,
        G,
        &["machine.servo_lag=30"],
        "S300 M03\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nS400\nX46.5\nG32 Z13\nG00 X58\n",
        9,
        1,
        "moves 0.1 along the axis, 18°",
    ),
    // M48x2 ending 0.3 before a shoulder turned up to X56: a 60° flank at the root (r 22.7) needs (28 − 22.7)·tan 30° = 3.06.
    (
        Code::ToolShoulder,
        G,
        &[],
        "G00 X60 Z2\nG01 X48 F0.2\nZ-40\nX56\nZ-60\nG00 X60\nZ5\nX45.4\nG32 Z-39.7 F2\nG00 X60\n",
        9,
        1,
        "cuts 2.76 into the shoulder at Z-40",
    ),
    // A thread starting at Z-5, inside the work turned to X48 from Z2: the infeed at X47.1 plunges into it.
    (
        Code::ApproachIntoPart,
        G,
        &[],
        "G00 X60 Z2\nG01 X48 F0.2\nZ-40\nG00 X60\nZ-5\nX47.1\nG32 Z-35 F2\nG00 X60\n",
        7,
        1,
        "where the program turned the part to X48",
    ),
    // Lead 3 on about X30: λ = arctan(3 / (π·29.4)) ≈ 1.86°: a 2° shim (Sandvik: the nearest degree), within 1° of the standard 1°.
    (
        Code::Shim,
        G,
        &[],
        "G00 X34 Z5\nX29.1\nG32 Z-30 F3\nG00 X34\nZ5\nX28.2\nG32 Z-30\nG00 X34\n",
        2,
        1,
        "use a 2° shim",
    ),
    // Four starts of lead 8 on X30 (the example, about 5°): the standard 1° shim is 3.9° off: a flank rubs (Mitsubishi: 1° for 60° forms).
    (
        Code::ShimRub,
        G,
        &[],
        "G00 X34 Z5\nG92 X29.2 Z-30 F8 L4\nX28.6\nX28.2\nG00 X100 Z100\n",
        2,
        1,
        "use a 4° shim (the steepest made",
    ),
    // An internal insert on an external thread, made for pitch 1.5 (threading.md §11: E/I, full profile pitch).
    (
        Code::InsertSide,
        G,
        &["tool.insert=16IR 2.0 ISO"],
        "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\n",
        2,
        1,
        "is for internal threads; this thread is external",
    ),
    (
        Code::InsertPitch,
        G,
        &["tool.insert=16ER 1.5 ISO"],
        "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\n",
        2,
        1,
        "made for a pitch of 1.5 mm",
    ),
    // A60 cuts 0.5–1.5 mm (Kyocera catalogue 2021–2022, 60° partial profile).
    (
        Code::InsertRange,
        G,
        &["tool.insert=16ER A60"],
        "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\n",
        2,
        1,
        "from 0.5 to 1.5 mm",
    ),
    (Code::SpindleSpeed, R, &[], "S1500 M03\nG00 X40 Z5\nG00 U-10\nG33 W-40 F2\n", 4, 1, "2300/t − 60 = 1090"),
    (Code::SpindleNotTurning, L, &[], "G18\nG0 X10 Z5\nG33 Z-20 K1.5\nM2\n", 3, 1, "Spindle not turning in G33"),
    (
        Code::CutterCompActive,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG41\nG76 P1.5 Z-20 I-1 J0.2 K1\nM2\n",
        5,
        1,
        "Cannot use G76 threading cycle with cutter radius compensation on",
    ),
    (Code::NoProgramEnd, L, &[], "G18\nM3 S300\nG0 X10 Z5\n", 3, 1, "File ended with no percent sign or program end"),
    (Code::ValueReadAs, L, &[], "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1 R0.5\nM2\n", 4, 27, "read as R1"),
    (Code::OddPitch, L, &[], "G18\nM3 S300\nG0 X10 Z5\nG33 Z-20 K-1.5\nM2\n", 4, 10, "zero or below"),
    (
        Code::FullDepthSkipped,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1 H-1\nM2\n",
        4,
        27,
        "never cut to K",
    ),
    (
        Code::BackwardCut,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1 E20 L3\nM2\n",
        4,
        1,
        "runs backwards, from Z-15 to Z0",
    ),
    (Code::PlaneNotXz, L, &[], "G17\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.2 K1\nM2\n", 4, 1, "G76 in G17"),
    (
        Code::CycleNeedsXz,
        L,
        &[],
        "G17 G7\no100 sub\nG1 X12 Z0\nG1 Z-10\no100 endsub\nG0 X20 Z2\nG71 Q100 X20 Z2 I1\nM2\n",
        7,
        1,
        "G71.0 can only be used in XZ plane (G18)",
    ),
    (
        Code::ProfileRefused,
        L,
        &[],
        "G18 G7\no100 sub\nG1 X12 Z0\nG1 X16 Z-10\nG1 X20 Z-5\no100 endsub\nG0 X24 Z2\nG71 Q100 X24 Z2 I1\nM2\n",
        8,
        1,
        "G7X error: Not monotonic: the profile of o100 goes back along Z",
    ),
    (
        Code::DriveLineKept,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 X5 Z-20 I-1 J0.2 K1\nM2\n",
        4,
        10,
        "drive line X10",
    ),
    (Code::ManyPasses, L, &[], "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-1 J0.01 K1\nM2\n", 4, 1, "100 passes"),
    (
        Code::FloatExtraPass,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG76 P1.5 Z-20 I-0.7 J0.3 K0.9\nM2\n",
        4,
        1,
        "floating-point rounding",
    ),
    (
        Code::LeadAlongPath,
        L,
        &[],
        "G18\nM3 S300\nG0 X10 Z5\nG33 X11 Z-20 K1.5\nM2\n",
        4,
        14,
        "1.4988 per revolution along Z",
    ),
];

/// The plan with the note on another dialect, as the command line and the app give it.
fn hinted(src: &str, dialect: Dialect, sets: &[&str]) -> screwcut::Plan {
    let mut plan = plan_with(src, dialect, sets);
    screwcut::hint::add(src, &screwcut::Settings::new(dialect), &mut plan, screwcut::hint::MAX_BYTES);
    plan
}

#[test]
fn every_code_at_its_line_and_column() {
    for &(code, dialect, sets, src, line, col, text) in CASES {
        let plan = hinted(src, dialect, sets);
        let d = at(&plan, code, line, col);
        assert!(d.message.contains(text), "{code}: message {:?} lacks {text:?}", d.message);
    }
}

/// Every case in both languages: the English is the message the case asks
/// for, every argument named is given and used, and the Chinese has no English words.
#[test]
fn every_case_in_both_languages() {
    let mut bad = Vec::new();
    for &(code, dialect, sets, src, line, col, _) in CASES {
        let plan = hinted(src, dialect, sets);
        let d = at(&plan, code, line, col);
        let zh = check_languages(&d);
        let english = english_words(&zh);
        if !english.is_empty() {
            bad.push(format!("{code} ({}): English {english:?} in {zh:?}", d.template.name));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn every_code_has_a_case() {
    for code in Code::ALL {
        assert!(CASES.iter().any(|c| c.0 == *code), "no test case triggers {code}");
    }
}

/// Zero needs no decimal point: X0/Z0/U0/W0 mean 0 in millimetres and in
/// increments alike, so Fanuc (3401#0 = 0) does not warn about them; X75
/// beside them still does.
#[test]
fn zero_without_a_decimal_point_is_not_a_warning() {
    let plan = plan_with("G00 X0 Z0\nG00 U0 W0\nG00 X-0 Z75\n", F, &[]);
    let lines: Vec<u32> = plan.with_code(Code::NoDecimalPoint).map(|d| d.line).collect();
    assert_eq!(lines, vec![3], "only Z75 warns: {lines:?}");
    let d = at(&plan, Code::NoDecimalPoint, 3, 9);
    assert!(d.message.contains("0.075 mm"), "{}", d.message);
    assert!(!plan.diagnostics.iter().any(|d| d.message.contains("means 0 mm")));
}

/// The outline makes the crest known: no assumption note, real first infeed.
#[test]
fn crest_from_outline() {
    let src = format!("{TURNED_48}X47.1\nG32 Z13 F2\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\n");
    let plan = gsk(&src);
    no_alarm(&plan);
    assert_eq!(plan.with_code(Code::CrestAssumed).count(), 0);
    let t = &plan.threads[0];
    assert_eq!(t.crest_source, screwcut::thread::CrestSource::Outline);
    eq(t.crest, 48.0);
    eq(t.passes[0].depth, 0.45);
    eq(t.passes[1].depth, 1.3);
    // δ1 = 70 − 67 = 3: no clearance warning; full depth 2.6: no depth warning.
    assert_eq!(plan.with_code(Code::Clearance).count(), 0);
    assert_eq!(plan.with_code(Code::DepthVsStandard).count(), 0);
}

/// Bad input of every kind gives diagnostics, never a panic.
#[test]
fn garbage_never_panics() {
    let inputs = [
        "",
        "\n\n\n",
        "%\n",
        "((((",
        "))))",
        "G",
        "G32",
        "X-",
        "\u{0}\u{1}\u{2}",
        "Ｇ３２ Ｗ－１０ Ｆ２",
        "G02 R-0 X0",
        "G32 X1e308 F1",
        "N1 N2 N3",
        "/G00 X10",
        "G00 X99999999 Z-99999999\nG32 Z99999999 F500 J99999999 K99999999",
        "G03 X10 Z10 I0 K0 F1",
        ";;;;;;",
        "G50 S2000",
        "O",
        ":1234",
    ];
    for d in Dialect::ALL {
        for src in inputs {
            let plan = plan_with(src, d, &[]);
            let _ = plan.to_json();
        }
    }
}

/// An internal thread in a turned bore: the bore (X30) is the crest, depths
/// grow outward: (30.6 − 30)/2 = 0.3, 0.6, then 1.3 = 1.3·P/2 (no depth warning);
/// the bore starts at Z2 and the passes at Z7, so δ1 = 5.
#[test]
fn internal_thread_in_a_turned_bore() {
    let src = "G00 X30 Z2\nG01 Z-40 F0.2\nG00 X28 Z7\nX30.6\nG32 Z-30 F2\nG00 X28\nZ7\nX31.2\nG32 Z-30\nG00 X28\nZ7\nX32.6\nG32 Z-30\nG00 X28\nZ7\n";
    let plan = gsk(src);
    no_alarm(&plan);
    let t = &plan.threads[0];
    assert!(t.internal);
    assert_eq!(t.crest_source, screwcut::thread::CrestSource::Outline);
    eq(t.crest, 30.0);
    let depths: Vec<f64> = t.passes.iter().map(|p| (p.depth * 1e9).round() / 1e9).collect();
    assert_eq!(depths, vec![0.3, 0.6, 1.3]);
    assert_eq!(plan.with_code(Code::DepthVsStandard).count(), 0);
    assert_eq!(plan.with_code(Code::Clearance).count(), 0);
    // Started at Z3 instead, δ1 = 1 warns.
    let plan = gsk(&src.replace("Z7", "Z3"));
    assert!(one(&plan, Code::Clearance).message.contains("δ1 = 1"));
}

/// A face thread's crest is a face: its assumed crest is a Z, not a diameter.
#[test]
fn a_face_threads_assumed_crest_is_a_z() {
    let text = "G00 X60 Z2\nZ-0.5\nG32 X10 F2\nG00 Z2\nX60\nZ-1.0\nG32 X10 F2\nG00 Z2\nX60\n";
    let plan = screwcut::plan(text, &screwcut::Settings::new(Dialect::Gsk980tdc));
    assert_eq!(plan.threads.len(), 1);
    let d = plan.diagnostics.iter().find(|d| d.code == Code::CrestAssumed).expect("crest-assumed");
    assert!(
        d.message.contains("face the crest of this face thread") && d.message.contains("crest assumed at Z"),
        "{}",
        d.message
    );
    assert!(!d.message.contains("diameter"), "{}", d.message);
}
