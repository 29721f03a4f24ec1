//! An episode's state: the world, the robot in it, the activity's bindings and the running
//! metrics. Cloning it is a checkpoint: the clone continues bit-identically.

use crate::metrics::Tracker;
use crate::score::Score;
use behavior_bddl::Activity;
use behavior_core::{AGENT_SYNSET, FLOOR_SYNSET};
use behavior_robots::{Robot, RobotError, RobotKind};
use behavior_sampling::SavedInstance;
use behavior_sim::{ObjectId, QueryFilter, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::Vector;
use std::f32::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

/// Everything that changes during an episode.
#[derive(Clone)]
pub(crate) struct Episode {
    pub(crate) world: World,
    pub(crate) robot: Robot,
    /// The object of each activity instance; the agent's is the robot's base.
    pub(crate) bindings: Vec<Option<ObjectId>>,
    pub(crate) steps: u32,
    /// The truth of the goal's atoms when `score` was computed.
    pub(crate) atoms: Vec<bool>,
    pub(crate) score: Score,
    /// The first-option potential, for [`crate::Reward::FirstOption`].
    pub(crate) potential: f64,
    pub(crate) tracker: Tracker,
    /// Where it started: the instance and the seed of the reset.
    pub(crate) start: Arc<Start>,
    pub(crate) over: bool,
}

/// How an episode began: enough to begin it again identically.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
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
            let aabb = world.bodies().aabb(id);
            let (yaw, _, _) = world.bodies().pose(id).rotation.to_euler(EulerRot::ZYX);
            (
                Vector::new(aabb.center().x, aabb.center().y, aabb.mins.z),
                yaw,
            )
        }
        None => (first_floor_centre(world), 0.0),
    };
    if let Some(id) = agent {
        world.bodies_mut().retire(id);
    }
    let mut robot = Robot::add(kind, space, world, Robot::standing_pose(kind, at, yaw))?;
    clear_start(world, &mut robot, at, yaw);
    Ok((robot, agent))
}

/// Quarter turns tried at each place, in order.
const START_TURNS: [f32; 4] = [0.0, FRAC_PI_2, -FRAC_PI_2, PI];
/// How far from the stand-in's place a robot that would overlap a wall there is moved at most,
/// in rings of [`START_STEP`], m.
const START_SHIFT: f32 = 0.5;
/// See [`START_SHIFT`].
const START_STEP: f32 = 0.1;

/// A robot put where the stand-in stood may overlap a wall or furniture there — Fetch's base is
/// wider than the stand-in and its arm reaches forward — and a kinematic body that starts inside
/// a wall never gets out. It is then turned by quarter turns and moved out in rings of 0.1 m
/// (8 directions each), up to 0.5 m, to the first pose clear of fixed things; if none is, it
/// stays where it was put.
fn clear_start(world: &mut World, robot: &mut Robot, at: Vector, yaw: f32) {
    if !hits_fixed(world, robot) {
        return;
    }
    let kind = robot.kind();
    let rings = (START_SHIFT / START_STEP).round() as usize;
    let places = (0..=rings).flat_map(|ring| {
        let r = ring as f32 * START_STEP;
        let directions = if ring == 0 { 1 } else { 8 };
        (0..directions).map(move |k| {
            let a = k as f32 * PI / 4.0;
            at + Vector::new(r * a.cos(), r * a.sin(), 0.0)
        })
    });
    let candidates: Vec<_> = places
        .flat_map(|p| START_TURNS.map(|t| Robot::standing_pose(kind, p, yaw + t)))
        .collect();
    for pose in candidates.iter().skip(1) {
        // Poses from a finite place and yaw: the robot takes them.
        if robot.teleport(world, *pose).is_ok() && !hits_fixed(world, robot) {
            return;
        }
    }
    let _ = robot.teleport(world, candidates[0]);
}

/// Whether a part of the robot overlaps a fixed object other than a floor.
fn hits_fixed(world: &World, robot: &Robot) -> bool {
    let mut ignored = robot.objects();
    let floors = world
        .bodies()
        .objects()
        .filter(|(_, o)| o.category == FLOOR_SYNSET);
    ignored.extend(floors.map(|(id, _)| id));
    let filter = QueryFilter {
        fixed_only: true,
        ..QueryFilter::excluding(&ignored)
    };
    robot.objects().into_iter().any(|id| {
        world
            .query()
            .collision_parts(id)
            .into_iter()
            .any(|(shape, pose)| {
                world
                    .query()
                    .overlaps(shape, pose, &filter)
                    .is_ok_and(|hits| !hits.is_empty())
            })
    })
}

/// For an activity without an agent: the centre of the first floor.
fn first_floor_centre(world: &World) -> Vector {
    world
        .bodies()
        .objects()
        .find(|(_, o)| o.category == FLOOR_SYNSET)
        .map_or(Vector::ZERO, |(id, _)| {
            let aabb = world.bodies().aabb(id);
            Vector::new(aabb.center().x, aabb.center().y, aabb.maxs.z)
        })
}

/// The start of an episode checkpoint's bytes, then a little-endian format version.
const CHECKPOINT_MAGIC: &[u8; 8] = b"BHVEPISD";
/// Bumped whenever a saved type changes shape (postcard does not describe its layout): 2 when
/// Fetch's gripper became a shared parallel gripper (issue 41).
pub const CHECKPOINT_FORMAT_VERSION: u32 = 2;

/// Why bytes are not an episode checkpoint.
#[derive(Debug, thiserror::Error)]
pub enum CheckpointError {
    /// They do not start as a checkpoint does.
    #[error("not an episode checkpoint (the bytes do not start with its magic)")]
    NotACheckpoint,
    /// Another version of the format.
    #[error("checkpoint format version {found}, but this build reads version {expected} only")]
    Version {
        /// The file's.
        found: u32,
        /// Ours.
        expected: u32,
    },
    /// The robot, bindings or metrics do not decode.
    #[error("a damaged episode checkpoint: {0}")]
    Decode(String),
    /// The world does not decode.
    #[error("a damaged episode checkpoint: {0}")]
    World(#[from] behavior_sim::WorldBytesError),
}

/// What an episode checkpoint holds: everything but how the episode began.
#[derive(serde::Serialize, serde::Deserialize)]
struct Saved {
    world: Vec<u8>,
    robot: Robot,
    bindings: Vec<Option<ObjectId>>,
    steps: u32,
    atoms: Vec<bool>,
    score: Score,
    potential: f64,
    tracker: Tracker,
    over: bool,
}

impl Episode {
    /// The episode as bytes: magic, version, then the world's own bytes and the rest.
    pub(crate) fn to_bytes(&self) -> Vec<u8> {
        let saved = Saved {
            world: self.world.to_bytes(),
            robot: self.robot.clone(),
            bindings: self.bindings.clone(),
            steps: self.steps,
            atoms: self.atoms.clone(),
            score: self.score.clone(),
            potential: self.potential,
            tracker: self.tracker.clone(),
            over: self.over,
        };
        let mut bytes = CHECKPOINT_MAGIC.to_vec();
        bytes.extend(CHECKPOINT_FORMAT_VERSION.to_le_bytes());
        // Plain data of our own types: encoding cannot fail.
        bytes.extend(postcard::to_stdvec(&saved).unwrap_or_default());
        bytes
    }

    /// An episode from [`Episode::to_bytes`], begun as `start` says.
    pub(crate) fn from_bytes(bytes: &[u8], start: Arc<Start>) -> Result<Episode, CheckpointError> {
        let body = bytes
            .strip_prefix(CHECKPOINT_MAGIC.as_slice())
            .ok_or(CheckpointError::NotACheckpoint)?;
        let (version, body) = body
            .split_at_checked(4)
            .ok_or(CheckpointError::NotACheckpoint)?;
        let found = u32::from_le_bytes([version[0], version[1], version[2], version[3]]);
        if found != CHECKPOINT_FORMAT_VERSION {
            return Err(CheckpointError::Version {
                found,
                expected: CHECKPOINT_FORMAT_VERSION,
            });
        }
        let saved: Saved =
            postcard::from_bytes(body).map_err(|e| CheckpointError::Decode(e.to_string()))?;
        let world = World::from_bytes(&saved.world)?;
        let objects = world.bodies().objects().len();
        let known = |id: &ObjectId| (id.0 as usize) < objects;
        if !saved.robot.objects().iter().all(known) || !saved.bindings.iter().flatten().all(known) {
            return Err(CheckpointError::Decode(
                "the robot or the bindings name objects the world does not have".into(),
            ));
        }
        Ok(Episode {
            world,
            robot: saved.robot,
            bindings: saved.bindings,
            steps: saved.steps,
            atoms: saved.atoms,
            score: saved.score,
            potential: saved.potential,
            tracker: saved.tracker,
            start,
            over: saved.over,
        })
    }
}
