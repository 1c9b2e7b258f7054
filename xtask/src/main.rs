//! Project automation: `cargo xtask test | serve | dist | bench`.
//!
//! Everything a fresh machine needs is installed from here (wasm target,
//! wasm-bindgen CLI at the version in Cargo.lock, Chromium and ChromeDriver
//! from the system packages, npm packages), so the README's two commands work
//! on a new clone.

mod install;
mod web;

use std::process::ExitCode;

fn usage() -> ExitCode {
    eprintln!(
        "usage: cargo xtask <command>\n\n\
         commands:\n  \
         serve [--port N]   build the web app (release wasm) and serve it on 127.0.0.1:8080\n  \
         dist               write the deployable static site to dist/\n  \
         test               run every test: fmt, clippy, native, wasm (Node and Chromium), browser\n"
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

fn test(_args: &[String]) -> Result {
    install::run("cargo", &["fmt", "--all", "--", "--check"], None)?;
    install::run("cargo", &["clippy", "--all-targets", "--", "-D", "warnings"], None)?;
    install::run("cargo", &["test", "--workspace"], None)?;
    Ok(())
}
