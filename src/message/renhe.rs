//! Renhe: G30 tails, G32 (inch) and G33 (metric) thread blocks, the
//! controller's own alarms E18-03 to E18-05 (their codes kept) and the
//! spindle advice.

use super::templates;

templates! {
    G30_WORDS = MissingWord:
        "G30 takes both U and W (a spiral tail), U0 W0 (no tail) or neither (standard)",
        "G30 需同时给出 U 和 W（螺旋退尾），或 U0 W0（不退尾），或都不给（标准退尾）";
    RENHE_NO_TPI = MissingLead:
        "{name} without F: give the threads per inch",
        "{name} 没有 F：请指定每英寸牙数";
    RENHE_NO_PITCH = MissingLead:
        "{name} without F: give the pitch",
        "{name} 没有 F：请指定螺距";
    RENHE_TPI_RANGE = ValueOutOfRange:
        "{word}: G32 takes 3..33 threads per inch (F11.2 = 11½; the digit after the point is a denominator)",
        "{word}：G32 的每英寸牙数为 3..33（F11.2 = 11½；小数点后的数字是分母）";
    RENHE_PITCH_RANGE = ValueOutOfRange:
        "{word}: G33 takes a pitch of 0.25..12 mm",
        "{word}：G33 的螺距范围为 0.25..12 mm";
    E18_03 = E18_03:
        "E18-03: {name} takes incremental dimensions only; write {inc} instead of {abs}",
        "E18-03：{name} 只能用增量坐标；请写 {inc}，不要写 {abs}";
    E18_04 = E18_04:
        "E18-04: the thread length |W| = {w} must exceed |U| = {u} and 4 mm",
        "E18-04：螺纹长度 |W| = {w} 必须大于 |U| = {u}，并且大于 4 mm";
    E18_05 = E18_05:
        "E18-05: {name} needs an X feed (G00 or G01 with U/X) before it to set the run-out direction",
        "E18-05：{name} 之前需要一个 X 向进刀（带 U/X 的 G00 或 G01）来确定退尾方向";
    TAIL_TOO_LONG = RunoutTooLong:
        "the tail is {k} long, more than the thread's |W| = {w}",
        "退尾长 {k}，超过螺纹的 |W| = {w}";
    SPINDLE_SPEED = SpindleSpeed:
        "S{s} is above the advised n ≤ 2300/t − 60 = {max} rev/min for a pitch of {pitch} mm: the thread may be damaged",
        "S{s} 高于螺距 {pitch} mm 时建议的转速 n ≤ 2300/t − 60 = {max} r/min：螺纹可能被破坏";
}
