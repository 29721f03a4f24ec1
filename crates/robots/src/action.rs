//! The BehaviorRobot's action: 26 numbers in [−1, 1], checked once when it is made, so a robot
//! only ever sees a valid one.
//!
//! Layout (iGibson 2.0's `BehaviorEnv`, iGibson 2.0.3's `robots/behavior_robot.py`: the 28-d raw
//! vector without its two "reset" entries):
//!
//! | index | part | meaning |
//! |---|---|---|
//! | 0–5 | body | Δ(x, y, z, roll, pitch, yaw) in the body's own frame |
//! | 6–11 | eye | Δ pose in the body frame |
//! | 12–17 | left hand | Δ pose in the body frame |
//! | 18 | left trigger | Δ trigger fraction |
//! | 19–24 | right hand | Δ pose in the body frame |
//! | 25 | right trigger | Δ trigger fraction |
//!
//! Every value is multiplied by [`ACTION_SCALE`]: at most 0.05 m, 0.05 rad or 0.05 of the
//! trigger per step. Values beyond [−1, 1] are clipped to it (a Gymnasium `Box` space's bounds);
//! NaN and infinities are refused.

use crate::hand::Side;
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Rotation, Vector};
use std::ops::Range;

/// How many numbers a BehaviorRobot action has.
pub const ACTION_DIM: usize = 26;

/// Metres, radians or trigger fraction per step for an action value of 1 (iGibson's
/// `BEHAVIOR_ROBOT_ACTION_SCALING`).
pub const ACTION_SCALE: f32 = 0.05;

/// Why a vector of numbers is not an action.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ActionError {
    /// It has the wrong number of values.
    #[error("an action of this space has {expected} values, got {got}")]
    WrongLength {
        /// The space's dimension.
        expected: usize,
        /// The length given.
        got: usize,
    },
    /// A value is NaN or infinite.
    #[error("action value {index} is {value}; every value must be a finite number")]
    NotFinite {
        /// Its index in the vector given.
        index: usize,
        /// The value.
        value: f32,
    },
    /// The robot has no such action space.
    #[error("the {robot} robot cannot be driven through the `{space}` action space")]
    Unsupported {
        /// The robot's name.
        robot: &'static str,
        /// The space's name.
        space: &'static str,
    },
}

/// N values checked: an error if there are not N or one is not finite; clipped to [−1, 1].
pub(crate) fn checked<const N: usize>(values: &[f32]) -> Result<[f32; N], ActionError> {
    if values.len() != N {
        return Err(ActionError::WrongLength {
            expected: N,
            got: values.len(),
        });
    }
    let mut action = [0.0; N];
    for (index, (&value, slot)) in values.iter().zip(&mut action).enumerate() {
        if !value.is_finite() {
            return Err(ActionError::NotFinite { index, value });
        }
        *slot = value.clamp(-1.0, 1.0);
    }
    Ok(action)
}

/// A valid BehaviorRobot action: 26 finite values in [−1, 1] (see the module docs for the
/// layout). It acts for one step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct Action([f32; ACTION_DIM]);

/// One part's motion for one step, scaled: metres and a rotation.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Delta {
    pub(crate) translation: Vector,
    pub(crate) rotation: Rotation,
}

impl Delta {
    /// Six values (x, y, z, roll, pitch, yaw), scaled. The rotation is roll about x, then pitch
    /// about y, then yaw about z (fixed axes), as pybullet's Euler angles.
    fn from_values(v: &[f32]) -> Delta {
        let s = ACTION_SCALE;
        Delta {
            translation: Vector::new(v[0], v[1], v[2]) * s,
            rotation: Rotation::from_euler(EulerRot::ZYX, v[5] * s, v[4] * s, v[3] * s),
        }
    }
}

impl Action {
    /// Indices of the body's Δ(x, y, z, roll, pitch, yaw).
    pub const BODY: Range<usize> = 0..6;
    /// Indices of the eye's Δ pose.
    pub const EYE: Range<usize> = 6..12;
    /// Indices of the left hand's Δ pose.
    pub const LEFT_HAND: Range<usize> = 12..18;
    /// Index of the left trigger's Δ.
    pub const LEFT_TRIGGER: usize = 18;
    /// Indices of the right hand's Δ pose.
    pub const RIGHT_HAND: Range<usize> = 19..25;
    /// Index of the right trigger's Δ.
    pub const RIGHT_TRIGGER: usize = 25;

    /// The action that moves nothing.
    pub const ZERO: Action = Action([0.0; ACTION_DIM]);

    /// An action from 26 values: an error if there are not 26 or one is not finite; values
    /// beyond [−1, 1] are clipped to it.
    pub fn new(values: &[f32]) -> Result<Action, ActionError> {
        checked(values).map(Action)
    }

    /// The 26 values, clipped to [−1, 1].
    pub fn values(&self) -> &[f32; ACTION_DIM] {
        &self.0
    }

    /// The indices of a hand's Δ pose.
    pub fn hand_range(side: Side) -> Range<usize> {
        match side {
            Side::Left => Action::LEFT_HAND,
            Side::Right => Action::RIGHT_HAND,
        }
    }

    /// The index of a hand's trigger.
    pub fn trigger_index(side: Side) -> usize {
        match side {
            Side::Left => Action::LEFT_TRIGGER,
            Side::Right => Action::RIGHT_TRIGGER,
        }
    }

    pub(crate) fn body(&self) -> Delta {
        Delta::from_values(&self.0[Action::BODY])
    }

    pub(crate) fn eye(&self) -> Delta {
        Delta::from_values(&self.0[Action::EYE])
    }

    pub(crate) fn hand(&self, side: Side) -> Delta {
        Delta::from_values(&self.0[Action::hand_range(side)])
    }

    /// The trigger's change this step, scaled.
    pub(crate) fn trigger(&self, side: Side) -> f32 {
        self.0[Action::trigger_index(side)] * ACTION_SCALE
    }
}

impl Default for Action {
    fn default() -> Self {
        Action::ZERO
    }
}

/// The reduced action spaces of iGibson's `BehaviorEnv` (its `action_filter`): a smaller vector
/// whose values go to some of the 26 entries, the others being zero.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ActionSpace {
    /// All 26 values.
    #[default]
    Full,
    /// 3 values: the body's Δx, Δy and Δyaw.
    Navigation,
    /// 17 values: the body's Δx, Δy, Δyaw, then the left hand's Δ pose and trigger, then the
    /// right hand's.
    MobileManipulation,
    /// 7 values: the right hand's Δ pose and trigger.
    TabletopManipulation,
    /// Fetch only: its whole action with the arm driven joint by joint instead of through
    /// inverse kinematics (iGibson 2.1+'s `JointController` on the arm), 13 values
    /// (`fetch_action.rs`). A motion planned in the arm's joint space is executed exactly as
    /// planned. The BehaviorRobot's hands have no joints: it is not among its
    /// [`crate::EmbodimentSpec::spaces`], and [`crate::Robot::add`] refuses it.
    Joints,
}

impl ActionSpace {
    /// Every space.
    pub const ALL: [ActionSpace; 5] = [
        ActionSpace::Full,
        ActionSpace::Navigation,
        ActionSpace::MobileManipulation,
        ActionSpace::TabletopManipulation,
        ActionSpace::Joints,
    ];

    /// Its name in files and on the command line: `full`, `navigation`,
    /// `mobile_manipulation`, `tabletop_manipulation` or `joints`.
    pub fn name(self) -> &'static str {
        match self {
            ActionSpace::Full => "full",
            ActionSpace::Navigation => "navigation",
            ActionSpace::MobileManipulation => "mobile_manipulation",
            ActionSpace::TabletopManipulation => "tabletop_manipulation",
            ActionSpace::Joints => "joints",
        }
    }

    /// The space with that [`ActionSpace::name`].
    pub fn from_name(name: &str) -> Option<ActionSpace> {
        ActionSpace::ALL.into_iter().find(|s| s.name() == name)
    }

    /// How many values a BehaviorRobot action of this space has (Fetch's:
    /// [`ActionSpace::fetch_dim`]); 0 for [`ActionSpace::Joints`], which it has not.
    pub fn dim(self) -> usize {
        match self {
            ActionSpace::Full => ACTION_DIM,
            ActionSpace::Navigation => 3,
            ActionSpace::MobileManipulation => 17,
            ActionSpace::TabletopManipulation => 7,
            ActionSpace::Joints => 0,
        }
    }

    /// The full action a vector of this space stands for; the same checks as [`Action::new`].
    pub fn action(self, values: &[f32]) -> Result<Action, ActionError> {
        if !crate::BehaviorRobot::SPEC.drives(self) {
            return Err(ActionError::Unsupported {
                robot: crate::RobotKind::Behavior.name(),
                space: self.name(),
            });
        }
        if values.len() != self.dim() {
            return Err(ActionError::WrongLength {
                expected: self.dim(),
                got: values.len(),
            });
        }
        let mut full = [0.0; ACTION_DIM];
        for (from, to) in self.mapping() {
            full[to.clone()].copy_from_slice(&values[from.clone()]);
        }
        // Errors name the index in the full vector; map it back to the caller's.
        Action::new(&full).map_err(|e| match e {
            ActionError::NotFinite { index, value } => ActionError::NotFinite {
                index: self.source_index(index),
                value,
            },
            other => other,
        })
    }

    /// Whether a BehaviorRobot's body moves by this space's actions.
    pub(crate) fn moves_body(self) -> bool {
        let body = Action::BODY.start;
        self.mapping().iter().any(|(_, to)| to.contains(&body))
    }

    /// The vector of this space that stands for `full` (its entries outside the space dropped);
    /// `None` for a space a BehaviorRobot is not driven through.
    pub(crate) fn reduce(self, full: &[f32; ACTION_DIM]) -> Option<Vec<f32>> {
        if !crate::BehaviorRobot::SPEC.drives(self) {
            return None;
        }
        let mut values = vec![0.0; self.dim()];
        for (from, to) in self.mapping() {
            values[from.clone()].copy_from_slice(&full[to.clone()]);
        }
        Some(values)
    }

    /// (range in this space, range in the full action) pairs.
    fn mapping(self) -> &'static [(Range<usize>, Range<usize>)] {
        match self {
            ActionSpace::Full => &[(0..26, 0..26)],
            ActionSpace::Navigation => &[(0..2, 0..2), (2..3, 5..6)],
            ActionSpace::MobileManipulation => &[(0..2, 0..2), (2..3, 5..6), (3..17, 12..26)],
            ActionSpace::TabletopManipulation => &[(0..7, 19..26)],
            ActionSpace::Joints => &[],
        }
    }

    fn source_index(self, full_index: usize) -> usize {
        self.mapping()
            .iter()
            .find(|(_, to)| to.contains(&full_index))
            .map_or(full_index, |(from, to)| from.start + full_index - to.start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_action_is_checked_and_clipped() {
        let mut values = [0.0; ACTION_DIM];
        values[3] = 7.0;
        assert_eq!(Action::new(&values).unwrap().values()[3], 1.0);
        values[4] = f32::NAN;
        assert!(matches!(
            Action::new(&values),
            Err(ActionError::NotFinite { index: 4, .. })
        ));
        assert_eq!(
            Action::new(&values[..25]),
            Err(ActionError::WrongLength {
                expected: 26,
                got: 25
            })
        );
    }

    #[test]
    fn reduced_spaces_fill_their_entries_of_the_full_action() {
        let nav = ActionSpace::Navigation.action(&[0.1, 0.2, 0.3]).unwrap();
        let mut expected = [0.0; ACTION_DIM];
        (expected[0], expected[1], expected[5]) = (0.1, 0.2, 0.3);
        assert_eq!(nav.values(), &expected);

        let values: Vec<f32> = (1..=17).map(|i| i as f32 / 100.0).collect();
        let mobile = ActionSpace::MobileManipulation.action(&values).unwrap();
        let v = mobile.values();
        assert_eq!((v[0], v[1], v[5]), (0.01, 0.02, 0.03));
        assert_eq!(&v[6..12], &[0.0; 6], "the eye stays");
        assert_eq!(v[Action::LEFT_HAND.start], 0.04);
        assert_eq!(v[Action::LEFT_TRIGGER], 0.10);
        assert_eq!(v[Action::RIGHT_HAND.start], 0.11);
        assert_eq!(v[Action::RIGHT_TRIGGER], 0.17);

        let table = ActionSpace::TabletopManipulation
            .action(&[0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
            .unwrap();
        assert_eq!(table.values()[Action::RIGHT_HAND.start], 0.5);
        assert_eq!(table.values()[Action::RIGHT_TRIGGER], 1.0);
        assert_eq!(table.values().iter().filter(|&&x| x != 0.0).count(), 2);

        let bad = ActionSpace::MobileManipulation.action(&{
            let mut v = [0.0; 17];
            v[4] = f32::INFINITY;
            v
        });
        assert!(
            matches!(bad, Err(ActionError::NotFinite { index: 4, .. })),
            "{bad:?}"
        );
        assert!(ActionSpace::Navigation.action(&[0.0; 26]).is_err());
    }
}
