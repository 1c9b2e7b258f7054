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
//! [`fingerprint`] keys the parts of a plan these read, so that unchanged
//! scenes need not be built or sent again.

pub mod band;
pub mod editor;
pub mod fingerprint;
pub mod memo;
pub mod packed;
pub mod scene;
pub mod side;
pub mod starts;
pub mod tooth;

pub use packed::{Packed, pack};
pub use scene::{Item, Label, Rect, Scene, Shape, Style, ViewKind};
pub use side::side;
pub use starts::starts;
pub use tooth::tooth;

#[cfg(test)]
mod tests;
