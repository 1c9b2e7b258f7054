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
