//! The paper's metrics (the BEHAVIOR paper and iGibson 2.0.3's `metrics/`): the success score Q
//! every step, success, simulated time, kinematic and logical disarrangement, distance navigated,
//! hand displacement and work; per episode ([`EpisodeMetrics`]), over the benchmark's episodes
//! ([`aggregate`]) and relative to people ([`HumanReference`]).
//!
//! Each metric lives in its own module: `kinematic.rs`, `logical.rs`, `agent.rs` (the robot's),
//! `aggregate.rs` (the benchmark protocol and human normalization).

mod agent;
mod aggregate;
mod kinematic;
mod logical;

pub use agent::{MAX_STEP_DISTANCE, PartTotals};
pub use aggregate::{Aggregate, HumanReference, HumanStatistics, Normalized, aggregate};

use crate::score::Score;
use agent::AgentMetrics;
use behavior_robots::Robot;
use behavior_sim::{ObjectId, World};
use kinematic::Kinematic;
use logical::Logical;
use serde::{Deserialize, Serialize};

/// Action steps per simulated second.
pub const ACTION_HZ: u32 = 30;

/// One episode's metrics: the per-episode JSON.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EpisodeMetrics {
    /// Action steps taken.
    pub steps: u32,
    /// Whether the goal held at the end.
    pub success: bool,
    /// Q at the end (the benchmark's Success Score).
    pub q_final: f64,
    /// The highest Q reached.
    pub q_max: f64,
    /// Simulated time, steps / 30, s.
    pub sim_time_s: f64,
    /// Kinematic disarrangement, relative (what the benchmark reports), m.
    pub kinematic_disarrangement: f64,
    /// Kinematic disarrangement, integrated over the steps, m.
    pub kinematic_integrated: f64,
    /// Logical disarrangement, relative (see `logical.rs`).
    pub logical_disarrangement: u32,
    /// Objects the logical disarrangement compared.
    pub logical_objects: u32,
    /// States it compared.
    pub logical_states: u32,
    /// The base's distance travelled, m.
    pub distance_navigated: f64,
    /// The left (or only) hand's displacement while touching or holding, m.
    pub hand_displacement_left: f64,
    /// The right hand's displacement while touching or holding (0 for a one-handed robot), m.
    pub hand_displacement_right: f64,
    /// Work of all parts, J.
    pub work: f64,
    /// Each part's totals.
    pub parts: Vec<PartTotals>,
}

/// The metrics over time, one entry per step (for plots).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Series {
    /// Q after each step.
    pub q: Vec<f32>,
    /// Kinematic disarrangement of each step, m.
    pub kinematic: Vec<f32>,
    /// The base's distance of each step, m.
    pub distance: Vec<f32>,
    /// The hands' displacement while touching or holding, of each step, m.
    pub hands: Vec<f32>,
}

/// The running metrics of an episode: started after the reset settled, stepped after every
/// step, finished on demand.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub(crate) struct Tracker {
    steps: u32,
    q: f64,
    q_max: f64,
    success: bool,
    kinematic: Kinematic,
    logical: Logical,
    agent: AgentMetrics,
    series: Series,
}

impl Tracker {
    /// Starts measuring; `ignored` are the objects the home's metrics leave out (the robot's
    /// parts, the agent's stand-in).
    pub(crate) fn start(
        world: &World,
        robot: &Robot,
        ignored: &[ObjectId],
        score: &Score,
    ) -> Tracker {
        Tracker {
            steps: 0,
            q: score.q,
            q_max: score.q,
            success: score.success,
            kinematic: Kinematic::start(world, ignored),
            logical: Logical::start(world, ignored),
            agent: AgentMetrics::start(world, robot),
            series: Series::default(),
        }
    }

    /// Measures a step just taken.
    pub(crate) fn step(&mut self, world: &World, robot: &Robot, score: &Score) {
        self.steps += 1;
        self.q = score.q;
        self.q_max = self.q_max.max(score.q);
        self.success = score.success;
        let kinematic = self.kinematic.step(world);
        let (base, hands) = self.agent.step(world, robot);
        let s = &mut self.series;
        s.q.push(score.q as f32);
        s.kinematic.push(kinematic as f32);
        s.distance.push(base as f32);
        s.hands.push(hands as f32);
    }

    /// The values over time.
    pub(crate) fn series(&self) -> &Series {
        &self.series
    }

    /// The episode's metrics as of now (the logical disarrangement compares the start with
    /// `world` now).
    pub(crate) fn finish(&self, world: &World) -> EpisodeMetrics {
        let logical = self.logical.compare(world);
        let parts = self.agent.parts.clone();
        // The body first, then the hands in the robot's order: the left (or only) one, then the
        // right.
        let contact = |hand: usize| parts.get(1 + hand).map_or(0.0, |p| p.contact_distance);
        EpisodeMetrics {
            steps: self.steps,
            success: self.success,
            q_final: self.q,
            q_max: self.q_max,
            sim_time_s: f64::from(self.steps) / f64::from(ACTION_HZ),
            kinematic_disarrangement: self.kinematic.relative(),
            kinematic_integrated: self.kinematic.integrated,
            logical_disarrangement: logical.relative,
            logical_objects: logical.total_objects,
            logical_states: logical.total_states,
            distance_navigated: parts.first().map_or(0.0, |p| p.distance),
            hand_displacement_left: contact(0),
            hand_displacement_right: contact(1),
            work: parts.iter().map(|p| p.work).sum(),
            parts,
        }
    }
}
