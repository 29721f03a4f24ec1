//! What an environment is made of: the activity, the homes, where instances come from, the
//! robot, the time steps, the observations and the reward.

use crate::sensors::{CameraConfig, FixedCamera};
use behavior_assets::Scene;
use behavior_bddl::{Activity, Taxonomy};
use behavior_robots::{ActionSpace, RobotKind};
use behavior_sampling::SavedInstance;
use behavior_sim::Substeps;
use std::sync::Arc;

/// The default episode length, in action steps (1/30 s each): 6,000 steps, 200 s simulated.
///
/// The original truncates at twice the mean length of the human demonstrations of the activity
/// (BEHAVIOR's `behavior/benchmark/behavior_benchmark.py`). Until our own demonstrations exist
/// there is no such mean, so every activity gets this one limit: long enough for a person to do any
/// of the 100 activities at a calm pace in our homes, short enough that a random agent's episode
/// ends in seconds of wall time.
pub const DEFAULT_MAX_STEPS: u32 = 6000;

/// Where each episode's initial state comes from.
#[derive(Clone, Debug)]
pub enum Instances {
    /// Sampled on every reset, in a home of the pool chosen by the seed (`seed % homes`), from
    /// the seed.
    Sampled,
    /// Drawn from saved instances (`seed % len`): one for a fixed start, several for a pool.
    Saved(Vec<SavedInstance>),
}

/// Which observations an environment computes (those left out cost nothing).
#[derive(Clone, Debug, PartialEq)]
pub struct Observations {
    /// The robot's proprioception (22 numbers for the BehaviorRobot, 49 for Fetch).
    pub proprioception: bool,
    /// The full-observability vector of the activity's objects ([`crate::TASK_OBS_DIM`]).
    pub task_obs: bool,
    /// Images from the robot's camera (the BehaviorRobot's eye, Fetch's head camera), each
    /// under its modality's name (`rgb`, `depth`, `normal`, `seg`, `ins_seg`, `highlight`,
    /// `flow`, `scene_flow`).
    pub camera: Option<CameraConfig>,
    /// Cameras fixed in the home, each reading under `NAME/MODALITY` (`overview/rgb`).
    pub fixed_cameras: Vec<FixedCamera>,
    /// A lidar's range image, under `lidar` (see [`crate::LidarSensor`]).
    pub lidar: bool,
}

impl Default for Observations {
    /// Proprioception and `task_obs`: the state-only observations, no images.
    fn default() -> Self {
        Observations {
            proprioception: true,
            task_obs: true,
            camera: None,
            fixed_cameras: Vec::new(),
            lidar: false,
        }
    }
}

/// The reward of a step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Reward {
    /// The change of the success score Q over the step (sums to the final Q over an episode).
    #[default]
    DeltaQ,
    /// The original `BehaviorEnv`'s potential: the change of the fraction of satisfied literals
    /// of one fixed option of the goal, whatever option the agent is working toward. The
    /// original takes the first of its option list; ours is the first of
    /// `behavior_bddl::options::options`, a smallest one.
    FirstOption,
}

/// Everything an [`crate::Env`] is built from.
#[derive(Clone, Debug)]
pub struct EnvConfig {
    /// The activity's definition.
    pub activity: Arc<Activity>,
    /// The taxonomy it was loaded with (the object library needs it).
    pub taxonomy: Arc<Taxonomy>,
    /// The homes episodes may be sampled in (for [`Instances::Sampled`]).
    pub scenes: Vec<Scene>,
    /// Where initial states come from.
    pub instances: Instances,
    /// The embodiment.
    pub robot: RobotKind,
    /// The BehaviorRobot's action space (its reduced spaces, iGibson 2.0.3's
    /// `robots/behavior_robot.py`).
    pub action_space: ActionSpace,
    /// Physics substeps of each 1/30 s action step: 1/300 s (default) or 1/120 s.
    pub physics: Substeps,
    /// Episodes are truncated after this many action steps.
    pub max_steps: u32,
    /// Which observations to compute.
    pub observations: Observations,
    /// The reward.
    pub reward: Reward,
}

impl EnvConfig {
    /// An environment of `activity` sampled in `scenes`, with the defaults: a BehaviorRobot with
    /// the full action space, 1/300 s physics, [`DEFAULT_MAX_STEPS`], proprioception and
    /// task observations, ΔQ reward.
    pub fn new(activity: Arc<Activity>, taxonomy: Arc<Taxonomy>, scenes: Vec<Scene>) -> EnvConfig {
        EnvConfig {
            activity,
            taxonomy,
            scenes,
            instances: Instances::Sampled,
            robot: RobotKind::Behavior,
            action_space: ActionSpace::Full,
            physics: Substeps::Hz300,
            max_steps: DEFAULT_MAX_STEPS,
            observations: Observations::default(),
            reward: Reward::DeltaQ,
        }
    }
}
