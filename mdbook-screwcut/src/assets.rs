//! The element's files copied into the book once: from the element's folder
//! (`cargo xtask dist`'s `dist/element/`, or the `screwcut-preview` npm
//! package) into a folder of the book's sources, which mdBook copies to the
//! output beside the pages. A file already there with the same bytes is not
//! written again (so `mdbook serve` does not rebuild for it).

use std::path::{Path, PathBuf};

/// The element's own script: a folder without it is not the element.
pub const SCRIPT: &str = "screwcut-preview.js";

/// Copies the files of `from` (recursively) into `to`, writing only what
/// differs, and a `.gitignore` that keeps the copy out of version control;
/// returns how many files were written.
pub fn copy_element(from: &Path, to: &Path) -> Result<usize, String> {
    if !from.join(SCRIPT).is_file() {
        return Err(format!(
            "{} is not the element's folder (no {SCRIPT}): build it with `cargo xtask dist` (dist/element) or install the npm package screwcut-preview, and point preprocessor.screwcut.element at it",
            from.display()
        ));
    }
    let mut written = 0;
    for (src, rel) in files(from)? {
        written += usize::from(write_if_changed(&to.join(rel), &read(&src)?)?);
    }
    written += usize::from(write_if_changed(&to.join(".gitignore"), b"# copied by mdbook-screwcut\n*\n")?);
    Ok(written)
}

/// Every file under `dir` with its path relative to it, sorted.
fn files(dir: &Path) -> Result<Vec<(PathBuf, PathBuf)>, String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = std::fs::read_dir(&d).map_err(|e| format!("cannot read {}: {e}", d.display()))?;
        for entry in entries {
            let path = entry.map_err(|e| format!("cannot read {}: {e}", d.display()))?.path();
            if path.is_dir() {
                stack.push(path);
            } else if let Ok(rel) = path.strip_prefix(dir) {
                out.push((path.clone(), rel.to_path_buf()));
            }
        }
    }
    out.sort();
    Ok(out)
}

fn read(path: &Path) -> Result<Vec<u8>, String> {
    std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

/// Writes `bytes` to `path` unless it holds them already; true if written.
fn write_if_changed(path: &Path, bytes: &[u8]) -> Result<bool, String> {
    if std::fs::read(path).is_ok_and(|old| old == bytes) {
        return Ok(false);
    }
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    }
    std::fs::write(path, bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_once_and_refuses_a_folder_without_the_script() {
        let base = std::env::temp_dir().join(format!("mdbook-screwcut-assets-{}", std::process::id()));
        let (from, to) = (base.join("element"), base.join("book").join("screwcut"));
        std::fs::create_dir_all(from.join("examples")).unwrap();
        assert!(copy_element(&from, &to).unwrap_err().contains("is not the element's folder (no screwcut-preview.js)"));
        std::fs::write(from.join(SCRIPT), "export {};\n").unwrap();
        std::fs::write(from.join("examples").join("a.nc"), "G32 Z13 F2\n").unwrap();
        assert_eq!(copy_element(&from, &to).unwrap(), 3, "the script, the example and .gitignore");
        assert_eq!(std::fs::read_to_string(to.join("examples").join("a.nc")).unwrap(), "G32 Z13 F2\n");
        assert_eq!(copy_element(&from, &to).unwrap(), 0, "nothing changed, nothing written");
        std::fs::write(from.join(SCRIPT), "export const a = 1;\n").unwrap();
        assert_eq!(copy_element(&from, &to).unwrap(), 1);
        std::fs::remove_dir_all(&base).unwrap();
    }
}
