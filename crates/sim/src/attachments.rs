//! Attachments: a constraint added at run time between two bodies at a point, as assisted
//! grasping makes between a hand and what it holds (iGibson 2.0: a fixed constraint of at most
//! 500 N, or point-to-point for a link of articulated furniture, released when its violation
//! exceeds 0.1 m — iGibson 2.0.3's `robots/behavior_robot.py`).
//!
//! An attachment pulls with at most its maximum force: rapier's joints have no force limit, so the
//! world reads the force each constraint applied in every substep and removes one that needed
//! more in half the substeps of the last action step's length (1/30 s), which then reports as
//! broken. PyBullet's force-limited constraint rides out a shorter overload with a lag of
//! millimetres, far below the 0.1 m at which the original lets go; broken at the first
//! substep over, Fetch dropped a carton whose lid met its hinge's limit on the way, in a drive
//! that touched nothing. Contacts between the two bodies are off while attached (a
//! hand does not push what it holds). Its violation — how far apart its two anchor points have
//! drifted — is the caller's to watch: a robot releases past its own threshold.

use crate::bodies::Bodies;
use crate::core::{Core, WorldError};
use crate::object::BodyRef;
use rapier3d::dynamics::{
    FixedJointBuilder, GenericJoint, ImpulseJointHandle, SphericalJointBuilder,
};
use rapier3d::math::{Pose, Vector};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Identifies an attachment for the world's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct AttachmentId(pub u64);

/// How an attachment holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum AttachmentKind {
    /// Keeps the two bodies' relative pose (a grasp).
    Fixed,
    /// Keeps one point of each together; they may turn about it (a handle of a door).
    Point,
}

/// What to attach.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AttachmentSpec {
    /// The holder (a hand).
    pub holder: BodyRef,
    /// What it holds.
    pub held: BodyRef,
    /// The point where they are joined, in the world, now.
    pub at: Vector,
    /// Fixed or point-to-point.
    pub kind: AttachmentKind,
    /// The largest force it may apply (N): needing more for half an action step, it breaks.
    pub max_force: f32,
}

/// An attachment's condition after the last step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AttachmentState {
    /// As it was made.
    pub spec: AttachmentSpec,
    /// The force it applied in the last substep (N).
    pub force: f32,
    /// How far apart its anchor points are now or were at most in the last step, before each
    /// substep's solve (m).
    pub violation: f32,
    /// It needed more than its maximum force and was removed.
    pub broken: bool,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct Record {
    spec: AttachmentSpec,
    joint: Option<ImpulseJointHandle>,
    /// The joining point in each body's frame.
    local: [Vector; 2],
    force: f32,
    /// The substeps it needed more than its maximum force in, the last in the lowest bit.
    #[serde(default)]
    overloaded: u32,
    /// The farthest its anchors were apart before a substep's solve in the last step.
    #[serde(default)]
    drift: f32,
}

/// The attachments of a world.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct AttachmentSet {
    records: BTreeMap<AttachmentId, Record>,
    next: u64,
}

impl AttachmentSet {
    /// Whether every attachment names known bodies and, unless broken, a joint in the physics.
    pub(crate) fn check_consistency(
        &self,
        body_known: impl Fn(BodyRef) -> bool,
        joint_known: impl Fn(ImpulseJointHandle) -> bool,
    ) -> Result<(), String> {
        let bad = self.records.iter().find(|(_, r)| {
            !body_known(r.spec.holder)
                || !body_known(r.spec.held)
                || r.joint.is_some_and(|j| !joint_known(j))
        });
        match bad {
            Some((id, _)) => Err(format!("attachment {} names a missing body or joint", id.0)),
            None if self.records.keys().any(|id| id.0 >= self.next) => {
                Err("an attachment id beyond the next one".into())
            }
            None => Ok(()),
        }
    }
}

/// The attachments, for reading. Reached through [`crate::World::attachments`].
#[derive(Clone, Copy)]
pub struct Attachments<'w> {
    pub(crate) bodies: &'w Bodies,
    pub(crate) set: &'w AttachmentSet,
}

/// The attachments, for making and removing them. Reached through
/// [`crate::World::attachments_mut`].
pub struct AttachmentsMut<'w> {
    pub(crate) bodies: &'w mut Bodies,
    pub(crate) set: &'w mut AttachmentSet,
}

impl<'w> AttachmentsMut<'w> {
    pub(crate) fn new(core: &'w mut Core) -> AttachmentsMut<'w> {
        AttachmentsMut {
            bodies: &mut core.bodies,
            set: &mut core.attachments,
        }
    }

    /// Joins two bodies at a point (see the module docs); contacts between them are off until
    /// [`AttachmentsMut::detach`] or until it breaks.
    pub fn attach(&mut self, spec: AttachmentSpec) -> Result<AttachmentId, WorldError> {
        let bodies = &mut *self.bodies;
        if !(spec.at.is_finite() && spec.max_force.is_finite() && spec.max_force > 0.0) {
            return Err(WorldError::NotFinite {
                what: "an attachment's point and positive maximum force",
                value: spec.max_force,
            });
        }
        if spec.holder == spec.held {
            return Err(WorldError::BadObject {
                name: bodies.object(spec.holder.object).name.clone(),
                reason: "a body cannot be attached to itself".into(),
            });
        }
        let (h1, h2) = (bodies.handle(spec.holder)?, bodies.handle(spec.held)?);
        let (p1, p2) = (bodies.body_pose(spec.holder)?, bodies.body_pose(spec.held)?);
        let local = [
            p1.inverse_transform_point(spec.at),
            p2.inverse_transform_point(spec.at),
        ];
        let joint: GenericJoint = match spec.kind {
            AttachmentKind::Fixed => {
                // Frames that coincide now: the relative pose is kept as it is.
                let frame1 = Pose::from_translation(local[0]);
                let frame2 = p2.inv_mul(&(p1 * frame1));
                FixedJointBuilder::new()
                    .local_frame1(frame1)
                    .local_frame2(frame2)
                    .contacts_enabled(false)
                    .build()
                    .into()
            }
            AttachmentKind::Point => SphericalJointBuilder::new()
                .local_anchor1(local[0])
                .local_anchor2(local[1])
                .contacts_enabled(false)
                .build()
                .into(),
        };
        let handle = bodies.physics.insert_impulse_joint(h1, h2, joint);
        let id = AttachmentId(self.set.next);
        self.set.next += 1;
        self.set.records.insert(
            id,
            Record {
                spec,
                joint: Some(handle),
                local,
                force: 0.0,
                overloaded: 0,
                drift: 0.0,
            },
        );
        bodies.wake(h1);
        bodies.wake(h2);
        Ok(id)
    }

    /// Removes an attachment (broken or not); `false` if there was none by that id.
    pub fn detach(&mut self, id: AttachmentId) -> bool {
        let Some(record) = self.set.records.remove(&id) else {
            return false;
        };
        if let Some(joint) = record.joint {
            self.bodies.physics.impulse_joints.remove(joint, true);
        }
        self.bodies.quiet = false;
        true
    }
}

impl<'w> Attachments<'w> {
    pub(crate) fn new(core: &'w Core) -> Attachments<'w> {
        Attachments {
            bodies: &core.bodies,
            set: &core.attachments,
        }
    }

    /// An attachment's condition, or `None` if it was detached.
    pub fn get(&self, id: AttachmentId) -> Option<AttachmentState> {
        let record = self.set.records.get(&id)?;
        Some(AttachmentState {
            spec: record.spec,
            force: record.force,
            violation: record.gap(self.bodies).max(record.drift),
            broken: record.joint.is_none(),
        })
    }

    /// Where an attachment's two anchor points are now in the world, the holder's first, or
    /// `None` if it was detached: the point a hand pulls a door by, to move it along the
    /// door's arc.
    pub fn anchors(&self, id: AttachmentId) -> Option<[Vector; 2]> {
        let record = self.set.records.get(&id)?;
        let at = |body: BodyRef, local: Vector| {
            self.bodies
                .body_pose(body)
                .ok()
                .map(|p| p.transform_point(local))
        };
        Some([
            at(record.spec.holder, record.local[0])?,
            at(record.spec.held, record.local[1])?,
        ])
    }
}

impl Record {
    /// How far apart the attachment's two anchor points are now.
    fn gap(&self, bodies: &Bodies) -> f32 {
        let at =
            |body: BodyRef, local: Vector| bodies.body_pose(body).map(|p| p.transform_point(local));
        match (
            at(self.spec.holder, self.local[0]),
            at(self.spec.held, self.local[1]),
        ) {
            (Ok(a), Ok(b)) => (a - b).length(),
            _ => f32::INFINITY,
        }
    }
}

impl AttachmentSet {
    /// Before a substep's solve: notes how far apart each attachment's anchors are, from the
    /// step's first substep on. A force-limited constraint would leave a held object taken
    /// 0.5 m away that far and let go; ours pulls it back within the substep, so the drift is
    /// read before the solve.
    pub(crate) fn note_drift(&mut self, bodies: &Bodies, substep: u32) {
        for record in self.records.values_mut() {
            let gap = record.gap(bodies);
            record.drift = if substep == 0 {
                gap
            } else {
                record.drift.max(gap)
            };
        }
    }

    /// After a substep: records each attachment's force and breaks those that needed too much
    /// in half the substeps of the last action step's length (see the module docs).
    pub(crate) fn watch(&mut self, bodies: &mut Bodies) {
        let substeps = bodies.substeps.count();
        let window = (1u32 << substeps) - 1;
        // Joint impulses are those of the solver's last internal iteration, which spans
        // dt / iterations.
        let params = &bodies.physics.integration_parameters;
        let dt = params.dt / params.num_solver_iterations.max(1) as f32;
        for record in self.records.values_mut() {
            let Some(handle) = record.joint else { continue };
            let Some(joint) = bodies.physics.impulse_joints.get(handle) else {
                record.joint = None;
                continue;
            };
            let i = joint.impulses;
            record.force = Vector::new(i[0], i[1], i[2]).length() / dt;
            let over = u32::from(record.force > record.spec.max_force);
            record.overloaded = (record.overloaded << 1) | over;
            if 2 * (record.overloaded & window).count_ones() >= substeps {
                bodies.physics.impulse_joints.remove(handle, true);
                record.joint = None;
            }
        }
    }
}
