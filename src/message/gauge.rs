//! The thread check: its verdict (a diagnostic) and its notes (listed with
//! the check and in the verdict).

use super::{phrases, templates};

templates! {
    GAUGE_OK = GaugeOk:
        "thread check {designation}: pitch diameter {d2}{range}: it gauges{fix}{notes}",
        "螺纹检验 {designation}：中径 {d2}{range}：合格{fix}{notes}";
    GAUGE_FAIL = GaugeFail:
        "thread check {designation}: pitch diameter {d2}{side}{range}: it will not gauge{fix}{notes}",
        "螺纹检验 {designation}：中径 {d2}{side}{range}：不合格{fix}{notes}";
    GAUGE_UNKNOWN_ANGLE = GaugeFail:
        "thread check {designation}: the tool angle is {angle}°, so the pitch diameter the program cuts is not known",
        "螺纹检验 {designation}：刀尖角为 {angle}°，无法得知程序切出的中径";
    DESIGNATION_WITHOUT_LIMITS = BadDesignation:
        "{designation}: {error}",
        "{designation}：{error}";
    BAD_DESIGNATION_SETTING = BadDesignation:
        "setting thread.designation = '{text}' is not a thread designation: {error}",
        "设置 thread.designation = '{text}' 不是螺纹标记：{error}";
    NOTE_KIND = GaugeFail:
        "the designation is for an {want} thread; the program cuts an {got} one",
        "标记是{want}螺纹，程序切的却是{got}螺纹";
    NOTE_LEAD = GaugeFail:
        "the program cuts a lead of {lead} mm; {designation} has a lead of {want} mm",
        "程序切的导程为 {lead} mm；{designation} 的导程为 {want} mm";
    NOTE_STARTS = GaugeOk:
        "{designation} has {n} start(s); the program's passes show {m} (starts are told apart by their start angle Q/L): checked at the designation's pitch {pitch} mm",
        "{designation} 为 {n} 头；程序各刀显示为 {m} 头（各头按起始角 Q/L 区分）：按标记的螺距 {pitch} mm 检验";
    NOTE_TOOL_ANGLE = GaugeFail:
        "the tool angle is {angle}°: the standard's flanks are 60°, so the thread will not fit the gauge's flanks",
        "刀尖角为 {angle}°：标准牙型角为 60°，螺纹牙侧与量规牙侧不吻合";
    NOTE_MULTI_START = GaugeOk:
        "multi-start: pitch = lead / starts = {pitch}; each start checked",
        "多头螺纹：螺距 = 导程 / 头数 = {pitch}；每一头都检验";
    NOTE_ON_NOSE = GaugeOk:
        "the pitch line crosses the tool's nose radius: the straight-flank formula overstates d2",
        "中径线落在刀尖圆弧上：按直牙侧公式算出的 d2 偏大";
    NOTE_ROOT_BELOW_MAJOR = GaugeFail:
        "the root X{root} is below the major diameter's {min}: the GO plug will not enter",
        "牙底 X{root} 小于大径下限 {min}：通端螺纹塞规旋不进";
    NOTE_ROOT_ABOVE_MINOR = GaugeFail:
        "the root X{root} is above the minor diameter's {max}: the GO ring gauge's crest will ride on it",
        "牙底 X{root} 大于小径上限 {max}：通端螺纹环规的牙顶会顶在牙底上";
    NOTE_ROOT_BELOW_MINOR = GaugeOk:
        "the root X{root} is below the minor diameter's {min} (a root radius of 0.125·P or more): a larger nose radius (setting tool.nose_radius) would keep it",
        "牙底 X{root} 小于小径下限 {min}（该下限对应 0.125·P 以上的牙底圆弧）：用更大的刀尖圆弧半径（设置 tool.nose_radius）可以保证";
    NOTE_TOOL_ASSUMED = GaugeOk:
        "the tool is not known (setting tool.nose_radius): taken as a full-profile insert, nose radius r = {factor}·P = {r} (ISO 965-1's smallest root radius of an external thread); {range}",
        "刀具未知（设置 tool.nose_radius）：按全牙型刀片计算，刀尖圆弧半径 r = {factor}·P = {r}（ISO 965-1 外螺纹牙底最小圆弧半径）；{range}";
    NOTE_TOOL_INSERT = GaugeOk:
        "the nose radius r = {r} is the root the full-profile insert {insert} forms (setting tool.insert)",
        "刀尖半径 r = {r} 取全牙型刀片 {insert} 形成的牙底（设置“tool.insert”）";
    NOTE_TOOL_ASSUMED_INTERNAL = GaugeOk:
        "the tool is not known (setting tool.nose_radius): taken as a full-profile insert, nose radius r = {factor}·P = {r} (the largest within ISO 68-1's basic profile, whose root flat is H/8 inside the sharp V); {range}",
        "刀具未知（设置 tool.nose_radius）：按全牙型刀片计算，刀尖圆弧半径 r = {factor}·P = {r}（ISO 68-1 基本牙型内允许的最大值，牙底平台距尖角 H/8）；{range}";
    NOTE_CREST_NOT_TURNED = GaugeOk:
        "the program does not turn the {what}: not checked",
        "程序没有车出{what}：不检验";
    NOTE_CREST_OUTSIDE = GaugeFail:
        "the turned {what} X{crest} is outside {min} … {max}",
        "车出的{what} X{crest} 超出 {min} … {max}";
    NOTE_NPT_TAPER = GaugeFail:
        "the cut taper is {taper} on diameter, not 1/16 = 0.0625 (± {tol}, setting gauge.npt_taper_tolerance)",
        "切出的锥度（直径上）为 {taper}，不是 1/16 = 0.0625（± {tol}，设置 gauge.npt_taper_tolerance）";
    NOTE_NPT_NEVER = GaugeFail:
        "the cut never reaches the pitch diameter {name} = {target} within its length",
        "在切削长度内中径始终达不到 {name} = {target}";
    NOTE_NPT_PLANE = GaugeOk:
        "NPT has no pitch-diameter class (ASME B1.20.1): the L1 gauge sits where the cut pitch diameter is {name} = {target}, at Z{z}; the {end} must be there within ±1 turn (±{pitch})",
        "NPT 没有中径公差等级（ASME B1.20.1）：L1 量规停在切出的中径等于 {name} = {target} 的位置，即 Z{z}；{end}必须在该处 ±1 圈（±{pitch}）以内";
}

phrases! {
    INTERNAL: "internal", "内";
    EXTERNAL: "external", "外";
    RANGE: " ({min} … {max})", "（{min} … {max}）";
    RANGE_CLASS: " ({min} … {max}, {class})", "（{min} … {max}，{class}）";
    FIX: "; ΔX {dx} (final pass X{x}) centres it", "；精车刀改为 X{x}（ΔX {dx}）可使中径位于公差带中间";
    TOO_LARGE: " is too large", " 偏大";
    TOO_SMALL: " is too small", " 偏小";
    NOSE_RANGE: "the pitch diameter is within its limits with a nose radius from {lo} to {hi}: set tool.nose_radius to your insert's", "刀尖圆弧半径在 {lo} 到 {hi} 之间时中径在公差内：请把 tool.nose_radius 设为所用刀片的半径";
    NOSE_NONE: "no nose radius from 0 to 0.25·P = {hi} puts the pitch diameter within its limits", "刀尖圆弧半径取 0 到 0.25·P = {hi} 之间的任何值，中径都不在公差内";
    BORE: "bore (minor diameter)", "内孔（小径）";
    MAJOR: "major diameter", "大径";
    FITTING_FACE: "face of the fitting", "管件端面";
    PIPE_END: "end of the pipe", "管子端部";
}
