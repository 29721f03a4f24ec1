//! Why a move outside physics was refused: the error of [`crate::Embodiment`]'s moves for
//! symbolic ("magic") action primitives (iGibson 2.0.3's
//! `envs/behavior_mp_env.py`: the original teleports the robot for NAVIGATE_TO, puts the object in
//! the hand and forces the assisted grasp for GRASP, and forces the release for PLACE_*).
//!
//! Each move leaves the robot at rest and consistent with the world: a teleported robot stands
//! with its hands parked where its targets put them, carrying what it holds along; a grasp made
//! here is the same attachment a pressed trigger makes, so the next steps hold it as any other.

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
