//! The wasm-bindgen binding layer.
