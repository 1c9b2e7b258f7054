//! The diagnostics list of an answer: the whole list, nothing (the caller
//! holds it), or the change from the list answered last ([`super::splice`]).

use js_sys::{Object, Uint32Array};
use wasm_bindgen::prelude::*;

use super::js::{editor_diagnostics_of, editor_offsets, set, to_js};
use super::splice::{entry_keys, list_key, splice};
use crate::message::Lang;
use crate::plan::Plan;

/// The diagnostics list a session answered last: its language, entries' keys and key.
#[derive(Default)]
pub(super) struct DiagnosticsSent {
    lang: Lang,
    keys: Vec<u64>,
    /// None before the first answer.
    key: Option<f64>,
}

impl DiagnosticsSent {
    /// Sets the plan's diagnostics in `lang` on `o`: `diagnosticsKey`, and
    /// `diagnostics` — null when the key is `known` (the key of the list
    /// the caller holds), else the whole list — unless the caller holds the
    /// list answered last: then `diagnostics` is null and
    /// `diagnosticsSplice` is `{at, remove, items, offsets}`: `remove`
    /// entries from `at` replaced by `items`, and every entry's `[from,
    /// to]` (UTF-16) in `offsets`, which a keystroke above moves.
    pub(super) fn answer(
        &mut self,
        o: &Object,
        text: &str,
        plan: &Plan,
        lang: Lang,
        known: f64,
    ) -> Result<(), JsValue> {
        let keys = entry_keys(plan);
        let key = list_key(&keys, lang);
        set(o, "diagnosticsKey", &key.into());
        let units = || editor_offsets(text, plan);
        if key == known {
            set(o, "diagnostics", &JsValue::NULL);
        } else if self.key == Some(known) && self.lang == lang {
            let c = splice(&self.keys, &keys);
            let units = units();
            let s = Object::new();
            set(&s, "at", &(c.at as u32).into());
            set(&s, "remove", &(c.remove as u32).into());
            set(&s, "items", &to_js(&editor_diagnostics_of(plan, &units, lang, c.at..c.at + c.insert))?);
            set(&s, "offsets", &Uint32Array::from(&units[..]).into());
            set(o, "diagnostics", &JsValue::NULL);
            set(o, "diagnosticsSplice", &s.into());
        } else {
            let units = units();
            let all = editor_diagnostics_of(plan, &units, lang, 0..plan.diagnostics.len());
            set(o, "diagnostics", &to_js(&all)?);
        }
        *self = DiagnosticsSent { lang, keys, key: Some(key) };
        Ok(())
    }
}
