//! Words and lines of the command line's summary: severities, thread
//! kinds, roles, the pass table's columns and the shop-floor lines.

use super::phrases;

phrases! {
    ALARM: "alarm", "报警";
    WARNING: "warning", "警告";
    NOTE: "note", "提示";
    STRAIGHT: "straight", "直螺纹";
    TAPER: "taper", "锥螺纹";
    FACE: "face", "端面螺纹";
    ROUGH: "rough", "粗车";
    FINISH: "finish", "精车";
    SPRING: "spring", "光刀";
    EXTERNAL_THREAD: "external", "外螺纹";
    INTERNAL_THREAD: "internal", "内螺纹";
    CREST_CYCLE: "cycle", "循环给定";
    CREST_OUTLINE: "outline", "车削轮廓";
    CREST_ASSUMED_WORD: "assumed", "假定";
    CREST_COMMENT: "comment", "注释给定";
    MEASURED: "measured", "实测";
    ASSUMED: "assumed", "假定";
    NOT_KNOWN: "not known", "未知";
    UNITS_MM: "mm", "mm";
    UNITS_INCH: "inch", "英寸";
    ONE_START: "1 start", "单头";
    STARTS: "{n} starts", "{n} 头";
    SUMMARY: "{file}: {dialect}, {units}; {threads} thread(s), {moves} move(s); {alarms} alarm(s), {warnings} warning(s), {notes} note(s){time}",
        "{file}：{dialect}，{units}；{threads} 个螺纹，{moves} 段运动；{alarms} 个报警，{warnings} 个警告，{notes} 条提示{time}";
    THREADING_TIME: "; threading time {t} s", "；螺纹加工时间 {t} s";
    THREAD_LINE: "thread {i} (lines {from}-{to}): {kind} {source} in {units}, lead {lead}, pitch {pitch}, {starts}, {side}; crest {axis}{crest} ({crest_source}), height {height}",
        "螺纹 {i}（第 {from}-{to} 行）：{kind} {source}（{units}），导程 {lead}，螺距 {pitch}，{starts}，{side}；牙顶 {axis}{crest}（{crest_source}），牙高 {height}";
    COL_START: "start", "头";
    COL_PASS: "pass", "刀";
    COL_X_FROM: "X from", "起点X";
    COL_Z_FROM: "Z from", "起点Z";
    COL_X_TO: "X to", "终点X";
    COL_Z_TO: "Z to", "终点Z";
    COL_DEPTH: "depth", "切深";
    COL_INFEED: "infeed", "进刀";
    COL_ROLE: "role", "类型";
    COL_AREA: "area", "面积";
    COL_EVEN: "even", "等面积";
    COL_TIME: "time s", "时间 s";
    COL_LINES: "lines", "程序行";
    // The element's pass table (the live one's headers: www/src/shared/i18n.js `col_*`).
    TABLE_PASS: "Pass", "次";
    TABLE_START: "Start", "头";
    TABLE_X: "X", "X";
    TABLE_Z_START: "Z start", "Z 起点";
    TABLE_Z_END: "Z end", "Z 终点";
    TABLE_DEPTH: "Depth", "切深";
    TABLE_INCREMENT: "Increment", "进刀量";
    TABLE_AREA: "Area", "面积";
    TABLE_EVEN: "Even area", "等面积";
    TABLE_TIME: "Time", "时间";
    TABLE_ROLE: "Role", "类型";
    TABLE_LINES: "Lines", "行";
    LIST_MORE: "… {n} more", "… 另有 {n} 条";
    TABLE_MORE: "… {n} more passes: point at the diagram to list them all", "… 另有 {n} 次走刀：指向图即可全部列出";
    TIME_LINE: "time: {cut} s cutting, {total} s with rapids; {n} rev/min, thread feed {feed} {u}/min (machine.max_thread_feed allows up to S{limit})",
        "时间：切削 {cut} s，含快速移动 {total} s；{n} r/min，螺纹进给 {feed} {u}/min（machine.max_thread_feed 允许最高 S{limit}）";
    TIME_UNKNOWN: "time: not known (no spindle speed S before the thread)", "时间：未知（螺纹之前没有主轴转速 S）";
    SPEED_LINE: "speed: lead-in δ1 {d1} ({source}), {n1} needed at this speed; run-out δ2 {d2}, {n2} needed",
        "速度：升速进刀段 δ1 {d1}（{source}），此转速需要 {n1}；降速退刀段 δ2 {d2}，需要 {n2}";
    HELIX_LINE: "helix angle {h}° at pitch diameter {d2}", "中径 {d2} 处的螺纹升角 {h}°";
    CHECK_LINE: "thread check {designation} ({from}): {verdict}", "螺纹检验 {designation}（{from}）：{verdict}";
    FROM_COMMENT: "comment on line {l}", "第 {l} 行的注释";
    FROM_SETTING: "setting thread.designation", "设置 thread.designation";
    GAUGES: "gauges", "合格";
    WILL_NOT_GAUGE: "WILL NOT GAUGE", "不合格";
    NPT_LINE: "pitch diameter {d2} at the small end; taper {taper} on diameter (1/16 = 0.0625); gauge plane at Z{z}",
        "小端中径 {d2}；锥度（直径上）{taper}（1/16 = 0.0625）；量规基面在 Z{z}";
    DIAMETERS_LINE: "pitch diameter {d2} in {d2_min} … {d2_max}; major {major} in {major_min} … {major_max}; minor {minor} in {minor_min} … {minor_max}",
        "中径 {d2}，范围 {d2_min} … {d2_max}；大径 {major}，范围 {major_min} … {major_max}；小径 {minor}，范围 {minor_min} … {minor_max}";
    FIX_LINE: "fix: ΔX {dx} on the final pass centres the pitch diameter", "修正：精车刀 ΔX {dx} 可使中径位于公差带中间";
    NOTE_LINE: "note: {note}", "说明：{note}";
    WIRES_LINE: "over three wires of Ø{w}: M {m} (for the limits {min} … {max})", "三针测量（量针 Ø{w}）：M {m}（公差对应 {min} … {max}）";
    DIAGNOSTICS_HEADING: "diagnostics:", "诊断：";
    CALLED_FROM: "called from line", "调用自第";
    CALLED_FROM_AFTER: "", "行";
    RAISED_TIMES: "raised {n} times", "出现 {n} 次";
}
