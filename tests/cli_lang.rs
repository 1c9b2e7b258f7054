#![cfg(not(target_arch = "wasm32"))]
//! `screwcut plan --lang`: the summary and its diagnostics in Chinese, the
//! JSON unchanged (English messages with their arguments).

use std::process::Command;

fn screwcut(args: &[&str]) -> (String, i32) {
    let out = Command::new(env!("CARGO_BIN_EXE_screwcut"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("screwcut runs");
    (String::from_utf8(out.stdout).expect("UTF-8"), out.status.code().unwrap_or(-1))
}

#[test]
fn plan_in_chinese() {
    let (zh, code) = screwcut(&["plan", "examples/o1006.nc", "--lang", "zh"]);
    assert_eq!(code, 0);
    assert!(
        zh.contains("5:1: 提示 [crest-assumed] 程序没有车出这个螺纹的大径：按最深一刀和 d = D − 1.3·P 假定牙顶在 X48"),
        "{zh}"
    );
    assert!(zh.contains("螺纹 1（第 5-24 行）：直螺纹 G32（mm），导程 2") && zh.contains("精车"), "{zh}");
    assert!(!zh.contains("crest assumed") && !zh.contains("rough"), "{zh}");
}

#[test]
fn plan_in_english_by_default_and_json_unchanged() {
    let (en, _) = screwcut(&["plan", "examples/o1006.nc"]);
    let (en2, _) = screwcut(&["plan", "examples/o1006.nc", "--lang", "en"]);
    assert_eq!(en, en2);
    assert!(en.contains(
        "5:1: note [crest-assumed] the program does not turn this thread's major diameter: crest assumed at X48"
    ));
    let (json, _) = screwcut(&["plan", "examples/o1006.nc", "--json", "--lang", "zh"]);
    assert!(json.contains("\"message\":\"the program does not turn this thread's major diameter"), "{json}");
    assert!(
        json.contains("\"args\":{\"what\":\"turn this thread's major diameter\",\"axis\":\"X\",\"crest\":48.0"),
        "{json}"
    );
    let (_, code) = screwcut(&["plan", "examples/o1006.nc", "--lang", "fr"]);
    assert_eq!(code, 2);
}

/// `generate` and `expand` say their notes and refusals in the language asked for, on standard error.
#[test]
fn generate_and_expand_in_chinese() {
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_screwcut"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .expect("screwcut runs");
        (String::from_utf8(out.stdout).unwrap(), String::from_utf8(out.stderr).unwrap(), out.status.code())
    };
    let g = ["generate", "M30x2-6g", "--length", "30", "--form", "g76"];
    let (en_prog, en, _) = run(&g);
    let (zh_prog, zh, code) = run(&[&g[..], &["--lang", "zh"]].concat());
    assert_eq!((code, &en_prog), (Some(0), &zh_prog), "the program does not depend on the language");
    assert!(en.contains("screwcut: note: the last pass puts the pitch diameter in the middle"), "{en}");
    assert!(zh.contains("screwcut: note: 最后一刀使中径落在公差带中间，刀具为 60°、刀尖圆弧半径 0"), "{zh}");
    let (_, zh, code) = run(&["generate", "M30x2", "--form", "g78", "--dialect", "fanuc0i", "--lang", "zh"]);
    assert_eq!(code, Some(2));
    assert!(zh.contains("Fanuc 0i-TF 没有 G78 增强螺纹循环 格式；可选：g32, g92, g76"), "{zh}");
    let (_, zh, code) = run(&["expand", "examples/renhe-tails.nc", "--dialect", "renhe", "--lang", "zh"]);
    assert_eq!(code, Some(0));
    assert_eq!(zh.trim_end(), "screwcut: note: 计划里没有进给速度：车削运动按 F0.2 写出");
}
