//! What a planner needs of a jointed arm, whichever robot it belongs to: the [`Arm`] trait and
//! the [`ArmConfig`] its joints take.
//!
//! An arm here is the chain of joints that moves one hand (a torso's joints included where they
//! carry it), read the way an arm planner reads it: the joints' limits, where every link the
//! chain moves is at a configuration (forward kinematics), which configuration puts the end
//! effector at a pose (inverse kinematics), and which action of the robot's own moves the joints
//! by an offset within a step, with what that action does to them. It is a snapshot: what
//! [`crate::Embodiment::arm`] hands out describes the arm as it stands when asked, owns what it
//! needs and borrows nothing, so that a planner can keep it while the episode steps on.

use behavior_sim::{BodyRef, ObjectId, Primitive, World};
use rapier3d::math::Pose;
use std::ops::{Index, IndexMut, Range};

/// The most joints an arm's chain has (Fetch: 8, its torso lift and seven arm joints).
pub const MAX_ARM_JOINTS: usize = 12;

/// The positions of an arm's joints in the arm's own order (torso first), m or rad: plain data,
/// copied freely (no allocation: at most [`MAX_ARM_JOINTS`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ArmConfig {
    len: u8,
    /// Unused entries stay 0, so that equal configurations compare equal.
    values: [f32; MAX_ARM_JOINTS],
}

impl ArmConfig {
    /// The configuration of `len` joints whose position `k` is `f(k)`; at most
    /// [`MAX_ARM_JOINTS`] (an arm declares no more).
    pub fn from_fn(len: usize, mut f: impl FnMut(usize) -> f32) -> ArmConfig {
        let len = len.min(MAX_ARM_JOINTS);
        let mut values = [0.0; MAX_ARM_JOINTS];
        for (k, value) in values.iter_mut().enumerate().take(len) {
            *value = f(k);
        }
        ArmConfig {
            len: len as u8,
            values,
        }
    }

    /// The configuration of these positions (at most [`MAX_ARM_JOINTS`] of them are kept).
    pub fn new(values: &[f32]) -> ArmConfig {
        ArmConfig::from_fn(values.len(), |k| values[k])
    }

    /// How many joints.
    pub fn len(&self) -> usize {
        usize::from(self.len)
    }

    /// Whether it has no joints (no arm).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The positions.
    pub fn values(&self) -> &[f32] {
        &self.values[..self.len()]
    }

    /// The positions, to change them.
    pub fn values_mut(&mut self) -> &mut [f32] {
        let len = self.len();
        &mut self.values[..len]
    }

    /// Whether every position is a finite number.
    pub fn is_finite(&self) -> bool {
        self.values().iter().all(|x| x.is_finite())
    }
}

impl Index<usize> for ArmConfig {
    type Output = f32;

    fn index(&self, k: usize) -> &f32 {
        &self.values()[k]
    }
}

impl IndexMut<usize> for ArmConfig {
    fn index_mut(&mut self, k: usize) -> &mut f32 {
        &mut self.values_mut()[k]
    }
}

/// A robot's arm as a planner reads it (see the module docs). Poses are in the base's frame
/// unless said otherwise; link lists are in the order of [`Arm::links`].
pub trait Arm: std::fmt::Debug + Send + Sync {
    /// The hand at its end (the robot's hand number).
    fn hand(&self) -> usize;

    /// Where its joints are now.
    fn now(&self) -> ArmConfig;

    /// Each joint's lower and upper limit, `None` for a continuous joint; one per joint of
    /// [`Arm::now`].
    fn limits(&self) -> &[Option<[f32; 2]>];

    /// The links whose poses [`Arm::link_poses`] gives: the base's and every link the joints
    /// move, the gripper's among them.
    fn links(&self) -> &[ObjectId];

    /// Which of [`Arm::links`] the joints move.
    fn moving(&self) -> Range<usize>;

    /// Which of [`Arm::links`] is the hand's (the gripper whose pose is the end effector's).
    fn gripper(&self) -> usize;

    /// Every link's pose at `c`, in [`Arm::links`] order.
    fn link_poses(&self, c: &ArmConfig) -> Vec<Pose>;

    /// The end effector's pose at `c`.
    fn eef(&self, c: &ArmConfig) -> Pose;

    /// A configuration within the limits that puts the end effector at `goal`, searched from
    /// `start` (and, failing that, from the arm's rest pose); `None` where none is found.
    fn ik(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig>;

    /// [`Arm::ik`] searched from `start` only: a solution near it, for small steps along a line.
    fn ik_near(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig>;

    /// The joint that lifts the torso straight up, m, if the arm has one (a planner raises
    /// what it carries with it).
    fn lift_joint(&self) -> Option<usize>;

    /// `from` with the arm folded over the base as the robot folds it to drive (its torso
    /// where it is).
    fn tucked(&self, from: &ArmConfig) -> ArmConfig;

    /// The box the fingers sweep over their travel, in the gripper's frame: kept clear of
    /// fixed things whether they are open or closed.
    fn finger_sweep(&self) -> (Primitive, Pose);

    /// How far the fingertips reach beyond the end effector along its x, m.
    fn tip(&self) -> f32;

    /// The gripper's bodies that touch what it takes (palm and fingers).
    fn gripper_bodies(&self) -> Vec<BodyRef>;

    /// Whether the fingers stand open (each at least nine tenths of its travel out).
    fn fingers_open(&self, world: &World) -> bool;

    /// The robot's action, in the space its physical primitives drive it through
    /// ([`crate::EmbodimentSpec::primitive_space`]), that moves each joint from `from` by
    /// `delta` as far as one step allows, the base and everything else still, the gripper
    /// commanded `gripper` (1 open, −1 closed); `None` if that is no valid action (not
    /// finite). A robot whose action moves joints by rates reads only `delta`; one whose action
    /// gives their positions (the R1's) needs `from`, where the planner has the arm.
    fn joint_action(&self, from: &ArmConfig, delta: &ArmConfig, gripper: f32) -> Option<Vec<f32>>;

    /// Where one step of `action` (as [`Arm::joint_action`] makes them) takes the joints from
    /// `c`, nothing in their way: the robot's own update, for planners that predict a path.
    fn after(&self, c: &ArmConfig, action: &[f32]) -> ArmConfig;
}
