//! Joints: positions, velocities and efforts, teleporting a joint to a position, drives (position
//! and velocity motors), and `open`.
//!
//! A joint's position is read from the pose of its link relative to its parent (the object's body
//! or an earlier link): the angle about the axis for a revolute joint, the displacement along it for
//! a prismatic one — the same reading for impulse and multibody joints, since both start at zero
//! with the link where the spec put it. An object is open when any joint with limits is beyond
//! 5 % of its range from its lower limit (iGibson's `_JOINT_THRESHOLD_BY_TYPE`).
//!
//! Efforts: rapier does not report the impulses of multibody motors, so a joint's effort is what
//! its drive commands at the current state — `stiffness·(target − q) + damping·(v_target − v)`,
//! clamped to the drive's maximum force (N or N·m) — or, without a drive, its passive damping
//! torque. For a single driven joint this is the torque the solver applies (a test holds a bar
//! against gravity and reads its weight's moment to 1 %). In a chain it is only approximate:
//! rapier solves the chain's motors together in 4 iterations without warm starting, so the
//! settled errors, and with them the commanded efforts, differ from the loads — measured on a
//! horizontal 3-link arm at stiffness 2,000 N·m/rad: 1.16×, 1.42× and 0.68× the gravity moments
//! from shoulder to wrist (1.01×, 1.04×, 0.97× with 4 internal solver iterations, which would cost
//! every scene), and 3.0× at the shoulder of the same arm bent to (0.5, −0.3, 0.4) rad. Choosing
//! the solver settings for robots belongs with the robots and their benchmark.

use crate::bodies::Bodies;
use crate::core::{Core, WorldError};
use crate::object::{BodyRef, JointHandle, JointKind, JointSpec, ObjectId};
use crate::states::StateError;
use behavior_core::rng::{SimRng, uniform};
use rand_chacha::rand_core::Rng;
use rapier3d::dynamics::{GenericJoint, JointAxis, MotorModel};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Fraction of a joint's range beyond which it counts as open.
pub const OPEN_FRACTION: f32 = 0.05;

/// A joint's state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct JointState {
    /// Radians or metres.
    pub position: f32,
    /// Radians or metres per second.
    pub velocity: f32,
    /// N·m or N: what its drive applies now (see the module docs).
    pub effort: f32,
}

/// A motor on a joint: toward a position (a spring-damper) and/or a velocity, with a force limit.
/// Gains are physical (N·m/rad and N·m·s/rad, or N/m and N·s/m).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Drive {
    /// The position it pulls toward, if any.
    pub target_position: Option<f32>,
    /// The velocity it drives toward.
    pub target_velocity: f32,
    /// Pull per unit of position error.
    pub stiffness: f32,
    /// Pull per unit of velocity error.
    pub damping: f32,
    /// The most it applies (N·m or N).
    pub max_force: f32,
}

impl Drive {
    /// A position servo, as a robot's arm joint: `stiffness` toward `target`, `damping` against
    /// motion, at most `max_force`.
    pub fn position(target: f32, stiffness: f32, damping: f32, max_force: f32) -> Drive {
        Drive {
            target_position: Some(target),
            target_velocity: 0.0,
            stiffness,
            damping,
            max_force,
        }
    }

    /// A velocity motor, as a wheel: `damping` toward `velocity`, at most `max_force`.
    pub fn velocity(velocity: f32, damping: f32, max_force: f32) -> Drive {
        Drive {
            target_position: None,
            target_velocity: velocity,
            stiffness: 0.0,
            damping,
            max_force,
        }
    }

    fn is_valid(&self) -> bool {
        let non_negative = |x: f32| x.is_finite() && x >= 0.0;
        self.target_position.is_none_or(f32::is_finite)
            && self.target_velocity.is_finite()
            && non_negative(self.stiffness)
            && non_negative(self.damping)
            && non_negative(self.max_force)
    }

    /// What the motor law applies at position `q` and velocity `v`.
    fn effort(&self, q: f32, v: f32) -> f32 {
        let spring = self
            .target_position
            .map_or(0.0, |t| self.stiffness * (t - q));
        (spring + self.damping * (self.target_velocity - v)).clamp(-self.max_force, self.max_force)
    }
}

/// The rapier axis a joint kind moves along.
pub(crate) fn free_axis(kind: JointKind) -> Option<JointAxis> {
    match kind {
        JointKind::Revolute => Some(JointAxis::AngX),
        JointKind::Prismatic => Some(JointAxis::LinX),
        JointKind::Fixed => None,
    }
}

/// The drives set on joints, by object and link: what [`Joints::state`] reports the effort of.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(transparent)]
pub(crate) struct Drives(BTreeMap<(ObjectId, usize), Drive>);

impl Drives {
    /// The driven links, for checking a decoded world.
    pub(crate) fn links(&self) -> impl Iterator<Item = &(ObjectId, usize)> {
        self.0.keys()
    }
}

/// The joints, for reading: positions, velocities, efforts, and `open`. Reached through
/// [`crate::World::joints`].
#[derive(Clone, Copy)]
pub struct Joints<'w> {
    pub(crate) bodies: &'w Bodies,
    pub(crate) drives: &'w Drives,
}

/// The joints, for acting on them: teleporting a joint to a position, drives. Reached through
/// [`crate::World::joints_mut`].
pub struct JointsMut<'w> {
    pub(crate) bodies: &'w mut Bodies,
    pub(crate) drives: &'w mut Drives,
}

impl<'w> Joints<'w> {
    pub(crate) fn new(core: &'w Core) -> Joints<'w> {
        Joints {
            bodies: &core.bodies,
            drives: &core.drives,
        }
    }

    /// The position of a link's joint: 0 where the spec put it, the upper limit fully open.
    /// Panics if the link does not exist; see [`Joints::state`] for a checked reading.
    pub fn position(&self, id: ObjectId, link: usize) -> f32 {
        position(self.bodies, id, link)
    }

    /// Position, velocity and effort of a link's joint.
    pub fn state(&self, id: ObjectId, link: usize) -> Result<JointState, WorldError> {
        check_link(self.bodies, id, link)?;
        let l = &self.bodies.object(id).links[link];
        let position = position(self.bodies, id, link);
        let velocity = velocity(self.bodies, id, link);
        let effort = match self.drives.0.get(&(id, link)) {
            Some(drive) => drive.effort(position, velocity),
            None => -l.joint.damping * velocity,
        };
        Ok(JointState {
            position,
            velocity,
            effort,
        })
    }

    /// Whether any joint with limits is beyond [`OPEN_FRACTION`] of its range.
    pub fn is_open(&self, id: ObjectId) -> bool {
        let links = &self.bodies.object(id).links;
        links.iter().enumerate().any(|(i, l)| {
            l.joint.limits.is_some_and(|[lo, hi]| {
                position(self.bodies, id, i) - lo > OPEN_FRACTION * (hi - lo)
            })
        })
    }
}

impl<'w> JointsMut<'w> {
    pub(crate) fn new(core: &'w mut Core) -> JointsMut<'w> {
        JointsMut {
            bodies: &mut core.bodies,
            drives: &mut core.drives,
        }
    }

    /// Moves a link to a joint position (clamped to its limits), at rest, keeping its children
    /// where they are relative to it.
    pub fn set_position(
        &mut self,
        id: ObjectId,
        link: usize,
        position: f32,
    ) -> Result<(), WorldError> {
        check_link(self.bodies, id, link)?;
        if !position.is_finite() {
            return Err(WorldError::NotFinite {
                what: "a joint position",
                value: position,
            });
        }
        let joint = &self.bodies.object(id).links[link].joint;
        let q = joint
            .limits
            .map_or(position, |[lo, hi]| position.clamp(lo, hi));
        let old = self.bodies.link_pose(id, link);
        let new = parent_pose(self.bodies, id, link) * displacement(joint, q);
        // The link's descendants keep their pose relative to it.
        let mut moves = vec![(link, new)];
        for i in (link + 1..self.bodies.object(id).links.len())
            .filter(|&i| descends_from(self.bodies, id, i, link))
        {
            moves.push((i, new * old.inv_mul(&self.bodies.link_pose(id, i))));
        }
        for (i, pose) in moves {
            let handle = self.bodies.object(id).links[i].body;
            let body = &mut self.bodies.physics.bodies[handle];
            body.set_position(pose, true);
            body.set_linvel(Vector::ZERO, true);
            body.set_angvel(Vector::ZERO, true);
        }
        self.set_multibody_coordinate(id, link, q);
        self.bodies.moved(id);
        self.bodies.refresh();
        Ok(())
    }

    /// A multibody keeps its own joint coordinates: a teleported joint must be told.
    fn set_multibody_coordinate(&mut self, id: ObjectId, link: usize, q: f32) {
        let JointHandle::Multibody(handle) = self.bodies.object(id).links[link].handle else {
            return;
        };
        let physics = &mut self.bodies.physics;
        if let Some((multibody, index)) = physics.multibody_joints.get_mut(handle) {
            let current = self::coordinate(multibody.link(index).map(|l| &l.joint));
            if let Some(current) = current {
                let ndofs = multibody.ndofs();
                let mut displacement = vec![0.0; ndofs];
                let offset = multibody.link(index).map_or(0, |l| l.assembly_id());
                if offset < ndofs {
                    displacement[offset] = q - current;
                    multibody.apply_displacements(&displacement);
                }
            }
            multibody.generalized_velocity_mut().fill(0.0);
            multibody.forward_kinematics(&physics.bodies, true);
            multibody.update_rigid_bodies(&mut physics.bodies, false);
        }
    }

    /// Sets a drive on a link's joint (replacing any earlier one) until [`JointsMut::release`].
    pub fn drive(&mut self, id: ObjectId, link: usize, drive: Drive) -> Result<(), WorldError> {
        check_link(self.bodies, id, link)?;
        if !drive.is_valid() {
            return Err(WorldError::BadObject {
                name: self.bodies.object(id).name.clone(),
                reason: format!(
                    "the drive of link {link} has a non-finite or negative value: {drive:?}"
                ),
            });
        }
        let l = &self.bodies.object(id).links[link];
        let Some(axis) = free_axis(l.joint.kind) else {
            return Err(WorldError::BadObject {
                name: self.bodies.object(id).name.clone(),
                reason: format!("link {link} is on a fixed joint and cannot be driven"),
            });
        };
        let (handle, body) = (l.handle, l.body);
        self.with_joint(handle, |joint| {
            joint.set_motor_model(axis, MotorModel::ForceBased);
            joint.set_motor(
                axis,
                drive.target_position.unwrap_or(0.0),
                drive.target_velocity,
                drive.stiffness,
                drive.damping,
            );
            joint.set_motor_max_force(axis, drive.max_force);
        });
        self.drives.0.insert((id, link), drive);
        self.bodies.wake(body);
        Ok(())
    }

    /// Takes a joint's drive off: it goes back to its passive damping.
    pub fn release(&mut self, id: ObjectId, link: usize) -> Result<(), WorldError> {
        check_link(self.bodies, id, link)?;
        let l = &self.bodies.object(id).links[link];
        let (handle, body, damping) = (l.handle, l.body, l.joint.damping);
        if let Some(axis) = free_axis(l.joint.kind) {
            self.with_joint(handle, |joint| passive(joint, axis, damping));
        }
        self.drives.0.remove(&(id, link));
        self.bodies.wake(body);
        Ok(())
    }

    fn with_joint(&mut self, handle: JointHandle, change: impl FnOnce(&mut GenericJoint)) {
        match handle {
            JointHandle::Impulse(h) => {
                if let Some(joint) = self.bodies.physics.impulse_joints.get_mut(h, true) {
                    change(&mut joint.data);
                }
            }
            JointHandle::Multibody(h) => {
                if let Some((multibody, index)) = self.bodies.physics.multibody_joints.get_mut(h)
                    && let Some(link) = multibody.link_mut(index)
                {
                    change(&mut link.joint.data);
                }
            }
        }
    }

    /// Opens a random non-empty set of the joints with limits, each to a random position between
    /// the open threshold and its open end (as iGibson's setter) — all the way for a joint
    /// gravity would close, a lid or an oven door, which rests open only against its limit — or
    /// closes them all fully.
    pub(crate) fn set_open(
        &mut self,
        id: ObjectId,
        open: bool,
        rng: &mut SimRng,
    ) -> Result<(), StateError> {
        let limited: Vec<(usize, [f32; 2], bool)> = self
            .bodies
            .object(id)
            .links
            .iter()
            .enumerate()
            .filter_map(|(i, l)| l.joint.limits.map(|limits| (i, limits, lifts(&l.joint))))
            .collect();
        if limited.is_empty() {
            return Err(StateError::NoJoints {
                object: self.bodies.object(id).name.clone(),
            });
        }
        let chosen = if open {
            random_subset(limited.len(), rng)
        } else {
            vec![true; limited.len()]
        };
        for (&(i, [lo, hi], lifted), opened) in limited.iter().zip(chosen) {
            let target = match (open, opened) {
                (false, _) => lo,
                (true, false) => continue,
                // A lid gravity would shut rests open only against its limit.
                (true, true) if lifted => hi,
                // Just beyond the threshold at least, so the draw always reads as open.
                (true, true) => lo + (hi - lo) * uniform(rng, OPEN_FRACTION + 0.01, 1.0),
            };
            // The link exists and the target is finite: this cannot fail.
            let _ = self.set_position(id, i, target);
        }
        Ok(())
    }
}

fn check_link(bodies: &Bodies, id: ObjectId, link: usize) -> Result<(), WorldError> {
    bodies.handle(BodyRef::link(id, link)).map(|_| ())
}

/// The pose of a link's parent body.
fn parent_pose(bodies: &Bodies, id: ObjectId, link: usize) -> Pose {
    match bodies.object(id).links[link].parent {
        None => bodies.pose(id),
        Some(p) => bodies.link_pose(id, p),
    }
}

/// The position of a link's joint: 0 where the spec put it, the upper limit fully open.
/// Panics if the link does not exist; see [`Joints::state`] for a checked reading.
fn position(bodies: &Bodies, id: ObjectId, link: usize) -> f32 {
    let l = &bodies.object(id).links[link];
    let relative = parent_pose(bodies, id, link).inv_mul(&bodies.link_pose(id, link));
    match l.joint.kind {
        JointKind::Revolute => {
            let q = relative.rotation;
            let along = Vector::new(q.x, q.y, q.z).dot(l.joint.axis);
            2.0 * along.atan2(q.w)
        }
        JointKind::Prismatic => relative.translation.dot(l.joint.axis),
        JointKind::Fixed => 0.0,
    }
}

fn velocity(bodies: &Bodies, id: ObjectId, link: usize) -> f32 {
    let l = &bodies.object(id).links[link];
    let parent = match l.parent {
        None => bodies.object(id).body,
        Some(p) => bodies.object(id).links[p].body,
    };
    let (pb, cb) = (
        &bodies.physics.bodies[parent],
        &bodies.physics.bodies[l.body],
    );
    let axis = pb.position().rotation * l.joint.axis;
    match l.joint.kind {
        JointKind::Revolute => (cb.angvel() - pb.angvel()).dot(axis),
        JointKind::Prismatic => {
            let at = cb.center_of_mass();
            (cb.linvel() - pb.velocity_at_point(at)).dot(axis)
        }
        JointKind::Fixed => 0.0,
    }
}

fn descends_from(bodies: &Bodies, id: ObjectId, link: usize, ancestor: usize) -> bool {
    let links = &bodies.object(id).links;
    let mut at = links[link].parent;
    while let Some(p) = at {
        if p == ancestor {
            return true;
        }
        at = links[p].parent;
    }
    false
}

fn lifts(joint: &JointSpec) -> bool {
    match joint.kind {
        JointKind::Revolute => joint.axis.z.abs() < 0.9,
        JointKind::Prismatic => joint.axis.z.abs() > 0.1,
        JointKind::Fixed => false,
    }
}

/// A random non-empty subset of `n` items, as flags.
fn random_subset(n: usize, rng: &mut SimRng) -> Vec<bool> {
    loop {
        let flags: Vec<bool> = (0..n).map(|_| rng.next_u32() & 1 == 1).collect();
        if flags.iter().any(|&f| f) {
            return flags;
        }
    }
}

/// Where a joint at position `q` puts its link relative to the link's place at zero, in the
/// parent's frame.
fn displacement(joint: &JointSpec, q: f32) -> Pose {
    match joint.kind {
        JointKind::Revolute => {
            let turn = Pose::from_rotation(Rotation::from_axis_angle(joint.axis, q));
            Pose::from_translation(joint.anchor) * turn * Pose::from_translation(-joint.anchor)
        }
        JointKind::Prismatic => Pose::from_translation(joint.axis * q),
        JointKind::Fixed => Pose::IDENTITY,
    }
}

/// A joint's passive state: a velocity motor toward 0 of factor `damping`, or no motor at all
/// (a motor with zero gains would lock the joint rigidly).
pub(crate) fn passive(joint: &mut GenericJoint, axis: JointAxis, damping: f32) {
    joint.set_motor_model(axis, MotorModel::AccelerationBased);
    joint.set_motor(axis, 0.0, 0.0, 0.0, damping);
    let max_force = if damping > 0.0 { f32::MAX } else { 0.0 };
    joint.set_motor_max_force(axis, max_force);
}

/// A one-degree-of-freedom multibody joint's coordinate.
fn coordinate(joint: Option<&rapier3d::dynamics::MultibodyJoint>) -> Option<f32> {
    let joint = joint?;
    let coords = joint.coords();
    Some(
        if joint
            .data
            .locked_axes
            .contains(rapier3d::dynamics::JointAxesMask::LIN_X)
        {
            // Revolute: the angle is the first angular coordinate.
            coords[3]
        } else {
            coords[0]
        },
    )
}
