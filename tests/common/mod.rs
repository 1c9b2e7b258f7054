//! Helpers shared by the integration tests.
#![allow(dead_code)]

use screwcut::diagnostic::Diagnostic;
use screwcut::{Code, Dialect, Plan, Settings};

/// Plans `src` with the defaults of `dialect` plus `sets` (`NAME=VALUE`).
pub fn plan_with(src: &str, dialect: Dialect, sets: &[&str]) -> Plan {
    let mut s = Settings::new(dialect);
    for a in sets {
        s.assign(a).unwrap_or_else(|e| panic!("{a}: {e}"));
    }
    screwcut::plan(src, &s)
}

/// Plans `src` as GSK980TDc with default settings.
pub fn gsk(src: &str) -> Plan {
    plan_with(src, Dialect::Gsk980tdc, &[])
}

/// The only diagnostic with `code` (fails when there is none or several).
pub fn one(plan: &Plan, code: Code) -> Diagnostic {
    let v: Vec<_> = plan.with_code(code).cloned().collect();
    assert_eq!(v.len(), 1, "expected one {code}, got {v:#?}\nall: {:#?}", plan.diagnostics);
    v[0].clone()
}

/// Asserts one diagnostic with `code` at `line`:`column` and returns it.
pub fn at(plan: &Plan, code: Code, line: u32, column: u32) -> Diagnostic {
    let d = plan
        .with_code(code)
        .find(|d| d.line == line && d.column == column)
        .cloned()
        .unwrap_or_else(|| panic!("no {code} at {line}:{column}; diagnostics: {:#?}", plan.diagnostics));
    assert_eq!(d.severity, code.severity());
    d
}

/// Asserts there is no alarm.
pub fn no_alarm(plan: &Plan) {
    let alarms: Vec<_> = plan.diagnostics.iter().filter(|d| d.severity == screwcut::Severity::Error).collect();
    assert!(alarms.is_empty(), "unexpected alarms: {alarms:#?}");
}

/// Asserts two lengths agree to 1e-9.
#[track_caller]
pub fn eq(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-9, "{a} != {b}");
}

/// Asserts a point is `[x, z]` to 1e-9.
#[track_caller]
pub fn pt(p: screwcut::motion::Point, x: f64, z: f64) {
    assert!((p.x - x).abs() < 1e-9 && (p.z - z).abs() < 1e-9, "({}, {}) != ({x}, {z})", p.x, p.z);
}
