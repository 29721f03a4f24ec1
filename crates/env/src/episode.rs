//! An episode's state: the world, the robot in it, the activity's bindings and the running
//! metrics. Cloning it is a checkpoint: the clone continues bit-identically.

use crate::metrics::Tracker;
use crate::score::Score;
use behavior_bddl::Activity;
use behavior_robots::{Robot, RobotError, RobotKind};
use behavior_sampling::SavedInstance;
use behavior_sim::{ObjectId, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::Vector;
use std::sync::Arc;

/// The synset of the activity's stand-in for the agent, which the robot replaces.
pub(crate) const AGENT_SYNSET: &str = "agent.n.01";

/// Everything that changes during an episode.
#[derive(Clone)]
pub(crate) struct Episode {
    pub(crate) world: World,
    pub(crate) robot: Robot,
    /// The object of each activity instance; the agent's is the robot's base.
    pub(crate) bindings: Vec<Option<ObjectId>>,
    pub(crate) steps: u32,
    pub(crate) score: Score,
    /// The first-option potential, for [`crate::Reward::FirstOption`].
    pub(crate) potential: f64,
    pub(crate) tracker: Tracker,
    /// Where it started: the instance and the seed of the reset.
    pub(crate) start: Arc<Start>,
    pub(crate) over: bool,
}

/// How an episode began: enough to begin it again identically.
#[derive(Clone, Debug)]
pub struct Start {
    /// The seed given to reset.
    pub seed: u64,
    /// The initial state, as a saved instance (sampled ones are saved and reloaded, so that a
    /// replay from the file starts from exactly the same world).
    pub instance: SavedInstance,
}

/// Replaces the activity's agent stand-in with a robot of `kind` standing where it stood;
/// returns the robot and the stand-in.
pub(crate) fn embody(
    world: &mut World,
    activity: &Activity,
    bindings: &[ObjectId],
    kind: RobotKind,
    space: behavior_robots::ActionSpace,
) -> Result<(Robot, Option<ObjectId>), RobotError> {
    let agent = activity
        .instances
        .iter()
        .position(|i| activity.categories[i.category.0 as usize].name == AGENT_SYNSET)
        .map(|k| bindings[k]);
    let (at, yaw) = match agent {
        Some(id) => {
            let aabb = world.aabb(id);
            let (yaw, _, _) = world.pose(id).rotation.to_euler(EulerRot::ZYX);
            (
                Vector::new(aabb.center().x, aabb.center().y, aabb.mins.z),
                yaw,
            )
        }
        None => (first_floor_centre(world), 0.0),
    };
    if let Some(id) = agent {
        world.core_mut().retire(id);
    }
    let robot = Robot::add(kind, space, world, Robot::standing_pose(kind, at, yaw))?;
    Ok((robot, agent))
}

/// For an activity without an agent: the centre of the first floor.
fn first_floor_centre(world: &World) -> Vector {
    world
        .objects()
        .find(|(_, o)| o.category == "floor.n.01")
        .map_or(Vector::ZERO, |(id, _)| {
            let aabb = world.aabb(id);
            Vector::new(aabb.center().x, aabb.center().y, aabb.maxs.z)
        })
}
