//! The app's page as a first visit sees it: the example it opens (o1006.nc)
//! written into `index.html`, its program and its three drawings as the
//! command line draws them, so that the first diagram is on screen with the
//! page itself while the app's script and wasm load behind it. The page
//! shows them only on a first visit (its inline script: no program kept, no
//! link), in the visitor's language (each is written in English and in
//! Chinese), and the app takes them away when its own drawings come. The
//! page's own words (texts, titles, placeholders) are in the visitor's
//! language from its first paint too: its script takes them from a table
//! written in here.

use std::path::Path;
use std::process::Command;

use crate::Result;
use crate::install::root;
use crate::web::{command_line, path_str};

/// The example a first visit opens (www/src/app/main.js).
const EXAMPLE: &str = "o1006.nc";

/// Each drawing's placeholder in `www/static/index.html`, its view, the
/// size it is laid out at and its class: the app's canvases in a 1400 × 900
/// window, and the side section's on a phone (390 wide: `narrow`, which the
/// stylesheet shows below 520 px instead of the other). Each scales to the
/// window's canvas, keeping its proportions.
const VIEWS: [(&str, &str, f64, f64, &str); 4] = [
    ("<!--first:side-->", "side", 882.0, 250.0, "first wide"),
    ("<!--first:side-narrow-->", "side", 376.0, 238.0, "first narrow"),
    ("<!--first:tooth-->", "tooth", 437.0, 173.0, "first"),
    ("<!--first:starts-->", "starts", 437.0, 173.0, "first"),
];

/// The program's placeholder (in the editor's place).
const CODE: &str = "<!--first:code-->";

/// The placeholder of the page's words in English and Chinese, in its
/// script that writes them in the visitor's language on a first visit.
const WORDS: &str = "/*first:words*/null";

/// The attributes by which the page names its words: keys of the app's
/// page texts (www/src/shared/i18n.js, which its `setLang` fills in), and
/// of the program library's (www/src/app/programs.js, which sets them).
const PAGE_WORDS: [&str; 3] = ["data-i18n", "data-i18n-title", "data-i18n-placeholder"];
const PROGRAM_WORDS: [&str; 2] = ["data-program-word", "data-program-title"];

/// Writes the example's program and drawings into `out/index.html` (the
/// built site's page), drawn by the command line of this tree, and the
/// English and Chinese text of the words the page names.
pub fn write_first_visit(out: &Path) -> Result {
    let examples = root().join("examples");
    let index =
        std::fs::read_to_string(examples.join("index.json")).map_err(|e| format!("examples/index.json: {e}"))?;
    let dialect = dialect_of(&index, EXAMPLE)?;
    let file = examples.join(EXAMPLE);
    let program = std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
    let cli = command_line()?;
    let page_path = out.join("index.html");
    let mut page = std::fs::read_to_string(&page_path).map_err(|e| format!("{}: {e}", page_path.display()))?;
    let path = path_str(&file)?;
    for (mark, view, width, height, class) in VIEWS {
        let (w, h) = (width.to_string(), height.to_string());
        // One drawing a language the app speaks; the page's script shows the visitor's.
        let mut html = String::new();
        for lang in ["en", "zh"] {
            let mut args = vec![
                "svg",
                &path,
                "--dialect",
                &dialect,
                "--view",
                view,
                "--width",
                &w,
                "--height",
                &h,
                "--lang",
                lang,
            ];
            if view == "side" {
                args.push("--stretch"); // as the app shows it (www/src/app/main.js binds the side view stretched)
            }
            let svg = draw(&cli, &args)?;
            let svg: Vec<&str> = svg.lines().filter(|l| !l.starts_with("<?xml")).collect();
            html += &format!("<div class=\"{class} {lang}\" aria-hidden=\"true\">{}</div>", svg.join("\n"));
        }
        page = replace_once(&page, mark, &html)?;
    }
    // A span a line, numbered by the stylesheet as the editor numbers them.
    let lines: Vec<String> = program.split('\n').map(|l| format!("<span>{}</span>", escape(l))).collect();
    let code = format!("<pre class=\"first\" aria-hidden=\"true\">{}</pre>", lines.join("\n"));
    page = replace_once(&page, CODE, &code)?;
    let mut page_keys = vec!["title".to_string()];
    page_keys.extend(word_keys(&page, &PAGE_WORDS));
    let words = page_words(&page_keys, &word_keys(&page, &PROGRAM_WORDS))?;
    page = replace_once(&page, WORDS, &words)?;
    std::fs::write(&page_path, page).map_err(|e| format!("{}: {e}", page_path.display()))
}

/// The keys the page names by `attributes` (each once, in order).
fn word_keys(page: &str, attributes: &[&str]) -> Vec<String> {
    let mut keys: Vec<String> = Vec::new();
    for attribute in attributes {
        let mark = format!(" {attribute}=\"");
        for (at, _) in page.match_indices(&mark) {
            let rest = &page[at + mark.len()..];
            let key = &rest[..rest.find('"').unwrap_or(0)];
            if !key.is_empty() && !keys.iter().any(|k| k == key) {
                keys.push(key.to_string());
            }
        }
    }
    keys
}

/// The English and Chinese text of each key as the app's own tables have
/// them (node reads www/src/shared/i18n.js for `page`, and
/// www/src/app/programs.js, which takes its language from the document's,
/// for `programs`), as a JavaScript object (`{"en": {"page": {key: text},
/// "programs": …}, "zh": …}`) safe inside `<script>`.
fn page_words(page: &[String], programs: &[String]) -> Result<String> {
    if let Some(k) = page.iter().chain(programs).find(|k| !k.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')) {
        return Err(format!("www/static/index.html names a word \"{k}\": keys are letters, digits and _"));
    }
    let list = |keys: &[String]| format!("[{}]", keys.iter().map(|k| format!("\"{k}\"")).collect::<Vec<_>>().join(","));
    let read = "globalThis.document = { documentElement: { lang: 'en' } }; \
        const { textIn } = await import('./src/shared/i18n.js'); \
        const { tr } = await import('./src/app/programs.js'); \
        const [page, programs] = [JSON.parse(process.argv[1]), JSON.parse(process.argv[2])]; \
        const table = (lang) => { document.documentElement.lang = lang; return { \
          page: Object.fromEntries(page.map((k) => [k, textIn(lang, k)])), \
          programs: Object.fromEntries(programs.map((k) => [k, tr(k)])) }; }; \
        process.stdout.write(JSON.stringify({ en: table('en'), zh: table('zh') }));";
    let out = Command::new("node")
        .args(["--input-type=module", "-e", read, &list(page), &list(programs)])
        .current_dir(root().join("www"))
        .output()
        .map_err(|e| format!("cannot run node: {e}"))?;
    if !out.status.success() {
        return Err(format!("node could not read the page's words: {}", String::from_utf8_lossy(&out.stderr)));
    }
    let json = String::from_utf8(out.stdout).map_err(|e| format!("node wrote no UTF-8: {e}"))?;
    Ok(json.replace("</", "<\\/"))
}

/// The command line's SVG: its standard output, or why there is none.
fn draw(cli: &Path, args: &[&str]) -> Result<String> {
    let out = Command::new(cli).args(args).output().map_err(|e| format!("cannot run {}: {e}", cli.display()))?;
    if !out.status.success() {
        return Err(format!("screwcut {} failed: {}", args.join(" "), String::from_utf8_lossy(&out.stderr)));
    }
    String::from_utf8(out.stdout).map_err(|e| format!("screwcut svg wrote no UTF-8: {e}"))
}

/// `page` with its one `mark` replaced by `with`.
fn replace_once(page: &str, mark: &str, with: &str) -> Result<String> {
    match page.matches(mark).count() {
        1 => Ok(page.replacen(mark, with, 1)),
        n => Err(format!("www/static/index.html has {n} of {mark}, not one")),
    }
}

/// The `dialect` of the entry for `file` in `examples/index.json` (one
/// object per example, the file named before its dialect).
fn dialect_of(index: &str, file: &str) -> Result<String> {
    let at = index.find(&format!("\"{file}\"")).ok_or(format!("examples/index.json does not list {file}"))?;
    let entry = &index[at..index[at..].find('}').map_or(index.len(), |e| at + e)];
    let key = entry.find("\"dialect\"").ok_or(format!("examples/index.json: {file} has no dialect"))?;
    let value =
        entry[key + 9..].split('"').nth(1).ok_or(format!("examples/index.json: {file}'s dialect has no value"))?;
    Ok(value.to_string())
}

/// Text as HTML element content.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_dialect_is_the_named_entrys() {
        let index =
            r#"[{"file": "a.nc", "dialect": "fanuc0itf"}, {"file": "o1006.nc", "dialect": "gsk980tdc", "title": "x"}]"#;
        assert_eq!(dialect_of(index, "o1006.nc").unwrap(), "gsk980tdc");
        assert_eq!(dialect_of(index, "a.nc").unwrap(), "fanuc0itf");
        assert!(dialect_of(index, "b.nc").is_err());
    }

    #[test]
    fn the_page_names_its_words_by_key() {
        let page = r#"<b data-i18n="passes">Passes</b><button data-i18n="open" data-i18n-title="open_help">Open</button>
            <input data-i18n-placeholder="find"><i data-i18n="passes">Passes</i><p data-i18n-x="no">"#;
        assert_eq!(word_keys(page, &PAGE_WORDS), ["passes", "open", "open_help", "find"]);
        let page = r#"<span data-program-word="programs"></span><button data-program-word="new" data-program-title="new_title">"#;
        assert_eq!(word_keys(page, &PROGRAM_WORDS), ["programs", "new", "new_title"]);
    }

    #[test]
    fn a_mark_is_replaced_once_or_refused() {
        assert_eq!(replace_once("a<!--m-->b", "<!--m-->", "X").unwrap(), "aXb");
        assert!(replace_once("ab", "<!--m-->", "X").is_err());
        assert!(replace_once("<!--m--><!--m-->", "<!--m-->", "X").is_err());
    }
}
