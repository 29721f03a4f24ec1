//! Teleoperation commands and the BehaviorRobot action each one makes.
//!
//! A keyboard or a gamepad gives rates, not poses: a held key or a tilted stick moves a part at
//! a fraction of its top speed (the action's scale: 0.05 m or rad per step), and the grip keys
//! close or open a hand's trigger. The page sends the current rates whenever they change; the
//! server applies the latest to every step until the next arrives.

use behavior_robots::{ACTION_DIM, Action};
use serde::{Deserialize, Serialize};

/// Rates for each part of the BehaviorRobot, each in [−1, 1] (a fraction of the part's top
/// speed), in the body's frame: x ahead, y left, z up; rotations roll, pitch, yaw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Drive {
    /// The body: Δ(x, y, z, roll, pitch, yaw).
    pub body: [f32; 6],
    /// The eye (head camera), relative to the body.
    pub eye: [f32; 6],
    /// The left hand, relative to the body.
    pub left: [f32; 6],
    /// The right hand, relative to the body.
    pub right: [f32; 6],
    /// The left and right triggers: +1 closes a hand at full speed, −1 opens it.
    pub grip: [f32; 2],
}

/// A field of a [`Drive`] that is not a finite number.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{field}[{index}]` is {value}; every rate must be a finite number in [-1, 1]")]
pub struct BadRate {
    /// The field's name.
    pub field: &'static str,
    /// Its index in the field.
    pub index: usize,
    /// The value sent.
    pub value: f32,
}

impl Drive {
    /// The first value that is not finite or lies outside [−1, 1].
    pub fn check(&self) -> Result<(), BadRate> {
        let fields: [(&'static str, &[f32]); 5] = [
            ("body", &self.body),
            ("eye", &self.eye),
            ("left", &self.left),
            ("right", &self.right),
            ("grip", &self.grip),
        ];
        for (field, values) in fields {
            for (index, &value) in values.iter().enumerate() {
                if !value.is_finite() || value.abs() > 1.0 {
                    return Err(BadRate {
                        field,
                        index,
                        value,
                    });
                }
            }
        }
        Ok(())
    }

    /// The BehaviorRobot's action for one step (the layout of [`Action`]).
    pub fn action(&self) -> [f32; ACTION_DIM] {
        let mut a = [0.0; ACTION_DIM];
        a[Action::BODY].copy_from_slice(&self.body);
        a[Action::EYE].copy_from_slice(&self.eye);
        a[Action::LEFT_HAND].copy_from_slice(&self.left);
        a[Action::LEFT_TRIGGER] = self.grip[0];
        a[Action::RIGHT_HAND].copy_from_slice(&self.right);
        a[Action::RIGHT_TRIGGER] = self.grip[1];
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_rate_lands_where_the_action_layout_puts_it() {
        let drive = Drive {
            body: [1.0, 0.0, 0.0, 0.0, 0.0, -0.5],
            right: [0.0, 0.0, 0.25, 0.0, 0.0, 0.0],
            grip: [0.0, 1.0],
            ..Drive::default()
        };
        let a = drive.action();
        assert_eq!(a[0], 1.0);
        assert_eq!(a[5], -0.5);
        assert_eq!(a[Action::RIGHT_HAND.start + 2], 0.25);
        assert_eq!(a[Action::RIGHT_TRIGGER], 1.0);
        assert_eq!(a[Action::LEFT_TRIGGER], 0.0);
        assert_eq!(a.iter().filter(|v| **v != 0.0).count(), 4);
        Action::new(&a).expect("a valid action");
    }

    #[test]
    fn a_rate_beyond_one_or_not_a_number_is_named() {
        let mut drive = Drive::default();
        drive.left[3] = f32::NAN;
        let e = drive.check().unwrap_err();
        assert_eq!((e.field, e.index), ("left", 3));
        drive.left[3] = 0.0;
        drive.grip[1] = 1.5;
        let e = drive.check().unwrap_err();
        assert_eq!((e.field, e.index), ("grip", 1));
        assert!(e.to_string().contains("grip[1]"), "{e}");
    }
}
