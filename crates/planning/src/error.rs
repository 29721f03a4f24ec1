//! Why a plan failed.

use thiserror::Error;

/// Why no path came back.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlanError {
    /// The start itself collides (the robot is already in contact with something).
    #[error("the start configuration collides with the world")]
    StartInCollision,
    /// The goal collides.
    #[error("the goal configuration collides with the world")]
    GoalInCollision,
    /// The search ran out of iterations and restarts.
    #[error("no collision-free path within {restarts} restarts of {iterations} iterations")]
    NoPath { restarts: u32, iterations: u32 },
    /// The lattice search (the base's fallback) found no way at its resolution.
    #[error("no collision-free path on a {cell} m lattice ({expansions} nodes expanded)")]
    NoLatticePath { cell: f32, expansions: usize },
    /// A configuration or parameter was not a finite number.
    #[error("{what} is not finite: {value}")]
    NotFinite { what: &'static str, value: f32 },
}
