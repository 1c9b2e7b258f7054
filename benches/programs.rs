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
