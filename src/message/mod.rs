//! The message catalogue: every diagnostic and thread-check note as a
//! template with named arguments, in English and Chinese.
//!
//! A site that finds something gives a [`Template`] (which carries the
//! diagnostic [`Code`]) and its [`Args`]; the text is written only when it is
//! shown, in the language asked for ([`Lang`]). Templates name their
//! arguments in braces (`{word}`); an argument is a number (written with up
//! to four decimals, as every message writes lengths), an integer, a text
//! kept verbatim in every language (a word as written, a designation, a
//! LinuxCNC message, which is quoted as LinuxCNC prints it) or a
//! [`Phrase`], itself a small template in both languages that reads the
//! same arguments.
//!
//! The templates live by area: [`lex`] (reading characters and words),
//! [`read`] (the interpreter and the controllers' commands), [`renhe`],
//! [`linuxcnc`], [`cycle`] (planning cycles and grouping passes), [`shop`]
//! (shop-floor checks and textbook advice), [`gauge`] (the thread check's
//! notes), [`standard`] (designations), [`tools`] (what the wizard and
//! `expand` say, as [`Remark`]s) and [`words`] (the command line's
//! summary). `words` is not re-exported: its names are read as `words::NAME`.

use std::borrow::Cow;

use serde::Serialize;
use serde::ser::SerializeMap;

use crate::block::Word;
use crate::code::Code;

pub mod cycle;
pub mod flow;
pub mod gauge;
pub mod lex;
pub mod linuxcnc;
pub mod read;
pub mod renhe;
pub mod shop;
pub mod standard;
pub mod tools;
pub mod words;

pub use cycle::*;
pub use flow::*;
pub use gauge::*;
pub use lex::*;
pub use linuxcnc::*;
pub use read::*;
pub use renhe::*;
pub use shop::*;
pub use standard::*;

/// A language messages are written in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Lang {
    /// English (the JSON's `message` and the default everywhere).
    #[default]
    En,
    /// Simplified Chinese.
    Zh,
}

impl Lang {
    /// `en` or `zh` (case-insensitive; `zh-CN` and the like are Chinese).
    pub fn parse(s: &str) -> Option<Lang> {
        let s = s.trim().to_ascii_lowercase();
        match s.as_str() {
            "en" | "english" => Some(Lang::En),
            _ if s == "zh" || s.starts_with("zh-") || s.starts_with("zh_") || s == "chinese" => Some(Lang::Zh),
            _ => None,
        }
    }

    /// `en` or `zh`.
    pub fn name(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
        }
    }
}

/// A message of the catalogue: its diagnostic code and its text in each language.
#[derive(Debug, PartialEq, Eq)]
pub struct Template {
    /// The code of the diagnostic this message is (notes carry the code of the check they belong to).
    pub code: Code,
    /// The template's name in the catalogue (for tests and reports; empty in the wasm build).
    pub name: &'static str,
    /// English.
    pub en: &'static str,
    /// Chinese.
    pub zh: &'static str,
}

impl Template {
    /// The template text in `lang`.
    pub fn text(&self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en,
            Lang::Zh => self.zh,
        }
    }
}

/// A piece of a message in both languages, given as an argument: it is
/// rendered with the arguments of the message it is part of.
#[derive(Debug, PartialEq, Eq, Hash)]
pub struct Phrase {
    /// English.
    pub en: &'static str,
    /// Chinese.
    pub zh: &'static str,
}

impl Phrase {
    /// The phrase in `lang`.
    pub fn text(&self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en,
            Lang::Zh => self.zh,
        }
    }

    /// The phrase in `lang` with `args` filled in.
    pub fn render(&self, args: &Args, lang: Lang) -> String {
        let mut out = String::new();
        write_template(&mut out, self.text(lang), args, lang, 0);
        out
    }
}

/// One argument of a message.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// A number, written with up to four decimals ([`crate::num::fmt`]).
    Num(f64),
    /// Numbers, each written as [`Arg::Num`], separated by spaces (a list
    /// of infeeds): written when shown, not when the message is made.
    Nums(Vec<f64>),
    /// A whole number.
    Int(i64),
    /// Text kept as it is in every language (a word as written, a name, a quoted message).
    Text(Cow<'static, str>),
    /// A phrase written in the message's language.
    Phrase(&'static Phrase),
    /// Another message, written in the same language (a designation's error in a diagnostic).
    Message(Box<Message>),
    /// Notes written after the message, each after a separator (nothing when empty).
    Notes(Vec<Message>),
}

impl From<f64> for Arg {
    fn from(v: f64) -> Arg {
        Arg::Num(v)
    }
}

macro_rules! int_args {
    ($($t:ty),*) => { $( impl From<$t> for Arg { fn from(v: $t) -> Arg { Arg::Int(v as i64) } } )* };
}
int_args!(i32, i64, u8, u32, u64, usize);

impl From<&str> for Arg {
    fn from(v: &str) -> Arg {
        Arg::Text(Cow::Owned(v.to_string()))
    }
}

impl From<String> for Arg {
    fn from(v: String) -> Arg {
        Arg::Text(Cow::Owned(v))
    }
}

impl From<char> for Arg {
    fn from(v: char) -> Arg {
        Arg::Text(Cow::Owned(v.to_string()))
    }
}

impl From<&Word> for Arg {
    fn from(w: &Word) -> Arg {
        Arg::Text(Cow::Owned(w.display()))
    }
}

impl From<&&Word> for Arg {
    fn from(w: &&Word) -> Arg {
        Arg::from(*w)
    }
}

impl From<Word> for Arg {
    fn from(w: Word) -> Arg {
        Arg::from(&w)
    }
}

impl From<&'static Phrase> for Arg {
    fn from(p: &'static Phrase) -> Arg {
        Arg::Phrase(p)
    }
}

impl Arg {
    /// A text argument without copying (a name or a fixed word).
    pub fn lit(s: &'static str) -> Arg {
        Arg::Text(Cow::Borrowed(s))
    }

    fn write(&self, out: &mut String, args: &Args, lang: Lang, depth: u8) {
        match self {
            Arg::Num(v) => out.push_str(&crate::num::fmt(*v)),
            Arg::Nums(vs) => write_nums(out, vs),
            Arg::Int(v) => out.push_str(&v.to_string()),
            Arg::Text(s) => out.push_str(s),
            Arg::Phrase(p) => write_template(out, p.text(lang), args, lang, depth + 1),
            Arg::Message(m) => write_template(out, m.template.text(lang), &m.args, lang, depth + 1),
            Arg::Notes(notes) => {
                for m in notes {
                    out.push_str(if lang == Lang::Zh { "；" } else { "; " });
                    write_template(out, m.template.text(lang), &m.args, lang, depth + 1);
                }
            }
        }
    }
}

/// `vs` written as [`Arg::Nums`] is.
fn write_nums(out: &mut String, vs: &[f64]) {
    for (i, v) in vs.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        out.push_str(&crate::num::fmt(*v));
    }
}

impl From<Message> for Arg {
    fn from(m: Message) -> Arg {
        Arg::Message(Box::new(m))
    }
}

/// Feeds `template` and the argument names (by address) and the values
/// to `h`: equal messages from the same places hash equally (a float by its
/// bits, so `0.0` and `-0.0` may differ); a caller compares the messages
/// whose keys match.
pub fn hash_message(template: &'static Template, args: &Args, h: &mut impl std::hash::Hasher) {
    h.write_usize(std::ptr::from_ref(template) as usize);
    for (name, arg) in &args.0 {
        h.write_usize(name.as_ptr() as usize);
        match arg {
            Arg::Num(v) => h.write_u64(v.to_bits()),
            Arg::Nums(vs) => {
                h.write_usize(vs.len());
                vs.iter().for_each(|v| h.write_u64(v.to_bits()));
            }
            Arg::Int(v) => h.write_u64(*v as u64 ^ 1),
            Arg::Text(t) => h.write(t.as_bytes()),
            Arg::Phrase(p) => h.write_usize(std::ptr::from_ref(*p) as usize),
            Arg::Message(m) => hash_message(m.template, &m.args, h),
            Arg::Notes(ns) => ns.iter().for_each(|m| hash_message(m.template, &m.args, h)),
        }
    }
}

/// The named arguments of a message, in the order given.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Args(pub Vec<(&'static str, Arg)>);

impl Args {
    /// The argument named `name`.
    pub fn get(&self, name: &str) -> Option<&Arg> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, a)| a)
    }

    /// These arguments and `name` = `arg`.
    pub fn with(mut self, name: &'static str, arg: impl Into<Arg>) -> Args {
        self.0.push((name, arg.into()));
        self
    }

    /// These arguments followed by `more`.
    pub fn with_all(mut self, more: Args) -> Args {
        self.0.extend(more.0);
        self
    }
}

impl Serialize for Args {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (name, arg) in &self.0 {
            match arg {
                Arg::Num(v) => m.serialize_entry(name, &crate::num::round_out(*v))?,
                // As text, as it is shown.
                Arg::Nums(vs) => {
                    let mut text = String::new();
                    write_nums(&mut text, vs);
                    m.serialize_entry(name, &text)?
                }
                // Beyond 2^53 a JavaScript number would not hold it exactly.
                Arg::Int(v) if v.unsigned_abs() < 1 << 53 => m.serialize_entry(name, v)?,
                Arg::Int(v) => m.serialize_entry(name, &(*v as f64))?,
                Arg::Text(t) => m.serialize_entry(name, t)?,
                Arg::Phrase(p) => {
                    let mut text = String::new();
                    write_template(&mut text, p.en, self, Lang::En, 1);
                    m.serialize_entry(name, &text)?
                }
                Arg::Message(msg) => m.serialize_entry(name, &msg.render(Lang::En))?,
                Arg::Notes(notes) => m.serialize_entry(name, notes)?,
            }
        }
        m.end()
    }
}

/// Builds [`Args`]: `args![n, limit = self.limit, word = &w]` (a name alone
/// takes the variable of that name).
#[macro_export]
macro_rules! args {
    (@v $name:ident) => { $name };
    (@v $name:ident $v:expr) => { $v };
    ($($name:ident $(= $v:expr)?),* $(,)?) => {
        $crate::message::Args(vec![$((stringify!($name), $crate::message::Arg::from($crate::args!(@v $name $($v)?)))),*])
    };
}

/// A template with its arguments: a diagnostic's message before it is placed, or a note.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// What is said.
    pub template: &'static Template,
    /// The values it names.
    pub args: Args,
}

impl Message {
    /// `template` with `args`.
    pub fn new(template: &'static Template, args: Args) -> Message {
        Message { template, args }
    }

    /// The diagnostic code of the template.
    pub fn code(&self) -> Code {
        self.template.code
    }

    /// The text in `lang`.
    pub fn render(&self, lang: Lang) -> String {
        render(self.template, &self.args, lang)
    }
}

/// A phrase with its arguments: what a tool says that is not a diagnostic
/// of a program (the wizard's notes and refusals, `expand`'s notes).
#[derive(Clone, Debug, PartialEq)]
pub struct Remark {
    /// What is said.
    pub phrase: &'static Phrase,
    /// The values it names.
    pub args: Args,
}

impl Remark {
    /// `phrase` with `args`.
    pub fn new(phrase: &'static Phrase, args: Args) -> Remark {
        Remark { phrase, args }
    }

    /// The text in `lang`.
    pub fn render(&self, lang: Lang) -> String {
        self.phrase.render(&self.args, lang)
    }
}

/// Remarks serialise as their English text.
impl Serialize for Remark {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.render(Lang::En))
    }
}

impl std::fmt::Display for Remark {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.render(Lang::En))
    }
}

/// Notes serialise as their English text (the JSON's language).
impl Serialize for Message {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.render(Lang::En))
    }
}

impl std::fmt::Display for Message {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.render(Lang::En))
    }
}

/// `template` in `lang` with `args` filled in. A name without an argument is
/// left as `{name}` (the tests look for those).
pub fn render(template: &Template, args: &Args, lang: Lang) -> String {
    let text = template.text(lang);
    let mut out = String::with_capacity(text.len() + 16);
    write_template(&mut out, text, args, lang, 0);
    out
}

fn write_template(out: &mut String, text: &str, args: &Args, lang: Lang, depth: u8) {
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        match after.find('}') {
            Some(close) => {
                let name = &after[..close];
                match args.get(name) {
                    Some(a) if depth < 4 => a.write(out, args, lang, depth),
                    _ => {
                        out.push('{');
                        out.push_str(name);
                        out.push('}');
                    }
                }
                rest = &after[close + 1..];
            }
            None => {
                out.push_str(&rest[open..]);
                rest = "";
            }
        }
    }
    out.push_str(rest);
}

/// The argument names a template text uses, in order.
pub fn names(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        let after = &rest[open + 1..];
        let Some(close) = after.find('}') else { break };
        out.push(&after[..close]);
        rest = &after[close + 1..];
    }
    out
}

/// Declares templates: `NAME = Code: "English", "中文";` each a `pub static`,
/// and `ALL`, every template of the file.
macro_rules! templates {
    ($( $name:ident = $code:ident: $en:literal, $zh:literal; )*) => {
        $(
            #[doc = $en]
            pub static $name: $crate::message::Template = $crate::message::Template {
                code: $crate::code::Code::$code,
                // The browser never shows a template's name: not shipped in the wasm.
                name: if cfg!(target_arch = "wasm32") { "" } else { stringify!($name) },
                en: $en,
                zh: $zh,
            };
        )*
        /// Every template of this part of the catalogue.
        pub(super) static ALL: &[&$crate::message::Template] = &[ $( &$name, )* ];
    };
}

/// Declares phrases: `NAME: "English", "中文";` each a `pub static`, and `PHRASES`.
macro_rules! phrases {
    ($( $name:ident: $en:literal, $zh:literal; )*) => {
        $(
            #[doc = concat!("“", $en, "”")]
            pub static $name: $crate::message::Phrase = $crate::message::Phrase { en: $en, zh: $zh };
        )*
        /// Every phrase of this part of the catalogue.
        pub(super) static PHRASES: &[&$crate::message::Phrase] = &[ $( &$name, )* ];
    };
}

pub(crate) use phrases;
pub(crate) use templates;

/// Every template of the catalogue.
pub fn all() -> impl Iterator<Item = &'static Template> {
    [lex::ALL, flow::ALL, read::ALL, renhe::ALL, linuxcnc::ALL, cycle::ALL, shop::ALL, gauge::ALL, standard::ALL]
        .into_iter()
        .flatten()
        .copied()
}

/// Every phrase of the catalogue.
pub fn all_phrases() -> impl Iterator<Item = &'static Phrase> {
    [
        read::PHRASES,
        flow::PHRASES,
        linuxcnc::PHRASES,
        cycle::PHRASES,
        shop::PHRASES,
        gauge::PHRASES,
        standard::PHRASES,
        tools::PHRASES,
        words::PHRASES,
    ]
    .into_iter()
    .flatten()
    .copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_named_arguments_in_either_language() {
        let a = args![n = 3_usize, limit = 2.5, word = "X1"];
        assert_eq!(render(&BLOCK_TOO_LONG, &a, Lang::En).matches("2.5").count(), 1);
        let t =
            Template { code: Code::AfterEnd, name: "T", en: "{word} at {n}: {limit} {missing}", zh: "{word}：{n}" };
        assert_eq!(render(&t, &a, Lang::En), "X1 at 3: 2.5 {missing}");
        assert_eq!(render(&t, &a, Lang::Zh), "X1：3");
        assert_eq!(names(t.en), ["word", "n", "limit", "missing"]);
        assert_eq!(serde_json::to_string(&a).unwrap(), r#"{"n":3,"limit":2.5,"word":"X1"}"#);
    }

    #[test]
    fn languages_parse() {
        assert_eq!(Lang::parse("ZH-cn"), Some(Lang::Zh));
        assert_eq!(Lang::parse("en"), Some(Lang::En));
        assert_eq!(Lang::parse("fr"), None);
    }
}
