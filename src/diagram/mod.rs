//! Scenes: what the views draw, computed from a plan.
