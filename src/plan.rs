//! The plan of a program: diagnostics, motions and threads. This is what the
//! CLI prints and what the wasm binding returns.

use serde::Serialize;

use crate::block::Block;
use crate::diagnostic::{Code, Diagnostic, Severity};
use crate::dialect::Dialect;
use crate::interp::Interp;
use crate::lexer::{LexLimits, Lexer};
use crate::motion::Move;
use crate::settings::{P, Settings};
use crate::span::{LineIndex, Span};
use crate::thread::Thread;

/// Program units.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres (G21).
    Mm,
    /// Inches (G20).
    Inch,
}

/// Everything screwcut knows about a program.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plan {
    /// Dialect the program was read as.
    pub dialect: Dialect,
    /// Units in force at the end of the program.
    pub units: Units,
    /// Alarms, warnings and advice, by position.
    pub diagnostics: Vec<Diagnostic>,
    /// Every motion in program order.
    pub moves: Vec<Move>,
    /// Every thread with its passes.
    pub threads: Vec<Thread>,
}

impl Plan {
    /// Whether any diagnostic is an alarm.
    pub fn has_alarm(&self) -> bool {
        self.diagnostics.iter().any(|d| d.severity == Severity::Error)
    }

    /// The diagnostics with `code`.
    pub fn with_code(&self, code: Code) -> impl Iterator<Item = &Diagnostic> {
        self.diagnostics.iter().filter(move |d| d.code == code)
    }

    /// Serialises to JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
    }
}

/// Plans `text` with `settings` (which also carry the dialect).
pub fn plan(text: &str, settings: &Settings) -> Plan {
    let mut it = Interp::with_capacity(settings, text.len());
    let mut starts = Vec::new();
    let limit = settings.get(P::LimitProgramBytes) as usize;
    if text.len() > limit {
        it.diag(
            Code::ProgramTooLarge,
            Span::new(0, 0),
            format!(
                "the program is {} bytes, larger than the limit of {limit} (setting limits.program_bytes)",
                text.len()
            ),
        );
    } else {
        let limits = LexLimits {
            block_chars: settings.int(P::LimitBlockChars).max(1) as usize,
            digits: settings.int(P::LimitDigits).clamp(1, 17) as usize,
        };
        let mut lexer = Lexer::new(text, settings.dialect(), limits);
        let mut block = Block::default();
        while lexer.next_block(&mut block, &mut it.diags) {
            it.block(&block);
            if it.stopped() {
                break;
            }
        }
        it.finish();
        starts = lexer.take_line_starts();
    }
    let index = LineIndex::from_starts(text, starts);
    let Interp { mut diags, moves, mut threads, inch, .. } = it;
    let spans = |line: u32| {
        let start = index.line_start(line);
        let end = text[start..].find(['\n', '\r']).map_or(text.len(), |e| start + e);
        Span::new(start, end)
    };
    crate::advice::finish_manual(&mut threads, &moves, settings, inch, &mut diags, &spans);
    let dropped = diags.dropped();
    let mut diagnostics = diags.finish(text, &index);
    if dropped > 0 {
        if let Some(last) = diagnostics.last().cloned() {
            diagnostics.push(Diagnostic {
                message: format!("{dropped} more diagnostics not shown (setting limits.diagnostics)"),
                ..last
            });
        }
    }
    Plan { dialect: settings.dialect(), units: if inch { Units::Inch } else { Units::Mm }, diagnostics, moves, threads }
}

/// Plans `text` with the default settings of `dialect`.
pub fn plan_default(text: &str, dialect: Dialect) -> Plan {
    plan(text, &Settings::new(dialect))
}
