#![cfg(not(target_arch = "wasm32"))]
//! Property tests of LinuxCNC's G71/G72 roughing (`cycle::g7x`): a profile
//! subroutine of any moves (G0–G3 with R, I, K, corners A and C, moves of
//! no length, turning back) roughed by any of G71, G71.1, G71.2, G72,
//! G72.1, G72.2 with any D, I and R (none, negative, zero, tiny, huge)
//! plans without a panic, in bounded time, keeping the invariants of
//! `props::check`; its cuts are at most the cycle's bound (10000, three
//! roughing moves each in a pocket) and it says so when it stops there.

mod common;
#[path = "common/props.rs"]
mod props;

use proptest::collection::vec;
use proptest::prelude::*;
use screwcut::motion::MoveKind;
use screwcut::{Code, Dialect, Settings};

/// A profile move: motion code, X, Z, centre or radius words, corner.
fn profile_move() -> impl Strategy<Value = String> {
    let g = prop::sample::select(vec!["G0", "G1", "G1", "G2", "G3", ""]);
    let len = prop_oneof![
        (-60i32..60).prop_map(|v| v.to_string()),
        (-600i32..600).prop_map(|v| format!("{}", v as f64 / 10.0))
    ];
    let centre =
        prop::sample::select(vec!["", "", " R2", " R-3", " R0.4", " I2", " K-2", " I1 K-1", " R2 K1", " R1e9"]);
    let corner = prop::sample::select(vec!["", "", "", " A1", " C0.5", " A0", " A1 C1", " A-2", " C40"]);
    (g, len.clone(), len, centre, corner, 0u8..4).prop_map(|(g, x, z, c, k, axes)| {
        let xs = if axes & 1 == 0 { format!(" X{x}") } else { String::new() };
        let zs = if axes & 2 == 0 { format!(" Z{z}") } else { String::new() };
        format!("{g}{xs}{zs}{c}{k}")
    })
}

/// A profile a part could have: from the face inwards along Z, the
/// diameter growing, with steps, tapers, grooves (pockets), arcs and corners.
fn part_profile() -> impl Strategy<Value = Vec<String>> {
    let step = (0u8..6, 1u8..5, prop::sample::select(vec!["", "", "", " A0.5", " C0.4"]));
    (2u8..10, vec(step, 1..8)).prop_map(|(x0, steps)| {
        let (mut x, mut z) = (f64::from(x0), 0.0);
        let mut out = vec![format!("G1 X{x} Z0")];
        for (kind, k, corner) in steps {
            let k = f64::from(k);
            let line = match kind {
                0 => {
                    z -= 2.0 * k;
                    format!("G1 Z{z}{corner}")
                }
                1 => {
                    x += k;
                    format!("G1 X{x}{corner}")
                }
                2 => {
                    x += k / 2.0;
                    z -= k;
                    format!("G1 X{x} Z{z}")
                }
                3 if x > 2.0 * k => {
                    x -= k;
                    z -= k;
                    format!("G1 X{x} Z{z}")
                }
                4 => {
                    x += 2.0 * k;
                    z -= k;
                    format!("G2 X{x} Z{z} R{k}")
                }
                _ => {
                    x += 2.0 * k;
                    z -= k;
                    format!("G3 X{x} Z{z} K-{k}")
                }
            };
            out.push(line);
        }
        out.push(format!("G1 Z{}", z - 3.0));
        out
    })
}

/// A cycle word's value, from the ordinary to the absurd.
fn value(ordinary: &'static [&'static str]) -> impl Strategy<Value = Option<&'static str>> {
    let odd = prop::sample::select(vec!["-1", "0", "0.0000001", "1e9", "-0.5", "40"]);
    prop_oneof![4 => prop::sample::select(ordinary.to_vec()).prop_map(Some), 2 => odd.prop_map(Some), 1 => Just(None)]
}

/// A program: the profile in o100, a start point, one roughing cycle, a
/// move after it; and the cycle's line.
fn program() -> impl Strategy<Value = (String, u32)> {
    let code = prop::sample::select(vec!["G71", "G71", "G71.1", "G71.2", "G72", "G72", "G72.1", "G72.2"]);
    let mode = prop::sample::select(vec!["G7", "G8"]);
    let any = (vec(profile_move(), 0..10), (-60i32..60, -20i32..20));
    let part = (part_profile(), (30i32..90, 1i32..5));
    (
        prop_oneof![any, part],
        code,
        mode,
        value(&["0", "0.2", "0.5", "1"]),
        value(&["0.5", "1", "1.5", "2"]),
        value(&["0.2", "0.5", "1"]),
    )
        .prop_map(|((moves, (x, z)), code, mode, d, i, r)| {
            let word = |l: &str, v: Option<&str>| v.map_or(String::new(), |v| format!(" {l}{v}"));
            let words = format!("{}{}{}", word("D", d), word("I", i), word("R", r));
            let text = format!(
                "G18 G21 G90 {mode}\nM3 S500\no100 sub\n{}\no100 endsub\nG0 X{x} Z{z}\n{code} Q100 X{x} Z{z}{words} F100\nG0 X70 Z30\nM2\n",
                moves.join("\n")
            );
            (text, 6 + moves.len().max(1) as u32)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    #[test]
    fn any_profile_is_roughed_within_bounds((text, line) in program()) {
        let s = Settings::new(Dialect::LinuxCnc);
        let started = std::time::Instant::now();
        let plan = screwcut::plan(&text, &s);
        props::check(&text, &s, &plan);
        prop_assert!(started.elapsed().as_secs_f64() < 20.0, "{:?} to plan", started.elapsed());
        prop_assert!(text.lines().nth(line as usize - 1).is_some_and(|l| l.starts_with("G7")), "line {line}");
        let cuts = plan.moves.iter().filter(|m| m.line == line && m.kind == MoveKind::Rough).count();
        let bounded = plan.with_code(Code::PassLimit).next().is_some();
        // A cut is one roughing move, in a pocket three (down the wall, across, back); the profile's pieces are fewer.
        prop_assert!(cuts <= 3 * 10_000 + 20, "{cuts} roughing moves");
        prop_assert!(bounded || cuts <= 3 * 10_000, "{cuts} roughing moves and no word of the bound");
    }
}

/// The absurd cases the strategy may miss, planned once each.
#[test]
fn absurd_words_and_profiles_plan() {
    let cases = [
        ("G1 X20 Z0\nG1 X20 Z-10", "G71", "D1e9 I1 R0.5"),
        ("G1 X20 Z0\nG1 X30 Z-10", "G71", "D0 I0.0000001 R0.5"),
        ("G1 X20 Z0\nG1 X30 Z-10", "G72", "D-5 I1 R-1"),
        ("G1 X20 Z0\nG2 X30 Z-10 R1", "G71", "D0.5 I1 R0.5"),
        ("G1 X20 Z0\nG3 X20 Z0 I5", "G71", "D0.5 I1 R0"),
        ("G1 X20 Z0\nG1 X20 Z0\nG1 X20 Z0", "G71.2", "D0.5 I1"),
        ("G1 X20 Z0 A1\nG1 X30 Z-10 C1\nG1 Z-20 A30", "G71", "D0.5 I1"),
        ("G1 X1e300 Z0\nG1 X20 Z-1e300", "G71", "D0.5 I1"),
    ];
    for (profile, code, words) in cases {
        let text = format!(
            "G18 G21 G90 G7\nM3 S500\no100 sub\n{profile}\no100 endsub\nG0 X40 Z5\n{code} Q100 X40 Z5 {words}\nM2\n"
        );
        let s = Settings::new(Dialect::LinuxCnc);
        let plan = screwcut::plan(&text, &s);
        props::check(&text, &s, &plan);
    }
}
