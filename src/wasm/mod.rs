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
//! - the bindings (`bind`, `session`, `js`, `listed`, `parts`; wasm32 only): per-view
//!   sessions — the app and every embedded element keep their own planner
//!   and scene pieces — and the functions JavaScript calls; `views`: each view's display list,
//!   hit test and SVG. These are the `view` module a page loads first;
//! - `tools` (wasm32 only, feature `tools`): the thread wizard, a program
//!   written block by block and the plan as JSON, a second module a page
//!   loads when one of them is first used. It plans from the text it is
//!   given and keeps nothing.
//!
//! Everything but the bindings is compiled natively too, so its tests run
//! with the core's.

pub mod keys;
pub mod memo;
pub mod pack;
pub mod shown;
pub mod splice;
pub mod text;

// The exports come in two sets, each a wasm module of its own (Cargo
// features `view` and `tools`; both in a default build and in the tests).
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod bind;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod compared;
#[cfg(target_arch = "wasm32")]
#[cfg_attr(not(feature = "view"), allow(dead_code))]
mod js;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod listed;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod parts;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod session;
#[cfg(all(target_arch = "wasm32", feature = "tools"))]
mod tools;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
mod views;

#[cfg(all(target_arch = "wasm32", feature = "view"))]
pub use bind::*;
#[cfg(all(target_arch = "wasm32", feature = "view"))]
pub use session::Session;
#[cfg(all(target_arch = "wasm32", feature = "tools"))]
pub use tools::*;

/// The binding's tests (wasm-bindgen-test), run in Node and in headless
/// Chromium by `cargo xtask test`.
#[cfg(all(test, target_arch = "wasm32", feature = "view", feature = "tools"))]
mod tests;
