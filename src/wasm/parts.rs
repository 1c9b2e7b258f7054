//! The parts of `update`'s answer that carry a content key, and what the
//! caller says it has of them: a part whose key it has is not sent (null),
//! and the thread list it holds is brought up to date entry by entry.

use js_sys::{Array, Object};
use wasm_bindgen::JsValue;

use super::js::set;
use super::keys::js_key;

/// Parts of the answer that carry a key, in the order of `update`'s `known` argument.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Part {
    Threads = 0,
    Passes = 1,
}

impl Part {
    fn name(self) -> &'static str {
        match self {
            Part::Threads => "threads",
            Part::Passes => "passes",
        }
    }
}

/// What the caller already has: a key per [`Part`] (a missing entry: nothing);
/// empty when the caller keeps no parts (it gets every part whole).
pub(super) struct Known(pub(super) Vec<f64>);

impl Known {
    /// Whether the caller keeps parts by key.
    pub(super) fn keeps(&self) -> bool {
        !self.0.is_empty()
    }

    /// The caller's key of `part`, if it gave one.
    pub(super) fn key(&self, part: Part) -> Option<f64> {
        self.0.get(part as usize).copied()
    }

    fn has(&self, part: Part, key: f64) -> bool {
        self.key(part) == Some(key)
    }
}

/// Sets `<part>` and `<part>Key` on `o`: the value from `make` unless the
/// caller has `key`, then null (the caller keeps its own).
pub(super) fn keyed(
    o: &Object,
    known: &Known,
    part: Part,
    key: u64,
    make: impl FnOnce() -> Result<JsValue, JsValue>,
) -> Result<(), JsValue> {
    let key = js_key(key);
    let value = if known.has(part, key) { JsValue::NULL } else { make()? };
    set(o, part.name(), &value);
    set(o, &format!("{}Key", part.name()), &key.into());
    Ok(())
}

/// The thread list last answered: its key and each entry's key.
#[derive(Default)]
pub(super) struct ThreadsSent {
    last: Option<(f64, Vec<u64>)>,
}

impl ThreadsSent {
    /// The thread list with the per-thread keys `keys` (list key `all`): to a
    /// caller holding the list last answered, `{changes: [[index, entry], ...],
    /// length}` with the entries whose key changed; else the whole list.
    /// `entry(i)` makes entry `i`.
    pub(super) fn answer(
        &mut self,
        known: &Known,
        all: u64,
        keys: &[u64],
        entry: impl Fn(usize) -> Result<JsValue, JsValue>,
    ) -> Result<JsValue, JsValue> {
        let held = match &self.last {
            Some((k, old)) if known.keeps() && known.key(Part::Threads) == Some(*k) => Some(old),
            _ => None,
        };
        let out: JsValue = match held {
            Some(old) => {
                let changes = Array::new();
                for (i, k) in keys.iter().enumerate() {
                    if old.get(i) != Some(k) {
                        changes.push(&Array::of2(&(i as u32).into(), &entry(i)?));
                    }
                }
                let o = Object::new();
                set(&o, "changes", &changes);
                set(&o, "length", &(keys.len() as u32).into());
                o.into()
            }
            None => (0..keys.len()).map(entry).collect::<Result<Array, JsValue>>()?.into(),
        };
        self.last = Some((js_key(all), keys.to_vec()));
        Ok(out)
    }
}
