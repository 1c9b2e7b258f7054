//! Scenes: what the views draw, computed from a plan.
//!
//! Pure Rust, no wasm or DOM: the web app renders these scenes on canvas and
//! as SVG, and tests check them natively. Every item carries the source
//! lines, thread and pass it comes from, so that hovering a drawing
//! highlights the program and the editor cursor highlights the drawing.
//!
//! - [`side()`]: the side section of the whole program ([`side`](mod@side)).
//! - [`tooth()`]: one thread space of one thread at large scale ([`tooth`](mod@tooth)).
//! - [`starts()`]: the start angles and axial offsets of one thread ([`starts`](mod@starts)).
//!
//! How scenes travel to a browser (packed into typed arrays, keyed, put
//! together from kept pieces) is the business of the wasm layer.

pub mod band;
pub mod detail;
pub mod overlay;
pub mod radial;
pub mod scene;
pub mod section;
pub mod side;
pub mod starts;
pub mod tooth;

pub use scene::{Item, Label, Rect, Scene, Shape, Style, ViewKind};
pub use side::side;
pub use starts::starts;
pub use tooth::tooth;

#[cfg(test)]
mod tests;
