//! One ```` ```screwcut ```` block as HTML: a `<screwcut-preview>` with the
//! program as its text and, inside it, the static SVG of each of its
//! drawings (the core's display list, as the live element draws it), so the
//! page shows the diagram before the script runs, without JavaScript and in
//! print. The block's diagnostics come back with their lines in the program.

use screwcut::diagram;
use screwcut::draw::View;
use screwcut::{Diagnostic, Plan, Severity};

use crate::options::Options;

/// A block made into HTML, and what the planner said of its program.
pub struct Rendered {
    /// The element, on lines none of which is blank (a Markdown HTML block
    /// ends at a blank line).
    pub html: String,
    /// The planner's alarms and warnings (notes are left out).
    pub diagnostics: Vec<Diagnostic>,
    /// Lines of the block before the program's first line (blank lines the
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

/// `s` with `&`, `<`, `>` and `"` written as HTML entities.
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
    let svg = screwcut::svg::svg(&scene, &v);
    let body: Vec<&str> = svg.lines().filter(|l| !l.starts_with("<?xml") && !l.trim().is_empty()).collect();
    Some(body.join("\n"))
}

/// The element's opening tag with the block's options as attributes; `live`
/// also when the static drawings cannot show the plan's warnings and alarms.
fn open_tag(o: &Options, live: bool) -> String {
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
    if o.lang != screwcut::message::Lang::En {
        tag += &format!(" lang=\"{}\"", o.lang.name());
    }
    if o.editable {
        tag += " editable";
    }
    if o.hide_code {
        tag += " hide-code";
    }
    if o.live || live {
        tag += " live";
    }
    if let Some(app) = &o.app {
        tag += &format!(" app=\"{}\"", escape(app));
    }
    tag + ">"
}

/// The block's program with options `o` as HTML, drawings `width` px wide in all.
pub fn render(block: &str, o: &Options, width: f64) -> Rendered {
    let (program, leading) = dedent(block);
    let plan = screwcut::plan(&program, &o.planner_settings());
    let diagnostics: Vec<Diagnostic> =
        plan.diagnostics.iter().filter(|d| d.severity != Severity::Info).cloned().collect();
    // The tag alone on its line: so Markdown takes what follows as HTML. An
    // element that would list warnings or alarms under its drawing plans
    // when scrolled near (the static drawing does not list them).
    let mut html = open_tag(o, !diagnostics.is_empty()) + "\n";
    // The drawings first, side by side as the element lays them out (no
    // text between them: without script the element's text is preformatted).
    let svgs: Vec<String> = widths(&o.views, width).into_iter().filter_map(|(v, w)| drawing(&plan, v, o, w)).collect();
    html += &svgs.join("");
    html.push('\n');
    html += &program_text(&program);
    html += "</screwcut-preview>\n";
    Rendered { html, diagnostics, leading }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::options::parse;

    /// The textbook's first two G32 passes (M48×2, X47.1 then X46.5), written for this test.
    const TWO_PASSES: &str =
        "\n  G00 X58. Z70.\n  X47.1\n\n  G32 Z13. F2.\n  G00 X58.\n  Z70.\n  X46.5\n  G32 Z13.\n  G00 X58.\n\n";

    #[test]
    fn dedents_as_the_element_does() {
        let (p, leading) = dedent(TWO_PASSES);
        assert_eq!(leading, 1);
        assert!(p.starts_with("G00 X58. Z70.\nX47.1\n\nG32 Z13. F2.\n"));
        assert!(p.ends_with("G00 X58.\n"));
    }

    #[test]
    fn the_element_carries_the_program_and_a_drawing_per_view_with_no_blank_line() {
        let o = parse("dialect=fanuc0i view=side,tooth,table height=300").unwrap();
        let r = render(TWO_PASSES, &o, 748.0);
        assert!(
            r.html
                .starts_with("<screwcut-preview dialect=\"fanuc0i\" view=\"side tooth table\" height=\"300\">\n<svg ")
        );
        assert!(r.html.contains("</svg>\nG00 X58. Z70.\nX47.1\n&#10;G32 Z13. F2.\n"));
        assert!(!r.html.contains("\n\n"), "a blank line would end the Markdown HTML block");
        assert_eq!(r.html.matches("<svg ").count(), 2, "side and tooth: the table is not a drawing");
        // Two drawings share the row: each (748 − 1) / 2 px wide, the canvas's 300 − 17 px high.
        assert_eq!(r.html.matches("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"373\" height=\"283\"").count(), 2);
        assert!(r.html.contains("<title>screwcut: side section</title>"));
        assert!(r.html.ends_with("G00 X58.\n</screwcut-preview>\n"));
        assert!(r.html.contains("</svg><svg "), "side by side");
        assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics.iter().map(|d| &d.message).collect::<Vec<_>>());
    }

    #[test]
    fn three_drawings_put_the_side_section_on_its_own_row() {
        assert_eq!(
            widths(&["side", "tooth", "starts"], 748.0),
            vec![("side", 748.0), ("tooth", 373.0), ("starts", 373.0)]
        );
        assert_eq!(widths(&["tooth", "table"], 748.0), vec![("tooth", 748.0)]);
    }

    #[test]
    fn a_program_that_alarms_reports_the_line() {
        // Fanuc 0i: G32 without F before any feed is an alarm on that block.
        let o = parse("dialect=fanuc0i").unwrap();
        let r = render("\nG00 X58 Z70\nX47.1\nG32 Z13\n", &o, 748.0);
        let alarm = r.diagnostics.iter().find(|d| d.severity == Severity::Error).expect("an alarm");
        assert_eq!((alarm.line, r.leading), (3, 1));
        // The alarm is listed under the live drawing only: the element plans when scrolled near.
        assert!(r.html.starts_with("<screwcut-preview dialect=\"fanuc0i\" view=\"side\" height=\"320\" live>\n<svg "));
    }

    #[test]
    fn a_clean_program_waits_for_the_reader_unless_live_is_asked() {
        let quiet = render(TWO_PASSES, &parse("view=side,tooth").unwrap(), 748.0);
        assert!(
            quiet.html.starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"side tooth\" height=\"320\">\n")
        );
        let asked = render(TWO_PASSES, &parse("view=side live").unwrap(), 748.0);
        assert!(asked.html.starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"side\" height=\"320\" live>\n"));
    }

    #[test]
    fn text_that_looks_like_html_is_escaped() {
        let o = parse("").unwrap();
        let r = render("G00 X58 Z70 (A<B & </screwcut-preview>)\n", &o, 748.0);
        assert!(r.html.contains("(A&lt;B &amp; &lt;/screwcut-preview&gt;)"));
        assert_eq!(r.html.matches("</screwcut-preview>").count(), 1);
    }
}
