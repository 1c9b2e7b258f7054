//! The two wasm modules of the site, built from the one crate with a Cargo
//! feature each: `screwcut_bg.wasm` (feature `view`: sessions, drawings,
//! settings tables, what a page needs for its first diagram) and
//! `screwcut_tools_bg.wasm` (feature `tools`: the thread wizard, a plan
//! written block by block, the plan as JSON), which the app loads the first
//! time one of them is used. Each gets its wasm-bindgen glue in `www/pkg/`
//! and, in a release build, `wasm-opt -Oz` from the binaryen pinned in
//! `www/package.json`, kept only if the glue still loads the output and it
//! does its work.

use std::path::Path;
use std::process::Command;

use crate::Result;
use crate::install::{ensure_wasm_bindgen, ensure_wasm_target, output, root, run};
use crate::web::{path_str, target_dir};

/// One wasm module of the site.
#[derive(Debug, Clone, Copy)]
pub struct Module {
    /// The stem of its files: `{stem}.js` (the glue), `{stem}_bg.wasm`.
    pub stem: &'static str,
    /// The crate feature that gives its exports.
    pub feature: &'static str,
    /// A Node script that fails unless the module (as `m`, initialised) does its work.
    check: &'static str,
}

impl Module {
    /// The name of its wasm file.
    pub fn wasm_file(&self) -> String {
        format!("{}_bg.wasm", self.stem)
    }
}

/// The site's modules: the first diagram's, then the tools.
pub const MODULES: [Module; 2] = [
    Module {
        stem: "screwcut",
        feature: "view",
        check: "const s = new m.Session();\
                const r = s.update('G00 X58 Z70\\nX47.1\\nG32 Z13 F2\\nG00 X58\\nZ70\\n', 'gsk980tdc', '', 0, 1, -1, undefined, false, false);\
                const d = s.draw('side', 640, 360, undefined, false, -1, -1, new Uint32Array(0), false);\
                if (r.threads.length !== 1 || !r.shown[0] || d.ops.length === 0) throw new Error('it plans or draws wrongly');\
                if (m.wizard_forms || m.expand) throw new Error('it carries the tools');",
    },
    Module {
        stem: "screwcut_tools",
        feature: "tools",
        check: "const e = m.expand('G00 X58 Z70\\nX47.1\\nG32 Z13 F2\\nG00 X58\\nZ70\\n', 'gsk980tdc', '', 'linuxcnc');\
                if (!e.program.includes('G33 X47.1 Z13 K2')) throw new Error('it expands wrongly');\
                if (m.wizard_forms('en').length < 4) throw new Error('it lists no wizard forms');\
                if (m.Session) throw new Error('it carries the sessions');",
    },
];

/// Builds every module (release or debug) into `pkg`: the wasm and its
/// glue, size-optimised in a release build (by the wasm-opt of `www/`'s npm
/// packages, installed by the caller). Returns what wasm-opt did to each, as
/// one outcome: optimised when all were.
pub fn build_modules(release: bool, pkg: &Path) -> Result<WasmOpt> {
    ensure_wasm_target()?;
    ensure_wasm_bindgen()?;
    let profile = if release { "release" } else { "debug" };
    let staged = target_dir()?.join("wasm-modules").join(profile);
    std::fs::create_dir_all(&staged).map_err(|e| format!("cannot create {}: {e}", staged.display()))?;
    let mut outcome = None;
    for m in MODULES {
        let mut args = vec![
            "build",
            "--package",
            "screwcut",
            "--lib",
            "--target",
            "wasm32-unknown-unknown",
            "--no-default-features",
        ];
        args.extend(["--features", m.feature]);
        if release {
            args.push("--release");
        }
        run("cargo", &args, None)?;
        // wasm-bindgen names its output after its input.
        let built = target_dir()?.join("wasm32-unknown-unknown").join(profile).join("screwcut.wasm");
        let input = staged.join(format!("{}.wasm", m.stem));
        std::fs::copy(&built, &input).map_err(|e| format!("cannot copy {}: {e}", built.display()))?;
        run(
            "wasm-bindgen",
            &["--target", "web", "--no-typescript", "--out-dir", &path_str(pkg)?, &path_str(&input)?],
            None,
        )?;
        let opt = if release { optimise(&pkg.join(m.wasm_file()), &m) } else { WasmOpt::Skipped("debug build".into()) };
        eprintln!("{}: {opt}", m.wasm_file());
        outcome = Some(match (outcome, opt) {
            (Some(WasmOpt::Skipped(why)), _) => WasmOpt::Skipped(why),
            (_, WasmOpt::Skipped(why)) => WasmOpt::Skipped(format!("{}: {why}", m.wasm_file())),
            (Some(WasmOpt::Optimised { version, before, after }), WasmOpt::Optimised { before: b, after: a, .. }) => {
                WasmOpt::Optimised { version, before: before + b, after: after + a }
            }
            (None, opt) => opt,
        });
    }
    outcome.ok_or_else(|| "no wasm module to build".into())
}

/// What the size optimisation of a release build did to the wasm modules.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WasmOpt {
    /// `wasm-opt -Oz` ran and its output loads and works: version and sizes in bytes (of all modules).
    Optimised { version: String, before: u64, after: u64 },
    /// A wasm is as wasm-bindgen wrote it, for this reason.
    Skipped(String),
}

impl std::fmt::Display for WasmOpt {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WasmOpt::Optimised { version, before, after } => write!(
                f,
                "size-optimised by {version} -Oz: {} KiB -> {} KiB",
                before.div_ceil(1024),
                after.div_ceil(1024)
            ),
            WasmOpt::Skipped(why) => write!(f, "NOT size-optimised: {why}"),
        }
    }
}

/// Runs `wasm-opt -Oz` on `wasm` (module `m`) in place with the binaryen
/// pinned in `www/package.json` (installed by `npm ci` there), and keeps
/// the result only if the wasm-bindgen glue still loads it and it works.
///
/// The pinned npm build is used rather than a system binaryen so that every
/// machine ships the wasm that was measured: Debian bookworm's binaryen 108
/// writes this module's `__wbindgen_externrefs` export against the wrong
/// table, and the glue then fails to load it.
fn optimise(wasm: &Path, m: &Module) -> WasmOpt {
    let tool = root().join("www").join("node_modules").join(".bin").join("wasm-opt");
    let Some(tool) = tool.to_str().filter(|_| tool.exists()) else {
        return WasmOpt::Skipped(format!("{} is missing (npm ci in www/)", tool.display()));
    };
    let version = output(tool, &["--version"]).map(|v| v.trim().to_string()).unwrap_or_default();
    if version.is_empty() {
        return WasmOpt::Skipped(format!("{tool} --version failed"));
    }
    let tmp = wasm.with_extension("opt.wasm");
    let features = [
        "--enable-bulk-memory",
        "--enable-nontrapping-float-to-int",
        "--enable-sign-ext",
        "--enable-mutable-globals",
        "--enable-reference-types",
        "--enable-multivalue",
    ];
    let size = |p: &Path| std::fs::metadata(p).map(|m| m.len()).unwrap_or(0);
    let before = size(wasm);
    let outcome = (|| -> Result<u64> {
        let (w, t) = (path_str(wasm)?, path_str(&tmp)?);
        let mut args = vec!["-Oz"];
        args.extend(features);
        args.extend([w.as_str(), "-o", t.as_str()]);
        run(tool, &args, None)?;
        smoke_test(&tmp, m)?;
        let after = size(&tmp);
        std::fs::rename(&tmp, wasm).map_err(|e| format!("{}: {e}", wasm.display()))?;
        Ok(after)
    })();
    match outcome {
        Ok(after) => WasmOpt::Optimised { version, before, after },
        Err(e) => {
            let _ = std::fs::remove_file(&tmp);
            WasmOpt::Skipped(format!("{version}: {e}"))
        }
    }
}

/// Loads `wasm` with module `m`'s wasm-bindgen glue beside it in Node and runs its check.
fn smoke_test(wasm: &Path, m: &Module) -> Result {
    let glue = wasm.with_file_name(format!("{}.js", m.stem));
    let script = format!(
        "import fs from 'node:fs';\
         const m = await import({glue:?});\
         m.initSync({{ module: fs.readFileSync({wasm:?}) }});\
         {check}",
        glue = format!("file://{}", path_str(&glue)?),
        wasm = path_str(wasm)?,
        check = m.check,
    );
    let out = Command::new("node")
        .args(["--input-type=module", "-e", &script])
        .output()
        .map_err(|e| format!("cannot run node: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        let msg = String::from_utf8_lossy(&out.stderr);
        let first = msg.lines().find(|l| l.contains("Error")).unwrap_or("failed").trim().to_string();
        Err(format!("the wasm-opt output of {} does not load or work ({first})", m.stem))
    }
}
