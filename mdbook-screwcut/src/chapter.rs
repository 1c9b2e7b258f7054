//! A chapter's Markdown with its ```` ```screwcut ```` blocks replaced by
//! the element (see [`crate::block`]), the script that defines it added
//! once per chapter, and what each block's program was told, placed at its
//! line in the chapter.

use pulldown_cmark::{CodeBlockKind, Event, Options as Md, Parser, Tag, TagEnd};
use screwcut::Severity;

use crate::options;

/// A diagnostic of a block's program at its place in the chapter.
#[derive(Clone, Debug, PartialEq)]
pub struct Said {
    /// Alarm or warning.
    pub severity: Severity,
    /// 1-based line in the chapter's file.
    pub line: usize,
    /// 1-based column in the program's line.
    pub column: u32,
    /// The diagnostic's code, as `screwcut codes` lists it.
    pub code: String,
    /// The message, in English.
    pub message: String,
}

/// What became of a chapter.
pub struct Done {
    /// The new Markdown.
    pub content: String,
    /// How many blocks it had.
    pub blocks: usize,
    /// The blocks' alarms and warnings.
    pub said: Vec<Said>,
}

/// A found block: its byte range, the line its fence is on, its info string
/// after `screwcut`, its text.
struct Found {
    range: std::ops::Range<usize>,
    line: usize,
    info: String,
    text: String,
}

/// The ```` ```screwcut ```` blocks of `md`, in order.
fn find(md: &str) -> Vec<Found> {
    let mut out = Vec::new();
    let mut open: Option<Found> = None;
    for (event, range) in Parser::new_ext(md, Md::empty()).into_offset_iter() {
        match event {
            Event::Start(Tag::CodeBlock(CodeBlockKind::Fenced(info))) => {
                let mut words = info.splitn(2, char::is_whitespace);
                if words.next().is_some_and(|w| w.eq_ignore_ascii_case("screwcut")) {
                    let line = md[..range.start].matches('\n').count() + 1;
                    let info = words.next().unwrap_or("").to_string();
                    open = Some(Found { range, line, info, text: String::new() });
                }
            }
            Event::Text(t) => {
                if let Some(f) = open.as_mut() {
                    f.text.push_str(&t);
                }
            }
            Event::End(TagEnd::CodeBlock) => out.extend(open.take()),
            _ => {}
        }
    }
    out
}

/// The prefix that continues the fence's line for the lines after it: a
/// block quote's `>` kept, a list item's marker as spaces.
fn continuation(md: &str, at: usize) -> String {
    let line_start = md[..at].rfind('\n').map_or(0, |i| i + 1);
    md[line_start..at].chars().map(|c| if c == '>' { '>' } else { ' ' }).collect()
}

/// The script that loads the element from the book's copy of it, relative
/// to the page (mdBook's `path_to_root`; `fallback_root` where a theme
/// does not define it), and the style that lays out the program and its
/// drawings where the script does not run.
fn loader(assets: &str, fallback_root: &str) -> String {
    format!(
        "<script type=\"module\">\n\
         const root = typeof path_to_root === 'string' ? path_to_root : '{fallback_root}';\n\
         import(new URL(root + '{assets}/screwcut-preview.js', document.baseURI).href);\n\
         </script>\n\
         <style>\n\
         screwcut-preview:not(:defined) {{ display: block; margin: 1em 0; padding: 6px; border: 1px solid #d1d5db; border-radius: 6px; white-space: pre; overflow-x: auto; font: 12px/1.4 monospace; }}\n\
         screwcut-preview:not(:defined) > svg {{ display: inline-block; vertical-align: top; max-width: 100%; height: auto; white-space: normal; }}\n\
         screwcut-preview:not(:defined) > ul {{ white-space: normal; margin: 4px 0; padding-left: 1.5em; font: 12px/1.4 system-ui, sans-serif; }}\n\
         screwcut-preview:not(:defined) > table {{ display: block; max-height: 24em; overflow: auto; margin: 4px 0; white-space: nowrap; font: 12px/1.5 system-ui, sans-serif; }}\n\
         </style>\n"
    )
}

/// The page's path back to the book's root for a chapter at `path`
/// (relative to the book's source folder).
pub fn root_of(path: &std::path::Path) -> String {
    "../".repeat(path.components().count().saturating_sub(1))
}

/// `md` with its blocks made into elements drawn `width` px wide; `Err`
/// names the line of a block whose options are wrong.
pub fn process(md: &str, root: &str, assets: &str, width: f64) -> Result<Done, String> {
    let found = find(md);
    let mut content = String::with_capacity(md.len());
    let mut said = Vec::new();
    let mut at = 0;
    for f in &found {
        let o = options::parse(&f.info).map_err(|e| format!("line {}: ```screwcut block: {e}", f.line))?;
        let r = screwcut::element::render(&f.text, &o, width);
        let prefix = continuation(md, f.range.start);
        content.push_str(&md[at..f.range.start]);
        let lines: Vec<&str> = r.html.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            if i > 0 {
                content.push_str(&prefix);
            }
            content.push_str(l);
            if i + 1 < lines.len() {
                content.push('\n');
            }
        }
        at = f.range.end;
        // The program's line 1 is the line after the fence, past the blank lines the element drops.
        let first = f.line + 1 + r.leading;
        said.extend(r.diagnostics.iter().map(|d| Said {
            severity: d.severity,
            line: first + d.line as usize - 1,
            column: d.column,
            code: d.code.as_str().to_string(),
            message: d.message.clone(),
        }));
    }
    content.push_str(&md[at..]);
    if !found.is_empty() {
        content.push_str("\n\n");
        content.push_str(&loader(assets, root));
    }
    Ok(Done { content, blocks: found.len(), said })
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHAPTER: &str = "# Fanuc\n\nText.\n\n```screwcut dialect=fanuc0i height=200\nG00 X58 Z70\nX47.1\nG32 Z13\n```\n\n```gcode\nG32 Z13 F2\n```\n";

    #[test]
    fn a_block_becomes_the_element_and_other_code_stays() {
        let d = process(CHAPTER, "../", "screwcut", 748.0).unwrap();
        assert_eq!(d.blocks, 1);
        assert!(d.content.starts_with(
            "# Fanuc\n\nText.\n\n<screwcut-preview dialect=\"fanuc0i\" view=\"side\" height=\"200\">\n<svg "
        ));
        // G32 with no feed yet is a Fanuc alarm: listed inside the element, under its drawing.
        assert!(d.content.contains("<li class=\"error\" data-line=\"3\"><b>3:1 alarm</b> <code>[missing-lead]</code>"));
        assert!(d.content.contains("</li></ul>\nG00 X58 Z70\n"), "the list after the drawing, then the program");
        assert!(d.content.contains("```gcode\nG32 Z13 F2\n```"));
        assert_eq!(
            d.content.matches("import(new URL(root + 'screwcut/screwcut-preview.js', document.baseURI).href)").count(),
            1
        );
        assert!(d.content.contains("path_to_root : '../'"));
    }

    #[test]
    fn the_alarm_is_placed_at_its_line_in_the_chapter() {
        // The fence is line 5; G32 without a lead is the program's line 3, the chapter's line 8.
        let d = process(CHAPTER, "", "screwcut", 748.0).unwrap();
        let alarm = d.said.iter().find(|s| s.severity == Severity::Error).expect("an alarm");
        assert_eq!(alarm.line, 8, "{alarm:?}");
    }

    #[test]
    fn a_bad_option_names_the_line() {
        let md = "Intro\n\n```screwcut view=front\nG00 X58\n```\n";
        assert_eq!(
            process(md, "", "screwcut", 748.0).err().unwrap(),
            "line 3: ```screwcut block: unknown view 'front' (known: side, tooth, starts, table)"
        );
    }

    #[test]
    fn a_block_in_a_list_item_keeps_its_indentation() {
        let md = "1. Pass one:\n\n   ```screwcut\n   G00 X58 Z70\n   X47.1\n   G32 Z13 F2\n   ```\n";
        let d = process(md, "", "screwcut", 748.0).unwrap();
        assert!(
            d.content.contains("   <screwcut-preview dialect=\"gsk980tdc\" view=\"side\" height=\"320\">\n   <svg ")
        );
        assert!(d.content.contains("\n   </svg>\n   G00 X58 Z70\n   X47.1\n"));
        assert!(d.said.is_empty(), "{:?}", d.said);
    }

    #[test]
    fn a_chapter_without_blocks_is_left_as_it_is() {
        let md = "# Intro\n\n```\nG32\n```\n";
        assert_eq!(process(md, "", "screwcut", 748.0).unwrap().content, md);
    }

    #[test]
    fn nested_chapters_reach_the_root() {
        assert_eq!(root_of(std::path::Path::new("dialects/fanuc.md")), "../");
        assert_eq!(root_of(std::path::Path::new("intro.md")), "");
    }
}
