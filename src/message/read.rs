//! The interpreter and the controllers' shared commands: G codes, modal
//! groups, arcs, words out of place or out of range, the lead and depth
//! words, G32, G76, G92 and G78.

use super::{phrases, templates};

templates! {
    AFTER_END = AfterEnd:
        "blocks after M30/M02 are never executed",
        "M30/M02 之后的程序段不会执行";
    UNSUPPORTED_G_CODE = UnsupportedGCode:
        "{word} is not a G code of the {controller} controller",
        "{word} 不是 {controller} 系统的 G 代码";
    CONFLICTING_G_CODES = ConflictingGCodes:
        "{first} and {second} are in the same modal group",
        "{first} 和 {second} 属于同一模态组";
    UNITS_CHANGED = UnitsChanged:
        "units changed after motion: earlier coordinates stay in the old unit and the drawing mixes them",
        "已有运动之后又切换了单位：之前的坐标仍按原单位，图形中两种单位混在一起";
    NOSE_COMP_NOT_SIMULATED = NotSimulated:
        "tool-nose radius compensation (G41/G42) is not simulated: the tool tip point is drawn",
        "不模拟刀尖半径补偿（G41/G42）：图中画的是刀尖点";
    SETUP_NOT_SIMULATED = NotSimulated:
        "{word}: {what} is not simulated",
        "{word}：{what}不模拟";
    NOT_DRAWN = NotSimulated:
        "{word}: {what} is not drawn",
        "{word}：{what}不绘制";
    SUBPROGRAM_NOT_FOLLOWED = NotSimulated:
        "{word}: subprogram calls are not followed",
        "{word}：不跟踪子程序调用";
    G28_INTERMEDIATE = NotSimulated:
        "G28: the move to the intermediate point is drawn; the reference point is machine-specific, so the position after it is unknown until the next absolute move",
        "G28：只绘制到中间点的移动；参考点位置取决于机床，因此在下一个绝对坐标移动之前刀具位置未知";
    G04_NEEDS_TIME = MissingWord:
        "G04 needs the dwell time: P (ms), X or U (s)",
        "G04 需要暂停时间：P（ms）、X 或 U（s）";
    G50_NEEDS_WORDS = MissingWord:
        "G50 needs X/Z (coordinate system) or S (spindle clamp)",
        "G50 需要 X/Z（设定坐标系）或 S（主轴最高转速限制）";
    MISSING_FEED = MissingFeed:
        "feed move without a feed rate: no F has been given yet",
        "切削进给没有进给速度：之前还没有指定过 F";
    ARC_FULL_CIRCLE = ArcRadiusTooSmall:
        "an R arc cannot be a full circle: its start and end are the same point",
        "用 R 编程的圆弧不能是整圆：起点和终点重合";
    ARC_RADIUS_TOO_SMALL = ArcRadiusTooSmall:
        "radius {radius} is shorter than half the chord {half}",
        "半径 {radius} 小于弦长的一半 {half}";
    ARC_RADIUS_MISMATCH = ArcRadiusMismatch:
        "the centre is {r0} from the start but {r1} from the end (tolerance {tol}, setting arc.tolerance)",
        "圆心到起点的距离为 {r0}，到终点的距离却为 {r1}（允差 {tol}，设置 arc.tolerance）";
    ARC_MISSING_CENTER = ArcMissingCenter:
        "{word} needs R or I/K for its centre",
        "{word} 需要 R 或 I/K 来确定圆心";
    START_ASSUMED = StartAssumed:
        "tool position unknown (no absolute X/Z or G50 before this block): start taken as {start} (settings start.x, start.z)",
        "刀具位置未知（本段之前没有绝对坐标 X/Z 或 G50）：起点取 {start}（设置 start.x、start.z）";
    NO_DECIMAL_POINT = NoDecimalPoint:
        "{word} has no decimal point: with parameter 3401#0 (DPI) = 0 it means {value} {unit}, not {written} {unit}; write {letter}{written}. if you meant {written}",
        "{word} 没有小数点：参数 3401#0（DPI）= 0 时它表示 {value} {unit}，而不是 {written} {unit}；如果要的是 {written}，请写成 {letter}{written}.";
    AXIS_CONFLICT = AxisConflict:
        "{abs} and {inc} in one block: give the axis once, absolute or incremental",
        "{abs} 和 {inc} 在同一程序段：同一轴只能指定一次，绝对或增量二选一";
    UNEXPECTED_WORD = UnexpectedWord:
        "{what} does not take {word}",
        "{what} 不能带 {word}";
    UNEXPECTED_WORD_FIRST_BLOCK = UnexpectedWord:
        "{what} (first block) does not take {word}",
        "{what}（第一段）不能带 {word}";
    VALUE_OUT_OF_RANGE = ValueOutOfRange:
        "{word}: {what} {value} is outside {lo}..{hi}",
        "{word}：{what} {value} 超出范围 {lo}..{hi}";
    LEAD_TWICE = UnexpectedWord:
        "{what}: give the lead once, F (lead) or I (threads per inch), not both",
        "{what}：导程只能指定一次，F（导程）或 I（每英寸牙数），不能同时指定";
    LEAD_OUT_OF_RANGE = ValueOutOfRange:
        "lead {word} is outside 0.001..{max} {unit}",
        "导程 {word} 超出范围 0.001..{max} {unit}";
    TPI_OUT_OF_RANGE = ValueOutOfRange:
        "{tpi} threads per inch is outside 0.06..25400",
        "每英寸牙数 {tpi} 超出范围 0.06..25400";
    FEED_REGISTER_NOT_A_LEAD = MissingLead:
        "{what} has no F, and the F register holds F{lead} from line {line}, which cannot be a lead; give the lead in this block",
        "{what} 没有 F，而 F 寄存器中是第 {line} 行的 F{lead}，不能作为导程；请在本段指定导程";
    LEAD_FROM_FEED = LeadFromFeed:
        "{what} has no F: the single F register holds F{lead} from line {line}, a feed rate, so this thread is cut with a lead of {lead}; give the lead in this block",
        "{what} 没有 F：系统只有一个 F 寄存器，其中是第 {line} 行的进给速度 F{lead}，因此这段螺纹按导程 {lead} 切削；请在本段指定导程";
    MISSING_LEAD_FEED_APART = MissingLead:
        "{what} without a lead: the feed F{feed} of line {line} is not a lead ({controller} keeps the thread lead apart); give F (lead){or_tpi}",
        "{what} 没有导程：第 {line} 行的进给速度 F{feed} 不是导程（{controller} 的螺纹导程单独保存）；请指定 F（导程）{or_tpi}";
    MISSING_LEAD = MissingLead:
        "{what} without a lead: give F (lead){or_tpi}",
        "{what} 没有导程：请指定 F（导程）{or_tpi}";
    START_ANGLE_NO_POINT = DecimalPointNotAllowed:
        "{word}: the start angle is in 0.001° and takes no decimal point (Q180000 = 180°)",
        "{word}：起始角以 0.001° 为单位，不能带小数点（Q180000 = 180°）";
    START_ANGLE_OUT_OF_RANGE = ValueOutOfRange:
        "start angle {word} is {deg}°, outside 0..360°",
        "起始角 {word} 为 {deg}°，超出 0..360°";
    DEPTH_NO_POINT = DecimalPointNotAllowed:
        "{word}: {what} is an integer in least input increments ({per} per unit)",
        "{word}：{what} 是以最小输入单位计的整数（每单位 {per}）";
    DEPTH_POINT_IGNORED = DecimalPointIgnored:
        "{word}: with NO182.7 = 0 {what} is in least input increments whatever the decimal point, so this is {value} {unit}",
        "{word}：NO182.7 = 0 时，不论有无小数点，{what} 都按最小输入单位计，所以这里是 {value} {unit}";
    MISSING_THREAD_HEIGHT = MissingThreadHeight:
        "{what} needs the thread height P(k)",
        "{what} 需要螺纹牙高 P(k)";
    MISSING_FIRST_DEPTH = MissingFirstDepth:
        "{what} needs the first cut depth Q(Δd)",
        "{what} 需要第一刀切深 Q(Δd)";
    Q_IGNORED = QIgnored:
        "{word}: in a continuous thread only the first block's start angle counts; this Q is ignored",
        "{word}：连续螺纹只有第一段的起始角有效；此 Q 被忽略";
    G32_NO_MOVE = ZeroLengthThread:
        "G32 does not move: the end point is the start point",
        "G32 没有移动：终点就是起点";
    RUNOUT_K_TOO_LONG = RunoutTooLong:
        "run-out length K = {k} is longer than the thread's {travel} of long-axis travel",
        "退尾长度 K = {k} 超过螺纹的长轴行程 {travel}";
    RUNOUT_BY_NO107 = RunoutSpeed:
        "run-out by parameter No.107: short axis at {speed} mm/min against the thread feed {feed} mm/min (lead {lead} × S{s}): it retracts {j} over {len} of long-axis travel, {angle}° from the axis (K = {k} is not used)",
        "按参数 No.107 退尾：短轴速度 {speed} mm/min，螺纹进给 {feed} mm/min（导程 {lead} × S{s}）：在长轴行程 {len} 内退出 {j}，与轴线成 {angle}°（不使用 K = {k}）";
    NO107_WITHOUT_SPINDLE = RunoutSpeed:
        "parameter No.107 = {v} sets the run-out speed, but the spindle speed (S under G97) is unknown: the run-out is drawn from J and K",
        "参数 No.107 = {v} 设定了退尾速度，但主轴转速（G97 下的 S）未知：退尾按 J 和 K 绘制";
    G76_P_DIGITS = ValueOutOfRange:
        "{word}: P(m)(r)(a) is six digits, mmrraa",
        "{word}：P(m)(r)(a) 为六位数 mmrraa";
    G76_FINISH_COUNT = ValueOutOfRange:
        "{word}: the finishing count m must be {min}..99",
        "{word}：精车次数 m 应为 {min}..99";
    G76_TOOL_ANGLE = ValueOutOfRange:
        "{word}: tool angle {a}°; {controller} G76 takes {list} or {last}",
        "{word}：刀尖角 {a}°；{controller} 的 G76 只接受 {list} 或 {last}";
    ALLOWANCE_OVER_HEIGHT = ValueOutOfRange:
        "finishing allowance d = {d} is more than the thread height k = {k}",
        "精车余量 d = {d} 大于螺纹牙高 k = {k}";
    G92_NEEDS_Z = MissingWord:
        "G92 needs the thread end Z (or W)",
        "G92 需要螺纹终点 Z（或 W）";
    G78_P_POINT = DecimalPointNotAllowed:
        "{word}: P(m)(r)(a) is a plain four-digit number",
        "{word}：P(m)(r)(a) 是不带小数点的四位数";
    G78_P_DIGITS = ValueOutOfRange:
        "{word}: P(m)(r)(a) has at most four digits",
        "{word}：P(m)(r)(a) 最多四位";
    G78_DEPTH_MODE = ValueOutOfRange:
        "{word}: depth mode m = {m}; 0 (equal) or 1 (degressive)",
        "{word}：切深方式 m = {m}；应为 0（等切深）或 1（递减切深）";
    G78_INFEED_MODE = ValueOutOfRange:
        "{word}: infeed mode r = {r}; 0 middle, 1 left, 2 right or 3 alternating",
        "{word}：进刀方式 r = {r}；应为 0 直进、1 左侧、2 右侧或 3 左右交替";
    FINER_THAN_INCREMENT = FinerThanIncrement:
        "{word} is written finer than the least input increment, {increment} {unit} (setting increment): the control cannot place the tool finer (noted once)",
        "{word} 写得比最小输入增量 {increment} {unit}（设置“increment”）更细：系统不能更细地定位刀具（只提示一次）";
    DIALECT_HINT = DialectHint:
        "this program reads as {title} without an alarm ({threads} thread(s)), but {why}: is it written for {title}? Choose {title} as the controller (--dialect {dialect})",
        "本程序按 {title} 读没有报警（{threads} 个螺纹），而{why}：它是否是为 {title} 编写的？请把系统选为 {title}（命令行“--dialect {dialect}”）";
}

phrases! {
    MM: "mm", "mm";
    INCH: "in", "英寸";
    OR_TPI: " or I (threads per inch)", "或 I（每英寸牙数）";
    NOTHING: "", "";
    FINISH_COUNT_D: "finishing count D", "精车次数 D";
    STARTS_L: "starts L", "头数 L";
    SCREW_IN_E: "screw-in E", "切入长度 E";
    TAPER_R: "taper R(i)", "锥度 R(i)";
    THREAD_HEIGHT_K: "thread height k", "螺纹牙高 k";
    FIRST_DEPTH: "first depth Δd", "第一刀切深 Δd";
    MIN_DEPTH: "Δdmin", "最小切深 Δdmin";
    FINISH_ALLOWANCE: "finishing allowance d", "精车余量 d";
    NS_G33_TAPPING: "G33 tapping cycle", "G33 攻丝循环";
    NS_G34: "G34 variable-lead thread", "G34 变导程螺纹切削";
    NS_G65: "G65 macro call", "G65 宏程序调用";
    NS_G71: "the roughing of G71 (stock removal in turning; its contour is drawn where G70 runs it)", "G71 外圆粗车循环的粗车走刀（其轮廓在 G70 执行处画出）";
    NS_G72: "the roughing of G72 (stock removal in facing; its contour is drawn where G70 runs it)", "G72 端面粗车循环的粗车走刀（其轮廓在 G70 执行处画出）";
    NS_G73: "the roughing of G73 (pattern repeating; its contour is drawn where G70 runs it)", "G73 封闭切削循环的粗车走刀（其轮廓在 G70 执行处画出）";
    NS_G74: "G74 face grooving / peck drilling", "G74 端面切槽/深孔钻循环";
    NS_G75: "G75 grooving cycle", "G75 切槽循环";
    NS_G30: "G30 second reference return", "G30 返回第二参考点";
    NS_G31: "G31 skip", "G31 跳转功能";
    NS_POLAR: "polar / cylindrical interpolation", "极坐标/圆柱插补";
    NS_WORK_OFFSET: "work coordinate system", "工件坐标系选择";
    NS_PLANE: "plane selection", "平面选择";
    NS_G5: "G5 spline", "G5 样条";
    NS_G10: "G10 table and offset setting", "G10 刀具表与偏置设定";
    NS_G33_1: "G33.1 rigid tapping", "G33.1 刚性攻丝";
    NS_G38: "G38 probing", "G38 探测";
    NS_G52: "G52 local offset", "G52 局部坐标偏移";
    NS_G53: "G53 move in machine coordinates", "G53 机床坐标系移动";
    NS_LATHE_CYCLE: "G70/G71/G72 lathe cycle", "G70/G71/G72 车削循环";
    NS_DRILLING: "canned drilling cycle", "钻孔固定循环";
    NS_G90_1: "G90.1 absolute arc centres", "G90.1 圆心绝对坐标";
    NS_G92_1: "G92.1-G92.3 coordinate offset reset", "G92.1-G92.3 坐标偏移复位";
    NS_G10_6: "G10.6 tool retract and recover", "G10.6 刀具退回与复归";
    NS_G22: "G22 stored stroke check", "G22 存储行程检查";
    NS_G29: "G29 movement from the reference position", "G29 从参考点返回";
    NS_G30_1: "G30.1 floating reference position return", "G30.1 返回浮动参考点";
    NS_G35: "G35/G36 circular threading", "G35/G36 圆弧螺纹切削";
    NS_G36: "G36/G37 automatic tool offset", "G36/G37 自动刀具补偿";
    NS_G50_3: "G50.3 workpiece coordinate system preset", "G50.3 工件坐标系预置";
    NS_POLYGON: "G50.2/G51.2 polygon turning", "G50.2/G51.2 多边形车削";
    NS_G66: "G66 macro modal call", "G66 宏程序模态调用";
    HINT_ALARMS: "as {current} it has {alarms} alarm(s)", "按 {current} 读有 {alarms} 个报警";
    HINT_NO_THREAD: "as {current} it cuts no thread", "按 {current} 读切不出螺纹";
    NS_MIRROR: "G68/G69 mirror image for double turrets", "G68/G69 双刀架镜像";
}

/// The unit of lengths in messages.
pub fn unit(inch: bool) -> &'static super::Phrase {
    if inch { &INCH } else { &MM }
}
