//! `mdbook-screwcut`: an mdBook preprocessor. A fenced block
//!
//! ````text
//! ```screwcut dialect=fanuc0i view=side,tooth height=320
//! G00 X58 Z70
//! …
//! ```
//! ````
//!
//! becomes a live `<screwcut-preview>` with the static SVG of the same
//! drawings and the pass table inside it (the core's `element::render`,
//! which `screwcut embed` writes too), so the page shows the diagram before
//! its script loads, without JavaScript and in print, and the element loads
//! the planner when the reader points at it. Each block's alarms and warnings are printed at
//! build time with the chapter's file and line; `fail-on` can make them
//! fail the build. A bad option always fails it, naming the file and line.
//!
//! `book.toml`:
//!
//! ```toml
//! [preprocessor.screwcut]
//! element = "../../dist/element"   # the element's folder, from the book's root
//! assets = "screwcut"              # where in the sources it is copied (default)
//! width = 748                      # drawings' width in px (default: mdBook's column)
//! fail-on = "alarm"                # "alarm", "warning" or "never" (default)
//! ```

mod assets;
mod chapter;
mod options;

use std::process::ExitCode;

use mdbook_preprocessor::book::{Book, BookItem};
use mdbook_preprocessor::errors::Error;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};
use screwcut::Severity;

/// The preprocessor's settings from `[preprocessor.screwcut]`.
#[derive(serde::Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
struct Config {
    element: Option<std::path::PathBuf>,
    assets: Option<String>,
    width: Option<f64>,
    fail_on: Option<String>,
}

/// When the blocks' diagnostics fail the build.
#[derive(Clone, Copy, PartialEq, PartialOrd)]
enum FailOn {
    Warning,
    Alarm,
    Never,
}

struct Screwcut;

impl Preprocessor for Screwcut {
    fn name(&self) -> &str {
        "screwcut"
    }

    fn run(&self, ctx: &PreprocessorContext, mut book: Book) -> mdbook_preprocessor::errors::Result<Book> {
        let config: Config = ctx.config.get("preprocessor.screwcut")?.unwrap_or_default();
        let fail_on = match config.fail_on.as_deref() {
            None | Some("never") => FailOn::Never,
            Some("alarm") => FailOn::Alarm,
            Some("warning") => FailOn::Warning,
            Some(other) => {
                return Err(Error::msg(format!(
                    "preprocessor.screwcut.fail-on = \"{other}\": use \"alarm\", \"warning\" or \"never\""
                )));
            }
        };
        let width = config.width.unwrap_or(748.0);
        if !(200.0..=4000.0).contains(&width) {
            return Err(Error::msg(format!("preprocessor.screwcut.width = {width}: use 200 to 4000 px")));
        }
        let assets = config.assets.unwrap_or_else(|| "screwcut".into());
        if assets.is_empty() || assets.contains("..") || assets.starts_with('/') || assets.contains(['\'', '\\']) {
            return Err(Error::msg(format!(
                "preprocessor.screwcut.assets = \"{assets}\": use a folder name inside the book's sources"
            )));
        }
        let src = ctx.root.join(&ctx.config.book.src);
        let mut errors = Vec::new();
        let (mut blocks, mut failing) = (0, 0);
        book.for_each_mut(|item| {
            let BookItem::Chapter(ch) = item else { return };
            let file = ch.source_path.as_ref().map(|p| ctx.config.book.src.join(p));
            let file = file.map_or_else(|| ch.name.clone(), |f| f.display().to_string());
            let root = ch.path.as_deref().map(chapter::root_of).unwrap_or_default();
            match chapter::process(&ch.content, &root, &assets, width) {
                Ok(done) => {
                    blocks += done.blocks;
                    for s in &done.said {
                        let word = if s.severity == Severity::Error { "alarm" } else { "warning" };
                        eprintln!(
                            "mdbook-screwcut: {file}:{}:{}: {word} [{}] {} (chapter \"{}\")",
                            s.line, s.column, s.code, s.message, ch.name
                        );
                        let level = if s.severity == Severity::Error { FailOn::Alarm } else { FailOn::Warning };
                        failing += usize::from(level >= fail_on && fail_on != FailOn::Never);
                    }
                    ch.content = done.content;
                }
                Err(e) => errors.push(format!("{file}: {e} (chapter \"{}\")", ch.name)),
            }
        });
        if !errors.is_empty() {
            return Err(Error::msg(errors.join("\n")));
        }
        if failing > 0 {
            return Err(Error::msg(format!(
                "{failing} diagnostic(s) in the book's screwcut blocks (preprocessor.screwcut.fail-on = \"{}\")",
                config.fail_on.unwrap_or_default()
            )));
        }
        if blocks > 0 {
            let element = config
                .element
                .map(|e| ctx.root.join(e))
                .unwrap_or_else(|| ctx.root.join("node_modules/screwcut-preview"));
            let n = assets::copy_element(&element, &src.join(&assets)).map_err(Error::msg)?;
            if n > 0 {
                eprintln!("mdbook-screwcut: copied {n} file(s) of the element into {}", src.join(&assets).display());
            }
        }
        Ok(book)
    }

    fn supports_renderer(&self, renderer: &str) -> mdbook_preprocessor::errors::Result<bool> {
        Ok(renderer == "html")
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("supports") => {
            let ok = args.get(1).is_some_and(|r| Screwcut.supports_renderer(r).unwrap_or(false));
            if ok { ExitCode::SUCCESS } else { ExitCode::FAILURE }
        }
        Some("--version" | "-V") => {
            println!("mdbook-screwcut {}", env!("CARGO_PKG_VERSION"));
            ExitCode::SUCCESS
        }
        Some(other) => {
            eprintln!("usage: mdbook-screwcut [supports RENDERER] (run by mdbook; got '{other}')");
            ExitCode::from(2)
        }
        None => match run() {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("mdbook-screwcut: {e}");
                ExitCode::FAILURE
            }
        },
    }
}

/// Reads the book from standard input, writes it processed to standard output.
fn run() -> Result<(), Error> {
    let (ctx, book) = mdbook_preprocessor::parse_input(std::io::stdin())?;
    if ctx.mdbook_version.split('.').take(2).ne(mdbook_preprocessor::MDBOOK_VERSION.split('.').take(2)) {
        eprintln!(
            "mdbook-screwcut: warning: built for mdbook {}, run by mdbook {}",
            mdbook_preprocessor::MDBOOK_VERSION,
            ctx.mdbook_version
        );
    }
    let book = Screwcut.run(&ctx, book)?;
    serde_json::to_writer(std::io::stdout(), &book)?;
    Ok(())
}
