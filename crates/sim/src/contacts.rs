//! Contacts and who may touch whom: a body's contacts as the last physics substep found them,
//! collision groups (a robot ignores water drops), and pairs of bodies whose contacts are ignored
//! (a hand and the object it holds).

use crate::bodies::Bodies;
use crate::core::{Core, DROP_TAG, WorldError, untag};
use crate::object::{BodyRef, ObjectId};
use rapier3d::dynamics::RigidBodySet;
use rapier3d::geometry::{
    ColliderHandle, Group, InteractionGroups, InteractionTestMode, SolverFlags,
};
use rapier3d::math::Vector;
use rapier3d::pipeline::{ActiveHooks, PairFilterContext, PhysicsHooks};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// Collision groups: bit masks saying what a body is and what it collides with. Two bodies
/// collide when each one's membership meets the other's filter.
pub mod groups {
    /// Furniture, objects, walls and floors: everything by default.
    pub const SCENE: u32 = 1;
    /// Robots' bodies.
    pub const ROBOT: u32 = 1 << 1;
    /// Water drops.
    pub const WATER: u32 = 1 << 2;
    /// Every group.
    pub const ALL: u32 = u32::MAX;
}

/// One contact point of a body with another, from the last physics substep.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Contact {
    /// The other body, or `None` for a water drop.
    pub other: Option<BodyRef>,
    /// Where, in the world (on this body's surface).
    pub point: Vector,
    /// Unit normal pointing from this body toward the other.
    pub normal: Vector,
    /// The normal impulse the solver applied there over the last physics substep (N·s); divided
    /// by the substep's length it is the contact force.
    pub impulse: f32,
    /// Penetration is negative; resting contacts sit about a millimetre apart.
    pub distance: f32,
}

/// Contact points farther apart than this are predictions, not contacts (m): the touching
/// distance, as resting bodies settle about 1 mm apart in rapier.
const CONTACT_DISTANCE: f32 = crate::kinematics::TOUCH_DISTANCE;

/// Pairs of bodies whose contacts are ignored (a hand and what it holds), each pair in order.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(transparent)]
pub(crate) struct IgnoredPairs(BTreeSet<(BodyRef, BodyRef)>);

impl IgnoredPairs {
    fn contains(&self, a: BodyRef, b: BodyRef) -> bool {
        self.0.contains(&ordered(a, b))
    }

    /// Every pair, for checking a decoded world.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &(BodyRef, BodyRef)> {
        self.0.iter()
    }
}

fn ordered(a: BodyRef, b: BodyRef) -> (BodyRef, BodyRef) {
    if a <= b { (a, b) } else { (b, a) }
}

/// The contacts of bodies as the last physics substep found them, and which pairs are ignored.
/// Reached through [`crate::World::contacts`].
#[derive(Clone, Copy)]
pub struct Contacts<'w> {
    pub(crate) bodies: &'w Bodies,
    pub(crate) ignored: &'w IgnoredPairs,
}

/// Who may touch whom: collision groups and ignored pairs. Reached through
/// [`crate::World::contacts_mut`].
pub struct ContactsMut<'w> {
    pub(crate) bodies: &'w mut Bodies,
    pub(crate) ignored: &'w mut IgnoredPairs,
}

impl<'w> Contacts<'w> {
    pub(crate) fn new(core: &'w Core) -> Contacts<'w> {
        Contacts {
            bodies: &core.bodies,
            ignored: &core.ignored,
        }
    }

    /// The contacts of a body (or of an object's body and all its links, with `link: None` in
    /// [`Contacts::of_object`]) found by the last physics substep, sorted by the other body.
    pub fn of(&self, body: BodyRef) -> Result<Vec<Contact>, WorldError> {
        let handle = self.bodies.handle(body)?;
        let colliders = self.bodies.physics.bodies[handle].colliders().to_vec();
        Ok(self.of_colliders(&colliders))
    }

    /// The contacts of an object's body and all its links.
    pub fn of_object(&self, id: ObjectId) -> Vec<Contact> {
        self.of_colliders(&self.bodies.object(id).colliders)
    }

    /// Whether contacts between two bodies are ignored.
    pub fn ignored(&self, a: BodyRef, b: BodyRef) -> bool {
        self.ignored.contains(a, b)
    }

    fn of_colliders(&self, colliders: &[rapier3d::geometry::ColliderHandle]) -> Vec<Contact> {
        let physics = &self.bodies.physics;
        let mut out = Vec::new();
        for &c in colliders {
            for pair in physics.narrow_phase.contact_pairs_with(c) {
                let (mine_first, other) = if pair.collider1 == c {
                    (true, pair.collider2)
                } else {
                    (false, pair.collider1)
                };
                if colliders.contains(&other) && other != c {
                    continue; // within the same body or object
                }
                let Some(other_collider) = physics.colliders.get(other) else {
                    continue;
                };
                let mine = &physics.colliders[c];
                for manifold in pair.manifolds() {
                    let local_normal = if mine_first {
                        manifold.local_n1
                    } else {
                        manifold.local_n2
                    };
                    let normal: Vector = mine.position().rotation * local_normal;
                    for p in manifold
                        .points
                        .iter()
                        .filter(|p| p.dist <= CONTACT_DISTANCE)
                    {
                        let local = if mine_first { p.local_p1 } else { p.local_p2 };
                        out.push(Contact {
                            other: untag(other_collider.user_data),
                            point: mine.position().transform_point(local),
                            normal,
                            impulse: p.data.impulse,
                            distance: p.dist,
                        });
                    }
                }
            }
        }
        out.sort_by_key(|c| c.other);
        out
    }
}

impl<'w> ContactsMut<'w> {
    pub(crate) fn new(core: &'w mut Core) -> ContactsMut<'w> {
        ContactsMut {
            bodies: &mut core.bodies,
            ignored: &mut core.ignored,
        }
    }

    /// Sets what an object's bodies (all its links too) are and collide with; see [`groups`].
    pub fn set_groups(&mut self, id: ObjectId, memberships: u32, filter: u32) {
        let groups = InteractionGroups::new(
            Group::from_bits_retain(memberships),
            Group::from_bits_retain(filter),
            InteractionTestMode::And,
        );
        let bodies = &mut *self.bodies;
        let object = &bodies.objects[id.0 as usize];
        for &c in &object.colliders {
            bodies.physics.colliders[c].set_collision_groups(groups);
        }
        let body = object.body;
        bodies.wake(body);
    }

    /// Ignores (or again allows) contacts between two bodies.
    pub fn ignore(&mut self, a: BodyRef, b: BodyRef, ignore: bool) -> Result<(), WorldError> {
        let bodies = &mut *self.bodies;
        let (ha, hb) = (bodies.handle(a)?, bodies.handle(b)?);
        let pair = ordered(a, b);
        if ignore {
            self.ignored.0.insert(pair);
            for h in [ha, hb] {
                for c in bodies.physics.bodies[h].colliders().to_vec() {
                    let collider = &mut bodies.physics.colliders[c];
                    let hooks = collider.active_hooks() | ActiveHooks::FILTER_CONTACT_PAIRS;
                    collider.set_active_hooks(hooks);
                }
            }
        } else {
            self.ignored.0.remove(&pair);
        }
        bodies.wake(ha);
        bodies.wake(hb);
        Ok(())
    }
}

/// The physics hooks of one step: drops ignored pairs and otherwise behaves as rapier's default
/// filter (no contacts between two bodies that never move).
pub(crate) struct ContactFilter<'a> {
    pub(crate) ignored: &'a IgnoredPairs,
}

impl PhysicsHooks for ContactFilter<'_> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        let dynamic = |bodies: &RigidBodySet, h: Option<rapier3d::dynamics::RigidBodyHandle>| {
            h.is_some_and(|h| bodies[h].is_dynamic())
        };
        if !dynamic(context.bodies, context.rigid_body1)
            && !dynamic(context.bodies, context.rigid_body2)
        {
            return None;
        }
        let body = |c: ColliderHandle| {
            let data = context.colliders[c].user_data;
            (data != DROP_TAG).then(|| untag(data)).flatten()
        };
        if let (Some(a), Some(b)) = (body(context.collider1), body(context.collider2))
            && self.ignored.contains(a, b)
        {
            return None;
        }
        Some(SolverFlags::COMPUTE_RIGID_IMPULSES)
    }
}
