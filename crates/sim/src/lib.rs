//! The BEHAVIOR world: objects made of rigid bodies with compound colliders and jointed links,
//! rooms and floors, rigid-body physics (rapier3d, z up, SI units), the state systems (water,
//! toggling, temperature, dirt, slicing), the kinematic predicates, queries for agents (rays,
//! shapes, contacts), attachments, appearance, and a step with hooks for the code that must run
//! inside it.
//!
//! It answers the language's predicates through [`BoundWorld`], a [`behavior_core::PredicateOracle`];
//! it knows nothing of BDDL text, activities, homes, assets, robots or rendering — those crates
//! read and act on the world through the concepts it lends out: [`World::bodies`],
//! [`World::relations`], [`World::query`], [`World::joints`], [`World::attachments`],
//! [`World::contacts`], [`World::visuals`] and [`World::rooms`] (with `_mut` twins for acting).
//!
//! ```
//! use behavior_sim::{ObjectSpec, Part, Primitive, World};
//! use rapier3d::math::Vector;
//!
//! let mut world = World::default();
//! let slab = Primitive::Box { half_extents: Vector::new(0.5, 0.5, 0.05) };
//! let table = world.add(ObjectSpec::new("table_1", "table.n.02", vec![Part::new(slab)]).fixed()).unwrap();
//! let ball = Primitive::Sphere { radius: 0.04 };
//! let apple = world.add(ObjectSpec::new("apple_1", "apple.n.01", vec![Part::new(ball)]).at(Vector::new(0.0, 0.0, 0.3))).unwrap();
//! for _ in 0..60 {
//!     world.step();
//! }
//! assert!(world.relations().ontop(apple, table));
//! ```
//!
//! Layout: [`World`] (`world.rs`) holds the core (`core.rs`: a plain aggregate of the parts below,
//! and their checkpoint form) and the state systems (`states/`). Each part is a type that owns
//! its data, in its own file: the bodies (`bodies.rs`; what controllers do to them in
//! `dynamics.rs`, how an object is built in `construct.rs`, what it is made of in `object.rs`),
//! the relations and their memo (`kinematics.rs`), the query index and queries (`query.rs`), the
//! joints' drives (`joints.rs`), the attachments (`attachments.rs`), the ignored contact pairs
//! (`contacts.rs`) and the rooms (`room.rs`). A part that reads the bodies is lent out as a view
//! pairing it with them ([`Relations`], [`Joints`], [`Attachments`], [`Contacts`], [`Query`],
//! [`Visuals`], and `Mut` twins), so each concept is reached one way. `step.rs` runs a step and
//! its hooks, `visual.rs` is what renderers draw, `placement.rs` is what the sampler places
//! with, `oracle.rs` the bridge to the language, `bytes.rs` the checkpoints.
//!
//! Checkpoints: [`World::to_bytes`] saves everything a [`Snapshot`] keeps, so a world read back
//! with [`World::from_bytes`] continues bit-identically (`tests/world_bytes.rs`, and a cluttered
//! home in `behavior-assets`' tests). Saved: the objects, rooms, drives, attachments, ignored
//! pairs, step and motion counters, the memoized relations (in key order, so equal worlds give
//! equal bytes), every state system with its generator, and rapier's whole state — bodies,
//! colliders, impulse and multibody joints, the island manager, the broad phase and the narrow
//! phase with its contact manifolds and warm-start impulses. Rebuilt: the query index (on first
//! use, as after any step), rapier's physics and collision pipelines and CCD solver (scratch
//! space, as a clone rebuilds them), and the few caches rapier itself leaves out of its serde
//! form. The bytes carry a magic, a format version ([`WORLD_FORMAT_VERSION`], bumped when a
//! saved type, ours or rapier's, changes shape) and a CRC-32; bad bytes are a
//! [`WorldBytesError`], never a panic. A cluttered home of 248 objects saves to about 0.9 MB
//! (a third of it the narrow phase's contacts; gzip takes it to 0.34 MB) in about 2 ms and
//! loads in about 4.5 ms.

mod attachments;
mod bodies;
mod bytes;
mod construct;
mod contacts;
mod core;
mod dynamics;
mod joints;
mod kinematics;
mod object;
mod oracle;
mod placement;
mod query;
mod room;
mod states;
mod step;
mod visual;
mod world;

pub use attachments::{
    AttachmentId, AttachmentKind, AttachmentSpec, AttachmentState, Attachments, AttachmentsMut,
};
pub use bodies::Bodies;
pub use bytes::{WORLD_FORMAT_VERSION, WORLD_MAGIC, WorldBytesError};
pub use contacts::{Contact, Contacts, ContactsMut, groups};
pub use core::{STEP_SECONDS, Substeps, WorldError};
pub use dynamics::Velocity;
pub use joints::{Drive, JointState, Joints, JointsMut, OPEN_FRACTION};
pub use kinematics::{
    FLAT_HEIGHT, HORIZONTAL_DIRECTIONS, HORIZONTAL_RANGE, ONFLOOR_HEIGHT, Relations, SUPPORT_COS,
    TOUCH_DISTANCE, VERTICAL_RANGE,
};
pub use object::{
    BodyKind, BodyRef, JointKind, JointModel, JointSpec, Link, LinkSpec, Object, ObjectId,
    ObjectSpec, Part, PointKind, Primitive,
};
pub use oracle::BoundWorld;
pub use placement::{
    DROP_GAP, LEVEL_SPACING, NEXTTO_GAP, PLACEMENT_ATTEMPTS, PlacementError, PlacementFailure,
    Relation, SUPPORT_NORMAL_Z, TOUCH_GAP,
};
pub use query::{Proximity, Query, QueryFilter, RayHit, Solid};
pub use room::{FloorRect, Room};
pub use states::StateError;
pub use states::dirt::{
    CLEAN_THRESHOLD, CLEANING_REACH, FLOOR_CLEAN_THRESHOLD, MIN_PARTICLES, PARTICLES_PER_SET,
    WIPE_MARGIN,
};
pub use states::record::{ObjectState, ParticleRecord};
pub use states::slicing::{EDGE_REACH, SLICE_FORCE};
pub use states::temperature::{
    DECAY_RATE, DEFAULT_BURN_TEMPERATURE, DEFAULT_COOK_TEMPERATURE, DEFAULT_DISTANCE_THRESHOLD,
    DEFAULT_FREEZE_TEMPERATURE, DEFAULT_HEATING_RATE, DEFAULT_SOURCE_TEMPERATURE, ROOM_TEMPERATURE,
};
pub use states::toggling::{TOGGLE_DISTANCE, TOGGLE_STEPS};
pub use states::water::{
    DROP_LIFETIME_STEPS, DROP_MASS, DROP_RADII, DROPS_PER_SOURCE, OUTLET_OFFSET,
    STEPS_BETWEEN_DROPS,
};
pub use step::StepHooks;
pub use visual::{
    Form, Ghost, HeldMesh, Material, Model, ModelLibrary, ModelPiece, Visual, VisualMesh,
    VisualPart, VisualShape, Visuals,
};
pub use world::{Snapshot, World};
