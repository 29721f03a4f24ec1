//! Activity instances: a physical initial state of an activity in a home, sampled from its
//! `:init` literals.
//!
//! [`instantiate`] binds the activity's furniture and floors (the instances with `inroom`) to the
//! home's objects that can host their own init literals, by bipartite matching per room type;
//! creates every other object from the object library; places them in dependency order, each by
//! all its placement literals at once (`ontop`, `inside`, `under`, `nextto`, `touching`,
//! `onfloor`); sets every unary literal; lets the world settle and checks every init literal in the
//! settled world. Before an instance is handed out, [`goal_feasible`] places some goal option's
//! objects for real in a copy of the world. A failed attempt is retried with fresh randomness;
//! after [`ATTEMPTS`] the error names the literal that could not be satisfied and why. The same
//! (activity, home, seed) always gives the same instance.
//!
//! This crate joins BDDL, the world and the assets; it knows nothing of robots or rendering.

pub mod instance;
pub mod sample;

pub use instance::{Instance, SavedInstance};
pub use sample::{ATTEMPTS, SampleError, goal_feasible, instantiate};
