//! Planning cycles and grouping passes: the cycles' geometry, run-out and
//! screw-in, the depth schedule, starts and the motion limit; the words
//! and contours of the stock-removal cycles G71–G73.

use super::{phrases, templates};

templates! {
    FACE_THREAD_CYCLE = FaceThreadNotAllowed:
        "{what} cuts straight and taper threads along Z only: the end Z is the start Z, which would be a face thread (use G32)",
        "{what} 只能沿 Z 向切削直螺纹和锥螺纹：终点 Z 等于起点 Z，那是端面螺纹（请用 G32）";
    TAPER_BEYOND_START = TaperBeyondStart:
        "{what}: taper R{i} and U/2 = {half_u} have opposite signs and |R| > |U/2|: the cut would start at X{x}, beyond the start point X{ax}; the manual allows |R| ≤ |U/2|",
        "{what}：锥度 R{i} 与 U/2 = {half_u} 符号相反且 |R| > |U/2|：切削将从 X{x} 开始，超出起点 X{ax}；说明书规定 |R| ≤ |U/2|";
    CYCLE_NO_LENGTH = ZeroLengthThread:
        "{what}: the thread has no length (end Z is the start Z)",
        "{what}：螺纹长度为零（终点 Z 等于起点 Z）";
    CYCLE_ALONG_X = FaceThreadNotAllowed:
        "{what} cuts straight and taper threads along Z only: this thread runs along X (a face or steep thread needs G32)",
        "{what} 只能沿 Z 向切削直螺纹和锥螺纹：这个螺纹沿 X 方向（端面螺纹或大锥度螺纹需用 G32）";
    ENDS_TOO_LONG = RunoutTooLong:
        "run-out {ro} and screw-in {si} together are longer than the thread's {len} of Z",
        "退尾 {ro} 与切入 {si} 之和超过螺纹的 Z 向长度 {len}";
    ENDS_TOO_LONG_SHIFTED = RunoutTooLong:
        "run-out {ro} and screw-in {si} together, with passes starting up to {shift} along the cut, are longer than the thread's {len} of Z",
        "退尾 {ro} 与切入 {si} 之和（各刀起点沿切削方向最多错开 {shift}）超过螺纹的 Z 向长度 {len}";
    PASS_LIMIT = PassLimit:
        "the depth schedule needs {needed} passes per start (k {k}, Δd {dd}, Δdmin {dmin}, d {d}): more than {limit} (setting limits.passes_per_start)",
        "切深分配每头需要 {needed} 刀（k {k}，Δd {dd}，Δdmin {dmin}，d {d}）：超过 {limit} 刀（设置 limits.passes_per_start）";
    CYCLE_TOO_MANY_STARTS = TooManyStarts:
        "{n} starts: at most {limit} (setting limits.starts)",
        "{n} 头：最多 {limit} 头（设置 limits.starts）";
    START_INSIDE_THREAD = StartInsideThread:
        "the start point X{x} is inside the thread's crest X{crest}: the approach rapids through the work",
        "起点 X{x} 在螺纹牙顶 X{crest} 以内：快速接近时会穿过工件";
    TOO_MANY_STARTS = TooManyStarts:
        "{n} starts (distinct start angles Q): at most {limit} (setting limits.starts)",
        "{n} 头（不同的起始角 Q）：最多 {limit} 头（设置 limits.starts）";
    ROUGH_DEPTH_ZERO = ValueOutOfRange:
        "{word}: the depth of cut Δd must be more than 0",
        "{word}：切削深度 Δd 必须大于 0";
    G73_DIVISIONS = ValueOutOfRange:
        "{word}: the number of divisions d of G73 is its number of passes, a whole number 1 or more",
        "{word}：G73 的分割次数 d 就是走刀次数，应为不小于 1 的整数";
    G73_DIVISIONS_OVER = PassLimit:
        "{word}: {d} passes: more than {limit} (setting limits.passes_per_start)",
        "{word}：{d} 次走刀：超过 {limit} 次（设置 limits.passes_per_start）";
    G73_NO_DIVISIONS = MissingWord:
        "{word} sets the relief U(Δi) W(Δk), but no number of divisions R(d) has been given: give R",
        "{word} 给出了退刀量 U(Δi) W(Δk)，但之前没有给出分割次数 R(d)：请指定 R";
    G73_TOO_MANY_MOVES = PassLimit:
        "G73: {d} passes over a contour of {points} points are {moves} motions, more than the {limit} the preview plans for one cycle",
        "G73：{d} 次走刀、轮廓 {points} 个点，共 {moves} 段运动，超过预览对一个循环规划的 {limit} 段";
    CONTOUR_GOES_BACK = ContourNotMonotone:
        "{what}: the finishing shape goes back along {cut}; the cuts run along {cut}, so it must go one way along it: not roughed",
        "{what}：精车形状沿 {cut} 向折返；粗车沿 {cut} 向切削，形状必须沿 {cut} 单向变化：不粗车";
    CONTOUR_TYPE_ONE = ContourNotMonotone:
        "{what}: the finishing shape goes up and down along {across} but its first block moves {across} only (type I, which needs a monotone shape); for pockets (type II) the first block must move both axes ({zero} when the other does not move): not roughed",
        "{what}：精车形状沿 {across} 向有升有降，但其第一段只移动 {across}（类型 I，要求形状单调）；要加工凹槽（类型 II），第一段须同时指定两轴（另一轴不移动时写 {zero}）：不粗车";
    CONTOUR_NO_POCKETS = ContourNotMonotone:
        "{what}: the finishing shape goes up and down along {across}; {controller} roughs a shape monotone along X and Z only (no pockets): not roughed",
        "{what}：精车形状沿 {across} 向有升有降；{controller} 只能粗车 X、Z 向都单调变化的形状（不能有凹槽）：不粗车";
    MOVE_LIMIT = MoveLimit:
        "more than {limit} motions (setting limits.moves): the rest of the program is not drawn",
        "运动超过 {limit} 段（设置 limits.moves）：程序其余部分不绘制";
}

phrases! {
    TOO_MANY: "too many", "过多";
}
