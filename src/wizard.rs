//! The thread wizard: a thread (designation or diameter and lead, length,
//! external/internal, starts, machine limits) and a target controller and
//! form → a program that plans without alarms and cuts the standard's depth.

use serde::Serialize;

/// The threading forms the wizard writes.
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
