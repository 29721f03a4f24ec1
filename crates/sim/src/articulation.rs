//! Doors and drawers: joint positions, and `open`.
//!
//! A link's joint position is read from the pose of its body relative to the object's body:
//! the angle about the axis for a revolute joint, the displacement along it for a prismatic one.
//! An object is open when any joint is beyond 5 % of its range from closed (iGibson's
//! `_JOINT_THRESHOLD_BY_TYPE`).
//!
//! Link indices are positions in [`crate::world::Object::links`]; like slice indices, an index
//! out of range is a programming error and panics.

use crate::states::StateError;
use crate::world::{JointKind, ObjectId, World};
use rapier3d::math::{Pose, Rotation, Vector};

/// Fraction of a joint's range beyond which it counts as open.
pub const OPEN_FRACTION: f32 = 0.05;

impl World {
    /// The position of a link's joint: 0 when closed, the link's range when fully open.
    pub fn joint_position(&self, id: ObjectId, link: usize) -> f32 {
        let object = self.object(id);
        let l = &object.links[link];
        let base = self.physics.bodies[object.body].position();
        let moved = self.physics.bodies[l.body].position();
        let relative = base.inv_mul(moved);
        match l.kind {
            JointKind::Revolute => {
                let q = relative.rotation;
                let along = Vector::new(q.x, q.y, q.z).dot(l.axis);
                2.0 * along.atan2(q.w)
            }
            JointKind::Prismatic => relative.translation.dot(l.axis),
        }
    }

    /// Moves a link to a joint position (clamped to its range), at rest.
    pub fn set_joint_position(&mut self, id: ObjectId, link: usize, position: f32) {
        let object = self.object(id);
        let l = &object.links[link];
        let q = if position.is_finite() {
            position.clamp(0.0, l.range)
        } else {
            0.0
        };
        let base = *self.physics.bodies[object.body].position();
        let local = match l.kind {
            JointKind::Revolute => {
                let turn = Pose::from_rotation(Rotation::from_axis_angle(l.axis, q));
                Pose::from_translation(l.anchor) * turn * Pose::from_translation(-l.anchor)
            }
            JointKind::Prismatic => Pose::from_translation(l.axis * q),
        };
        let link_body = l.body;
        let body = &mut self.physics.bodies[link_body];
        body.set_position(base * local, true);
        body.set_linvel(Vector::ZERO, true);
        body.set_angvel(Vector::ZERO, true);
        self.moved(id);
        self.refresh();
    }

    /// Drives a link's joint toward a velocity (rad/s or m/s) with a motor of the given
    /// strength; velocity 0 with the link's damping is the default, passive state.
    pub fn set_joint_motor(&mut self, id: ObjectId, link: usize, velocity: f32, factor: f32) {
        let (velocity, factor) = if velocity.is_finite() && factor.is_finite() {
            (velocity, factor.max(0.0))
        } else {
            (0.0, 0.0)
        };
        let l = &self.object(id).links[link];
        let (handle, body, kind) = (l.joint, l.body, l.kind);
        if let Some(joint) = self.physics.impulse_joints.get_mut(handle, true) {
            let axis = match kind {
                JointKind::Revolute => rapier3d::dynamics::JointAxis::AngX,
                JointKind::Prismatic => rapier3d::dynamics::JointAxis::LinX,
            };
            joint.data.set_motor_velocity(axis, velocity, factor);
        }
        self.physics.bodies[body].wake_up(true);
        self.quiet = false;
    }

    pub fn is_open(&self, id: ObjectId) -> bool {
        let links = &self.object(id).links;
        (0..links.len()).any(|i| self.joint_position(id, i) > OPEN_FRACTION * links[i].range)
    }

    /// Opens every joint fully, or closes them all.
    pub(crate) fn set_open(&mut self, id: ObjectId, open: bool) -> Result<(), StateError> {
        let count = self.object(id).links.len();
        if count == 0 {
            return Err(StateError::NoJoints {
                object: self.object(id).name.clone(),
            });
        }
        for i in 0..count {
            let target = if open {
                self.object(id).links[i].range
            } else {
                0.0
            };
            self.set_joint_position(id, i, target);
        }
        Ok(())
    }
}
