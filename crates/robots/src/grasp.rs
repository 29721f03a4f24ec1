//! Assisted grasping, as the original's (iGibson 2.0.3's `robots/behavior_robot.py`): the fingers
//! only touch, a constraint holds.
//!
//! While a hand's trigger is above [`GraspRules::threshold`] and it holds nothing, after each step
//! it looks for something to hold:
//! 1. 16 rays from 4 points (the palm's centre and base, the thumb's middle and tip) to the 4
//!    fingertips; every body they hit, the robot's own excepted, is a candidate;
//! 2. the candidate hit closest to the palm's centre is chosen — only it;
//! 3. it must touch the hand (palm or a finger) in the last substep;
//! 4. it must not be held by the other hand;
//! 5. it must be holdable ([`GraspRules::holdable`]): a movable body of at most
//!    [`GraspRules::max_mass`] or of an allow-listed category, or a door, lid or drawer of fixed
//!    furniture.
//!
//! It is then attached at the hit point: a fixed attachment of at most 500 N, or point-to-point of
//! 350 N for a link of fixed furniture on a revolute or prismatic joint (a door turns about the
//! hand). Contacts between it and the robot (the hand, the body and the other hand) are off
//! while held; the fingers freeze where they are.
//!
//! A hand lets go after a step in which its trigger is at or below the threshold, the attachment
//! broke (it needed more than its maximum force) or its two anchor points drifted more than
//! 0.1 m apart. Contacts come back once the released object's box no longer overlaps the box of
//! each robot part — not after the original's fixed release window of one step — so that a
//! released object still inside closed fingers drops out instead of being pushed out, a released
//! lid falls past the fingers that held its edge instead of wedging on them (they are rigid, see
//! `hand.rs`), and nothing is grasped again before the hand has left it.
//!
//! Differences from the original: it requires contact with a fingertip, we with any part of the
//! hand (our fingers are single capsules); it re-enables contacts after a fixed 1/30 s, we once
//! apart; its allow-list comes from per-category data we do not have (empty by default). It
//! keeps the held object's contacts with the other hand; we turn them off as the robot's parts
//! ignore each other: a plank held by its end, swung back beside the body, struck the other
//! hand hard enough to break its 500 N grasp.

use crate::hand::{FINGERS, HandPoints};
use crate::magic::MagicError;
use behavior_sim::{
    AttachmentId, AttachmentKind, AttachmentSpec, BodyKind, BodyRef, JointKind, ObjectId,
    QueryFilter, World,
};
use rapier3d::math::Vector;
use rapier3d::parry::bounding_volume::BoundingVolume;
use std::collections::BTreeSet;

/// The rules of assisted grasping; [`Default`] gives the original's.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug, PartialEq)]
pub struct GraspRules {
    /// A trigger fraction above this grasps; at or below it, lets go.
    pub threshold: f32,
    /// The heaviest body a hand may hold, kg.
    pub max_mass: f32,
    /// Categories (synsets) a hand may hold whatever their mass.
    pub allowed: BTreeSet<String>,
    /// The most force a fixed grasp applies before it breaks, N.
    pub fixed_force: f32,
    /// The most force a point-to-point grasp (a door) applies before it breaks, N.
    pub point_force: f32,
    /// A grasp whose anchors drift farther apart than this is let go, m.
    pub max_violation: f32,
}

impl Default for GraspRules {
    fn default() -> Self {
        GraspRules {
            threshold: 0.5,
            max_mass: 10.0,
            allowed: BTreeSet::new(),
            fixed_force: 500.0,
            point_force: 0.7 * 500.0,
            max_violation: 0.1,
        }
    }
}

impl GraspRules {
    /// How a hand may hold a body, or `None` if it may not: fixed for a movable body within the
    /// mass limit or allow-listed (for a link of a movable object, the object's own body mass
    /// counts: the world does not report a link's mass); point-to-point for a link of fixed
    /// furniture on a revolute or prismatic joint, whatever its mass (its hinge carries it).
    /// Fixed and kinematic bodies (furniture, walls, robots) cannot be held.
    pub fn holdable(&self, world: &World, body: BodyRef) -> Option<AttachmentKind> {
        let object = world.bodies().object(body.object);
        if !object.is_present() {
            return None;
        }
        if let Some(link) = body.link
            && object.is_fixed()
        {
            let moves = object.links[link].joint.kind != JointKind::Fixed;
            return moves.then_some(AttachmentKind::Point);
        }
        // What the hand would lift: the object with its links (a box with its lid).
        let light = world.bodies().total_mass(body.object) <= self.max_mass;
        let movable = object.body_kind == BodyKind::Dynamic;
        (movable && (light || self.allowed.contains(&object.category)))
            .then_some(AttachmentKind::Fixed)
    }

    /// How a hand of a robot made of `own` may take `body` at once: as the rules hold it, never
    /// one of the robot's own objects nor what its other hand holds (`besides`).
    pub(crate) fn kind_for(
        &self,
        world: &World,
        body: BodyRef,
        own: &[ObjectId],
        besides: Option<ObjectId>,
    ) -> Result<AttachmentKind, MagicError> {
        self.holdable(world, body)
            .filter(|_| !own.contains(&body.object) && besides != Some(body.object))
            .ok_or(MagicError::NotHoldable(body.object))
    }

    pub(crate) fn max_force(&self, kind: AttachmentKind) -> f32 {
        match kind {
            AttachmentKind::Fixed => self.fixed_force,
            AttachmentKind::Point => self.point_force,
        }
    }
}

/// What a hand holds.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grasp {
    pub(crate) body: BodyRef,
    pub(crate) attachment: AttachmentId,
    /// The finger joint angles when it closed, kept while it holds.
    pub(crate) fingers: [f32; crate::hand::FINGERS],
}

/// A released body whose contacts with some robot parts are still off.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug, PartialEq)]
pub(crate) struct Release {
    pub(crate) body: BodyRef,
    /// Robot objects (a hand, the body) still ignoring it.
    pub(crate) parts: Vec<ObjectId>,
    /// The world's step count when it was let go: contacts stay off for that step at least.
    pub(crate) since: u64,
}

/// The robot as the grasp sees it.
pub(crate) struct Grasper<'a> {
    pub(crate) rules: &'a GraspRules,
    /// The hand's object.
    pub(crate) hand: ObjectId,
    /// Every robot object: ignored by the rays, and by what the hand takes while it holds it.
    pub(crate) own: &'a [ObjectId],
    /// What the other hand holds.
    pub(crate) other_holds: Option<BodyRef>,
    /// The hand's finger angles now: they stay so while it holds.
    pub(crate) fingers: [f32; FINGERS],
}

impl Grasper<'_> {
    /// Tries to grasp (steps 1–5 of the module docs) and attaches on success.
    pub(crate) fn try_grasp(&self, world: &mut World) -> Option<Grasp> {
        // Only a touched body can be held (step 3), so a hand touching nothing casts no rays:
        // the rays need the world's query index, rebuilt after every substep in which
        // something moved, and a hand waving through the air would pay for it every step.
        let touched = self.touched(world);
        if touched.is_empty() {
            return None;
        }
        let (body, at) = self.candidate(world)?;
        if !touched.contains(&body) || self.other_holds.is_some_and(|o| o == body) {
            return None;
        }
        let kind = self.rules.holdable(world, body)?;
        let hand = BodyRef::from(self.hand);
        let spec = AttachmentSpec {
            holder: hand,
            held: body,
            at,
            kind,
            max_force: self.rules.max_force(kind),
        };
        let attachment = world.attachments_mut().attach(spec).ok()?;
        // With all of a held object's bodies (a folder's cover too, which otherwise struck
        // the palm that held the folder and broke the grasp).
        for &part in self.own {
            ignore_between(world, part, body, true);
        }
        Some(Grasp {
            body,
            attachment,
            fingers: self.fingers,
        })
    }

    /// Every body the hand (palm or a finger) touched in the last substep, its own excepted.
    fn touched(&self, world: &World) -> Vec<BodyRef> {
        let contacts = world.contacts().of(BodyRef::from(self.hand));
        let others = contacts
            .unwrap_or_default()
            .into_iter()
            .filter_map(|c| c.other);
        others.filter(|b| !self.own.contains(&b.object)).collect()
    }

    /// The body hit closest to the palm's centre by the rays between palm and fingertips, and
    /// where.
    fn candidate(&self, world: &World) -> Option<(BodyRef, Vector)> {
        let points = HandPoints::of(world, self.hand);
        let filter = QueryFilter::excluding(self.own);
        let mut best: Option<(f32, BodyRef, Vector)> = None;
        for origin in points.origins {
            for tip in points.tips {
                let Some((body, at)) = first_hit(world, origin, tip, &filter) else {
                    continue;
                };
                let d = (at - points.palm_centre).length();
                if best.is_none_or(|(bd, bb, _)| d < bd || (d == bd && body < bb)) {
                    best = Some((d, body, at));
                }
            }
        }
        best.map(|(_, body, at)| (body, at))
    }
}

/// The first body a segment from `origin` to `end` hits, and where.
fn first_hit(
    world: &World,
    origin: Vector,
    end: Vector,
    filter: &QueryFilter,
) -> Option<(BodyRef, Vector)> {
    let direction = end - origin;
    let length = direction.length();
    if length < 1e-6 {
        return None;
    }
    let hit = world
        .query()
        .cast_ray(origin, direction, length, filter)
        .ok()??;
    Some((hit.body?, hit.point))
}

/// Whether a grasp must end: its trigger let go, or its attachment broke or drifted.
pub(crate) fn must_release(world: &World, grasp: &Grasp, trigger: f32, rules: &GraspRules) -> bool {
    match world.attachments().get(grasp.attachment) {
        None => true,
        Some(state) => {
            trigger <= rules.threshold || state.broken || state.violation > rules.max_violation
        }
    }
}

impl Release {
    /// Turns contacts back on with each part it is now clear of; whether none is left.
    pub(crate) fn settle(&mut self, world: &mut World) -> bool {
        let body = self.body;
        self.parts.retain(|&part| {
            let clear = !world
                .bodies()
                .aabb(body.object)
                .intersects(&world.bodies().aabb(part));
            if clear {
                ignore_between(world, part, body, false);
            }
            !clear
        });
        self.parts.is_empty()
    }
}

/// For a grasp made at once (`magic.rs`): contacts between the held body and every other
/// object whose box its box overlaps where it was put, turned off while held, so that a
/// carton put in the hand beside a shelf does not break its grasp against it. `None` when it
/// overlaps nothing.
pub(crate) fn overlooked(
    world: &mut World,
    body: BodyRef,
    own: &[ObjectId],
    since: u64,
) -> Option<Release> {
    let held = world.bodies().aabb(body.object);
    let parts: Vec<ObjectId> = world
        .bodies()
        .objects()
        .filter(|(id, o)| *id != body.object && o.is_present() && !own.contains(id))
        .map(|(id, _)| id)
        .filter(|&id| world.bodies().aabb(id).intersects(&held))
        .collect();
    for &part in &parts {
        ignore_between(world, part, body, true);
    }
    (!parts.is_empty()).then_some(Release { body, parts, since })
}

/// A robot taking and letting go of things at once, as the assisted grasp does (the symbolic
/// moves of `magic.rs`), whichever hand: its rules, its own objects and the releases it watches.
pub(crate) struct Hold<'r> {
    pub(crate) rules: &'r GraspRules,
    /// Every object of the robot.
    pub(crate) own: Vec<ObjectId>,
    pub(crate) releases: &'r mut Vec<Release>,
}

impl Hold<'_> {
    /// Attaches `body` to `hand` at `at` as the assisted grasp does: its contacts with every
    /// part of the robot off while held, and with what it was put beside until clear of it.
    pub(crate) fn attach(
        &mut self,
        world: &mut World,
        hand: ObjectId,
        body: BodyRef,
        at: Vector,
        kind: AttachmentKind,
    ) -> Result<AttachmentId, MagicError> {
        let spec = AttachmentSpec {
            holder: BodyRef::from(hand),
            held: body,
            at,
            kind,
            max_force: self.rules.max_force(kind),
        };
        let attachment = world.attachments_mut().attach(spec)?;
        for &part in &self.own {
            ignore_between(world, part, body, true);
        }
        let since = world.bodies().steps();
        self.releases
            .extend(overlooked(world, body, &self.own, since));
        Ok(attachment)
    }

    /// Lets go of `body`, held by `attachment`, at once: its contacts with what it was put
    /// beside back now, with the robot's parts once it is clear of each.
    pub(crate) fn let_go(self, world: &mut World, body: BodyRef, attachment: AttachmentId) {
        world.attachments_mut().detach(attachment);
        restore_overlooked(world, self.releases, body, &self.own);
        self.releases.push(Release {
            body,
            parts: self.own,
            since: world.bodies().steps(),
        });
    }
}

/// When a body held by a grasp made at once is let go at once: its contacts with what it was
/// put beside come back now (it is about to be placed clear of everything), those with the
/// robot as after any release.
pub(crate) fn restore_overlooked(
    world: &mut World,
    releases: &mut Vec<Release>,
    body: BodyRef,
    own: &[ObjectId],
) {
    releases.retain(|r| {
        if r.body != body || r.parts.iter().all(|p| own.contains(p)) {
            return true;
        }
        for &part in &r.parts {
            ignore_between(world, part, body, false);
        }
        false
    });
}

/// An object's body and its links' bodies.
fn object_bodies(world: &World, id: ObjectId) -> Vec<BodyRef> {
    let links = world.bodies().object(id).links.len();
    std::iter::once(BodyRef::from(id))
        .chain((0..links).map(|l| BodyRef::link(id, l)))
        .collect()
}

/// Turns contacts off (or back on) between every body of `part` and `held` — with all of
/// `held`'s object, links included, when it is movable (a carton with its lid; a folder held
/// by its cover, whose other half otherwise strikes the palm); only the link held of fixed
/// furniture (a door).
pub(crate) fn ignore_between(world: &mut World, part: ObjectId, held: BodyRef, ignore: bool) {
    let helds = match held.link {
        Some(_) if world.bodies().object(held.object).is_fixed() => vec![held],
        _ => object_bodies(world, held.object),
    };
    for p in object_bodies(world, part) {
        for &h in &helds {
            let _ = world.contacts_mut().ignore(p, h, ignore);
        }
    }
}

/// Moves an object, as it is turned, so that its box's centre lands on `centre` (an object put
/// in a hand at once).
pub(crate) fn centre_on(
    world: &mut World,
    object: ObjectId,
    centre: Vector,
) -> Result<(), behavior_sim::WorldError> {
    let pose = world.bodies().pose(object);
    let shift = centre - world.bodies().aabb(object).center();
    world.bodies_mut().set_pose(
        object,
        rapier3d::math::Pose::from_parts(pose.translation + shift, pose.rotation),
    )
}
