//! The wasm layer: what only a browser needs, over the core.
//!
//! - [`text`]: byte offsets as UTF-16 positions (what JavaScript strings and
//!   the editor count);
//! - [`pack`]: scenes as flat typed arrays, with the item record layout
//!   defined once ([`pack::FIELDS`]) and read by name on the JavaScript side;
//! - [`keys`]: content keys of the parts of a plan, as JavaScript numbers;
//! - [`memo`]: the side section put together from the pieces an edit did
//!   not change;
//! - [`shown`]: which scenes the views show (the last good drawing's policy);
//! - [`splice`]: the diagnostics list sent as the change from the last one;
//! - the bindings (`bind`, `session`, `js`, `listed`, `parts`, `tools`; wasm32 only): per-view
//!   sessions — the app and every embedded element keep their own planner
//!   and scene pieces — and the functions JavaScript calls; `views`: each view's display list,
//!   hit test and SVG.
//!
//! Everything but the bindings is compiled natively too, so its tests run
//! with the core's.

pub mod keys;
pub mod memo;
pub mod pack;
pub mod shown;
pub mod splice;
pub mod text;

#[cfg(target_arch = "wasm32")]
mod bind;
#[cfg(target_arch = "wasm32")]
mod compared;
#[cfg(target_arch = "wasm32")]
mod js;
#[cfg(target_arch = "wasm32")]
mod listed;
#[cfg(target_arch = "wasm32")]
mod parts;
#[cfg(target_arch = "wasm32")]
mod session;
#[cfg(target_arch = "wasm32")]
mod tools;
#[cfg(target_arch = "wasm32")]
mod views;

#[cfg(target_arch = "wasm32")]
pub use bind::*;
#[cfg(target_arch = "wasm32")]
pub use session::Session;
#[cfg(target_arch = "wasm32")]
pub use tools::*;

/// The binding's tests (wasm-bindgen-test), run in Node and in headless
/// Chromium by `cargo xtask test`.
#[cfg(all(test, target_arch = "wasm32"))]
mod tests;
