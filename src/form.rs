//! The threading forms a program can be written in: a name and a title for each.
//! Each controller lists the forms it has (its `Writing` table).

use serde::Serialize;

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

/// Names of the forms, in [`Form::ALL`] order (command line and JSON).
const FORM_NAMES: [(&str, &str); 7] = [
    ("g32", "G32 block by block (textbook, table 4-3)"),
    ("g92", "G92 simple cycle"),
    ("g76", "G76 multiple cycle"),
    ("g78", "G78 enhanced cycle"),
    ("renhe_g33", "Renhe G33 block by block"),
    ("g33", "LinuxCNC G33 block by block"),
    ("linuxcnc_g76", "LinuxCNC G76 cycle"),
];

impl Form {
    /// Every form.
    pub const ALL: [Form; 7] = [Form::G32, Form::G92, Form::G76, Form::G78, Form::RenheG33, Form::G33, Form::LinuxG76];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        FORM_NAMES[self as usize].0
    }

    /// A display title.
    pub fn title(self) -> &'static str {
        FORM_NAMES[self as usize].1
    }

    /// Reads a form name (case-insensitive, `-` for `_`).
    pub fn parse(s: &str) -> Option<Form> {
        let s = s.trim().to_ascii_lowercase().replace('-', "_");
        Form::ALL.into_iter().find(|f| f.name() == s)
    }
}
