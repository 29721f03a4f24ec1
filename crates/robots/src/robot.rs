//! Any robot, built by its kind's name: the only code that knows every embodiment.
//!
//! [`Robot`] is an enum over the embodiments (not a boxed trait object) so that it can be cloned
//! with the world for snapshots and replay and (de)serialized with them. It adds the action space
//! a robot is driven through and otherwise hands everything to the [`Embodiment`] each variant
//! implements: callers use it as an [`Embodiment`] (it derefs to one), never a `match` on the kind.

use crate::action::{ActionError, ActionSpace};
use crate::behavior_robot::BehaviorRobot;
use crate::embodiment::{Embodiment, EmbodimentSpec};
use crate::fetch::Fetch;
use crate::r1::R1;
use behavior_sim::{StepHooks, World, WorldError};
use rapier3d::math::{Pose, Rotation, Vector};

/// Why a robot could not be added.
#[derive(Debug, PartialEq, thiserror::Error)]
pub enum RobotError {
    /// The pose is not finite or its rotation is not a unit quaternion.
    #[error("a robot's pose must be finite, with a unit quaternion for its rotation")]
    BadPose,
    /// The world refused one of the robot's parts.
    #[error("the world refused a robot part: {0}")]
    World(#[from] WorldError),
    /// The robot cannot be driven through the action space asked for.
    #[error(transparent)]
    Space(#[from] ActionError),
}

/// Whether a pose can place a robot: finite, with a unit quaternion.
pub(crate) fn pose_ok(pose: &Pose) -> bool {
    pose.is_finite() && (pose.rotation.length() - 1.0).abs() < 1e-3
}

/// Which embodiment.
#[derive(
    serde::Serialize,
    serde::Deserialize,
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
)]
pub enum RobotKind {
    /// The bimanual humanoid of the VR demonstrations ([`BehaviorRobot`]).
    #[default]
    Behavior,
    /// The Fetch mobile manipulator ([`Fetch`]).
    Fetch,
    /// The Galaxea R1 Pro of the BEHAVIOR Challenge ([`R1`]).
    R1,
}

impl RobotKind {
    /// Every embodiment.
    pub const ALL: [RobotKind; 3] = [RobotKind::Behavior, RobotKind::Fetch, RobotKind::R1];

    /// Its name on the command line and in files: `behavior`, `fetch` or `r1`.
    pub fn name(self) -> &'static str {
        match self {
            RobotKind::Behavior => "behavior",
            RobotKind::Fetch => "fetch",
            RobotKind::R1 => "r1",
        }
    }

    /// The kind with that [`RobotKind::name`].
    pub fn from_name(name: &str) -> Option<RobotKind> {
        RobotKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// The facts about robots of this kind.
    pub fn spec(self) -> &'static EmbodimentSpec {
        match self {
            RobotKind::Behavior => &BehaviorRobot::SPEC,
            RobotKind::Fetch => &Fetch::SPEC,
            RobotKind::R1 => &R1::SPEC,
        }
    }
}

/// A robot of any kind, with the action space it is driven through.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub enum Robot {
    /// A [`BehaviorRobot`] and the space its actions come in.
    Behavior(BehaviorRobot, ActionSpace),
    /// A [`Fetch`] and the space its actions come in.
    Fetch(Fetch, ActionSpace),
    /// An [`R1`] and the space its actions come in.
    R1(R1, ActionSpace),
}

impl Robot {
    /// Adds a robot of `kind` driven through `space` (the original's reduced spaces; each kind
    /// has its own reading of them, [`Embodiment::action_dim`]).
    ///
    /// `pose` is the robot's own origin, which differs by kind
    /// ([`EmbodimentSpec::origin_height`]: a BehaviorRobot's body centre floats above the floor,
    /// Fetch's base origin is on it); [`Robot::standing_pose`] gives it for a point on the
    /// floor, so that callers need not know.
    pub fn add(
        kind: RobotKind,
        space: ActionSpace,
        world: &mut World,
        pose: Pose,
    ) -> Result<Robot, RobotError> {
        if !kind.spec().drives(space) {
            return Err(RobotError::Space(ActionError::Unsupported {
                robot: kind.name(),
                space: space.name(),
            }));
        }
        match kind {
            RobotKind::Behavior => Ok(Robot::Behavior(BehaviorRobot::add(world, pose)?, space)),
            RobotKind::Fetch => Ok(Robot::Fetch(Fetch::add(world, pose)?, space)),
            RobotKind::R1 => Ok(Robot::R1(R1::add(world, pose)?, space)),
        }
    }

    /// The pose to pass to [`Robot::add`] for a robot of `kind` standing on the floor at
    /// `floor_point` (on the floor's top surface), facing `yaw` (rad, about z from +x).
    pub fn standing_pose(kind: RobotKind, floor_point: Vector, yaw: f32) -> Pose {
        let lift = Vector::new(0.0, 0.0, kind.spec().origin_height);
        Pose::from_parts(floor_point + lift, Rotation::from_rotation_z(yaw))
    }

    /// The robot as an embodiment, whichever it is.
    pub fn embodiment(&self) -> &(dyn Embodiment + 'static) {
        match self {
            Robot::Behavior(robot, _) => robot,
            Robot::Fetch(robot, _) => robot,
            Robot::R1(robot, _) => robot,
        }
    }

    /// The robot as an embodiment, to move it.
    pub fn embodiment_mut(&mut self) -> &mut (dyn Embodiment + 'static) {
        match self {
            Robot::Behavior(robot, _) => robot,
            Robot::Fetch(robot, _) => robot,
            Robot::R1(robot, _) => robot,
        }
    }

    /// Which embodiment it is.
    pub fn kind(&self) -> RobotKind {
        self.spec().kind
    }

    /// The action space it is driven through.
    pub fn space(&self) -> ActionSpace {
        match self {
            Robot::Behavior(_, space) | Robot::Fetch(_, space) | Robot::R1(_, space) => *space,
        }
    }

    /// How many numbers an action has.
    pub fn action_dim(&self) -> usize {
        self.embodiment().action_dim(self.space())
    }

    /// Each action number's lower and upper bound.
    pub fn action_bounds(&self) -> Vec<[f32; 2]> {
        self.embodiment().action_bounds(self.space())
    }

    /// Checks `values` as an action and sets it for the next step. A bad one is an error and
    /// changes nothing.
    pub fn set_action(&mut self, values: &[f32]) -> Result<(), ActionError> {
        let space = self.space();
        self.embodiment_mut().set_action(space, values)
    }

    /// The action that moves the base by `step` within one step, as nearly as one step allows,
    /// in the space it is driven through (`None` for a space without the base).
    pub fn base_action(&self, step: crate::BaseMove) -> Option<Vec<f32>> {
        self.embodiment().base_action(self.space(), step)
    }

    /// How many hands (or grippers) it has.
    pub fn hands(&self) -> usize {
        self.spec().hands()
    }
}

impl std::ops::Deref for Robot {
    type Target = dyn Embodiment;

    fn deref(&self) -> &(dyn Embodiment + 'static) {
        self.embodiment()
    }
}

impl std::ops::DerefMut for Robot {
    fn deref_mut(&mut self) -> &mut (dyn Embodiment + 'static) {
        self.embodiment_mut()
    }
}

impl StepHooks for Robot {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        self.embodiment_mut().before_substep(world, substep);
    }

    fn after_step(&mut self, world: &mut World) {
        self.embodiment_mut().after_step(world);
    }
}
