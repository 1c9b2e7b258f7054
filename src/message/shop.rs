//! The textbook's advice (the crest, table 4-3, δ1/δ2) and the shop-floor
//! checks: thread feed and spindle limits, speed-dependent δ1/δ2, chip loads.

use super::{phrases, templates};

templates! {
    CREST_ASSUMED = CrestAssumed:
        "the program does not {what}: crest assumed at {axis}{crest} from the deepest pass and d = D − {factor}·P, so the pass depths are relative to it; the textbook's δ1/δ2 are not checked",
        "程序没有{what}：按最深一刀和 d = D − {factor}·P 假定牙顶在 {axis}{crest}，各刀切深都相对于它计算；不检查教材中的 δ1/δ2";
    DEPTH_VS_STANDARD = DepthVsStandard:
        "total depth {total} (diameter) against {factor}·P = {standard} for pitch {pitch}: the thread is {verdict}",
        "总切深 {total}（直径值），螺距 {pitch} 的标准牙深为 {factor}·P = {standard}：螺纹{verdict}";
    INFEED_GUIDANCE = InfeedGuidance:
        "table 4-3 for pitch {pitch}: {n} passes, diameter infeeds {table}; programmed: {count} passes, {infeeds}{same}",
        "表 4-3 螺距 {pitch}：{n} 刀，直径进刀量 {table}；程序：{count} 刀，{infeeds}{same}";
    INFEED_TOO_LARGE = InfeedTooLarge:
        "pass {n} takes {infeed} of diameter at once; table 4-3 starts pitch {pitch} with {largest}",
        "第 {n} 刀一次切入直径 {infeed}；表 4-3 中螺距 {pitch} 的第一刀为 {largest}";
    CLEARANCE_INSIDE = Clearance:
        "the pass starts {d} inside the work: the lead-in δ1 must keep the acceleration off the thread (textbook: 2–10 mm)",
        "该刀的起点在工件内 {d} 处：升速进刀段 δ1 应让加速过程不落在螺纹上（教材：2–10 mm）";
    CLEARANCE_LEAD_IN = Clearance:
        "lead-in δ1 = {d} is shorter than the textbook's 2–10 mm (larger for larger leads): the first turns are cut while the axis accelerates",
        "升速进刀段 δ1 = {d} 短于教材的 2–10 mm（导程越大应越长）：最初几圈是在进给轴加速时切出的";
    CLEARANCE_RUN_OUT = Clearance:
        "run-out δ2 = {d2} is shorter than δ1/4 = {quarter} (textbook: δ2 = δ1/4 to δ1/2)",
        "降速退刀段 δ2 = {d2} 短于 δ1/4 = {quarter}（教材：δ2 = δ1/4 到 δ1/2）";
    THREAD_FEED_LIMIT = ThreadFeedLimit:
        "thread feed {feed} mm/min (lead {lead} mm × {n} rev/min) is above the machine's {max} mm/min (setting machine.max_thread_feed): the control would cut the lead wrong; at most S{fits} fits this lead",
        "螺纹进给 {feed} mm/min（导程 {lead} mm × {n} r/min）超过机床的 {max} mm/min（设置 machine.max_thread_feed）：系统会切错导程；这个导程最高只能用 S{fits}";
    SPINDLE_LIMIT = SpindleLimit:
        "S{s} is above the machine's highest spindle speed of {max} rev/min (setting machine.max_rpm)",
        "S{s} 超过机床的最高主轴转速 {max} r/min（设置 machine.max_rpm）";
    INSERT_SIDE = InsertSide:
        "the insert {insert} (setting tool.insert) is for {is} threads; this thread is {thread}",
        "刀片 {insert}（设置“tool.insert”）用于{is}螺纹，而这个螺纹是{thread}螺纹";
    INSERT_PITCH = InsertPitch:
        "the full-profile insert {insert} (setting tool.insert) is made for a pitch of {made} mm; this thread's pitch is {pitch} mm: its crest and root will not fit the thread",
        "全牙型刀片 {insert}（设置“tool.insert”）适用于螺距 {made} mm，而这个螺纹的螺距是 {pitch} mm：刀片的牙顶和牙底与螺纹不符";
    INSERT_RANGE = InsertRange:
        "the partial-profile insert {insert} (setting tool.insert) cuts pitches from {min} to {max} mm; this thread's pitch is {pitch} mm",
        "部分牙型刀片 {insert}（设置“tool.insert”）适用螺距 {min} 到 {max} mm，而这个螺纹的螺距是 {pitch} mm";
    TOOL_SHOULDER = ToolShoulder:
        "pass {n} (start {start}) ends with the tool's tip at X{tipx} Z{tipz}: its leading flank ({angle}° form) cuts {into} into the shoulder at Z{z} (up to X{x}); the tip must stay {need} from the shoulder along Z: end the thread earlier, or turn a relief groove",
        "第 {n} 刀（第 {start} 头）结束时刀尖在 X{tipx} Z{tipz}：刀具前侧刃（{angle}° 牙型）切入 Z{z} 处的台阶 {into}（台阶至 X{x}）；刀尖沿 Z 向须离台阶 {need}：应提前结束螺纹，或车出退刀槽";
    APPROACH_INTO_PART = ApproachIntoPart:
        "pass {n} (start {start}) starts its cut at X{x} Z{z}, where the program turned the part to X{part}: the infeed plunges into the part in rapid; start the thread before the work (a lead-in δ1)",
        "第 {n} 刀（第 {start} 头）在 X{x} Z{z} 开始切削，而程序在此处已把工件车到 X{part}：快速进刀会扎入工件；螺纹应从工件之外开始（留升速进刀段 δ1）";
    SHIM = Shim:
        "helix angle {lambda}° ({hand}): use a {shim}° shim under the insert instead of the holder's standard 1° (Sandvik Coromant: the shim nearest the helix angle)",
        "螺旋升角 {lambda}°（{hand}）：刀片下应换用 {shim}° 刀垫，而不是刀杆标配的 1° 刀垫（山特维克：选最接近螺旋升角的刀垫）";
    SHIM_RUB = ShimRub:
        "helix angle {lambda}° ({hand}): on the holder's standard 1° shim the insert leans {off}° off the helix, more than the {win}° the makers allow for this form, so a flank rubs; use a {shim}° shim{reach}",
        "螺旋升角 {lambda}°（{hand}）：用刀杆标配的 1° 刀垫时刀片倾角与螺旋线相差 {off}°，超过刀具厂商对此牙型允许的 {win}°，一侧牙面会摩擦；应换用 {shim}° 刀垫{reach}";
    SPEED_BETWEEN_PASSES = SpeedBetweenPasses:
        "pass {n} (start {start}) is cut at S{s}, the thread's first pass at S{first}: the axis lags the spindle by more the faster it turns, so this pass starts elsewhere on the helix and cuts across the thread; keep S the same for every pass{shift}",
        "第 {n} 刀（第 {start} 头）的转速是 S{s}，而本螺纹第一刀是 S{first}：转速越高，进给轴滞后主轴越多，这一刀的起点落在螺旋线的别处，会把螺纹切乱；各刀应使用相同的 S{shift}";
    THREAD_CSS = ThreadCss:
        "thread cut under G96 (constant surface speed S{s} {unit}): the spindle speed changes with X ({n} rev/min at X{x}), so the passes need not follow one helix; cut threads under G97 with a fixed S",
        "在 G96（恒线速 S{s} {unit}）下切螺纹：主轴转速随 X 变化（X{x} 处为 {n} r/min），各刀不一定在同一条螺旋线上（乱牙）；螺纹应在 G97 下用固定的 S 切削";
    DELTA1_SPEED = Delta1Speed:
        "lead-in δ1 = {d} is shorter than the δ1 ≈ n·L/{divisor} = {need} at S{n} and lead {lead} the axis needs to reach the thread feed ({how}): the first turns are cut while it accelerates; start the passes {more} earlier{slower}",
        "升速进刀段 δ1 = {d} 短于进给轴加速到螺纹进给所需的 δ1 ≈ n·L/{divisor} = {need}（S{n}，导程 {lead}）（{how}）：最初几圈是在加速时切出的；请把各刀起点提前 {more}{slower}";
    DELTA2_SPEED = Delta2Speed:
        "run-out δ2 = {d} is shorter than the δ2 ≈ n·L/{divisor} = {need} at S{n} and lead {lead} the axis needs to stop ({how}): the last turns are cut while it decelerates; run the passes {more} further{slower}",
        "降速退刀段 δ2 = {d} 短于进给轴停下所需的 δ2 ≈ n·L/{divisor} = {need}（S{n}，导程 {lead}）（{how}）：最后几圈是在减速时切出的；请把各刀再向后延长 {more}{slower}";
    CHIP_HEAVY_FIRST = ChipHeavyFirst:
        "pass {n} removes {area} mm², {ratio}× the {even} mm² of a constant-area schedule of {count} passes to depth {depth} (setting chip.first_pass_ratio = {limit}): a first pass this heavy loads the tool tip most; start at depth {start}",
        "第 {n} 刀切除 {area} mm²，是等面积分配（{count} 刀切到深度 {depth}）每刀 {even} mm² 的 {ratio} 倍（设置 chip.first_pass_ratio = {limit}）：第一刀这么重，刀尖负荷最大；第一刀宜切到深度 {start}";
    CHIP_OVER_TOOL = ChipHeavyFirst:
        "pass {n} removes {area} mm², more than the tool's {max} mm² (setting tool.max_chip_area)",
        "第 {n} 刀切除 {area} mm²，超过刀具允许的 {max} mm²（设置 tool.max_chip_area）";
    CROSS_LEAD = CrossThread:
        "this pass cuts a lead of {lead} where the other {n} passes on this surface (lines {from}–{to}) cut {other}: it cuts a second helix across the thread",
        "这一刀的导程是 {lead}，而同一表面上的其他 {n} 刀（第 {from}–{to} 行）导程是 {other}：它切出第二条螺旋线，会把螺纹切乱";
    CROSS_PHASE = CrossThread:
        "this pass starts {turn}° off the helix of the other {n} passes on this surface (lines {from}–{to}): its {why} is not a whole number of leads from theirs, so it cuts a second helix across the thread",
        "这一刀的起点与同一表面上其他 {n} 刀（第 {from}–{to} 行）的螺旋线相差 {turn}°：它的{why}与它们相差的不是导程的整数倍，会切出第二条螺旋线，把螺纹切乱";
    CHIP_NONE = ChipNone:
        "pass {n} removes nothing: it is no deeper than the passes before it (depth {depth}), so it only rubs; drop it or make it deeper",
        "第 {n} 刀没有切除材料：它不比前面各刀深（切深 {depth}），只会摩擦；请删去这一刀或加大切深";
    CHIP_THIN = ChipThin:
        "pass {n} deepens the thread by only {infeed} (radial; setting chip.min_infeed = {min} mm): so thin a cut rubs and work-hardens rather than cuts",
        "第 {n} 刀只加深 {infeed}（半径值；设置 chip.min_infeed = {min} mm）：切得这么薄，刀具是在摩擦并使表面加工硬化，而不是在切削";
}

phrases! {
    RIGHT_HAND: "right-hand thread, cut towards −Z", "右旋螺纹，向 −Z 切削";
    LEFT_HAND: "left-hand thread, cut towards +Z: negative shims", "左旋螺纹，向 +Z 切削：用负角度刀垫";
    SHIM_WITHIN: "", "";
    SHIM_BEYOND: " (the steepest made: the helix is beyond the shims, −2° … 4°)", "（已是最大的刀垫：螺旋升角超出刀垫范围 −2° … 4°）";
    TURN_MAJOR: "turn this thread's major diameter", "车出这个螺纹的大径";
    TURN_MINOR: "turn this thread's minor diameter", "车出这个螺纹的小径";
    FACE_CREST: "face the crest of this face thread", "车出这个端面螺纹的牙顶端面";
    NOT_FULL_DEPTH: "not cut to full depth", "没有切到全牙深";
    TOO_DEEP: "cut deeper than standard", "切得比标准深";
    AS_THE_TABLE: " (as the table)", "（与表相同）";
    PROGRAM_LEAD_IN: "the program's lead-in", "程序中的升速进刀段";
    ASSUMED_LEAD_IN: "the assumed lead-in (the program does not turn the work, so setting shop.assumed_lead_in, the textbook's O1006 value, stands in for it)",
        "假定的升速进刀段：程序没有车出工件，因此用设置 shop.assumed_lead_in（教材 O1006 的值）代替";
    PROGRAM_RUN_OUT: "the program's run-out", "程序中的降速退刀段";
    ASSUMED_RUN_OUT: "the assumed run-out (the program does not turn the work, so setting shop.assumed_run_out, the textbook's O1006 value, stands in for it)",
        "假定的降速退刀段：程序没有车出工件，因此用设置 shop.assumed_run_out（教材 O1006 的值）代替";
    SLOWER: " or lower the speed to S{fits}", "，或把转速降到 S{fits}";
    X_INSERT_HEAD: "a size and side, such as 16ER or 16IL", "尺寸和内外、左右，如 16ER 或 16IL";
    X_INSERT_PROFILE: "a profile: a pitch and ISO (1.5 ISO), threads per inch and UN (16 UN), or A60, AG60, G60", "牙型：螺距加 ISO（1.5 ISO）、每英寸牙数加 UN（16 UN），或 A60、AG60、G60";
    SPEED_SHIFT: " (with the servo lag of {lag} ms, setting machine.servo_lag, its start moves {dz} along the axis, {deg}° of a turn)", "（按伺服滞后 {lag} ms（设置“machine.servo_lag”）估算，起点沿轴向移动 {dz}，即 {deg}°）";
    SPEED_NO_LAG: " (setting machine.servo_lag gives the shift)", "（设置“machine.servo_lag”可估算偏移量）";
    START_Z: "start Z {z} (the others start at Z{at})", "起点 Z{z}（其他各刀起点 Z{at}）";
    START_ANGLE: "start angle Q {q}° (the others {at}°)", "起始角 Q {q}°（其他各刀 {at}°）";
}
