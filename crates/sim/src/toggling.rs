//! `toggled_on`: a hand point held within 0.1 m of an object's toggle button for 5 consecutive
//! steps flips the state once; holding longer does not flip it again (iGibson 2.0, §1.8).
//!
//! Hand points are world positions that the embodiment reports each step ([`World::set_hand_points`]).

use crate::world::{ObjectId, PointKind, World};
use behavior_bddl::taxonomy::Ability;
use rapier3d::math::Vector;

pub const TOGGLE_DISTANCE: f32 = 0.1;
pub const TOGGLE_STEPS: u32 = 5;

impl World {
    /// The points (palms, fingertips, gripper) that can press buttons, from now on.
    pub fn set_hand_points(&mut self, points: &[Vector]) {
        self.hands = points.iter().copied().filter(|p| p.is_finite()).collect();
    }

    pub(crate) fn update_toggles(&mut self) {
        for i in 0..self.states.len() {
            let id = ObjectId(i as u32);
            let object = self.object(id);
            if !object.has(Ability::Toggleable) {
                continue;
            }
            let Some(button) = object.point(PointKind::ToggleButton) else {
                continue;
            };
            let button = self.pose(id).transform_point(button);
            let near = self
                .hands
                .iter()
                .any(|h| (*h - button).length() <= TOGGLE_DISTANCE);
            let s = &mut self.states[i];
            if near {
                s.toggle_steps += 1;
                if s.toggle_steps == TOGGLE_STEPS {
                    s.toggled_on = !s.toggled_on;
                }
            } else {
                s.toggle_steps = 0;
            }
        }
    }
}
