//! Kinematic predicates, computed from geometry alone (shape queries and ray casts), never from
//! the solver's contact cache, so a predicate has the same value for sleeping and awake bodies
//! and right after a teleport.
//!
//! Definitions (after iGibson 2.0's, see `../shared/reference/igibson-2.0-reference.md` §1.2–1.3):
//! - `touching(a, b)`: some collider of `a` is within [`TOUCH_DISTANCE`] of some collider of `b`.
//! - `ontop(a, b)`: `b` supports `a`: they touch at a point where `b`'s surface faces up (its
//!   outward normal within 45° of +z). iGibson instead asks for contact and for `b` to be hit by
//!   a ray cast down from `a`'s centre of mass; the normal test also holds for an object resting
//!   near an edge, and never for two objects side by side.
//! - `under(a, b)`: a ray cast up from the top centre of `a`'s box hits `b` within 5 m, and a ray
//!   cast down from its bottom centre does not.
//! - `inside(a, b)`: the centre of `a`'s box lies in `b`'s box, and rays from it along at least
//!   two of the three axes hit `b` in both directions (`b` surrounds `a`).
//! - `nextto(a, b)`: the gap between their boxes is at most a sixth of the mean of their summed
//!   extents, and a horizontal ray from the centre of one (16 directions, 1 m) hits the other.
//! - `onfloor(a, floor)`: `a` touches the floor object, and the room at the centre of `a`'s box
//!   is the floor's room.
//! - `inroom(a, type)`: the room at the centre of `a`'s box has that type.
//!
//! Ray casts collect up to [`MAX_HITS`] objects per ray, as iGibson's do.

use crate::world::{DROP_TAG, ObjectId, World};
use rapier3d::math::Vector;
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::parry::query;
use rapier3d::pipeline::QueryFilter;
use rapier3d::prelude::Ray;

/// Colliders closer than this touch (m). Resting contacts sit within rapier's contact margin.
pub const TOUCH_DISTANCE: f32 = 0.005;
/// A support normal must be within 45° of vertical.
pub const SUPPORT_COS: f32 = std::f32::consts::FRAC_1_SQRT_2;
pub const VERTICAL_RANGE: f32 = 5.0;
pub const HORIZONTAL_RANGE: f32 = 1.0;
pub const HORIZONTAL_DIRECTIONS: usize = 16;
pub const MAX_HITS: usize = 10;

impl World {
    /// The collider pairs of two objects whose boxes come within `margin`.
    fn near_pairs(
        &self,
        a: ObjectId,
        b: ObjectId,
        margin: f32,
    ) -> impl Iterator<Item = (&rapier3d::geometry::Collider, &rapier3d::geometry::Collider)> {
        let colliders = &self.physics.colliders;
        let (ca, cb) = (&self.object(a).colliders, &self.object(b).colliders);
        ca.iter().flat_map(move |&x| {
            cb.iter().filter_map(move |&y| {
                let (x, y) = (&colliders[x], &colliders[y]);
                let grown = x.compute_aabb().loosened(margin);
                grown.intersects(&y.compute_aabb()).then_some((x, y))
            })
        })
    }

    pub fn touching(&self, a: ObjectId, b: ObjectId) -> bool {
        a != b
            && self.near_pairs(a, b, TOUCH_DISTANCE).any(|(x, y)| {
                query::distance(x.position(), x.shape(), y.position(), y.shape())
                    .is_ok_and(|d| d.distance <= TOUCH_DISTANCE)
            })
    }

    /// Whether `b` supports `a` (see the module docs).
    pub fn ontop(&self, a: ObjectId, b: ObjectId) -> bool {
        a != b
            && self.near_pairs(a, b, TOUCH_DISTANCE).any(|(x, y)| {
                // normal2 is `y`'s outward normal at the contact: up when `y` carries `x`.
                let contact = query::contact(
                    x.position(),
                    x.shape(),
                    y.position(),
                    y.shape(),
                    TOUCH_DISTANCE,
                );
                matches!(contact, Ok(Some(c)) if c.normal2.z >= SUPPORT_COS)
            })
    }

    pub fn under(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let aabb = self.aabb(a);
        let c = aabb.center();
        let up = self.ray_hits(
            a,
            Vector::new(c.x, c.y, aabb.maxs.z),
            Vector::Z,
            VERTICAL_RANGE,
        );
        let down = self.ray_hits(
            a,
            Vector::new(c.x, c.y, aabb.mins.z),
            -Vector::Z,
            VERTICAL_RANGE,
        );
        up.contains(&b) && !down.contains(&b)
    }

    pub fn inside(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let center = self.aabb(a).center();
        let container = self.aabb(b);
        if !container.contains_local_point(center) {
            return false;
        }
        let reach = (container.maxs - container.mins).length();
        let surrounded = [Vector::X, Vector::Y, Vector::Z]
            .into_iter()
            .filter(|&axis| {
                self.ray_hits(a, center, axis, reach).contains(&b)
                    && self.ray_hits(a, center, -axis, reach).contains(&b)
            })
            .count();
        surrounded >= 2
    }

    pub fn nextto(&self, a: ObjectId, b: ObjectId) -> bool {
        if a == b {
            return false;
        }
        let (ba, bb) = (self.aabb(a), self.aabb(b));
        let gap = (ba.mins - bb.maxs)
            .max(bb.mins - ba.maxs)
            .max(Vector::ZERO)
            .length();
        let extents = (ba.maxs - ba.mins) + (bb.maxs - bb.mins);
        let threshold = (extents.x + extents.y + extents.z) / 3.0 / 6.0;
        gap <= threshold && (self.sees_horizontally(a, b) || self.sees_horizontally(b, a))
    }

    fn sees_horizontally(&self, from: ObjectId, target: ObjectId) -> bool {
        let center = self.aabb(from).center();
        (0..HORIZONTAL_DIRECTIONS).any(|k| {
            let angle = k as f32 * std::f32::consts::TAU / HORIZONTAL_DIRECTIONS as f32;
            let dir = Vector::new(angle.cos(), angle.sin(), 0.0);
            self.ray_hits(from, center, dir, HORIZONTAL_RANGE)
                .contains(&target)
        })
    }

    pub fn onfloor(&self, a: ObjectId, floor: ObjectId) -> bool {
        let c = self.aabb(a).center();
        let room_floor = self.room_at(c.x, c.y).and_then(|r| r.floor);
        room_floor == Some(floor) && self.touching(a, floor)
    }

    /// The type of the room at the centre of the object's box.
    pub fn room_of(&self, a: ObjectId) -> Option<&str> {
        let c = self.aabb(a).center();
        self.room_at(c.x, c.y).map(|r| r.kind.as_str())
    }

    /// The first [`MAX_HITS`] objects other than `from` along a ray, nearest first.
    pub fn ray_hits(
        &self,
        from: ObjectId,
        origin: Vector,
        dir: Vector,
        range: f32,
    ) -> Vec<ObjectId> {
        let ray = Ray::new(origin, dir);
        let own = u128::from(from.0);
        let others = |_, c: &rapier3d::geometry::Collider| {
            c.user_data != own && c.user_data != DROP_TAG && c.is_enabled()
        };
        let filter = QueryFilter::default().predicate(&others);
        let mut hits: Vec<(f32, ObjectId)> = self
            .physics
            .intersect_ray(ray, range, true, filter)
            .map(|(_, collider, hit)| (hit.time_of_impact, ObjectId(collider.user_data as u32)))
            .collect();
        // Ties broken by id so the result never depends on the tree's traversal order.
        hits.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let mut objects: Vec<ObjectId> = Vec::with_capacity(MAX_HITS);
        for (_, id) in hits {
            if !objects.contains(&id) {
                objects.push(id);
                if objects.len() == MAX_HITS {
                    break;
                }
            }
        }
        objects
    }
}
