//! Fetch's action: 11 numbers in [−1, 1], as iGibson 2.0's `FetchGripper` (iGibson 2.0.3's
//! `robots/fetch_gripper_robot.py`, and iGibson 2.0.3's `fetch_gripper_robot.py` for the scaling),
//! checked once when it is made.
//!
//! | index | meaning | 1.0 means |
//! |---|---|---|
//! | 0 | base linear velocity (differential drive) | 1 m/s forward |
//! | 1 | base angular velocity | π rad/s counter-clockwise (iGibson 2.0.3 turns clockwise, a
//! wheel-order bug) |
//! | 2, 3 | head pan and tilt velocity | 1.57 rad/s |
//! | 4–6 | end-effector Δ position in the base frame | 0.05 m |
//! | 7–9 | end-effector Δ orientation (axis-angle, base frame) | 0.262 rad |
//! | 10 | gripper | > 0 opens, otherwise closes, at 0.05 m/s; < 0 also grasps |
//!
//! Values beyond [−1, 1] are clipped to it; NaN and infinities are refused.
//!
//! The reduced spaces ([`ActionSpace`], shared with the BehaviorRobot, the names of iGibson's
//! `action_filter`s) give Fetch:
//! - [`ActionSpace::Navigation`]: 2 values, the base's linear and angular velocity;
//! - [`ActionSpace::MobileManipulation`]: 9 values, the base's 2, the end effector's 6 and the
//!   gripper (the head stays);
//! - [`ActionSpace::TabletopManipulation`]: 7 values, the end effector's 6 and the gripper.
//!
//! [`ActionSpace::Joints`] drives the arm joint by joint instead ([`FetchJointAction`], as
//! iGibson 2.1+'s `JointController` in velocity mode), 13 values:
//!
//! | index | meaning | 1.0 means |
//! |---|---|---|
//! | 0–3 | base and head, as above | |
//! | 4 | torso lift velocity | its maximum, 0.1 m/s |
//! | 5–11 | arm joint velocities, shoulder pan to wrist roll | each joint's maximum (1.26–2.27
//! rad/s) |
//! | 12 | gripper, as above | |
//!
//! The first four and the last have the same meaning in both, so [`FetchCommand`] reads them
//! alike.

use crate::action::{ActionError, ActionSpace, checked};
use crate::fetch_body::FetchJoint;
use behavior_sim::STEP_SECONDS;
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::PI;
use std::ops::Range;

/// How many numbers a Fetch action has.
pub const FETCH_ACTION_DIM: usize = 11;
/// The base's speed at action 1, m/s.
pub const MAX_LINEAR_SPEED: f32 = 1.0;
/// The base's turning rate at action 1, rad/s.
pub const MAX_ANGULAR_SPEED: f32 = PI;
/// The head joints' speed at action 1, rad/s (their URDF maximum).
pub const HEAD_SPEED: f32 = 1.57;
/// The end effector's Δ position per step at action 1, m (iGibson's 0.25 × 0.2).
pub const EEF_STEP: f32 = 0.05;
/// The end effector's Δ rotation per step at action 1, rad (iGibson's 0.5236 ≈ π/6, × 0.5).
pub const EEF_TURN: f32 = std::f32::consts::FRAC_PI_6 * 0.5;

/// A valid Fetch action (see the module docs for the layout). It acts for one step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, Default, PartialEq)]
pub struct FetchAction([f32; FETCH_ACTION_DIM]);

impl FetchAction {
    /// Index of the base's linear velocity.
    pub const LINEAR: usize = 0;
    /// Index of the base's angular velocity.
    pub const ANGULAR: usize = 1;
    /// Indices of the head's pan and tilt velocities.
    pub const HEAD: Range<usize> = 2..4;
    /// Indices of the end effector's Δ position.
    pub const EEF_POSITION: Range<usize> = 4..7;
    /// Indices of the end effector's Δ orientation.
    pub const EEF_ROTATION: Range<usize> = 7..10;
    /// Index of the gripper's command.
    pub const GRIPPER: usize = 10;

    /// The action that moves nothing and closes the gripper (iGibson's zero action does too:
    /// only a positive value opens).
    pub const ZERO: FetchAction = FetchAction([0.0; FETCH_ACTION_DIM]);

    /// An action from 11 values: an error if there are not 11 or one is not finite; values
    /// beyond [−1, 1] are clipped to it.
    pub fn new(values: &[f32]) -> Result<FetchAction, ActionError> {
        checked(values).map(FetchAction)
    }

    /// The 11 values, clipped to [−1, 1].
    pub fn values(&self) -> &[f32; FETCH_ACTION_DIM] {
        &self.0
    }

    /// The end effector's Δ position (m) and Δ rotation for this step, in the base frame.
    pub fn eef(&self) -> (Vector, Rotation) {
        let p = Vector::from_slice(&self.0[Self::EEF_POSITION]) * EEF_STEP;
        let r = Vector::from_slice(&self.0[Self::EEF_ROTATION]) * EEF_TURN;
        (p, Rotation::from_scaled_axis(r))
    }

    /// Whether the end effector is told to move.
    pub fn moves_eef(&self) -> bool {
        self.0[4..10].iter().any(|&x| x != 0.0)
    }
}

/// How many numbers a Fetch action of [`ActionSpace::Joints`] has.
pub const FETCH_JOINT_ACTION_DIM: usize = 13;

/// A valid Fetch action of [`ActionSpace::Joints`]: the arm driven joint by joint (see the
/// module docs for the layout). It acts for one step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct FetchJointAction([f32; FETCH_JOINT_ACTION_DIM]);

impl FetchJointAction {
    /// Index of the torso lift's velocity.
    pub const TORSO: usize = 4;
    /// Indices of the torso's and the seven arm joints' velocities (the planner's order).
    pub const JOINTS: Range<usize> = 4..12;
    /// Index of the gripper's command.
    pub const GRIPPER: usize = 12;

    /// An action from 13 values, checked as [`FetchAction::new`] checks 11.
    pub fn new(values: &[f32]) -> Result<FetchJointAction, ActionError> {
        checked(values).map(FetchJointAction)
    }

    /// The 13 values, clipped to [−1, 1].
    pub fn values(&self) -> &[f32; FETCH_JOINT_ACTION_DIM] {
        &self.0
    }

    /// The torso's (m/s) and the arm joints' (rad/s) commanded velocities, torso first.
    pub fn rates(&self) -> [f32; 8] {
        std::array::from_fn(|k| self.0[Self::TORSO + k] * arm_joint(k).info().max_velocity)
    }

    /// The value that asks joint `k` of [`FetchJointAction::rates`] (0 the torso) to move by
    /// `delta` (m or rad) in one step, within [−1, 1].
    pub fn value_for(k: usize, delta: f32) -> f32 {
        (delta / (arm_joint(k).info().max_velocity * STEP_SECONDS)).clamp(-1.0, 1.0)
    }
}

/// The joint of [`FetchJointAction::rates`]'s entry `k`: the torso, then the arm's.
fn arm_joint(k: usize) -> FetchJoint {
    match k {
        0 => FetchJoint::TorsoLift,
        _ => FetchJoint::ARM[k - 1],
    }
}

/// What Fetch is told for a step, through either of its arm's controllers.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub enum FetchCommand {
    /// The end effector's motion, through inverse kinematics.
    EndEffector(FetchAction),
    /// The torso's and arm joints' velocities.
    Joints(FetchJointAction),
}

impl Default for FetchCommand {
    /// Nothing moves and the gripper closes.
    fn default() -> Self {
        FetchCommand::EndEffector(FetchAction::ZERO)
    }
}

impl From<FetchAction> for FetchCommand {
    fn from(action: FetchAction) -> Self {
        FetchCommand::EndEffector(action)
    }
}

impl From<FetchJointAction> for FetchCommand {
    fn from(action: FetchJointAction) -> Self {
        FetchCommand::Joints(action)
    }
}

impl FetchCommand {
    /// The values: both layouts begin with the base's and head's four and end with the
    /// gripper's.
    pub fn values(&self) -> &[f32] {
        match self {
            FetchCommand::EndEffector(a) => a.values(),
            FetchCommand::Joints(a) => a.values(),
        }
    }

    /// The base's commanded linear (m/s) and angular (rad/s) velocity.
    pub fn base(&self) -> (f32, f32) {
        let v = self.values();
        (
            v[FetchAction::LINEAR] * MAX_LINEAR_SPEED,
            v[FetchAction::ANGULAR] * MAX_ANGULAR_SPEED,
        )
    }

    /// The head's commanded pan and tilt velocities, rad/s.
    pub fn head(&self) -> [f32; 2] {
        let v = self.values();
        [v[2] * HEAD_SPEED, v[3] * HEAD_SPEED]
    }

    /// The gripper's command: > 0 opens, otherwise closes.
    pub fn gripper(&self) -> f32 {
        self.values().last().copied().unwrap_or(0.0)
    }
}

impl ActionSpace {
    /// How many values a Fetch action of this space has (see `fetch_action.rs`).
    pub fn fetch_dim(self) -> usize {
        match self {
            ActionSpace::Full => FETCH_ACTION_DIM,
            ActionSpace::Navigation => 2,
            ActionSpace::MobileManipulation => 9,
            ActionSpace::TabletopManipulation => 7,
            ActionSpace::Joints => FETCH_JOINT_ACTION_DIM,
        }
    }

    /// The full Fetch command a vector of this space stands for, the other entries zero (the
    /// head still; the gripper closing, in [`ActionSpace::Navigation`]); the same checks as
    /// [`FetchAction::new`], errors naming the caller's index.
    pub fn fetch_action(self, values: &[f32]) -> Result<FetchCommand, ActionError> {
        if self == ActionSpace::Joints {
            return FetchJointAction::new(values).map(FetchCommand::Joints);
        }
        if values.len() != self.fetch_dim() {
            return Err(ActionError::WrongLength {
                expected: self.fetch_dim(),
                got: values.len(),
            });
        }
        let offset = match self {
            ActionSpace::Full | ActionSpace::Navigation | ActionSpace::Joints => 0,
            ActionSpace::MobileManipulation => 2,
            ActionSpace::TabletopManipulation => 4,
        };
        let mut full = [0.0; FETCH_ACTION_DIM];
        for (k, &value) in values.iter().enumerate() {
            // The base's two values keep their places; the rest skip the head's two.
            let to = if k < 2 && offset != 4 { k } else { k + offset };
            full[to] = value;
        }
        let action = FetchAction::new(&full).map_err(|e| match e {
            ActionError::NotFinite { index, value } => ActionError::NotFinite {
                index: if index < 2 { index } else { index - offset },
                value,
            },
            other => other,
        })?;
        Ok(FetchCommand::EndEffector(action))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduced_spaces_fill_their_entries_of_the_full_action() {
        let nav = ActionSpace::Navigation.fetch_action(&[0.5, -0.25]).unwrap();
        assert_eq!(nav.base(), (0.5, -0.25 * PI));
        let values: Vec<f32> = (1..=9).map(|i| i as f32 / 10.0).collect();
        let mobile = ActionSpace::MobileManipulation
            .fetch_action(&values)
            .unwrap();
        let v = mobile.values();
        assert_eq!((v[0], v[1], v[2], v[3]), (0.1, 0.2, 0.0, 0.0));
        assert_eq!(&v[4..], &[0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]);
        let table = ActionSpace::TabletopManipulation
            .fetch_action(&[0.1, 0.2, 0.3, 0.4, 0.5, 0.6, -1.0])
            .unwrap();
        assert_eq!(&table.values()[..4], &[0.0; 4]);
        assert_eq!(table.gripper(), -1.0);
        let bad = ActionSpace::TabletopManipulation.fetch_action(&[
            0.0,
            0.0,
            f32::NAN,
            0.0,
            0.0,
            0.0,
            0.0,
        ]);
        assert!(matches!(bad, Err(ActionError::NotFinite { index: 2, .. })));
        let bad = ActionSpace::MobileManipulation.fetch_action(&[
            0.0,
            f32::INFINITY,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ]);
        assert!(matches!(bad, Err(ActionError::NotFinite { index: 1, .. })));
        assert!(ActionSpace::Full.fetch_action(&[0.0; 10]).is_err());
        assert_eq!(FetchAction::new(&[9.0; 11]).unwrap().values(), &[1.0; 11]);
    }
}
