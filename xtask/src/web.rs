//! Building, bundling and serving the web app.
//!
//! The site is: `index.html` (with the example a first visit opens written
//! in: `crate::first`), `docs.html` and the other files of
//! `www/static/`, `app.js` (the app bundled by esbuild, with the
//! wasm-bindgen glue), `worker.js` (its planning and drawing worker),
//! `screwcut-preview.js` (the embeddable
//! `<screwcut-preview>` element, bundled the same way without the editor),
//! `screwcut_bg.wasm` (the core, size-optimised by the binaryen pinned in
//! `www/package.json`; shared by both bundles), `screwcut_tools_bg.wasm`
//! (the program-writing tools, which the app loads when first used; see
//! `crate::wasm`) and `examples/` (every file
//! listed in `examples/index.json`). `cargo xtask dist` adds `element/`, the element
//! as a folder a documentation site can vendor: the element, and the app its
//! "Open in editor" link opens by default.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::install::{ensure_chromium, ensure_npm, ensure_wasm_bindgen, ensure_wasm_target, output, root, run};
use crate::wasm::WasmOpt;
use crate::{Result, server};

/// Default port of `cargo xtask serve`.
pub const DEFAULT_PORT: u16 = 8080;

/// `cargo xtask serve [--port N]`: builds the site (release wasm) and serves it on 127.0.0.1.
pub fn serve(args: &[String]) -> Result {
    let mut port = DEFAULT_PORT;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--port" | "-p" => {
                let v = it.next().ok_or("--port needs a number")?;
                port = v.parse().map_err(|_| format!("--port: '{v}' is not a port number"))?;
            }
            s if s.starts_with("--port=") => {
                let v = &s["--port=".len()..];
                port = v.parse().map_err(|_| format!("--port: '{v}' is not a port number"))?;
            }
            other => return Err(format!("serve: unknown option '{other}' (usage: cargo xtask serve [--port N])")),
        }
    }
    let out = target_dir()?.join("site");
    build_site(true, &out)?;
    // docs.html links to the element's README in its folder.
    write_element_package(&out, &out.join("element"))?;
    let server = server::bind(port)?;
    eprintln!("serving {} on http://127.0.0.1:{port}/ (Ctrl-C to stop)", out.display());
    server::serve_forever(server, out);
    Ok(())
}

/// `cargo xtask dist`: writes the deployable static site to `dist/`.
pub fn dist(args: &[String]) -> Result {
    if let Some(a) = args.first() {
        return Err(format!("dist: unknown option '{a}' (usage: cargo xtask dist)"));
    }
    let out = root().join("dist");
    let opt = build_site(true, &out)?;
    let element = out.join("element");
    write_element_package(&out, &element)?;
    eprintln!("wrote the site to {} and the embeddable element to {}", out.display(), element.display());
    eprintln!("dist: the wasm is {opt}");
    match opt {
        WasmOpt::Optimised { .. } => Ok(()),
        WasmOpt::Skipped(why) => {
            Err(format!("dist: the wasm was not size-optimised ({why}); dist/ is not the measured build"))
        }
    }
}

/// The files of the element's folder: the bundle and the wasm from the
/// built site `site`, a package.json and the README of `www/element/`.
pub const ELEMENT_FILES: [&str; 4] = ["screwcut-preview.js", "screwcut_bg.wasm", "package.json", "README.md"];

/// The app, copied from the built site into the element's folder with its
/// `examples/`: the "Open in editor" link opens the app next to the script
/// by default, so the link works wherever the folder is copied (the app
/// shares the element's wasm; its tools module is the app's alone).
pub const APP_FILES: [&str; 9] = [
    "index.html",
    "app.js",
    "worker.js",
    "style.css",
    "favicon.svg",
    "screwcut_tools_bg.wasm",
    "screwcut_tools.js",
    "wizard.js",
    "page-engine.js",
];

/// Writes `dir` (emptied first) as the vendorable element package, from the built site `site`.
pub fn write_element_package(site: &Path, dir: &Path) -> Result {
    if dir.exists() {
        std::fs::remove_dir_all(dir).map_err(|e| format!("cannot empty {}: {e}", dir.display()))?;
    }
    std::fs::create_dir_all(dir.join("examples")).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    for f in ELEMENT_FILES[..2].iter().chain(&APP_FILES) {
        copy(&site.join(f), &dir.join(f))?;
    }
    let index = read(&site.join("examples").join("index.json"))?;
    for f in example_files(&index)?.iter().map(String::as_str).chain(["index.json"]) {
        copy(&site.join("examples").join(f), &dir.join("examples").join(f))?;
    }
    let version = crate_version(&read(&root().join("Cargo.toml"))?)?;
    write(&dir.join("package.json"), &element_package_json(&version))?;
    copy(&root().join("www").join("element").join("README.md"), &dir.join("README.md"))?;
    copy(&root().join("www").join("element").join("screwcut-preview.d.ts"), &dir.join("screwcut-preview.d.ts"))?;
    for licence in ["LICENSE-MIT", "LICENSE-APACHE"] {
        copy(&root().join(licence), &dir.join(licence))?;
    }
    for f in ELEMENT_FILES[..2].iter().chain(&APP_FILES[1..3]) {
        let size = std::fs::metadata(dir.join(f)).map(|m| m.len()).unwrap_or(0);
        eprintln!("element: {f} {} KiB", size.div_ceil(1024));
    }
    Ok(())
}

/// The `version` of the `[package]` table of a Cargo.toml.
fn crate_version(manifest: &str) -> Result<String> {
    let package = manifest.split("\n[").next().unwrap_or(manifest);
    package
        .lines()
        .find_map(|l| {
            l.trim().strip_prefix("version").map(|v| v.trim_start().trim_start_matches('=').trim().trim_matches('"'))
        })
        .map(str::to_string)
        .ok_or_else(|| "Cargo.toml: no package version".to_string())
}

/// The package.json of the element folder.
fn element_package_json(version: &str) -> String {
    // The app's files as APP_FILES lists them (copied beside the element by `write_element_package`).
    let app = APP_FILES.map(|f| format!("\"{f}\"")).join(", ");
    format!(
        r#"{{
  "name": "screwcut-preview",
  "version": "{version}",
  "description": "<screwcut-preview>: a live diagram of CNC lathe thread-cutting G-code (GSK980TDc, Fanuc 0i, Renhe, LinuxCNC) for documentation pages",
  "license": "MIT OR Apache-2.0",
  "type": "module",
  "main": "screwcut-preview.js",
  "module": "screwcut-preview.js",
  "types": "screwcut-preview.d.ts",
  "exports": {{
    ".": {{
      "types": "./screwcut-preview.d.ts",
      "default": "./screwcut-preview.js"
    }},
    "./screwcut_bg.wasm": "./screwcut_bg.wasm",
    "./app": "./index.html",
    "./package.json": "./package.json"
  }},
  "files": ["screwcut-preview.js", "screwcut-preview.d.ts", "screwcut_bg.wasm", "README.md", "LICENSE-MIT", "LICENSE-APACHE", {app}, "examples/"],
  "sideEffects": true,
  "keywords": ["cnc", "lathe", "g-code", "thread", "web-component", "custom-element", "wasm"]
}}
"#
    )
}

/// Lints the wasm-bindgen tests of the binding layer (`src/wasm/tests/`) and
/// runs them twice from the library's wasm32 test binary: in Node, then in
/// headless Chromium through ChromeDriver from the system packages (options
/// in `webdriver.json`). Both runs print their results and pass counts.
pub fn wasm_tests() -> Result {
    ensure_wasm_target()?;
    ensure_wasm_bindgen()?;
    // The tests are wasm32-only code that the native clippy run never sees.
    run(
        "cargo",
        &["clippy", "--target", "wasm32-unknown-unknown", "--lib", "--profile", "test", "--", "-D", "warnings"],
        None,
    )?;
    let node = wasm_test_run("Node", &[])?;
    ensure_chromium()?;
    eprintln!("browser: {}", chromium_version());
    let driver = root().join("webdriver.json");
    let browser = wasm_test_run(
        "Chromium",
        &[
            ("WASM_BINDGEN_USE_BROWSER", "1"),
            ("CHROMEDRIVER", "/usr/bin/chromedriver"),
            ("WASM_BINDGEN_TEST_WEBDRIVER_JSON", &path_str(&driver)?),
        ],
    )?;
    eprintln!("wasm tests: {node} passed in Node, {browser} passed in Chromium");
    Ok(())
}

/// What `/usr/bin/chromium --version` prints, for the test log.
pub fn chromium_version() -> String {
    output("/usr/bin/chromium", &["--version"])
        .map_or_else(|| "unknown (chromium --version failed)".into(), |v| v.trim().into())
}

/// `cargo test --target wasm32-unknown-unknown --lib wasm::` under
/// wasm-bindgen-test-runner with `env`; echoes the output and returns the
/// number of tests that passed (an error when any failed or none ran).
fn wasm_test_run(place: &str, env: &[(&str, &str)]) -> Result<u32> {
    let args = ["test", "--target", "wasm32-unknown-unknown", "--lib", "wasm::"];
    let shown: Vec<String> = env.iter().map(|(k, v)| format!("{k}={v} ")).collect();
    eprintln!("$ {}cargo {}   ({place})", shown.concat(), args.join(" "));
    let mut child = Command::new("cargo")
        .args(args)
        .env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER", "wasm-bindgen-test-runner")
        .envs(env.iter().copied())
        .current_dir(root())
        .stdout(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let mut passed = 0;
    if let Some(out) = child.stdout.take() {
        for line in BufReader::new(out).lines().map_while(std::result::Result::ok) {
            println!("{line}");
            if let Some(n) = passed_count(&line) {
                passed += n;
            }
        }
    }
    let status = child.wait().map_err(|e| format!("cargo test: {e}"))?;
    if !status.success() {
        return Err(format!("wasm tests in {place} failed ({status})"));
    }
    if passed == 0 {
        return Err(format!("no wasm test ran in {place}"));
    }
    Ok(passed)
}

/// The pass count of a libtest summary line (`test result: ok. 27 passed; ...`).
fn passed_count(line: &str) -> Option<u32> {
    let rest = line.trim().strip_prefix("test result: ")?;
    let (_, counts) = rest.split_once(". ")?;
    counts.split_once(" passed")?.0.trim().parse().ok()
}

/// Builds the site (with `element/`, as `cargo xtask dist` writes it),
/// serves it on a free local port and runs the Playwright tests in
/// `tests/browser/` against it with the system Chromium: the app
/// (`test.mjs`), its engine in a worker and on the page and a program too
/// big to draw whole (`engine.test.mjs`), the documentation page of
/// embedded previews (`docs.test.mjs`), hostile links, the program
/// list and the element's guards (`safety.test.mjs`), the keyboard, a
/// phone's screen and Chinese (`access.test.mjs`), then the drawings' labels
/// in the app and in embeds, English and Chinese (`labels.test.mjs`), and
/// the thread wizard and "Expand to blocks" (`tools.test.mjs`), and a
/// program with subprograms: passes and diagnostics with their calls
/// (`calls.test.mjs`), what a new user hits (`newuser.test.mjs`), and
/// "Compare with…" (`compare.test.mjs`), and the example book built by
/// mdBook with `mdbook-screwcut`: live, without JavaScript, in print
/// (`book.test.mjs`), and the element installed from its npm package
/// (`package.test.mjs`);
/// fails when any fails.
pub fn browser_tests(only: &[String]) -> Result {
    let all = [
        "test.mjs",
        "engine.test.mjs",
        "docs.test.mjs",
        "safety.test.mjs",
        "access.test.mjs",
        "labels.test.mjs",
        "tools.test.mjs",
        "calls.test.mjs",
        "newuser.test.mjs",
        "first.test.mjs",
        "compare.test.mjs",
        "book.test.mjs",
        "package.test.mjs",
    ];
    if let Some(unknown) = only.iter().find(|o| !all.contains(&o.as_str())) {
        return Err(format!("test browser: no test file '{unknown}' (known: {})", all.join(", ")));
    }
    let chosen: Vec<&str> = all.into_iter().filter(|t| only.is_empty() || only.iter().any(|o| o == t)).collect();
    ensure_chromium()?;
    let out = target_dir()?.join("site-test");
    if let WasmOpt::Skipped(why) = build_site(true, &out)? {
        return Err(format!("the wasm under test was not size-optimised as a release is ({why})"));
    }
    write_element_package(&out, &out.join("element"))?;
    // The example book, served beside the site, and the preprocessor's build-time messages.
    crate::book::build_example(&out.join("element"), &out.join("book"))?;
    crate::book::check_build_messages(&out.join("element"), &target_dir()?.join("book-scratch"))?;
    // The element as an npm package, installed into a page served at pkg-scratch/.
    ensure_npm(&root().join("tests").join("browser"))?;
    crate::package::pack_and_install(&out.join("element"), &out.join("pkg-scratch"))?;
    let dir = root().join("tests").join("browser");
    ensure_npm(&dir)?;
    let server = server::bind(0)?;
    let port = server::port(&server)?;
    std::thread::spawn(move || server::serve_forever(server, out));
    let url = format!("http://127.0.0.1:{port}/");
    // The app's SVG export is compared with the command line's (test.mjs),
    // the one the site was built with (its first visit's drawings).
    let cli = path_str(&command_line()?)?;
    // Each file runs even when one before it failed; the first failure is returned.
    let runs: Vec<Result> = chosen
        .into_iter()
        .map(|t| {
            if t == "test.mjs" {
                run("node", &[t, &url, &cli], Some(&dir))
            } else {
                run("node", &[t, &url], Some(&dir))
            }
        })
        .collect();
    runs.into_iter().collect::<Result<Vec<()>>>().map(|_| ())
}

/// Builds the site into `out` (emptied first): the two wasm modules
/// (release or debug, with their wasm-bindgen glue and wasm-opt for a
/// release build: `crate::wasm`), the esbuild bundles, static files and
/// examples. Says, and returns, what wasm-opt did.
pub fn build_site(release: bool, out: &Path) -> Result<WasmOpt> {
    let www = root().join("www");
    let pkg = www.join("pkg");
    // The bundler, and wasm-opt for the modules, are the front end's npm packages.
    ensure_npm(&www)?;
    let opt = crate::wasm::build_modules(release, &pkg)?;
    if out.exists() {
        std::fs::remove_dir_all(out).map_err(|e| format!("cannot empty {}: {e}", out.display()))?;
    }
    std::fs::create_dir_all(out.join("examples")).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let esbuild = path_str(&www.join("node_modules").join(".bin").join("esbuild"))?;
    // The bundles: the app, its worker, the element; and what the app and
    // its worker fetch on first use (each bundled whole, so that a first
    // diagram waits for no shared chunk): the tools' glue, the dialogs, the
    // page's own planner (`?engine=page`, or no worker).
    let entries = [
        ("src/app/main.js", "app.js"),
        ("src/engine/worker.js", "worker.js"),
        ("src/embed/element.js", "screwcut-preview.js"),
        ("pkg/screwcut_tools.js", "screwcut_tools.js"),
        ("src/app/wizard.js", "wizard.js"),
        ("src/engine/page.js", "page-engine.js"),
    ];
    for (entry, file) in entries {
        let outfile = format!("--outfile={}", path_str(&out.join(file))?);
        let mut args = vec![entry, "--bundle", "--format=esm", "--target=es2022", "--charset=utf8", &outfile];
        if release {
            args.push("--minify");
        } else {
            args.push("--sourcemap");
        }
        run(&esbuild, &args, Some(&www))?;
    }
    for m in crate::wasm::MODULES {
        copy(&pkg.join(m.wasm_file()), &out.join(m.wasm_file()))?;
    }
    let statics = www.join("static");
    for entry in std::fs::read_dir(&statics).map_err(|e| format!("{}: {e}", statics.display()))? {
        let entry = entry.map_err(|e| e.to_string())?;
        if entry.path().is_file() {
            copy(&entry.path(), &out.join(entry.file_name()))?;
        }
    }
    crate::first::write_first_visit(out)?;
    let examples = root().join("examples");
    let index = read(&examples.join("index.json"))?;
    for file in example_files(&index)? {
        copy(&examples.join(&file), &out.join("examples").join(&file))?;
    }
    copy(&examples.join("index.json"), &out.join("examples").join("index.json"))?;
    crate::precompress::precompress(out)?;
    let size = |f: &str| std::fs::metadata(out.join(f)).map(|m| m.len().div_ceil(1024)).unwrap_or(0);
    let gz = |f: &str| crate::precompress::gz_size(&out.join(f)).div_ceil(1024);
    let br = |f: &str| crate::precompress::br_size(&out.join(f)).div_ceil(1024);
    eprintln!(
        "site: {} (KiB raw/gzip/brotli: wasm {}/{}/{}, tools wasm {}/{}/{}; app.js {}/{}/{}; screwcut-preview.js {}/{}/{})\nwasm: {opt}",
        out.display(),
        size("screwcut_bg.wasm"),
        gz("screwcut_bg.wasm"),
        br("screwcut_bg.wasm"),
        size("screwcut_tools_bg.wasm"),
        gz("screwcut_tools_bg.wasm"),
        br("screwcut_tools_bg.wasm"),
        size("app.js"),
        gz("app.js"),
        br("app.js"),
        size("screwcut-preview.js"),
        gz("screwcut-preview.js"),
        br("screwcut-preview.js")
    );
    Ok(opt)
}

/// The `file` entries of `examples/index.json`, checked to be plain file names.
fn example_files(index: &str) -> Result<Vec<String>> {
    let mut files = Vec::new();
    let mut rest = index;
    while let Some(at) = rest.find("\"file\"") {
        rest = &rest[at + 6..];
        let open = rest.find('"').ok_or("examples/index.json: a \"file\" without a value")?;
        let value = &rest[open + 1..];
        let close = value.find('"').ok_or("examples/index.json: unterminated file name")?;
        let name = &value[..close];
        if name.is_empty() || name.contains(['/', '\\']) || name.starts_with('.') {
            return Err(format!("examples/index.json: '{name}' is not a plain file name"));
        }
        files.push(name.to_string());
        rest = &value[close + 1..];
    }
    if files.is_empty() {
        return Err("examples/index.json lists no files".into());
    }
    Ok(files)
}

/// The command line `screwcut` of this tree (a debug build), built if it is not up to date.
pub fn command_line() -> Result<PathBuf> {
    run("cargo", &["build", "--quiet", "--package", "screwcut", "--bin", "screwcut"], None)?;
    Ok(target_dir()?.join("debug").join("screwcut"))
}

/// Cargo's target directory: `CARGO_TARGET_DIR`, else what `cargo metadata` says.
pub fn target_dir() -> Result<PathBuf> {
    if let Some(dir) = std::env::var_os("CARGO_TARGET_DIR").filter(|d| !d.is_empty()) {
        let dir = PathBuf::from(dir);
        return Ok(if dir.is_absolute() { dir } else { root().join(dir) });
    }
    let out = Command::new("cargo")
        .args(["metadata", "--format-version", "1", "--no-deps"])
        .current_dir(root())
        .output()
        .map_err(|e| format!("cannot run cargo metadata: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let key = "\"target_directory\":\"";
    let at = text.find(key).ok_or("cargo metadata gave no target_directory")? + key.len();
    let end = text[at..].find('"').ok_or("cargo metadata: bad target_directory")?;
    Ok(PathBuf::from(text[at..at + end].replace("\\\\", "\\")))
}

pub fn path_str(p: &Path) -> Result<String> {
    p.to_str().map(str::to_string).ok_or_else(|| format!("path is not UTF-8: {}", p.display()))
}

fn read(p: &Path) -> Result<String> {
    std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))
}

fn write(p: &Path, text: &str) -> Result {
    std::fs::write(p, text).map_err(|e| format!("{}: {e}", p.display()))
}

fn copy(from: &Path, to: &Path) -> Result {
    std::fs::copy(from, to).map(|_| ()).map_err(|e| format!("cannot copy {} to {}: {e}", from.display(), to.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pass_counts_are_read_from_libtest_summaries() {
        assert_eq!(
            passed_count("test result: ok. 27 passed; 0 failed; 0 ignored; 0 filtered out; finished in 0.85s"),
            Some(27)
        );
        assert_eq!(passed_count("test result: FAILED. 3 passed; 1 failed; 0 ignored"), Some(3));
        assert_eq!(passed_count("running 27 tests"), None);
        assert_eq!(passed_count("test wasm::tests::a ... ok"), None);
    }

    #[test]
    fn element_package_carries_the_crate_version() {
        let manifest = "[package]\nname = \"screwcut\"\nversion = \"1.2.3\"\n\n[dependencies]\nversion = \"9\"\n";
        assert_eq!(crate_version(manifest).unwrap(), "1.2.3");
        assert!(crate_version("[package]\nname = \"x\"\n").is_err());
        let real = crate_version(&read(&root().join("Cargo.toml")).unwrap()).unwrap();
        let json = element_package_json(&real);
        assert!(json.contains(&format!("\"version\": \"{real}\"")));
        assert!(json.contains("\"main\": \"screwcut-preview.js\""));
        assert!(root().join("www").join("element").join("README.md").exists());
        // The app the "Open in editor" link opens by default ships in the folder and its package.
        for f in APP_FILES {
            assert!(json.contains(&format!("\"{f}\"")), "package.json lacks {f}");
        }
        assert!(json.contains("\"examples/\""));
        for f in ["index.html", "style.css", "favicon.svg"] {
            assert!(root().join("www").join("static").join(f).exists(), "www/static/{f}");
        }
    }

    /// The app and the element check a dialect name against the planner's
    /// list in JavaScript (www/src/shared/fragment.js), so they must know every
    /// spelling the planner accepts (src/dialect.rs `NAMES`).
    #[test]
    fn the_front_end_knows_every_dialect_spelling() {
        let names = read(&root().join("src").join("dialect.rs")).unwrap();
        let js = read(&root().join("www").join("src").join("shared").join("fragment.js")).unwrap();
        let table = names.split("const NAMES").nth(1).expect("src/dialect.rs has NAMES");
        let table = &table[..table.find("];").expect("NAMES ends")];
        let mut seen = 0;
        for row in table.lines().map(str::trim).filter(|l| l.starts_with("(\"")) {
            let quoted: Vec<&str> = row.split('"').skip(1).step_by(2).collect();
            let (name, aliases) = (quoted[0], &quoted[2..]);
            for alias in aliases {
                assert!(
                    js.contains(&format!("{alias}: '{name}'")),
                    "www/src/shared/fragment.js lacks the spelling {alias} of {name}"
                );
                seen += 1;
            }
        }
        assert!(seen >= 6, "read {seen} spellings from src/dialect.rs");
    }

    #[test]
    fn example_files_are_read_from_the_index() {
        let index = r#"[{"file": "o1006.nc", "dialect": "gsk980tdc"}, {"file":"b.nc"}]"#;
        assert_eq!(example_files(index).unwrap(), vec!["o1006.nc", "b.nc"]);
        assert!(example_files(r#"[{"file": "../x"}]"#).is_err());
        assert!(example_files("[]").is_err());
        let real = read(&root().join("examples").join("index.json")).unwrap();
        assert!(example_files(&real).unwrap().contains(&"o1006.nc".to_string()));
    }
}
