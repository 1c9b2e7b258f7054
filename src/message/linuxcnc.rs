//! LinuxCNC: its interpreter's own error messages are quoted verbatim (in
//! both languages, between “ ” in Chinese) with what they mean around
//! them; the warnings say what LinuxCNC does where it is silent.

use super::{phrases, templates};

templates! {
    LCNC_NON_INTEGER = ValueOutOfRange:
        "{word}: Non integer value for integer ({what} is a whole number)",
        "{word}：LinuxCNC 报警“Non integer value for integer”（{what} 必须是整数）";
    LCNC_NEGATIVE_L = ValueOutOfRange:
        "{word}: Negative l word used",
        "{word}：LinuxCNC 报警“Negative l word used”（L 不能为负）";
    LCNC_ALL_AXES_MISSING = MissingWord:
        "{word}: All axes missing with motion code (give the end point: X, Z)",
        "{word}：LinuxCNC 报警“All axes missing with motion code”（请给出终点 X、Z）";
    LCNC_WORD_UNUSED = UnexpectedWord:
        "{word}: {message}",
        "{word}：LinuxCNC 报警“{message}”（本段没有使用这个地址的代码）";
    LCNC_S_MISSING_G96 = MissingWord:
        "S word missing with G96 (the surface speed)",
        "LinuxCNC 报警“S word missing with G96”（G96 需要用 S 指定线速度）";
    LCNC_K_MISSING_G33 = MissingLead:
        "K word missing with g33/g33.1: every G33 block gives K, the distance along the move per revolution",
        "LinuxCNC 报警“K word missing with g33/g33.1”：每个 G33 程序段都要给出 K，即每转沿运动方向移动的距离";
    LCNC_F_WITH_G33 = UnexpectedWord:
        "{word}: F word used with a g33/g33.1",
        "{word}：LinuxCNC 报警“F word used with a g33/g33.1”（G33 的导程用 K 指定）";
    LCNC_P_MISSING_G76 = MissingLead:
        "P word missing with G76: every G76 block gives the pitch P, and I, J, K",
        "LinuxCNC 报警“P word missing with G76”：每个 G76 程序段都要给出螺距 P 以及 I、J、K";
    LCNC_P_MINUS_ONE_G76 = MissingLead:
        "P word missing with G76 (P-1 is the interpreter's value for no P): every G76 block gives the pitch P, and I, J, K",
        "LinuxCNC 报警“P word missing with G76”（P-1 在解释器中表示没有 P）：每个 G76 程序段都要给出螺距 P 以及 I、J、K";
    LCNC_I_MISSING_G76 = MissingWord:
        "I J or K words missing with G76 ({letter} is missing: I the peak offset, J the first depth, K the thread depth)",
        "LinuxCNC 报警“I J or K words missing with G76”（缺少 {letter}：I 为牙顶偏移，J 为第一刀切深，K 为牙深）";
    LCNC_J_MISSING_G76 = MissingFirstDepth:
        "I J or K words missing with G76 ({letter} is missing: I the peak offset, J the first depth, K the thread depth)",
        "LinuxCNC 报警“I J or K words missing with G76”（缺少 {letter}：I 为牙顶偏移，J 为第一刀切深，K 为牙深）";
    LCNC_K_MISSING_G76 = MissingThreadHeight:
        "I J or K words missing with G76 ({letter} is missing: I the peak offset, J the first depth, K the thread depth)",
        "LinuxCNC 报警“I J or K words missing with G76”（缺少 {letter}：I 为牙顶偏移，J 为第一刀切深，K 为牙深）";
    LCNC_COMP_RADIUS_G76 = CutterCompActive:
        "Bug code not g0 or g1: with cutter radius compensation on (radius {radius}) LinuxCNC sends G76 to the compensation path, which knows only G0 and G1; cancel it with G40 before G76",
        "LinuxCNC 报警“Bug code not g0 or g1”：刀具半径补偿有效（半径 {radius}）时，LinuxCNC 把 G76 交给补偿路径处理，而补偿路径只认 G0 和 G1；请在 G76 之前用 G40 取消补偿";
    LCNC_SPINDLE_NUMBER = ValueOutOfRange:
        "{message}: {word} selects a spindle, and {n} configured (setting linuxcnc.spindles) are $0..${last}",
        "LinuxCNC 报警“{message}”：{word} 选择主轴，而已配置的 {n} 个主轴（设置 linuxcnc.spindles）是 $0..${last}";
    LCNC_SPINDLE_NOT_TURNING_G76 = SpindleNotTurning:
        "Chosen spindle ({n}) not turning in G76: start it with M3 or M4 first",
        "LinuxCNC 报警“Chosen spindle ({n}) not turning in G76”：请先用 M3 或 M4 启动主轴";
    LCNC_ROTARY_G76 = UnexpectedWord:
        "{word}: Cannot move rotary axes with G76",
        "{word}：LinuxCNC 报警“Cannot move rotary axes with G76”（G76 不能移动旋转轴）";
    LCNC_COMP_G76 = CutterCompActive:
        "Cannot use G76 threading cycle with cutter radius compensation on: cancel it with G40 before G76",
        "LinuxCNC 报警“Cannot use G76 threading cycle with cutter radius compensation on”：请在 G76 之前用 G40 取消刀具半径补偿";
    LCNC_I_ZERO = ValueOutOfRange:
        "In G76, I must not be 0: I is the peak's offset from the drive line (negative external, positive internal)",
        "LinuxCNC 报警“In G76, I must not be 0”：I 是牙顶相对驱动线的偏移（外螺纹为负，内螺纹为正）";
    LCNC_J_NOT_POSITIVE = ValueOutOfRange:
        "In G76, J must be greater than 0 (J is the first pass depth; here {j})",
        "LinuxCNC 报警“In G76, J must be greater than 0”（J 为第一刀切深；此处为 {j}）";
    LCNC_K_NOT_OVER_J = ValueOutOfRange:
        "In G76, K must be greater than J (K {k} is the thread depth, J {j} the first pass depth)",
        "LinuxCNC 报警“In G76, K must be greater than J”（K {k} 为牙深，J {j} 为第一刀切深）";
    LCNC_ODD_P = OddPitch:
        "{word}: LinuxCNC passes a P of zero or below on as the spindle sync ratio; {what}",
        "{word}：LinuxCNC 把小于或等于零的 P 直接作为主轴同步比；{what}";
    LCNC_ODD_K = OddPitch:
        "{word}: LinuxCNC passes a K of zero or below on as the spindle sync ratio; {what}",
        "{word}：LinuxCNC 把小于或等于零的 K 直接作为主轴同步比；{what}";
    LCNC_DRIVE_LINE = DriveLineKept:
        "{word}: the passes are cut from the drive line X{x} (where the tool is); {letter} only moves the tool at the end of the cycle",
        "{word}：各刀从驱动线 X{x}（刀具所在位置）开始切削；{letter} 只在循环结束时移动刀具";
    LCNC_R_BELOW_1 = ValueReadAs:
        "{word}: a degression below 1 is read as R1 (constant depth J per pass)",
        "{word}：小于 1 的递减系数按 R1 读取（每刀切深都是 J）";
    LCNC_Q_MINUS_ONE = ValueReadAs:
        "Q-1 is the interpreter's value for no Q: the passes feed straight in (Q0), not at -1°",
        "Q-1 在解释器中表示没有 Q：各刀直进（Q0），而不是按 -1° 斜进";
    LCNC_NEGATIVE_H = FullDepthSkipped:
        "{word}: LinuxCNC cuts H + 1 passes at full depth, so with a negative H the thread is never cut to K",
        "{word}：LinuxCNC 在全牙深处切 H + 1 刀，H 为负时螺纹永远切不到 K";
    LCNC_NEGATIVE_E = ValueReadAs:
        "{word}: a negative taper length is read as E0: no taper is cut",
        "{word}：负的锥长按 E0 读取：不切锥";
    LCNC_L_MASK = ValueReadAs:
        "{word}: L is a bit mask (1 entry, 2 exit): L{l} gives {ends}",
        "{word}：L 是位掩码（1 入口，2 出口）：L{l} 表示{ends}";
    LCNC_E_WITHOUT_L = ValueReadAs:
        "{word}: without L1, L2 or L3 the taper length gives no taper",
        "{word}：没有 L1、L2 或 L3 时锥长不起作用，不切锥";
    LCNC_L_WITHOUT_E = ValueReadAs:
        "{word}: without a taper length E it gives no taper",
        "{word}：没有锥长 E 时它不起作用，不切锥";
    LCNC_SPINDLE_NOT_TURNING_G33 = SpindleNotTurning:
        "Spindle not turning in G33: start the spindle with M3 or M4 first",
        "LinuxCNC 报警“Spindle not turning in G33”：请先用 M3 或 M4 启动主轴";
    LCNC_LEAD_ALONG_PATH = LeadAlongPath:
        "{word}: G33 K is the distance along the move per revolution, so on this taper the tool advances {lead} per revolution along {axis} (K·cos α, α = {alpha}° from the axis); G32's F would give the lead along the long axis",
        "{word}：G33 的 K 是每转沿运动方向的距离，因此在这个锥螺纹上刀具每转沿 {axis} 前进 {lead}（K·cos α，α = {alpha}° 为与轴线的夹角）；G32 的 F 给出的才是沿长轴的导程";
    LCNC_NO_PROGRAM_END = NoProgramEnd:
        "File ended with no percent sign or program end: LinuxCNC needs M2 or M30 at the end (or the program between % lines); setting linuxcnc.require_end",
        "LinuxCNC 报警“File ended with no percent sign or program end”：程序末尾需要 M2 或 M30（或把程序放在两个 % 行之间）；设置 linuxcnc.require_end";
    LCNC_PLANE = PlaneNotXz:
        "{what} in G{plane}: the interpreter runs it as in G18, but the manual requires the XZ plane; put G18 in the program (or setting linuxcnc.startup_plane)",
        "{what} 在 G{plane} 平面：解释器按 G18 执行，但说明书要求 XZ 平面；请在程序中写 G18（或设置 linuxcnc.startup_plane）";
    LCNC_PASS_LIMIT = PassLimit:
        "G76 needs at least {n} passes (J {j}, K {k}, R {r}, H {h}): more than {limit} (setting limits.passes_per_start)",
        "G76 至少需要 {n} 刀（J {j}，K {k}，R {r}，H {h}）：超过 {limit} 刀（设置 limits.passes_per_start）";
    LCNC_FLOAT_EXTRA_PASS = FloatExtraPass:
        "pass {n}: |I| + {n}·J = {sum} is below |I| + K = {full} only by floating-point rounding, so LinuxCNC cuts it as a roughing pass at the full depth {k} and then cuts the full depth again",
        "第 {n} 刀：|I| + {n}·J = {sum} 只是因为浮点舍入才小于 |I| + K = {full}，所以 LinuxCNC 把它当作粗车刀切到全牙深 {k}，然后再切一次全牙深";
    LCNC_BACKWARD_CUT = BackwardCut:
        "taper length E{e} is more than half of the {len} between the thread's start and end: the synchronised cut between the tapers runs backwards, from Z{from} to Z{to}",
        "锥长 E{e} 超过螺纹起点到终点距离 {len} 的一半：两锥之间的同步切削方向相反，从 Z{from} 到 Z{to}";
    LCNC_MANY_PASSES = ManyPasses:
        "G76 cuts {n} passes (J {j}, K {k}, degression R {r}, H {h}); more than {limit} (setting linuxcnc.pass_warning): a larger J or a smaller R cuts fewer",
        "G76 切 {n} 刀（J {j}，K {k}，递减系数 R {r}，H {h}）；超过 {limit} 刀（设置 linuxcnc.pass_warning）：加大 J 或减小 R 可以减少刀数";
    LCNC_G7X_NO_Q = MissingWord:
        "{word}: G7x.x requires a Q word (Q names the subroutine that holds the profile: Q100 for o100)",
        "{word}：LinuxCNC 报警“G7x.x requires a Q word”（Q 指定存放轮廓的子程序：Q100 即 o100）";
    LCNC_G7X_COMP = CutterCompActive:
        "{name} cannot be used with cutter compensation enabled: cancel it with G40 before the cycle",
        "LinuxCNC 报警“{name} cannot be used with cutter compensation enabled”：请在循环之前用 G40 取消刀具半径补偿";
    LCNC_G7X_PLANE = CycleNeedsXz:
        "{name} can only be used in XZ plane (G18): put G18 before it",
        "LinuxCNC 报警“{name} can only be used in XZ plane (G18)”：请在它之前写 G18";
    LCNC_G7X_I = ValueOutOfRange:
        "{word}: G7X error: I must be greater than zero. (I is the depth of each cut)",
        "{word}：LinuxCNC 报警“G7X error: I must be greater than zero.”（I 为每刀的切深）";
    LCNC_G7X_NOT_MONOTONIC = ProfileRefused:
        "G7X error: Not monotonic: the profile of {sub} goes back along {axis}, and {name} needs it to run one way along {axis} from its first point to its last (pockets go in and out along {other} only)",
        "LinuxCNC 报警“G7X error: Not monotonic”：子程序 {sub} 的轮廓沿 {axis} 向回走，而 {name} 要求轮廓从第一点到最后一点沿 {axis} 单向走（凹槽只能沿 {other} 进出）";
    LCNC_G70_NOT_MONOTONIC = ProfileRefused:
        "G7X error: Not monotonic: the profile of {sub} goes back both along Z and along X, and G70 needs it to run one way along one of them from its first point to its last",
        "LinuxCNC 报警“G7X error: Not monotonic”：子程序 {sub} 的轮廓沿 Z 和沿 X 都有向回走的段，而 G70 要求轮廓从第一点到最后一点至少沿其中一个方向单向走";
    LCNC_G7X_PROFILE = ProfileRefused:
        "G7X error: {message}: LinuxCNC gives up on the profile of {sub} offset by D{d}",
        "LinuxCNC 报警“G7X error: {message}”：LinuxCNC 无法处理子程序 {sub} 偏移 D{d} 后的轮廓";
    LCNC_G7X_PARALLEL = ProfileRefused:
        "G7X error: Cannot intersect parallel lines: two pieces of the profile of {sub} next to each other run along one line, and LinuxCNC offsets each (by D{d}, or for a corner A or C) and joins it to the next where they cross; write them as one move",
        "LinuxCNC 报警“G7X error: Cannot intersect parallel lines”：子程序 {sub} 的轮廓中相邻两段在同一直线上，而 LinuxCNC 把每段偏移（偏移 D{d}，或为拐角 A、C 偏移）后在交点处与下一段相接；请把它们写成一段";
    LCNC_G7X_MOVE = ProfileRefused:
        "G7X error: {message} (in the profile of {sub}: an arc takes R, or I and K; a corner A or C)",
        "LinuxCNC 报警“G7X error: {message}”（子程序 {sub} 的轮廓中：圆弧用 R，或用 I 和 K；拐角用 A 或 C）";
    LCNC_G7X_ARC = ArcRadiusMismatch:
        "{message}: an arc of {name}'s path, from where the tool is, which LinuxCNC checks as a programmed arc (X as radii)",
        "LinuxCNC 报警“{message}”：{name} 路径中的一段圆弧，从刀具所在处开始，LinuxCNC 按编程圆弧检查它（X 为半径）";
    LCNC_G7X_OFFSET = ProfileRefused:
        "{name}: offsetting the profile of {sub} by D{d} does not come to an end (LinuxCNC offsets it in steps of at most half its shortest piece): the cycle is not drawn",
        "{name}：子程序 {sub} 的轮廓偏移 D{d} 无法完成（LinuxCNC 每次最多偏移最短一段的一半）：不绘制该循环";
    LCNC_G7X_ENDLESS = ProfileRefused:
        "{name}: the profile of {sub} does not cross the cut from X{x} Z{z}, and LinuxCNC 2.9 repeats that cut for ever: the moves are drawn up to there",
        "{name}：子程序 {sub} 的轮廓与从 X{x} Z{z} 开始的切削线不相交，LinuxCNC 2.9 会无限重复这一刀：只绘制到此为止的移动";
    LCNC_G7X_TOO_MANY = PassLimit:
        "{name} needs more than {limit} cuts (I {i}): the moves are drawn up to there",
        "{name} 需要超过 {limit} 刀（I {i}）：只绘制到此为止的移动";
    LCNC_G70_TOO_MANY = PassLimit:
        "G70 runs more than {limit} passes, or moves (P {p}): the moves are drawn up to there",
        "G70 的走刀超过 {limit} 次或移动过多（P {p}）：只绘制到此为止的移动";
}

phrases! {
    PROFILE_Q: "Q, the number of the profile's subroutine", "Q（轮廓子程序的编号）";
    NS_G7X_INCREMENTAL: "a G70–G72 profile cycle in incremental mode G91", "增量模式 G91 下的 G70–G72 轮廓循环";
    SPRING_COUNT_H: "the spring pass count H", "光刀次数 H";
    L_WORD: "L", "L";
    P_ZERO: "no thread is drawn, only the moves", "不绘制螺纹，只绘制移动";
    P_NEGATIVE: "the thread is drawn with |P|", "螺纹按 |P| 绘制";
    K_ZERO: "with K0 the axes would wait for a spindle that never moves them: the move is drawn, but no thread",
        "K0 时各轴等待的主轴同步永远不会让它们移动：只绘制移动，不绘制螺纹";
    K_NEGATIVE: "a negative ratio runs the axes against the spindle: the thread is drawn with |K|",
        "负的同步比使各轴与主轴反向运动：螺纹按 |K| 绘制";
    NO_TAPER: "no taper", "不切锥";
    ENTRY_TAPER: "an entry taper", "入口锥";
    EXIT_TAPER: "an exit taper", "出口锥";
    BOTH_TAPERS: "tapers at both ends", "两端都切锥";
}
