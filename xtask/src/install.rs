//! Installing what the tasks need, and running commands.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::Result;

/// The repository root (the parent of `xtask/`).
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask is inside the repository").to_path_buf()
}

/// Runs a command in `dir` (default: the repository root), failing on a non-zero exit.
pub fn run(program: &str, args: &[&str], dir: Option<&Path>) -> Result {
    let dir = dir.map_or_else(root, Path::to_path_buf);
    eprintln!("$ {program} {}", args.join(" "));
    let status = Command::new(program)
        .args(args)
        .current_dir(&dir)
        .status()
        .map_err(|e| format!("cannot run {program}: {e}"))?;
    if status.success() { Ok(()) } else { Err(format!("{program} {} failed ({status})", args.join(" "))) }
}

/// Output of a command, if it ran and succeeded.
pub fn output(program: &str, args: &[&str]) -> Option<String> {
    let o = Command::new(program).args(args).output().ok()?;
    o.status.success().then(|| String::from_utf8_lossy(&o.stdout).into_owned())
}

/// The version of a package in Cargo.lock.
pub fn locked_version(package: &str) -> Result<String> {
    let lock = std::fs::read_to_string(root().join("Cargo.lock")).map_err(|e| format!("Cargo.lock: {e}"))?;
    let needle = format!("name = \"{package}\"\nversion = \"");
    let at = lock.find(&needle).ok_or_else(|| format!("{package} is not in Cargo.lock"))? + needle.len();
    Ok(lock[at..].split('"').next().unwrap_or_default().to_string())
}

/// Adds the wasm32 target when rustup does not list it as installed.
pub fn ensure_wasm_target() -> Result {
    let installed = output("rustup", &["target", "list", "--installed"]).unwrap_or_default();
    if installed.lines().any(|l| l.trim() == "wasm32-unknown-unknown") {
        return Ok(());
    }
    run("rustup", &["target", "add", "wasm32-unknown-unknown"], None)
}

/// Installs wasm-bindgen-cli at exactly the version of the `wasm-bindgen`
/// crate in Cargo.lock, unless both `wasm-bindgen` and
/// `wasm-bindgen-test-runner` already answer with that version. `--force`,
/// because cargo's record of installed crates outlives deleted binaries.
pub fn ensure_wasm_bindgen() -> Result {
    let want = locked_version("wasm-bindgen")?;
    let at = |program: &str| output(program, &["--version"]).unwrap_or_default();
    let ok = ["wasm-bindgen", "wasm-bindgen-test-runner"]
        .iter()
        .all(|p| at(p).split_whitespace().nth(1) == Some(want.as_str()));
    if ok {
        return Ok(());
    }
    run("cargo", &["install", "wasm-bindgen-cli", "--version", &want, "--force"], None)
}

/// Installs Debian's Chromium, ChromeDriver, DejaVu Sans (the labels' font:
/// the core places labels with its advances) and CJK fonts (Chinese labels) when they are missing.
pub fn ensure_chromium() -> Result {
    ensure_debian(&[
        ("/usr/bin/chromium", "chromium"),
        ("/usr/bin/chromedriver", "chromium-driver"),
        ("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "fonts-dejavu-core"),
        ("/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", "fonts-noto-cjk"),
    ])
}

/// Installs Debian's `linuxcnc-uspace` when `rs274`, LinuxCNC's stand-alone
/// interpreter (the oracle of the LinuxCNC dialect's tests), is missing.
pub fn ensure_rs274() -> Result {
    ensure_debian(&[("/usr/bin/rs274", "linuxcnc-uspace")])
}

/// Installs the Debian packages of `wanted` (file it installs, package)
/// whose file is missing, with apt-get (through `sudo -n` when not root).
pub fn ensure_debian(wanted: &[(&str, &str)]) -> Result {
    let missing: Vec<&str> = wanted.iter().filter(|(file, _)| !Path::new(file).exists()).map(|&(_, p)| p).collect();
    if missing.is_empty() {
        return Ok(());
    }
    let sudo = output("id", &["-u"]).is_some_and(|u| u.trim() != "0");
    let apt: Vec<&str> = if sudo { vec!["sudo", "-n", "apt-get"] } else { vec!["apt-get"] };
    let (prog, pre) = apt.split_first().expect("non-empty");
    // Another apt run (an unattended upgrade, a second job) holds the lock for a while: wait for it.
    let lock = ["-o", "DPkg::Lock::Timeout=600"];
    let mut update: Vec<&str> = pre.to_vec();
    update.extend(lock);
    update.extend(["update", "-q"]);
    run(prog, &update, None)?;
    let mut inst: Vec<&str> = pre.to_vec();
    inst.extend(lock);
    inst.extend(["install", "-y", "-q", "--no-install-recommends"]);
    inst.extend(&missing);
    let mut cmd = Command::new(prog);
    cmd.args(&inst).env("DEBIAN_FRONTEND", "noninteractive").stdin(std::process::Stdio::null());
    eprintln!("$ {prog} {}", inst.join(" "));
    let status = cmd.status().map_err(|e| format!("cannot run apt-get: {e}"))?;
    if !status.success() {
        return Err(format!("installing {} failed ({status})", missing.join(", ")));
    }
    match wanted.iter().find(|(file, _)| !Path::new(file).exists()) {
        Some((file, package)) => Err(format!("{package} is installed but {file} is not there")),
        None => Ok(()),
    }
}

/// `npm ci` in `dir` when its node_modules is missing or older than its lock file.
pub fn ensure_npm(dir: &Path) -> Result {
    let lock = dir.join("package-lock.json");
    let modules = dir.join("node_modules");
    let stale = match (std::fs::metadata(&lock), std::fs::metadata(modules.join(".package-lock.json"))) {
        (Ok(l), Ok(m)) => l.modified().ok() > m.modified().ok(),
        _ => true,
    };
    if !stale {
        return Ok(());
    }
    if lock.exists() {
        run("npm", &["ci", "--no-audit", "--no-fund"], Some(dir))
    } else {
        run("npm", &["install", "--no-audit", "--no-fund"], Some(dir))
    }
}
