//! What the program-writing tools say: the thread wizard's ([`crate::wizard`])
//! notes and refusals, and the notes of `expand` ([`crate::expand`]). They
//! are not diagnostics of a program (no code, no position), so they are
//! phrases with arguments ([`super::Remark`]).

use super::phrases;

phrases! {
    WZ_NOSE_GIVEN: "", "";
    WZ_NOSE_ASSUMED: " (not given: a full-profile insert, 0.125·P external, 0.108·P internal, as the thread check takes it)", "（未给出：按全牙型刀片，外螺纹 0.125·P、内螺纹 0.108·P，与螺纹检验相同）";
    // ---- the forms a program is written in ----
    FORM_G32: "G32 block by block (textbook, table 4-3)", "G32 逐段编程（教材表 4-3）";
    FORM_G92: "G92 simple cycle", "G92 简单螺纹循环";
    FORM_G76: "G76 multiple cycle", "G76 复合螺纹循环";
    FORM_G78: "G78 enhanced cycle", "G78 增强螺纹循环";
    FORM_RENHE_G33: "Renhe G33 block by block", "仁和 G33 逐段编程";
    FORM_G33: "LinuxCNC G33 block by block", "LinuxCNC G33 逐段编程";
    FORM_LINUXCNC_G76: "LinuxCNC G76 cycle", "LinuxCNC G76 螺纹循环";
    // ---- the wizard: what it cannot write ----
    WZ_NO_FORM:
        "{dialect} has no {form} form; it has {forms}",
        "{dialect} 没有 {form} 格式；可选：{forms}";
    WZ_NEED_SIZE:
        "give a designation, or a major diameter and a lead",
        "请给出螺纹标记，或者大径和导程";
    WZ_SIZE_POSITIVE:
        "the major diameter and the lead must be positive",
        "大径和导程必须为正数";
    WZ_DESIGNATION:
        "{error}",
        "{error}";
    WZ_NEED_END:
        "give the thread's end Z or its length",
        "请给出螺纹终点 Z 或螺纹长度";
    WZ_NO_LENGTH:
        "the thread has no length: its end Z is its start Z",
        "螺纹长度为零：终点 Z 与起点 Z 相同";
    WZ_NO_DEPTH:
        "the thread has no depth",
        "螺纹深度为零";
    WZ_NO_SPEED:
        "no spindle speed fits: the thread feed lead {lead} × 1 rev/min is over the machine's {feed} mm/min",
        "没有合适的主轴转速：导程 {lead} × 1 转/分 的螺纹进给已超过机床的 {feed} mm/min";
    WZ_BORE_TOO_SMALL:
        "the bore (Ø{bore}) is too small to enter with {clearance} of clearance",
        "内孔（Ø{bore}）太小，留 {clearance} 的间隙后刀具进不去";
    WZ_RENHE_NO_SPEED:
        "the Renhe speed advice n ≤ 2300/t − 60 leaves no speed for a lead of {lead}",
        "按仁和的转速建议 n ≤ 2300/t − 60，导程 {lead} 没有可用的转速";
    WZ_RENHE_TOO_SHORT:
        "Renhe threads must be longer than 4 mm (E18-04), lead-in included",
        "仁和系统的螺纹（含升速进刀段）必须长于 4 mm（E18-04）";
    WZ_RENHE_PITCH:
        "Renhe's G33 takes a pitch of 0.25..12 mm, not {lead}",
        "仁和 G33 的螺距范围为 0.25..12 mm，不能是 {lead}";
    WZ_LINUXCNC_TAPER:
        "LinuxCNC's G76 cuts straight threads only (E and L taper its ends): choose G33 for a taper thread",
        "LinuxCNC 的 G76 只切直螺纹（E 和 L 只使两端成锥）：锥螺纹请选 G33";
    // ---- the wizard: its choices ----
    WZ_BASIC_PROFILE:
        "no designation: a basic 60° profile (ISO 68-1) without a tolerance class",
        "没有螺纹标记：按 60° 基本牙型（ISO 68-1）计算，不带公差等级";
    WZ_NPT:
        "NPT: a 1:16 taper on the diameter, the small end at the start Z, cut to the truncated height 0.8·P",
        "NPT：直径上 1:16 的锥度，小端在起点 Z，切到截顶牙高 0.8·P";
    WZ_LAST_PASS:
        "the last pass puts the pitch diameter in the middle of its tolerance with a 60° tool of nose radius {r}{how} (d2 = X ∓ 2r ± 0.866025·P)",
        "最后一刀使中径落在公差带中间，刀具为 60°、刀尖圆弧半径 {r}{how}（d2 = X ∓ 2r ± 0.866025·P）";
    WZ_SPINDLE:
        "spindle S{s}: within the machine's {rpm} rev/min and {feed} mm/min of thread feed, with n·L/500 ≤ 5 mm of lead-in and n·L/1800 ≤ 2 mm of run-out past the end (leave a relief groove)",
        "主轴 S{s}：不超过机床的 {rpm} 转/分和 {feed} mm/min 螺纹进给，且升速进刀段 n·L/500 ≤ 5 mm、终点后的降速退刀段 n·L/1800 ≤ 2 mm（请留退刀槽）";
    WZ_RENHE_SPINDLE:
        "spindle S{s} by Renhe's advice n ≤ 2300/t − 60",
        "按仁和的建议 n ≤ 2300/t − 60，主轴取 S{s}";
    WZ_G92_CHAMFER:
        "G92 ends in the chamfer of parameter 5130 (default: one lead): programmed to Z{z}, one lead past the thread's end, so leave a relief groove",
        "G92 以参数 5130 的倒角收尾（默认一个导程）：编程到 Z{z}，比螺纹终点多一个导程，请留退刀槽";
    WZ_LINUXCNC_G76:
        "G76 with R2 (constant chip area), Q29.5 (compound infeed along the flank of a 60° tool) and H1",
        "G76 取 R2（切削面积恒定）、Q29.5（沿 60° 刀具牙侧斜进）和 H1";
    // ---- expand ----
    EX_MM_ONLY:
        "{dialect} reads millimetres only: the inch program is written in mm",
        "{dialect} 只接受毫米：英制程序按毫米写出";
    EX_NO_CSS:
        "constant surface speed (G96) is not written: set the spindle speed before the threads",
        "恒线速（G96）没有写出：请在螺纹之前设定主轴转速";
    EX_STRAY_THREAD_MOVE:
        "line {line}: a synchronised move that belongs to no thread is written as a feed",
        "第 {line} 行：不属于任何螺纹的同步运动按进给写出";
    EX_NO_FEED:
        "the plan has no feed rates: the turning moves are written with F0.2",
        "计划里没有进给速度：车削运动按 F0.2 写出";
    EX_RENHE_TAIL_LAST:
        "Renhe applies the G30 tail to every block of a continuous thread: the segments before the last are written without a tail",
        "仁和对连续螺纹的每一段都执行 G30 退尾：最后一段之前的各段按无退尾写出";
    EX_RENHE_RUNOUT:
        "a run-out Renhe cannot write as a G30 tail is written as a thread block",
        "无法用 G30 退尾表示的退尾段按螺纹程序段写出";
    EX_RENHE_SHORT:
        "a Renhe thread block must be longer than 4 mm and than its U: W{w} U{u} will alarm (E18-04)",
        "仁和的螺纹程序段必须长于 4 mm 且长于其 U：W{w} U{u} 会报警（E18-04）";
    EX_RENHE_X_FEED:
        "Renhe sets a thread's run-out direction from the X feed before it (E18-05 without one): the first pass, approached from an unknown place, goes out to X{x} and back in before it",
        "仁和由螺纹之前的 X 向进刀确定退尾方向（没有则报警 E18-05）：第一刀的进刀起点未知，先退到 X{x} 再进刀";
}
