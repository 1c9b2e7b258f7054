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
    assert!(zh.contains("螺纹 1（第 5-24 行）：直螺纹 G32，导程 2") && zh.contains("精车"), "{zh}");
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
