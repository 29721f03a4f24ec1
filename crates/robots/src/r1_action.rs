//! The R1's action: the BEHAVIOR Challenge's 23 numbers, checked once when made.
//!
//! Layout (OmniGibson's R1Pro as the challenge drives it, `docs/r1-pro-facts.md` §4):
//!
//! | index | part | meaning |
//! |---|---|---|
//! | 0–2 | base | velocity forward, to the left and turning, in [−1, 1] of ±(0.75 m/s, 0.75 m/s, 1 rad/s) |
//! | 3–6 | torso | absolute joint positions, rad |
//! | 7–13 | left arm | absolute joint positions, rad, shoulder first |
//! | 14 | left gripper | above 0 opens, below 0 closes, 0 leaves it as it is |
//! | 15–21 | right arm | absolute joint positions, rad |
//! | 22 | right gripper | as the left |
//!
//! Base and gripper values beyond [−1, 1] are clipped to it, joint positions to the joint's
//! limits; NaN and infinities are refused. Each joint moves toward its position at most at its
//! URDF velocity (the challenge's position controller, whose gain of 150 reaches any target
//! within a step or two, is limited by the same velocities). The challenge's gripper is a
//! position too (−1 closed to 1 open); ours closes or opens a stroke a step, as Fetch's, so
//! that the assisted grasp sees a closing gripper: a value's sign is what counts.
//!
//! The `navigation` space is the base's three values, every joint held where it is.

use crate::action::{ActionError, checked};
use crate::chain::ChainJoint;
use crate::hand::Side;
use crate::kinematic_links::Twist;
use crate::r1_body::R1Joints;
use crate::r1_kinematics::{arm_joints, torso_joints};
use std::ops::Range;

/// How many numbers an R1 action has.
pub const R1_ACTION_DIM: usize = 23;

/// The base's top speeds: forward and sideways, m/s, and turning, rad/s (the challenge's base
/// controller's output limits).
pub const R1_BASE_SPEED: [f32; 3] = [0.75, 0.75, 1.0];

/// A valid R1 action (see the module docs for the layout). It acts for one step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct R1Action([f32; R1_ACTION_DIM]);

impl R1Action {
    /// Indices of the base's velocity.
    pub const BASE: Range<usize> = 0..3;
    /// Indices of the torso's joint positions.
    pub const TORSO: Range<usize> = 3..7;
    /// Indices of the left arm's joint positions.
    pub const LEFT_ARM: Range<usize> = 7..14;
    /// Index of the left gripper's command.
    pub const LEFT_GRIPPER: usize = 14;
    /// Indices of the right arm's joint positions.
    pub const RIGHT_ARM: Range<usize> = 15..22;
    /// Index of the right gripper's command.
    pub const RIGHT_GRIPPER: usize = 22;

    /// An action from 23 values: an error if there are not 23 or one is not finite; values
    /// beyond their range are clipped to it.
    pub fn new(values: &[f32]) -> Result<R1Action, ActionError> {
        // Checked (and clipped to [-1, 1]) for the base and the grippers; the joints come as
        // they were given, to be clipped to their limits.
        let mut out = checked::<R1_ACTION_DIM>(values)?;
        let joints_given: [f32; R1_ACTION_DIM] = std::array::from_fn(|k| values[k]);
        R1Action::put_joints(&mut out, &R1Action::joints_of(&joints_given));
        let joints = R1Action::joints_of(&out).clamped();
        R1Action::put_joints(&mut out, &joints);
        Ok(R1Action(out))
    }

    /// The action that holds every joint at `joints`, the base still, the grippers as they are.
    pub fn holding(joints: &R1Joints) -> R1Action {
        let mut values = [0.0; R1_ACTION_DIM];
        R1Action::put_joints(&mut values, &joints.clamped());
        R1Action(values)
    }

    /// Each value's lower and upper bound: [−1, 1] for the base and the grippers, the joint's
    /// limits for a joint's position.
    pub fn bounds() -> [[f32; 2]; R1_ACTION_DIM] {
        let mut bounds = [[-1.0, 1.0]; R1_ACTION_DIM];
        let limits = |joints: &[ChainJoint]| -> Vec<[f32; 2]> {
            joints
                .iter()
                .map(|j| j.limits.unwrap_or([-1.0, 1.0]))
                .collect()
        };
        bounds[R1Action::TORSO].copy_from_slice(&limits(&torso_joints()));
        for side in Side::BOTH {
            bounds[R1Action::arm_range(side)].copy_from_slice(&limits(&arm_joints(side)));
        }
        bounds
    }

    /// The 23 values, clipped.
    pub fn values(&self) -> &[f32; R1_ACTION_DIM] {
        &self.0
    }

    /// The indices of an arm's joint positions.
    pub fn arm_range(side: Side) -> Range<usize> {
        match side {
            Side::Left => R1Action::LEFT_ARM,
            Side::Right => R1Action::RIGHT_ARM,
        }
    }

    /// The index of a gripper's command.
    pub fn gripper_index(side: Side) -> usize {
        match side {
            Side::Left => R1Action::LEFT_GRIPPER,
            Side::Right => R1Action::RIGHT_GRIPPER,
        }
    }

    /// The joint positions it asks for.
    pub fn joints(&self) -> R1Joints {
        R1Action::joints_of(&self.0)
    }

    /// The base's velocity it asks for.
    pub(crate) fn twist(&self) -> Twist {
        let [x, y, w] = [0, 1, 2].map(|k| self.0[k] * R1_BASE_SPEED[k]);
        Twist {
            forward: x,
            left: y,
            turn: w,
        }
    }

    /// A gripper's command: above 0 opens, below 0 closes, 0 leaves it.
    pub fn gripper(&self, side: Side) -> f32 {
        self.0[R1Action::gripper_index(side)]
    }

    fn joints_of(values: &[f32; R1_ACTION_DIM]) -> R1Joints {
        R1Joints {
            torso: std::array::from_fn(|k| values[R1Action::TORSO.start + k]),
            arms: Side::BOTH.map(|side| {
                let start = R1Action::arm_range(side).start;
                std::array::from_fn(|k| values[start + k])
            }),
        }
    }

    fn put_joints(values: &mut [f32; R1_ACTION_DIM], joints: &R1Joints) {
        values[R1Action::TORSO].copy_from_slice(&joints.torso);
        for side in Side::BOTH {
            values[R1Action::arm_range(side)].copy_from_slice(&joints.arms[side.index()]);
        }
    }
}

/// Where one step toward `target` takes the joints from `now`: each at most its URDF velocity
/// times the step, within its limits.
pub(crate) fn step_toward(now: &R1Joints, target: &R1Joints, step: f32) -> R1Joints {
    let approach = |q: &mut f32, goal: f32, joint: &ChainJoint| {
        let most = joint.max_velocity * step;
        *q += (goal - *q).clamp(-most, most);
    };
    let mut out = *now;
    for ((q, &goal), joint) in out.torso.iter_mut().zip(&target.torso).zip(&torso_joints()) {
        approach(q, goal, joint);
    }
    for side in Side::BOTH {
        let (arm, goals) = (&mut out.arms[side.index()], &target.arms[side.index()]);
        for ((q, &goal), joint) in arm.iter_mut().zip(goals).zip(&arm_joints(side)) {
            approach(q, goal, joint);
        }
    }
    out.clamped()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_action_is_checked_and_clipped_to_its_ranges() {
        let mut values = [0.0; R1_ACTION_DIM];
        values[0] = 3.0;
        values[R1Action::TORSO.start] = 9.0;
        values[R1Action::RIGHT_GRIPPER] = -4.0;
        let action = R1Action::new(&values).unwrap();
        assert_eq!(action.values()[0], 1.0);
        assert_eq!(action.twist().forward, 0.75);
        // torso_joint1's upper limit.
        assert_eq!(action.joints().torso[0], 1.8326);
        assert_eq!(action.gripper(Side::Right), -1.0);
        values[5] = f32::NAN;
        assert!(matches!(
            R1Action::new(&values),
            Err(ActionError::NotFinite { index: 5, .. })
        ));
        assert!(matches!(
            R1Action::new(&values[..22]),
            Err(ActionError::WrongLength {
                expected: 23,
                got: 22
            })
        ));
    }

    #[test]
    fn joints_move_toward_their_targets_at_most_at_their_velocity() {
        let now = R1Joints::default();
        let mut target = now;
        target.torso[0] += 1.0;
        target.arms[0][6] += 0.01;
        let next = step_toward(&now, &target, 1.0 / 30.0);
        assert!((next.torso[0] - now.torso[0] - 2.5 / 30.0).abs() < 1e-6);
        assert_eq!(next.arms[0][6], target.arms[0][6]);
        assert_eq!(R1Action::holding(&now).joints(), now);
    }
}
