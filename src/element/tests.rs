use super::*;

/// The textbook's first two G32 passes (M48×2, X47.1 then X46.5), written for this test.
const TWO_PASSES: &str =
    "\n  G00 X58. Z70.\n  X47.1\n\n  G32 Z13. F2.\n  G00 X58.\n  Z70.\n  X46.5\n  G32 Z13.\n  G00 X58.\n\n";

fn options(views: &[&'static str]) -> Options {
    Options { views: views.to_vec(), ..Options::default() }
}

#[test]
fn dedents_as_the_element_does() {
    let (p, leading) = dedent(TWO_PASSES);
    assert_eq!(leading, 1);
    assert!(p.starts_with("G00 X58. Z70.\nX47.1\n\nG32 Z13. F2.\n"));
    assert!(p.ends_with("G00 X58.\n"));
}

#[test]
fn the_element_carries_the_program_and_a_drawing_per_view_with_no_blank_line() {
    let o = Options { dialect: Dialect::Fanuc0i, height: 300, ..options(&["side", "tooth", "table"]) };
    let r = render(TWO_PASSES, &o, 748.0);
    assert!(
        r.html.starts_with("<screwcut-preview dialect=\"fanuc0i\" view=\"side tooth table\" height=\"300\">\n<svg ")
    );
    assert!(r.html.contains("</table>\nG00 X58. Z70.\nX47.1\n&#10;G32 Z13. F2.\n"));
    assert!(!r.html.contains("\n\n"), "a blank line would end the Markdown HTML block");
    assert_eq!(r.html.matches("<svg ").count(), 2, "side and tooth: the table is not a drawing");
    // Two drawings share the row: each (748 − 1) / 2 px wide, the canvas's 300 − 17 px high.
    assert_eq!(r.html.matches("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"373\" height=\"283\"").count(), 2);
    assert!(r.html.contains("<title>screwcut: side section</title>"));
    assert!(r.html.ends_with("G00 X58.\n</screwcut-preview>\n"));
    assert!(r.html.contains("</svg><svg "), "side by side");
    assert!(r.html.contains("</svg><table data-screwcut=\"passes\""), "the table after the drawings");
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics.iter().map(|d| &d.message).collect::<Vec<_>>());
}

#[test]
fn the_static_table_is_the_threads_passes() {
    // No major diameter turned: the crest is assumed at X49.1 (d = D − 1.3·P
    // below the deepest pass), so pass 1 at X47.1 is 1 deep and pass 2 at X46.5
    // 1.3 deep (0.3 more). A 60° form's cut is h²·tan 30°: 0.5774 mm² for the
    // first pass, 1.69·tan 30° − 0.5774 = 0.3984 mm² for the second.
    let r = render(TWO_PASSES, &options(&["side", "table"]), 748.0);
    let rows: Vec<&str> = r.html.split("<tr class=").skip(1).collect();
    assert_eq!(rows.len(), 2);
    assert!(
        rows[0].starts_with(
            "\"rough\"><td>1</td><td>1</td><td>47.1</td><td>70</td><td>13</td><td>1</td><td>1</td><td>0.5774</td>"
        ),
        "{}",
        rows[0]
    );
    assert!(
        rows[1].starts_with(
            "\"finish\"><td>2</td><td>1</td><td>46.5</td><td>70</td><td>13</td><td>1.3</td><td>0.3</td><td>0.3984</td>"
        ),
        "{}",
        rows[1]
    );
    // No spindle speed: no time; the blocks of each pass (line 3 of the program is blank).
    assert!(
        rows[0].contains(
            "<td></td><td class=\"role\" style=\"text-align:left\">rough</td><td class=\"lines\" style=\"text-align:left\">2,4,5,6</td></tr>"
        ),
        "{}",
        rows[0]
    );
    assert!(
        r.html.contains("<th>X <span class=\"unit\">(mm)</span></th>")
            && r.html.contains("<th>Area <span class=\"unit\">(mm²)</span></th>")
    );
    // In Chinese, the command line's column words.
    let zh = render(TWO_PASSES, &Options { lang: Lang::Zh, ..options(&["table"]) }, 748.0);
    assert!(
        zh.html.contains("<th>切深 <span class=\"unit\">(mm)</span></th>") && zh.html.contains(">精车</td>"),
        "{}",
        zh.html
    );
    assert!(
        zh.html
            .starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"table\" height=\"320\" lang=\"zh\">\n<table ")
    );
}

#[test]
fn no_thread_no_table_and_no_tooth() {
    let r = render("G00 X58 Z70\nG01 X40 F0.2\n", &options(&["side", "tooth", "table"]), 748.0);
    assert_eq!((r.html.matches("<svg ").count(), r.html.contains("<table")), (1, false));
}

#[test]
fn three_drawings_put_the_side_section_on_its_own_row() {
    assert_eq!(widths(&["side", "tooth", "starts"], 748.0), vec![("side", 748.0), ("tooth", 373.0), ("starts", 373.0)]);
    assert_eq!(widths(&["tooth", "table"], 748.0), vec![("tooth", 748.0)]);
}

#[test]
fn a_program_that_alarms_reports_the_line_and_lists_it_inside() {
    // Fanuc 0i: G32 without F before any feed is an alarm on that block.
    let o = Options { dialect: Dialect::Fanuc0i, ..Options::default() };
    let r = render("\nG00 X58 Z70\nX47.1\nG32 Z13\n", &o, 748.0);
    let alarm = r.diagnostics.iter().find(|d| d.severity == Severity::Error).expect("an alarm");
    assert_eq!((alarm.line, r.leading), (3, 1));
    // Listed inside the element as it lists it under the live drawing, with the
    // program's line (the element drops the blank line before it); and the two
    // lengths with no decimal point, warnings in Fanuc 0i.
    assert!(r.html.starts_with("<screwcut-preview dialect=\"fanuc0i\" view=\"side\" height=\"320\">\n<svg "));
    assert!(r.html.contains("<ul data-screwcut=\"diagnostics\"><li class=\"warning\" data-line=\"1\"><b>1:5 warning</b> <code>[no-decimal-point]</code> X58 has no decimal point"), "{}", r.html);
    assert!(
        r.html.contains(
            "<li class=\"error\" data-line=\"3\"><b>3:1 alarm</b> <code>[missing-lead]</code> G32 without a lead"
        ),
        "{}",
        r.html
    );
}

#[test]
fn at_most_six_diagnostics_are_listed_and_the_rest_counted() {
    // Eight lengths with no decimal point: eight Fanuc 0i warnings.
    let o = Options { dialect: Dialect::Fanuc0i, lang: Lang::Zh, ..Options::default() };
    let r = render("G00 X58 Z70\nX57 Z69\nX56 Z68\nX55 Z67\n", &o, 748.0);
    assert_eq!(r.diagnostics.len(), 8);
    assert_eq!(r.html.matches("<li class=\"warning\"").count(), 6);
    assert!(r.html.contains("<li>… 另有 2 条</li></ul>"), "{}", r.html);
}

#[test]
fn a_clean_program_waits_for_the_reader_unless_live_is_asked() {
    let quiet = render(TWO_PASSES, &options(&["side", "tooth"]), 748.0);
    assert!(quiet.html.starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"side tooth\" height=\"320\">\n"));
    let asked = render(TWO_PASSES, &Options { live: true, ..Options::default() }, 748.0);
    assert!(asked.html.starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"side\" height=\"320\" live>\n"));
}

#[test]
fn text_that_looks_like_html_is_escaped() {
    let r = render("G00 X58 Z70 (A<B & </screwcut-preview>)\n", &Options::default(), 748.0);
    assert!(r.html.contains("(A&lt;B &amp; &lt;/screwcut-preview&gt;)"));
    assert_eq!(r.html.matches("</screwcut-preview>").count(), 1);
}

#[test]
fn the_app_is_http_or_relative() {
    assert_eq!(app_url("https://example.org/screwcut/"), Ok("https://example.org/screwcut/".into()));
    assert_eq!(app_url("../app/"), Ok("../app/".into()));
    assert_eq!(
        app_url("javascript:alert(1)"),
        Err("app 'javascript:alert(1)' is not an http(s) or relative URL".into())
    );
    assert_eq!(app_url(" "), Err("app needs a URL".into()));
}

#[test]
fn a_long_table_is_cut_and_says_how_much_more() {
    // 250 block-by-block passes of one G32 thread (M48×2 from X47.9 down by 0.004 mm each).
    let mut text = String::from("G00 X58. Z70.\n");
    for k in 0..250 {
        text += &format!("X{}\nG32 Z13. F2.\nG00 X58.\nZ70.\n", fmt(47.9 - 0.004 * f64::from(k)));
    }
    let r = render(&text, &options(&["table"]), 748.0);
    assert_eq!(r.html.matches("<tr class=").count(), STATIC_ROWS);
    assert!(r.html.contains("<td>200</td><td>1</td><td>47.104</td>"), "the 200th pass at X47.9 − 199 × 0.004");
    assert!(r.html.contains(">… 50 more passes: point at the diagram to list them all</td></tr></tbody>"));
}

#[test]
fn an_alarm_raised_again_in_a_loop_is_listed_once_with_the_count() {
    // A Fanuc WHILE loop runs a G01 with a Q word three times: one row, as
    // the element's script writes it (`_renderDiagnostics`).
    let o = Options { dialect: Dialect::Fanuc0i, ..Options::default() };
    let program = "G00 X40. Z5.\n#1=0\nWHILE[#1LT3]DO1\nG01 X40. Q3 F0.2\n#1=#1+1\nEND1\n";
    let r = render(program, &o, 748.0);
    let rows = r.html.matches("[unexpected-word]").count();
    assert_eq!(rows, 1, "{}", r.html);
    assert!(r.html.contains("G01 does not take Q3 <i>raised 3 times</i></li>"), "{}", r.html);
}
