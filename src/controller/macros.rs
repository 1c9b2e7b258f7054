//! What a controller reads of subprograms and macros: data in its rules,
//! run by the program flow.

use crate::settings::{P, Settings};

/// The controller's macro language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flavor {
    /// Fanuc custom macro B (Fanuc 0i, and GSK980TDc's `#` macros).
    Fanuc,
    /// LinuxCNC's rs274ngc: o-words, named parameters.
    LinuxCnc,
}

/// A nesting limit: fixed by the controller, or a parameter of it.
#[derive(Clone, Copy, Debug)]
pub enum Depth {
    /// Fixed in the controller's software.
    Fixed(u32),
    /// Set by a parameter (a setting).
    Setting(P),
}

impl Depth {
    /// The limit under `settings`.
    pub fn get(self, settings: &Settings) -> u32 {
        match self {
            Depth::Fixed(n) => n,
            Depth::Setting(p) => settings.int(p).max(1) as u32,
        }
    }

    /// The setting that holds it, if one does.
    pub fn setting(self) -> Option<&'static str> {
        match self {
            Depth::Fixed(_) => None,
            Depth::Setting(p) => Some(crate::settings::DEFS[p as usize].name),
        }
    }
}

/// A controller's macro and subprogram forms (data in its [`Rules`](super::Rules)).
#[derive(Debug)]
pub struct Macros {
    /// The macro language.
    pub flavor: Flavor,
    /// `M98 P… L…` calls and `M99` returns.
    pub subprograms: bool,
    /// `G65`/`G66` macro calls with arguments.
    pub macro_calls: bool,
    /// Deepest nesting of subprogram calls the controller allows.
    pub sub_depth: Depth,
    /// Deepest nesting of macro calls (`G65`, LinuxCNC `call`).
    pub macro_depth: Depth,
    /// Highest `DO`/`END` loop number.
    pub max_loop: u8,
    /// Macro A: `G65 Hm P#i Q#j R#k` operations and jumps (GSK).
    pub h_codes: bool,
    /// Whose the nesting limits are, as the alarms name them (no English
    /// words: the Chinese messages show it as it is).
    pub source: &'static str,
}
