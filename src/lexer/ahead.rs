//! Blocks lexed ahead on a second thread (native builds only): a whole
//! program's reading is a pipeline of two nearly equal halves, the lexer
//! and the rest (the program flow, the interpreter, the assembler), so on a
//! machine with a second core the lexer runs the text in order on it while
//! the reading takes the blocks it asks for.
//!
//! The reading gets exactly what a [`Lexer`] would give it: a jump forward
//! passes over the blocks lexed before its target, a jump back (a loop, a
//! subprogram above) is lexed on the reading's own thread until it comes
//! back to the lines lexed ahead; the lexer's diagnostics of a block are
//! said when the reading takes the block (through its own collector, with
//! its limit and call chain), and the line starts are recorded as the
//! reading passes the lines.

use std::sync::mpsc::{Receiver, Sender, SyncSender, channel, sync_channel};

use super::{Blocks, Lexer};
use crate::block::Block;
use crate::diagnostic::{Diagnostics, Item};

/// Blocks a chunk carries: about 8 KB of a program of G01 blocks.
const CHUNK: usize = 256;
/// Chunks lexed and not yet taken (the lexer waits beyond them).
const QUEUE: usize = 4;

/// One line as the lexer ahead read it.
#[derive(Default)]
struct Lexed {
    block: Block,
    /// Byte offset of the line.
    start: usize,
    /// Byte offset of the next line (one past the end after the last line).
    next: usize,
    /// Its diagnostics: `Chunk::diags[from..to]`.
    from: usize,
    to: usize,
}

/// Lines lexed ahead, in order; sent to the reading and back to be refilled.
#[derive(Default)]
struct Chunk {
    lines: Vec<Lexed>,
    /// How many of `lines` hold lines of this chunk.
    filled: usize,
    diags: Vec<Item>,
}

/// The blocks of a text lexed ahead on another thread, taken by a reading.
pub(crate) struct Ahead<'a> {
    /// The reading's own lexer: where it is, its line starts, and the lines
    /// it reads itself (after a jump back).
    lexer: Lexer<'a>,
    full: Receiver<Chunk>,
    empty: Sender<Chunk>,
    chunk: Chunk,
    /// The next line of `chunk` to take.
    k: usize,
}

/// Reads `text` with `lexer` on a second thread while `read` takes the
/// blocks through an [`Ahead`]; returns what `read` returns and the
/// reading's lexer (its position and line starts).
pub(crate) fn with<'a, T>(lexer: Lexer<'a>, read: impl FnOnce(&mut Ahead<'a>) -> T) -> (T, Lexer<'a>) {
    let (full_tx, full) = sync_channel(QUEUE);
    let (empty, empty_rx) = channel();
    let mut producer = lexer.clone();
    std::thread::scope(|scope| {
        // Where no thread can be started, the sender goes with the closure
        // and the reading lexes every line itself.
        let _ = std::thread::Builder::new()
            .name("screwcut-lexer".into())
            .spawn_scoped(scope, move || lex_ahead(&mut producer, &full_tx, &empty_rx));
        let mut ahead = Ahead { lexer, full, empty, chunk: Chunk::default(), k: 0 };
        let out = read(&mut ahead);
        // Dropping the receiver stops the lexer ahead at its next chunk.
        (out, ahead.lexer)
    })
}

/// Lexes the whole text in order into chunks (reused when they come back)
/// until the end or until the reading no longer takes them.
fn lex_ahead(lexer: &mut Lexer, full: &SyncSender<Chunk>, empty: &Receiver<Chunk>) {
    let mut diags = Diagnostics::with_limit(usize::MAX);
    loop {
        let mut chunk = empty.try_recv().unwrap_or_default();
        chunk.filled = 0;
        chunk.diags.clear();
        let mut more = true;
        while chunk.filled < CHUNK {
            if chunk.lines.len() == chunk.filled {
                chunk.lines.push(Lexed::default());
            }
            let line = &mut chunk.lines[chunk.filled];
            line.start = lexer.offset();
            more = lexer.next_block(&mut line.block, &mut diags);
            if !more {
                break;
            }
            line.next = lexer.offset();
            line.from = chunk.diags.len();
            diags.move_into(&mut chunk.diags);
            line.to = chunk.diags.len();
            chunk.filled += 1;
        }
        if chunk.filled > 0 && full.send(chunk).is_err() {
            return;
        }
        if !more {
            return;
        }
    }
}

impl Ahead<'_> {
    /// The start of the next line lexed ahead, if the channel still gives one.
    fn front(&mut self) -> Option<usize> {
        if self.k == self.chunk.filled {
            let next = self.full.recv().ok()?;
            let done = std::mem::replace(&mut self.chunk, next);
            // The lexer ahead refills it (or it is dropped if the lexer is done).
            let _ = self.empty.send(done);
            self.k = 0;
        }
        Some(self.chunk.lines[self.k].start)
    }
}

impl<'a> Blocks<'a> for Ahead<'a> {
    fn offset(&self) -> usize {
        self.lexer.offset()
    }
    fn line(&self) -> u32 {
        self.lexer.line()
    }
    fn text(&self) -> &'a str {
        self.lexer.text()
    }
    fn jump(&mut self, offset: usize, line: u32) {
        self.lexer.jump(offset, line)
    }
    fn next_block(&mut self, block: &mut Block, diags: &mut Diagnostics) -> bool {
        let want = self.lexer.offset();
        while let Some(start) = self.front() {
            if start > want {
                break; // behind the lines lexed ahead: read here
            }
            let k = self.k;
            self.k += 1;
            if start < want {
                continue; // jumped over
            }
            let line = &mut self.chunk.lines[k];
            std::mem::swap(block, &mut line.block);
            self.lexer.passed(line.start, line.next);
            for (message, span, _) in &self.chunk.diags[line.from..line.to] {
                diags.push_message(message.clone(), *span);
            }
            return true;
        }
        self.lexer.next_block(block, diags)
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::{plan, plan_lexed_ahead};
    use crate::settings::P;
    use crate::{Dialect, Settings};

    /// The plan read with its blocks lexed ahead, and read on one thread (the reference).
    fn both(text: &str, s: &Settings) -> crate::Plan {
        let (ahead, one) = (plan_lexed_ahead(text, s), plan(text, s));
        assert!(text.len() < crate::plan::AHEAD_FROM, "the reference must read on one thread");
        assert_eq!(ahead, one, "{:?}:\n{text}", s.dialect());
        assert_eq!(ahead.to_json(), one.to_json());
        ahead
    }

    /// How many diagnostics of `code` a plan has.
    fn count(p: &crate::Plan, code: &str) -> usize {
        p.diagnostics.iter().filter(|d| d.code.as_str() == code).count()
    }

    /// Every example in every dialect (alarms and all).
    #[test]
    fn examples_plan_the_same() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
        let mut read = 0;
        for e in std::fs::read_dir(dir).unwrap() {
            let path = e.unwrap().path();
            if matches!(path.extension().and_then(|x| x.to_str()), Some("nc" | "ngc")) {
                let text = std::fs::read_to_string(&path).unwrap();
                for d in Dialect::ALL {
                    both(&text, &Settings::new(d));
                }
                read += 1;
            }
        }
        assert!(read >= 13, "{read} examples");
    }

    /// Jumps back and forward over many chunks (a subprogram at the end
    /// called three times from the start, a loop back over 600 lines, a
    /// forward GOTO), lexer alarms in the lines lexed ahead and in the lines
    /// read again, over a diagnostics limit that drops some.
    #[test]
    fn jumps_and_lexer_alarms_plan_the_same() {
        let mut fanuc = String::from("O0001\nG99 S500 M3\n#1=0\nWHILE[#1LT2]DO1\nM98 P9000 L3\n");
        for k in 0..600 {
            fanuc.push_str(&format!("N{} G01 X{}.5 Z-{k}.25 F0.2\n", k + 10, 20 + k % 30));
            if k % 97 == 0 {
                fanuc.push_str("G01 X１２ Z-3 @ F0.2\nX\n");
            }
        }
        fanuc.push_str("#1=#1+1\nEND1\nGOTO 50\nG01 X99 Z99\nN50 G00 X60 Z5\nM30\nO9000\nG00 X50.\nX47.1 Z5.\nG32 Z-20. F2.\nG00 X55.\nZ5.\n@\nM99\n");
        let mut s = Settings::new(Dialect::Fanuc0i);
        // The loop runs twice, each time calling the subprogram three times:
        // six passes, and each lexer alarm of the loop's lines said twice.
        let p = both(&fanuc, &s);
        let passes: usize = p.threads.iter().map(|t| t.passes.len()).sum();
        assert_eq!(passes, 6);
        // Seven in the main program's lines, one in the subprogram's (said at
        // each call): eight rows, the main program's raised twice and the
        // subprogram's six times (after the same call).
        assert_eq!(count(&p, "unexpected-character"), 7 + 1);
        let raised: u32 = p.with_code(crate::Code::UnexpectedCharacter).map(|d| d.repeats).sum();
        assert_eq!(raised, 2 * (7 + 3));
        s.set(P::LimitDiagnostics, 5.0);
        let p = both(&fanuc, &s);
        // Room for five distinct ones: the subprogram's (raised three times at
        // its first call), then line 7's two, line 8's and line 106's first;
        // the loop's second run raises each again (kept, counted), and the
        // rest are dropped and said to be, from line 106 on.
        let rows: Vec<_> = p.diagnostics.iter().map(|d| (d.line, d.code.as_str(), d.repeats)).collect();
        let want = [
            (7, "full-width", 2),
            (7, "unexpected-character", 2),
            (8, "missing-value", 2),
            (106, "more-diagnostics", 1),
            (106, "unexpected-character", 2),
            (632, "unexpected-character", 6),
        ];
        assert_eq!(rows, want);
        let gsk = fanuc.replace("WHILE[#1LT2]DO1\n", "").replace("#1=#1+1\nEND1\nGOTO 50\n", "");
        let p = both(&gsk, &Settings::new(Dialect::Gsk980tdc));
        // Once through: the subprogram's alarm raised at its three calls, one row.
        assert_eq!(count(&p, "unexpected-character"), 7 + 1);
        let raised: u32 = p.with_code(crate::Code::UnexpectedCharacter).map(|d| d.repeats).sum();
        assert_eq!(raised, 7 + 3);
        let mut lcnc = String::from(
            "o<pass> sub\nG0 X50\nX47.1 Z5\nG33 Z-20 K2\nG0 X55\nZ5\no<pass> endsub\nS500 M3\n#1=0\no1 while [#1 LT 2]\n",
        );
        for k in 0..600 {
            lcnc.push_str(&format!("G1 X{}.5 Z-{k}.25 F0.2\n", 20 + k % 30));
        }
        lcnc.push_str("o<pass> call\n#1=[#1+1]\no1 endwhile\nM2\n");
        let p = both(&lcnc, &Settings::new(Dialect::LinuxCnc));
        assert_eq!(p.threads.iter().map(|t| t.passes.len()).sum::<usize>(), 2);
    }

    /// Where no thread could be started, the reading lexes every line itself.
    #[test]
    fn without_the_thread_the_reading_lexes_every_line() {
        use crate::plan::{Reading, finish, lexer_for};
        use std::sync::mpsc::{channel, sync_channel};
        let text = "G00 X50 Z5\nX47.1\nG32 Z-20 F2\nG00 X55 @\nZ5\n".repeat(200);
        let s = Settings::new(Dialect::Gsk980tdc);
        let mut r = Reading::new(&s, text.len());
        let lexer = lexer_for(&text, &s, &mut r.diags).unwrap();
        let (gone, full) = sync_channel(1);
        drop(gone);
        let (empty, _kept) = channel();
        let mut ahead = super::Ahead { lexer, full, empty, chunk: super::Chunk::default(), k: 0 };
        r.run(&mut ahead, usize::MAX, |_, _, _, _| true);
        let p = finish(&text, &s, r.outputs(), ahead.lexer.take_line_starts());
        assert_eq!(count(&p, "unexpected-character"), 200);
        assert_eq!(p, plan(&text, &s));
    }

    /// Line ends of every kind, a byte-order mark, a last line without its
    /// end, and a line over the block limit.
    #[test]
    fn line_ends_plan_the_same() {
        let long = format!("G01 X10 Z-{}1\n", "0".repeat(300));
        for text in [
            "\u{FEFF}G00 X50 Z5\r\nG32 Z-20 F2\rG00 X55\n\nZ5",
            "G00 X50 Z5\nG32 Z-20 F2\n",
            long.as_str(),
            "",
            "\n\n\r\n",
        ] {
            both(&text.repeat(150), &Settings::new(Dialect::Gsk980tdc));
        }
    }
}
