//! Dust and stains as particles on surfaces, and cleaning.
//!
//! Making an object dusty (or stained) places 20 particles on its upward-facing surfaces, found by
//! casting rays down onto it at points drawn over its footprint (first a random spot in the
//! particle's cell of a 5 × 4 grid, then anywhere, up to 20 tries) from the world's seeded
//! generator ([`crate::World::reseed`]), so layouts differ between instances and repeat for a
//! seed. Each particle is fixed to the body it
//! landed on, the object's or a link's, and moves with it: a dusty cabinet door keeps its dust
//! when it swings open. The object is dusty while more than 50 % of the particles ever placed
//! remain (75 % for floors), as in iGibson 2.0 (§1.6; iGibson also uses side faces).
//!
//! Each step, a cleaning tool that touches a dirty object removes the particles inside its box,
//! grown by 1 cm (and, if the tool names a cleaning area, within 10 cm of it); stains only come
//! off when the tool is soaked.

use crate::core::{Core, untag};
use crate::kinematics::Relations;
use crate::object::{Object, ObjectId, PointKind};
use crate::states::StateError;
use crate::states::water::Water;
use behavior_core::rng::{SimRng, uniform};
use behavior_core::{Ability, FLOOR_SYNSET, Predicate};
use rapier3d::math::{Pose, Vector};
use rapier3d::parry::bounding_volume::BoundingVolume;
use serde::{Deserialize, Serialize};

/// Particles placed on a newly dirty object.
pub const PARTICLES_PER_SET: usize = 20;
/// Tries to land each particle on a surface facing up (iGibson's 20).
pub const ATTEMPTS_PER_PARTICLE: usize = 20;
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

/// A particle: where it sits in the frame of the body it lies on.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Particle {
    /// The link it lies on, or `None` for the object's body.
    pub(crate) link: Option<usize>,
    /// Its position in that body's frame.
    pub(crate) local: Vector,
}

/// Particles of one kind on one object.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct ParticleSet {
    pub(crate) points: Vec<Particle>,
    /// How many were placed when the set was last made.
    pub(crate) placed: usize,
}

/// The dirt system: each object's dust and stain particles.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Dirt {
    dust: Vec<ParticleSet>,
    stain: Vec<ParticleSet>,
    /// The cleaning tools, in id order.
    tools: Vec<ObjectId>,
    /// The objects that can get dusty or stained, in id order: only they are wiped.
    dirtyable: Vec<ObjectId>,
}

impl Dirt {
    /// Two particle sets per object, each particle on a link the object has; the tools and
    /// dirtyable objects are objects.
    pub(crate) fn check_consistency(&self, core: &Core) -> Result<(), String> {
        let n = core.bodies.objects.len();
        let on_links = |sets: &[ParticleSet]| {
            sets.iter().zip(&core.bodies.objects).all(|(set, object)| {
                set.points
                    .iter()
                    .all(|p| p.link.is_none_or(|l| l < object.links.len()))
            })
        };
        if self.dust.len() != n
            || self.stain.len() != n
            || !on_links(&self.dust)
            || !on_links(&self.stain)
            || self
                .tools
                .iter()
                .chain(&self.dirtyable)
                .any(|id| id.0 as usize >= n)
        {
            return Err("dirt: tables disagree with the objects".into());
        }
        Ok(())
    }
}

impl Dirt {
    pub(crate) fn add_object(&mut self, id: ObjectId, object: &Object) {
        self.dust.push(ParticleSet::default());
        self.stain.push(ParticleSet::default());
        if object.has(Ability::CleaningTool) {
            self.tools.push(id);
        }
        if object.has(Ability::Dustyable) || object.has(Ability::Stainable) {
            self.dirtyable.push(id);
        }
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
        let points = &self.set(id, kind).points;
        if points.is_empty() {
            // Most objects hold none; their frames need not be worked out.
            return Vec::new();
        }
        let frames = Frames::of(core, id);
        points.iter().map(|p| frames.place(p)).collect()
    }

    /// An object's particles of one kind, as kept (for saving).
    pub(crate) fn particles(&self, id: ObjectId, kind: Predicate) -> &ParticleSet {
        self.set(id, kind)
    }

    /// Replaces an object's particles of one kind (for loading a saved state).
    pub(crate) fn put(&mut self, id: ObjectId, kind: Predicate, set: ParticleSet) {
        *self.set_mut(id, kind) = set;
    }

    pub(crate) fn is_dirty(&self, core: &Core, id: ObjectId, kind: Predicate) -> bool {
        let set = self.set(id, kind);
        let threshold = if core.bodies.object(id).category == FLOOR_SYNSET {
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
        (kind, dirty): (Predicate, bool),
        rng: &mut SimRng,
    ) -> Result<(), StateError> {
        if !dirty {
            *self.set_mut(id, kind) = ParticleSet::default();
            return Ok(());
        }
        let points = sample_top_surface(core, id, rng);
        if points.len() < MIN_PARTICLES {
            return Err(StateError::Unsupported {
                object: core.bodies.object(id).name.clone(),
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
        // By index: the loop wipes this system's particles while reading its lists.
        for t in 0..self.tools.len() {
            let tool = self.tools[t];
            let area = core.bodies.aabb(tool).loosened(WIPE_MARGIN);
            let face = core
                .bodies
                .object(tool)
                .point(PointKind::CleaningArea)
                .map(|p| core.bodies.pose(tool).transform_point(p));
            let wipes = |p: Vector| {
                area.contains_local_point(p)
                    && face.is_none_or(|f| (p - f).length() <= CLEANING_REACH)
            };
            let kinds: &[Predicate] = if water.is_soaked(tool) {
                &[Predicate::Dusty, Predicate::Stained]
            } else {
                &[Predicate::Dusty]
            };
            for d in 0..self.dirtyable.len() {
                let dirty = self.dirtyable[d];
                let clean = self.dust[dirty.0 as usize].points.is_empty()
                    && self.stain[dirty.0 as usize].points.is_empty();
                if dirty == tool || clean || !Relations::new(core).touching(tool, dirty) {
                    continue;
                }
                let frames = Frames::of(core, dirty);
                for &kind in kinds {
                    self.set_mut(dirty, kind)
                        .points
                        .retain(|p| !wipes(frames.place(p)));
                }
            }
        }
    }
}

/// The current poses of an object's body and links, to place particles in the world.
struct Frames {
    body: Pose,
    links: Vec<Pose>,
}

impl Frames {
    fn of(core: &Core, id: ObjectId) -> Frames {
        let links = (0..core.bodies.object(id).links.len())
            .map(|l| core.bodies.link_pose(id, l))
            .collect();
        Frames {
            body: core.bodies.pose(id),
            links,
        }
    }

    fn place(&self, p: &Particle) -> Vector {
        let frame = p.link.and_then(|l| self.links.get(l)).unwrap_or(&self.body);
        frame.transform_point(p.local)
    }
}

/// Up to [`PARTICLES_PER_SET`] particles on the object's surfaces that face up, each fixed to
/// the body (object or link) it landed on. Particle `k` is looked for in cell `k` of a 5 × 4 grid
/// over the footprint first, so that the particles cover it, then anywhere over it, up to
/// [`ATTEMPTS_PER_PARTICLE`] tries in all (iGibson's 20): a thin rod or a spoon lying askew
/// offers little to land on.
fn sample_top_surface(core: &Core, id: ObjectId, rng: &mut SimRng) -> Vec<Particle> {
    let (cols, rows) = (5, 4);
    (0..PARTICLES_PER_SET)
        .filter_map(|k| {
            (0..ATTEMPTS_PER_PARTICLE).find_map(|attempt| {
                let (fx, fy) = if attempt == 0 {
                    (
                        ((k % cols) as f32 + uniform(rng, 0.1, 0.9)) / cols as f32,
                        ((k / cols) as f32 + uniform(rng, 0.1, 0.9)) / rows as f32,
                    )
                } else {
                    (uniform(rng, 0.0, 1.0), uniform(rng, 0.0, 1.0))
                };
                land(core, id, fx, fy)
            })
        })
        .collect()
}

/// Where a particle dropped at the fraction (fx, fy) of the object's footprint lands on one of
/// its upward-facing surfaces, if it does.
fn land(core: &Core, id: ObjectId, fx: f32, fy: f32) -> Option<Particle> {
    let aabb = core.bodies.aabb(id);
    let x = aabb.mins.x + fx * (aabb.maxs.x - aabb.mins.x);
    let y = aabb.mins.y + fy * (aabb.maxs.y - aabb.mins.y);
    let top = Vector::new(x, y, aabb.maxs.z + 0.01);
    let ray = rapier3d::prelude::Ray::new(top, -Vector::Z);
    let range = aabb.maxs.z - aabb.mins.z + 0.02;
    let (t, link) = core
        .bodies
        .object(id)
        .colliders
        .iter()
        .map(|&c| &core.bodies.physics.colliders[c])
        .filter_map(|c| {
            c.shape()
                .cast_ray_and_get_normal(c.position(), &ray, range, true)
                .filter(|hit| hit.normal.z > 0.5)
                .map(|hit| (hit.time_of_impact, untag(c.user_data).and_then(|b| b.link)))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))?;
    let frame = link.map_or_else(|| core.bodies.pose(id), |l| core.bodies.link_pose(id, l));
    let local = frame.inverse_transform_point(top - Vector::Z * t);
    Some(Particle { link, local })
}
