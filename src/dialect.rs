//! The dialects screwcut reads: names and titles. What each controller does
//! with a program — words, G codes, unit rules, parameters, alarms — is in
//! its own module under `controller`.

use serde::Serialize;

/// A controller family whose programs screwcut reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Dialect {
    /// GSK980TDc turning system (G32 with J/K/Q, G78, G92, G76).
    Gsk980tdc,
    /// Fanuc 0i-TF, G-code system A (G32, G92, G76; no decimal point = increments).
    Fanuc0i,
    /// Renhe economy lathe controller (G30 run-out, G32 inch, G33 metric, incremental threads).
    Renhe,
    /// LinuxCNC (rs274ngc): G7/G8 diameter/radius mode, G33 (K along the move), G76 (drive line, I J K R Q H E L).
    LinuxCnc,
}

/// Name, title and accepted spellings of each dialect, in [`Dialect::ALL`] order.
const NAMES: [(&str, &str, &[&str]); 4] = [
    ("gsk980tdc", "GSK980TDc", &["gsk", "gsk980", "gsk980tdi"]),
    ("fanuc0i", "Fanuc 0i-TF", &["fanuc", "fanuc0it", "fanuc0itf"]),
    ("renhe", "Renhe", &[]),
    ("linuxcnc", "LinuxCNC", &["lcnc", "emc2", "rs274ngc"]),
];

impl Dialect {
    /// Every dialect.
    pub const ALL: [Dialect; 4] = [Dialect::Gsk980tdc, Dialect::Fanuc0i, Dialect::Renhe, Dialect::LinuxCnc];

    /// Position in [`Dialect::ALL`].
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        NAMES[self.index()].0
    }

    /// A display title.
    pub fn title(self) -> &'static str {
        NAMES[self.index()].1
    }

    /// Parses a dialect name (case-insensitive; a few common spellings).
    pub fn parse(s: &str) -> Option<Dialect> {
        let s = s.trim().to_ascii_lowercase().replace(['-', '_', ' '], "");
        Dialect::ALL.into_iter().find(|d| {
            let (name, _, aliases) = NAMES[d.index()];
            name == s || aliases.contains(&s.as_str())
        })
    }

    /// The names of every dialect, for messages: `gsk980tdc, fanuc0i, renhe, linuxcnc`.
    pub fn names() -> String {
        NAMES.iter().map(|n| n.0).collect::<Vec<_>>().join(", ")
    }
}

/// A set of upper-case letters as a bit mask (bit 0 = A).
pub const fn letters(s: &[u8]) -> u32 {
    let mut m = 0;
    let mut i = 0;
    while i < s.len() {
        m |= 1 << (s[i] - b'A');
        i += 1;
    }
    m
}

impl std::fmt::Display for Dialect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for d in Dialect::ALL {
            assert_eq!(Dialect::parse(d.name()), Some(d));
            assert_eq!(Dialect::ALL[d.index()], d);
        }
        assert_eq!(Dialect::parse(" Fanuc-0i "), Some(Dialect::Fanuc0i));
        assert_eq!(Dialect::parse("GSK"), Some(Dialect::Gsk980tdc));
        assert_eq!(Dialect::parse("haas"), None);
        assert_eq!(Dialect::parse("LinuxCNC"), Some(Dialect::LinuxCnc));
        assert_eq!(Dialect::names(), "gsk980tdc, fanuc0i, renhe, linuxcnc");
    }
}
