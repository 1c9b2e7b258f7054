//! Deterministic generated programs for the benchmarks, shaped like a CAM
//! post's output: turning sections (G01, G02), threads cut block by block
//! (G32 in the textbook's infeed–cut–retract–return pattern) and G76 cycles.

/// A small deterministic generator (64-bit LCG).
pub struct Lcg(u64);

impl Lcg {
    /// Seeded generator.
    pub fn new(seed: u64) -> Lcg {
        Lcg(seed)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// A thread-dense program of about `bytes` bytes: every few blocks a new
/// thread (one G32 pass at a random diameter) or a G76 cycle between
/// turning moves — the worst case for per-thread work.
pub fn thread_dense(bytes: usize, seed: u64) -> String {
    use std::fmt::Write;
    let mut r = Lcg::new(seed);
    let mut s = String::with_capacity(bytes + 256);
    s.push_str("O1001\nG50 X100 Z100\nG99 S800 M03 T0101\nG00 X62 Z5\n");
    while s.len() < bytes {
        let p = r.range(0.0, 1.0);
        if p < 0.45 {
            let _ = writeln!(s, "G01 X{:.3} Z{:.3} F0.2", r.range(20.0, 60.0), r.range(-80.0, 0.0));
        } else if p < 0.6 {
            let x = r.range(30.0, 50.0);
            let _ = writeln!(s, "G01 X{:.3} Z{:.3}\nG02 X{:.3} W-8 R10", x, r.range(-60.0, -20.0), x + 6.0);
        } else if p < 0.92 {
            let _ = writeln!(s, "G00 X{:.3} Z5\nG32 Z-40 F2\nG00 X62\nZ5", r.range(40.0, 50.0));
        } else {
            s.push_str("G00 X35 Z5\nG76 P011060 Q100 R0.05\nG76 X27.4 Z-30 P1300 Q400 F2\nG00 X62\n");
        }
    }
    s.push_str("M30\n");
    s
}

/// A program of about `bytes` bytes of G01 moves only, as a CAM post writes
/// a turned contour (`N.. G01 X.. Z.. F..`): the plain reading speed.
pub fn g01(bytes: usize, seed: u64) -> String {
    use std::fmt::Write;
    let mut r = Lcg::new(seed);
    let mut s = String::with_capacity(bytes + 256);
    s.push_str("O1002\nG50 X100 Z100\nG99 S800 M03 T0101\nG00 X62 Z5\n");
    let mut n = 10u32;
    while s.len() < bytes {
        let _ = writeln!(s, "N{n} G01 X{:.3} Z{:.3} F0.2", r.range(20.0, 60.0), r.range(-80.0, 0.0));
        n = n.wrapping_add(10);
    }
    s.push_str("M30\n");
    s
}

/// A program of about `bytes` bytes (GSK980TDc).
pub fn program(bytes: usize, seed: u64) -> String {
    use std::fmt::Write;
    let mut r = Lcg::new(seed);
    let mut s = String::with_capacity(bytes + 256);
    s.push_str("O1000\nG50 X100 Z100\nG99 S800 M03 T0101\nG00 X62 Z5\n");
    let mut n = 10u32;
    while s.len() < bytes {
        let p = r.range(0.0, 1.0);
        if p < 0.6 {
            // A turning section: lines and arcs.
            let count = r.range(10.0, 30.0) as usize;
            for _ in 0..count {
                if r.range(0.0, 1.0) < 0.75 {
                    let _ = writeln!(s, "N{n} G01 X{:.3} Z{:.3} F0.2", r.range(20.0, 60.0), r.range(-80.0, 0.0));
                } else {
                    let x = r.range(30.0, 50.0);
                    let _ = writeln!(
                        s,
                        "N{n} G01 X{:.3} Z{:.3}\nN{} G02 X{:.3} W-8 R10",
                        x,
                        r.range(-60.0, -20.0),
                        n + 5,
                        x + 6.0
                    );
                }
                n += 10;
            }
            s.push_str("G00 X62 Z5\n");
        } else if p < 0.85 {
            // A thread cut block by block: five passes, pitch 2.
            let d = r.range(30.0, 56.0);
            for (i, inf) in [0.9, 0.6, 0.6, 0.4, 0.1]
                .iter()
                .scan(0.0, |a, x| {
                    *a += x;
                    Some(*a)
                })
                .enumerate()
            {
                let _ = writeln!(s, "N{n} G00 X{:.3}\nG32 Z-40 F2\nG00 X62\nZ5", d - inf);
                n += 10;
                let _ = i;
            }
        } else {
            let _ = writeln!(s, "N{n} G00 X35 Z5\nG76 P011060 Q100 R0.05\nG76 X27.4 Z-30 P1300 Q400 F2\nG00 X62");
            n += 10;
        }
    }
    s.push_str("M30\n");
    s
}

/// Metric threads of the loop program's jobs: major diameter, pitch.
const THREADS: [(f64, f64); 10] = [
    (20.0, 2.5),
    (24.0, 3.0),
    (30.0, 2.0),
    (30.0, 1.5),
    (36.0, 3.0),
    (42.0, 2.0),
    (48.0, 2.0),
    (56.0, 2.0),
    (16.0, 2.0),
    (27.0, 2.0),
];

/// One job of the loop program: its lines in the main program and the
/// subprograms it adds.
struct Job {
    main: Vec<String>,
    subs: Vec<String>,
}

/// Job `j`: turning (inline, or a contour subprogram called with `M98`),
/// then a thread cut one of three ways: a `WHILE` loop in the main program
/// computing X per pass from variables, a one-pass subprogram called with
/// `M98 P… L3` and two spring passes, or the common macro `G65 P9010`.
fn job(j: usize, r: &mut Lcg) -> Job {
    let (d, p) = THREADS[j % THREADS.len()];
    let len = (r.range(2.0, 8.0) as usize * 5) as f64;
    let rpm = if d <= 30.0 { 500 } else { 350 };
    let (kind, n) = (j % 3, 10 * (j + 1));
    let mut main = vec![
        format!("(JOB {}: M{d}X{p} THREAD LENGTH {len})", j + 1),
        format!("N{n} G50 S2500"),
        "T0101 (OD TURNING 80 DEG)".into(),
        "G96 S180 M03".into(),
        format!("G00 X{:.1} Z2.", d + 6.0),
    ];
    let mut subs = Vec::new();
    let contour = contour(d, len, r);
    if j % 2 == 0 {
        main.extend(contour);
    } else {
        main.push(format!("M98 P{} (CONTOUR)", 3000 + j));
        subs.push(format!("O{} (CONTOUR M{d} JOB {})", 3000 + j, j + 1));
        subs.extend(contour);
        subs.push("M99".into());
    }
    main.extend([
        "G00 X200. Z200.".into(),
        "T0303 (60 DEG EXTERNAL THREADING)".into(),
        format!("G97 S{rpm} M03"),
        format!("G00 X{:.1} Z5.", d + 10.0),
    ]);
    let passes = (p * 3.0).round() as usize + 2;
    match kind {
        0 => main.extend(while_thread(d, p, len, passes)),
        1 => {
            main.extend(vars(d, p, 3));
            main.push(format!("M98 P{} L3 (THREE ROUGHING PASSES)", 2000 + j));
            main.extend(["(TWO SPRING PASSES)".into(), "G00 X[#1-#3]".into(), format!("G32 Z-{len}. F#2")]);
            main.extend(["G00 X[#1+10.]".into(), "Z5.".into(), "G00 X[#1-#3]".into(), format!("G32 Z-{len}. F#2")]);
            main.extend(["G00 X[#1+10.]".into(), "Z5.".into()]);
            subs.extend(pass_sub(2000 + j, d, p, len));
        }
        _ => main.push(format!("G65 P9010 A{} B{} C5. D-{len}. K{passes}.", mm(d), mm(p))),
    }
    main.extend(["G00 X200. Z200.".into(), "M05".into(), "M01".into()]);
    Job { main, subs }
}

/// A turned contour: facing, a chamfer, the thread's diameter, a shoulder.
fn contour(d: f64, len: f64, r: &mut Lcg) -> Vec<String> {
    let shoulder = d + r.range(4.0, 12.0).round();
    vec![
        "G00 Z0.".into(),
        "G01 X-1.6 F0.25 (FACE)".into(),
        "G00 Z3.".into(),
        format!("X{:.1}", d - 3.0),
        "G01 Z0. F0.2".into(),
        format!("X{:.2} Z-1.5", d - 0.2),
        format!("Z-{:.1}", len + 5.0),
        format!("X{shoulder:.1}"),
        format!("Z-{:.1}", len + 20.0),
        format!("G00 X{:.1}", shoulder + 4.0),
        "Z2.".into(),
    ]
}

/// `v` as a Fanuc length: always with a decimal point (`2.`, `1.5`).
fn mm(v: f64) -> String {
    if v.fract() == 0.0 { format!("{v}.") } else { format!("{v}") }
}

/// The thread's variables: #1 major diameter, #2 pitch, #3 depth on the
/// diameter, #4 pass counter, #5 passes.
fn vars(d: f64, p: f64, passes: usize) -> Vec<String> {
    vec![
        "(#1 DIA #2 PITCH #3 DEPTH ON DIA #4 PASS #5 PASSES)".into(),
        format!("#1={}", mm(d)),
        format!("#2={p}"),
        "#3=#2*1.227".into(),
        "#4=0".into(),
        format!("#5={passes}"),
    ]
}

/// A thread cut by a `WHILE` loop in the main program, degressive depth.
fn while_thread(d: f64, p: f64, len: f64, passes: usize) -> Vec<String> {
    let mut v = vars(d, p, passes);
    v.extend([
        "WHILE[#4 LT #5]DO1".into(),
        "#4=#4+1".into(),
        "G00 X[#1-#3*SQRT[#4/#5]]".into(),
        format!("G32 Z-{len}. F#2"),
        "G00 X[#1+10.]".into(),
        "Z5.".into(),
        "END1".into(),
    ]);
    v
}

/// A subprogram cutting one pass of the caller's thread (variables #1–#5).
fn pass_sub(o: usize, d: f64, p: f64, len: f64) -> Vec<String> {
    vec![
        format!("O{o} (ONE PASS OF M{d}X{p})"),
        "#4=#4+1".into(),
        "G00 X[#1-#3*SQRT[#4/#5]]".into(),
        format!("G32 Z-{len}. F#2"),
        "G00 X[#1+10.]".into(),
        "Z5.".into(),
        "M99".into(),
    ]
}

/// The common threading macro `G65 P9010 A(dia) B(pitch) C(start Z) D(end Z) K(passes)`.
const MACRO_9010: &str = "\
O9010 (G32 THREAD, A DIA B PITCH C START Z D END Z K PASSES)
#10=#2*1.227
#11=0
WHILE[#11 LT #6]DO1
#11=#11+1
#12=#1-#10*SQRT[#11/#6]
G00 X#12
G32 Z#7 F#2
G00 X[#1+10.]
Z#3
END1
M99";

/// A Fanuc 0i shop program of exactly `lines` lines (at least 200): a
/// main program O0100 of jobs (tool calls, G50 S clamp, G96 turning, G97
/// threading) whose threads are cut by macro loops, `M98 P… L3` pass
/// subprograms and the `G65 P9010` macro, then its subprograms, the
/// macro last. The header's job list fills the count.
pub fn fanuc_loops(lines: usize) -> String {
    let mut r = Lcg::new(11);
    let head = ["%", "O0100 (SHAFTS - TURN AND THREAD)", "(MATERIAL C45 - T0101 TURN - T0303 THREAD)"];
    let tail_main = ["G00 X200. Z200.", "M30", "%"];
    let mut jobs: Vec<Job> = Vec::new();
    let macro_lines = MACRO_9010.lines().count() + 1;
    let count = |jobs: &[Job]| jobs.iter().map(|j| j.main.len() + j.subs.len()).sum::<usize>();
    loop {
        let next = job(jobs.len(), &mut r);
        let used = head.len() + tail_main.len() + macro_lines + count(&jobs) + next.main.len() + next.subs.len();
        if used > lines {
            break;
        }
        jobs.push(next);
    }
    let mut out: Vec<String> = head.iter().map(|s| s.to_string()).collect();
    let spare = lines - (head.len() + tail_main.len() + macro_lines + count(&jobs));
    for k in 0..spare {
        let (d, p) = THREADS[k % THREADS.len()];
        out.push(format!("(JOB {}: M{d}X{p})", k + 1));
    }
    out.extend(jobs.iter().flat_map(|j| j.main.iter().cloned()));
    out.extend(tail_main.iter().map(|s| s.to_string()));
    out.extend(jobs.iter().flat_map(|j| j.subs.iter().cloned()));
    out.extend(MACRO_9010.lines().map(String::from));
    out.push("%".into());
    let mut s = out.join("\n");
    s.push('\n');
    s
}
