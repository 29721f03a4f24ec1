//! Questions about space asked without stepping: the first thing a ray hits, many rays at once
//! (lidar), which bodies a shape at some pose would overlap, and how far the nearest one is
//! (motion planning).
//!
//! Queries run against a bounding-volume hierarchy over every collider (parry's `Bvh`), built on
//! the first query after anything moved and kept until the next change, so a planner that asks a
//! thousand questions of one configuration pays for one build. It never uses rapier's broad phase,
//! which lags teleports until the next physics step. The index (`QueryIndex`) is kept with the
//! bodies, whose moves invalidate it; [`Query`] is the view that asks it.

use crate::bodies::Bodies;
use crate::construct::colliders_of;
use crate::core::{WorldError, pose_is_finite, untag};
use crate::object::{BodyRef, ObjectId, Part, Primitive};
use rapier3d::geometry::{Collider, ColliderHandle};
use rapier3d::math::{Pose, Vector};
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::partitioning::{Bvh, BvhBuildStrategy};
use rapier3d::parry::query;
use rapier3d::pipeline::PhysicsWorld;
use rapier3d::prelude::Ray;
use serde::{Deserialize, Serialize};
use std::sync::OnceLock;

/// What a query ignores.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct QueryFilter {
    /// Objects to ignore entirely (the robot itself).
    pub exclude_objects: Vec<ObjectId>,
    /// Single bodies to ignore (a hand, the object it holds).
    pub exclude_bodies: Vec<BodyRef>,
    /// Whether water drops count (they are ignored by default).
    pub include_drops: bool,
    /// Only the bodies of fixed objects (walls, floors, furniture) count. Such queries are
    /// answered from an index of fixed bodies that survives steps (it changes only when objects
    /// are added, retired or teleported), so a robot checking its moves against walls every step
    /// does not rebuild an index of the whole, moving world.
    #[serde(default)]
    pub fixed_only: bool,
}

impl QueryFilter {
    /// Ignores these objects.
    pub fn excluding(objects: &[ObjectId]) -> QueryFilter {
        QueryFilter {
            exclude_objects: objects.to_vec(),
            ..QueryFilter::default()
        }
    }

    fn admits(&self, collider: &Collider) -> bool {
        if !collider.is_enabled() {
            return false;
        }
        match untag(collider.user_data) {
            None => self.include_drops,
            Some(body) => {
                !self.exclude_objects.contains(&body.object) && !self.exclude_bodies.contains(&body)
            }
        }
    }
}

/// The first hit of a ray.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RayHit {
    /// The body hit, or `None` for a water drop.
    pub body: Option<BodyRef>,
    /// Along the ray, m.
    pub distance: f32,
    /// Where, in the world.
    pub point: Vector,
    /// The surface's outward normal there.
    pub normal: Vector,
}

/// The nearest body to a shape.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Proximity {
    /// The body.
    pub body: BodyRef,
    /// The gap between them, m; 0 when they overlap.
    pub distance: f32,
}

/// Every enabled collider (or every fixed one) in a bounding-volume hierarchy.
#[derive(Clone)]
struct Tree {
    bvh: Bvh,
    colliders: Vec<ColliderHandle>,
}

impl Tree {
    /// Over every enabled collider, or only over those of fixed bodies.
    fn build(physics: &PhysicsWorld, fixed_only: bool) -> Tree {
        let bodies = &physics.bodies;
        let fixed = |c: &Collider| c.parent().is_some_and(|b| bodies[b].is_fixed());
        let (colliders, boxes): (Vec<ColliderHandle>, Vec<Aabb>) = physics
            .colliders
            .iter()
            .filter(|(_, c)| c.is_enabled() && (!fixed_only || fixed(c)))
            .map(|(h, c)| (h, c.compute_aabb()))
            .unzip();
        Tree {
            bvh: Bvh::from_leaves(BvhBuildStrategy::Binned, &boxes),
            colliders,
        }
    }
}

/// The query structures: one over every collider, dropped whenever a collider may have moved
/// (each physics substep, a teleport, a part moved on its body), and one over fixed bodies only,
/// dropped only when objects are added, retired or teleported. Each is built on first use.
#[derive(Clone, Default)]
pub(crate) struct QueryIndex {
    all: OnceLock<Tree>,
    fixed: OnceLock<Tree>,
}

impl QueryIndex {
    /// Drops both structures: objects were added, retired or teleported.
    pub(crate) fn clear(&mut self) {
        *self = QueryIndex::default();
    }

    /// Drops the structure over every collider: something may have moved.
    pub(crate) fn clear_moving(&mut self) {
        self.all = OnceLock::new();
    }

    fn tree(&self, physics: &PhysicsWorld, fixed_only: bool) -> &Tree {
        let cell = if fixed_only { &self.fixed } else { &self.all };
        cell.get_or_init(|| Tree::build(physics, fixed_only))
    }
}

/// Questions about space: rays, overlaps, nearest bodies, and an object's collision shapes.
/// Reached through [`crate::World::query`].
#[derive(Clone, Copy)]
pub struct Query<'w> {
    pub(crate) bodies: &'w Bodies,
}

impl<'w> Query<'w> {
    /// The first thing a ray from `origin` along `direction` hits within `max_distance`.
    pub fn cast_ray(
        &self,
        origin: Vector,
        direction: Vector,
        max_distance: f32,
        filter: &QueryFilter,
    ) -> Result<Option<RayHit>, WorldError> {
        let ray = checked_ray(origin, direction, max_distance)?;
        Ok(self.first_hit(&ray, max_distance, filter))
    }

    /// Many rays at once (a lidar sweep): the first hit of each, in order.
    pub fn cast_rays(
        &self,
        rays: &[(Vector, Vector)],
        max_distance: f32,
        filter: &QueryFilter,
    ) -> Result<Vec<Option<RayHit>>, WorldError> {
        let rays: Vec<Ray> = rays
            .iter()
            .map(|&(o, d)| checked_ray(o, d, max_distance))
            .collect::<Result<_, _>>()?;
        Ok(rays
            .iter()
            .map(|ray| self.first_hit(ray, max_distance, filter))
            .collect())
    }

    fn first_hit(&self, ray: &Ray, max_distance: f32, filter: &QueryFilter) -> Option<RayHit> {
        let physics = &self.bodies.physics;
        let index = self.bodies.index.tree(physics, false);
        let colliders = &physics.colliders;
        let (leaf, distance) = index.bvh.cast_ray(ray, max_distance, |leaf, best| {
            let c = &colliders[index.colliders[leaf as usize]];
            if !filter.admits(c) {
                return None;
            }
            c.shape().cast_ray(c.position(), ray, best, true)
        })?;
        let c = &colliders[index.colliders[leaf as usize]];
        let normal = c
            .shape()
            .cast_ray_and_get_normal(c.position(), ray, distance + 1e-4, true)
            .map_or(-ray.dir, |hit| hit.normal);
        Some(RayHit {
            body: untag(c.user_data),
            distance,
            point: ray.point_at(distance),
            normal,
        })
    }

    /// An object's collision shapes (its body's and its links'), each posed in the world as it
    /// is now: what moves with it, for checking it at other poses with [`Query::overlaps`].
    /// Unlike [`crate::Visuals::parts`], never visual meshes. Nothing for an object no longer
    /// present.
    pub fn collision_parts(&self, id: ObjectId) -> Vec<(&'w Primitive, Pose)> {
        let bodies = self.bodies;
        let object = bodies.object(id);
        if !object.is_present() {
            return Vec::new();
        }
        let body = object.parts.iter().map(|p| (p, bodies.pose(id)));
        // A link's parts are given in the object's frame at zero joint position; its body
        // started at the object's pose, so its current pose maps them.
        let links = object.links.iter().enumerate().flat_map(|(l, link)| {
            let frame = bodies.link_pose(id, l);
            link.parts.iter().map(move |p| (p, frame))
        });
        body.chain(links)
            .map(|(part, frame)| (&part.primitive, frame * part.offset))
            .collect()
    }

    /// The bodies that a shape at `pose` would overlap, each once, in id order.
    pub fn overlaps(
        &self,
        shape: &Primitive,
        pose: Pose,
        filter: &QueryFilter,
    ) -> Result<Vec<BodyRef>, WorldError> {
        let probe = probe(shape, pose)?;
        let mut hits: Vec<BodyRef> = self
            .near(&probe, 0.0, filter)
            .filter(|c| {
                query::intersection_test(probe.position(), probe.shape(), c.position(), c.shape())
                    .map_or(true, |i| i.intersecting)
            })
            .filter_map(|c| untag(c.user_data))
            .collect();
        hits.sort();
        hits.dedup();
        Ok(hits)
    }

    /// The nearest body within `max_distance` of a shape at `pose`.
    pub fn nearest(
        &self,
        shape: &Primitive,
        pose: Pose,
        max_distance: f32,
        filter: &QueryFilter,
    ) -> Result<Option<Proximity>, WorldError> {
        if !(max_distance.is_finite() && max_distance >= 0.0) {
            return Err(WorldError::NotFinite {
                what: "a query's distance",
                value: max_distance,
            });
        }
        let probe = probe(shape, pose)?;
        let mut best: Option<Proximity> = None;
        for c in self.near(&probe, max_distance, filter) {
            let Some(body) = untag(c.user_data) else {
                continue;
            };
            // A contact query with the search radius as its margin: parry's cuboid distance
            // overestimates the gap between slightly turned boxes.
            let found = query::contact(
                probe.position(),
                probe.shape(),
                c.position(),
                c.shape(),
                max_distance,
            );
            let Ok(Some(contact)) = found else {
                continue;
            };
            let d = contact.dist.max(0.0);
            let better = best.is_none_or(|b| d < b.distance || (d == b.distance && body < b.body));
            if d <= max_distance && better {
                best = Some(Proximity { body, distance: d });
            }
        }
        Ok(best)
    }

    /// Admitted colliders whose boxes come within `margin` of the probe's.
    fn near<'a>(
        &self,
        probe: &Collider,
        margin: f32,
        filter: &'a QueryFilter,
    ) -> impl Iterator<Item = &'w Collider> + 'a
    where
        'w: 'a,
    {
        let physics = &self.bodies.physics;
        let index = self.bodies.index.tree(physics, filter.fixed_only);
        let area = probe.compute_aabb().loosened(margin);
        let leaves: Vec<u32> = index.bvh.intersect_aabb(&area).collect();
        leaves
            .into_iter()
            .map(move |leaf| &physics.colliders[index.colliders[leaf as usize]])
            .filter(move |c| filter.admits(c))
    }
}

fn checked_ray(origin: Vector, direction: Vector, max_distance: f32) -> Result<Ray, WorldError> {
    let length = direction.length();
    if !(origin.is_finite() && length.is_finite() && length > 1e-9) {
        return Err(WorldError::NotFinite {
            what: "a ray's origin and non-zero direction",
            value: length,
        });
    }
    if !(max_distance.is_finite() && max_distance >= 0.0) {
        return Err(WorldError::NotFinite {
            what: "a ray's length",
            value: max_distance,
        });
    }
    Ok(Ray::new(origin, direction / length))
}

/// A free collider for a query shape at a pose.
/// A collision primitive built once, for tests between shapes that are not where the world
/// has them: a robot's links against what its gripper holds, at configurations the arm has not
/// taken.
#[derive(Clone, Debug)]
pub struct Solid {
    collider: Collider,
}

impl Solid {
    /// `shape`, placed at `offset` in the frame it will be posed by.
    pub fn new(shape: &Primitive, offset: Pose) -> Result<Solid, WorldError> {
        Ok(Solid {
            collider: probe(shape, offset)?,
        })
    }

    /// The solid's box with its frame at `at`: its lowest and highest corners.
    pub fn aabb(&self, at: Pose) -> (Vector, Vector) {
        let b = self
            .collider
            .shape()
            .compute_aabb(&(at * *self.collider.position()));
        (b.mins, b.maxs)
    }

    /// Whether this solid with its frame at `at` overlaps `other` with its frame at
    /// `other_at` (touching counts; unknown pairs of shapes count as overlapping).
    pub fn intersects(&self, at: Pose, other: &Solid, other_at: Pose) -> bool {
        let a = at * *self.collider.position();
        let b = other_at * *other.collider.position();
        query::intersection_test(&a, self.collider.shape(), &b, other.collider.shape())
            .map_or(true, |i| i.intersecting)
    }
}

fn probe(shape: &Primitive, pose: Pose) -> Result<Collider, WorldError> {
    let bad = || WorldError::BadObject {
        name: "query shape".into(),
        reason: "its size or pose is not finite and positive".into(),
    };
    if !pose_is_finite(&pose) {
        return Err(bad());
    }
    let mut colliders = colliders_of(&[Part::new(shape.clone())], 1.0, 0.0, 0).ok_or_else(bad)?;
    let mut probe = colliders.pop().ok_or_else(bad)?;
    probe.set_position(pose);
    Ok(probe)
}
