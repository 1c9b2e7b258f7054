//! The options of a ```` ```screwcut ```` block: its info string read as the
//! element's attributes (`dialect=fanuc0i view=side,tooth height=320`),
//! each checked the way the element would use it, so that a bad option is a
//! build error instead of a diagram that quietly shows something else.

use screwcut::message::Lang;
use screwcut::{Dialect, Settings};

/// The options a block may carry (the element's attributes, less `src`: the
/// program is the block).
pub const KNOWN: [&str; 10] =
    ["dialect", "view", "height", "thread", "settings", "lang", "editable", "hide-code", "live", "app"];

pub use screwcut::element::Options;

/// The words of an info string after the language: `key`, `key=value`,
/// `key="value with spaces"` or `key='…'`.
fn words(info: &str) -> Result<Vec<(String, Option<String>)>, String> {
    let mut out = Vec::new();
    let mut chars = info.chars().peekable();
    loop {
        while chars.next_if(|c| c.is_whitespace()).is_some() {}
        if chars.peek().is_none() {
            return Ok(out);
        }
        let mut key = String::new();
        while let Some(c) = chars.next_if(|c| !c.is_whitespace() && *c != '=') {
            key.push(c);
        }
        if chars.next_if_eq(&'=').is_none() {
            out.push((key, None));
            continue;
        }
        let mut value = String::new();
        match chars.next_if(|c| *c == '"' || *c == '\'') {
            Some(q) => loop {
                match chars.next() {
                    Some(c) if c == q => break,
                    Some(c) => value.push(c),
                    None => return Err(format!("the value of '{key}' has no closing {q}")),
                }
            },
            None => {
                while let Some(c) = chars.next_if(|c| !c.is_whitespace()) {
                    value.push(c);
                }
            }
        }
        out.push((key, Some(value)));
    }
}

/// Reads the options of a block from its info string without the leading
/// `screwcut`; `Err` says which option is wrong and why.
pub fn parse(info: &str) -> Result<Options, String> {
    let mut o = Options::default();
    let mut seen: Vec<String> = Vec::new();
    let mut words = words(info)?;
    // The dialect first: the settings are checked against it.
    words.sort_by_key(|(k, _)| k != "dialect");
    for (key, value) in words {
        if seen.contains(&key) {
            return Err(format!("option '{key}' is given twice"));
        }
        seen.push(key.clone());
        let flag = matches!(key.as_str(), "editable" | "hide-code" | "live");
        let value = match (flag, value) {
            (true, None) => String::new(),
            (true, Some(_)) => return Err(format!("'{key}' is a flag: write it without a value")),
            (false, Some(v)) => v,
            (false, None) if key == "src" => String::new(),
            (false, None) if KNOWN.contains(&key.as_str()) => return Err(format!("option '{key}' needs a value")),
            (false, None) => String::new(),
        };
        apply(&mut o, &key, &value)?;
    }
    Ok(o)
}

/// Sets one option from its text.
fn apply(o: &mut Options, key: &str, value: &str) -> Result<(), String> {
    match key {
        "dialect" => {
            o.dialect = Dialect::parse(value)
                .ok_or_else(|| format!("unknown dialect '{value}' (known: {})", Dialect::names()))?;
        }
        "view" => o.views = screwcut::element::views(value)?,
        "height" => {
            o.height = value
                .parse::<u32>()
                .ok()
                .filter(|h| (120..=1200).contains(h))
                .ok_or_else(|| format!("height '{value}' is not a whole number of px from 120 to 1200"))?;
        }
        "thread" => {
            o.thread = value
                .parse::<usize>()
                .ok()
                .filter(|&n| n >= 1)
                .ok_or_else(|| format!("thread '{value}' is not a thread number (1, 2, …)"))?;
        }
        "settings" => {
            let mut s = Settings::new(o.dialect);
            for e in value.split([';', '\n']).map(str::trim).filter(|e| !e.is_empty()) {
                s.assign(e).map_err(|err| format!("setting '{e}': {err}"))?;
                o.settings.push(e.to_string());
            }
        }
        "lang" => {
            o.lang = Lang::parse(value).ok_or_else(|| format!("unknown lang '{value}' (known: en, zh)"))?;
        }
        "editable" => o.editable = true,
        "hide-code" => o.hide_code = true,
        "live" => o.live = true,
        "app" => o.app = Some(screwcut::element::app_url(value)?),
        "src" => return Err("'src' is not an option here: the program is the block's content".into()),
        _ => return Err(format!("unknown option '{key}' (known: {})", KNOWN.join(", "))),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_attributes_as_the_element_takes_them() {
        let o = parse(r#" view=table,side height=280 thread=2 settings="block_delete=1; x_mode=radius" lang=zh dialect=fanuc0i editable"#)
            .unwrap();
        assert_eq!(o.dialect, Dialect::Fanuc0i);
        assert_eq!(o.views, vec!["side", "table"]);
        assert_eq!((o.height, o.thread, o.lang, o.editable, o.hide_code), (280, 2, Lang::Zh, true, false));
        assert_eq!(o.settings, vec!["block_delete=1", "x_mode=radius"]);
    }

    #[test]
    fn defaults_are_the_elements() {
        let o = parse("").unwrap();
        assert_eq!((o.dialect, o.views.clone(), o.height, o.thread), (Dialect::Gsk980tdc, vec!["side"], 320, 1));
    }

    #[test]
    fn a_bad_option_says_which_and_why() {
        let err = |info: &str| parse(info).unwrap_err();
        assert!(err("heigth=300").starts_with("unknown option 'heigth' (known: dialect,"));
        assert_eq!(err("dialect=haas9"), format!("unknown dialect 'haas9' (known: {})", Dialect::names()));
        assert_eq!(err("view=side,top"), "unknown view 'top' (known: side, tooth, starts, table)");
        assert_eq!(err("height=50"), "height '50' is not a whole number of px from 120 to 1200");
        assert_eq!(err("thread=0"), "thread '0' is not a thread number (1, 2, …)");
        assert!(err("settings=\"No.999=1\"").starts_with("setting 'No.999=1': "));
        assert_eq!(err("settings=\"bad"), "the value of 'settings' has no closing \"");
        assert_eq!(err("editable=yes"), "'editable' is a flag: write it without a value");
        assert_eq!(err("dialect"), "option 'dialect' needs a value");
        assert_eq!(err("src=a.nc"), "'src' is not an option here: the program is the block's content");
        assert_eq!(err("app=javascript:alert(1)"), "app 'javascript:alert(1)' is not an http(s) or relative URL");
        assert_eq!(err("height=300 height=320"), "option 'height' is given twice");
    }
}
