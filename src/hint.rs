//! Which controller a program is written for, when it reads badly as the
//! chosen one: pasted LinuxCNC code under Fanuc alarms on its `G76 P I J
//! K`; a Fanuc `G92 X Z F` read by LinuxCNC is a coordinate offset and cuts
//! no thread. When another dialect reads the same text without an alarm
//! where the chosen one alarms, or cuts threads where the chosen one cuts
//! none, one note names it (`dialect-hint`, with the dialect's name as the
//! argument `dialect`, for a one-click switch).

use crate::diagnostic::{Code, Diagnostic, Diagnostics};
use crate::dialect::Dialect;
use crate::message as msg;
use crate::plan::Plan;
use crate::settings::Settings;
use crate::span::{LineIndex, Span};

/// Larger programs are not read again in every dialect by the command
/// line; a pasted program is usually much smaller.
pub const MAX_BYTES: usize = 100_000;

/// The app, which asks at every keystroke while the program has an alarm,
/// reads smaller programs only (three more plans of 30 KB are a few ms).
pub const MAX_BYTES_LIVE: usize = 30_000;

/// Adds the `dialect-hint` note to `plan` (the plan of `text` as `settings`'
/// dialect) when another dialect reads it better and `text` is at most
/// `max_bytes` long; returns whether it did.
pub fn add(text: &str, settings: &Settings, plan: &mut Plan, max_bytes: usize) -> bool {
    if text.len() > max_bytes {
        return false;
    }
    let Some(d) = suggest(text, settings.dialect(), plan) else { return false };
    plan.diagnostics.retain(|x| x.code != Code::DialectHint);
    let at = plan.diagnostics.iter().find(|x| x.severity == crate::Severity::Error).map_or(Span::new(0, 0), |x| x.span);
    let pos = plan.diagnostics.partition_point(|x| x.span.start < at.start);
    plan.diagnostics.insert(pos, d.resolve(text, at));
    true
}

/// What another dialect reads.
struct Other {
    dialect: Dialect,
    threads: usize,
    why: &'static msg::Phrase,
    alarms: usize,
    current: Dialect,
}

impl Other {
    fn resolve(&self, text: &str, at: Span) -> Diagnostic {
        let mut d = Diagnostics::with_limit(1);
        let args = crate::args![
            title = crate::message::Arg::lit(self.dialect.title()),
            threads = self.threads as i64,
            why = self.why,
            current = crate::message::Arg::lit(self.current.title()),
            alarms = self.alarms as i64,
            dialect = crate::message::Arg::lit(self.dialect.name())
        ];
        d.push(&msg::DIALECT_HINT, at, args);
        d.finish(text, &LineIndex::new(text)).remove(0)
    }
}

/// The dialect that reads `text` better than `current` did (`plan`), if any:
/// no alarm where `current` has some, or threads where `current` has none.
fn suggest(text: &str, current: Dialect, plan: &Plan) -> Option<Other> {
    let alarms = plan.diagnostics.iter().filter(|d| d.severity == crate::Severity::Error).count();
    let no_threads = plan.threads.is_empty();
    if (alarms == 0 && !no_threads) || text.trim().is_empty() {
        return None;
    }
    let why = if alarms > 0 { &msg::HINT_ALARMS } else { &msg::HINT_NO_THREAD };
    Dialect::ALL
        .iter()
        .filter(|&&d| d != current)
        .filter_map(|&d| {
            let other = crate::plan(text, &Settings::new(d));
            let clean = !other.has_alarm() && !other.threads.is_empty();
            clean.then_some(Other { dialect: d, threads: other.threads.len(), why, alarms, current })
        })
        .min_by_key(|o| std::cmp::Reverse(o.threads))
}
