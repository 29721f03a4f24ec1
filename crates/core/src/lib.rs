//! The shared vocabulary of BEHAVIOR in Rust: the words every stage of the data flow uses to talk
//! to the next, and nothing heavier.
//!
//! - [`Predicate`]: the closed set of BDDL predicates a simulator must answer;
//! - [`Ability`] and [`AbilityParams`]: what an object of a synset can do or undergo, with the
//!   taxonomy's parameters (`cook_temperature`, `requires_toggled_on`, …);
//! - [`RoomType`]: the eleven room types of BEHAVIOR homes;
//! - [`PredicateOracle`], [`Atom`] and [`InstanceId`]: the bridge between the language, which
//!   grounds goals over an activity's instances, and a world, which answers each ground atom;
//! - [`rng`]: the one seeded generator and the one way of turning it into floats.
//!
//! The language (`behavior-bddl`) and the world (`behavior-sim`) both depend on this crate and on
//! neither of each other. It must never know about text, physics, geometry or files.
//!
//! ```
//! use behavior_core::{Atom, InstanceId, Predicate, PredicateOracle};
//!
//! // Any closure over atoms is an oracle: here apples (instance 0) are cooked and nothing else.
//! let oracle = |atom: Atom| atom.predicate == Predicate::Cooked && atom.subject == InstanceId(0);
//! assert!(oracle.holds(Atom::unary(Predicate::Cooked, InstanceId(0))));
//! assert!(!oracle.holds(Atom::binary(Predicate::OnTop, InstanceId(0), InstanceId(1))));
//! ```

mod ability;
mod oracle;
mod predicate;
pub mod rng;
mod room;

pub use ability::{Ability, AbilityParams, ParamValue};
pub use oracle::{Atom, InstanceId, PredicateOracle};
pub use predicate::Predicate;
pub use room::{RoomType, UnknownRoomType};

/// The synset every activity uses for the robot.
pub const AGENT_SYNSET: &str = "agent.n.01";
/// The synset of room floors: bound to a room's floor rather than created as an object.
pub const FLOOR_SYNSET: &str = "floor.n.01";
/// The synset of a home's wall pieces: fixed scenery that no activity names.
pub const WALL_SYNSET: &str = "wall.n.01";
/// The synset of a home's doors (doorway leaves, which activities open, close and lock).
pub const DOOR_SYNSET: &str = "door.n.01";
/// The synset of a home's windows.
pub const WINDOW_SYNSET: &str = "window.n.01";

/// An angle, rad, brought into (−π, π]: the robots' controllers and the planners compare
/// headings with it.
pub fn wrap_angle(a: f32) -> f32 {
    use std::f32::consts::PI;
    let w = (a + PI).rem_euclid(2.0 * PI) - PI;
    if w <= -PI { w + 2.0 * PI } else { w }
}

/// How far (x, y) is from the rectangle `min`–`max` across the floor: 0 inside it. The planners
/// ask it of stands, the sampler of where a person stands by an object on the floor.
pub fn floor_gap(min: [f32; 2], max: [f32; 2], x: f32, y: f32) -> f32 {
    let dx = (min[0] - x).max(x - max[0]).max(0.0);
    let dy = (min[1] - y).max(y - max[1]).max(0.0);
    dx.hypot(dy)
}
