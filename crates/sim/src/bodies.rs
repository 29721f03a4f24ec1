//! The bodies: every object with its rigid bodies, colliders and joints in the physics engine
//! (rapier3d), and the bookkeeping every other part of the world reads — how often each object
//! has moved (which keeps memoized relations valid), the step count, whether the scene is at
//! rest, the forces pushed for the current step — and the query index, which is derived from the
//! colliders' poses and so lives with what invalidates it.
//!
//! [`Bodies`] is implemented here (objects, poses, masses, boxes, teleports, sleeping),
//! in `dynamics.rs` (what controllers do: velocities, forces, kinematic targets) and in
//! `construct.rs` (adding an object).

use crate::core::{STEP_SECONDS, Substeps, WorldError, pose_is_finite};
use crate::object::{BodyRef, JointHandle, Object, ObjectId};
use crate::query::QueryIndex;
use crate::visual::Ghost;
use rapier3d::dynamics::{CCDSolver, RigidBodyActivation, RigidBodyHandle};
use rapier3d::math::{Pose, Vector};
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::pipeline::{CollisionPipeline, PhysicsPipeline, PhysicsWorld};
use rapier3d::prelude::Aabb;
use std::collections::BTreeMap;

/// Every object's bodies, colliders and joints in the physics engine, with the bookkeeping of
/// their motion. Reached through [`crate::World::bodies`] and [`crate::World::bodies_mut`].
pub struct Bodies {
    pub(crate) physics: PhysicsWorld,
    pub(crate) objects: Vec<Object>,
    /// Per object: how many times it has moved (see [`Bodies::motion`]).
    pub(crate) motion: Vec<u64>,
    /// Bodies given a force or torque for the current step, cleared after it.
    pub(crate) pushed: Vec<RigidBodyHandle>,
    /// The last physics step left every body asleep and nothing has changed since, so further
    /// substeps would change nothing: they are skipped until something wakes.
    pub(crate) quiet: bool,
    /// Bodies added asleep that have not yet been through a physics substep, with the time at
    /// rest they need to fall asleep (see [`Bodies::fall_asleep_at_once`]).
    pub(crate) waking_to_sleep: Vec<(RigidBodyHandle, f32)>,
    pub(crate) steps: u64,
    pub(crate) substeps: Substeps,
    /// Velocities of velocity-driven bodies at the root of a multibody chain, which the chain
    /// would otherwise overwrite (see [`Bodies::lead_kinematic_chains`]).
    pub(crate) carried: BTreeMap<ObjectId, crate::dynamics::Velocity>,
    /// Ray and shape queries' structures, rebuilt on first use after the colliders moved.
    pub(crate) index: QueryIndex,
}

impl Clone for Bodies {
    fn clone(&self) -> Self {
        let p = &self.physics;
        Bodies {
            // The pipelines and CCD solver are scratch space, rebuilt on demand.
            physics: PhysicsWorld {
                gravity: p.gravity,
                integration_parameters: p.integration_parameters,
                physics_pipeline: PhysicsPipeline::new(),
                collision_pipeline: CollisionPipeline::new(),
                islands: p.islands.clone(),
                broad_phase: p.broad_phase.clone(),
                narrow_phase: p.narrow_phase.clone(),
                bodies: p.bodies.clone(),
                colliders: p.colliders.clone(),
                impulse_joints: p.impulse_joints.clone(),
                multibody_joints: p.multibody_joints.clone(),
                soft_bodies: p.soft_bodies.clone(),
                ccd_solver: CCDSolver::new(),
            },
            objects: self.objects.clone(),
            motion: self.motion.clone(),
            pushed: self.pushed.clone(),
            quiet: self.quiet,
            waking_to_sleep: self.waking_to_sleep.clone(),
            steps: self.steps,
            substeps: self.substeps,
            carried: self.carried.clone(),
            index: self.index.clone(),
        }
    }
}

impl Bodies {
    pub(crate) fn new(substeps: Substeps) -> Bodies {
        let mut physics = PhysicsWorld::new();
        physics.gravity = Vector::new(0.0, 0.0, -9.81);
        physics.integration_parameters.dt = STEP_SECONDS / substeps.count() as f32;
        Bodies {
            physics,
            objects: Vec::new(),
            motion: Vec::new(),
            pushed: Vec::new(),
            quiet: false,
            waking_to_sleep: Vec::new(),
            steps: 0,
            substeps,
            carried: BTreeMap::new(),
            index: QueryIndex::default(),
        }
    }

    /// Every object with its id, in the order they were added.
    pub fn objects(&self) -> impl ExactSizeIterator<Item = (ObjectId, &Object)> {
        self.objects
            .iter()
            .enumerate()
            .map(|(i, o)| (ObjectId(i as u32), o))
    }

    /// An object. Ids come from this world, so an unknown one is a programming error and panics,
    /// like an index out of range.
    pub fn object(&self, id: ObjectId) -> &Object {
        &self.objects[id.0 as usize]
    }

    /// The first object of that name.
    pub fn object_named(&self, name: &str) -> Option<ObjectId> {
        self.objects
            .iter()
            .position(|o| o.name == name)
            .map(|i| ObjectId(i as u32))
    }

    /// Whether an object is in the world: not replaced by its halves, not retired.
    pub fn present(&self, id: ObjectId) -> bool {
        self.object(id).is_present()
    }

    /// Puts a drawn-only shape with an object, or takes it away ([`Ghost`]). The physics never
    /// sees it; the object counts as moved (what is drawn of it changed).
    pub fn set_ghost(&mut self, id: ObjectId, ghost: Option<Ghost>) {
        let object = &mut self.objects[id.0 as usize];
        if object.ghost != ghost {
            object.ghost = ghost;
            self.moved(id);
        }
    }

    /// Wakes a body through the physics world, so that the island manager hears of it (a
    /// sleeping multibody wakes as a whole), and ends the scene's rest.
    pub(crate) fn wake(&mut self, body: RigidBodyHandle) {
        self.physics.wake_up(body, true);
        self.quiet = false;
    }

    /// Action steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// How finely each action step is integrated.
    pub fn substeps(&self) -> Substeps {
        self.substeps
    }

    /// The pose of an object's body.
    pub fn pose(&self, id: ObjectId) -> Pose {
        *self.physics.bodies[self.object(id).body].position()
    }

    /// The pose of a link's body. Its parts are given in the object's frame at zero joint
    /// position, so this pose maps them to the world.
    pub fn link_pose(&self, id: ObjectId, link: usize) -> Pose {
        *self.physics.bodies[self.object(id).links[link].body].position()
    }

    /// The rapier handle of a body, after checking that the link exists.
    pub(crate) fn handle(&self, body: BodyRef) -> Result<RigidBodyHandle, WorldError> {
        let object = self.object(body.object);
        match body.link {
            None => Ok(object.body),
            Some(l) => object
                .links
                .get(l)
                .map(|l| l.body)
                .ok_or(WorldError::NoLink {
                    name: object.name.clone(),
                    link: l,
                    count: object.links.len(),
                }),
        }
    }

    /// The pose of any body.
    pub fn body_pose(&self, body: BodyRef) -> Result<Pose, WorldError> {
        Ok(*self.physics.bodies[self.handle(body)?].position())
    }

    /// The mass of an object's body (its links excluded), kg.
    pub fn mass(&self, id: ObjectId) -> f32 {
        self.physics.bodies[self.object(id).body].mass()
    }

    /// The mass of one body, the object's or a link's, kg.
    pub fn body_mass(&self, body: BodyRef) -> Result<f32, WorldError> {
        Ok(self.physics.bodies[self.handle(body)?].mass())
    }

    /// The mass of an object with all its links (a box with its lid), kg: what a hand lifts.
    pub fn total_mass(&self, id: ObjectId) -> f32 {
        let object = self.object(id);
        let links: f32 = object
            .links
            .iter()
            .map(|l| self.physics.bodies[l.body].mass())
            .sum();
        self.mass(id) + links
    }

    /// The world's gravity (m/s²), −9.81 along z unless changed.
    pub fn gravity(&self) -> Vector {
        self.physics.gravity
    }

    /// Whether the object's body is asleep.
    pub fn is_sleeping(&self, id: ObjectId) -> bool {
        self.physics.bodies[self.object(id).body].is_sleeping()
    }

    /// The axis-aligned box around all of an object's colliders.
    pub fn aabb(&self, id: ObjectId) -> Aabb {
        let colliders = &self.object(id).colliders;
        let mut aabb = self.physics.colliders[colliders[0]].compute_aabb();
        for &c in &colliders[1..] {
            aabb.merge(&self.physics.colliders[c].compute_aabb());
        }
        aabb
    }

    /// The box around an object's body colliders (its links' excluded) in its own frame: its
    /// size as built, whatever way it is turned.
    pub fn local_aabb(&self, id: ObjectId) -> Aabb {
        self.box_of(id, self.object(id).body)
    }

    /// The box around one link's colliders in the object's frame with every joint at zero (the
    /// frame its parts are given in; [`Bodies::link_pose`] maps it to the world): a door's
    /// extent, to find its edge away from the hinge.
    pub fn link_local_aabb(&self, id: ObjectId, link: usize) -> Aabb {
        self.box_of(id, self.object(id).links[link].body)
    }

    /// The box around the object's colliders on `body`, in that body's frame.
    fn box_of(&self, id: ObjectId, body: RigidBodyHandle) -> Aabb {
        let mut boxes = self
            .object(id)
            .colliders
            .iter()
            .map(|&c| &self.physics.colliders[c])
            .filter(|c| c.parent() == Some(body))
            .map(|c| {
                let at = c.position_wrt_parent().copied().unwrap_or(Pose::IDENTITY);
                c.shape().compute_aabb(&at)
            });
        let first = boxes
            .next()
            .unwrap_or_else(|| Aabb::new(Vector::ZERO, Vector::ZERO));
        boxes.fold(first, |mut all, b| {
            all.merge(&b);
            all
        })
    }

    /// How many times an object has moved: a step in which its body or a link was awake, or a
    /// teleport. Memoized relations are valid while the counts of their objects are unchanged.
    pub fn motion(&self, id: ObjectId) -> u64 {
        self.motion[id.0 as usize]
    }

    /// Moves an object (teleport) with its links, at rest, waking it. A sliced object's halves
    /// move with it, as one rigid piece, so that it can be placed like a whole.
    pub fn set_pose(&mut self, id: ObjectId, pose: Pose) -> Result<(), WorldError> {
        if !pose_is_finite(&pose) {
            return Err(WorldError::BadObject {
                name: self.object(id).name.clone(),
                reason: "the requested pose is not finite".into(),
            });
        }
        // Links move with the body, keeping their joint positions.
        let object = &self.objects[id.0 as usize];
        let old = *self.physics.bodies[object.body].position();
        if let Some(halves) = object.replaced_by {
            for half in halves {
                let relative = old.inv_mul(&self.pose(half));
                self.set_pose(half, pose * relative)?;
            }
        }
        let object = &self.objects[id.0 as usize];
        let moves: Vec<(RigidBodyHandle, Pose)> = std::iter::once((object.body, pose))
            .chain(object.links.iter().map(|l| {
                let relative = old.inv_mul(self.physics.bodies[l.body].position());
                (l.body, pose * relative)
            }))
            .collect();
        for (handle, target) in moves {
            let body = &mut self.physics.bodies[handle];
            body.set_position(target, true);
            body.set_linvel(Vector::ZERO, true);
            body.set_angvel(Vector::ZERO, true);
        }
        self.sync_multibody(id);
        self.moved(id);
        self.refresh();
        Ok(())
    }

    /// After a teleport, tells a multibody whose root moved where its links now are.
    pub(crate) fn sync_multibody(&mut self, id: ObjectId) {
        let object = &self.objects[id.0 as usize];
        let Some(first) = object.links.iter().find_map(|l| match l.handle {
            JointHandle::Multibody(h) => Some(h),
            JointHandle::Impulse(_) => None,
        }) else {
            return;
        };
        let physics = &mut self.physics;
        if let Some((multibody, _)) = physics.multibody_joints.get_mut(first) {
            // The root takes the body's new pose; joint coordinates are kept.
            multibody.forward_kinematics(&physics.bodies, true);
            multibody.update_rigid_bodies(&mut physics.bodies, false);
        }
    }

    /// Takes an object out of the simulation for good: its bodies stop colliding and moving, and
    /// it is no longer [`Object::is_present`], so no predicate, placement or query sees it. For a
    /// stand-in that something else replaces (an activity's `agent.n.01` capsule, by a robot).
    pub fn retire(&mut self, id: ObjectId) {
        let object = &mut self.objects[id.0 as usize];
        object.retired = true;
        let bodies: Vec<RigidBodyHandle> = std::iter::once(object.body)
            .chain(object.links.iter().map(|l| l.body))
            .collect();
        for body in bodies {
            if let Some(b) = self.physics.bodies.get_mut(body) {
                b.set_enabled(false);
            }
        }
        self.moved(id);
        self.refresh();
    }

    /// Sets the physics substeps per action step (an instance sampled at 1/300 s may be run at
    /// 1/120 s). Takes effect from the next step.
    pub fn set_substeps(&mut self, substeps: Substeps) {
        self.substeps = substeps;
        self.physics.integration_parameters.dt = STEP_SECONDS / substeps.count() as f32;
    }

    /// Lets resting bodies sleep (the default) or keeps every body simulated, for benchmarks of
    /// an awake scene.
    pub fn set_sleeping_allowed(&mut self, allowed: bool) {
        for (_, body) in self.physics.bodies.iter_mut() {
            if body.is_dynamic() {
                *body.activation_mut() = if allowed {
                    RigidBodyActivation::active()
                } else {
                    RigidBodyActivation::cannot_sleep()
                };
                body.wake_up(true);
            }
        }
        self.quiet = false;
    }

    /// Lets a body added asleep go back to sleep within its first substep. Rapier wakes every
    /// body whose contact begins, and the first substep after a body is added finds all its
    /// resting contacts, so a body added asleep on a shelf wakes at once and would then need its
    /// full time at rest (half a second) to sleep again, simulated all the while. With that time
    /// at zero for its first substep it is asleep again at the end of it, unmoved (every bit of
    /// its pose: `tests/asleep.rs`); from then on it needs the usual time, like any body.
    pub(crate) fn fall_asleep_at_once(&mut self, handle: RigidBodyHandle) {
        let activation = self.physics.bodies[handle].activation_mut();
        self.waking_to_sleep
            .push((handle, activation.time_until_sleep));
        activation.time_until_sleep = 0.0;
    }

    /// After a physics substep: bodies added asleep need their usual time at rest again.
    pub(crate) fn restore_sleep_times(&mut self) {
        for (handle, time) in self.waking_to_sleep.drain(..) {
            if let Some(body) = self.physics.bodies.get_mut(handle) {
                body.activation_mut().time_until_sleep = time;
            }
        }
    }

    /// Positions, orientations and velocities of every object's body and links as raw bits:
    /// equal digests mean bit-identical motion state.
    pub fn motion_bits(&self) -> Vec<u32> {
        let mut bits = Vec::with_capacity(self.objects.len() * 13);
        for object in &self.objects {
            let handles = std::iter::once(object.body).chain(object.links.iter().map(|l| l.body));
            for handle in handles {
                let body = &self.physics.bodies[handle];
                let p = body.position();
                let (t, r) = (p.translation, p.rotation);
                let (v, w) = (body.linvel(), body.angvel());
                for x in [
                    t.x, t.y, t.z, r.x, r.y, r.z, r.w, v.x, v.y, v.z, w.x, w.y, w.z,
                ] {
                    bits.push(x.to_bits());
                }
            }
        }
        bits
    }

    /// Moves colliders with their teleported bodies now rather than at the next step, so that
    /// relations see the change at once, and drops the query structure. (Running rapier's
    /// collision pipeline here instead would consume its record of changed bodies and keep new
    /// bodies from ever waking.)
    pub(crate) fn refresh(&mut self) {
        self.quiet = false;
        self.index.clear();
        let physics = &mut self.physics;
        physics
            .bodies
            .propagate_modified_body_positions_to_colliders(&mut physics.colliders);
    }

    /// Marks an object as moved: its memoized relations are stale.
    pub(crate) fn moved(&mut self, id: ObjectId) {
        self.motion[id.0 as usize] += 1;
    }

    /// A new object's bookkeeping.
    pub(crate) fn push_object(&mut self, object: Object) -> ObjectId {
        let id = ObjectId(self.objects.len() as u32);
        self.objects.push(object);
        self.motion.push(0);
        id
    }

    /// Marks every object whose body or a link was awake during the last substeps as moved.
    pub(crate) fn note_motion(&mut self) {
        for (i, object) in self.objects.iter().enumerate() {
            let awake = |b: RigidBodyHandle| {
                let body = &self.physics.bodies[b];
                body.is_enabled() && !body.is_fixed() && !body.is_sleeping()
            };
            if awake(object.body) || object.links.iter().any(|l| awake(l.body)) {
                self.motion[i] += 1;
            }
        }
    }
}
