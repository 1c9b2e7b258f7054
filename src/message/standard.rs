//! Thread designations: what the parser did not understand and the
//! limits a standard does not give (shown in the `bad-designation`
//! diagnostics and by the wizard).

use super::{phrases, templates};

templates! {
    STD_EMPTY = BadDesignation:
        "empty designation",
        "螺纹标记为空";
    STD_NOT_ASCII = BadDesignation:
        "'{s}': unexpected character (only ASCII and × are understood)",
        "'{s}'：有无法识别的字符（只识别 ASCII 字符和 ×）";
    STD_NOT_A_DESIGNATION = BadDesignation:
        "'{s}' is not a thread designation: expected M<d>[x<P>][-<class>] (ISO metric), <size>-<tpi> UNC/UNF/UNEF/UN[-<class>] (Unified) or <size>-<tpi> NPT",
        "'{s}' 不是螺纹标记：应为 M<d>[x<P>][-<公差带>]（ISO 米制）、<尺寸>-<每英寸牙数> UNC/UNF/UNEF/UN[-<等级>]（统一螺纹）或 <尺寸>-<每英寸牙数> NPT";
    STD_ISO_MIXED = BadDesignation:
        "ISO class mixes external (e f g h) and internal (G H) positions",
        "ISO 公差带混用了外螺纹（e f g h）和内螺纹（G H）的基本偏差";
    STD_ISO_EXTERNAL_GRADES = BadDesignation:
        "tolerance class not in ISO 965-1: external grades are 3–9 for the pitch diameter and 4, 6, 8 for the major diameter",
        "ISO 965-1 中没有这个公差带：外螺纹中径公差等级为 3–9，大径为 4、6、8";
    STD_ISO_INTERNAL_GRADES = BadDesignation:
        "tolerance class not in ISO 965-1: internal grades are 4–8",
        "ISO 965-1 中没有这个公差带：内螺纹公差等级为 4–8";
    STD_TWO_CLASSES = BadDesignation:
        "'{s}': two tolerance classes (fit designations such as 6H/6g are not read; give one)",
        "'{s}'：有两个公差带（不识别 6H/6g 这样的配合标记；请只给一个）";
    STD_FIT = BadDesignation:
        "'{s}': fit designations such as 6H/6g are not read; give one class",
        "'{s}'：不识别 6H/6g 这样的配合标记；请只给一个公差带";
    STD_NOT_UNDERSTOOD = BadDesignation:
        "'{s}': did not understand '{rest}': after the size come a tolerance class (a grade and a position: 6g, 4h6h, 6H), LH, or an engagement group S, N or L",
        "'{s}'：无法识别 '{rest}'：尺寸之后应为公差带（公差等级加基本偏差：6g、4h6h、6H）、LH 或旋合长度组 S、N、L";
    STD_NO_DIAMETER = BadDesignation:
        "'{s}': expected the nominal diameter after M",
        "'{s}'：M 后应为公称直径";
    STD_NO_LEAD = BadDesignation:
        "'{s}': expected the lead after Ph",
        "'{s}'：Ph 后应为导程";
    STD_NO_PITCH_AFTER_LEAD = BadDesignation:
        "'{s}': expected P<pitch> after Ph<lead>",
        "'{s}'：Ph<导程> 后应为 P<螺距>";
    STD_NO_PITCH = BadDesignation:
        "'{s}': expected the pitch after x",
        "'{s}'：x 后应为螺距";
    STD_NO_COARSE_PITCH = BadDesignation:
        "M{d} has no ISO 261 coarse pitch; give the pitch, e.g. M{d}x1.5",
        "M{d} 在 ISO 261 中没有粗牙螺距；请给出螺距，如 M{d}x1.5";
    STD_LEAD_NOT_MULTIPLE = BadDesignation:
        "'{s}': lead Ph{lead} is not a whole multiple of pitch P{pitch}",
        "'{s}'：导程 Ph{lead} 不是螺距 P{pitch} 的整数倍";
    STD_UNKNOWN_SERIES = BadDesignation:
        "'{s}': unknown Unified series '{word}'",
        "'{s}'：未知的统一螺纹系列 '{word}'";
    STD_NO_SIZE_AND_TPI = BadDesignation:
        "'{s}': could not read the size and threads per inch",
        "'{s}'：无法读出尺寸和每英寸牙数";
    STD_NO_SIZE = BadDesignation:
        "'{s}': could not read the size '{size}'",
        "'{s}'：无法读出尺寸 '{size}'";
    STD_GIVE_TPI = BadDesignation:
        "'{s}': give the threads per inch, e.g. 1-8 UN-2A",
        "'{s}'：请给出每英寸牙数，如 1-8 UN-2A";
    STD_UNIFIED_CLASS = BadDesignation:
        "did not understand '{tok}' (Unified classes are 1A, 2A, 3A, 1B, 2B, 3B)",
        "无法识别 '{tok}'（统一螺纹的等级为 1A、2A、3A、1B、2B、3B）";
    STD_NPTF = BadDesignation:
        "'{s}': NPTF (dryseal, ASME B1.20.3) is not covered",
        "'{s}'：不支持 NPTF（干密封管螺纹，ASME B1.20.3）";
    STD_AFTER_NPT = BadDesignation:
        "'{s}': did not understand '{tail}' after NPT",
        "'{s}'：无法识别 NPT 后的 '{tail}'";
    STD_NO_PIPE_SIZE_AND_TPI = BadDesignation:
        "'{s}': could not read the pipe size and threads per inch",
        "'{s}'：无法读出管子尺寸和每英寸牙数";
    STD_NO_PIPE_SIZE = BadDesignation:
        "'{s}': could not read the pipe size",
        "'{s}'：无法读出管子尺寸";
    STD_NOT_NPT_SIZE = BadDesignation:
        "'{s}': {nominal} in is not an NPT size (1/16 … 12)",
        "'{s}'：{nominal} 英寸不是 NPT 尺寸（1/16 … 12）";
    STD_NPT_TPI = BadDesignation:
        "'{s}': NPT {size} has {standard} threads per inch, not {tpi}",
        "'{s}'：NPT {size} 的每英寸牙数为 {standard}，不是 {tpi}";
    STD_NOT_POSITIVE = BadDesignation:
        "nominal diameter and pitch must be positive numbers",
        "公称直径和螺距必须是正数";
    STD_UNIFIED_NEEDS_CLASS = BadDesignation:
        "a Unified thread needs a class 1A–3A or 1B–3B",
        "统一螺纹需要等级 1A–3A 或 1B–3B";
    STD_UNIFIED_NO_GRADE = BadDesignation:
        "Unified class {grade} does not exist (1, 2 or 3)",
        "统一螺纹没有 {grade} 级（只有 1、2、3 级）";
    STD_ISO_PITCH = BadDesignation:
        "pitch {p} mm is not one of the ISO 965-1 pitches (0.2 … 8 mm); no tolerances",
        "螺距 {p} mm 不是 ISO 965-1 中的螺距（0.2 … 8 mm）；没有公差";
    STD_ISO_NO_PITCH_TOLERANCE = BadDesignation:
        "ISO 965-1 tabulates no pitch-diameter tolerance for d = {d} mm with P = {p} mm",
        "ISO 965-1 没有列出 d = {d} mm、P = {p} mm 的中径公差";
    STD_ISO_UNDEFINED = BadDesignation:
        "ISO 965-1 defines no {what} for {zone} at P = {p} mm (d = {d} mm)",
        "ISO 965-1 没有规定 {zone} 在 P = {p} mm（d = {d} mm）时的{what}";
    STD_ISO_NEEDS_CLASS = BadDesignation:
        "an ISO metric thread needs an ISO tolerance class such as 6g or 6H",
        "ISO 米制螺纹需要公差带，如 6g 或 6H";
    STD_ISO_TOO_LARGE = BadDesignation:
        "d = {d} mm is outside ISO 965-1 (up to 355 mm tabulated)",
        "d = {d} mm 超出 ISO 965-1 的范围（表中到 355 mm）";
    STD_NO_NPT_SIZE = BadDesignation:
        "no NPT size has an outside diameter of {d} in",
        "没有外径为 {d} 英寸的 NPT 尺寸";
}

phrases! {
    FUNDAMENTAL_DEVIATION: "fundamental deviation", "基本偏差";
    TD2: "Td2", "中径公差 Td2";
    TD: "Td", "大径公差 Td";
    TD2_INTERNAL: "TD2", "中径公差 TD2";
    TD1: "TD1", "小径公差 TD1";
}
