//! Another program compared with a session's (`Session::compare`): the
//! items laid over its drawings and the comparison as a JavaScript value.

use js_sys::{Float64Array, Object};
use wasm_bindgen::JsValue;

use super::js::{set, to_js};

/// The items of the compared plan `b` laid over the side section and over the tooth section of thread `thread`.
pub(super) fn overlay_items(b: &crate::plan::Plan, thread: usize) -> [Vec<crate::diagram::Item>; 2] {
    let side = crate::diagram::overlay::items(&crate::diagram::side(b));
    let tooth = crate::diagram::tooth(b, thread, 1).map(|s| crate::diagram::overlay::items(&s)).unwrap_or_default();
    [side, tooth]
}

/// A comparison as a JS value: `{same, threads, passes, differences}`.
pub(super) fn comparison_js(c: &crate::compare::Comparison) -> JsValue {
    let o = Object::new();
    set(&o, "same", &c.same().into());
    set(&o, "threads", &Float64Array::from(&[c.threads[0] as f64, c.threads[1] as f64][..]).into());
    set(&o, "passes", &Float64Array::from(&[c.passes[0] as f64, c.passes[1] as f64][..]).into());
    set(&o, "differences", &to_js(&c.differences).unwrap_or(JsValue::NULL));
    o.into()
}
