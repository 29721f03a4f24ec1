//! The robot's own metrics (iGibson 2.0.3's `metrics/`, `agent.py`): how far its base and each hand
//! moved, how far each hand moved while touching or holding something, and the work its parts did.
//!
//! Per step and part: Δ = the distance its origin moved, clipped at [`MAX_STEP_DISTANCE`] so that
//! a teleport does not count. Distance navigated is the base's ΣΔ; a hand's displacement is its
//! ΣΔ over the steps it touched something (any contact with a body not of the robot) or held
//! something. Work is Σ Δ·‖F‖ with F the force that part's actuator had to supply: the original
//! reads it from its motion constraints; ours has kinematic and servoed parts, so F is estimated
//! as m·‖a − g‖ from the part's mass (with what it holds) and its change of velocity over the
//! step — carrying a 1 kg box 1 m level costs about 9.8 J, as in the original.

use behavior_robots::{Robot, TrackedPart};
use behavior_sim::{BodyRef, STEP_SECONDS, World};
use rapier3d::math::Vector;

/// A larger per-step move is a teleport, not motion, m.
pub const MAX_STEP_DISTANCE: f32 = 0.2;

/// One part's running totals.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PartTotals {
    /// `body`, `left_hand`, `right_hand` or `gripper`.
    pub name: String,
    /// ΣΔ, m.
    pub distance: f64,
    /// ΣΔ while touching or holding, m.
    pub contact_distance: f64,
    /// Σ Δ·‖F‖, J.
    pub work: f64,
}

#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
struct Last {
    position: Vector,
    velocity: Vector,
}

/// The running agent metrics of an episode.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub(crate) struct AgentMetrics {
    pub(crate) parts: Vec<PartTotals>,
    last: Vec<Last>,
}

impl AgentMetrics {
    pub(crate) fn start(world: &World, robot: &Robot) -> AgentMetrics {
        let tracked = robot.tracked_parts();
        AgentMetrics {
            parts: tracked
                .iter()
                .map(|p| PartTotals {
                    name: p.name.to_string(),
                    ..PartTotals::default()
                })
                .collect(),
            last: tracked.iter().map(|p| last_of(world, p)).collect(),
        }
    }

    /// Measures one step; returns (base distance, hands' contact distance) of the step, m.
    pub(crate) fn step(&mut self, world: &World, robot: &Robot) -> (f64, f64) {
        let mut base = 0.0;
        let mut hands = 0.0;
        for (k, part) in robot.tracked_parts().iter().enumerate() {
            let now = last_of(world, part);
            let delta = f64::from((now.position - self.last[k].position).length())
                .min(f64::from(MAX_STEP_DISTANCE));
            let totals = &mut self.parts[k];
            totals.distance += delta;
            if delta > 0.0 {
                totals.work += delta * f64::from(force(world, robot, part, &self.last[k], &now));
            }
            if k == 0 {
                base = delta;
            } else if delta > 0.0 && (part.holding || touches(world, robot, part)) {
                totals.contact_distance += delta;
                hands += delta;
            }
            self.last[k] = now;
        }
        (base, hands)
    }
}

fn last_of(world: &World, part: &TrackedPart) -> Last {
    let velocity = world
        .bodies()
        .velocity(BodyRef::from(part.object))
        .map_or(Vector::ZERO, |v| v.linear);
    Last {
        position: world.bodies().pose(part.object).translation,
        velocity,
    }
}

/// Whether a part touches anything that is not the robot's.
fn touches(world: &World, robot: &Robot, part: &TrackedPart) -> bool {
    let own = robot.objects();
    world
        .contacts()
        .of_object(part.object)
        .iter()
        .any(|c| c.other.is_some_and(|b| !own.contains(&b.object)))
}

/// The force the part's actuator supplied over the step, N (see the module docs).
fn force(world: &World, robot: &Robot, part: &TrackedPart, before: &Last, now: &Last) -> f32 {
    let held = (0..robot.hands())
        .filter_map(|h| robot.held(h))
        .filter(|_| part.holding)
        .map(|id| world.bodies().total_mass(id))
        .sum::<f32>();
    let mass = world.bodies().total_mass(part.object) + held;
    let acceleration = (now.velocity - before.velocity) / STEP_SECONDS;
    mass * (acceleration - world.bodies().gravity()).length()
}
