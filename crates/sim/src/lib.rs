//! The BEHAVIOR world: objects made of rigid bodies with compound colliders, rooms and floors,
//! rigid-body physics (rapier3d, z up, SI units), the step pipeline, snapshots, and the BDDL
//! predicates computed from them.
//!
//! It implements the BDDL [`behavior_bddl::PredicateOracle`] through [`oracle::BoundWorld`]; it
//! knows nothing of BDDL text, activities' goals, homes, assets or rendering.
//!
//! ```
//! use behavior_sim::world::{ObjectSpec, Part, Primitive, World};
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
//! assert!(world.ontop(apple, table));
//! ```

pub mod articulation;
pub mod bench_scene;
pub mod kinematics;
pub mod oracle;
pub mod particles;
pub mod placement;
pub mod slicing;
pub mod states;
pub mod temperature;
pub mod toggling;
pub mod water;
pub mod world;

pub use oracle::BoundWorld;
pub use placement::{PlacementError, Relation};
pub use states::StateError;
pub use world::{
    JointKind, LinkSpec, ObjectId, ObjectSpec, Part, PointKind, Primitive, Room, Snapshot,
    Substeps, World, WorldError,
};
