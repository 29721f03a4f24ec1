//! Kinematic predicates, computed from geometry alone (shape queries and ray casts), never from
//! the solver's contact cache, so a predicate has the same value for sleeping and awake bodies
//! and right after a teleport.
//!
//! Definitions (after iGibson 2.0's kinematic states, `igibson/object_states/` in its code):
//! - `touching(a, b)`: some collider of `a` is within [`TOUCH_DISTANCE`] of some collider of `b`.
//! - `ontop(a, b)`: `b` supports `a` and is not above it: they touch at a point where `b`'s
//!   surface faces up (its outward normal within 45° of +z), and a ray cast up from the centre of
//!   `a`'s box does not hit `b` (so an apple on the shelf of a fridge is inside it, not on top).
//!   iGibson asks for contact, for `b` to be hit by a ray cast down from `a`'s centre of mass and
//!   not by one cast up; the normal test replaces the downward ray, since it also holds for an
//!   object resting near an edge, and never for two objects side by side.
//! - `under(a, b)`: a ray cast up from the top centre of `a`'s box hits `b` within 5 m, and a ray
//!   cast down from its bottom centre does not.
//! - `inside(a, b)`: the centre of `a`'s box lies in `b`'s box, at least half of `a`'s box lies
//!   within `b`'s (iGibson checks the centre only, which lets a table standing over a bin be
//!   "inside" it), and rays from the centre along at least two of the three axes hit `b` in both
//!   directions (`b` surrounds `a`).
//! - `nextto(a, b)`: the gap between their boxes is at most a sixth of the mean of their summed
//!   extents, and a horizontal ray from the centre of one (16 directions, 1 m) hits the other.
//! - `onfloor(a, floor)`: the room at the centre of `a`'s box is the floor's room, and `a` touches
//!   the floor, or its bottom is within 10 cm of it and what lies right below it is the floor or
//!   a flat thing lying on the floor (at most [`FLAT_HEIGHT`] tall and touching it: a mat, a
//!   towel). iGibson requires contact, which makes "the soap on the towel on the floor" — both
//!   literals in `washing_floor` — impossible; we keep that one exception so the activity can be
//!   done, while an apple in a basket, a bottom drawer or a shelf's lowest board does not count.
//! - `inroom(a, type)`: the room at the centre of `a`'s box has that type.
//!
//! A ray "hits" an object when it meets any of its colliders, whatever lies between (iGibson
//! collects the first 10 objects along each ray, which comes to the same in household scenes), so
//! a predicate depends on its two objects only.
//!
//! A sliced object relates as its halves do: both halves must satisfy a predicate it is the
//! subject of, either half one it is the object of.
//!
//! Values are memoized per pair (a mutex-guarded map, so that worlds are `Sync`) and kept until either object moves: after a step, an object
//! whose body (or a link's) is awake counts as moved, and so does one that is teleported. A
//! settled scene therefore answers every predicate from the cache.

use crate::bodies::Bodies;
use crate::core::Core;
use crate::object::ObjectId;
use crate::room::Room;
use behavior_core::{Predicate, RoomType};
use rapier3d::math::Vector;
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::parry::query;
use rapier3d::prelude::Ray;
use std::collections::HashMap;
use std::sync::Mutex;

/// Colliders closer than this touch (m). Resting contacts sit within rapier's contact margin.
pub const TOUCH_DISTANCE: f32 = 0.005;
/// A support normal must be within 45° of vertical.
pub const SUPPORT_COS: f32 = std::f32::consts::FRAC_1_SQRT_2;
/// How far up and down `under` looks (m).
pub const VERTICAL_RANGE: f32 = 5.0;
/// How far sideways `nextto` looks (m).
pub const HORIZONTAL_RANGE: f32 = 1.0;
/// An object whose bottom is this close above a floor is on it, even lying on a mat or a towel.
pub const ONFLOOR_HEIGHT: f32 = 0.1;
/// The tallest thing lying on the floor that an object on it still counts as `onfloor` on (m).
pub const FLAT_HEIGHT: f32 = 0.03;
/// How many horizontal directions `nextto` looks in.
pub const HORIZONTAL_DIRECTIONS: usize = 16;

/// Memoized binary relations: (predicate, a, b) → (value, motion counts of a and b when it was
/// computed). Behind a mutex so that a world is `Sync`: readers on several threads share it. It
/// is only ever looked up, never iterated, so its order cannot reach the simulation.
#[derive(Default)]
pub(crate) struct RelationMemo(Mutex<MemoMap>);

/// (predicate, a, b) → (value, motion counts of a and b).
type MemoMap = HashMap<(Predicate, ObjectId, ObjectId), (bool, (u64, u64))>;

impl Clone for RelationMemo {
    fn clone(&self) -> Self {
        RelationMemo(Mutex::new(self.lock().clone()))
    }
}

/// One memoized relation, as saved.
type MemoEntry = ((Predicate, ObjectId, ObjectId), (bool, (u64, u64)));

/// Saved sorted by key, so that equal memos give equal bytes whatever the map's order.
impl serde::Serialize for RelationMemo {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut entries: Vec<MemoEntry> = self.lock().iter().map(|(&k, &v)| (k, v)).collect();
        entries.sort_unstable_by_key(|&(k, _)| k);
        serde::Serialize::serialize(&entries, s)
    }
}

impl<'de> serde::Deserialize<'de> for RelationMemo {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let entries: Vec<MemoEntry> = serde::Deserialize::deserialize(d)?;
        Ok(RelationMemo(Mutex::new(entries.into_iter().collect())))
    }
}

impl RelationMemo {
    fn lock(&self) -> std::sync::MutexGuard<'_, MemoMap> {
        // A panic while holding the lock cannot leave the map half-written (inserts are atomic
        // from the map's point of view), so a poisoned lock is still good.
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    pub(crate) fn clear(&self) {
        self.lock().clear();
    }

    /// The value memoized for `key` if it was computed when its objects' motion counts were
    /// `stamp`, else `compute`'s, memoized.
    fn get_or_compute(
        &self,
        key: (Predicate, ObjectId, ObjectId),
        stamp: (u64, u64),
        compute: impl FnOnce() -> bool,
    ) -> bool {
        if let Some(&(value, seen)) = self.lock().get(&key)
            && seen == stamp
        {
            return value;
        }
        // Computed without the lock: relations of sliced objects recurse into this.
        let value = compute();
        self.lock().insert(key, (value, stamp));
        value
    }
}

/// The kinematic relations between objects (see the module docs), memoized. Reached through
/// [`crate::World::relations`].
#[derive(Clone, Copy)]
pub struct Relations<'w> {
    pub(crate) bodies: &'w Bodies,
    pub(crate) memo: &'w RelationMemo,
    pub(crate) rooms: &'w [Room],
}

impl<'w> Relations<'w> {
    pub(crate) fn new(core: &'w Core) -> Relations<'w> {
        Relations {
            bodies: &core.bodies,
            memo: &core.memo,
            rooms: &core.rooms,
        }
    }

    /// Whether `a` stands in the binary relation `predicate` to `b` (`ontop`, `inside`,
    /// `under`, `nextto`, `touching` or `onfloor`); false for any other predicate.
    pub fn relation(&self, predicate: Predicate, a: ObjectId, b: ObjectId) -> bool {
        match predicate {
            Predicate::OnTop => self.ontop(a, b),
            Predicate::Inside => self.inside(a, b),
            Predicate::Under => self.under(a, b),
            Predicate::NextTo => self.nextto(a, b),
            Predicate::Touching => self.touching(a, b),
            Predicate::OnFloor => self.onfloor(a, b),
            _ => false,
        }
    }

    /// `touching(a, b)` (see the module docs).
    pub fn touching(&self, a: ObjectId, b: ObjectId) -> bool {
        self.relate(Predicate::Touching, a, b)
    }

    /// `ontop(a, b)` (see the module docs).
    pub fn ontop(&self, a: ObjectId, b: ObjectId) -> bool {
        self.relate(Predicate::OnTop, a, b)
    }

    /// `under(a, b)` (see the module docs).
    pub fn under(&self, a: ObjectId, b: ObjectId) -> bool {
        self.relate(Predicate::Under, a, b)
    }

    /// `inside(a, b)` (see the module docs).
    pub fn inside(&self, a: ObjectId, b: ObjectId) -> bool {
        self.relate(Predicate::Inside, a, b)
    }

    /// `nextto(a, b)` (see the module docs).
    pub fn nextto(&self, a: ObjectId, b: ObjectId) -> bool {
        self.relate(Predicate::NextTo, a, b)
    }

    /// A binary predicate. A sliced object relates as its halves do: both halves must relate as
    /// the subject, either half will do as the object (an apple sliced on a plate is still on it).
    fn relate(&self, predicate: Predicate, a: ObjectId, b: ObjectId) -> bool {
        if let Some(halves) = self.replaced_by(a) {
            return halves.iter().all(|&h| self.relate(predicate, h, b));
        }
        if let Some(halves) = self.replaced_by(b) {
            return halves.iter().any(|&h| self.relate(predicate, a, h));
        }
        self.cached(predicate, a, b, || match predicate {
            Predicate::OnTop => self.compute_ontop(a, b),
            Predicate::Inside => self.compute_inside(a, b),
            Predicate::Under => self.compute_under(a, b),
            Predicate::NextTo => self.compute_nextto(a, b),
            _ => self.compute_touching(a, b),
        })
    }

    /// The halves that replaced a sliced object.
    fn replaced_by(&self, id: ObjectId) -> Option<[ObjectId; 2]> {
        self.bodies.object(id).replaced_by
    }

    /// A memoized predicate: valid while neither object has moved (see [`Bodies::motion`]).
    fn cached(
        &self,
        predicate: Predicate,
        a: ObjectId,
        b: ObjectId,
        compute: impl FnOnce() -> bool,
    ) -> bool {
        let stamp = (self.bodies.motion(a), self.bodies.motion(b));
        self.memo.get_or_compute((predicate, a, b), stamp, compute)
    }

    /// The collider pairs of two objects whose boxes come within `margin`.
    fn near_pairs(
        &self,
        a: ObjectId,
        b: ObjectId,
        margin: f32,
    ) -> impl Iterator<
        Item = (
            &'w rapier3d::geometry::Collider,
            &'w rapier3d::geometry::Collider,
        ),
    > + use<'w> {
        let bodies = self.bodies;
        let colliders = &bodies.physics.colliders;
        let (ca, cb) = (&bodies.object(a).colliders, &bodies.object(b).colliders);
        ca.iter().flat_map(move |&x| {
            cb.iter().filter_map(move |&y| {
                let (x, y) = (&colliders[x], &colliders[y]);
                let grown = x.compute_aabb().loosened(margin);
                grown.intersects(&y.compute_aabb()).then_some((x, y))
            })
        })
    }

    /// The contacts between two objects' colliders within [`TOUCH_DISTANCE`]. A contact query
    /// with that margin rather than a distance: parry's cuboid–cuboid distance overestimates the
    /// gap between two slightly turned boxes (by centimetres, for faces 0.5 mm apart), while its
    /// contact query is exact there.
    fn near_contacts(
        &self,
        a: ObjectId,
        b: ObjectId,
    ) -> impl Iterator<Item = query::Contact> + use<'w> {
        self.near_pairs(a, b, TOUCH_DISTANCE).filter_map(|(x, y)| {
            let (px, py) = (x.position(), y.position());
            query::contact(px, x.shape(), py, y.shape(), TOUCH_DISTANCE)
                .ok()
                .flatten()
                .filter(|c| c.dist <= TOUCH_DISTANCE)
        })
    }

    fn compute_touching(&self, a: ObjectId, b: ObjectId) -> bool {
        a != b && self.near_contacts(a, b).next().is_some()
    }

    /// Whether `b` supports `a` and is not above it (see the module docs).
    fn compute_ontop(&self, a: ObjectId, b: ObjectId) -> bool {
        a != b
            && self.supports(a, b)
            && !self.ray_hits(b, self.bodies.aabb(a).center(), Vector::Z, VERTICAL_RANGE)
    }

    /// Whether `a` and `b` touch where `b`'s surface faces up: `normal2` is `b`'s outward normal
    /// at the contact, up when `b` carries `a`.
    fn supports(&self, a: ObjectId, b: ObjectId) -> bool {
        self.near_contacts(a, b).any(|c| c.normal2.z >= SUPPORT_COS)
    }

    fn compute_under(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let aabb = self.bodies.aabb(a);
        let c = aabb.center();
        let top = Vector::new(c.x, c.y, aabb.maxs.z);
        let bottom = Vector::new(c.x, c.y, aabb.mins.z);
        self.ray_hits(b, top, Vector::Z, VERTICAL_RANGE)
            && !self.ray_hits(b, bottom, -Vector::Z, VERTICAL_RANGE)
    }

    fn compute_inside(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let own = self.bodies.aabb(a);
        let center = own.center();
        let container = self.bodies.aabb(b);
        if !container.contains_local_point(center) || !mostly_within(&own, &container) {
            return false;
        }
        let reach = (container.maxs - container.mins).length();
        let surrounded = [Vector::X, Vector::Y, Vector::Z]
            .into_iter()
            .filter(|&axis| {
                self.ray_hits(b, center, axis, reach) && self.ray_hits(b, center, -axis, reach)
            })
            .count();
        surrounded >= 2
    }

    fn compute_nextto(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let (ba, bb) = (self.bodies.aabb(a), self.bodies.aabb(b));
        let gap = (ba.mins - bb.maxs)
            .max(bb.mins - ba.maxs)
            .max(Vector::ZERO)
            .length();
        let extents = (ba.maxs - ba.mins) + (bb.maxs - bb.mins);
        let threshold = (extents.x + extents.y + extents.z) / 3.0 / 6.0;
        gap <= threshold && (self.sees_horizontally(a, b) || self.sees_horizontally(b, a))
    }

    fn sees_horizontally(&self, from: ObjectId, target: ObjectId) -> bool {
        let center = self.bodies.aabb(from).center();
        (0..HORIZONTAL_DIRECTIONS).any(|k| {
            let angle = k as f32 * std::f32::consts::TAU / HORIZONTAL_DIRECTIONS as f32;
            let dir = Vector::new(angle.cos(), angle.sin(), 0.0);
            self.ray_hits(target, center, dir, HORIZONTAL_RANGE)
        })
    }

    /// `onfloor(a, floor)` (see the module docs).
    pub fn onfloor(&self, a: ObjectId, floor: ObjectId) -> bool {
        if let Some(halves) = self.replaced_by(a) {
            return halves.iter().all(|&h| self.onfloor(h, floor));
        }
        if a == floor {
            return false;
        }
        let own = self.bodies.aabb(a);
        let c = own.center();
        let room_floor = self.room_at(c.x, c.y).and_then(|r| r.floor);
        if room_floor != Some(floor) {
            return false;
        }
        if self.touching(a, floor) {
            return true;
        }
        // Lying on something flat on the floor (a mat, a towel), not in a basket, a bottom drawer
        // or on a shelf's lowest board: low enough, and resting on the floor or on a flat thing
        // that lies on it.
        let low = own.mins.z - self.bodies.aabb(floor).maxs.z <= ONFLOOR_HEIGHT;
        low && match self.first_below(a, Vector::new(c.x, c.y, own.mins.z + 0.001)) {
            Some(below) if below == floor => true,
            Some(below) => {
                let b = self.bodies.aabb(below);
                b.maxs.z - b.mins.z <= FLAT_HEIGHT && self.touching(below, floor)
            }
            None => false,
        }
    }

    /// The nearest object straight below a point, other than `except`.
    fn first_below(&self, except: ObjectId, from: Vector) -> Option<ObjectId> {
        let ray = Ray::new(from, -Vector::Z);
        let mut best: Option<(f32, ObjectId)> = None;
        for (id, object) in self.bodies.objects() {
            if id == except || !self.bodies.present(id) {
                continue;
            }
            for &c in &object.colliders {
                let c = &self.bodies.physics.colliders[c];
                if let Some(t) = c.shape().cast_ray(c.position(), &ray, 10.0, true)
                    && best.is_none_or(|(bt, _)| t < bt)
                {
                    best = Some((t, id));
                }
            }
        }
        best.map(|(_, id)| id)
    }

    /// The room whose footprint contains (x, y); the first one added wins on shared walls.
    pub fn room_at(&self, x: f32, y: f32) -> Option<&'w Room> {
        self.rooms.iter().find(|r| r.contains(x, y))
    }

    /// The type of the room at the centre of the object's box.
    pub fn room_of(&self, a: ObjectId) -> Option<RoomType> {
        let c = self.bodies.aabb(a).center();
        self.room_at(c.x, c.y).map(|r| r.kind)
    }

    /// Whether a ray hits `target` within `range`. Rays are tested against the target's own
    /// colliders, so what lies between does not matter and the result needs no query structure
    /// (it is right even just after a teleport).
    pub fn ray_hits(&self, target: ObjectId, origin: Vector, dir: Vector, range: f32) -> bool {
        if !self.bodies.present(target) {
            return false;
        }
        let ray = Ray::new(origin, dir);
        self.bodies.object(target).colliders.iter().any(|&c| {
            let c = &self.bodies.physics.colliders[c];
            c.is_enabled() && c.shape().intersects_ray(c.position(), &ray, range)
        })
    }
}

/// Whether at least half of `inner`'s volume lies within `outer`.
fn mostly_within(
    inner: &rapier3d::parry::bounding_volume::Aabb,
    outer: &rapier3d::parry::bounding_volume::Aabb,
) -> bool {
    let overlap = (inner.maxs.min(outer.maxs) - inner.mins.max(outer.mins)).max(Vector::ZERO);
    let size = inner.maxs - inner.mins;
    overlap.x * overlap.y * overlap.z >= 0.5 * size.x * size.y * size.z
}
