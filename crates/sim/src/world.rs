//! The world: objects made of rigid bodies with compound colliders, rooms with their floors, the
//! physics engine (rapier3d), the step pipeline and snapshots.
//!
//! Units are metres, kilograms and seconds; z points up. One [`World::step`] is one action step
//! of 1/30 s, run as physics substeps of 1/300 s (or 1/120 s, see [`Substeps`]).

use crate::states::UnaryStates;
use rapier3d::dynamics::{CCDSolver, RigidBodyBuilder, RigidBodyHandle};
use rapier3d::geometry::{ColliderBuilder, ColliderHandle};
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::pipeline::{CollisionPipeline, PhysicsPipeline, PhysicsWorld};
use rapier3d::prelude::Aabb;

/// One action step, in seconds.
pub const STEP_SECONDS: f32 = 1.0 / 30.0;

/// Index of an object in its [`World`], stable for the world's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ObjectId(pub u32);

/// A collision primitive in the object's frame. Cylinders and capsules stand along z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive {
    Box { half_extents: Vector },
    Cylinder { radius: f32, half_height: f32 },
    Sphere { radius: f32 },
    Capsule { radius: f32, half_height: f32 },
}

/// One primitive of an object's compound shape, placed in the object's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Part {
    pub primitive: Primitive,
    pub offset: Pose,
}

impl Part {
    pub fn new(primitive: Primitive) -> Part {
        Part {
            primitive,
            offset: Pose::IDENTITY,
        }
    }

    pub fn at(primitive: Primitive, offset: Vector) -> Part {
        Part {
            primitive,
            offset: Pose::from_translation(offset),
        }
    }
}

/// Everything needed to add an object.
#[derive(Clone, Debug)]
pub struct ObjectSpec {
    /// E.g. `apple.n.01_1` once bound to an activity, or a scene name such as `table_3`.
    pub name: String,
    /// The synset, e.g. `apple.n.01`.
    pub category: String,
    pub parts: Vec<Part>,
    pub pose: Pose,
    /// Fixed objects (furniture, walls, floors) never move.
    pub fixed: bool,
    /// kg/m³; the mass follows from the parts' volumes.
    pub density: f32,
    pub friction: f32,
    /// 1/s. Stands in for rolling resistance: household objects are not perfect spheres, and
    /// without it a round object nudged on a flat plate rolls away for ever.
    pub angular_damping: f32,
}

impl ObjectSpec {
    pub fn new(name: &str, category: &str, parts: Vec<Part>) -> ObjectSpec {
        ObjectSpec {
            name: name.to_string(),
            category: category.to_string(),
            parts,
            pose: Pose::IDENTITY,
            fixed: false,
            density: 500.0,
            friction: 0.7,
            angular_damping: 1.0,
        }
    }

    pub fn at(mut self, position: Vector) -> ObjectSpec {
        self.pose = Pose::from_translation(position);
        self
    }

    pub fn fixed(mut self) -> ObjectSpec {
        self.fixed = true;
        self
    }
}

#[derive(Clone, Debug)]
pub struct Object {
    pub name: String,
    pub category: String,
    pub fixed: bool,
    pub body: RigidBodyHandle,
    pub colliders: Vec<ColliderHandle>,
}

/// A room of a home: its type (`kitchen`), its instance number among rooms of that type, its
/// footprint (an axis-aligned rectangle in x, y) and its floor object.
#[derive(Clone, Debug, PartialEq)]
pub struct Room {
    pub kind: String,
    pub instance: u32,
    pub min: [f32; 2],
    pub max: [f32; 2],
    pub floor: Option<ObjectId>,
}

impl Room {
    pub fn contains(&self, x: f32, y: f32) -> bool {
        (self.min[0]..=self.max[0]).contains(&x) && (self.min[1]..=self.max[1]).contains(&y)
    }
}

/// How finely each action step is integrated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Substeps {
    /// 10 substeps of 1/300 s: stable stacking of small objects.
    #[default]
    Hz300,
    /// 4 substeps of 1/120 s: faster, for scenes without small stacked objects.
    Hz120,
}

impl Substeps {
    pub fn count(self) -> u32 {
        match self {
            Substeps::Hz300 => 10,
            Substeps::Hz120 => 4,
        }
    }
}

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum WorldError {
    #[error("object `{name}`: {reason}")]
    BadObject { name: String, reason: String },
}

/// The simulated world. Cloning it (or taking a [`Snapshot`]) copies every piece of state, so a
/// clone continues bit-identically.
pub struct World {
    pub(crate) physics: PhysicsWorld,
    objects: Vec<Object>,
    rooms: Vec<Room>,
    pub(crate) states: Vec<UnaryStates>,
    steps: u64,
    substeps: Substeps,
}

impl Default for World {
    fn default() -> Self {
        World::new(Substeps::default())
    }
}

impl Clone for World {
    fn clone(&self) -> Self {
        let p = &self.physics;
        World {
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
            rooms: self.rooms.clone(),
            states: self.states.clone(),
            steps: self.steps,
            substeps: self.substeps,
        }
    }
}

/// A saved world state; [`World::restore`] continues from it bit-identically.
#[derive(Clone)]
pub struct Snapshot(World);

impl World {
    pub fn new(substeps: Substeps) -> World {
        let mut physics = PhysicsWorld::new();
        physics.gravity = Vector::new(0.0, 0.0, -9.81);
        physics.integration_parameters.dt = STEP_SECONDS / substeps.count() as f32;
        World {
            physics,
            objects: Vec::new(),
            rooms: Vec::new(),
            states: Vec::new(),
            steps: 0,
            substeps,
        }
    }

    /// Adds an object; its colliders carry its id so queries can map hits back to objects.
    pub fn add(&mut self, spec: ObjectSpec) -> Result<ObjectId, WorldError> {
        let bad = |reason: &str| WorldError::BadObject {
            name: spec.name.clone(),
            reason: reason.to_string(),
        };
        if spec.parts.is_empty() {
            return Err(bad("it has no parts"));
        }
        if !(spec.density.is_finite() && spec.density > 0.0) {
            return Err(bad("density must be a positive number"));
        }
        let non_negative = |x: f32| x.is_finite() && x >= 0.0;
        if !non_negative(spec.friction) || !non_negative(spec.angular_damping) {
            return Err(bad("friction and damping must be non-negative numbers"));
        }
        if !pose_is_finite(&spec.pose) {
            return Err(bad("its pose is not finite"));
        }
        let id = ObjectId(self.objects.len() as u32);
        let body = if spec.fixed {
            RigidBodyBuilder::fixed()
        } else {
            RigidBodyBuilder::dynamic()
        }
        .pose(spec.pose)
        .angular_damping(spec.angular_damping)
        .user_data(u128::from(id.0))
        .build();
        let body = self.physics.insert_body(body);
        let mut colliders = Vec::with_capacity(spec.parts.len());
        for part in &spec.parts {
            let builder = collider(part.primitive)
                .ok_or_else(|| bad("a part has a non-positive or non-finite size"))?;
            if !pose_is_finite(&part.offset) {
                return Err(bad("a part's offset is not finite"));
            }
            let built = builder
                .position(part.offset)
                .density(spec.density)
                .friction(spec.friction)
                .user_data(u128::from(id.0))
                .build();
            colliders.push(self.physics.insert_collider(built, Some(body)));
        }
        self.objects.push(Object {
            name: spec.name,
            category: spec.category,
            fixed: spec.fixed,
            body,
            colliders,
        });
        self.states.push(UnaryStates::default());
        Ok(id)
    }

    /// Adds a room; `floor`, if given, is the object standing for its floor.
    pub fn add_room(&mut self, room: Room) {
        self.rooms.push(room);
    }

    pub fn objects(&self) -> impl ExactSizeIterator<Item = (ObjectId, &Object)> {
        self.objects
            .iter()
            .enumerate()
            .map(|(i, o)| (ObjectId(i as u32), o))
    }

    pub fn object(&self, id: ObjectId) -> &Object {
        &self.objects[id.0 as usize]
    }

    pub fn object_named(&self, name: &str) -> Option<ObjectId> {
        self.objects
            .iter()
            .position(|o| o.name == name)
            .map(|i| ObjectId(i as u32))
    }

    pub fn rooms(&self) -> &[Room] {
        &self.rooms
    }

    /// The room whose footprint contains (x, y); the first one added wins on shared walls.
    pub fn room_at(&self, x: f32, y: f32) -> Option<&Room> {
        self.rooms.iter().find(|r| r.contains(x, y))
    }

    /// Action steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    pub fn substeps(&self) -> Substeps {
        self.substeps
    }

    /// The pose of an object's body.
    pub fn pose(&self, id: ObjectId) -> Pose {
        *self.physics.bodies[self.object(id).body].position()
    }

    /// Moves an object (teleport), waking it.
    pub fn set_pose(&mut self, id: ObjectId, pose: Pose) -> Result<(), WorldError> {
        if !pose_is_finite(&pose) {
            return Err(WorldError::BadObject {
                name: self.object(id).name.clone(),
                reason: "the requested pose is not finite".into(),
            });
        }
        let body = self.object(id).body;
        let body = &mut self.physics.bodies[body];
        body.set_position(pose, true);
        body.set_linvel(Vector::ZERO, true);
        body.set_angvel(Vector::ZERO, true);
        Ok(())
    }

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

    /// Advances one action step: the physics substeps, then the state rules.
    pub fn step(&mut self) {
        for _ in 0..self.substeps.count() {
            self.physics.step();
        }
        self.steps += 1;
    }

    pub fn snapshot(&self) -> Snapshot {
        Snapshot(self.clone())
    }

    pub fn restore(&mut self, snapshot: &Snapshot) {
        *self = snapshot.0.clone();
    }

    /// Positions, orientations and velocities of every object as raw bits: equal digests mean
    /// bit-identical motion state.
    pub fn motion_bits(&self) -> Vec<u32> {
        let mut bits = Vec::with_capacity(self.objects.len() * 13);
        for object in &self.objects {
            let body = &self.physics.bodies[object.body];
            let p = body.position();
            let (t, r) = (p.translation, p.rotation);
            let (v, w) = (body.linvel(), body.angvel());
            for x in [
                t.x, t.y, t.z, r.x, r.y, r.z, r.w, v.x, v.y, v.z, w.x, w.y, w.z,
            ] {
                bits.push(x.to_bits());
            }
        }
        bits
    }
}

fn pose_is_finite(pose: &Pose) -> bool {
    pose.translation.is_finite() && pose.rotation.is_finite()
}

fn collider(primitive: Primitive) -> Option<ColliderBuilder> {
    let ok = |x: f32| x.is_finite() && x > 0.0;
    // parry's cylinders and capsules run along y; ours stand along z.
    let upright = Pose::from_rotation(Rotation::from_rotation_x(std::f32::consts::FRAC_PI_2));
    Some(match primitive {
        Primitive::Box { half_extents: h } if ok(h.x) && ok(h.y) && ok(h.z) => {
            ColliderBuilder::cuboid(h.x, h.y, h.z)
        }
        Primitive::Sphere { radius } if ok(radius) => ColliderBuilder::ball(radius),
        Primitive::Capsule {
            radius,
            half_height,
        } if ok(radius) && ok(half_height) => ColliderBuilder::capsule_z(half_height, radius),
        Primitive::Cylinder {
            radius,
            half_height,
        } if ok(radius) && ok(half_height) => {
            let shape = rapier3d::geometry::SharedShape::cylinder(half_height, radius);
            ColliderBuilder::compound(vec![(upright, shape)])
        }
        _ => return None,
    })
}
