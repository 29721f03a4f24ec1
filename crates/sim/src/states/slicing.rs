//! `sliced`: a slicer pressing a sliceable object with more than 10 N replaces it by two halves.
//!
//! The force is the mean over the action step (1/30 s) of the slicers' contact forces, from the
//! contact impulses of its physics substeps. iGibson 2.0 §1.7 reads the normal force of the
//! slicer link's contacts after the step; a mean over the step keeps a knife laid on a tomato,
//! whose landing spikes one substep's force, from cutting it, while a steady push above 10 N
//! does. When the slicer names a slicing edge, only contacts near it count, so pressing with the
//! handle does not cut. The whole object is then disabled (it leaves the
//! simulation and the ray casts, but keeps its id, its last pose and its states), and two halves
//! appear in its place as new objects that inherit its states: the halves its archetype defines
//! ([`crate::ObjectSpec::halves`]), or else the two halves of its bounding box, split across its
//! longer horizontal side. Slicing cannot be undone.

use crate::World;
use crate::bodies::Bodies;
use crate::core::DROP_TAG;
use crate::object::{ObjectId, ObjectSpec, Part, PointKind, Primitive};
use crate::states::StateError;
use behavior_core::{Ability, Predicate};
use rapier3d::math::{Pose, Vector};

/// Newtons.
pub const SLICE_FORCE: f32 = 10.0;
/// How close to a slicer's [`PointKind::SlicingEdge`] a contact must be to cut (m).
pub const EDGE_REACH: f32 = 0.05;

/// The impulse (N·s) slicers applied in the last substep to each sliceable object they
/// touched (at their edge, if they name one), in id order.
pub(crate) fn slicer_impulses(bodies: &Bodies) -> Vec<(ObjectId, f32)> {
    let mut impulses: Vec<(ObjectId, f32)> = Vec::new();
    for (slicer, object) in bodies.objects() {
        if !object.has(Ability::Slicer) {
            continue;
        }
        let edge = object
            .point(PointKind::SlicingEdge)
            .map(|p| bodies.pose(slicer).transform_point(p));
        for &c in &object.colliders {
            for pair in bodies.physics.narrow_phase.contact_pairs_with(c) {
                let Some(target) = sliceable_other(bodies, pair, c, slicer) else {
                    continue;
                };
                if edge.is_some_and(|edge| !touches_near(bodies, pair, edge)) {
                    continue;
                }
                add_impulse(&mut impulses, target, pair.total_impulse_magnitude());
            }
        }
    }
    impulses.sort_by_key(|&(id, _)| id);
    impulses
}

/// The other side of a slicer's contact pair, if it is a sliceable object still whole.
fn sliceable_other(
    bodies: &Bodies,
    pair: &rapier3d::geometry::ContactPair,
    own: rapier3d::geometry::ColliderHandle,
    slicer: ObjectId,
) -> Option<ObjectId> {
    let other = if pair.collider1 == own {
        pair.collider2
    } else {
        pair.collider1
    };
    let other = bodies.physics.colliders.get(other)?;
    let id = ObjectId(other.user_data as u32);
    let valid = other.user_data != DROP_TAG
        && id != slicer
        && (id.0 as usize) < bodies.objects.len()
        && bodies.object(id).has(Ability::Sliceable)
        && bodies.object(id).is_present();
    valid.then_some(id)
}

/// Whether a contact pair touches within [`EDGE_REACH`] of a slicing edge.
fn touches_near(bodies: &Bodies, pair: &rapier3d::geometry::ContactPair, edge: Vector) -> bool {
    let c1 = &bodies.physics.colliders[pair.collider1];
    pair.manifolds()
        .iter()
        .flat_map(|m| &m.points)
        .any(|p| (c1.position().transform_point(p.local_p1) - edge).length() <= EDGE_REACH)
}

/// Adds an impulse to an object's running total.
fn add_impulse(impulses: &mut Vec<(ObjectId, f32)>, id: ObjectId, impulse: f32) {
    match impulses.iter_mut().find(|(o, _)| *o == id) {
        Some((_, total)) => *total += impulse,
        None => impulses.push((id, impulse)),
    }
}

/// The slicer impulses of a step's substeps, summed per object.
#[derive(Default)]
pub(crate) struct SlicerPush(Vec<(ObjectId, f32)>);

impl SlicerPush {
    /// Adds one substep's impulses ([`slicer_impulses`]).
    pub(crate) fn add(&mut self, substep: Vec<(ObjectId, f32)>) {
        for (id, impulse) in substep {
            add_impulse(&mut self.0, id, impulse);
        }
    }

    /// The objects pushed, on average over the step of `seconds`, harder than [`SLICE_FORCE`], in
    /// id order.
    pub(crate) fn pressed(mut self, seconds: f32) -> Vec<ObjectId> {
        self.0.sort_by_key(|&(id, _)| id);
        self.0
            .into_iter()
            .filter(|&(_, impulse)| impulse / seconds > SLICE_FORCE)
            .map(|(id, _)| id)
            .collect()
    }
}

impl World {
    /// Replaces a sliceable object by its two halves (see the module docs).
    pub(crate) fn set_sliced(&mut self, id: ObjectId, sliced: bool) -> Result<(), StateError> {
        if self.core.bodies.object(id).replaced_by.is_some() == sliced {
            return Ok(());
        }
        if !sliced {
            return Err(StateError::Unsupported {
                object: self.core.bodies.object(id).name.clone(),
                predicate: Predicate::Sliced,
                value: false,
                reason: "slicing cannot be undone".into(),
            });
        }
        let object = self.core.bodies.object(id);
        let mut specs = Vec::new();
        if let Some(halves) = &object.halves {
            // The archetype's halves, where the whole object stands.
            let pose = self.core.bodies.pose(id);
            for (k, parts) in halves.iter().enumerate() {
                let mut spec = ObjectSpec::new(
                    &format!("{}_half_{}", object.name, k + 1),
                    &object.category,
                    parts.clone(),
                );
                spec.pose = pose;
                spec.density = object.density;
                specs.push(spec);
            }
        } else {
            let aabb = self.core.bodies.aabb(id);
            let half = (aabb.maxs - aabb.mins) * 0.5;
            let center = aabb.center();
            let mass = self.core.bodies.physics.bodies[object.body].mass();
            // Split across the longer horizontal side.
            let along = if half.x >= half.y {
                Vector::X
            } else {
                Vector::Y
            };
            let piece = half - along * (half.dot(along) * 0.5);
            let volume = 8.0 * piece.x * piece.y * piece.z;
            for (k, sign) in [(1, -1.0f32), (2, 1.0)] {
                let mut spec = ObjectSpec::new(
                    &format!("{}_half_{k}", object.name),
                    &object.category,
                    vec![Part::new(Primitive::Box {
                        half_extents: piece,
                    })],
                );
                spec.pose = Pose::from_translation(center + along * (sign * half.dot(along) * 0.5));
                spec.density = (mass * 0.5 / volume).max(1.0);
                specs.push(spec);
            }
        }
        // The halves are of the whole's stuff: its look, friction and damping.
        for spec in &mut specs {
            spec.abilities = object.abilities.clone();
            spec.abilities.remove(&Ability::Sliceable);
            spec.visual = object.visual;
            spec.friction = object.friction;
            spec.angular_damping = object.angular_damping;
        }
        let mut halves = [id; 2];
        for (k, spec) in specs.into_iter().enumerate() {
            let half = self.add(spec).map_err(|e| StateError::Unsupported {
                object: self.core.bodies.object(id).name.clone(),
                predicate: Predicate::Sliced,
                value: true,
                reason: e.to_string(),
            })?;
            self.systems.inherit(id, half);
            halves[k] = half;
        }
        let core = &mut self.core;
        let body = core.bodies.objects[id.0 as usize].body;
        core.bodies.physics.bodies[body].set_enabled(false);
        core.bodies.objects[id.0 as usize].replaced_by = Some(halves);
        core.bodies.moved(id);
        core.bodies.refresh();
        Ok(())
    }
}
