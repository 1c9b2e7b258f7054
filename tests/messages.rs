#![cfg(not(target_arch = "wasm32"))]
//! The message catalogue: every code in both languages, every argument a
//! template names given by every site that emits it (over the examples,
//! LinuxCNC's test programs and the fuzz corpus), Chinese without English
//! words, and a few Chinese messages as they read.

mod common;
use common::*;

use std::collections::BTreeSet;
use std::path::Path;

use screwcut::message::{self, Lang, Message};
use screwcut::{Code, Dialect, Plan, Settings};

/// Every program the tests have: (name, dialect, text).
fn programs() -> Vec<(String, Dialect, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    let index: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("examples/index.json")).unwrap()).unwrap();
    for e in index.as_array().unwrap() {
        let file = e["file"].as_str().unwrap();
        let dialect = Dialect::parse(e["dialect"].as_str().unwrap()).unwrap();
        out.push((file.to_string(), dialect, std::fs::read_to_string(root.join("examples").join(file)).unwrap()));
    }
    for dir in ["tests/linuxcnc", "fuzz/corpus/plan"] {
        let mut files: Vec<_> = std::fs::read_dir(root.join(dir)).unwrap().flatten().map(|e| e.path()).collect();
        files.sort();
        for f in files {
            if f.extension().is_some_and(|x| x == "out" || x == "err" || x == "md") {
                continue;
            }
            let text = String::from_utf8_lossy(&std::fs::read(&f).unwrap()).into_owned();
            let name = f.file_name().unwrap().to_string_lossy().into_owned();
            let dialects: &[Dialect] = if dir == "tests/linuxcnc" { &[Dialect::LinuxCnc] } else { &Dialect::ALL };
            for d in dialects {
                out.push((name.clone(), *d, text.clone()));
            }
        }
    }
    out
}

fn plan(text: &str, d: Dialect) -> Plan {
    screwcut::plan(text, &Settings::new(d))
}

/// Every template and phrase of the catalogue names the same arguments in both languages.
#[test]
fn both_languages_name_the_same_arguments() {
    let set = |t: &'static str| message::names(t).into_iter().collect::<BTreeSet<_>>();
    for t in message::all() {
        assert!(!t.en.is_empty() && !t.zh.is_empty(), "{}", t.name);
        assert_eq!(set(t.en), set(t.zh), "{}", t.name);
    }
    for p in message::all_phrases() {
        assert_eq!(set(p.en), set(p.zh), "{:?}", p.en);
    }
}

/// Every code has a message in both languages (its templates carry it).
#[test]
fn every_code_has_both_templates() {
    for code in Code::ALL {
        let t = message::all().find(|t| t.code == *code);
        assert!(t.is_some_and(|t| !t.en.is_empty() && !t.zh.is_empty()), "{code} has no template");
    }
}

/// Every diagnostic and thread-check note of every program, in both
/// languages: arguments named and given agree, the English is the message,
/// the Chinese has no English words.
#[test]
fn every_message_of_every_program_renders_in_both_languages() {
    let mut seen = BTreeSet::new();
    let mut bad = Vec::new();
    let mut n = 0;
    for (name, dialect, text) in programs() {
        let p = plan(&text, dialect);
        let notes = p.threads.iter().filter_map(|t| t.shop.gauge.as_ref()).flat_map(|g| g.notes.iter());
        let messages: Vec<(Message, String)> = p
            .diagnostics
            .iter()
            .map(|d| (Message::new(d.template, d.args.clone()), check_languages(d)))
            .chain(notes.map(|m| (m.clone(), check_message(m))))
            .collect();
        for (m, zh) in messages {
            n += 1;
            seen.insert(m.template.name);
            let english = english_words(&zh);
            if !english.is_empty() {
                bad.push(format!("{name} ({}) {}: {english:?} in {zh:?}", dialect.name(), m.template.name));
            }
        }
    }
    bad.sort();
    bad.dedup_by(|a, b| a.split(':').next() == b.split(':').next());
    assert!(bad.is_empty(), "English words in Chinese messages:\n{}", bad.join("\n"));
    assert!(n > 1000, "only {n} messages");
    let unseen: Vec<&str> = message::all().map(|t| t.name).filter(|t| !seen.contains(t)).collect();
    eprintln!("{n} messages of {} templates; not emitted by any program: {unseen:?}", seen.len());
}

/// The checker finds English, and leaves quoted LinuxCNC messages, words, settings and codes alone.
#[test]
fn the_english_checker_finds_english() {
    assert_eq!(english_words("程序 does not turn 大径"), ["does", "not", "turn"]);
    assert!(english_words("LinuxCNC 报警“Spindle not turning in G33”：请先用 M3 或 M4").is_empty());
    assert!(english_words("'G01 Z5' 在 ';' 之后；设置 limits.diagnostics，参数 No.107，E18-03，3401#0").is_empty());
}

fn zh_of(text: &str, dialect: Dialect, code: Code) -> String {
    let p = plan(text, dialect);
    let d = p.with_code(code).next().unwrap_or_else(|| panic!("no {code} in {:?}", p.diagnostics));
    d.render(Lang::Zh).into_owned()
}

/// A few messages as a lathe programmer reads them.
#[test]
fn chinese_messages_read_as_written() {
    let o1006 = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/o1006.nc")).unwrap();
    assert_eq!(
        zh_of(&o1006, Dialect::Gsk980tdc, Code::CrestAssumed),
        "程序没有车出这个螺纹的大径：按最深一刀和 d = D − 1.3·P 假定牙顶在 X48，各刀切深都相对于它计算；不检查教材中的 δ1/δ2"
    );
    assert_eq!(
        zh_of(&o1006, Dialect::Gsk980tdc, Code::InfeedGuidance),
        "表 4-3 螺距 2：5 刀，直径进刀量 0.9 0.6 0.6 0.4 0.1；程序：5 刀，0.9 0.6 0.6 0.4 0.1（与表相同）"
    );
    assert_eq!(
        zh_of("G00 X50 Z10\nG00 U-16\nG33 W-3 U1 F1.5\n", Dialect::Renhe, Code::E18_04),
        "E18-04：螺纹长度 |W| = 3 必须大于 |U| = 1，并且大于 4 mm"
    );
    assert_eq!(
        zh_of("G18 G21 G7\nG0 X14 Z3\nG33 Z-10 K1.5\nM2\n", Dialect::LinuxCnc, Code::SpindleNotTurning),
        "LinuxCNC 报警“Spindle not turning in G33”：请先用 M3 或 M4 启动主轴"
    );
    assert_eq!(zh_of("G04\n", Dialect::Gsk980tdc, Code::MissingWord), "G04 需要暂停时间：P（ms）、X 或 U（s）");
    assert_eq!(
        zh_of("G00 X10 X20\n", Dialect::Gsk980tdc, Code::RepeatedWord),
        "地址 X 在同一程序段内出现两次（X10 和 X20）"
    );
}

/// The JSON keeps the English message and adds the arguments.
#[test]
fn json_diagnostics_carry_their_arguments() {
    let p = plan("G00 X10 X20\n", Dialect::Gsk980tdc);
    let v: serde_json::Value = serde_json::from_str(&p.to_json()).unwrap();
    let d = &v["diagnostics"][0];
    assert_eq!(d["message"], "address X appears twice in one block (X10 and X20)");
    assert_eq!(d["args"], serde_json::json!({"letter": "X", "first": "X10", "second": "X20"}));
}

/// Designations the parser or the tables refuse: their messages in both languages.
#[test]
fn designation_errors_in_both_languages() {
    let mut seen = BTreeSet::new();
    let mut bad = Vec::new();
    for s in [
        "",
        "M10x1.5-6k",
        "M10x1.5-2g",
        "M10x1.5-6g6H",
        "M20x2-6H/6g",
        "M30xPh5P2",
        "M15",
        "Mx1",
        "1/4-20 UNX-2A",
        "1-1/16 UN",
        "1/2-18 NPT",
        "1/2-14 NPTF",
        "1/2-14 NPTX",
        "Mé",
        "G32 Z13 F2",
        "M10x-6g",
        "M30xPh",
        "M30xPh6",
        "M10x1.5-6g6g",
        "1/4-20 UNC-4A",
        "x-20 UNC",
        "1/4 UN",
        "13/16-14 NPT",
        "-14 NPT",
        "1/4-20 UNC-2A 6g",
        "M22x3-6g",
        "M1-6H",
        "M10x0.1-6g",
        "M2000x2-6g",
        "M10x1.5",
        "1/4-20 UNC",
        "M10x1.5-3G",
    ] {
        let e = match screwcut::standard::parse(s) {
            Err(e) => e,
            Ok(d) => match screwcut::standard::limits(&d) {
                Err(e) => e,
                Ok(_) => continue,
            },
        };
        assert_eq!(e.message, e.detail.render(Lang::En));
        let zh = check_message(&e.detail);
        seen.insert(e.detail.template.name);
        let english = english_words(&zh);
        if !english.is_empty() {
            bad.push(format!("{s:?}: {english:?} in {zh:?}"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert!(seen.len() >= 20, "{seen:?}");
}

/// The shop checks, limits and thread check under settings that trigger them.
#[test]
fn shop_checks_and_limits_in_both_languages() {
    let settings: &[&[&str]] = &[
        &["limits.diagnostics=1"],
        &["limits.moves=5"],
        &["limits.program_bytes=100"],
        &["machine.max_thread_feed=100", "machine.max_rpm=50", "tool.max_chip_area=0.01"],
        &["No.107=400"],
        &["thread.designation=M48x2-6g", "tool.nose_radius=0.25"],
        &["thread.designation=M48x2-6H", "tool.nose_radius=0.125"],
        &["thread.designation=M48x1.5-6g"],
        &["thread.designation=1/2-14 NPT"],
        &["thread.designation=bogus"],
        &["limits.starts=1", "limits.passes_per_start=3"],
    ];
    let mut seen = BTreeSet::new();
    let mut bad = Vec::new();
    for (name, dialect, text) in programs().into_iter().filter(|(n, ..)| !n.chars().all(|c| c.is_ascii_hexdigit())) {
        for sets in settings {
            let mut s = Settings::new(dialect);
            for a in *sets {
                let _ = s.assign(a); // a setting of another dialect is left out
            }
            let p = screwcut::plan(&text, &s);
            let notes = p.threads.iter().filter_map(|t| t.shop.gauge.as_ref()).flat_map(|g| g.notes.iter());
            let all: Vec<(&str, String)> = p
                .diagnostics
                .iter()
                .map(|d| (d.template.name, check_languages(d)))
                .chain(notes.map(|m| (m.template.name, check_message(m))))
                .collect();
            for (t, zh) in all {
                seen.insert(t);
                let english = english_words(&zh);
                if !english.is_empty() {
                    bad.push(format!("{name} {sets:?} {t}: {english:?} in {zh:?}"));
                }
            }
        }
    }
    bad.sort();
    bad.dedup();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    for t in [
        "MORE_DIAGNOSTICS",
        "MOVE_LIMIT",
        "THREAD_FEED_LIMIT",
        "SPINDLE_LIMIT",
        "GAUGE_FAIL",
        "BAD_DESIGNATION_SETTING",
    ] {
        assert!(seen.contains(t), "{t} not emitted: {seen:?}");
    }
    eprintln!("{} templates under settings: {seen:?}", seen.len());
}

/// What the writing tools say, in Chinese without English words: the
/// wizard's notes and refusals over designations, controllers and forms,
/// and `expand`'s notes over the examples written for every controller.
#[test]
fn the_writing_tools_speak_both_languages() {
    use screwcut::wizard::{Form, Request, generate};
    let mut said: Vec<message::Remark> = Vec::new();
    let designations = ["M10x1.5-6g", "M24xPh3P1.5", "1/2-14 NPT", "M20x1.5-6H", "1/2-13 UNC-2A"];
    for d in designations {
        for dialect in Dialect::ALL {
            for form in Form::ALL {
                let r =
                    Request { designation: Some(d.into()), length: Some(25.0), dialect, form, ..Request::default() };
                match generate(&r) {
                    Ok(g) => said.extend(g.notes),
                    Err(e) => said.push(e),
                }
            }
        }
    }
    let base = Request { length: Some(25.0), ..Request::default() };
    let refused = [
        Request { length: None, designation: Some("M30x2".into()), ..base.clone() },
        Request { major: Some(-3.0), lead: Some(1.0), ..base.clone() },
        Request { major: Some(30.0), lead: Some(2.0), end_z: Some(0.0), ..base.clone() },
        Request { designation: Some("M30x2".into()), max_feed: 1.0, ..base.clone() },
        Request { major: Some(1.5), lead: Some(0.3), internal: Some(true), ..base.clone() },
        Request { designation: Some("M30x15".into()), dialect: Dialect::Renhe, form: Form::RenheG33, ..base.clone() },
        Request { designation: Some("Q12".into()), ..base.clone() },
    ];
    for r in &refused {
        said.push(generate(r).err().unwrap_or_else(|| panic!("{r:?} was written")));
    }
    for (_, dialect, text) in
        programs().into_iter().filter(|(n, ..)| n.ends_with(".nc") || n.ends_with(".ngc")).take(60)
    {
        let plan = plan(&text, dialect);
        for to in Dialect::ALL {
            said.extend(screwcut::expand::expand(&plan, to).notes);
        }
    }
    let mut bad = Vec::new();
    let mut seen = BTreeSet::new();
    for r in &said {
        let (en, zh) = (r.render(Lang::En), r.render(Lang::Zh));
        seen.insert(r.phrase.en);
        assert_eq!(en, r.to_string());
        if en.contains('{') || zh.contains('{') || !english_words(&zh).is_empty() {
            bad.push(format!("{zh:?}: {:?}", english_words(&zh)));
        }
    }
    bad.sort();
    bad.dedup();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert!(seen.len() >= 15, "only {} of the tools' phrases said: {seen:#?}", seen.len());
}
