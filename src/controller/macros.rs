//! What a controller reads of subprograms and macros: data in its rules,
//! run by the program flow.

/// The controller's macro language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flavor {
    /// Fanuc custom macro B (Fanuc 0i, and GSK980TDc's `#` macros).
    Fanuc,
    /// LinuxCNC's rs274ngc: o-words, named parameters.
    LinuxCnc,
}

/// A controller's macro and subprogram forms (data in its [`Rules`]).
#[derive(Debug)]
pub struct Macros {
    /// The macro language.
    pub flavor: Flavor,
    /// `M98 P… L…` calls and `M99` returns.
    pub subprograms: bool,
    /// `G65`/`G66` macro calls with arguments.
    pub macro_calls: bool,
    /// Deepest nesting of subprogram calls the controller allows.
    pub sub_depth: u32,
    /// Deepest nesting of macro calls (`G65`, LinuxCNC `call`).
    pub macro_depth: u32,
    /// Highest `DO`/`END` loop number.
    pub max_loop: u8,
    /// Macro A: `G65 Hm P#i Q#j R#k` operations and jumps (GSK).
    pub h_codes: bool,
    /// Whose the nesting limits are, as the alarms name them (no English
    /// words: the Chinese messages show it as it is).
    pub source: &'static str,
}
