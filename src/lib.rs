//! screwcut: an interpreter and pass planner for CNC lathe thread-cutting
//! G-code (GSK980TDc, Fanuc 0i, Renhe).
//!
//! Data flows one way: text → [`block`]s ([`lexer`]) → events ([`interp`],
//! reading each block through its [`controller`]) → motions and threads with
//! the motions of each pass ([`assemble`]: [`group`], [`cycle`]) → depths
//! and advice ([`advice`]) → shop-floor figures and checks ([`shop`]) →
//! [`plan::Plan`] → scenes ([`diagram`]). What only a browser needs (UTF-16
//! positions, scenes packed into typed arrays, content keys as JavaScript
//! numbers, sessions) is in [`wasm`], whose bindings are compiled for wasm32
//! only. The core is free of wasm and the DOM; the
//! browser binding lives in `wasm` and is compiled only for wasm32.
//!
//! ```
//! use screwcut::{plan::plan_default, dialect::Dialect};
//! let plan = plan_default("G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nM30\n", Dialect::Gsk980tdc);
//! assert_eq!(plan.threads.len(), 1);
//! assert_eq!(plan.threads[0].passes[0].to.z, 13.0);
//! ```

pub mod advice;
pub mod assemble;
pub mod block;
pub mod chip;
pub mod code;
pub mod comment;
pub mod compare;
pub mod controller;
pub mod cycle;
pub mod diagnostic;
pub mod diagram;
pub mod dialect;
pub mod draw;
pub mod element;
pub mod event;
pub mod exec;
pub mod expand;
pub mod figures;
pub mod form;
pub mod gcode;
pub mod geom;
pub mod group;
pub mod hash;
pub mod helix;
pub mod hint;
mod huge;
pub mod insert;
pub mod interp;
pub mod lexer;
pub mod message;
pub mod motion;
pub mod num;
pub mod order;
pub mod parts;
pub mod plan;
pub mod planner;
pub mod settings;
pub mod shop;
pub mod span;
pub mod standard;
pub mod state;
pub mod svg;
pub mod thread;
pub mod wasm;
pub mod wizard;

pub use diagnostic::{Code, Diagnostic, Severity};
pub use dialect::Dialect;
pub use plan::{Plan, plan};
pub use settings::Settings;
