//! Activity instances: a physical initial state of an activity in a home, sampled from its
//! `:init` literals.
//!
//! [`instantiate`] binds the activity's furniture and floors (the instances with `inroom`) to the
//! home's objects by bipartite matching per room type, creates every other object from the object
//! library, places them in dependency order (`ontop`, `inside`, `under`, `onfloor`), sets every
//! unary literal, lets the world settle and checks every init literal in the settled world. A
//! failed attempt is retried with fresh randomness; after [`ATTEMPTS`] the error names the literal
//! that could not be satisfied and why. Before an instance is handed out, [`goal_feasible`]
//! checks that some goal option's placements can be made in this home. The same (activity, home,
//! seed) always gives the same instance.
//!
//! This crate joins BDDL, the world and the assets; it knows nothing of robots or rendering.

pub mod instance;
pub mod sample;

pub use instance::{Instance, SavedInstance};
pub use sample::{ATTEMPTS, SampleError, goal_feasible, instantiate};
