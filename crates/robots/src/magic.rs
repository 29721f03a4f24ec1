//! Moves outside physics, for symbolic ("magic") action primitives (iGibson 2.0.3's
//! `envs/behavior_mp_env.py`: the original teleports the robot for NAVIGATE_TO, puts the object in
//! the hand and forces the assisted grasp for GRASP, and forces the release for PLACE_*).
//!
//! Each move leaves the robot at rest and consistent with the world: a teleported robot stands
//! with its hands parked where its targets put them, carrying what it holds along; a grasp made
//! here is the same attachment a pressed trigger makes, so the next steps hold it as any other.

use crate::embodiment::Robot;
use behavior_sim::{ObjectId, WorldError};

/// Why a symbolic move was refused. Nothing changed.
#[derive(Debug, PartialEq, thiserror::Error)]
pub enum MagicError {
    /// The pose is not finite or its rotation is not a unit quaternion.
    #[error("the robot's pose must be finite, with a unit quaternion for its rotation")]
    BadPose,
    /// The robot has no such hand.
    #[error("the robot has no hand {0}")]
    NoHand(usize),
    /// The hand already holds something.
    #[error("the hand already holds object {0:?}")]
    HandFull(ObjectId),
    /// The grasp rules do not let a hand hold it (fixed, too heavy, a robot part).
    #[error("object {0:?} cannot be held")]
    NotHoldable(ObjectId),
    /// A forced grasp needs the hand to touch the object, and it does not.
    #[error("the hand does not touch object {0:?}")]
    NotTouching(ObjectId),
    /// The world refused a move.
    #[error("the world refused: {0}")]
    World(#[from] WorldError),
}

impl Robot {
    /// Puts the base at `pose` (as [`Robot::base_pose`] gives it) at once, the hands or arm
    /// with it and what they hold with them; nothing else moves, and nothing is checked for
    /// collisions (a caller checks where it sends the robot).
    pub fn teleport(
        &mut self,
        world: &mut behavior_sim::World,
        pose: rapier3d::math::Pose,
    ) -> Result<(), MagicError> {
        match self {
            Robot::Behavior(robot, _) => robot.teleport(world, pose),
            Robot::Fetch(robot, _) => robot.teleport(world, pose),
        }
    }

    /// Puts `object` in hand `hand` (0 left, 1 right for a BehaviorRobot; 0 for Fetch's
    /// gripper) and holds it there with the assisted grasp's attachment, closing the hand.
    pub fn grasp_now(
        &mut self,
        world: &mut behavior_sim::World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        match self {
            Robot::Behavior(robot, _) => robot.grasp_now(world, side(hand)?, object),
            Robot::Fetch(_, _) if hand != 0 => Err(MagicError::NoHand(hand)),
            Robot::Fetch(robot, _) => robot.grasp_now(world, object),
        }
    }

    /// Holds `object` in hand `hand` where it is, if the hand touches it: the original's
    /// forced assisted grasp after a physical GRASP closed the hand (it also asks for contact,
    /// not for the assisted grasp's rays). Fetch has one hand, 0: its palm or a finger must
    /// touch the object.
    pub fn grasp_touching(
        &mut self,
        world: &mut behavior_sim::World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        match self {
            Robot::Behavior(robot, _) => robot.grasp_touching(world, side(hand)?, object),
            Robot::Fetch(robot, _) if hand == 0 => robot.grasp_touching(world, object),
            Robot::Fetch(..) => Err(MagicError::NoHand(hand)),
        }
    }

    /// Puts a BehaviorRobot's hand `hand` at its target at once, with what it holds: the
    /// original robot's "reset" entry, for a hand pinned behind furniture. Fetch's arm is
    /// kinematic and never left behind: nothing to do.
    pub fn reset_hand(
        &mut self,
        world: &mut behavior_sim::World,
        hand: usize,
    ) -> Result<(), MagicError> {
        match self {
            Robot::Behavior(robot, _) => robot.reset_hand(world, side(hand)?),
            Robot::Fetch(..) if hand == 0 => Ok(()),
            Robot::Fetch(..) => Err(MagicError::NoHand(hand)),
        }
    }

    /// Lets go of what hand `hand` holds at once and opens it; the object it held, if any.
    /// The object stays where it is, its contacts with the hand back once they are apart.
    pub fn release_now(
        &mut self,
        world: &mut behavior_sim::World,
        hand: usize,
    ) -> Option<ObjectId> {
        match self {
            Robot::Behavior(robot, _) => {
                let side = *crate::Side::BOTH.get(hand)?;
                robot.release_now(world, side)
            }
            Robot::Fetch(robot, _) if hand == 0 => robot.release_now(world),
            Robot::Fetch(..) => None,
        }
    }
}

/// A BehaviorRobot's hand by its number: 0 left, 1 right.
fn side(hand: usize) -> Result<crate::Side, MagicError> {
    crate::Side::BOTH
        .get(hand)
        .copied()
        .ok_or(MagicError::NoHand(hand))
}
