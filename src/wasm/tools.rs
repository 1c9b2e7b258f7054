//! The program-writing tools JavaScript calls: the thread wizard
//! ([`crate::wizard`]) and its table of forms, a program written block by
//! block for another controller ([`crate::expand`]) and the plan as JSON.
//! They are a wasm module of their own (feature `tools`), loaded by a page
//! when first used: each plans the text it is given (what the page's
//! session planned last) and keeps nothing.
//!
//! As in `bind`, nothing here may panic: a request is read field by field,
//! every wrong field is named in the error.

use js_sys::Reflect;
use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::js::{dialect, err, settings_from, to_js};
use crate::dialect::Dialect;
use crate::form::Form;
use crate::message::{Lang, Remark};
use crate::wizard::{Request, generate};

/// A form for the wizard's selector.
#[derive(Serialize)]
struct FormInfo {
    name: &'static str,
    title: &'static str,
}

/// A dialect and the forms the wizard writes for it.
#[derive(Serialize)]
struct DialectForms {
    dialect: &'static str,
    title: &'static str,
    forms: Vec<FormInfo>,
}

/// The wizard's targets: `[{dialect, title, forms: [{name, title}]}]`, the
/// forms' titles in `lang` (`en` or `zh`; anything else is English).
#[wasm_bindgen]
pub fn wizard_forms(lang: Option<String>) -> Result<JsValue, JsValue> {
    let lang = lang.as_deref().and_then(Lang::parse).unwrap_or_default();
    let list: Vec<DialectForms> = Dialect::ALL
        .iter()
        .map(|d| DialectForms {
            dialect: d.name(),
            title: d.title(),
            forms: Form::of(*d)
                .iter()
                .map(|f| FormInfo { name: f.name(), title: f.title_phrase().text(lang) })
                .collect(),
        })
        .collect();
    to_js(&list)
}

/// Field `key` of `o`: `None` when missing, null or an empty string.
fn field(o: &JsValue, key: &str) -> Option<JsValue> {
    let v = Reflect::get(o, &JsValue::from_str(key)).ok()?;
    if v.is_undefined() || v.is_null() || v.as_string().is_some_and(|s| s.trim().is_empty()) {
        return None;
    }
    Some(v)
}

/// A number field: a JS number or a numeric string; finite.
fn number(o: &JsValue, key: &str) -> Result<Option<f64>, JsValue> {
    let Some(v) = field(o, key) else { return Ok(None) };
    let n = v.as_f64().or_else(|| v.as_string().and_then(|s| s.trim().parse::<f64>().ok()));
    match n {
        Some(n) if n.is_finite() => Ok(Some(n)),
        _ => Err(err(format!("{key}: not a number"))),
    }
}

/// A text field, at most 200 characters.
fn text(o: &JsValue, key: &str) -> Result<Option<String>, JsValue> {
    let Some(v) = field(o, key) else { return Ok(None) };
    let s = v.as_string().ok_or_else(|| err(format!("{key}: not text")))?;
    if s.chars().count() > 200 {
        return Err(err(format!("{key}: longer than 200 characters")));
    }
    Ok(Some(s.trim().to_string()))
}

/// Reads a wizard request: `{designation, major, lead, starts, internal,
/// startZ, endZ, length, noseRadius, maxRpm, maxFeed, dialect, form, lang}` (all
/// optional but a thread — a designation, or major and lead — and a length or end Z).
fn request(o: &JsValue) -> Result<Request, JsValue> {
    let mut r = Request {
        designation: text(o, "designation")?,
        major: number(o, "major")?,
        lead: number(o, "lead")?,
        ..Request::default()
    };
    if let Some(n) = number(o, "starts")? {
        if n.fract() != 0.0 || !(1.0..=360.0).contains(&n) {
            return Err(err("starts: a whole number from 1 to 360"));
        }
        r.starts = Some(n as u32);
    }
    r.internal = field(o, "internal").map(|v| v.as_bool().unwrap_or(false));
    r.start_z = number(o, "startZ")?.unwrap_or(0.0);
    r.end_z = number(o, "endZ")?;
    r.length = number(o, "length")?;
    r.nose_radius = number(o, "noseRadius")?.unwrap_or(r.nose_radius);
    r.max_rpm = number(o, "maxRpm")?.unwrap_or(r.max_rpm);
    r.max_feed = number(o, "maxFeed")?.unwrap_or(r.max_feed);
    if let Some(d) = text(o, "dialect")? {
        r.dialect = dialect(&d)?;
    }
    if let Some(f) = text(o, "form")? {
        r.form = Form::parse(&f).ok_or_else(|| {
            let names: Vec<&str> = Form::ALL.iter().map(|f| f.name()).collect();
            err(format!("form: unknown '{f}' ({})", names.join(", ")))
        })?;
    }
    Ok(r)
}

/// A written program with its notes in the page's language.
#[derive(Serialize)]
struct Written<'a, S: Serialize> {
    program: &'a str,
    notes: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    spec: Option<S>,
}

impl<'a, S: Serialize> Written<'a, S> {
    /// `program` with `notes` rendered in `lang` (and the wizard's `spec`).
    fn new(program: &'a str, notes: &[Remark], lang: Lang, spec: Option<S>) -> Self {
        Written { program, notes: notes.iter().map(|n| n.render(lang)).collect(), spec }
    }
}

/// The wizard's program for `req` (see [`request`]; its `lang`, `en` or
/// `zh`, is the language of the notes and the refusal): `{program, notes,
/// spec}`; an error names what is wrong with the request or why the thread
/// cannot be written for the form.
#[wasm_bindgen]
pub fn wizard_generate(req: JsValue) -> Result<JsValue, JsValue> {
    let r = request(&req)?;
    let lang = text(&req, "lang")?.and_then(|l| Lang::parse(&l)).unwrap_or_default();
    let g = generate(&r).map_err(|e| err(e.render(lang)))?;
    to_js(&Written::new(&g.program, &g.notes, lang, Some(&g.spec)))
}

/// The plan of `text` written block by block for dialect `to` (every pass
/// with its approach, cut, run-out, retract and return; see
/// [`crate::expand`]): `{program, notes}`, the notes in `lang` (`en` or
/// `zh`; anything else is English). Planned again, the program gives the
/// same passes.
#[wasm_bindgen]
pub fn expand(
    text: &str,
    dialect_name: &str,
    settings: &str,
    to: &str,
    lang: Option<String>,
) -> Result<JsValue, JsValue> {
    let (s, _) = settings_from(dialect(dialect_name)?, settings);
    let to = dialect(to)?;
    let lang = lang.as_deref().and_then(Lang::parse).unwrap_or_default();
    let e = crate::expand::expand(&crate::plan(text, &s), to);
    to_js(&Written::<()>::new(&e.program, &e.notes, lang, None))
}

/// The whole plan of `text` as a JSON-compatible value (what the CLI's
/// `--json` writes, once `JSON.stringify`-ed, with its `dialect-hint` note
/// when another dialect reads the text better), for download. The wasm
/// carries no JSON writer of its own.
#[wasm_bindgen]
pub fn plan_value(text: &str, dialect_name: &str, settings: &str) -> Result<JsValue, JsValue> {
    let (s, _) = settings_from(dialect(dialect_name)?, settings);
    let mut plan = crate::plan(text, &s);
    crate::hint::add(text, &s, &mut plan, crate::hint::MAX_BYTES);
    plan.serialize(&serde_wasm_bindgen::Serializer::json_compatible()).map_err(err)
}
