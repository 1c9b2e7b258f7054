//! Native throughput of lex + interpret + plan on generated programs, and
//! peak memory. Run with `cargo bench --bench throughput`; figures are rates
//! and ratios measured in one run, never asserted.

mod programs;

use std::time::Instant;

use screwcut::{Dialect, Settings};

fn peak_rss_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// The generated program `name` (mixed, thread-dense, g01) of about `mb` MiB.
fn generate(name: &str, mb: usize) -> String {
    match name {
        "thread-dense" => programs::thread_dense(mb << 20, 7),
        "g01" => programs::g01(mb << 20, 7),
        _ => programs::program(mb << 20, 7),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    // Profiling mode: plan 1 MB many times (for perf, callgrind): `--profile N [mixed|g01|thread-dense]`.
    if let Some(i) = args.iter().position(|a| a == "--profile") {
        let n: usize = args[i + 1].parse().expect("count");
        let text = generate(args.get(i + 2).map_or("mixed", String::as_str), 1);
        let settings = Settings::new(Dialect::Gsk980tdc);
        let mut moves = 0;
        for _ in 0..n {
            moves += screwcut::plan(&text, &settings).moves.len();
        }
        println!("{moves}");
        return;
    }
    // Child mode: plan one size and report peak memory of this process.
    if let Some(i) = args.iter().position(|a| a == "--child") {
        let mb: usize = args[i + 1].parse().expect("size");
        let text = generate(args.get(i + 2).map_or("mixed", String::as_str), mb);
        let base = peak_rss_kib().unwrap_or(0);
        let plan = screwcut::plan(&text, &Settings::new(Dialect::Gsk980tdc));
        let peak = peak_rss_kib().unwrap_or(0);
        println!("{} {} {}", base, peak, plan.moves.len());
        return;
    }
    let out_dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/bench");
    let _ = std::fs::create_dir_all(&out_dir);
    let settings = Settings::new(Dialect::Gsk980tdc);
    println!("screwcut native throughput (lex + interpret + plan), release build");
    for (name, mb) in [("mixed", 1usize), ("mixed", 20), ("thread-dense", 1), ("g01", 10)] {
        let text = generate(name, mb);
        let _ = std::fs::write(out_dir.join(format!("{name}-{mb}mb.nc")), &text);
        let runs = if mb == 1 { 20 } else { 3 };
        let mut best = f64::INFINITY;
        let mut summary = (0, 0, 0);
        for _ in 0..runs {
            let t = Instant::now();
            let plan = screwcut::plan(&text, &settings);
            best = best.min(t.elapsed().as_secs_f64());
            summary = (plan.moves.len(), plan.threads.len(), plan.diagnostics.len());
        }
        let rate = text.len() as f64 / best / 1e6;
        let mem = std::process::Command::new(&args[0])
            .args(["--child", &mb.to_string(), name])
            .output()
            .ok()
            .and_then(|o| String::from_utf8(o.stdout).ok())
            .and_then(|s| {
                let v: Vec<u64> = s.split_whitespace().filter_map(|x| x.parse().ok()).collect();
                (v.len() == 3).then(|| (v[0], v[1]))
            });
        println!(
            "  {name:>12} {:>2} MB ({} bytes, {} lines): best of {runs} {:.1} ms = {:.1} MB/s; {} moves, {} threads, {} diagnostics",
            mb,
            text.len(),
            text.lines().count(),
            best * 1e3,
            rate,
            summary.0,
            summary.1,
            summary.2
        );
        // A machine-readable line for `cargo xtask bench`.
        println!("RATE {name}-{mb}mb.nc {rate:.3}");
        if let Some((base, peak)) = mem {
            println!(
                "                     peak memory {:.1} MiB (text and generator {:.1} MiB before planning): {:.1}× the program size",
                peak as f64 / 1024.0,
                base as f64 / 1024.0,
                (peak as f64 * 1024.0) / text.len() as f64
            );
        }
    }
}
