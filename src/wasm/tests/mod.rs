//! The binding's tests, run twice by `cargo xtask test` from the library's
//! wasm32 test binary: in Node (wasm-bindgen-test-runner's default) and in
//! headless Chromium through ChromeDriver (`WASM_BINDGEN_USE_BROWSER=1`,
//! `CHROMEDRIVER=/usr/bin/chromedriver`, browser options in the crate's
//! `webdriver.json`):
//!
//! ```sh
//! export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner
//! cargo test --target wasm32-unknown-unknown --lib wasm::
//! WASM_BINDGEN_USE_BROWSER=1 CHROMEDRIVER=/usr/bin/chromedriver cargo test --target wasm32-unknown-unknown --lib wasm::
//! ```
//!
//! They call the public functions of [`crate::wasm`] as JavaScript would and
//! check values: plans, diagnostics with UTF-16 positions, settings applied
//! and refused, the scenes by their numbers, and bad input that must come
//! back as values, never as a trap. (They live in the library rather than in
//! `tests/`: an integration test would make Cargo build the command-line
//! binary for wasm32 too.)

mod helpers;
mod incremental;
mod input;
mod lang;
mod plans;
mod scenes;
mod tools;
