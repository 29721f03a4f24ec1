//! Dust and stains as particles on surfaces, and cleaning.
//!
//! Making an object dusty (or stained) places 20 particles on its upward-facing surfaces, found by
//! casting rays down onto it on a jittered grid over its footprint; they are fixed in the object's
//! frame and move with it. The object is dusty while more than 50 % of the particles ever placed
//! remain (75 % for floors), as in iGibson 2.0 (§1.6; iGibson also uses side faces).
//!
//! Each step, a cleaning tool that touches a dirty object removes the particles inside its box,
//! grown by 1 cm (and, if the tool names a cleaning area, within 10 cm of it); stains only come
//! off when the tool is soaked.

use crate::core::Core;
use crate::object::{ObjectId, PointKind};
use crate::states::StateError;
use crate::states::water::Water;
use behavior_core::{Ability, FLOOR_SYNSET, Predicate};
use rapier3d::math::Vector;
use rapier3d::parry::bounding_volume::BoundingVolume;

/// Particles placed on a newly dirty object.
pub const PARTICLES_PER_SET: usize = 20;
/// Fewer successful placements than this and the setter fails (iGibson's minimum).
pub const MIN_PARTICLES: usize = 5;
/// An object is dirty while more than this fraction of its particles remain.
pub const CLEAN_THRESHOLD: f32 = 0.5;
/// The same for floors.
pub const FLOOR_CLEAN_THRESHOLD: f32 = 0.75;
/// How far beyond its box a cleaning tool wipes (m).
pub const WIPE_MARGIN: f32 = 0.01;
/// With a [`PointKind::CleaningArea`], only particles this close to it are wiped (m).
pub const CLEANING_REACH: f32 = 0.1;

/// Particles of one kind on one object, in the object's frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct ParticleSet {
    points: Vec<Vector>,
    /// How many were placed when the set was last made.
    placed: usize,
}

/// The dirt system: each object's dust and stain particles.
#[derive(Clone, Debug, Default)]
pub(crate) struct Dirt {
    dust: Vec<ParticleSet>,
    stain: Vec<ParticleSet>,
}

impl Dirt {
    pub(crate) fn add_object(&mut self) {
        self.dust.push(ParticleSet::default());
        self.stain.push(ParticleSet::default());
    }

    fn set(&self, id: ObjectId, kind: Predicate) -> &ParticleSet {
        let sets = if kind == Predicate::Dusty {
            &self.dust
        } else {
            &self.stain
        };
        &sets[id.0 as usize]
    }

    fn set_mut(&mut self, id: ObjectId, kind: Predicate) -> &mut ParticleSet {
        let sets = if kind == Predicate::Dusty {
            &mut self.dust
        } else {
            &mut self.stain
        };
        &mut sets[id.0 as usize]
    }

    /// A half made by slicing keeps the whole's particles, in its own frame.
    pub(crate) fn inherit(&mut self, from: ObjectId, to: ObjectId) {
        for kind in [Predicate::Dusty, Predicate::Stained] {
            let whole = self.set(from, kind).clone();
            *self.set_mut(to, kind) = whole;
        }
    }

    /// Particles of an object in world coordinates.
    pub(crate) fn positions(&self, core: &Core, id: ObjectId, kind: Predicate) -> Vec<Vector> {
        let pose = core.pose(id);
        self.set(id, kind)
            .points
            .iter()
            .map(|&p| pose.transform_point(p))
            .collect()
    }

    pub(crate) fn is_dirty(&self, core: &Core, id: ObjectId, kind: Predicate) -> bool {
        let set = self.set(id, kind);
        let threshold = if core.object(id).category == FLOOR_SYNSET {
            FLOOR_CLEAN_THRESHOLD
        } else {
            CLEAN_THRESHOLD
        };
        set.placed > 0 && set.points.len() as f32 > threshold * set.placed as f32
    }

    pub(crate) fn set_dirty(
        &mut self,
        core: &Core,
        id: ObjectId,
        kind: Predicate,
        dirty: bool,
    ) -> Result<(), StateError> {
        if !dirty {
            *self.set_mut(id, kind) = ParticleSet::default();
            return Ok(());
        }
        let points = sample_top_surface(core, id, kind as u64);
        if points.len() < MIN_PARTICLES {
            return Err(StateError::Unsupported {
                object: core.object(id).name.clone(),
                predicate: kind,
                value: true,
                reason: format!(
                    "only {} of {PARTICLES_PER_SET} particles found a surface facing up",
                    points.len()
                ),
            });
        }
        let placed = points.len();
        *self.set_mut(id, kind) = ParticleSet { points, placed };
        Ok(())
    }

    /// One step of cleaning: every cleaning tool wipes what it touches.
    pub(crate) fn update(&mut self, core: &Core, water: &Water) {
        let tools: Vec<ObjectId> = core
            .objects()
            .filter(|(_, o)| o.has(Ability::CleaningTool))
            .map(|(id, _)| id)
            .collect();
        for tool in tools {
            let area = core.aabb(tool).loosened(WIPE_MARGIN);
            let face = core
                .object(tool)
                .point(PointKind::CleaningArea)
                .map(|p| core.pose(tool).transform_point(p));
            let wipes = |p: Vector| {
                area.contains_local_point(p)
                    && face.is_none_or(|f| (p - f).length() <= CLEANING_REACH)
            };
            let kinds: &[Predicate] = if water.is_soaked(tool) {
                &[Predicate::Dusty, Predicate::Stained]
            } else {
                &[Predicate::Dusty]
            };
            for (dirty, _) in core.objects() {
                let clean = self.dust[dirty.0 as usize].points.is_empty()
                    && self.stain[dirty.0 as usize].points.is_empty();
                if dirty == tool || clean || !core.touching(tool, dirty) {
                    continue;
                }
                let pose = core.pose(dirty);
                for &kind in kinds {
                    self.set_mut(dirty, kind)
                        .points
                        .retain(|&p| !wipes(pose.transform_point(p)));
                }
            }
        }
    }
}

/// Up to [`PARTICLES_PER_SET`] points on the object's surfaces that face up, in its frame.
fn sample_top_surface(core: &Core, id: ObjectId, salt: u64) -> Vec<Vector> {
    let aabb = core.aabb(id);
    let pose = core.pose(id);
    let (cols, rows) = (5, 4);
    let mut points = Vec::new();
    for k in 0..cols * rows {
        // A fixed jitter per cell (a hash of object, kind and cell) keeps placement repeatable.
        let h = splitmix(u64::from(id.0) << 32 ^ salt << 16 ^ k as u64);
        let (jx, jy) = (
            (h & 0xffff) as f32 / 65535.0,
            (h >> 16 & 0xffff) as f32 / 65535.0,
        );
        let fx = ((k % cols) as f32 + 0.1 + 0.8 * jx) / cols as f32;
        let fy = ((k / cols) as f32 + 0.1 + 0.8 * jy) / rows as f32;
        let x = aabb.mins.x + fx * (aabb.maxs.x - aabb.mins.x);
        let y = aabb.mins.y + fy * (aabb.maxs.y - aabb.mins.y);
        let top = Vector::new(x, y, aabb.maxs.z + 0.01);
        let colliders = &core.object(id).colliders;
        let hit = colliders
            .iter()
            .filter_map(|&c| {
                let c = &core.physics.colliders[c];
                let ray = rapier3d::prelude::Ray::new(top, -Vector::Z);
                let range = aabb.maxs.z - aabb.mins.z + 0.02;
                c.shape()
                    .cast_ray_and_get_normal(c.position(), &ray, range, true)
                    .filter(|hit| hit.normal.z > 0.5)
                    .map(|hit| hit.time_of_impact)
            })
            .min_by(f32::total_cmp);
        if let Some(t) = hit {
            let world = top - Vector::Z * t;
            points.push(pose.inverse_transform_point(world));
        }
    }
    points
}

fn splitmix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}
