#![cfg(not(target_arch = "wasm32"))]
//! Property tests of the program flow (`src/exec/`): generated programs with
//! subprograms, custom macro B and LinuxCNC o-words.
//!
//! The generator writes a main program of threading blocks (G32/G33 passes,
//! G92, G76, feeds) with calls into generated subprograms (`M98 P… L…`, the
//! packed `M98 P□□□□○○○○`, `G65 P… L… A… B…`; LinuxCNC `o<…> call`), loops
//! with counters (`WHILE[…]DOm`, a backward `IF[…]GOTOn`; `while`, `do`,
//! `repeat`), forward jumps and `if`, variables at addresses
//! (`X[46.5-0.1*#10]`), `M99` in a subprogram or the main program, `break`,
//! `continue`, `return` and recursion; for the broken programs, lines from a
//! pool of faults are inserted and lines deleted. Checked:
//!
//! - any such program, also under tight `limits.blocks` and
//!   `limits.call_depth`, plans without a panic and keeps the invariants of
//!   `props::check` (Fanuc 0i, GSK980TDc — `M98` where Fanuc has `G65` — and
//!   Renhe with the Fanuc forms; LinuxCNC with o-words);
//! - re-planning after edits (in the main program, in a subprogram, in a
//!   loop, at a call's count, past the first program end) gives exactly the
//!   plan of a full re-plan, also when the last reading's tail was kept
//!   with a loop open in it;
//! - any such program, short or long, whole or broken, read with its blocks
//!   lexed ahead on a second thread plans exactly as read on one thread.
//!
//! Calls compared with the program written out: `flow_unrolled.rs`.

mod common;
#[path = "common/props.rs"]
mod props;

use props::{block, check};
use proptest::collection::vec;
use proptest::prelude::*;
use screwcut::settings::P;
use screwcut::{Dialect, Settings};

/// One step of a generated program; the writer keeps constructs paired
/// (every loop closed, every jump's target placed).
#[derive(Clone, Debug)]
enum Op {
    /// A threading pass or cycle: its form and X.
    Pass(u8, u8),
    /// Opens a construct of a kind, with a count: Fanuc WHILE, backward
    /// GOTO loop, forward IF GOTO; LinuxCNC while, do, repeat, if/else.
    Open(u8, u8),
    /// Closes the innermost construct.
    Close,
    /// A call: which subprogram, how many times, in which form.
    Call(u8, u8, u8),
    /// A change of flow or variables (counter, IF THEN, M99, M2, break, continue, return).
    Flow(u8),
    /// Plain blocks, as many as the program's padding says.
    Plain(u8),
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        4 => (0u8..6, 0u8..20).prop_map(|(f, x)| Op::Pass(f, x)),
        2 => (0u8..4, 1u8..4).prop_map(|(k, n)| Op::Open(k, n)),
        2 => Just(Op::Close),
        2 => (0u8..4, 0u8..4, 0u8..4).prop_map(|(s, n, f)| Op::Call(s, n, f)),
        1 => (0u8..4).prop_map(Op::Flow),
        1 => (0u8..8).prop_map(Op::Plain),
    ]
}

/// A generated program: the main program's steps, each subprogram's, the
/// padding (half of it in plain blocks first, an eighth per unit of a
/// `Plain` step: long programs have checkpoints inside loops and calls),
/// how the main program ends, whether a subprogram may call itself or an
/// earlier one, whether LinuxCNC's subroutines come first.
#[derive(Clone, Debug)]
struct Prog {
    main: Vec<Op>,
    subs: Vec<Vec<Op>>,
    pad: usize,
    end: u8,
    recursive: bool,
    subs_first: bool,
}

fn prog(pad: std::ops::Range<usize>) -> impl Strategy<Value = Prog> {
    (vec(op(), 0..16), vec(vec(op(), 0..10), 0..4), pad, 0u8..4, any::<bool>(), any::<bool>())
        .prop_map(|(main, subs, pad, end, recursive, subs_first)| Prog { main, subs, pad, end, recursive, subs_first })
}

/// Where a line stands: edits aim at each.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Tag {
    Main,
    Sub,
    Loop,
    Call,
}

/// A program's lines with their places, and the last sequence number or label given.
#[derive(Default)]
struct Out {
    lines: Vec<(String, Tag)>,
    seq: u32,
}

impl Out {
    /// Adds the lines of `text`.
    fn push(&mut self, tag: Tag, text: impl AsRef<str>) {
        self.lines.extend(text.as_ref().split('\n').map(|l| (l.to_string(), tag)));
    }

    fn text(&self) -> String {
        self.lines.iter().map(|l| l.0.as_str()).collect::<Vec<_>>().join("\n")
    }

    /// `n` plain blocks.
    fn plain(&mut self, tag: Tag, n: usize, linuxcnc: bool) {
        for k in 0..n {
            let x = 50 + k % 8;
            self.push(tag, if linuxcnc { format!("G0 X{x} Z70") } else { format!("G00 X{x}. Z70.") });
        }
    }
}

/// The place of a line inside `open` constructs of program `who`.
fn tag_of(open: bool, who: Option<usize>) -> Tag {
    if open {
        Tag::Loop
    } else if who.is_some() {
        Tag::Sub
    } else {
        Tag::Main
    }
}

/// The subprogram a call of `s` from program `who` (`None`: the main
/// program) goes to: a later one, or any when recursion is allowed.
fn callee(p: &Prog, who: Option<usize>, s: u8) -> Option<usize> {
    let (n, s) = (p.subs.len(), s as usize);
    match who {
        _ if n == 0 => None,
        None => Some(s % n),
        Some(_) if p.recursive => Some(s % n),
        Some(i) => (i + 1 < n).then(|| i + 1 + s % (n - i - 1)),
    }
}

/// X of a pass: 46.0 to 47.9.
fn x_of(x: u8) -> String {
    format!("{}.{}", 46 + x / 10, x % 10)
}

/// Writes a program: Fanuc forms (Fanuc 0i, GSK980TDc, Renhe) or LinuxCNC's.
fn write(p: &Prog, d: Dialect) -> Out {
    let lcnc = d == Dialect::LinuxCnc;
    let mut o = Out::default();
    o.push(Tag::Main, if lcnc { "G18 G21 G90 G7\nM3 S300\nG0 X58 Z70" } else { "O0001\nG97 S300 M03\nG00 X58. Z70." });
    let subs = |o: &mut Out| {
        for i in 0..p.subs.len() {
            o.push(Tag::Sub, if lcnc { format!("o<s{i}> sub") } else { format!("O{}", 2000 + i) });
            body(o, p, Some(i), d);
            o.push(Tag::Sub, if lcnc { format!("o<s{i}> endsub") } else { "M99".into() });
        }
    };
    if lcnc && p.subs_first {
        subs(&mut o);
    }
    o.plain(Tag::Main, p.pad / 2, lcnc);
    body(&mut o, p, None, d);
    let ends = if lcnc { ["M2", "M30", "M2", ""] } else { ["M30", "M99", "M30", "G00 X100. Z100."] };
    if !ends[p.end as usize % 4].is_empty() {
        o.push(Tag::Main, ends[p.end as usize % 4]);
    }
    if !(lcnc && p.subs_first) {
        subs(&mut o);
    }
    o
}

/// The constructs' opening and closing lines: `{v}` the counter, `{n}` the
/// count, `{l}` the sequence number or label, `{m}` the DO number, `{c}` the
/// enclosing loop's counter. Fanuc: WHILE (twice), backward jump, forward jump.
const FANUC_FORMS: [(&str, &str); 4] = [
    ("{v}=0\nWHILE[{v} LT {n}]DO{m}\n{v}={v}+1", "END{m}"),
    ("{v}=0\nWHILE[{v} LT {n}]DO{m}\n{v}={v}+1", "END{m}"),
    ("{v}=0\nN{l} {v}={v}+1", "IF[{v} LT {n}]GOTO{l}"),
    ("IF[{c} EQ {n}]GOTO{l}", "N{l} G00 X58."),
];

/// LinuxCNC: while, do, repeat, if/else.
const LCNC_FORMS: [(&str, &str); 4] = [
    ("{v} = 0\no{l} while [{v} LT {n}]\n{v} = [{v} + 1]", "o{l} endwhile"),
    ("{v} = 0\no{l} do\n{v} = [{v} + 1]", "o{l} while [{v} LT {n}]"),
    ("o{l} repeat [{n}]", "o{l} endrepeat"),
    ("o{l} if [{c} GT 1]", "o{l} else\nG0 X58\no{l} endif"),
];

/// Writes the steps of program `who` (`None`: the main program).
fn body(o: &mut Out, p: &Prog, who: Option<usize>, d: Dialect) {
    /// An open construct: kind, label, counter (if any), closing lines.
    struct Open(u8, u32, String, String);
    let lcnc = d == Dialect::LinuxCnc;
    let forms = if lcnc { LCNC_FORMS } else { FANUC_FORMS };
    let mut stack: Vec<Open> = Vec::new();
    for op in who.map_or(&p.main, |i| &p.subs[i]) {
        let tag = tag_of(!stack.is_empty(), who);
        let counter = stack.iter().rev().find(|s| !s.2.is_empty()).map_or("#1".into(), |s| s.2.clone());
        let innermost_loop = stack.iter().rev().find(|s| s.0 < 3).map(|s| s.1);
        match *op {
            Op::Pass(f, x) => o.push(tag, if lcnc { lcnc_pass(f, x, &counter) } else { fanuc_pass(f, x, &counter) }),
            Op::Open(k, n) if stack.len() < 4 => {
                o.seq += 1;
                let l = 10 * o.seq;
                // Fanuc's DO numbers go to 3: a fourth loop jumps back instead.
                let m = stack.iter().filter(|s| !lcnc && s.0 < 2).count() + 1;
                let k = if !lcnc && k < 2 && m > 3 { 2 } else { k };
                // Counters: Fanuc's main program's in its locals, a subprogram's in common variables.
                let v = match k {
                    0 | 1 if lcnc => format!("#<c{l}>"),
                    0..=2 if !lcnc => format!("#{}", who.map_or(10, |i| 100 + 10 * i) + stack.len()),
                    _ => String::new(),
                };
                let fill = |t: &str| {
                    let t = t.replace("{v}", &v).replace("{c}", &counter).replace("{m}", &m.to_string());
                    t.replace("{n}", &n.to_string()).replace("{l}", &l.to_string())
                };
                o.push(Tag::Loop, fill(forms[k as usize].0));
                stack.push(Open(k, l, v.clone(), fill(forms[k as usize].1)));
            }
            Op::Open(..) | Op::Close => stack.pop().into_iter().for_each(|s| o.push(Tag::Loop, s.3)),
            Op::Call(s, n, f) => match callee(p, who, s) {
                None if lcnc => o.push(tag, lcnc_pass(f, s, &counter)),
                None => o.push(tag, fanuc_pass(f, s, &counter)),
                Some(j) if lcnc => {
                    let call = match f {
                        0 | 1 => format!("o<s{j}> call [{}] [2]", x_of(s)),
                        2 => format!("o<s{j}> call"),
                        _ => format!("o<s{j}> call [{counter} * 0.1 + 46] [2]"),
                    };
                    o.seq += 1;
                    let l = 10 * o.seq;
                    o.push(Tag::Call, if f == 1 { format!("o{l} repeat [{n}]\n{call}\no{l} endrepeat") } else { call });
                }
                Some(j) => o.push(
                    Tag::Call,
                    match (f, 2000 + j) {
                        (0, num) => format!("M98 P{num} L{n}"),
                        (1, num) => format!("M98 P{n}{num:04}"),
                        (2, num) => format!("M98 P{num}"),
                        (_, num) if d == Dialect::Fanuc0i => format!("G65 P{num} L{n} A{}. B2.", 46 + n),
                        (_, num) => format!("M98 P{num} L{}", n + 1),
                    },
                ),
            },
            Op::Flow(k) => o.push(
                tag,
                match (lcnc, k, innermost_loop, who) {
                    (false, 0, ..) => format!("{counter}={counter}+1"),
                    (false, 1, ..) => "IF[#1 LT 5]THEN #1=#1+1".into(),
                    (false, 2, ..) => "G00 X[#1+50.] Z#5002".into(),
                    (false, _, _, Some(_)) => "M99".into(),
                    (false, ..) => "#500=#500+1".into(),
                    (true, 0, Some(l), _) => format!("o{l} break"),
                    (true, 1, Some(l), _) => format!("o{l} continue"),
                    (true, 3, _, Some(i)) => format!("o<s{i}> return [#31]"),
                    (true, 3, _, None) => "#<_g> = [#31 * 2]".into(),
                    (true, 2, ..) => "M2".into(),
                    (true, ..) => "#31 = [#31 + 1]".into(),
                },
            ),
            Op::Plain(n) => o.plain(tag, n as usize * p.pad / 8, lcnc),
        }
    }
    while let Some(s) = stack.pop() {
        o.push(Tag::Loop, s.3);
    }
}

/// A pass or cycle in the Fanuc forms; `counter`: the innermost loop's.
fn fanuc_pass(f: u8, x: u8, counter: &str) -> String {
    let (xv, cut) = (x_of(x), "G32 Z13. F2.\nG00 X58.\nZ70.");
    match f % 6 {
        0 => format!("G00 X{xv}\n{cut}"),
        1 => format!("G92 X{xv} Z13. F2.\nG00 X58."),
        2 => format!("G00 X[{xv}-0.1*{counter}]\n{cut}"),
        3 => format!("G76 P020060 Q100 R0.05\nG76 X{}.{} Z13. P1300 Q450 F2.", 44 + x / 10, x % 10),
        4 => format!("G00 X#1 Z[70.-{counter}]"),
        _ => format!("G01 X{xv} Z60. F0.2\nG00 X58. Z70."),
    }
}

/// A pass or cycle in LinuxCNC's forms.
fn lcnc_pass(f: u8, x: u8, counter: &str) -> String {
    let (xv, cut) = (x_of(x), "G33 Z13 K2\nG0 X58\nZ70");
    match f % 6 {
        0 => format!("G0 X{xv}\n{cut}"),
        1 => format!("G0 X[{xv} - 0.1 * {counter}]\n{cut}"),
        2 => "G0 X50 Z70\nG76 P2 Z13 I-2 J0.4 K1.3 R2 Q29.5 H1\nG0 X58 Z70".into(),
        3 => format!("G0 X[#1 + {xv}] Z70"),
        4 => format!("G1 X{xv} Z60 F100\nG0 X58 Z70"),
        _ => format!("G0 X{xv}\nG33 Z[13 + {counter}] K2\nG0 X58 Z70"),
    }
}

/// Faulty lines for the Fanuc forms, `|` between them.
const FANUC_FAULTS: &str = "END1|END2|DO1|WHILE[#1 LT 3]DO1|WHILE[1]DO4|GOTO 9999|GOTO 10|IF[#1]GOTO|\
    IF[#1 LT 2]GOTO 0|M99|M99 P10|M98 P2000|M98 P2999|M98|M98 P2000 L-1|M98 P2001 L99999|M98 P99992000|\
    G65 P2001 L2 A[#1+1] B2.|G65 A1.|#3000=7|#1=1/0|#1=SQRT[-1]|#[#1+2]=3|#9999=1|#1=#1+|G00 X[#1|\
    G00 X[#100-0.2] Z#5002|O2000|O2001|%|N10|N10 G00 X58.|IF[#1 LT 5]THEN #1=#1+1|#100=#100+1|M30|\
    /M98 P2001|G32 Z[13.-#1] F[#2+2.]|G92 X46. Z13. F#2";

/// Faulty lines for LinuxCNC.
const LCNC_FAULTS: &str = "o10 endwhile|o10 while [1]|o20 endif|o<s0> call|o<s9> call [1]|o<s0> endsub|\
    o<s1> sub|o10 break|o10 continue|o30 repeat [-1]|o30 endrepeat|#<x> = [#<y> + 1]|#1 = [1/0]|\
    G0 X[#<nope>]|o<s0> return [3]|M2|o10 do|o10 while [#1 LT 3]|#5602 = 1|o40 elseif [1]|o40 else|\
    (o10 while)|G33 Z13 K[#1 + 2]|o<s0> call [1] [2] [3] [4] [5] [6] [7] [8] [9] [10] [11] [12] [13] [14] \
    [15] [16] [17] [18] [19] [20] [21] [22] [23] [24] [25] [26] [27] [28] [29] [30] [31]";

/// Breaks a program: each `(where, what)` inserts a faulty line, or deletes one when `what` is past the pool.
fn spoil(o: &mut Out, pool: &str, breaks: &[(f64, u8)]) {
    for &(at, what) in breaks {
        let i = ((o.lines.len() as f64) * at) as usize;
        match pool.split('|').nth(what as usize) {
            Some(f) => o.lines.insert(i, (f.into(), Tag::Main)),
            None if i < o.lines.len() => drop(o.lines.remove(i)),
            None => {}
        }
    }
}

/// Settings under tight or moderate limits (never the default million
/// blocks, which a loop without end would run in full): blocks run again,
/// call nesting, runs of a main program ending in M99, the main program's number.
fn limits(d: Dialect) -> impl Strategy<Value = Settings> {
    let blocks = prop_oneof![1u32..300, 2000u32..20000];
    let depth = prop_oneof![1u32..6, Just(64)];
    let main = prop_oneof![3 => Just(0u32), 1 => 2000u32..2003];
    (blocks, depth, 1u32..4, main).prop_map(move |(blocks, depth, runs, main)| {
        let mut s = Settings::new(d);
        s.set(P::LimitBlocks, blocks.into());
        s.set(P::LimitCallDepth, depth.into());
        s.set(P::MainRepeats, runs.into());
        s.set(P::MainProgram, main.into());
        s
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Fanuc-form programs with subprograms and macros, whole or broken,
    /// plan without a panic and keep the invariants, under any limits.
    #[test]
    fn fanuc_flow_keeps_invariants(
        p in prog(0..4), breaks in vec((0.0f64..1.0, 0u8..48), 0..4),
        s in prop_oneof![limits(Dialect::Fanuc0i), limits(Dialect::Gsk980tdc), limits(Dialect::Renhe)],
    ) {
        let mut o = write(&p, s.dialect());
        spoil(&mut o, FANUC_FAULTS, &breaks);
        let text = o.text();
        check(&text, &s, &screwcut::plan(&text, &s));
    }

    /// The same for LinuxCNC programs with o-word subroutines and loops.
    #[test]
    fn linuxcnc_flow_keeps_invariants(
        p in prog(0..4), breaks in vec((0.0f64..1.0, 0u8..32), 0..4), s in limits(Dialect::LinuxCnc),
    ) {
        let mut o = write(&p, Dialect::LinuxCnc);
        spoil(&mut o, LCNC_FAULTS, &breaks);
        let text = o.text();
        check(&text, &s, &screwcut::plan(&text, &s));
    }
}

/// The plan of `text` read with its blocks lexed ahead on a second thread
/// (what `plan` does natively from `AHEAD_FROM` bytes) is the plan read on one thread.
fn ahead_matches(text: &str, s: &Settings) -> Result<(), TestCaseError> {
    prop_assume!(text.len() < screwcut::plan::AHEAD_FROM, "plan reads it on one thread");
    prop_assert_eq!(screwcut::plan::plan_lexed_ahead(text, s), screwcut::plan(text, s), "{}", text);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Fanuc-form programs, whole or broken, long and short, any limits:
    /// the jumps of calls and loops over the lines lexed ahead.
    #[test]
    fn fanuc_lexed_ahead_plans_the_same(
        p in prop_oneof![prog(0..4), prog(250..600)], breaks in vec((0.0f64..1.0, 0u8..48), 0..4),
        s in prop_oneof![limits(Dialect::Fanuc0i), limits(Dialect::Gsk980tdc), limits(Dialect::Renhe)],
    ) {
        let mut o = write(&p, s.dialect());
        spoil(&mut o, FANUC_FAULTS, &breaks);
        ahead_matches(&o.text(), &s)?;
    }

    /// The same for LinuxCNC programs with o-words.
    #[test]
    fn linuxcnc_lexed_ahead_plans_the_same(
        p in prop_oneof![prog(0..4), prog(250..600)], breaks in vec((0.0f64..1.0, 0u8..32), 0..4),
        s in limits(Dialect::LinuxCnc),
    ) {
        let mut o = write(&p, Dialect::LinuxCnc);
        spoil(&mut o, LCNC_FAULTS, &breaks);
        ahead_matches(&o.text(), &s)?;
    }
}

/// An edit: where (a line of a kind, at a fraction of them), what (replace,
/// insert, delete, change a count, lengthen the first line — the same
/// lines, the rest moved, so the last reading's tail may be kept —, or let
/// the program run past its first end), and the new line (a G-code-shaped
/// block, or a faulty line of the pool).
type Edit = (u8, f64, u8, Result<String, u8>);

fn edit() -> impl Strategy<Value = Edit> {
    let line = prop_oneof![block().prop_map(Ok), any::<u8>().prop_map(Err)];
    (0u8..4, 0.0f64..1.0, 0u8..6, line)
}

/// Changes one number: a call's count, or else the line's last digit.
fn tweak(line: &str) -> String {
    if let Some(i) = line.find(" L") {
        let digits = line[i + 2..].bytes().take_while(u8::is_ascii_digit).count();
        let n: u32 = line[i + 2..i + 2 + digits].parse().unwrap_or(0);
        return format!("{} L{}{}", &line[..i], (n + 1) % 5, &line[i + 2 + digits..]);
    }
    match line.rfind(|c: char| c.is_ascii_digit()) {
        Some(i) => format!("{}{}{}", &line[..i], (line.as_bytes()[i] - b'0' + 1) % 10, &line[i + 1..]),
        None => format!("{line} X1."),
    }
}

fn apply(o: &mut Out, (kind, at, what, line): &Edit, pool: &str) {
    let want = [Tag::Main, Tag::Sub, Tag::Loop, Tag::Call][*kind as usize];
    let of_kind: Vec<usize> = (0..o.lines.len()).filter(|&i| o.lines[i].1 == want).collect();
    let pick = |n: usize| ((n as f64) * at) as usize;
    let i = if of_kind.is_empty() { pick(o.lines.len()) } else { of_kind[pick(of_kind.len())] };
    let new = line.clone().unwrap_or_else(|k| pool.split('|').cycle().nth(k.into()).unwrap().to_string());
    match what {
        0 if i < o.lines.len() => o.lines[i].0 = new,
        2 if i < o.lines.len() => drop(o.lines.remove(i)),
        3 if i < o.lines.len() => o.lines[i].0 = tweak(&o.lines[i].0),
        4 => o.lines[0].0.push_str(" (TOP)"),
        5 => match o.lines.iter().position(|l| ["M2", "M30", "M99"].contains(&l.0.as_str())) {
            Some(k) => o.lines[k].0 = "G00 X52. Z70.".into(),
            None => o.lines[0].0.push_str(" (TOP)"),
        },
        _ => o.lines.insert(i, (new, want)),
    }
}

/// Settings for re-planning: few diagnostics (which are kept must match
/// too) or not, tight limits of blocks and calls or moderate ones.
fn replanning(d: Dialect) -> impl Strategy<Value = Settings> {
    (any::<bool>(), any::<bool>()).prop_map(move |(few, tight)| {
        let mut s = Settings::new(d);
        s.set(P::LimitBlocks, if tight { 400.0 } else { 20000.0 });
        s.set(P::LimitCallDepth, if tight { 2.0 } else { 64.0 });
        if few {
            s.set(P::LimitDiagnostics, 5.0);
        }
        s
    })
}

/// Plans `o`, then after each edit both incrementally and in full.
fn incremental(mut o: Out, edits: &[Edit], s: &Settings, pool: &str) -> Result<(), TestCaseError> {
    let mut planner = screwcut::planner::Planner::new(s.clone());
    planner.plan(&o.text());
    for e in edits {
        apply(&mut o, e, pool);
        let text = o.text();
        let inc = planner.plan(&text).clone();
        let full = screwcut::plan(&text, s);
        prop_assert_eq!(inc, full, "after {:?} in\n{}", e, text);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Re-planning a Fanuc 0i or GSK980TDc program with subprograms and
    /// loops after edits gives the plan of a full re-plan.
    #[test]
    fn fanuc_incremental_matches_full(
        p in prog(250..600), edits in vec(edit(), 1..6),
        s in prop_oneof![replanning(Dialect::Fanuc0i), replanning(Dialect::Gsk980tdc)],
    ) {
        incremental(write(&p, s.dialect()), &edits, &s, FANUC_FAULTS)?;
    }

    /// The same for LinuxCNC programs with o-words.
    #[test]
    fn linuxcnc_incremental_matches_full(p in prog(250..600), edits in vec(edit(), 1..6), s in replanning(Dialect::LinuxCnc)) {
        incremental(write(&p, Dialect::LinuxCnc), &edits, &s, LCNC_FAULTS)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// A reading that never jumped keeps its tail across an edit that keeps
    /// the lines; a loop the program ended inside (WHILE or a backward
    /// jump's; while, do or repeat), its end never reached, goes on right
    /// once a later edit removes that end.
    #[test]
    fn loops_open_in_a_kept_tail_follow_the_edits(
        before in 0usize..400, inside in 200usize..500, kind in 0usize..3, lcnc in any::<bool>(),
    ) {
        let d = if lcnc { Dialect::LinuxCnc } else { Dialect::Fanuc0i };
        let forms = if lcnc { LCNC_FORMS } else { FANUC_FORMS };
        let v = if lcnc { "#<c10>" } else { "#10" };
        let fill = |t: &str| t.replace("{v}", v).replace("{n}", "2").replace("{l}", "10").replace("{m}", "1");
        let mut o = Out::default();
        o.push(Tag::Main, "(TOP)");
        o.plain(Tag::Main, before, lcnc);
        o.push(Tag::Loop, fill(forms[kind].0));
        o.plain(Tag::Loop, inside, lcnc);
        o.push(Tag::Loop, "M30");
        o.push(Tag::Loop, fill(forms[kind].1));
        o.push(Tag::Main, "G00 X52. Z70.\nM30");
        let edits = [(0, 0.0, 4, Err(0)), (0, 0.0, 5, Err(0))];
        incremental(o, &edits, &Settings::new(d), FANUC_FAULTS)?;
    }
}
