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
    NoPath {
        /// Runs after the first.
        restarts: u32,
        /// Iterations of each run.
        iterations: u32,
    },
    /// The lattice search (the base's fallback) found no way at its resolution.
    #[error("no collision-free path on a {cell} m lattice ({expansions} nodes expanded)")]
    NoLatticePath {
        /// The lattice's cell, m.
        cell: f32,
        /// Nodes expanded before it gave up.
        expansions: usize,
    },
    /// A configuration or parameter was not a finite number.
    #[error("{what} is not finite: {value}")]
    NotFinite {
        /// What it was.
        what: &'static str,
        /// Its value.
        value: f32,
    },
}
