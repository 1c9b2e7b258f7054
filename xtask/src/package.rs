//! The element as an npm package: `npm pack` of the element's folder (its
//! tarball must carry the script, the wasm, the type declarations, the
//! README and the licences), installed with `npm install` into a scratch
//! page that the browser test opens (`package.test.mjs`), and its type
//! declarations checked by TypeScript on a page's script that uses them
//! (`tests/browser/package/consumer.ts` must compile; `wrong.ts`, which uses
//! them wrongly, must not, at each wrong line).

use std::path::Path;
use std::process::Command;

use crate::Result;
use crate::install::{root, run};

/// Files the packed tarball must hold (under `package/`).
const PACKED: [&str; 9] = [
    "package.json",
    "screwcut-preview.js",
    "screwcut-preview.d.ts",
    "screwcut_bg.wasm",
    "screwcut_tools_bg.wasm",
    "README.md",
    "LICENSE-MIT",
    "LICENSE-APACHE",
    "index.html",
];

/// Packs `element` and installs it into `scratch` with the test page; checks the tarball and the types.
pub fn pack_and_install(element: &Path, scratch: &Path) -> Result {
    let _ = std::fs::remove_dir_all(scratch);
    std::fs::create_dir_all(scratch).map_err(|e| format!("{}: {e}", scratch.display()))?;
    let dest = crate::web::path_str(scratch)?;
    run("npm", &["pack", "--pack-destination", &dest], Some(element))?;
    let tgz = std::fs::read_dir(scratch)
        .map_err(|e| format!("{}: {e}", scratch.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .find(|p| p.extension().is_some_and(|x| x == "tgz"))
        .ok_or("npm pack wrote no tarball")?;
    let listing = Command::new("tar").arg("tzf").arg(&tgz).output().map_err(|e| format!("cannot run tar: {e}"))?;
    let listing = String::from_utf8_lossy(&listing.stdout);
    let missing: Vec<&str> =
        PACKED.iter().copied().filter(|f| !listing.lines().any(|l| l == format!("package/{f}"))).collect();
    if !missing.is_empty() {
        return Err(format!("the packed element lacks {}", missing.join(", ")));
    }
    eprintln!("ok   npm pack: {} holds {}", tgz.display(), PACKED.join(", "));
    let page = root().join("tests").join("browser").join("package");
    for f in ["index.html", "consumer.ts", "wrong.ts"] {
        std::fs::copy(page.join(f), scratch.join(f)).map_err(|e| format!("cannot copy {f}: {e}"))?;
    }
    std::fs::write(
        scratch.join("package.json"),
        "{ \"name\": \"scratch-page\", \"private\": true, \"type\": \"module\" }\n",
    )
    .map_err(|e| format!("scratch package.json: {e}"))?;
    let tgz = crate::web::path_str(&tgz)?;
    run("npm", &["install", "--no-audit", "--no-fund", "--offline", &tgz], Some(scratch))?;
    check_types(scratch)
}

/// TypeScript on the scratch page's scripts: `consumer.ts` compiles, `wrong.ts` fails at lines 5, 6 and 7.
fn check_types(scratch: &Path) -> Result {
    let tsc = root().join("tests").join("browser").join("node_modules").join("typescript").join("bin").join("tsc");
    let tsc = crate::web::path_str(&tsc)?;
    let compile = |file: &str| {
        let o = Command::new("node")
            .args([tsc.as_str(), "--noEmit", "--strict", "--target", "es2022", "--lib", "es2022,dom"])
            .args(["--module", "nodenext", "--moduleResolution", "nodenext", file])
            .current_dir(scratch)
            .output()
            .map_err(|e| format!("cannot run tsc: {e}"))?;
        Ok::<_, String>((o.status.success(), String::from_utf8_lossy(&o.stdout).into_owned()))
    };
    let (ok, out) = compile("consumer.ts")?;
    if !ok {
        return Err(format!("the package's types reject a correct use (consumer.ts):\n{out}"));
    }
    eprintln!("ok   the package's types accept a page's script (consumer.ts)");
    let (ok, out) = compile("wrong.ts")?;
    let at = |line: u32| out.contains(&format!("wrong.ts({line},"));
    if ok || !(at(5) && at(6) && at(7)) {
        return Err(format!("the package's types let wrong uses through (wrong.ts lines 5, 6, 7):\n{out}"));
    }
    eprintln!("ok   … and reject its wrong uses (wrong.ts lines 5, 6, 7)");
    Ok(())
}
