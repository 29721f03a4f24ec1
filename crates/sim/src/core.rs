//! The world's core: the aggregate of its geometric parts (bodies, rooms, relations' memo,
//! attachments, ignored contacts, drives), its checkpoint form, and what they share — the step's
//! length, substeps, errors, and the tags that map rapier's bodies and colliders to objects.
//!
//! The state systems ([`crate::states`]) own everything beyond this; the core knows nothing of
//! temperature, water, dirt or toggling.

use crate::attachments::AttachmentSet;
use crate::bodies::Bodies;
use crate::contacts::IgnoredPairs;
use crate::dynamics::Velocity;
use crate::joints::Drives;
use crate::kinematics::RelationMemo;
use crate::object::{BodyRef, JointHandle, Object, ObjectId};
use crate::query::QueryIndex;
use crate::room::Room;
use rapier3d::dynamics::RigidBodyHandle;
use rapier3d::math::Pose;
use rapier3d::pipeline::PhysicsWorld;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// One action step, in seconds.
pub const STEP_SECONDS: f32 = 1.0 / 30.0;

/// `user_data` of water drops' bodies and colliders, which belong to no object.
pub(crate) const DROP_TAG: u128 = u128::MAX;

/// How finely each action step is integrated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Substeps {
    /// 10 substeps of 1/300 s: stable stacking of small objects.
    #[default]
    Hz300,
    /// 4 substeps of 1/120 s: faster, for scenes without small stacked objects.
    Hz120,
}

impl Substeps {
    /// Physics substeps per action step.
    pub fn count(self) -> u32 {
        match self {
            Substeps::Hz300 => 10,
            Substeps::Hz120 => 4,
        }
    }
}

/// Why an object or a request about it was refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum WorldError {
    /// The object's spec or a value given for it is malformed.
    #[error("object `{name}`: {reason}")]
    BadObject {
        /// The object's name.
        name: String,
        /// What is wrong.
        reason: String,
    },
    /// A link index beyond the object's links.
    #[error("object `{name}` has no link {link} (it has {count})")]
    NoLink {
        /// The object's name.
        name: String,
        /// The index asked for.
        link: usize,
        /// How many links it has.
        count: usize,
    },
    /// A value that must be a finite number is not.
    #[error("{what} must be finite, got {value}")]
    NotFinite {
        /// What the value is.
        what: &'static str,
        /// The value.
        value: f32,
    },
}

/// The world's parts, each a type that owns its state: the bodies (objects, rapier's sets and
/// the bookkeeping of their motion), the rooms, the memoized relations, the attachments, the
/// ignored contact pairs and the joints' drives. A plain aggregate: the parts' own modules say
/// what they do, and [`crate::World`] lends them out by concept.
#[derive(Clone)]
pub(crate) struct Core {
    pub(crate) bodies: Bodies,
    pub(crate) rooms: Vec<Room>,
    pub(crate) memo: RelationMemo,
    pub(crate) attachments: AttachmentSet,
    pub(crate) ignored: IgnoredPairs,
    pub(crate) drives: Drives,
}

/// The serde form of a [`Core`], the core's part of [`crate::World::to_bytes`]: its fields in the
/// order that format version 1 laid them out (postcard has no framing, so the order is the
/// format). Everything but the query index, which is rebuilt on first use.
#[derive(Serialize)]
struct CoreOut<'a> {
    physics: &'a PhysicsWorld,
    objects: &'a Vec<Object>,
    rooms: &'a Vec<Room>,
    motion: &'a Vec<u64>,
    memo: &'a RelationMemo,
    attachments: &'a AttachmentSet,
    ignored: &'a IgnoredPairs,
    pushed: &'a Vec<RigidBodyHandle>,
    quiet: bool,
    waking_to_sleep: &'a Vec<(RigidBodyHandle, f32)>,
    steps: u64,
    substeps: Substeps,
    drives: &'a Drives,
    carried: &'a BTreeMap<ObjectId, Velocity>,
}

/// [`CoreOut`], read back.
#[derive(Deserialize)]
struct CoreIn {
    physics: PhysicsWorld,
    objects: Vec<Object>,
    rooms: Vec<Room>,
    motion: Vec<u64>,
    memo: RelationMemo,
    attachments: AttachmentSet,
    ignored: IgnoredPairs,
    pushed: Vec<RigidBodyHandle>,
    quiet: bool,
    waking_to_sleep: Vec<(RigidBodyHandle, f32)>,
    steps: u64,
    substeps: Substeps,
    drives: Drives,
    carried: BTreeMap<ObjectId, Velocity>,
}

impl Serialize for Core {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let b = &self.bodies;
        CoreOut {
            physics: &b.physics,
            objects: &b.objects,
            rooms: &self.rooms,
            motion: &b.motion,
            memo: &self.memo,
            attachments: &self.attachments,
            ignored: &self.ignored,
            pushed: &b.pushed,
            quiet: b.quiet,
            waking_to_sleep: &b.waking_to_sleep,
            steps: b.steps,
            substeps: b.substeps,
            drives: &self.drives,
            carried: &b.carried,
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Core {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = CoreIn::deserialize(d)?;
        Ok(Core {
            bodies: Bodies {
                physics: c.physics,
                objects: c.objects,
                motion: c.motion,
                pushed: c.pushed,
                quiet: c.quiet,
                waking_to_sleep: c.waking_to_sleep,
                steps: c.steps,
                substeps: c.substeps,
                carried: c.carried,
                index: QueryIndex::default(),
            },
            rooms: c.rooms,
            memo: c.memo,
            attachments: c.attachments,
            ignored: c.ignored,
            drives: c.drives,
        })
    }
}

/// The `user_data` that tags a body and its colliders with the body they belong to.
pub(crate) fn tag(body: BodyRef) -> u128 {
    u128::from(body.object.0) | (body.link.map_or(0, |l| l as u128 + 1) << 32)
}

/// The body a `user_data` tag names, or `None` for a water drop.
pub(crate) fn untag(data: u128) -> Option<BodyRef> {
    if data == DROP_TAG {
        return None;
    }
    let object = ObjectId(data as u32);
    let link = ((data >> 32) as u32).checked_sub(1).map(|l| l as usize);
    Some(BodyRef { object, link })
}

impl Core {
    pub(crate) fn new(substeps: Substeps) -> Core {
        Core {
            bodies: Bodies::new(substeps),
            rooms: Vec::new(),
            memo: RelationMemo::default(),
            attachments: AttachmentSet::default(),
            ignored: IgnoredPairs::default(),
            drives: Drives::default(),
        }
    }

    /// Whether a decoded core holds together: a table entry per object, and every handle an
    /// object, a room, a drive or an attachment names is in the physics (see
    /// [`crate::World::from_bytes`]).
    pub(crate) fn check_consistency(&self) -> Result<(), String> {
        let b = &self.bodies;
        let n = b.objects.len();
        let p = &b.physics;
        if b.motion.len() != n {
            return Err(format!("{} motion counts for {n} objects", b.motion.len()));
        }
        let known = |id: ObjectId| (id.0 as usize) < n;
        for (i, object) in b.objects.iter().enumerate() {
            let bad = |what: &str| Err(format!("object {i} (`{}`): {what}", object.name));
            if object.colliders.is_empty() {
                return bad("no collider");
            }
            let bodies = std::iter::once(object.body).chain(object.links.iter().map(|l| l.body));
            if bodies.into_iter().any(|b| p.bodies.get(b).is_none()) {
                return bad("a body missing from the physics");
            }
            if object
                .colliders
                .iter()
                .any(|&c| p.colliders.get(c).is_none())
            {
                return bad("a collider missing from the physics");
            }
            for (l, link) in object.links.iter().enumerate() {
                let joint = match link.handle {
                    JointHandle::Impulse(h) => p.impulse_joints.get(h).is_some(),
                    JointHandle::Multibody(h) => p.multibody_joints.get(h).is_some(),
                };
                if !joint || link.parent.is_some_and(|parent| parent >= l) {
                    return bad("a link with a missing joint or a bad parent");
                }
            }
            if object
                .replaced_by
                .is_some_and(|halves| !halves.into_iter().all(known))
            {
                return bad("halves that are not objects");
            }
        }
        let body_known = |r: &BodyRef| {
            known(r.object)
                && r.link
                    .is_none_or(|l| l < b.objects[r.object.0 as usize].links.len())
        };
        if self
            .rooms
            .iter()
            .any(|r| r.floor.is_some_and(|f| !known(f)))
            || self
                .ignored
                .iter()
                .any(|(a, b)| !body_known(a) || !body_known(b))
            || self
                .drives
                .links()
                .any(|&(id, link)| !known(id) || link >= b.objects[id.0 as usize].links.len())
            || b.carried.keys().any(|&id| !known(id))
        {
            return Err("a room, ignored pair or drive names an unknown object or link".into());
        }
        if b.pushed.iter().any(|&h| p.bodies.get(h).is_none()) {
            return Err("a pushed body missing from the physics".into());
        }
        self.attachments
            .check_consistency(|b| body_known(&b), |j| p.impulse_joints.get(j).is_some())
    }
}

/// Finite, with a rotation that is a unit quaternion up to rounding (a zero one would become NaN).
pub(crate) fn pose_is_finite(pose: &Pose) -> bool {
    pose.translation.is_finite()
        && pose.rotation.is_finite()
        && (pose.rotation.length() - 1.0).abs() < 1e-3
}
