//! `toggled_on`: a hand point held within 0.1 m of an object's toggle button for 5 consecutive
//! steps flips the state once; holding longer does not flip it again (iGibson 2.0, §1.8).
//!
//! Hand points are world positions that the embodiment reports each step
//! ([`crate::World::set_hand_points`]).

use crate::core::Core;
use crate::object::{Object, ObjectId, PointKind};
use behavior_core::Ability;
use rapier3d::math::Vector;
use serde::{Deserialize, Serialize};

/// How near a hand must be to a button (m).
pub const TOGGLE_DISTANCE: f32 = 0.1;
/// For how many consecutive steps.
pub const TOGGLE_STEPS: u32 = 5;

/// The toggling system: each object's switch and how long a hand has been at its button.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Toggles {
    on: Vec<bool>,
    held_steps: Vec<u32>,
    hands: Vec<Vector>,
    /// The toggleable objects, in id order: the rule visits only them.
    toggleable: Vec<ObjectId>,
}

impl Toggles {
    /// A switch and a count per object; the toggleables are objects.
    pub(crate) fn check_consistency(&self, n: usize) -> Result<(), String> {
        if self.on.len() != n
            || self.held_steps.len() != n
            || self.toggleable.iter().any(|id| id.0 as usize >= n)
        {
            return Err("toggling: tables disagree with the objects".into());
        }
        Ok(())
    }
}

impl Toggles {
    pub(crate) fn add_object(&mut self, id: ObjectId, object: &Object) {
        self.on.push(false);
        self.held_steps.push(0);
        if object.has(Ability::Toggleable) {
            self.toggleable.push(id);
        }
    }

    pub(crate) fn is_on(&self, id: ObjectId) -> bool {
        self.on[id.0 as usize]
    }

    pub(crate) fn set(&mut self, id: ObjectId, on: bool) {
        self.on[id.0 as usize] = on;
        self.held_steps[id.0 as usize] = 0;
    }

    /// Steps a hand has been held at the object's button.
    pub(crate) fn held_steps(&self, id: ObjectId) -> u32 {
        self.held_steps[id.0 as usize]
    }

    /// Puts back a saved switch and counter.
    pub(crate) fn restore(&mut self, id: ObjectId, on: bool, held_steps: u32) {
        self.on[id.0 as usize] = on;
        self.held_steps[id.0 as usize] = held_steps;
    }

    /// A half made by slicing starts with the whole's switch.
    pub(crate) fn inherit(&mut self, from: ObjectId, to: ObjectId) {
        self.on[to.0 as usize] = self.on[from.0 as usize];
    }

    pub(crate) fn set_hands(&mut self, points: &[Vector]) {
        self.hands = points.iter().copied().filter(|p| p.is_finite()).collect();
    }

    pub(crate) fn update(&mut self, core: &Core) {
        for &id in &self.toggleable {
            let object = core.bodies.object(id);
            if !object.is_present() {
                continue;
            }
            let Some(button) = object.point(PointKind::ToggleButton) else {
                continue;
            };
            let button = core.bodies.pose(id).transform_point(button);
            let near = self
                .hands
                .iter()
                .any(|h| (*h - button).length() <= TOGGLE_DISTANCE);
            let i = id.0 as usize;
            if near {
                self.held_steps[i] += 1;
                if self.held_steps[i] == TOGGLE_STEPS {
                    self.on[i] = !self.on[i];
                }
            } else {
                self.held_steps[i] = 0;
            }
        }
    }
}
