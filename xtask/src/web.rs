//! Building, bundling and serving the web app.

use crate::Result;

/// `cargo xtask serve`.
pub fn serve(_args: &[String]) -> Result {
    Err("serve: not built yet".into())
}

/// `cargo xtask dist`.
pub fn dist(_args: &[String]) -> Result {
    Err("dist: not built yet".into())
}
