//! The variables of a running program: local ones per call level, common
//! (global) ones, and LinuxCNC's named parameters. Kept sparse, so a
//! snapshot of a program that uses few variables is small.

use std::collections::BTreeMap;

/// One call level's local variables.
#[derive(Clone, Debug, PartialEq)]
pub struct Locals {
    /// `#1`…`#33` (Fanuc) or `#1`…`#30` (LinuxCNC); `None` is vacant.
    pub num: [Option<f64>; 33],
    /// LinuxCNC `#<name>` of this level.
    pub named: BTreeMap<Box<str>, f64>,
}

impl Default for Locals {
    fn default() -> Self {
        Locals { num: [None; 33], named: BTreeMap::new() }
    }
}

/// Every variable of a running program.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vars {
    /// Local variables, one entry per macro call level (the main program is level 0).
    pub levels: Vec<Locals>,
    /// Numbered variables outside the local range that have a value.
    pub common: BTreeMap<u32, f64>,
    /// LinuxCNC `#<_name>`.
    pub global_named: BTreeMap<Box<str>, f64>,
}

impl Vars {
    /// Variables at the start of a program: the main level, and the common
    /// variables given by the settings.
    pub fn new(start: &[(u32, f64)]) -> Vars {
        Vars { levels: vec![Locals::default()], common: start.iter().copied().collect(), global_named: BTreeMap::new() }
    }

    /// The current level's locals.
    pub fn top(&mut self) -> &mut Locals {
        if self.levels.is_empty() {
            self.levels.push(Locals::default());
        }
        let n = self.levels.len();
        &mut self.levels[n - 1]
    }

    /// Local `#n` (1-based) of the current level.
    pub fn local(&self, n: usize) -> Option<f64> {
        self.levels.last().and_then(|l| l.num.get(n.wrapping_sub(1)).copied().flatten())
    }

    /// Sets local `#n` (1-based) of the current level.
    pub fn set_local(&mut self, n: usize, v: Option<f64>) {
        if let Some(slot) = self.top().num.get_mut(n.wrapping_sub(1)) {
            *slot = v;
        }
    }

    /// Common `#n`.
    pub fn common(&self, n: u32) -> Option<f64> {
        self.common.get(&n).copied()
    }

    /// Sets common `#n` (vacant removes it).
    pub fn set_common(&mut self, n: u32, v: Option<f64>) {
        match v {
            Some(v) => {
                self.common.insert(n, v);
            }
            None => {
                self.common.remove(&n);
            }
        }
    }

    /// A named parameter: `_` names are global, others the current level's.
    pub fn named(&self, name: &str) -> Option<f64> {
        if name.starts_with('_') {
            self.global_named.get(name).copied()
        } else {
            self.levels.last().and_then(|l| l.named.get(name).copied())
        }
    }

    /// Sets a named parameter.
    pub fn set_named(&mut self, name: &str, v: f64) {
        if name.starts_with('_') {
            self.global_named.insert(name.into(), v);
        } else {
            self.top().named.insert(name.into(), v);
        }
    }
}

/// Parses the `macro.common` setting text: `#500=1.5 #501=2` (blanks or
/// `;` between). Returns the pairs, or the first piece it cannot read.
pub fn parse_start(text: &str) -> Result<Vec<(u32, f64)>, String> {
    let mut out = Vec::new();
    for piece in text.split([' ', ';', ',', '\n']).filter(|s| !s.is_empty()) {
        let bad = || piece.to_string();
        let (name, value) = piece.split_once('=').ok_or_else(bad)?;
        let n: u32 = name.trim().trim_start_matches('#').parse().map_err(|_| bad())?;
        let v: f64 = value.trim().parse().map_err(|_| bad())?;
        if !v.is_finite() {
            return Err(bad());
        }
        out.push((n, v));
    }
    Ok(out)
}
