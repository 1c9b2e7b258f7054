#![cfg(not(target_arch = "wasm32"))]
//! Property test: a Fanuc 0i or GSK980TDc program that calls subprograms
//! (`M98 P… Ln`, packed counts, repeated calls, `G65` with arguments, calls
//! in loops and in subprograms, counters in variables) cuts the same passes
//! and makes the same motions as the program written out by the generator:
//! each call replaced by its body `n` times, each counter by its value; with
//! each subprogram called once, no block counts against `limits.blocks`.
//! (The other properties of the program flow are in `flow_properties.rs`.)

mod common;

use proptest::collection::vec;
use proptest::prelude::*;
use screwcut::settings::P;
use screwcut::{Dialect, Settings};

/// A step of a program that calls subprograms, for the comparison with the
/// program written out. X in thousandths above 45 mm.
#[derive(Clone, Debug)]
enum Step {
    /// A pass at a fixed X (G32, or G92 when true).
    Pass(u16, bool),
    /// The program's counter goes up by one; a pass at X0 − dX·counter.
    Count(u16, u16, bool),
    /// A call: subprogram, count, form (`L`, packed, the call written n times).
    Call(u8, u8, u8),
    /// A loop run n times over its steps: WHILE, or a backward GOTO when true.
    Loop(u8, Vec<Step>, bool),
    /// `G65 P3000 Ln A<X> B2.` (Fanuc 0i; GSK980TDc sets #1 and #2 and calls
    /// with M98): a pass at X − 0.01·counter.
    Macro(u16, u8),
}

fn leaf() -> impl Strategy<Value = Step> {
    prop_oneof![
        (0u16..3000, any::<bool>()).prop_map(|(x, g)| Step::Pass(x, g)),
        (0u16..3000, 5u16..100, any::<bool>()).prop_map(|(x, d, g)| Step::Count(x, d, g)),
        (0u8..4, 1u8..4, 0u8..3).prop_map(|(s, n, f)| Step::Call(s, n, f)),
    ]
}

/// The main program's steps and each subprogram's (a subprogram calls only later ones).
type Calls = (Vec<Step>, Vec<Vec<Step>>);

fn calls() -> impl Strategy<Value = Calls> {
    let step = prop_oneof![
        3 => leaf(),
        1 => (1u8..4, vec(leaf(), 1..3), any::<bool>()).prop_map(|(n, s, g)| Step::Loop(n, s, g)),
        1 => (0u16..3000, 1u8..4).prop_map(|(x, n)| Step::Macro(x, n)),
    ];
    (vec(step.clone(), 1..5), vec(vec(step, 1..4), 1..5))
}

/// A length in thousandths as Fanuc writes it.
fn mm(thousandths: i64) -> String {
    let (sign, t) = (if thousandths < 0 { "-" } else { "" }, thousandths.abs());
    format!("{sign}{}.{:03}", t / 1000, t % 1000)
}

/// X0 − d·n rounded to the least increment, as the controller computes it.
fn less(x0: &str, d: &str, n: i64) -> String {
    let (x0, d): (f64, f64) = (x0.parse().unwrap(), d.parse().unwrap());
    mm(((x0 - d * n as f64) * 1000.0).round() as i64)
}

fn pass(out: &mut Vec<String>, x: &str, g92: bool) {
    let text =
        if g92 { format!("G92 X{x} Z13. F2.\nG00 X58.") } else { format!("G00 X{x}\nG32 Z13. F2.\nG00 X58.\nZ70.") };
    out.extend(text.split('\n').map(String::from));
}

/// The subprogram program `who` (the main program: `subs`) calls with `s`.
fn sub_of(subs: usize, who: usize, s: u8) -> Option<usize> {
    let first = if who == subs { 0 } else { who + 1 };
    (first < subs).then(|| first + s as usize % (subs - first))
}

/// Writes program `who`'s steps as the controller reads them (`seq`: the last sequence number given).
fn write_calls(steps: &[Step], who: usize, subs: usize, d: Dialect, seq: &mut u32, out: &mut Vec<String>) {
    let (counter, w) = (100 + who, 110 + who);
    for st in steps {
        match *st {
            Step::Pass(x, g) => pass(out, &mm(45000 + i64::from(x)), g),
            Step::Count(x, dx, g) => {
                out.push(format!("#{counter}=#{counter}+1"));
                pass(out, &format!("[{}-{}*#{counter}]", mm(45000 + i64::from(x)), mm(dx.into())), g);
            }
            Step::Call(s, n, f) => {
                let Some(num) = sub_of(subs, who, s).map(|j| 2000 + j) else { continue };
                match f {
                    0 => out.push(format!("M98 P{num} L{n}")),
                    1 => out.push(format!("M98 P{n}{num:04}")),
                    _ => out.extend((0..n).map(|_| format!("M98 P{num}"))),
                }
            }
            Step::Loop(n, ref body, false) => {
                out.extend([format!("#{w}=0"), format!("WHILE[#{w} LT {n}]DO1")]);
                write_calls(body, who, subs, d, seq, out);
                out.extend([format!("#{w}=#{w}+1"), "END1".into()]);
            }
            Step::Loop(n, ref body, true) => {
                *seq += 10;
                let s = *seq;
                out.extend([format!("#{w}=0"), format!("N{s} #{w}=#{w}+1")]);
                write_calls(body, who, subs, d, seq, out);
                out.push(format!("IF[#{w} LT {n}]GOTO{s}"));
            }
            Step::Macro(x, n) if d == Dialect::Fanuc0i => {
                out.push(format!("G65 P3000 L{n} A{} B2.", mm(45000 + i64::from(x))));
            }
            Step::Macro(x, n) => {
                out.extend([format!("#1={}", mm(45000 + i64::from(x))), "#2=2.".into(), format!("M98 P3000 L{n}")]);
            }
        }
    }
}

/// Writes program `who`'s steps out: calls replaced by their bodies,
/// counters by their values; false past 1500 lines.
fn write_out(c: &Calls, steps: &[Step], who: usize, counters: &mut [i64; 8], out: &mut Vec<String>) -> bool {
    for st in steps {
        match *st {
            Step::Pass(x, g) => pass(out, &mm(45000 + i64::from(x)), g),
            Step::Count(x, dx, g) => {
                counters[who] += 1;
                pass(out, &less(&mm(45000 + i64::from(x)), &mm(dx.into()), counters[who]), g);
            }
            Step::Call(s, n, _) => {
                let Some(j) = sub_of(c.1.len(), who, s) else { continue };
                if !(0..n).all(|_| write_out(c, &c.1[j], j, counters, out)) {
                    return false;
                }
            }
            Step::Loop(n, ref body, _) => {
                if !(0..n).all(|_| write_out(c, body, who, counters, out)) {
                    return false;
                }
            }
            Step::Macro(x, n) => {
                for _ in 0..n {
                    counters[7] += 1;
                    pass(out, &less(&mm(45000 + i64::from(x)), "0.010", counters[7]), false);
                }
            }
        }
        if out.len() > 1500 {
            return false;
        }
    }
    true
}

/// The program with its subprograms, and the same written out (`None` when too long).
fn programs(c: &Calls, d: Dialect) -> (String, Option<String>) {
    let (head, tail) = ("O0001\nG97 S300 M03\nG00 X58. Z70.", "G00 X100. Z100.\nM30");
    let subs = c.1.len();
    let mut called = vec![head.to_string()];
    let seq = &mut 0;
    write_calls(&c.0, subs, subs, d, seq, &mut called);
    called.push(tail.into());
    for (i, body) in c.1.iter().enumerate() {
        called.push(format!("O{}", 2000 + i));
        write_calls(body, i, subs, d, seq, &mut called);
        called.push("M99".into());
    }
    called.push("O3000\n#190=#190+1\nG00 X[#1-0.010*#190]\nG32 Z13. F#2\nG00 X58.\nZ70.\nM99".into());
    let mut flat = vec![head.to_string()];
    let fits = write_out(c, &c.0, subs, &mut [0; 8], &mut flat);
    flat.push(tail.into());
    (called.join("\n"), fits.then(|| flat.join("\n")))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Subprogram calls (M98 with L, packed counts, repeated calls, G65 with
    /// arguments, calls in loops and in subprograms) cut exactly the passes
    /// of the program written out.
    #[test]
    fn calls_cut_as_written_out(mut c in calls(), gsk in any::<bool>()) {
        let d = if gsk { Dialect::Gsk980tdc } else { Dialect::Fanuc0i };
        if gsk {
            // GSK980TDc nests subprograms four deep: three and the M98 of the "macro".
            c.1.truncate(3);
        }
        let (called, flat) = programs(&c, d);
        prop_assume!(flat.is_some());
        let flat = flat.unwrap();
        let s = Settings::new(d);
        let (a, b) = (screwcut::plan(&called, &s), screwcut::plan(&flat, &s));
        // The program written out cuts whenever it holds a pass.
        prop_assert_eq!(b.threads.is_empty(), !flat.contains(" F2."));
        common::same_cut(&a, &b);
        // Each subprogram called once, in turn, without loops: no block runs again.
        let pass = |s: &&Step| matches!(s, Step::Pass(..) | Step::Count(..));
        let once = (0..c.1.len()).map(|j| Step::Call(j as u8, 1, 0)).collect();
        let once = (once, c.1.iter().map(|b| b.iter().filter(pass).cloned().collect()).collect());
        let mut s = Settings::new(d);
        s.set(P::LimitBlocks, 1.0);
        let p = screwcut::plan(&programs(&once, d).0, &s);
        prop_assert_eq!(p.with_code(screwcut::Code::BlockLimit).count(), 0);
    }
}
