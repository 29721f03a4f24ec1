//! What a planner needs of a hand whose pose the robot's actions set directly (the
//! BehaviorRobot's palms): the [`PosedHand`] trait.
//!
//! Such a hand has no arm to plan: it is told where to be (its target, in the base's frame),
//! within reach of a shoulder, and a servo brings the palm there. A planner moves the target by
//! at most one step's offset per action, presses or lets go its trigger, and raises or lowers
//! the body that carries it. Like [`crate::Arm`], what [`crate::Embodiment::posed_hand`] hands
//! out is a snapshot of the hand as it stands, owning what it needs.

use behavior_sim::{Primitive, World};
use rapier3d::math::{Pose, Vector};

/// A hand posed directly by actions, as a planner reads it (see the module docs).
pub trait PosedHand: std::fmt::Debug + Send + Sync {
    /// Its number among the robot's hands.
    fn hand(&self) -> usize;

    /// Where it is told to be, in the base's frame.
    fn target(&self) -> Pose;

    /// The centre of its reach, in the world: a target farther than [`PosedHand::reach`] from
    /// it is refused.
    fn shoulder(&self, world: &World) -> Vector;

    /// How far from the shoulder it reaches, m.
    fn reach(&self) -> f32;

    /// How far one action moves its target at most, along each of its six offsets (m, rad).
    fn step(&self) -> f32;

    /// The shape the robot keeps out of fixed things (the palm with its fingers straight) and
    /// its pose in the hand's frame: a plan that keeps it clear is never refused.
    fn sweep(&self) -> (Primitive, Pose);

    /// How far its trigger is pressed: 0 open, 1 closed.
    fn trigger(&self) -> f32;

    /// Where it is drawn in to before the base drives, in the base's frame.
    fn tucked(&self) -> Pose;

    /// The robot's action, in its primitive space, that moves the target by `offset` (x, y,
    /// z, roll, pitch, yaw in the base's frame, m and rad) as far as one step allows,
    /// everything else still.
    fn move_action(&self, offset: [f32; 6]) -> Vec<f32>;

    /// The action that presses (`press` 1) or lets go (−1) its trigger, everything else still.
    fn trigger_action(&self, press: f32) -> Vec<f32>;

    /// The action that raises the body carrying the hands by `up` (m; down if negative) as
    /// far as one step allows, everything else still.
    fn lift_action(&self, up: f32) -> Vec<f32>;
}
