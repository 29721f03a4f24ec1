//! Moving bodies by hand: velocities, forces, torques and impulses, and the targets of kinematic
//! bodies. This is how controllers act, usually from [`crate::StepHooks::before_substep`].
//!
//! Forces and torques act for the rest of the current action step (every remaining substep) and
//! are then cleared, so a controller states each step what it pushes with. Impulses act at once.

use crate::bodies::Bodies;
use crate::core::{WorldError, pose_is_finite};
use crate::object::{BodyKind, BodyRef, JointHandle, Object, ObjectId};
use rapier3d::dynamics::{MultibodyJointHandle, RigidBody};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// A body's velocity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Velocity {
    /// m/s, of its centre of mass, in the world frame.
    pub linear: Vector,
    /// rad/s, in the world frame.
    pub angular: Vector,
}

fn finite(what: &'static str, v: Vector) -> Result<(), WorldError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(WorldError::NotFinite {
            what,
            value: v.x + v.y + v.z,
        })
    }
}

impl Bodies {
    /// A body's velocity.
    pub fn velocity(&self, body: BodyRef) -> Result<Velocity, WorldError> {
        let handle = self.handle(body)?;
        if let (None, Some(&carried)) = (body.link, self.carried.get(&body.object)) {
            return Ok(carried);
        }
        let b = &self.physics.bodies[handle];
        Ok(Velocity {
            linear: b.linvel(),
            angular: b.angvel(),
        })
    }

    /// Where a body's centre of mass is, in the world frame: the point whose velocity
    /// [`Velocity::linear`] is.
    pub fn centre_of_mass(&self, body: BodyRef) -> Result<Vector, WorldError> {
        let handle = self.handle(body)?;
        Ok(self.physics.bodies[handle].center_of_mass())
    }

    /// Sets a dynamic or velocity-driven kinematic body's velocity, waking it.
    pub fn set_velocity(&mut self, body: BodyRef, velocity: Velocity) -> Result<(), WorldError> {
        finite("a linear velocity", velocity.linear)?;
        finite("an angular velocity", velocity.angular)?;
        let handle = self.handle(body)?;
        let b = &mut self.physics.bodies[handle];
        b.set_linvel(velocity.linear, true);
        b.set_angvel(velocity.angular, true);
        if body.link.is_none() && self.leads_chain(body.object) == Some(BodyKind::KinematicVelocity)
        {
            self.carried.insert(body.object, velocity);
        }
        self.wake(handle);
        Ok(())
    }

    /// Moves one of the parts of an object's body (not of a link) to a new pose in the object's
    /// frame. This is for parts a controller animates without joints of their own, such as a
    /// BehaviorRobot's fingers: no body and no joint for the solver to pay for, at the price that
    /// the part goes exactly where it is put and does not yield — what it now overlaps is pushed
    /// apart by contacts, moving whichever side is free to move. The body's mass properties
    /// follow the parts (rapier recomputes them), and [`crate::Object::parts`] reports the new
    /// pose at once; contacts and queries see it from the next substep on.
    pub fn set_part_offset(
        &mut self,
        object: ObjectId,
        part: usize,
        offset: Pose,
    ) -> Result<(), WorldError> {
        let o = self.object(object);
        if part >= o.parts.len() {
            return Err(WorldError::BadObject {
                name: o.name.clone(),
                reason: format!("no part {part}: its body has {}", o.parts.len()),
            });
        }
        if !pose_is_finite(&offset) {
            return Err(WorldError::NotFinite {
                what: "a part's offset",
                value: f32::NAN,
            });
        }
        // The body's parts come first among the object's colliders, in order.
        let collider = o.colliders[part];
        let body = o.body;
        self.objects[object.0 as usize].parts[part].offset = offset;
        if let Some(c) = self.physics.colliders.get_mut(collider) {
            c.set_position_wrt_parent(offset);
        }
        self.index.clear_moving();
        self.wake(body);
        Ok(())
    }

    /// Where a position-driven kinematic body must be at the end of the next substep; it moves
    /// there with the velocity that takes, pushing what is in the way.
    pub fn set_kinematic_target(&mut self, body: BodyRef, pose: Pose) -> Result<(), WorldError> {
        if !pose_is_finite(&pose) {
            return Err(WorldError::NotFinite {
                what: "a kinematic target",
                value: f32::NAN,
            });
        }
        let kind = self.object(body.object).body_kind;
        if body.link.is_some() || kind != BodyKind::KinematicPosition {
            return Err(WorldError::BadObject {
                name: self.object(body.object).name.clone(),
                reason: format!(
                    "only a {:?} body takes pose targets; this one is {kind:?}",
                    BodyKind::KinematicPosition
                ),
            });
        }
        let handle = self.handle(body)?;
        self.physics.bodies[handle].set_next_kinematic_position(pose);
        self.wake(handle);
        Ok(())
    }

    /// Pushes a body's centre of mass with a force (N) for the rest of this action step.
    pub fn apply_force(&mut self, body: BodyRef, force: Vector) -> Result<(), WorldError> {
        finite("a force", force)?;
        self.push_for_the_step(body, |b| b.add_force(force, true))
    }

    /// Pushes a body at a world point with a force (N) for the rest of this action step.
    pub fn apply_force_at(
        &mut self,
        body: BodyRef,
        force: Vector,
        point: Vector,
    ) -> Result<(), WorldError> {
        finite("a force", force)?;
        finite("a point", point)?;
        self.push_for_the_step(body, |b| b.add_force_at_point(force, point, true))
    }

    /// Twists a body with a torque (N·m, world frame) for the rest of this action step.
    pub fn apply_torque(&mut self, body: BodyRef, torque: Vector) -> Result<(), WorldError> {
        finite("a torque", torque)?;
        self.push_for_the_step(body, |b| b.add_torque(torque, true))
    }

    /// Applies a force or torque that lasts until the end of the action step.
    fn push_for_the_step(
        &mut self,
        body: BodyRef,
        apply: impl FnOnce(&mut RigidBody),
    ) -> Result<(), WorldError> {
        let handle = self.handle(body)?;
        apply(&mut self.physics.bodies[handle]);
        self.pushed.push(handle);
        self.wake(handle);
        Ok(())
    }

    /// Gives a body's centre of mass an impulse (N·s), changing its velocity at once.
    pub fn apply_impulse(&mut self, body: BodyRef, impulse: Vector) -> Result<(), WorldError> {
        finite("an impulse", impulse)?;
        let handle = self.handle(body)?;
        self.physics.bodies[handle].apply_impulse(impulse, true);
        self.wake(handle);
        Ok(())
    }

    /// Before a substep: a kinematic body at the root of a multibody chain (a robot's base
    /// carrying its arm) would be held in place by the chain, which writes its root's pose and
    /// velocity back from its own record; so the body and the record are both moved first to
    /// where the body goes this substep (by its pose target, or by the velocity kept in
    /// `carried`).
    pub(crate) fn lead_kinematic_chains(&mut self) {
        let dt = self.physics.integration_parameters.dt;
        for (i, object) in self.objects.iter().enumerate() {
            // Most objects are not kinematic: the cheap test first.
            let kind = object.body_kind;
            let kinematic = matches!(
                kind,
                BodyKind::KinematicPosition | BodyKind::KinematicVelocity
            );
            let Some(chain) = first_chain(object).filter(|_| kinematic) else {
                continue;
            };
            let id = ObjectId(i as u32);
            let body = &self.physics.bodies[object.body];
            let target = match kind {
                BodyKind::KinematicVelocity => {
                    let v = self.carried.get(&id).copied().unwrap_or_default();
                    let p = body.position();
                    let turn = Rotation::from_scaled_axis(v.angular * dt);
                    let rotation = (turn * p.rotation).normalize();
                    Pose::from_parts(p.translation + v.linear * dt, rotation)
                }
                _ => *body.next_position(),
            };
            self.physics.bodies[object.body].set_position(target, true);
            if let Some((multibody, _)) = self.physics.multibody_joints.get_mut(chain) {
                multibody.root_mut().joint.data.local_frame1 = target;
            }
        }
    }

    /// The kind of a kinematic body that roots a multibody chain.
    fn leads_chain(&self, id: ObjectId) -> Option<BodyKind> {
        let object = self.object(id);
        let kinematic = matches!(
            object.body_kind,
            BodyKind::KinematicPosition | BodyKind::KinematicVelocity
        );
        (kinematic && first_chain(object).is_some()).then_some(object.body_kind)
    }

    /// Clears the forces and torques of the step just taken.
    pub(crate) fn clear_forces(&mut self) {
        for handle in std::mem::take(&mut self.pushed) {
            if let Some(b) = self.physics.bodies.get_mut(handle) {
                b.reset_forces(false);
                b.reset_torques(false);
            }
        }
    }
}

/// The handle of an object's first multibody link, if it has a chain.
fn first_chain(object: &Object) -> Option<MultibodyJointHandle> {
    object.links.iter().find_map(|l| match l.handle {
        JointHandle::Multibody(h) => Some(h),
        JointHandle::Impulse(_) => None,
    })
}
