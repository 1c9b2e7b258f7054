//! Native throughput of lex + interpret + plan on generated programs, and
//! peak memory; then the 5,000-line Fanuc program with subprograms and
//! macro loops: a full plan, and the incremental planner's re-plan after a
//! one-character edit in a subprogram and in the main program. Run with
//! `cargo bench --bench throughput`; figures are rates, times and ratios
//! measured in one run, never asserted.

mod programs;

use std::time::Instant;

use screwcut::planner::Planner;
use screwcut::{Dialect, Settings, Severity};

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
    // The loop program alone: `--loops`.
    if args.iter().any(|a| a == "--typed") {
        typed();
        return;
    }
    // Profiling mode: the 50,000-line program's first-pass digit typed and deleted N times (incremental re-plans only).
    if let Some(i) = args.iter().position(|a| a == "--typed-profile") {
        let n: usize = args[i + 1].parse().expect("count");
        let (text, edited) = typed_texts(50_000);
        let mut p = Planner::new(Settings::new(Dialect::Gsk980tdc));
        p.plan(&text);
        for k in 0..n {
            p.plan(if k % 2 == 0 { &edited } else { &text });
        }
        println!("{}", p.last().map_or(0, |l| l.moves.len()));
        return;
    }
    // Profiling mode: the side section of the 50,000-line program after that digit, from the kept pieces, N times.
    if let Some(i) = args.iter().position(|a| a == "--side-profile") {
        let n: usize = args[i + 1].parse().expect("count");
        let (text, edited) = typed_texts(50_000);
        let settings = Settings::new(Dialect::Gsk980tdc);
        let plans = [screwcut::plan(&text, &settings), screwcut::plan(&edited, &settings)];
        let keys = plans.each_ref().map(screwcut::wasm::keys::PlanKeys::of);
        let mut memo = screwcut::wasm::memo::SideMemo::new();
        let mut items = 0;
        for k in 0..=n {
            items += memo.side(&plans[k % 2], &keys[k % 2]).items.len();
            if std::env::var_os("SIDE_COUNTS").is_some() {
                eprintln!("built, reused: {:?}", memo.counts());
            }
        }
        println!("{items}");
        return;
    }
    // Profiling mode: the side view's display list of the 50,000-line program, before and after that digit, N times.
    if let Some(i) = args.iter().position(|a| a == "--draw-profile") {
        let n: usize = args[i + 1].parse().expect("count");
        let (text, edited) = typed_texts(50_000);
        let settings = Settings::new(Dialect::Gsk980tdc);
        let plans = [screwcut::plan(&text, &settings), screwcut::plan(&edited, &settings)];
        // As the app draws them: from the kept pieces, whose repeated paths share their points.
        let mut side = screwcut::wasm::memo::SideMemo::new();
        let scenes = plans.each_ref().map(|p| side.side(p, &screwcut::wasm::keys::PlanKeys::of(p)));
        let view = screwcut::draw::View { width: 936.0, height: 420.0, ..Default::default() };
        let mut memo = screwcut::draw::FitMemo::default();
        let mut ops = 0;
        for k in 0..=n {
            ops += screwcut::draw::display_kept(&scenes[k % 2], &view, &mut memo).ops.len();
        }
        println!("{ops}");
        return;
    }
    if args.iter().any(|a| a == "--loops") {
        loops(&out_dir);
        typed();
        return;
    }
    // One thread of many passes through the editor's planner alone: `--one-thread`.
    if args.iter().any(|a| a == "--one-thread") {
        one_thread();
        return;
    }
    let settings = Settings::new(Dialect::Gsk980tdc);
    println!("screwcut native throughput (lex + interpret + plan), release build");
    for (name, mb) in [("mixed", 1usize), ("mixed", 20), ("thread-dense", 1), ("g01", 10)] {
        let text = generate(name, mb);
        let _ = std::fs::write(out_dir.join(format!("{name}-{mb}mb.nc")), &text);
        let runs = if mb == 1 { 20 } else { 7 };
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
    loops(&out_dir);
    typed();
    one_thread();
}

/// The best of `runs` timings of `f`, in milliseconds, and its last result.
fn best_ms<R>(runs: usize, mut f: impl FnMut() -> (f64, R)) -> (f64, R) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let (ms, r) = f();
        best = best.min(ms);
        last = Some(r);
    }
    (best, last.expect("at least one run"))
}

/// The browser bench's plain program (`bench/browser.mjs`, `program`): a
/// turning section, then five G32 passes, repeated, `lines` long.
fn plain(lines: usize) -> String {
    let mut out = vec!["O2000".to_string(), "G50 X100 Z100".into(), "S300 M03 T0101".into()];
    let mut n = 0;
    while out.len() < lines - 1 {
        let d = 30 + n % 20;
        out.extend([format!("G00 X{} Z70", d + 10), format!("G01 X{d} F0.2"), "Z20".into(), format!("X{}", d + 5)]);
        out.push("G00 Z70".into());
        for x in [0.9, 1.5, 2.1, 2.5, 2.6] {
            out.extend([
                format!("X{:.1}", d as f64 - x),
                "G32 Z13 F2".into(),
                format!("G00 X{}", d + 10),
                "Z70".into(),
            ]);
        }
        n += 1;
    }
    out.push("M30".into());
    out.truncate(lines);
    out.join("\n") + "\n"
}

/// The plain program of `lines` lines, and the same with the browser bench's
/// digit typed at the end of line 9 (the first pass).
fn typed_texts(lines: usize) -> (String, String) {
    let text = plain(lines);
    let at = text.match_indices('\n').nth(8).map_or(0, |(i, _)| i);
    let edited = format!("{}1{}", &text[..at], &text[at..]);
    (text, edited)
}

/// The keystroke the browser bench types (a digit at the end of line 9, the
/// first pass) into its 5,000- and 50,000-line programs, re-planned natively
/// by the incremental planner.
fn typed() {
    let settings = Settings::new(Dialect::Gsk980tdc);
    for lines in [5_000, 50_000] {
        let (text, edited) = typed_texts(lines);
        let (full, _) = best_ms(5, || {
            let t = Instant::now();
            let plan = screwcut::plan(&edited, &settings);
            (t.elapsed().as_secs_f64() * 1e3, plan.moves.len())
        });
        let (ms, (resumed, stopped)) = best_ms(10, || {
            let mut p = Planner::new(settings.clone());
            p.plan(&text);
            let t = Instant::now();
            p.plan(&edited);
            (t.elapsed().as_secs_f64() * 1e3, (p.resumed_at(), p.stopped_at()))
        });
        let stop = stopped.map_or("read to the end".to_string(), |l| format!("stopped at line {l}"));
        println!(
            "  a digit typed in the first pass of the plain {lines}-line program: incremental re-plan best of 10 {ms:.2} ms \
             (resumed at line {resumed}, {stop}); a full plan {full:.2} ms"
        );
        println!("FIG typed{}k_ms {ms:.3}", lines / 1000);
        // The side section after that keystroke, from the app's kept pieces.
        let plans = [screwcut::plan(&text, &settings), screwcut::plan(&edited, &settings)];
        let keys = plans.each_ref().map(screwcut::wasm::keys::PlanKeys::of);
        let mut memo = screwcut::wasm::memo::SideMemo::new();
        memo.side(&plans[0], &keys[0]);
        let mut typed = 0;
        let (side, items) = best_ms(10, || {
            typed += 1;
            let k = typed % 2;
            let t = Instant::now();
            let scene = memo.side(&plans[k], &keys[k]);
            (t.elapsed().as_secs_f64() * 1e3, scene.items.len())
        });
        println!("  … its side section from the kept pieces: best of 10 {side:.2} ms ({items} items)");
        println!("FIG typed{}k_side_ms {side:.3}", lines / 1000);
    }
}

/// The 5,000-line Fanuc 0i program with subprograms, `M98 P… L3`, `G65`
/// and `WHILE` loops (written to `loops-5000.nc` for the browser bench):
/// a full plan, and re-plans by the incremental planner (the app's) after
/// typing one digit at the end of a line in the common macro O9010, in the
/// first job's thread and in the last job's thread of the main program.
/// One block-by-block thread of many passes (the four lines `X47.1 /
/// G32 Z13.0 F2.0 / G00 X58.0 / Z70.0` repeated) planned by the editor's
/// incremental planner, which snapshots the reading every 256 blocks: the
/// time must grow with the size, not its square (a snapshot once copied
/// every pass of the thread being grouped).
fn one_thread() {
    println!("one block-by-block thread of many passes, the editor's planner (snapshots every 256 blocks):");
    for mb in [0.5, 1.0, 2.0, 5.0] {
        let mut text = String::from("G00 X58.0 Z70.0\n");
        while (text.len() as f64) < mb * 1e6 {
            text.push_str("X47.1\nG32 Z13.0 F2.0\nG00 X58.0\nZ70.0\n");
        }
        let (ms, passes) = best_ms(3, || {
            let t = Instant::now();
            let mut p = screwcut::planner::Planner::new(Settings::new(Dialect::Gsk980tdc));
            let passes = p.plan(&text).threads.iter().map(|t| t.passes.len()).sum::<usize>();
            (t.elapsed().as_secs_f64() * 1e3, passes)
        });
        println!("  {mb} MB: {passes} passes, first plan best of 3 {ms:.0} ms ({:.1} MB/s)", mb / ms * 1e3);
        println!("FIG one_thread_{}mb_ms {ms:.1}", (mb * 10.0) as u32);
    }
}

fn loops(out_dir: &std::path::Path) {
    let text = programs::fanuc_loops(5000);
    let _ = std::fs::write(out_dir.join("loops-5000.nc"), &text);
    let settings = Settings::new(Dialect::Fanuc0i);
    let (full, plan) = best_ms(20, || {
        let t = Instant::now();
        let plan = screwcut::plan(&text, &settings);
        (t.elapsed().as_secs_f64() * 1e3, plan)
    });
    let alarms = plan.diagnostics.iter().filter(|d| d.severity == Severity::Error).count();
    println!(
        "  fanuc loops 5,000 lines ({} bytes, {} lines; subprograms, M98 L3, G65, WHILE): full plan best of 20 {full:.2} ms; \
         {} moves, {} threads, {} diagnostics, {alarms} alarms",
        text.len(),
        text.lines().count(),
        plan.moves.len(),
        plan.threads.len(),
        plan.diagnostics.len(),
    );
    println!("FIG loops5k_full_ms {full:.3}");
    let line_end = |at: usize| at + text[at..].find('\n').unwrap_or(text.len() - at);
    let edits = [
        ("sub", "in the macro O9010 (#10=#2*1.227)", line_end(text.find("#10=#2*1.227").expect("the macro"))),
        ("main", "in the main program, first job's #1", line_end(text.find("\n#1=").expect("a #1 line") + 1)),
        ("main_end", "in the main program, last job's #1", line_end(text.rfind("\n#1=").expect("a #1 line") + 1)),
    ];
    for (key, what, at) in edits {
        let edited = format!("{}1{}", &text[..at], &text[at..]);
        let (ms, (resumed, stopped, inc)) = best_ms(10, || {
            let mut p = Planner::new(settings.clone());
            p.plan(&text);
            let t = Instant::now();
            p.plan(&edited);
            let ms = t.elapsed().as_secs_f64() * 1e3;
            (ms, (p.resumed_at(), p.stopped_at(), p.last().cloned()))
        });
        let line = text[..at].matches('\n').count() + 1;
        let stop = stopped.map_or("read to the end".to_string(), |l| format!("stopped at line {l}"));
        println!(
            "  one digit typed {what}, line {line}: incremental re-plan best of 10 {ms:.2} ms \
             (resumed at line {resumed}, {stop}; the same plan as a full plan: {})",
            inc.as_ref() == Some(&screwcut::plan(&edited, &settings))
        );
        println!("FIG loops5k_edit_{key}_ms {ms:.3}");
    }
}
