//! `cargo xtask bench`: the performance figures, measured in one run and
//! printed (never asserted): native throughput and memory, the wasm size,
//! gcode-toolpath side by side, and in headless Chromium what a person
//! typing feels (Event Timing, the app's frame marks, long tasks) in a plain
//! 5,000-line program, in a 5,000-line Fanuc program of subprograms and macro
//! loops and in a 50,000-line one, the app against the bare editor typed
//! into alternately (the floor and the ratio), the first load's transferred
//! bytes (app and one embedded diagram), the L99 program and the wasm
//! planner's rate. Ends with a table of each figure beside the one measured when the
//! work to reach it began (for the loop program: the plain 5,000-line figure
//! of the same run), and its target.

use std::collections::BTreeMap;
use std::process::{Command, Stdio};

use comfy_table::{Table, presets::UTF8_FULL_CONDENSED};

use crate::{Result, install, web};

/// A figure of the summary: key, what it is, the value before (issue #11's
/// "today", 2026-11), the target, and whether smaller is better.
struct Figure {
    key: &'static str,
    what: &'static str,
    before: &'static str,
    target: &'static str,
    unit: &'static str,
}

const FIGURES: &[Figure] = &[
    Figure {
        key: "k5_event_p50",
        what: "5,000 lines: keystroke to next paint, p50",
        before: "48",
        target: "≤ 16",
        unit: "ms",
    },
    Figure {
        key: "k5_event_p95",
        what: "5,000 lines: keystroke to next paint, p95",
        before: "96",
        target: "≤ 33",
        unit: "ms",
    },
    Figure {
        key: "k5_mark_p50",
        what: "5,000 lines: keystroke to committed drawing, p50",
        before: "39–45",
        target: "≤ 16",
        unit: "ms",
    },
    Figure {
        key: "k5_long_max",
        what: "5,000 lines: longest page task while typing",
        before: "—",
        target: "≤ 50",
        unit: "ms",
    },
    Figure {
        key: "k50_event_p50",
        what: "50,000 lines: keystroke to next paint, p50",
        before: "112",
        target: "≤ 33",
        unit: "ms",
    },
    Figure {
        key: "k50_long_sum",
        what: "50,000 lines: page long tasks over 20 keystrokes",
        before: "≈ 1000",
        target: "0",
        unit: "ms",
    },
    Figure {
        key: "k50_long_max",
        what: "50,000 lines: longest page task while typing",
        before: "—",
        target: "≤ 50",
        unit: "ms",
    },
    Figure {
        key: "l99_ready", what: "L99 from a link: page ready", before: "≈ 19000", target: "≤ 1000", unit: "ms"
    },
    Figure {
        key: "l99_key_event", what: "L99: a keystroke to next paint", before: "—", target: "≤ 100", unit: "ms"
    },
    Figure {
        key: "paste_0_5mb",
        what: "one thread put in the editor, 0.5 MB: to its plan",
        before: "282",
        target: "linear",
        unit: "ms",
    },
    Figure { key: "paste_1mb", what: "… 1 MB", before: "1700", target: "linear", unit: "ms" },
    Figure { key: "paste_2mb", what: "… 2 MB", before: "> 45000", target: "linear", unit: "ms" },
    Figure { key: "paste_5mb", what: "… 5 MB", before: "> 45000", target: "linear", unit: "ms" },
    Figure {
        key: "wasm_20mb_rate", what: "wasm planner, 20 MB program", before: "62", target: "≥ 100", unit: "MB/s"
    },
    Figure {
        key: "native_g01_10mb",
        what: "native planner, 10 MB G01 program",
        before: "≈ 150",
        target: "≥ 250",
        unit: "MB/s",
    },
    Figure {
        key: "native_mixed_20mb",
        what: "native planner, 20 MB mixed program",
        before: "—",
        target: "—",
        unit: "MB/s",
    },
    Figure { key: "wasm_gz_kib", what: "wasm, gzip -9", before: "—", target: "≤ 195 (200 KB)", unit: "KiB" },
    Figure {
        key: "v5_bare_p50",
        what: "5,000 lines: bare editor keystroke to next paint, p50 (the floor)",
        before: "8–16",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v5_screen_p50",
        what: "5,000 lines: app keystroke to diagram on screen, p50",
        before: "26–29",
        target: "≤ 1.25 × floor",
        unit: "ms",
    },
    Figure {
        key: "v5_ratio_p50", what: "… ratio to the floor, p50", before: "1.5–3", target: "≤ 1.25", unit: "×"
    },
    Figure {
        key: "v5_ratio_p95", what: "… ratio to the floor, p95", before: "2.5–3", target: "≤ 1.25", unit: "×"
    },
    Figure {
        key: "v5_alone_ratio_p50",
        what: "… the page alone (the app, its edits not planned) to its next paint, ratio to the floor, p50",
        before: "1.25–1.28 (2026-11-27)",
        target: "—",
        unit: "×",
    },
    Figure {
        key: "v5_apppaint_p50",
        what: "… the app planning: its own next paint, p50 (the figure waits for the later of it and the drawing)",
        before: "22–24 (2026-11-27)",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v5_drawn_later",
        what: "… keystrokes whose drawing came after the page's paint",
        before: "0.01–0.05 (2026-11-27)",
        target: "—",
        unit: "of all",
    },
    Figure {
        key: "v5_bare_work_p50",
        what: "… from the frame's beginning to the bare editor's paint (the figure without the wait for the display's cadence), p50",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v5_app_work_p50",
        what: "… and to the app's diagram on screen, p50",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v5_callback_gap_p50",
        what: "… the app's frame callbacks run later than the bare editor's (its page thread busy when the frame begins), p50",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v5_after_callback_gap_p50",
        what: "… and from them to the task after the frame, longer than the bare editor's (its frame and the tasks before), p50",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "k50_replan_p50",
        what: "50,000 lines: the worker's re-plan after a keystroke, p50",
        before: "10.6–16.7 (2026-11-26)",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "k50_draw_p50",
        what: "… the worker's drawing of the views (display lists, canvas calls), p50",
        before: "8.2–11.8 (2026-11-26)",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "v50_ratio_p50",
        what: "50,000 lines: the same ratio, p50",
        before: "—",
        target: "≤ 1.25",
        unit: "×",
    },
    Figure {
        key: "v50_ratio_p95",
        what: "50,000 lines: the same ratio, p95",
        before: "—",
        target: "≤ 1.25",
        unit: "×",
    },
    Figure {
        key: "load_app_kib",
        what: "the app's first load, transferred (wasm + JS + CSS + page)",
        before: "≈ 491",
        target: "≤ 244 (250 KB)",
        unit: "KiB",
    },
    Figure {
        key: "load_app_first_kib",
        what: "… a first visit's first diagram (the example's drawings in the page): what its first paint waited for",
        before: "the whole first load",
        target: "≤ 244 (250 KB)",
        unit: "KiB",
    },
    Figure {
        key: "load_app_first_ms",
        what: "… that first paint, from the navigation (loopback)",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "load_app_live_ms",
        what: "… the app's own drawing in its place (script, worker and wasm fetched, planned, drawn)",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "load_embed_kib",
        what: "one embedded diagram's first load, transferred",
        before: "≈ 360",
        target: "≤ 195 (200 KB)",
        unit: "KiB",
    },
    Figure {
        key: "load_embed_static_kib",
        what: "the same with its static drawing inside, as `screwcut embed` writes it (the wasm when pointed at)",
        before: "≈ 360",
        target: "≤ 195 (200 KB)",
        unit: "KiB",
    },
    Figure {
        key: "embed_pointed_ms",
        what: "… pointed at: the live drawing drawn (wasm fetched, planned, drawn)",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "native_loops5k_full_ms",
        what: "native planner, 5,000-line Fanuc program with loops: full plan",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "native_typed5k_ms",
        what: "native planner, a digit typed in the first pass, 5,000 lines: re-plan",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure { key: "native_typed50k_ms", what: "… 50,000 lines: re-plan", before: "—", target: "—", unit: "ms" },
    Figure {
        key: "native_loops5k_edit_sub_ms",
        what: "the same, re-plan after a digit typed in a subprogram",
        before: "—",
        target: "—",
        unit: "ms",
    },
    Figure {
        key: "native_loops5k_edit_main_ms",
        what: "the same, re-plan after a digit typed in the main program",
        before: "—",
        target: "—",
        unit: "ms",
    },
];

/// A figure of the Fanuc program with subprograms and macro loops (issue
/// #19), whose "before" is the plain 5,000-line program's figure `plain`
/// measured in the same run; its target is to be no worse.
struct Versus {
    key: &'static str,
    plain: &'static str,
    what: &'static str,
    unit: &'static str,
}

const VERSUS: &[Versus] = &[
    Versus {
        key: "k5loop_event_p50",
        plain: "k5_event_p50",
        what: "loop program, main program: keystroke to next paint, p50 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loop_event_p95",
        plain: "k5_event_p95",
        what: "loop program, main program: keystroke to next paint, p95 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loop_mark_p50",
        plain: "k5_mark_p50",
        what: "loop program, main program: keystroke to committed drawing, p50 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loop_long_max",
        plain: "k5_long_max",
        what: "loop program, main program: longest page task while typing (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loopsub_event_p50",
        plain: "k5_event_p50",
        what: "loop program, subprogram: keystroke to next paint, p50 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loopsub_event_p95",
        plain: "k5_event_p95",
        what: "loop program, subprogram: keystroke to next paint, p95 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loopsub_mark_p50",
        plain: "k5_mark_p50",
        what: "loop program, subprogram: keystroke to committed drawing, p50 (before: plain, this run)",
        unit: "ms",
    },
    Versus {
        key: "k5loopsub_long_max",
        plain: "k5_long_max",
        what: "loop program, subprogram: longest page task while typing (before: plain, this run)",
        unit: "ms",
    },
];

/// Runs `program args` in `dir`, printing its output but for `FIG name value`
/// and `RATE name value` lines, which are returned.
fn figures_of(
    program: &str,
    args: &[&str],
    dir: &std::path::Path,
    env: &[(&str, String)],
) -> Result<Vec<(String, f64)>> {
    let mut cmd = Command::new(program);
    cmd.args(args).current_dir(dir).stderr(Stdio::inherit());
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().map_err(|e| format!("cannot run {program}: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let mut figs = Vec::new();
    for line in text.lines() {
        let rest = line.strip_prefix("FIG ").or_else(|| line.strip_prefix("RATE "));
        match rest.and_then(|r| r.split_once(' ')) {
            Some((k, v)) => figs.push((k.to_string(), v.trim().parse().unwrap_or(f64::NAN))),
            None => println!("{line}"),
        }
    }
    if !out.status.success() {
        return Err(format!("{program} {} failed ({})", args.join(" "), out.status));
    }
    Ok(figs)
}

/// The machine: CPU model and count, memory, and the date.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let mem = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|s| s.lines().next().and_then(|l| l.split_whitespace().nth(1)).and_then(|k| k.parse::<f64>().ok()))
        .map_or(String::new(), |k| format!(", {:.0} GiB", k / 1024.0 / 1024.0));
    let date = install::output("date", &["-u", "+%Y-%m-%d %H:%M UTC"]).unwrap_or_default();
    format!("{} · {cpu} × {cores}{mem}", date.trim())
}

/// `cargo xtask bench`.
pub fn bench(args: &[String]) -> Result {
    if let Some(a) = args.first() {
        return Err(format!("bench: unknown option '{a}' (usage: cargo xtask bench)"));
    }
    let root = install::root();
    let mut figs: BTreeMap<String, f64> = BTreeMap::new();
    eprintln!("\n== native throughput and memory");
    let native = figures_of("cargo", &["bench", "--bench", "throughput"], &root, &[])?;
    let rates: Vec<String> =
        native.iter().filter(|(k, _)| k.ends_with(".nc")).map(|(k, v)| format!("{k}={v}")).collect();
    for (k, v) in &native {
        figs.insert(format!("native_{}", k.trim_end_matches(".nc").replace('-', "_")), *v);
    }
    eprintln!("\n== wasm build and size");
    let site = root.join("target").join("site-bench");
    web::build_site(true, &site)?;
    for m in crate::wasm::MODULES {
        let wasm = site.join(m.wasm_file());
        let raw = std::fs::metadata(&wasm).map_err(|e| format!("{}: {e}", wasm.display()))?.len();
        let gz = Command::new("gzip")
            .args(["-9", "-c"])
            .arg(&wasm)
            .output()
            .map_err(|e| format!("cannot run gzip: {e}"))?
            .stdout
            .len();
        let br = crate::precompress::br_size(&wasm) as f64 / 1024.0;
        println!(
            "{} ({}): {raw} bytes raw, {gz} bytes gzipped (-9) ({:.1} KiB), {br:.1} KiB Brotli",
            m.wasm_file(),
            if m.feature == "view" { "loaded first" } else { "loaded when a tool is first used" },
            gz as f64 / 1024.0
        );
        if m.feature == "view" {
            figs.insert("wasm_gz_kib".into(), gz as f64 / 1024.0);
        }
    }
    let bench = root.join("bench");
    install::ensure_npm(&bench)?;
    let programs = root.join("target").join("bench");
    let p = |name: &str| programs.join(name).display().to_string();
    let pkg = root.join("www").join("pkg").display().to_string();
    eprintln!("\n== gcode-toolpath side by side (Node)");
    println!("gcode-toolpath (cncjs) and screwcut on the same files:");
    figures_of(
        "node",
        &["toolpath.mjs", &pkg, &p("mixed-1mb.nc"), &p("mixed-20mb.nc")],
        &bench,
        &[("NATIVE_RATES", rates.join(","))],
    )?;
    eprintln!("\n== headless Chromium");
    install::ensure_chromium()?;
    let chromium = install::output("chromium", &["--version"]).unwrap_or_default();
    println!("headless Chromium ({}):", chromium.trim());
    let browser = figures_of(
        "node",
        &["browser.mjs", &site.display().to_string(), &pkg, &p("mixed-20mb.nc"), &p("loops-5000.nc")],
        &bench,
        &[],
    )?;
    figs.extend(browser);
    summary(&figs, chromium.trim());
    Ok(())
}

/// The table of figures: before, now, target.
fn summary(figs: &BTreeMap<String, f64>, chromium: &str) {
    let mut t = Table::new();
    t.load_style(UTF8_FULL_CONDENSED);
    t.set_header(["figure", "before (2026-11)", "now", "target", "unit"]);
    for f in FIGURES {
        t.add_row([f.what, f.before, &shown(figs, f.key, f.unit), f.target, f.unit]);
    }
    for f in VERSUS {
        let before = shown(figs, f.plain, f.unit);
        t.add_row([f.what, &before, &shown(figs, f.key, f.unit), "≤ plain 5,000 lines", f.unit]);
    }
    println!("\n{}  ({chromium})\n{t}", machine());
    println!(
        "(Event Timing reports only events of 16 ms and more: \"< 16\" is a keystroke painted within one 60 Hz frame.)"
    );
}

/// Figure `key` as the table shows it.
fn shown(figs: &BTreeMap<String, f64>, key: &str, unit: &str) -> String {
    figs.get(key).map_or("not measured".to_string(), |v| {
        if v.is_nan() {
            "n/a".into()
        } else if unit == "ms" && *v < 16.0 && key.contains("event") {
            "< 16".into()
        } else if unit == "×" {
            format!("{v:.2}")
        } else {
            format!("{v:.1}")
        }
    })
}
