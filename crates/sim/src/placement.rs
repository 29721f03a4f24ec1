//! Placement helpers for sampling initial states: put an object on, in, under or next to another,
//! or on a room's floor, at a sampled collision-free pose where the relation holds.
//!
//! Each attempt draws a point over the target's footprint (inside its box, for `inside`; beside
//! one of its sides, up to [`NEXTTO_GAP`] away for `nextto` and within touching distance for
//! `touching`), finds the supporting surface below it by a ray cast (an upward-facing surface of
//! the target for `ontop` — looking down from its top or, for a shelf, from above one of its
//! boards — of the container or what already lies in it for `inside`, of anything
//! else for `under`, `nextto` and `touching`, of the floor for `onfloor`), sets the object on
//! it, 2 mm up, and accepts the pose if the object then overlaps nothing and the predicate holds.
//! The object keeps its orientation ([`World::place_jointly`]), or each attempt turns it about the
//! vertical by a random yaw, keeping its tilt (the resting orientation it was given) — as
//! iGibson's `sample_kinematics` does, with 10 attempts ([`World::place_turning`]); we allow
//! [`PLACEMENT_ATTEMPTS`]. For `touching` the object slides sideways until it touches the target
//! (turned boxes rarely touch where their bounding boxes do). An object asked to stand in several relations at once is
//! placed by the first, its centre drawn where the others' areas overlap it, and accepted only if
//! all hold ([`World::place_jointly`]); iGibson instead places by each literal in turn, the last
//! one winning. A sliced object is placed like a whole: its two halves move together, keeping
//! how they lie relative to each other. Settling is left to the caller, who usually places
//! several objects first ([`World::settle`]).

use crate::World;
use crate::bodies::Bodies;
use crate::core::Core;
use crate::kinematics::{RelationMemo, Relations};
use crate::object::ObjectId;
use crate::room::Room;
use behavior_core::FLOOR_SYNSET;
use behavior_core::rng::{SimRng, uniform};
use rand_chacha::rand_core::Rng;
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::query;
use rapier3d::prelude::Ray;
use std::fmt;

/// Poses tried before giving up: 20 until issue 40's homes, whose rooms are furnished as homes
/// are (a bed in every bedroom, chairs round the tables), left less free floor and fewer free
/// spots on crowded tables and counters; more attempts change only what used to fail.
pub const PLACEMENT_ATTEMPTS: usize = 100;
/// Gap left under a placed object (m); it lands within a step.
pub const DROP_GAP: f32 = 0.002;
/// The widest gap left beside a target for `nextto` (m); the predicate allows a sixth of the
/// two objects' mean extent.
pub const NEXTTO_GAP: f32 = 0.03;
/// Boards of a shelf closer than this (m) count as one level for `ontop`.
pub const LEVEL_SPACING: f32 = 0.1;
/// A support surface's normal must be this close to vertical.
pub const SUPPORT_NORMAL_Z: f32 = 0.7;
/// The gap a `touching` placement leaves between the two objects (m), within
/// [`crate::TOUCH_DISTANCE`].
pub const TOUCH_GAP: f32 = 0.002;

/// A kinematic relation a placement makes true.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Relation {
    /// `ontop`
    OnTop,
    /// `inside`
    Inside,
    /// `under`
    Under,
    /// `onfloor`
    OnFloor,
    /// `nextto`
    NextTo,
    /// `touching`
    Touching,
}

impl Relation {
    /// `nextto` and `touching` hold both ways round.
    pub fn is_symmetric(self) -> bool {
        matches!(self, Relation::NextTo | Relation::Touching)
    }

    /// The BDDL predicate's name.
    pub fn name(self) -> &'static str {
        match self {
            Relation::OnTop => "ontop",
            Relation::Inside => "inside",
            Relation::Under => "under",
            Relation::OnFloor => "onfloor",
            Relation::NextTo => "nextto",
            Relation::Touching => "touching",
        }
    }
}

/// Why a sampled pose was rejected.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlacementFailure {
    /// No relation was asked for.
    #[error("no relation asked for")]
    NothingAsked,
    /// An object was asked to stand in a relation to itself.
    #[error("an object cannot be placed relative to itself")]
    ToItself,
    /// The areas where the relations allow the object's centre do not overlap.
    #[error("the relations' areas do not overlap")]
    AreasDisjoint,
    /// For `under`: the target has no surface above the sampled point.
    #[error("the target has no underside there")]
    NoUnderside,
    /// Nothing facing up to rest on below the sampled point.
    #[error("no surface facing up below the sampled point")]
    NoSurface,
    /// The object would intersect another.
    #[error("it would overlap {other}")]
    Overlaps {
        /// The other object's name.
        other: String,
    },
    /// The pose was valid but a relation does not hold there.
    #[error("`{relation}` does not hold at the sampled pose")]
    DoesNotHold {
        /// The relation that failed.
        relation: Relation,
    },
}

/// A placement that found no pose in [`PLACEMENT_ATTEMPTS`] attempts; the object is back where
/// it was.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlacementError {
    /// The object's name.
    pub object: String,
    /// The relations asked for, with their targets' names.
    pub relations: Vec<(Relation, String)>,
    /// How many poses were tried.
    pub attempts: usize,
    /// Why the last one failed.
    pub reason: PlacementFailure,
}

impl fmt::Display for PlacementError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "could not place {}", self.object)?;
        for (k, (relation, target)) in self.relations.iter().enumerate() {
            let and = if k == 0 { "" } else { " and" };
            write!(f, "{and} {relation} {target}")?;
        }
        write!(f, " in {} attempts: {}", self.attempts, self.reason)
    }
}

impl std::error::Error for PlacementError {}

impl fmt::Display for Relation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl World {
    /// Places `object` in `relation` to `target` (see the module docs); returns the pose chosen.
    /// On failure the object is back where it was.
    ///
    /// ```
    /// use behavior_core::rng::seeded;
    /// use behavior_sim::{ObjectSpec, Part, Primitive, Relation, World};
    /// use rapier3d::math::Vector;
    ///
    /// let mut world = World::default();
    /// let top = Primitive::Box { half_extents: Vector::new(0.5, 0.4, 0.02) };
    /// let table = ObjectSpec::new("table_1", "table.n.02", vec![Part::at(top, Vector::new(0.0, 0.0, 0.75))]);
    /// let table = world.add(table.fixed()).unwrap();
    /// let ball = Part::new(Primitive::Sphere { radius: 0.04 });
    /// let apple = world.add(ObjectSpec::new("apple_1", "apple.n.01", vec![ball])).unwrap();
    /// world.place(apple, Relation::OnTop, table, &mut seeded(1)).unwrap();
    /// assert!(world.relations().ontop(apple, table));
    /// ```
    pub fn place(
        &mut self,
        object: ObjectId,
        relation: Relation,
        target: ObjectId,
        rng: &mut SimRng,
    ) -> Result<Pose, PlacementError> {
        Placer::new(&mut self.core).place_with(object, &[(relation, target)], Heading::Keep, rng)
    }

    /// Places `object`, as it is turned, so that every one of `relations` holds at once: the
    /// first picks the surface it rests on, the others narrow where its centre may go (to their
    /// target's footprint, or the floor's room) and must hold too — a shoe under a table and on
    /// the floor of the room that part of the table stands in. On failure the object is back
    /// where it was.
    pub fn place_jointly(
        &mut self,
        object: ObjectId,
        relations: &[(Relation, ObjectId)],
        rng: &mut SimRng,
    ) -> Result<Pose, PlacementError> {
        Placer::new(&mut self.core).place_with(object, relations, Heading::Keep, rng)
    }

    /// Places `object` so that every one of `relations` holds at once, each attempt at a random
    /// heading (see [`World::place_jointly`]): how the activity sampler places, as iGibson's does.
    /// A thing at least 1 m long set on a floor is turned by a random quarter turn instead, so
    /// that it stands square to the walls (a car across a garage closed the way to its shelves).
    pub fn place_turning(
        &mut self,
        object: ObjectId,
        relations: &[(Relation, ObjectId)],
        rng: &mut SimRng,
    ) -> Result<Pose, PlacementError> {
        Placer::new(&mut self.core).place_with(object, relations, Heading::Random, rng)
    }
}

/// How long a thing placed on a floor must be to be left square to the walls, m: the width of
/// a way between furniture.
const SQUARE_LENGTH: f32 = 1.0;

/// The turn that takes a box heading `now` (rad) to the quarter turn nearest `now + drawn`: a
/// random heading, square to the (axis-aligned) walls.
fn square_turn(now: f32, drawn: f32) -> f32 {
    let quarter = std::f32::consts::FRAC_PI_2;
    ((now + drawn) / quarter).round() * quarter - now
}

/// Which way a placed object faces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Heading {
    /// As it is turned now.
    Keep,
    /// Each attempt turns it about the vertical by a random yaw, keeping its tilt.
    Random,
}

/// One placement's access to the world: the bodies it moves and reads, and the relations it
/// checks.
struct Placer<'a> {
    bodies: &'a mut Bodies,
    memo: &'a RelationMemo,
    rooms: &'a [Room],
}

impl<'a> Placer<'a> {
    fn new(core: &'a mut Core) -> Placer<'a> {
        Placer {
            bodies: &mut core.bodies,
            memo: &core.memo,
            rooms: &core.rooms,
        }
    }

    fn relations(&self) -> Relations<'_> {
        Relations {
            bodies: self.bodies,
            memo: self.memo,
            rooms: self.rooms,
        }
    }

    /// Places `object` so that every one of `relations` holds at once: the first picks the
    /// surface it rests on, the others narrow where its centre may go (to their target's
    /// footprint, or the floor's room) and must hold too — a shoe under a table and on the floor of
    /// the room that part of the table stands in. `heading` says whether it keeps its orientation.
    /// On failure the object is back where it was.
    fn place_with(
        &mut self,
        object: ObjectId,
        relations: &[(Relation, ObjectId)],
        heading: Heading,
        rng: &mut SimRng,
    ) -> Result<Pose, PlacementError> {
        let original = self.bodies.pose(object);
        let mut reason = PlacementFailure::NothingAsked;
        if !relations.is_empty() {
            let square = self.squared_on_floor(object, relations);
            for _ in 0..PLACEMENT_ATTEMPTS {
                if heading == Heading::Random {
                    let drawn = uniform(rng, 0.0, std::f32::consts::TAU);
                    let yaw = Rotation::from_rotation_z(match square {
                        Some(now) => square_turn(now, drawn),
                        None => drawn,
                    });
                    let turned = Pose::from_parts(original.translation, yaw * original.rotation);
                    // A finite pose turned by a finite angle: the teleport cannot fail.
                    let _ = self.bodies.set_pose(object, turned);
                }
                match self.try_place(object, relations, rng) {
                    Ok(pose) => return Ok(pose),
                    Err(why) => reason = why,
                }
            }
        }
        // A pose that was valid before stays valid; restoring it cannot fail.
        let _ = self.bodies.set_pose(object, original);
        Err(PlacementError {
            object: self.bodies.object(object).name.clone(),
            relations: relations
                .iter()
                .map(|&(r, t)| (r, self.bodies.object(t).name.clone()))
                .collect(),
            attempts: PLACEMENT_ATTEMPTS,
            reason,
        })
    }

    /// For an object as long as a way is wide placed on a floor (a car, a pool, a sheet of
    /// plywood), the heading of its box now: such things are left square to the walls, as
    /// people park a car or lean a board, and one turned across a garage at random closed the
    /// way to its shelves. `None` for everything else, which turns freely.
    fn squared_on_floor(
        &self,
        object: ObjectId,
        relations: &[(Relation, ObjectId)],
    ) -> Option<f32> {
        let &(_, support) = relations.first()?;
        if self.bodies.object(support).category != FLOOR_SYNSET {
            return None;
        }
        let rotation = self.bodies.pose(object).rotation;
        let local = self.bodies.local_aabb(object);
        let size = local.maxs - local.mins;
        // The box's axes that stay level after its resting orientation, with their lengths.
        let level: Vec<(Vector, f32)> = [Vector::X, Vector::Y, Vector::Z]
            .into_iter()
            .zip(size.to_array())
            .map(|(axis, length)| (rotation * axis, length))
            .filter(|(world_axis, _)| world_axis.z.abs() < 0.5)
            .collect();
        let longest = level.iter().map(|&(_, l)| l).fold(0.0, f32::max);
        let &(axis, _) = level.first()?;
        (longest >= SQUARE_LENGTH).then(|| axis.y.atan2(axis.x))
    }

    fn try_place(
        &mut self,
        object: ObjectId,
        relations: &[(Relation, ObjectId)],
        rng: &mut SimRng,
    ) -> Result<Pose, PlacementFailure> {
        let request = Request::new(self.bodies, object, relations);
        if relations
            .iter()
            .any(|&(_, t)| t == object || request.members.contains(&t))
        {
            return Err(PlacementFailure::ToItself);
        }
        let (x, y) = self.sample_xy(&request, rng)?;
        let start_z = self.start_height(&request, (x, y), rng)?;
        let support = self
            .support_height(&request, (x, y), start_z)
            .ok_or(PlacementFailure::NoSurface)?;
        let bottom_center = Vector::new(x, y, support + DROP_GAP + request.half.z);
        let mut candidate =
            Pose::from_parts(bottom_center - request.center_offset, request.rotation);
        let touching = request
            .relations
            .iter()
            .find(|(r, _)| *r == Relation::Touching);
        if let Some(&(_, target)) = touching {
            candidate = self.slide_into_touch(&request, candidate, target);
        }
        if let Some(other) = self.overlap_at(&request, candidate) {
            return Err(PlacementFailure::Overlaps {
                other: self.bodies.object(other).name.clone(),
            });
        }
        // The candidate is built from finite values, so the teleport cannot fail.
        let _ = self.bodies.set_pose(object, candidate);
        match relations.iter().find(|&&(r, t)| !self.holds(object, r, t)) {
            Some(&(relation, _)) => Err(PlacementFailure::DoesNotHold { relation }),
            None => Ok(candidate),
        }
    }

    fn holds(&self, object: ObjectId, relation: Relation, target: ObjectId) -> bool {
        match relation {
            Relation::OnTop => self.relations().ontop(object, target),
            Relation::Inside => self.relations().inside(object, target),
            Relation::Under => self.relations().under(object, target),
            Relation::OnFloor => self.relations().onfloor(object, target),
            Relation::NextTo => self.relations().nextto(object, target),
            Relation::Touching => self.relations().touching(object, target),
        }
    }

    /// Where the object's centre may go for a relation: over the target (in its room, for a
    /// floor), or around it for `nextto` and `touching`.
    fn area_of(&self, request: &Request, relation: Relation, target: ObjectId) -> Aabb {
        match relation {
            Relation::OnFloor => self.floor_area(target),
            Relation::NextTo | Relation::Touching => self
                .bodies
                .aabb(target)
                .loosened(request.half.max_element() + NEXTTO_GAP),
            _ => self.bodies.aabb(target),
        }
    }

    /// A point (x, y) for the object's centre: beside the target for the symmetric relations,
    /// over it otherwise, within the bounds the other relations set.
    fn sample_xy(
        &self,
        request: &Request,
        rng: &mut SimRng,
    ) -> Result<(f32, f32), PlacementFailure> {
        let (relation, target) = request.relations[0];
        let half = request.half;
        // The other relations only bound the centre: the object may reach beyond their area.
        let (mut x0, mut x1, mut y0, mut y1) = (f32::MIN, f32::MAX, f32::MIN, f32::MAX);
        for &(r, t) in &request.relations[1..] {
            let other = self.area_of(request, r, t);
            (x0, x1) = (x0.max(other.mins.x), x1.min(other.maxs.x));
            (y0, y1) = (y0.max(other.mins.y), y1.min(other.maxs.y));
        }
        let (x, y) = if relation.is_symmetric() {
            beside(&self.bodies.aabb(target), half, relation, rng)
        } else {
            let area = self.area_of(request, relation, target);
            let span = |lo: f32, hi: f32, h: f32| {
                if hi - lo > 2.0 * h {
                    (lo + h, hi - h)
                } else {
                    ((lo + hi) * 0.5, (lo + hi) * 0.5)
                }
            };
            let (a0, a1) = span(area.mins.x, area.maxs.x, half.x);
            let (b0, b1) = span(area.mins.y, area.maxs.y, half.y);
            (x0, x1, y0, y1) = (x0.max(a0), x1.min(a1), y0.max(b0), y1.min(b1));
            if x0 > x1 || y0 > y1 {
                return Err(PlacementFailure::AreasDisjoint);
            }
            (uniform(rng, x0, x1), uniform(rng, y0, y1))
        };
        if !(x0..=x1).contains(&x) || !(y0..=y1).contains(&y) {
            return Err(PlacementFailure::AreasDisjoint);
        }
        Ok((x, y))
    }

    /// The height from which to look down for a surface to rest on.
    fn start_height(
        &self,
        request: &Request,
        (x, y): (f32, f32),
        rng: &mut SimRng,
    ) -> Result<f32, PlacementFailure> {
        let (relation, target) = request.relations[0];
        let area = self.bodies.aabb(target);
        Ok(match relation {
            Relation::OnTop => {
                let levels = self.support_levels(target);
                levels[rng.next_u32() as usize % levels.len()] + 0.01
            }
            Relation::OnFloor => self.area_of(request, relation, target).maxs.z + 0.01,
            Relation::NextTo | Relation::Touching => area.maxs.z + 0.01,
            Relation::Inside => {
                let lowest = area.mins.z + request.half.z;
                uniform(rng, lowest, area.maxs.z.max(lowest))
            }
            // Just below the target's underside at (x, y).
            Relation::Under => {
                self.underside(target, x, y, area.mins.z - 1.0)
                    .ok_or(PlacementFailure::NoUnderside)?
                    - 0.001
            }
        })
    }

    /// The height of the surface the object will rest on below (x, y, start_z): the target's for
    /// `ontop` and `onfloor`; else whatever is there — the floor, what the target stands on, or
    /// (inside) the container's floor or what already lies in it.
    fn support_height(&self, request: &Request, (x, y): (f32, f32), start_z: f32) -> Option<f32> {
        let (relation, target) = request.relations[0];
        match relation {
            Relation::OnTop | Relation::OnFloor => self.surface_below(&[target], x, y, start_z),
            Relation::Under | Relation::NextTo | Relation::Touching | Relation::Inside => {
                let others: Vec<ObjectId> = self
                    .bodies
                    .objects()
                    .map(|(id, _)| id)
                    .filter(|&id| {
                        !request.is_moved(id) && (id != target || relation == Relation::Inside)
                    })
                    .collect();
                self.surface_below(&others, x, y, start_z)
            }
        }
    }

    /// Heights from which `ontop` looks down for a surface of `target`: its top, and for anything
    /// without doors, drawers or lids the top of each of its parts below (a shelf's boards, a
    /// sofa's seat, a sink's basin — where `ontop` holds too), tops less than [`LEVEL_SPACING`]
    /// apart counting as one. Closed furniture offers its top only, so nothing sampled `ontop` a
    /// cabinet ends up shut inside it.
    fn support_levels(&self, target: ObjectId) -> Vec<f32> {
        let object = self.bodies.object(target);
        let top = self.bodies.aabb(target).maxs.z;
        if !object.links.is_empty() {
            return vec![top];
        }
        let mut tops: Vec<f32> = object
            .colliders
            .iter()
            .map(|&c| self.bodies.physics.colliders[c].compute_aabb().maxs.z)
            .collect();
        tops.sort_by(|a, b| b.total_cmp(a));
        let mut levels = vec![top];
        for t in tops {
            if levels.last().is_some_and(|&l| l - t >= LEVEL_SPACING) {
                levels.push(t);
            }
        }
        levels
    }

    /// The footprint of the room whose floor `floor` is (at the floor's top), or the floor's box.
    fn floor_area(&self, floor: ObjectId) -> Aabb {
        let aabb = self.bodies.aabb(floor);
        match self.rooms.iter().find(|r| r.floor == Some(floor)) {
            // An L-shaped room's box: a point drawn in its notch finds no floor below and is
            // drawn again.
            Some(room) => {
                let b = room.bounds();
                Aabb::new(
                    Vector::new(b.min[0], b.min[1], aabb.mins.z),
                    Vector::new(b.max[0], b.max[1], aabb.maxs.z),
                )
            }
            None => aabb,
        }
    }

    /// The height of the first upward-facing surface of `among` straight below (x, y, z).
    fn surface_below(&self, among: &[ObjectId], x: f32, y: f32, z: f32) -> Option<f32> {
        let ray = Ray::new(Vector::new(x, y, z), -Vector::Z);
        let mut best: Option<(f32, f32)> = None;
        for &id in among {
            if !self.bodies.present(id) {
                continue;
            }
            for &c in &self.bodies.object(id).colliders {
                let c = &self.bodies.physics.colliders[c];
                if !c.is_enabled() {
                    continue;
                }
                if let Some(hit) = c
                    .shape()
                    .cast_ray_and_get_normal(c.position(), &ray, 50.0, true)
                    && best.is_none_or(|(t, _)| hit.time_of_impact < t)
                {
                    best = Some((hit.time_of_impact, hit.normal.z));
                }
            }
        }
        let (t, normal_z) = best?;
        (normal_z >= SUPPORT_NORMAL_Z).then_some(z - t)
    }

    /// The height of the target's lowest surface above (x, y, z), seen from below.
    fn underside(&self, target: ObjectId, x: f32, y: f32, z: f32) -> Option<f32> {
        let ray = Ray::new(Vector::new(x, y, z), Vector::Z);
        self.bodies
            .object(target)
            .colliders
            .iter()
            .map(|&c| &self.bodies.physics.colliders[c])
            .filter(|c| c.is_enabled())
            .filter_map(|c| c.shape().cast_ray(c.position(), &ray, 100.0, true))
            .min_by(f32::total_cmp)
            .map(|t| z + t)
    }

    /// The candidate slid sideways toward `target` until the two are within
    /// [`TOUCH_GAP`] of each other, where they are not already (a few steps of closing the
    /// horizontal part of the gap between their closest points).
    fn slide_into_touch(&self, request: &Request, candidate: Pose, target: ObjectId) -> Pose {
        let mut pose = candidate;
        for _ in 0..4 {
            let Some((distance, from, to)) = self.closest_at(request, pose, target) else {
                break;
            };
            let mut across = to - from;
            across.z = 0.0;
            if distance <= TOUCH_GAP || across.length() < 1e-6 {
                break;
            }
            pose.translation += across * (1.0 - TOUCH_GAP / distance);
        }
        pose
    }

    /// The distance and the closest points (on the object, on `target`) if the object stood at
    /// `pose`, within 0.5 m.
    fn closest_at(
        &self,
        request: &Request,
        pose: Pose,
        target: ObjectId,
    ) -> Option<(f32, Vector, Vector)> {
        let shift = pose * self.bodies.pose(request.object).inverse();
        let mut best: Option<(f32, Vector, Vector)> = None;
        let colliders = &self.bodies.physics.colliders;
        for &m in &request.members {
            for &c in &self.bodies.object(m).colliders {
                let (c, at) = (&colliders[c], shift * colliders[c].position());
                for &t in &self.bodies.object(target).colliders {
                    let t = &colliders[t];
                    let found = query::closest_points(&at, c.shape(), t.position(), t.shape(), 0.5);
                    if let Ok(query::ClosestPoints::WithinMargin(p, q)) = found {
                        let d = (q - p).length();
                        if best.is_none_or(|(b, ..)| d < b) {
                            best = Some((d, p, q));
                        }
                    }
                }
            }
        }
        best
    }

    /// Some other object that the request's object (its halves, if sliced) would intersect if
    /// it stood at `pose`.
    fn overlap_at(&self, request: &Request, pose: Pose) -> Option<ObjectId> {
        // The rigid move from where the object stands to `pose`, applied to every collider.
        let shift = pose * self.bodies.pose(request.object).inverse();
        let moved: Vec<(Pose, &rapier3d::geometry::Collider)> = request
            .members
            .iter()
            .flat_map(|&m| &self.bodies.object(m).colliders)
            .map(|&c| {
                let c = &self.bodies.physics.colliders[c];
                (shift * c.position(), c)
            })
            .collect();
        for (id, other) in self.bodies.objects() {
            if request.is_moved(id) || !self.bodies.present(id) {
                continue;
            }
            for &oc in &other.colliders {
                let oc = &self.bodies.physics.colliders[oc];
                if !oc.is_enabled() {
                    continue;
                }
                let other_box = oc.compute_aabb();
                for (p, c) in &moved {
                    if !c.shape().compute_aabb(p).intersects(&other_box) {
                        continue;
                    }
                    if query::intersection_test(p, c.shape(), oc.position(), oc.shape())
                        .map_or(true, |i| i.intersecting)
                    {
                        return Some(id);
                    }
                }
            }
        }
        None
    }
}

/// What one placement attempt asks, with the object's box as it stands.
struct Request<'r> {
    object: ObjectId,
    /// What moves: the object, or its two halves if it was sliced.
    members: Vec<ObjectId>,
    relations: &'r [(Relation, ObjectId)],
    /// Half the object's box.
    half: Vector,
    /// Where the object's box centre sits relative to its pose's origin.
    center_offset: Vector,
    /// Its orientation, kept.
    rotation: rapier3d::math::Rotation,
}

impl<'r> Request<'r> {
    fn new(
        bodies: &Bodies,
        object: ObjectId,
        relations: &'r [(Relation, ObjectId)],
    ) -> Request<'r> {
        let pose = bodies.pose(object);
        let members = match bodies.object(object).replaced_by {
            Some(halves) => halves.to_vec(),
            None => vec![object],
        };
        let mut own = bodies.aabb(members[0]);
        for &m in &members[1..] {
            own.merge(&bodies.aabb(m));
        }
        Request {
            object,
            members,
            relations,
            half: (own.maxs - own.mins) * 0.5,
            center_offset: own.center() - pose.translation,
            rotation: pose.rotation,
        }
    }
}

impl Request<'_> {
    /// Whether the placement moves `id` (the object or one of its halves).
    fn is_moved(&self, id: ObjectId) -> bool {
        id == self.object || self.members.contains(&id)
    }
}

/// A centre beside one of the target box's four sides, a small gap away, facing some part of it.
fn beside(area: &Aabb, half: Vector, relation: Relation, rng: &mut SimRng) -> (f32, f32) {
    let gap = match relation {
        Relation::NextTo => uniform(rng, 0.005, NEXTTO_GAP),
        _ => uniform(rng, 0.0005, 0.8 * crate::kinematics::TOUCH_DISTANCE),
    };
    match rng.next_u32() % 4 {
        0 => (
            area.maxs.x + gap + half.x,
            uniform(rng, area.mins.y, area.maxs.y),
        ),
        1 => (
            area.mins.x - gap - half.x,
            uniform(rng, area.mins.y, area.maxs.y),
        ),
        2 => (
            uniform(rng, area.mins.x, area.maxs.x),
            area.maxs.y + gap + half.y,
        ),
        _ => (
            uniform(rng, area.mins.x, area.maxs.x),
            area.mins.y - gap - half.y,
        ),
    }
}
