//! The threading forms a program can be written in: a name and a title for each.
//! Each controller lists the forms it has (its `Writing` table).

use serde::Serialize;

use crate::message::{Phrase, tools};

/// The threading forms a program can be written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Form {
    /// G32 block by block, textbook style (infeed, cut, retract, return per pass; table 4-3 infeeds).
    G32,
    /// G92, the simple cycle: one block per pass.
    G92,
    /// G76, the two-block multiple cycle (GSK, Fanuc).
    G76,
    /// G78, GSK's enhanced cycle.
    G78,
    /// Renhe G33 block by block (incremental, G30 tail).
    RenheG33,
    /// LinuxCNC G33 block by block.
    G33,
    /// LinuxCNC's G76 cycle.
    LinuxG76,
}

/// Names and titles of the forms, in [`Form::ALL`] order (names: command line and JSON).
const FORM_NAMES: [(&str, &Phrase); 7] = [
    ("g32", &tools::FORM_G32),
    ("g92", &tools::FORM_G92),
    ("g76", &tools::FORM_G76),
    ("g78", &tools::FORM_G78),
    ("renhe_g33", &tools::FORM_RENHE_G33),
    ("g33", &tools::FORM_G33),
    ("linuxcnc_g76", &tools::FORM_LINUXCNC_G76),
];

impl Form {
    /// Every form.
    pub const ALL: [Form; 7] = [Form::G32, Form::G92, Form::G76, Form::G78, Form::RenheG33, Form::G33, Form::LinuxG76];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        FORM_NAMES[self as usize].0
    }

    /// A display title (English).
    pub fn title(self) -> &'static str {
        FORM_NAMES[self as usize].1.en
    }

    /// The display title in both languages.
    pub fn title_phrase(self) -> &'static Phrase {
        FORM_NAMES[self as usize].1
    }

    /// Reads a form name (case-insensitive, `-` for `_`).
    pub fn parse(s: &str) -> Option<Form> {
        let s = s.trim().to_ascii_lowercase().replace('-', "_");
        Form::ALL.into_iter().find(|f| f.name() == s)
    }
}
