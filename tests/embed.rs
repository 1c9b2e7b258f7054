#![cfg(not(target_arch = "wasm32"))]
//! `screwcut embed`: a program as a `<screwcut-preview>` with its static
//! drawings and pass table inside, its alarms and warnings on standard error.

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs `screwcut embed ARGS` with `stdin`: (stdout, stderr, exit code).
fn embed(args: &[&str], stdin: &str) -> (String, String, i32) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_screwcut"))
        .arg("embed")
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("screwcut runs");
    // A refused option ends the command before it reads: the pipe may be closed.
    let _ = child.stdin.take().expect("stdin").write_all(stdin.as_bytes());
    let out = child.wait_with_output().expect("screwcut ends");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8");
    (text(out.stdout), text(out.stderr), out.status.code().unwrap_or(-1))
}

#[test]
fn the_example_as_an_element_with_its_drawings_and_passes() {
    let (html, err, code) =
        embed(&["examples/o1006.nc", "--view", "table,tooth,side", "--height", "300", "--width", "701"], "");
    assert_eq!((code, err.as_str()), (0, ""));
    // The views in the element's order; two drawings share the 701 px row: (701 − 1) / 2 each.
    assert!(
        html.starts_with("<screwcut-preview dialect=\"gsk980tdc\" view=\"side tooth table\" height=\"300\">\n<svg "),
        "{html}"
    );
    assert_eq!(html.matches("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"350\" height=\"283\"").count(), 2);
    // o1006 cuts M48×2 in passes X47.1, 46.5, 45.9, 45.5, 45.4 (its own comments).
    for x in ["47.1", "46.5", "45.9", "45.5", "45.4"] {
        assert!(html.contains(&format!("</td><td>1</td><td>{x}</td>")), "pass at X{x}: {html}");
    }
    assert!(html.ends_with("</screwcut-preview>\n"));
    assert!(!html.contains("\n\n"));
}

#[test]
fn alarms_go_to_standard_error_with_the_files_line_and_into_the_element() {
    // Fanuc 0i: G32 with no lead yet is an alarm (on line 4 of the text: the
    // blank line before the program is dropped from the element but counted here).
    let (html, err, code) = embed(&["-", "-d", "fanuc0i", "--lang", "zh"], "\nG00 X58. Z70.\nX47.1\nG32 Z13.\n");
    assert_eq!(code, 0, "a program with alarms is drawn too");
    assert!(
        html.starts_with("<screwcut-preview dialect=\"fanuc0i\" view=\"side\" height=\"320\" lang=\"zh\">\n"),
        "{html}"
    );
    // In the element, on the program's line 3.
    assert!(
        html.contains("<li class=\"error\" data-line=\"3\"><b>3:1 报警</b> <code>[missing-lead]</code> "),
        "{html}"
    );
    assert!(err.starts_with("-:4:1: 报警 [missing-lead] "), "{err}");
}

#[test]
fn bad_options_are_refused() {
    for (args, said) in [
        (&["-", "--view", "front"][..], "unknown view 'front' (known: side, tooth, starts, table)"),
        (&["-", "--app", "javascript:alert(1)"][..], "app 'javascript:alert(1)' is not an http(s) or relative URL"),
        (&["-", "--height", "50"][..], "--height"),
        (&["-", "--width", "NaN"][..], "--width NaN is not a width in px from 120 to 10000"),
        (&["-", "--set", "No.999=1"][..], "No.999"),
    ] {
        let (html, err, code) = embed(args, "G00 X58 Z70\n");
        assert_eq!((code, html.as_str()), (2, ""), "{args:?}");
        assert!(err.contains(said), "{args:?}: {err}");
    }
}
