//! The words of the drawings' labels in both languages: a scene's label is
//! a key and a value (`dia_major`, `48`); its text is the key's template in
//! the view's language with the value in place of `{}`.

use crate::message::Lang;

/// The English template of a label key, as the drawings show it.
pub fn english(key: &str) -> Option<&'static str> {
    Some(match key {
        "dia_major" => "major Ø{}",
        "dia_minor" => "minor Ø{}",
        "lead" => "Ph {}",
        "pitch" => "P {}",
        "length" => "L {}",
        "taper" => "taper {}",
        "delta1" => "δ1 {}",
        "delta2" => "δ2 {}",
        "height" => "h {}",
        "tool_angle" => "tool angle {}",
        "start_of" => "start {}",
        "pass_depth" => "{}",
        "pass_depth_finish" => "{} finish",
        "pass_depth_spring" => "{} spring",
        "infeed_radial" => "radial infeed",
        "infeed_left" => "left flank infeed",
        "infeed_right" => "right flank infeed",
        "infeed_alternating" => "alternating flanks",
        "infeed_programmed" => "infeed as programmed",
        "one_rev" => "one-rev signal {}",
        "axial_offsets" => "axial offsets lead·θ/360",
        "start_angle" => "{}",
        "starts_capped" => "{} starts: the first 360 are drawn",
        "moves_capped" => "motions outside the threads: only the first {} are drawn",
        "square_tool" => "0° tool: width {} assumed",
        "detail_passes" => "every n-th pass drawn (n/all): {}",
        "detail_starts" => "one start drawn, the others cut the same path (1/starts): {}",
        "detail_starts_passes" => "one start and every n-th pass drawn (1/starts n/all): {}",
        "radial_break" => "radial scale compressed beyond this line",
        "shoulder_into" => "the tool cuts {} into the shoulder",
        "insert_full" => "insert {} full profile",
        "insert_partial" => "insert {} partial profile",
        "shoulder_clear" => "the tool clears the shoulder by {}",
        _ => return None,
    })
}

/// The Chinese template of a label key, as the drawings show it.
pub fn chinese(key: &str) -> Option<&'static str> {
    Some(match key {
        "dia_major" => "大径 Ø{}",
        "dia_minor" => "小径 Ø{}",
        "lead" => "导程 {}",
        "pitch" => "螺距 {}",
        "length" => "长 {}",
        "taper" => "锥度 {}",
        "height" => "牙高 {}",
        "tool_angle" => "刀尖角 {}",
        "start_of" => "第 {} 头",
        "pass_depth_finish" => "{} 精车",
        "pass_depth_spring" => "{} 光刀",
        "infeed_radial" => "径向进刀(中线)",
        "infeed_left" => "左侧面进刀",
        "infeed_right" => "右侧面进刀",
        "infeed_alternating" => "左右交替进刀",
        "infeed_programmed" => "按程序进刀",
        "one_rev" => "一转信号 {}",
        "axial_offsets" => "轴向偏移 导程·θ/360",
        "starts_capped" => "{} 头：只画前 360 头",
        "moves_capped" => "螺纹以外的运动只画前 {} 段",
        "square_tool" => "0° 刀：假定刀宽 {}",
        "detail_passes" => "每隔 n 次走刀画一次(n/总数)：{}",
        "detail_starts" => "只画一头，其余各头路径相同(1/头数)：{}",
        "detail_starts_passes" => "只画一头、每隔 n 次走刀画一次(1/头数 n/总数)：{}",
        "radial_break" => "此线以外径向比例压缩",
        "shoulder_into" => "刀具切入台阶 {}",
        "insert_full" => "全牙型刀片 {}",
        "insert_partial" => "非全牙型刀片 {}",
        "shoulder_clear" => "刀具离台阶 {}",
        // δ1, δ2 and the bare values read the same in both languages.
        key => return english(key),
    })
}

/// The label keys a scene uses.
pub const LABEL_KEYS: [&str; 33] = [
    "dia_major",
    "dia_minor",
    "lead",
    "pitch",
    "length",
    "taper",
    "delta1",
    "delta2",
    "height",
    "tool_angle",
    "start_of",
    "pass_depth",
    "pass_depth_finish",
    "pass_depth_spring",
    "infeed_radial",
    "infeed_left",
    "infeed_right",
    "infeed_alternating",
    "infeed_programmed",
    "one_rev",
    "axial_offsets",
    "start_angle",
    "starts_capped",
    "moves_capped",
    "square_tool",
    "detail_passes",
    "detail_starts",
    "detail_starts_passes",
    "radial_break",
    "shoulder_into",
    "shoulder_clear",
    "insert_full",
    "insert_partial",
];

/// The text of a label in `lang`: its key's template with `value` in place
/// of `{}`; a bare value for an empty key; a key without a template as the
/// key and the value.
pub fn label_text(lang: Lang, key: &str, value: &str) -> String {
    if key.is_empty() {
        return value.to_string();
    }
    let template = match lang {
        Lang::Zh => chinese(key),
        Lang::En => english(key),
    };
    match template {
        Some(t) => t.replacen("{}", value, 1),
        None if value.is_empty() => key.to_string(),
        None => format!("{key} {value}"),
    }
}
