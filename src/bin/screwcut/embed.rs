//! `screwcut embed`: a program as the HTML of a `<screwcut-preview>` with
//! its static drawings and pass table inside (what mdbook-screwcut writes
//! for a block), for any page.

use std::process::ExitCode;

use clap::Args;
use screwcut::Dialect;
use screwcut::element::{Options, render, views};
use screwcut::message::Lang;

/// The options of `screwcut embed`: the element's attributes.
#[derive(Args)]
pub struct EmbedArgs {
    /// Program file, or '-' for standard input.
    file: String,
    /// Controller dialect.
    #[arg(long, short, default_value = "gsk980tdc", value_parser = super::parse_dialect)]
    dialect: Dialect,
    /// Set a controller parameter or setting (repeatable); written into the element's `settings`.
    #[arg(long = "set", short = 's', value_name = "NAME=VALUE")]
    set: Vec<String>,
    /// The views, separated by commas: side, tooth, starts, table.
    #[arg(long, default_value = "side", value_parser = |s: &str| views(s).map(Views))]
    view: Views,
    /// Height of each drawing in CSS px (120–1200).
    #[arg(long, default_value_t = 320, value_parser = clap::value_parser!(u32).range(120..=1200))]
    height: u32,
    /// Width of the element on the page in px: the static drawings are laid out in it.
    #[arg(long, default_value_t = 800.0)]
    width: f64,
    /// Thread (1-based) of the tooth, starts and table views.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    thread: u32,
    /// Language of the labels: en or zh.
    #[arg(long, default_value = "en", value_parser = ["en", "zh"])]
    lang: String,
    /// A plain text editor under the drawings.
    #[arg(long)]
    editable: bool,
    /// Leave the program's listing out.
    #[arg(long)]
    hide_code: bool,
    /// Plan when scrolled near, not only when the reader points at the element.
    #[arg(long)]
    live: bool,
    /// The app "Open in editor" opens (http(s) or relative URL).
    #[arg(long, value_parser = screwcut::element::app_url)]
    app: Option<String>,
}

/// Views as the element lays them out (clap wants one type for the value).
#[derive(Clone)]
struct Views(Vec<&'static str>);

/// Writes the element to standard output and the program's alarms and
/// warnings to standard error (exit 0: a program with alarms is drawn too).
pub fn embed(a: EmbedArgs) -> ExitCode {
    let (_, text) = match super::input(&a.file, a.dialect, &a.set) {
        Ok(v) => v,
        Err(code) => return code,
    };
    if !(a.width.is_finite() && (120.0..=10_000.0).contains(&a.width)) {
        eprintln!("screwcut: --width {} is not a width in px from 120 to 10000", a.width);
        return ExitCode::from(2);
    }
    let o = Options {
        dialect: a.dialect,
        views: a.view.0,
        height: a.height,
        thread: a.thread as usize,
        settings: a.set,
        lang: Lang::parse(&a.lang).unwrap_or_default(),
        editable: a.editable,
        hide_code: a.hide_code,
        live: a.live,
        app: a.app,
    };
    let r = render(&text, &o, a.width);
    super::emit(&r.html);
    // The element drops the blank lines before the program: the file's lines are `leading` further.
    for d in &r.diagnostics {
        let line = d.line as usize + r.leading;
        eprintln!(
            "{}:{line}:{}: {} [{}] {}",
            a.file,
            d.column,
            d.severity.word().text(o.lang),
            d.code,
            d.render(o.lang)
        );
    }
    ExitCode::SUCCESS
}
