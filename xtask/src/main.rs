//! Project automation: `cargo xtask test | serve | dist | book | bench`.
//!
//! Everything a fresh machine needs is installed from here (wasm target,
//! wasm-bindgen CLI at the version in Cargo.lock, Chromium and ChromeDriver
//! and LinuxCNC's `rs274` from the Debian packages, mdBook at the version
//! of `mdbook-preprocessor` in Cargo.lock, npm packages including the
//! pinned binaryen and TypeScript),
//! so the README's two commands work on a new clone.

mod bench;
mod book;
mod first;
mod install;
mod package;
mod precompress;
mod server;
mod wasm;
mod web;

use std::process::ExitCode;

fn usage() -> ExitCode {
    eprintln!(
        "usage: cargo xtask <command>\n\n\
         commands:\n  \
         serve [--port N]   build the web app (release wasm) and serve it on 127.0.0.1:8080\n  \
         dist               write the deployable static site to dist/\n  \
         book [--port N]    build the example book (docs/book) with mdbook-screwcut and serve it\n  \
         test               run every test: fmt, clippy, native, wasm (Node and Chromium), browser\n  \
         test browser [F…]  only the browser tests (tests/browser/F, or all), on the site built as for test\n  \
         bench              print the performance figures: native throughput and memory, gcode-toolpath\n                     side by side, edit-to-frame and wasm plan time in Chromium, wasm size\n"
    );
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(cmd) = args.first() else { return usage() };
    let rest = &args[1..];
    let result = match cmd.as_str() {
        "serve" => web::serve(rest),
        "dist" => web::dist(rest),
        "test" => test(rest),
        "bench" => bench::bench(rest),
        "book" => book::book(rest),
        _ => return usage(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Error type of the tasks: a message.
pub type Result<T = ()> = std::result::Result<T, String>;

/// Every test, in the order that fails fastest: formatting and lints (Rust
/// and JavaScript), the native tests, the wasm tests (Node and headless Chromium), the browser test.
fn test(args: &[String]) -> Result {
    // `cargo xtask test browser [FILE…]`: only the browser tests (of
    // tests/browser/, all or those named), on a site built as for the whole run.
    if args.first().map(String::as_str) == Some("browser") {
        return web::browser_tests(&args[1..]);
    }
    if let Some(a) = args.first() {
        return Err(format!("test: unknown option '{a}' (usage: cargo xtask test [browser [FILE…]])"));
    }
    let started = std::time::Instant::now();
    let step = |name: &str| eprintln!("\n== {name} ({:.0} s)", started.elapsed().as_secs_f64());
    step("formatting");
    install::run("cargo", &["fmt", "--all", "--", "--check"], None)?;
    step("JavaScript: Biome's lints and formatting (www/biome.json)");
    let www = install::root().join("www");
    install::ensure_npm(&www)?;
    install::run("node", &["node_modules/@biomejs/biome/bin/biome", "check", "--error-on-warnings"], Some(&www))?;
    step("clippy (native and wasm32)");
    install::run("cargo", &["clippy", "--workspace", "--all-targets", "--", "-D", "warnings"], None)?;
    install::ensure_wasm_target()?;
    install::run("cargo", &["clippy", "--lib", "--target", "wasm32-unknown-unknown", "--", "-D", "warnings"], None)?;
    step("native tests");
    // LinuxCNC's interpreter is the oracle of tests/linuxcnc.rs.
    install::ensure_rs274()?;
    install::run("cargo", &["test", "--workspace"], None)?;
    step("wasm tests in Node and Chromium");
    web::wasm_tests()?;
    step("browser test");
    web::browser_tests(&[])?;
    step("all tests passed");
    Ok(())
}
