//! `screwcut compare A B`: two programs planned and compared pass by pass
//! (`screwcut::compare`), printed as text or JSON.

use screwcut::compare::{Comparison, Difference};

/// Six significant decimals, trimmed.
fn num(v: Option<f64>) -> String {
    match v {
        None => "—".into(),
        Some(v) => {
            let s = format!("{:.4}", (v * 1e4).round() / 1e4);
            let s = s.trim_end_matches('0').trim_end_matches('.');
            if s == "-0" { "0".into() } else { s.to_string() }
        }
    }
}

/// What a difference is called in the listing.
fn name(d: &Difference) -> &'static str {
    match d.what {
        "threads" => "threads",
        "passes" => "passes",
        "lead" => "lead",
        "starts" => "starts",
        "start" => "start",
        "points" => "points of the path",
        "x" => "X",
        "z" => "Z",
        "depth" => "depth",
        "time" => "time (s)",
        other => other,
    }
}

/// The comparison as text: a line for the whole, then one per difference.
pub fn text(c: &Comparison, a: &str, b: &str) -> String {
    let mut out = if c.same() {
        format!("{a} and {b} cut the same passes: {} thread(s), {} pass(es)\n", c.threads[0], c.passes[0])
    } else {
        format!(
            "{a} and {b} differ: {} thread(s), {} pass(es) against {} thread(s), {} pass(es); {} difference(s)\n",
            c.threads[0],
            c.passes[0],
            c.threads[1],
            c.passes[1],
            c.differences.len()
        )
    };
    for d in &c.differences {
        let at = match (d.pass, d.start) {
            (Some(p), Some(s)) => format!("thread {} pass {p} (start {s})", d.thread),
            _ if d.thread == 0 => "program".to_string(),
            _ => format!("thread {}", d.thread),
        };
        out += &format!("  {at}: {} {} ≠ {}\n", name(d), num(d.a), num(d.b));
    }
    out
}
