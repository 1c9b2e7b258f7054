//! A program as the HTML of a `<screwcut-preview>` element with its static
//! parts inside: the SVG of each drawing (the core's display list, as the
//! live element draws it) and the pass table, so that a page shows the
//! diagram before the element's script runs, without JavaScript and in
//! print — and an element whose static parts show all its views waits for
//! the reader before it loads the planner. `screwcut embed` and the
//! mdbook-screwcut preprocessor write it.

use std::fmt::Write;

use crate::diagnostic::{Diagnostic, Severity};
use crate::dialect::Dialect;
use crate::draw::View;
use crate::message::{Lang, words as w};
use crate::num::fmt;
use crate::settings::Settings;
use crate::thread::{Role, Thread};
use crate::{Plan, diagram};

/// The views of `<screwcut-preview>`, in the order it lays them out.
pub const VIEWS: [&str; 4] = ["side", "tooth", "starts", "table"];

/// `side,tooth` (commas, spaces or bars, any case) → the views in the
/// element's order, as the element reads its `view` attribute; `Err` says
/// which view is unknown.
pub fn views(value: &str) -> Result<Vec<&'static str>, String> {
    let asked: Vec<&str> = value.split([',', ' ', '|']).filter(|v| !v.is_empty()).collect();
    if asked.is_empty() {
        return Err(format!("view needs one or more of {}", VIEWS.join(", ")));
    }
    if let Some(bad) = asked.iter().find(|v| !VIEWS.contains(&v.to_ascii_lowercase().as_str())) {
        return Err(format!("unknown view '{bad}' (known: {})", VIEWS.join(", ")));
    }
    Ok(VIEWS.into_iter().filter(|v| asked.iter().any(|a| a.eq_ignore_ascii_case(v))).collect())
}

/// The element's attributes.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// The controller the program is read as.
    pub dialect: Dialect,
    /// The views, in the element's order, without repeats.
    pub views: Vec<&'static str>,
    /// Height of each drawing, CSS px (120–1200).
    pub height: u32,
    /// The thread (1-based) the tooth, starts and table views show.
    pub thread: usize,
    /// `NAME=VALUE` entries, each accepted by the planner's settings.
    pub settings: Vec<String>,
    /// The labels' language.
    pub lang: Lang,
    /// The element's `editable` flag.
    pub editable: bool,
    /// The element's `hide-code` flag.
    pub hide_code: bool,
    /// The element's `live` flag: plan when scrolled near, not only when the
    /// reader points at the static drawing.
    pub live: bool,
    /// The app the "Open in editor" link opens (http(s) or relative).
    pub app: Option<String>,
}

impl Default for Options {
    /// The element's defaults: GSK980TDc, the side section, 320 px, thread 1.
    fn default() -> Options {
        Options {
            dialect: Dialect::Gsk980tdc,
            views: vec!["side"],
            height: 320,
            thread: 1,
            settings: Vec::new(),
            lang: Lang::En,
            editable: false,
            hide_code: false,
            live: false,
            app: None,
        }
    }
}

impl Options {
    /// The settings the planner reads the program with (entries it refuses
    /// are left out: check them with [`Settings::assign`] when reading them).
    pub fn planner_settings(&self) -> Settings {
        let mut s = Settings::new(self.dialect);
        for e in &self.settings {
            let _ = s.assign(e);
        }
        s
    }
}

/// `value` as the element's `app`: http(s) or relative, as the element
/// follows it; `Err` says why not.
pub fn app_url(value: &str) -> Result<String, String> {
    let scheme = value.split_once(':').map(|(s, _)| s).filter(|s| {
        s.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            && s.chars().all(|c| c.is_ascii_alphanumeric() || "+.-".contains(c))
    });
    match scheme {
        Some(s) if !s.eq_ignore_ascii_case("http") && !s.eq_ignore_ascii_case("https") => {
            Err(format!("app '{value}' is not an http(s) or relative URL"))
        }
        _ if value.trim().is_empty() => Err("app needs a URL".into()),
        _ => Ok(value.to_string()),
    }
}

/// A program made into the element, and what the planner said of it.
pub struct Rendered {
    /// The element, on lines none of which is blank (a Markdown HTML block
    /// ends at a blank line).
    pub html: String,
    /// The planner's alarms and warnings (notes are left out).
    pub diagnostics: Vec<Diagnostic>,
    /// Lines of the text before the program's first line (blank lines the
    /// element drops).
    pub leading: usize,
}

/// The program as the element reads its text: blank lines at either end
/// dropped and the common indentation removed; and how many lines were
/// dropped at the start.
pub fn dedent(text: &str) -> (String, usize) {
    let text = text.replace("\r\n", "\n").replace('\r', "\n");
    let lines: Vec<&str> = text.split('\n').collect();
    let first = lines.iter().position(|l| !l.trim().is_empty());
    let Some(first) = first else { return (String::new(), 0) };
    let last = lines.iter().rposition(|l| !l.trim().is_empty()).unwrap_or(first);
    let body = &lines[first..=last];
    let indent =
        body.iter().filter(|l| !l.trim().is_empty()).map(|l| l.len() - l.trim_start_matches([' ', '\t']).len()).min();
    let indent = indent.unwrap_or(0);
    let out: Vec<&str> = body.iter().map(|l| l.get(indent..).unwrap_or("")).collect();
    (out.join("\n") + "\n", first)
}

/// `s` with `&`, `<`, `>` and `"` written as HTML entities; unlike
/// [`crate::svg::escape`] (XML), every other character is kept as it is:
/// the element's text is the program, which reads the same.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// The program as the element's text with no blank line: each blank line
/// is written as a `&#10;` at the start of the next line (the text the
/// element reads is the same).
fn program_text(program: &str) -> String {
    let mut out = String::new();
    let mut pending = 0;
    for line in program.lines() {
        if line.trim().is_empty() {
            pending += 1;
            continue;
        }
        out.push_str(&"&#10;".repeat(pending));
        pending = 0;
        out.push_str(&escape(line));
        out.push('\n');
    }
    out
}

/// The width of each drawing in a row of `width` px, as the element lays
/// them out: one drawing takes the row; two share it; of three, the side
/// section takes a row and the other two share the next.
fn widths(views: &[&'static str], width: f64) -> Vec<(&'static str, f64)> {
    let drawings: Vec<&'static str> = views.iter().copied().filter(|v| *v != "table").collect();
    let half = ((width - 1.0) / 2.0).floor();
    drawings
        .iter()
        .map(|&v| {
            let whole = drawings.len() == 1 || (drawings.len() == 3 && v == "side");
            (v, if whole { width } else { half })
        })
        .collect()
}

/// Height of a drawing's caption line in the element (`.view .cap`: 3 px
/// padding and a 14 px line), above its canvas.
const CAPTION: f64 = 17.0;

/// The static SVG of one view, as the element would draw it at that size,
/// without the XML declaration; `None` when the plan has no such drawing.
fn drawing(plan: &Plan, view: &str, o: &Options, width: f64) -> Option<String> {
    let ti = o.thread - 1;
    let scene = match view {
        "tooth" => diagram::tooth(plan, ti, 1)?,
        "starts" => diagram::starts(plan, ti)?,
        _ => diagram::side(plan),
    };
    // The element's canvas: the drawing's height less its caption line; the side section stretched radially.
    let height = f64::from(o.height) - CAPTION;
    let v = View { width, height, stretch: view == "side", thread: ti, lang: o.lang, ..Default::default() };
    let svg = crate::svg::svg(&scene, &v);
    let body: Vec<&str> = svg.lines().filter(|l| !l.starts_with("<?xml") && !l.trim().is_empty()).collect();
    Some(body.join("\n"))
}

/// Most rows of a static pass table: the live table lists them all.
pub const STATIC_ROWS: usize = 200;

/// The static pass table of the element's thread, on one line: the live
/// table's headers and cells (www/src/shared/lists.js `passHead`,
/// `passRow`), styled inline for a page without the element's script, its
/// first [`STATIC_ROWS`] passes and a row that says how many more; `None`
/// when the plan has no such thread.
fn pass_table(plan: &Plan, o: &Options) -> Option<String> {
    let t = plan.threads.get(o.thread - 1)?;
    let lang = o.lang;
    let u = if t.units.is_inch() { "in" } else { "mm" };
    let u2 = if t.units.is_inch() { "in²" } else { "mm²" };
    let mut html = String::from(
        "<table data-screwcut=\"passes\" style=\"border-collapse:collapse;text-align:right;white-space:nowrap;font:12px/1.5 system-ui,sans-serif;font-variant-numeric:tabular-nums\" cellpadding=\"3\"><thead><tr>",
    );
    let heads = [
        (&w::TABLE_PASS, ""),
        (&w::TABLE_START, ""),
        (&w::TABLE_X, u),
        (&w::TABLE_Z_START, u),
        (&w::TABLE_Z_END, u),
        (&w::TABLE_DEPTH, u),
        (&w::TABLE_INCREMENT, u),
        (&w::TABLE_AREA, u2),
        (&w::TABLE_EVEN, u2),
        (&w::TABLE_TIME, "s"),
    ];
    for (h, unit) in heads {
        let unit = if unit.is_empty() { String::new() } else { format!(" <span class=\"unit\">({unit})</span>") };
        let _ = write!(html, "<th>{}{unit}</th>", escape(h.text(lang)));
    }
    for h in [&w::TABLE_ROLE, &w::TABLE_LINES] {
        let _ = write!(html, "<th class=\"role\" style=\"text-align:left\">{}</th>", escape(h.text(lang)));
    }
    html.push_str("</tr></thead><tbody>");
    for k in 0..t.passes.len().min(STATIC_ROWS) {
        pass_row(&mut html, t, k, lang);
    }
    if t.passes.len() > STATIC_ROWS {
        let more = w::TABLE_MORE.render(&crate::args![n = t.passes.len() - STATIC_ROWS], lang);
        let _ = write!(html, "<tr><td colspan=\"12\" style=\"text-align:left\">{}</td></tr>", escape(&more));
    }
    html.push_str("</tbody></table>");
    Some(html)
}

/// Row `k` of thread `t`'s static pass table.
fn pass_row(html: &mut String, t: &Thread, k: usize, lang: Lang) {
    let p = &t.passes[k];
    let chip = t.shop.chip.get(k);
    let opt = |v: Option<f64>| v.map_or_else(String::new, fmt);
    let role = match p.role {
        Role::Rough => (&w::ROUGH, "rough"),
        Role::Finish => (&w::FINISH, "finish"),
        Role::Spring => (&w::SPRING, "spring"),
    };
    let mut lines = p.lines.iter().map(u32::to_string).collect::<Vec<_>>().join(",");
    if !p.via.is_empty() {
        lines += " ← ";
        lines += &p.via.iter().map(u32::to_string).collect::<Vec<_>>().join(" ← ");
    }
    let cells = [
        p.index.to_string(),
        p.start.to_string(),
        fmt(p.from.x),
        fmt(p.from.z),
        fmt(p.to.z),
        fmt(p.depth),
        fmt(p.infeed),
        opt(chip.and_then(|c| c.area)),
        opt(chip.and_then(|c| c.even_area)),
        opt(t.shop.pass_time_s.get(k).copied()),
    ];
    let _ = write!(html, "<tr class=\"{}\">", role.1);
    for c in cells {
        let _ = write!(html, "<td>{c}</td>");
    }
    let _ = write!(
        html,
        "<td class=\"role\" style=\"text-align:left\">{}</td><td class=\"lines\" style=\"text-align:left\">{lines}</td></tr>",
        escape(role.0.text(lang))
    );
}

/// Most diagnostics listed under the element (its script's `MAX_LISTED`).
const LISTED: usize = 6;

/// The plan's alarms and warnings `diags` as the element lists them under
/// its drawing (www/src/embed/element.js `_renderDiagnostics`): the first
/// [`LISTED`] and how many more; empty without any.
fn diagnostics_list(diags: &[Diagnostic], lang: Lang) -> String {
    if diags.is_empty() {
        return String::new();
    }
    let mut html = String::from("<ul data-screwcut=\"diagnostics\">");
    for d in diags.iter().take(LISTED) {
        let _ = write!(
            html,
            "<li class=\"{2}\" data-line=\"{0}\"><b>{0}:{1} {3}</b> <code>[{4}]</code> {5}{6}</li>",
            d.line,
            d.column,
            d.severity.name(),
            d.severity.word().text(lang),
            escape(&d.code.to_string()),
            escape(&d.render(lang)),
            repeats(d, lang)
        );
    }
    if diags.len() > LISTED {
        let more = w::LIST_MORE.render(&crate::args![n = diags.len() - LISTED], lang);
        let _ = write!(html, "<li>{}</li>", escape(&more));
    }
    html + "</ul>"
}

/// How many times a diagnostic raised more than once was raised, as the
/// element's list says it (` <i>raised 50 times</i>`); empty for one.
fn repeats(d: &Diagnostic, lang: Lang) -> String {
    if d.repeats < 2 {
        return String::new();
    }
    format!(" <i>{}</i>", escape(&w::RAISED_TIMES.render(&crate::args![n = d.repeats], lang)))
}

/// The element's opening tag with the options as attributes.
fn open_tag(o: &Options) -> String {
    let mut tag = format!(
        "<screwcut-preview dialect=\"{}\" view=\"{}\" height=\"{}\"",
        o.dialect.name(),
        o.views.join(" "),
        o.height
    );
    if o.thread != 1 {
        tag += &format!(" thread=\"{}\"", o.thread);
    }
    if !o.settings.is_empty() {
        tag += &format!(" settings=\"{}\"", escape(&o.settings.join("; ")));
    }
    if o.lang != Lang::En {
        tag += &format!(" lang=\"{}\"", o.lang.name());
    }
    if o.editable {
        tag += " editable";
    }
    if o.hide_code {
        tag += " hide-code";
    }
    if o.live {
        tag += " live";
    }
    if let Some(app) = &o.app {
        tag += &format!(" app=\"{}\"", escape(app));
    }
    tag + ">"
}

/// The program in `text` (dedented) with options `o` as the element's HTML,
/// its drawings `width` px wide in all.
pub fn render(text: &str, o: &Options, width: f64) -> Rendered {
    let (program, leading) = dedent(text);
    let plan = crate::plan(&program, &o.planner_settings());
    let diagnostics: Vec<Diagnostic> =
        plan.diagnostics.iter().filter(|d| d.severity != Severity::Info).cloned().collect();
    // The tag alone on its line: so Markdown takes what follows as HTML.
    let mut html = open_tag(o) + "\n";
    // The drawings first, side by side as the element lays them out (no
    // text between them: without script the element's text is preformatted),
    // then the pass table and the alarms and warnings.
    let svgs: Vec<String> = widths(&o.views, width).into_iter().filter_map(|(v, w)| drawing(&plan, v, o, w)).collect();
    html += &svgs.join("");
    if o.views.contains(&"table") {
        html += &pass_table(&plan, o).unwrap_or_default();
    }
    html += &diagnostics_list(&diagnostics, o.lang);
    html.push('\n');
    html += &program_text(&program);
    html += "</screwcut-preview>\n";
    Rendered { html, diagnostics, leading }
}

#[cfg(test)]
#[path = "element/tests.rs"]
mod tests;
