// English and Chinese labels: the page's own text (data-i18n attributes and
// t()) and the scene labels (keys from src/diagram with a value put in).

const EN = {
  title: 'screwcut — lathe thread G-code previewer',
  dialect: 'Controller',
  examples: 'Examples',
  example_pick: 'Open an example…',
  settings: 'Parameters',
  reset: 'Reset to defaults',
  close: 'Close',
  share: 'Copy link',
  shared: 'Link copied',
  share_failed: 'Link in the address bar',
  download_plan: 'Plan JSON',
  side: 'Side section',
  tooth: 'Tooth section',
  starts: 'Starts',
  fit: 'Fit',
  stretch: 'Stretch radially',
  svg: 'SVG',
  png: 'PNG',
  passes: 'Passes',
  diagnostics: 'Diagnostics',
  thread: 'Thread',
  start: 'Start',
  col_pass: 'Pass',
  col_start: 'Start',
  col_x: 'X',
  col_z: 'Z start',
  col_z_end: 'Z end',
  col_depth: 'Depth',
  col_infeed: 'Increment',
  col_area: 'Area',
  col_role: 'Role',
  col_lines: 'Lines',
  called_from: 'called from line {lines}',
  switch_to: 'Read it as {title}',
  switched: 'Controller: {title}',
  wizard: 'Thread wizard…',
  expand: 'Expand to blocks…',
  wz_title: 'Thread wizard',
  wz_help: 'A designation (or, with the designation cleared, a major diameter and a lead), the thread\'s length or end Z, a controller and a form: the program is written as you type.',
  wz_designation: 'Designation',
  wz_major: 'Major Ø (mm)',
  wz_lead: 'Lead (mm)',
  wz_length: 'Length (mm)',
  wz_start_z: 'Start Z',
  wz_end_z: 'End Z (instead of the length)',
  wz_starts: 'Starts',
  wz_nose: 'Tool nose radius (mm)',
  wz_max_rpm: 'Max spindle speed (rev/min)',
  wz_max_feed: 'Max thread feed (mm/min)',
  wz_kind: 'External or internal',
  wz_kind_auto: 'as the designation says',
  wz_external: 'external',
  wz_internal: 'internal',
  wz_form: 'Form',
  wz_program: 'The program',
  wz_open: 'Open as a new program',
  wz_cancel: 'Cancel',
  ex_title: 'Expand to blocks',
  ex_help: 'The program as planned, written block by block for a controller: every pass with its approach, cut, run-out, retract and return; multi-start by start angle where the controller has one, else by axial offset. It opens as a new program; this one stays.',
  ex_to: 'Write for',
  ex_alarms: 'The program has {n} alarm(s): the expansion writes what was planned up to them.',
  col_even: 'Even area',
  view_keys: 'Keys: arrows pan, + and − zoom, 0 fits, Enter picks what is at the centre.',
  alt_side: '{threads#thread|threads}, {moves#motion|motions}, {alarms#alarm|alarms}.',
  alt_thread: 'thread {i}: {kind}, lead {lead}, {starts#start|starts}',
  alt_passes: '{n#pass|passes} from X{x0} to X{x1}, Z{z0} to Z{z1}',
  alt_tooth: 'depth {h}, tool angle {angle}°, {n#pass|passes}.',
  alt_starts: '{n#start|starts}, start {st} shown.',
  list_passes: 'Passes of the chosen thread: arrow keys choose a pass, Enter goes to its line',
  list_diagnostics: 'Diagnostics: arrow keys choose one, Enter goes to its line and column',
  col_time: 'Time',
  designation: 'Designation',
  designation_help: 'Thread designation for the check when no comment before the thread names one (setting thread.designation)',
  designation_placeholder: 'e.g. M48x2-6g',
  export_failed: 'The {view} was not exported: {why}',
  export_empty: 'The {view} has nothing to export',
  export_no_thread: 'this program has no thread to draw it for',
  check_none: 'No designation: name one in a comment before the thread, e.g. (M48x2-6g), or here, to check the pitch diameter.',
  check_from_comment: 'read from the comment on line {line}',
  check_from_setting: 'read from the Designation field (setting thread.designation)',
  check_d2: 'd2',
  check_dx: 'ΔX {dx} on the final pass',
  check_nose: 'tool r {r} assumed (full profile)',
  check_nose_range: 'd2 within limits for r {lo}…{hi}; set tool.nose_radius to your insert\'s',
  check_nose_none: 'no nose radius puts d2 within limits',
  check_limits: 'limits {min}…{max} {u}',
  check_dx_help: 'Change of the final pass X (diameter) that puts the pitch diameter in the middle of its tolerance',
  summary_time: 'threading {s} s',
  check_ok: 'gauges',
  check_fail: 'fails',
  check_time: '{s} s (cutting {cut} s)',
  check_no_speed: 'no time: no spindle speed S',
  check_rpm: 'S{n}',
  check_feed: 'F {f} {u}',
  check_rpm_limit: 'max S{n}',
  check_helix: 'helix {a}°',
  check_delta1: 'δ1 {have} (min {need})',
  check_delta2: 'δ2 {have} (min {need})',
  check_assumed: 'δ1/δ2 assumed: the program turns no work',
  check_assumed_short: 'δ assumed',
  rough: 'rough',
  finish: 'finish',
  spring: 'spring',
  no_threads: 'No thread in this program.',
  no_diagnostics: 'No diagnostics.',
  stale: 'Alarm: the drawing shows the last program without alarms.',
  crashed: 'The planner stopped on this input; the drawing shows the last good program.',
  summary: '{threads#thread|threads} · {moves#move|moves} · {alarms#alarm|alarms} · {warnings#warning|warnings} · {notes#note|notes}',
  timing: 'plan {plan} ms · draw {draw} ms',
  error: 'alarm',
  warning: 'warning',
  info: 'note',
  legend_side: 'cut ─  rapid ╌  run-out/screw-in ┄  finish green · spring violet',
  units: 'units',
  kind_straight: 'straight',
  kind_taper: 'taper',
  kind_face: 'face',
  default: 'default',
  range: 'range',
  // Scene labels.
  dia_major: 'major Ø{}',
  dia_minor: 'minor Ø{}',
  lead: 'Ph {}',
  pitch: 'P {}',
  length: 'L {}',
  taper: 'taper {}',
  delta1: 'δ1 {}',
  delta2: 'δ2 {}',
  height: 'h {}',
  tool_angle: 'tool angle {}',
  start_of: 'start {}',
  pass_depth: '{}',
  pass_depth_finish: '{} finish',
  pass_depth_spring: '{} spring',
  infeed_radial: 'radial infeed',
  infeed_left: 'left flank infeed',
  infeed_right: 'right flank infeed',
  infeed_alternating: 'alternating flanks',
  infeed_programmed: 'infeed as programmed',
  one_rev: 'one-rev signal {}',
  axial_offsets: 'axial offsets lead·θ/360',
  start_angle: '{}',
  starts_capped: '{} starts: the first 360 are drawn',
  moves_capped: 'motions outside the threads: only the first {} are drawn',
  detail_passes: 'every n-th pass drawn (n/all): {}',
  detail_starts: 'one start drawn, the others cut the same path (1/starts): {}',
  detail_starts_passes: 'one start and every n-th pass drawn (1/starts n/all): {}',
  square_tool: '0° tool: width {} assumed',
  // Embedded previews.
  embed_summary: '{threads#thread|threads} · {passes#pass|passes} · {alarms#alarm|alarms} · {warnings#warning|warnings}',
  open_in_editor: 'Open in editor',
  loading: 'Loading…',
  more: '… {n} more',
};

const ZH = {
  title: 'screwcut — 车床螺纹 G 代码预览',
  dialect: '系统',
  examples: '示例',
  example_pick: '打开示例…',
  settings: '参数',
  close: '关闭',
  reset: '恢复默认',
  share: '复制链接',
  shared: '链接已复制',
  share_failed: '链接在地址栏中',
  download_plan: '计划 JSON',
  side: '侧剖面',
  tooth: '牙型剖面',
  starts: '多头',
  fit: '适应',
  stretch: '径向放大',
  svg: 'SVG',
  png: 'PNG',
  passes: '走刀',
  diagnostics: '诊断',
  thread: '螺纹',
  start: '头',
  col_pass: '次',
  col_start: '头',
  col_x: 'X',
  col_z: 'Z 起点',
  col_z_end: 'Z 终点',
  col_depth: '切深',
  col_infeed: '进刀量',
  col_area: '面积',
  col_role: '类型',
  col_lines: '行',
  called_from: '调用自第 {lines} 行',
  switch_to: '按 {title} 读',
  switched: '系统：{title}',
  wizard: '螺纹向导…',
  expand: '展开为逐段程序…',
  wz_title: '螺纹向导',
  wz_help: '填写螺纹标记(或清空标记后填大径和导程)、螺纹长度或终点 Z、系统和编程方式：程序随输入生成。',
  wz_designation: '螺纹标记',
  wz_major: '大径 Ø (mm)',
  wz_lead: '导程 (mm)',
  wz_length: '长度 (mm)',
  wz_start_z: '起点 Z',
  wz_end_z: '终点 Z(代替长度)',
  wz_starts: '头数',
  wz_nose: '刀尖圆弧半径 (mm)',
  wz_max_rpm: '最高主轴转速 (转/分)',
  wz_max_feed: '最高螺纹进给 (mm/分)',
  wz_kind: '外螺纹或内螺纹',
  wz_kind_auto: '按螺纹标记',
  wz_external: '外螺纹',
  wz_internal: '内螺纹',
  wz_form: '编程方式',
  wz_program: '程序',
  wz_open: '作为新程序打开',
  wz_cancel: '取消',
  ex_title: '展开为逐段程序',
  ex_help: '按规划结果为指定系统逐段写出程序：每次走刀的进刀、切削、退尾、退刀和返回；多头螺纹在系统支持时用起始角，否则用轴向偏移。作为新程序打开，当前程序保留。',
  ex_to: '目标系统',
  ex_alarms: '程序有 {n} 个报警：展开只写出报警之前规划的内容。',
  col_even: '等面积',
  view_keys: '按键：方向键平移，+ 和 − 缩放，0 适应窗口，Enter 选取中心处的图元。',
  alt_side: '{threads} 条螺纹，{moves} 段运动，{alarms} 个报警。',
  alt_thread: '第 {i} 条螺纹：{kind}，导程 {lead}，{starts} 头',
  alt_passes: '{n} 次走刀，X{x0} 至 X{x1}，Z{z0} 至 Z{z1}',
  alt_tooth: '牙深 {h}，刀尖角 {angle}°，{n} 次走刀。',
  alt_starts: '{n} 头，显示第 {st} 头。',
  list_passes: '所选螺纹的走刀：方向键选择，Enter 跳到程序行',
  list_diagnostics: '诊断信息：方向键选择，Enter 跳到行和列',
  col_time: '时间',
  designation: '螺纹标记',
  designation_help: '螺纹前没有注释标记时用于检验的螺纹标记(参数 thread.designation)',
  designation_placeholder: '例如 M48x2-6g',
  export_failed: '{view}未能导出：{why}',
  export_empty: '{view}没有可导出的内容',
  export_no_thread: '本程序没有可绘制的螺纹',
  check_none: '没有螺纹标记：在螺纹前的注释中写出，如 (M48x2-6g)，或填在此处，即可检验中径。',
  check_from_comment: '取自第 {line} 行注释',
  check_from_setting: '取自“螺纹标记”栏(参数 thread.designation)',
  check_d2: '中径',
  check_dx: '精车 ΔX {dx}',
  check_nose: '刀尖 r {r}（按全牙型刀片假定）',
  check_nose_range: '刀尖 r 在 {lo}…{hi} 时中径合格；请把 tool.nose_radius 设为所用刀片的半径',
  check_nose_none: '任何刀尖半径都不能使中径合格',
  check_limits: '公差 {min}…{max} {u}',
  check_dx_help: '精车走刀 X(直径)改变此值，中径即居公差中间',
  summary_time: '螺纹加工 {s} 秒',
  check_ok: '合格',
  check_fail: '不合格',
  check_time: '{s} 秒(切削 {cut} 秒)',
  check_no_speed: '无时间：无主轴转速 S',
  check_rpm: 'S{n}',
  check_feed: 'F {f} {u}',
  check_rpm_limit: '最高 S{n}',
  check_helix: '螺旋升角 {a}°',
  check_delta1: 'δ1 {have}(至少 {need})',
  check_delta2: 'δ2 {have}(至少 {need})',
  check_assumed: 'δ1/δ2 为假定值：程序未车外圆',
  check_assumed_short: 'δ 为假定值',
  rough: '粗车',
  finish: '精车',
  spring: '光刀',
  no_threads: '程序中没有螺纹。',
  no_diagnostics: '没有诊断信息。',
  stale: '报警：图中显示的是上一次无报警的程序。',
  crashed: '此输入使计算中止；图中显示的是上一次正常的程序。',
  summary: '{threads} 条螺纹 · {moves} 段运动 · {alarms} 报警 · {warnings} 警告 · {notes} 提示',
  timing: '计算 {plan} ms · 绘图 {draw} ms',
  error: '报警',
  warning: '警告',
  info: '提示',
  legend_side: '切削 ─  快移 ╌  退尾/旋进 ┄  精车 绿 · 光刀 紫',
  units: '单位',
  kind_straight: '直螺纹',
  kind_taper: '锥螺纹',
  kind_face: '端面螺纹',
  default: '默认',
  range: '范围',
  dia_major: '大径 Ø{}',
  dia_minor: '小径 Ø{}',
  lead: '导程 {}',
  pitch: '螺距 {}',
  length: '长 {}',
  taper: '锥度 {}',
  delta1: 'δ1 {}',
  delta2: 'δ2 {}',
  height: '牙高 {}',
  tool_angle: '刀尖角 {}',
  start_of: '第 {} 头',
  pass_depth: '{}',
  pass_depth_finish: '{} 精车',
  pass_depth_spring: '{} 光刀',
  infeed_radial: '径向进刀(中线)',
  infeed_left: '左侧面进刀',
  infeed_right: '右侧面进刀',
  infeed_alternating: '左右交替进刀',
  infeed_programmed: '按程序进刀',
  one_rev: '一转信号 {}',
  axial_offsets: '轴向偏移 导程·θ/360',
  start_angle: '{}',
  starts_capped: '{} 头：只画前 360 头',
  moves_capped: '螺纹以外的运动只画前 {} 段',
  detail_passes: '每隔 n 次走刀画一次(n/总数)：{}',
  detail_starts: '只画一头，其余各头路径相同(1/头数)：{}',
  detail_starts_passes: '只画一头、每隔 n 次走刀画一次(1/头数 n/总数)：{}',
  square_tool: '0° 刀：假定刀宽 {}',
  embed_summary: '{threads} 条螺纹 · {passes} 次走刀 · {alarms} 报警 · {warnings} 警告',
  open_in_editor: '在编辑器中打开',
  loading: '加载中…',
  more: '… 另有 {n} 条',
};

const TABLES = { en: EN, zh: ZH };

/** The settings' units in Chinese (English shows them as the planner names them). */
const UNITS_ZH = {
  '0.1 lead': '0.1 导程',
  bytes: '字节',
  characters: '字符',
  diagnostics: '条',
  diameter: '直径值',
  digits: '位',
  increment: '最小增量',
  leads: '导程',
  moves: '段',
  'on diameter': '(直径上)',
  passes: '刀',
  'program unit': '程序单位',
  'rev/min': 'r/min',
  spindles: '个主轴',
  starts: '头',
  '× even share': '× 等分量',
  '× pitch': '× 螺距',
};

/** The settings' choices in Chinese; the value (what the planner reads) stays as it is and is shown after. */
const CHOICES_ZH = {
  diameter: '直径',
  radius: '半径',
  parameter: '取参数',
  zero: '取 0',
  'minus-z': '−Z 侧',
  'plus-z': '+Z 侧',
  start: '起点',
  thread: '成品螺纹',
  previous: '上次切深 + Δdmin',
  printed: '手册公式',
  steps: '首刀切除余量',
  split: '均分余量',
  fraction: '分数',
  decimal: '小数',
};

/** A setting's unit in the page's language. */
export function unitText(unit) {
  return (lang === 'zh' && UNITS_ZH[unit]) || unit;
}

/** A setting's choice in the page's language (`半径 (radius)`); its value is unchanged. */
export function choiceText(value) {
  const zh = lang === 'zh' && CHOICES_ZH[value];
  return zh ? `${zh} (${value})` : value;
}
let lang = 'en';

export function setLang(l) {
  lang = TABLES[l] ? l : 'en';
  document.documentElement.lang = lang === 'zh' ? 'zh-CN' : 'en';
  for (const el of document.querySelectorAll('[data-i18n]')) el.textContent = t(el.dataset.i18n);
  for (const el of document.querySelectorAll('[data-i18n-title]')) el.title = t(el.dataset.i18nTitle);
  for (const el of document.querySelectorAll('[data-i18n-placeholder]')) el.placeholder = t(el.dataset.i18nPlaceholder);
  document.title = t('title');
}

export function getLang() {
  return lang;
}

/** Page text by key, with `{name}` fields filled from `vars`. */
export function t(key, vars) {
  return textIn(lang, key, vars);
}

/** A scene label: the key's pattern with the value in place of `{}`. */
export function label(key, value) {
  return labelIn(lang, key, value);
}

/**
 * Page text by key in language `l` (en, zh), whatever the page's language is.
 * `{name}` is replaced by `vars.name`; `{name#one|other}` by the number and
 * the singular or plural word (`1 thread`, `2 threads`).
 */
export function textIn(l, key, vars) {
  let s = (TABLES[l] || EN)[key] ?? EN[key] ?? key;
  if (vars) {
    s = s.replace(/\{(\w+)#([^|}]*)\|([^}]*)\}/g, (m, k, one, other) =>
      k in vars ? `${vars[k]} ${Number(vars[k]) === 1 ? one : other}` : m,
    );
    s = s.replace(/\{(\w+)\}/g, (_, k) => (k in vars ? vars[k] : `{${k}}`));
  }
  return s;
}

/** Every text of language `l` as `[key, template, key, template…]` (the SVG writer's label templates). */
export function labelTable(l) {
  const out = [];
  for (const [k, v] of Object.entries(TABLES[l] || EN)) if (typeof v === 'string') out.push(k, v);
  return out;
}

/** A scene label in language `l`. */
export function labelIn(l, key, value) {
  const pattern = (TABLES[l] || EN)[key] ?? EN[key];
  if (pattern === undefined) return value ? `${key} ${value}` : key;
  return pattern.includes('{}') ? pattern.replace('{}', value) : pattern;
}
