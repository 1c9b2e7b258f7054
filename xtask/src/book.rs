//! The example book (`docs/book/`) built with mdBook and the project's
//! preprocessor `mdbook-screwcut`, and the preprocessor's build-time
//! behaviour checked on scratch books: a block's alarm printed with the
//! chapter's file and line (and failing the build when `fail-on` asks), a
//! bad option failing the build with a clear message.

use std::path::Path;
use std::process::Command;

use crate::Result;
use crate::install::{locked_version, output, root, run};

/// `cargo xtask book [--port N]`: builds the site's element (release), the
/// example book with it into `target/book/`, and serves the book.
pub fn book(args: &[String]) -> Result {
    let port = match args {
        [] => 8080,
        [flag, n] if flag == "--port" => n.parse().map_err(|_| format!("book: '{n}' is not a port number"))?,
        _ => return Err("usage: cargo xtask book [--port N]".into()),
    };
    let target = crate::web::target_dir()?;
    let site = target.join("site");
    crate::web::build_site(true, &site)?;
    let element = site.join("element");
    crate::web::write_element_package(&site, &element)?;
    let out = target.join("book");
    build_example(&element, &out)?;
    let server = crate::server::bind(port)?;
    eprintln!("serving the example book {} on http://127.0.0.1:{port}/ (Ctrl-C to stop)", out.display());
    crate::server::serve_forever(server, out);
    Ok(())
}

/// Installs mdBook at the version of the `mdbook-preprocessor` crate in
/// Cargo.lock (the preprocessor speaks that version's JSON) unless
/// `mdbook --version` already answers with it.
pub fn ensure_mdbook() -> Result {
    let want = locked_version("mdbook-preprocessor")?;
    let have = output("mdbook", &["--version"]).unwrap_or_default();
    if have.trim().trim_start_matches("mdbook v") == want {
        return Ok(());
    }
    run("cargo", &["install", "mdbook", "--version", &want, "--force"], None)
}

/// What one `mdbook build` did: its exit and what it printed.
pub struct Built {
    /// The build succeeded.
    pub ok: bool,
    /// Its standard error (the preprocessor's messages).
    pub stderr: String,
}

/// Builds the book at `book` into `out` with the debug build of the
/// preprocessor and the element's folder `element`.
pub fn mdbook_build(book: &Path, out: &Path, element: &Path) -> Result<Built> {
    let bin = crate::web::target_dir()?.join("debug");
    let path = std::env::join_paths(
        std::iter::once(bin).chain(std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())),
    )
    .map_err(|e| format!("PATH: {e}"))?;
    eprintln!("$ mdbook build {} -d {}", book.display(), out.display());
    let o = Command::new("mdbook")
        .args(["build", "-d"])
        .arg(out)
        .current_dir(book)
        .env("PATH", path)
        .env("MDBOOK_PREPROCESSOR__SCREWCUT__ELEMENT", element)
        .output()
        .map_err(|e| format!("cannot run mdbook: {e}"))?;
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    eprint!("{stderr}");
    Ok(Built { ok: o.status.success(), stderr })
}

/// Builds the example book into `out` with the element of `element`;
/// fails when the build fails or a block has an alarm (its warnings are
/// printed: the book shows what the checks say).
pub fn build_example(element: &Path, out: &Path) -> Result {
    ensure_mdbook()?;
    run("cargo", &["build", "--package", "mdbook-screwcut"], None)?;
    let b = mdbook_build(&root().join("docs").join("book"), out, element)?;
    if !b.ok {
        return Err("the example book did not build".into());
    }
    // book.toml has fail-on = "alarm": a block with an alarm failed the build above.
    if b.stderr.contains(": alarm [") {
        return Err("a block of the example book has an alarm (listed above)".into());
    }
    Ok(())
}

/// A scratch book with one chapter, `fail-on` as given.
fn scratch(dir: &Path, chapter: &str, fail_on: &str) -> Result {
    let _ = std::fs::remove_dir_all(dir);
    let src = dir.join("src");
    std::fs::create_dir_all(&src).map_err(|e| format!("{}: {e}", src.display()))?;
    let toml = format!("[book]\ntitle = \"scratch\"\n\n[preprocessor.screwcut]\nfail-on = \"{fail_on}\"\n");
    for (file, text) in [
        (dir.join("book.toml"), toml.as_str()),
        (src.join("SUMMARY.md"), "# Summary\n\n- [Checks](checks.md)\n"),
        (src.join("checks.md"), chapter),
    ] {
        std::fs::write(&file, text).map_err(|e| format!("{}: {e}", file.display()))?;
    }
    Ok(())
}

/// The preprocessor at build time, on scratch books: an alarm printed with
/// the chapter's file, line and column (the build goes on with `fail-on =
/// "never"`, stops with `"alarm"`); a bad option stops the build naming
/// the file, the line and the option.
pub fn check_build_messages(element: &Path, scratch_dir: &Path) -> Result {
    // Line 5 is the fence; the program's line 3 (G32 with no lead: the GSK's alarm) is the chapter's line 8.
    let alarm = "# Checks\n\nA pass with no lead.\n\n```screwcut dialect=gsk980tdc\nG00 X58 Z70\nX47.1\nG32 Z13\n```\n";
    let out = scratch_dir.join("out");
    let mut failures = Vec::new();
    let mut check = |name: &str, ok: bool, detail: &str| {
        eprintln!("{} {name}", if ok { "ok  " } else { "FAIL" });
        if !ok {
            failures.push(format!("{name}: {detail}"));
        }
    };
    scratch(scratch_dir, alarm, "never")?;
    let b = mdbook_build(scratch_dir, &out, element)?;
    let line = "mdbook-screwcut: src/checks.md:8:1: alarm [";
    check(
        "an alarm is printed with the chapter's file and line; the build goes on",
        b.ok && b.stderr.contains(line),
        &b.stderr,
    );
    check("… and the chapter's title", b.stderr.contains("(chapter \"Checks\")"), &b.stderr);
    scratch(scratch_dir, alarm, "alarm")?;
    let b = mdbook_build(scratch_dir, &out, element)?;
    check(
        "with fail-on = \"alarm\" the alarm fails the build",
        !b.ok && b.stderr.contains(line) && b.stderr.contains("1 diagnostic(s) in the book's screwcut blocks"),
        &b.stderr,
    );
    let bad = "# Checks\n\n```screwcut dialect=fanuc0i view=side,front\nG00 X58. Z70.\n```\n";
    scratch(scratch_dir, bad, "never")?;
    let b = mdbook_build(scratch_dir, &out, element)?;
    check(
        "a bad option fails the build, naming the file, the line and the option",
        !b.ok
            && b.stderr.contains(
                "src/checks.md: line 3: ```screwcut block: unknown view 'front' (known: side, tooth, starts, table)",
            ),
        &b.stderr,
    );
    if failures.is_empty() { Ok(()) } else { Err(failures.join("\n")) }
}
