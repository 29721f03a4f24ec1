//! Any robot, for code that does not care which: an environment, metrics, recordings.
//!
//! [`Robot`] is an enum over the embodiments (not a trait object) so that it can be cloned with
//! the world for snapshots and replay, and matched where the embodiments differ. Its methods are
//! what an episode needs of a body: actions as plain numbers, proprioception as plain numbers,
//! where the body and hands are, what the hands hold, and the robot-relative predicates.

use crate::action::{ActionError, ActionSpace};
use crate::body::BODY_HEIGHT;
use crate::fetch::Fetch;
use crate::fetch_proprioception::FetchProprioception;
use crate::hand::Side;
use crate::proprioception::Proprioception;
use crate::robot::{BehaviorRobot, RobotError};
use behavior_sim::{ObjectId, StepHooks, World};
use rapier3d::math::{Pose, Rotation, Vector};

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
}

impl RobotKind {
    /// Every embodiment.
    pub const ALL: [RobotKind; 2] = [RobotKind::Behavior, RobotKind::Fetch];

    /// Its name on the command line and in files: `behavior` or `fetch`.
    pub fn name(self) -> &'static str {
        match self {
            RobotKind::Behavior => "behavior",
            RobotKind::Fetch => "fetch",
        }
    }

    /// The kind with that [`RobotKind::name`].
    pub fn from_name(name: &str) -> Option<RobotKind> {
        RobotKind::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// A part of a robot whose motion the episode's metrics follow (the original's body and hands,
/// or body and gripper).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackedPart {
    /// `body`, `left_hand`, `right_hand` or `gripper`.
    pub name: &'static str,
    /// The world object it is.
    pub object: ObjectId,
    /// Whether it holds something now.
    pub holding: bool,
}

/// A robot of any kind, with the action space it is driven through.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub enum Robot {
    /// A [`BehaviorRobot`] and the space its actions come in.
    Behavior(BehaviorRobot, ActionSpace),
    /// A [`Fetch`] and the space its actions come in.
    Fetch(Fetch, ActionSpace),
}

impl Robot {
    /// Adds a robot of `kind` driven through `space` (the original's reduced spaces; each kind
    /// has its own reading of them: [`ActionSpace::dim`] for a BehaviorRobot,
    /// [`ActionSpace::fetch_dim`] for Fetch).
    ///
    /// `pose` is the robot's own origin, which differs by kind:
    /// - [`RobotKind::Behavior`]: the body capsule's centre, [`BODY_HEIGHT`] above the floor;
    /// - [`RobotKind::Fetch`]: the base's origin on the floor's top (only its yaw counts).
    ///
    /// [`Robot::standing_pose`] gives it for a point on the floor, so that callers need not know.
    pub fn add(
        kind: RobotKind,
        space: ActionSpace,
        world: &mut World,
        pose: Pose,
    ) -> Result<Robot, RobotError> {
        if !space.fits(kind) {
            return Err(RobotError::Space(ActionError::Unsupported {
                robot: kind.name(),
                space: space.name(),
            }));
        }
        match kind {
            RobotKind::Behavior => Ok(Robot::Behavior(BehaviorRobot::add(world, pose)?, space)),
            RobotKind::Fetch => Ok(Robot::Fetch(Fetch::add(world, pose)?, space)),
        }
    }

    /// The pose to pass to [`Robot::add`] for a robot of `kind` standing on the floor at
    /// `floor_point` (on the floor's top surface), facing `yaw` (rad, about z from +x).
    pub fn standing_pose(kind: RobotKind, floor_point: Vector, yaw: f32) -> Pose {
        let lift = match kind {
            RobotKind::Behavior => BODY_HEIGHT,
            RobotKind::Fetch => 0.0,
        };
        Pose::from_parts(
            floor_point + Vector::new(0.0, 0.0, lift),
            Rotation::from_rotation_z(yaw),
        )
    }

    /// Which embodiment it is.
    pub fn kind(&self) -> RobotKind {
        match self {
            Robot::Behavior(..) => RobotKind::Behavior,
            Robot::Fetch(..) => RobotKind::Fetch,
        }
    }

    /// The action space it is driven through.
    pub fn space(&self) -> ActionSpace {
        match self {
            Robot::Behavior(_, space) | Robot::Fetch(_, space) => *space,
        }
    }

    /// How many numbers an action has.
    pub fn action_dim(&self) -> usize {
        match self {
            Robot::Behavior(_, space) => space.dim(),
            Robot::Fetch(_, space) => space.fetch_dim(),
        }
    }

    /// Checks `values` as an action and sets it for the next step. A bad one is an error and
    /// changes nothing.
    pub fn set_action(&mut self, values: &[f32]) -> Result<(), ActionError> {
        match self {
            Robot::Behavior(robot, space) => {
                robot.set_action(space.action(values)?);
                Ok(())
            }
            Robot::Fetch(robot, space) => {
                robot.set_action(space.fetch_action(values)?);
                Ok(())
            }
        }
    }

    /// How many numbers [`Robot::proprioception`] gives.
    pub fn proprioception_dim(&self) -> usize {
        match self {
            Robot::Behavior(..) => Proprioception::DIM,
            Robot::Fetch(..) => FetchProprioception::DIM,
        }
    }

    /// Appends the robot's proprioception to `out` ([`Robot::proprioception_dim`] numbers).
    pub fn proprioception(&self, world: &World, out: &mut Vec<f32>) {
        match self {
            Robot::Behavior(robot, _) => out.extend(robot.proprioception(world).to_array()),
            Robot::Fetch(robot, _) => out.extend(robot.proprioception(world).to_array()),
        }
    }

    /// The base's pose (a BehaviorRobot's body centre, Fetch's base origin on the floor).
    pub fn base_pose(&self, world: &World) -> Pose {
        match self {
            Robot::Behavior(robot, _) => robot.body_pose(world),
            Robot::Fetch(robot, _) => robot.base_pose(world),
        }
    }

    /// The base's object (a BehaviorRobot's body, Fetch's base link).
    pub fn base(&self) -> ObjectId {
        match self {
            Robot::Behavior(robot, _) => robot.parts().body,
            Robot::Fetch(robot, _) => robot.parts().base(),
        }
    }

    /// The world objects the robot is made of.
    pub fn objects(&self) -> Vec<ObjectId> {
        match self {
            Robot::Behavior(robot, _) => robot.parts().all().to_vec(),
            Robot::Fetch(robot, _) => robot.parts().all().to_vec(),
        }
    }

    /// The base, then each hand or gripper, as the original's metrics follow them.
    pub fn tracked_parts(&self) -> Vec<TrackedPart> {
        match self {
            Robot::Behavior(robot, _) => {
                let parts = robot.parts();
                let hand = |name, side: Side| TrackedPart {
                    name,
                    object: parts.hand(side),
                    holding: robot.holding(side).is_some(),
                };
                vec![
                    TrackedPart {
                        name: "body",
                        object: parts.body,
                        holding: false,
                    },
                    hand("left_hand", Side::Left),
                    hand("right_hand", Side::Right),
                ]
            }
            Robot::Fetch(robot, _) => {
                let parts = robot.parts();
                vec![
                    TrackedPart {
                        name: "body",
                        object: parts.base(),
                        holding: false,
                    },
                    TrackedPart {
                        name: "gripper",
                        object: parts.gripper(),
                        holding: robot.holding().is_some(),
                    },
                ]
            }
        }
    }

    /// How many hands (or grippers) it has.
    pub fn hands(&self) -> usize {
        match self {
            Robot::Behavior(..) => 2,
            Robot::Fetch(..) => 1,
        }
    }

    /// The object hand `k` holds (0 left, 1 right for a BehaviorRobot; 0 the gripper for Fetch).
    pub fn held(&self, hand: usize) -> Option<ObjectId> {
        match self {
            Robot::Behavior(robot, _) => {
                let side = *Side::BOTH.get(hand)?;
                robot.holding(side).map(|b| b.object)
            }
            Robot::Fetch(robot, _) => robot.holding().filter(|_| hand == 0).map(|b| b.object),
        }
    }

    /// `in hand`: whether a hand holds the object.
    pub fn is_holding(&self, object: ObjectId) -> bool {
        match self {
            Robot::Behavior(robot, _) => robot.is_holding(object),
            Robot::Fetch(robot, _) => robot.is_holding(object),
        }
    }

    /// `in reach` (see `relative.rs`).
    pub fn in_reach(&self, world: &World, object: ObjectId) -> bool {
        match self {
            Robot::Behavior(robot, _) => robot.in_reach(world, object),
            Robot::Fetch(robot, _) => robot.in_reach(world, object),
        }
    }

    /// `in the same room` (see `relative.rs`).
    pub fn in_same_room(&self, world: &World, object: ObjectId) -> bool {
        match self {
            Robot::Behavior(robot, _) => robot.in_same_room(world, object),
            Robot::Fetch(robot, _) => robot.in_same_room(world, object),
        }
    }

    /// The on-board camera's pose in the world: the BehaviorRobot's eye, Fetch's head camera.
    /// It looks along its +x, with +z up.
    pub fn camera_pose(&self, world: &World) -> Pose {
        match self {
            Robot::Behavior(robot, _) => robot.eye_pose(world),
            Robot::Fetch(robot, _) => robot.camera_pose(world),
        }
    }

    /// `in the field of view` (see `relative.rs`).
    pub fn in_field_of_view(&self, world: &World, object: ObjectId) -> bool {
        match self {
            Robot::Behavior(robot, _) => robot.in_field_of_view(world, object),
            Robot::Fetch(robot, _) => robot.in_field_of_view(world, object),
        }
    }
}

impl StepHooks for Robot {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        match self {
            Robot::Behavior(robot, _) => robot.before_substep(world, substep),
            Robot::Fetch(robot, _) => robot.before_substep(world, substep),
        }
    }

    fn after_step(&mut self, world: &mut World) {
        match self {
            Robot::Behavior(robot, _) => robot.after_step(world),
            Robot::Fetch(robot, _) => robot.after_step(world),
        }
    }
}
