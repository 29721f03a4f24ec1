//! The world: objects made of rigid bodies with compound colliders, rooms with their floors, the
//! physics engine (rapier3d), the step pipeline and snapshots.
//!
//! Units are metres, kilograms and seconds; z points up. One [`World::step`] is one action step
//! of 1/30 s, run as physics substeps of 1/300 s (or 1/120 s, see [`Substeps`]).

use crate::states::ObjectState;
use crate::water::WaterStream;
use behavior_bddl::Predicate;
use behavior_bddl::taxonomy::{Ability, AbilityParams, ParamValue, Taxonomy};
use rapier3d::dynamics::{
    CCDSolver, GenericJoint, ImpulseJointHandle, PrismaticJointBuilder, RevoluteJointBuilder,
    RigidBodyActivation, RigidBodyBuilder, RigidBodyHandle,
};
use rapier3d::geometry::{Collider, ColliderBuilder, ColliderHandle};
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::bounding_volume::BoundingVolume;
use rapier3d::pipeline::{CollisionPipeline, PhysicsPipeline, PhysicsWorld};
use rapier3d::prelude::Aabb;
use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};

/// One action step, in seconds.
pub const STEP_SECONDS: f32 = 1.0 / 30.0;

/// `user_data` of water drops' colliders, which belong to no object.
pub const DROP_TAG: u128 = u128::MAX;

/// Index of an object in its [`World`], stable for the world's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ObjectId(pub u32);

/// A collision primitive in the object's frame. Cylinders and capsules stand along z.
#[derive(Clone, Debug, PartialEq)]
pub enum Primitive {
    Box {
        half_extents: Vector,
    },
    Cylinder {
        radius: f32,
        half_height: f32,
    },
    Sphere {
        radius: f32,
    },
    Capsule {
        radius: f32,
        half_height: f32,
    },
    /// The convex hull of these points (imported meshes, convex decompositions).
    ConvexHull {
        points: Vec<Vector>,
    },
}

/// One primitive of an object's compound shape, placed in the object's frame.
#[derive(Clone, Debug, PartialEq)]
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
    /// What the object can do or undergo, with the parameters (from the taxonomy).
    pub abilities: BTreeMap<Ability, AbilityParams>,
    /// Named points in the object's frame: heating element, toggle button, water outlet, slicing
    /// edge, cleaning area.
    pub points: Vec<(PointKind, Vector)>,
    /// Moving parts: doors and drawers, each on one joint to the object's body.
    pub links: Vec<LinkSpec>,
    /// For a sliceable object, the parts of its two halves in its frame; without them slicing
    /// splits its bounding box.
    pub halves: Option<[Vec<Part>; 2]>,
}

/// Where an ability acts, as a point in the object's frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum PointKind {
    /// A heat source's element (stove burner): objects within its distance threshold heat up.
    HeatingElement,
    /// Touched by a hand for a few steps, it toggles the object on or off.
    ToggleButton,
    /// Where a water source's drops come out.
    WaterOutlet,
    /// A slicer's cutting edge: only contacts within [`crate::slicing::EDGE_REACH`] of it slice.
    SlicingEdge,
    /// A cleaning tool's working face: only particles within [`crate::particles::CLEANING_REACH`]
    /// of it are wiped.
    CleaningArea,
}

/// A door or drawer of an object: its parts (in the object's frame, as when closed) and the joint
/// that moves it. Joint position 0 is closed; `range` is fully open (radians or metres).
#[derive(Clone, Debug)]
pub struct LinkSpec {
    pub name: String,
    pub parts: Vec<Part>,
    pub joint: JointKind,
    /// A point on the joint axis, in the object's frame.
    pub anchor: Vector,
    /// The joint axis, in the object's frame; opening turns or slides positively about it.
    pub axis: Vector,
    pub range: f32,
    /// Velocity damping factor of the joint (a motor with target velocity 0).
    pub damping: f32,
    pub density: f32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    Revolute,
    Prismatic,
}

/// A built link: its body, colliders and joint.
#[derive(Clone, Debug)]
pub struct Link {
    pub name: String,
    pub body: RigidBodyHandle,
    pub colliders: Vec<ColliderHandle>,
    pub joint: ImpulseJointHandle,
    pub kind: JointKind,
    pub anchor: Vector,
    /// Unit length.
    pub axis: Vector,
    pub range: f32,
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
            abilities: BTreeMap::new(),
            points: Vec::new(),
            links: Vec::new(),
            halves: None,
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

    /// Takes the abilities (and their parameters) of the spec's category from the taxonomy;
    /// `false` if the taxonomy lacks the synset.
    pub fn abilities_from(&mut self, taxonomy: &Taxonomy) -> bool {
        match taxonomy.get(&self.category) {
            Some(synset) => {
                self.abilities = taxonomy.synset(synset).abilities.clone();
                true
            }
            None => false,
        }
    }

    /// Adds an ability with its parameters, e.g. `(Cookable, &[("cook_temperature", 70)])`.
    pub fn ability(mut self, ability: Ability, params: &[(&str, ParamValue)]) -> ObjectSpec {
        let params = params.iter().map(|(k, v)| (k.to_string(), *v)).collect();
        self.abilities.insert(ability, params);
        self
    }

    pub fn point(mut self, kind: PointKind, position: Vector) -> ObjectSpec {
        self.points.push((kind, position));
        self
    }

    pub fn link(mut self, link: LinkSpec) -> ObjectSpec {
        self.links.push(link);
        self
    }
}

#[derive(Clone, Debug)]
pub struct Object {
    pub name: String,
    pub category: String,
    pub fixed: bool,
    pub body: RigidBodyHandle,
    /// Every collider of the object, its links' included.
    pub colliders: Vec<ColliderHandle>,
    pub abilities: BTreeMap<Ability, AbilityParams>,
    pub points: Vec<(PointKind, Vector)>,
    pub links: Vec<Link>,
    pub halves: Option<[Vec<Part>; 2]>,
    /// The density the object was made with (for its halves).
    pub density: f32,
}

impl Object {
    pub fn has(&self, ability: Ability) -> bool {
        self.abilities.contains_key(&ability)
    }

    /// A numeric parameter of an ability, or `default` when the ability lists none.
    pub fn param(&self, ability: Ability, name: &str, default: f32) -> f32 {
        self.abilities
            .get(&ability)
            .and_then(|p| p.get(name))
            .and_then(|v| v.as_f64())
            .map_or(default, |v| v as f32)
    }

    /// A boolean parameter of an ability, or `default`.
    pub fn flag(&self, ability: Ability, name: &str, default: bool) -> bool {
        self.abilities
            .get(&ability)
            .and_then(|p| p.get(name))
            .and_then(|v| v.as_bool())
            .unwrap_or(default)
    }

    /// The first named point of a kind, in the object's frame.
    pub fn point(&self, kind: PointKind) -> Option<Vector> {
        self.points
            .iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, p)| *p)
    }
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
    pub(crate) states: Vec<ObjectState>,
    /// Hand points reported by the embodiment, for toggling.
    pub(crate) hands: Vec<Vector>,
    pub(crate) water: Vec<WaterStream>,
    /// Per object: how many times it has moved (see [`World::motion`]).
    motion: Vec<u64>,
    /// Memoized binary predicates with the motion counts they were computed at.
    pub(crate) cache: RefCell<PredicateMemo>,
    /// The last physics step left every body asleep and nothing has changed since, so further
    /// substeps would change nothing: they are skipped until something wakes.
    pub(crate) quiet: bool,
    steps: u64,
    substeps: Substeps,
}

/// Memoized binary predicates: (predicate, a, b) → (value, motion counts of a and b).
pub(crate) type PredicateMemo = HashMap<(Predicate, ObjectId, ObjectId), (bool, (u64, u64))>;

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
            hands: self.hands.clone(),
            water: self.water.clone(),
            motion: self.motion.clone(),
            cache: RefCell::new(self.cache.borrow().clone()),
            quiet: self.quiet,
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
            hands: Vec::new(),
            water: Vec::new(),
            motion: Vec::new(),
            cache: RefCell::new(HashMap::new()),
            quiet: false,
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
            return Err(bad(
                "its pose is not finite or its rotation not a unit quaternion",
            ));
        }
        if !spec.points.iter().all(|(_, p)| p.is_finite()) {
            return Err(bad("a named point is not finite"));
        }
        if let Some(halves) = &spec.halves
            && halves
                .iter()
                .any(|h| h.is_empty() || colliders_of(h, 1.0, 0.5, ObjectId(0)).is_none())
        {
            return Err(bad("its halves must each have valid parts"));
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
        let builders = colliders_of(&spec.parts, spec.density, spec.friction, id)
            .ok_or_else(|| bad("a part has a non-positive or non-finite size or offset"))?;
        // Validate every link before touching the physics, so a bad spec leaves no trace.
        let mut link_builders = Vec::with_capacity(spec.links.len());
        for link in &spec.links {
            let ok = link.range.is_finite()
                && link.range > 0.0
                && link.damping.is_finite()
                && link.damping >= 0.0
                && link.density.is_finite()
                && link.density > 0.0
                && link.anchor.is_finite()
                && link.axis.is_finite()
                && link.axis.length() > 1e-6
                && !link.parts.is_empty();
            match colliders_of(&link.parts, link.density, spec.friction, id) {
                Some(parts) if ok => link_builders.push(parts),
                _ => return Err(bad(&format!("link `{}` is malformed", link.name))),
            }
        }
        let body = self.physics.insert_body(body);
        let mut colliders: Vec<ColliderHandle> = builders
            .into_iter()
            .map(|c| self.physics.insert_collider(c, Some(body)))
            .collect();
        let mut links = Vec::with_capacity(spec.links.len());
        for (link, builders) in spec.links.iter().zip(link_builders) {
            let link_body = RigidBodyBuilder::dynamic()
                .pose(spec.pose)
                .angular_damping(spec.angular_damping)
                .user_data(u128::from(id.0))
                .build();
            let link_body = self.physics.insert_body(link_body);
            let link_colliders: Vec<ColliderHandle> = builders
                .into_iter()
                .map(|c| self.physics.insert_collider(c, Some(link_body)))
                .collect();
            colliders.extend_from_slice(&link_colliders);
            let axis = link.axis.normalize();
            let joint: GenericJoint = match link.joint {
                JointKind::Revolute => RevoluteJointBuilder::new(axis)
                    .local_anchor1(link.anchor)
                    .local_anchor2(link.anchor)
                    .limits([0.0, link.range])
                    .motor_velocity(0.0, link.damping)
                    .contacts_enabled(false)
                    .build()
                    .into(),
                JointKind::Prismatic => PrismaticJointBuilder::new(axis)
                    .local_anchor1(link.anchor)
                    .local_anchor2(link.anchor)
                    .limits([0.0, link.range])
                    .motor_velocity(0.0, link.damping)
                    .contacts_enabled(false)
                    .build()
                    .into(),
            };
            let joint = self.physics.insert_impulse_joint(body, link_body, joint);
            links.push(Link {
                name: link.name.clone(),
                body: link_body,
                colliders: link_colliders,
                joint,
                kind: link.joint,
                anchor: link.anchor,
                axis,
                range: link.range,
            });
        }
        self.objects.push(Object {
            name: spec.name,
            category: spec.category,
            fixed: spec.fixed,
            body,
            colliders,
            abilities: spec.abilities,
            points: spec.points,
            links,
            halves: spec.halves,
            density: spec.density,
        });
        self.states.push(ObjectState::default());
        self.motion.push(0);
        if self.object(id).has(Ability::WaterSource) {
            self.add_water_stream(id);
        }
        self.refresh();
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

    /// Moves an object (teleport) with its links, at rest, waking it.
    pub fn set_pose(&mut self, id: ObjectId, pose: Pose) -> Result<(), WorldError> {
        if !pose_is_finite(&pose) {
            return Err(WorldError::BadObject {
                name: self.object(id).name.clone(),
                reason: "the requested pose is not finite".into(),
            });
        }
        // Doors, drawers and lids move with the body, keeping their joint positions.
        let object = &self.objects[id.0 as usize];
        let old = *self.physics.bodies[object.body].position();
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
        self.moved(id);
        self.refresh();
        Ok(())
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

    /// The mass of an object's body (its links excluded), kg.
    pub fn mass(&self, id: ObjectId) -> f32 {
        self.physics.bodies[self.object(id).body].mass()
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

    /// Advances one action step: the physics substeps (watching slicers' contact forces), then
    /// the state rules once: water, toggles, temperature, cleaning, slicing.
    pub fn step(&mut self) {
        let mut pressed: Vec<ObjectId> = Vec::new();
        if !self.quiet {
            for _ in 0..self.substeps.count() {
                self.physics.step();
                for id in self.pressed_by_slicers() {
                    if !pressed.contains(&id) {
                        pressed.push(id);
                    }
                }
            }
            self.quiet = self.physics.islands.num_active_bodies() == 0;
        }
        self.note_motion();
        self.update_water();
        self.update_toggles();
        self.update_temperatures(STEP_SECONDS);
        self.update_cleaning();
        pressed.sort();
        for id in pressed {
            // A sliceable object always accepts slicing; an error here would be a bug in add().
            let _ = self.set_sliced(id, true);
        }
        self.steps += 1;
    }

    /// Drops every memoized predicate (for benchmarks of the uncached computation).
    pub fn forget_predicates(&self) {
        self.cache.borrow_mut().clear();
    }

    /// How many times an object has moved: a step in which its body or a link was awake, or a
    /// teleport. Memoized predicates are valid while the counts of their objects are unchanged.
    pub fn motion(&self, id: ObjectId) -> u64 {
        self.motion[id.0 as usize]
    }

    /// Moves colliders with their teleported bodies now rather than at the next step, so that
    /// predicates see the change at once. (Running the collision pipeline here instead would
    /// consume rapier's record of changed bodies and keep new bodies from ever waking.)
    pub(crate) fn refresh(&mut self) {
        self.quiet = false;
        let physics = &mut self.physics;
        physics
            .bodies
            .propagate_modified_body_positions_to_colliders(&mut physics.colliders);
    }

    pub(crate) fn moved(&mut self, id: ObjectId) {
        self.motion[id.0 as usize] += 1;
    }

    fn note_motion(&mut self) {
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

/// Finite, with a rotation that is a unit quaternion up to rounding (a zero one would become NaN).
fn pose_is_finite(pose: &Pose) -> bool {
    pose.translation.is_finite()
        && pose.rotation.is_finite()
        && (pose.rotation.length() - 1.0).abs() < 1e-3
}

/// Colliders for parts, tagged with the object's id; `None` if a part is malformed.
fn colliders_of(
    parts: &[Part],
    density: f32,
    friction: f32,
    id: ObjectId,
) -> Option<Vec<Collider>> {
    parts
        .iter()
        .map(|part| {
            let builder = collider(&part.primitive)?;
            pose_is_finite(&part.offset).then(|| {
                builder
                    .position(part.offset)
                    .density(density)
                    .friction(friction)
                    .user_data(u128::from(id.0))
                    .build()
            })
        })
        .collect()
}

fn collider(primitive: &Primitive) -> Option<ColliderBuilder> {
    let ok = |x: f32| x.is_finite() && x > 0.0;
    // parry's cylinders and capsules run along y; ours stand along z.
    let upright = Pose::from_rotation(Rotation::from_rotation_x(std::f32::consts::FRAC_PI_2));
    Some(match *primitive {
        Primitive::ConvexHull { ref points } => {
            if points.len() < 4 || !points.iter().all(|p| p.is_finite()) {
                return None;
            }
            ColliderBuilder::convex_hull(points)?
        }
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
