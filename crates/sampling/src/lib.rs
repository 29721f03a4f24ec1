//! Activity instances: a physical initial state of an activity in a home, sampled from its
//! `:init` literals.
//!
//! [`instantiate`] binds the activity's furniture and floors (the instances with `inroom`) to the
//! home's objects that can host their own init literals, by bipartite matching per room type
//! (never to the home's clutter); puts away the clutter around the bound furniture and floors the
//! activity places things relative to, so that its objects find room; creates every other object from the object library; places them in dependency order, each by
//! all its placement literals at once (`ontop`, `inside`, `under`, `nextto`, `touching`,
//! `onfloor`); sets every unary literal; lets the world settle and checks every init literal in the
//! settled world ([`check_init`]). Before an instance is handed out, [`goal_feasible`] places some
//! goal option's objects for real in a copy of the world, in the same dependency order. A failed
//! attempt is retried with fresh randomness; after [`ATTEMPTS`] the error names the literal that
//! could not be satisfied and why ([`SampleError`]). The same (activity, home, seed) always gives
//! the same instance. [`SavedInstance`] is an instance as a file, with the whole world state;
//! loading one re-checks it ([`LoadError`]). [`Instance::facts`] lists the logical state: every
//! predicate that holds among the activity's objects.
//!
//! This crate joins BDDL, the world and the assets; it knows nothing of robots or rendering.
//!
//! An instance of an official activity in the first named home that fits it:
//!
//! ```
//! use behavior_assets::{Library, first_covering};
//! use behavior_bddl::Knowledge;
//! use behavior_bddl::load::read_source;
//! use behavior_data::DataDir;
//! use behavior_sampling::{check_init, instantiate};
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let data = DataDir::locate(None, |message| eprintln!("{message}"))?;
//! let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path())?;
//! let source = read_source(&data.problem_path("bottling_fruit")?)?;
//! let (activity, _warnings) = knowledge.load(&source)?;
//! let library = Library::new(&knowledge.taxonomy);
//! let home = first_covering(&activity, &library, &knowledge.taxonomy)?.expect("a home fits");
//! let instance = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy)?;
//! assert!(check_init(&activity, &instance.world, &instance.bindings).all_hold());
//! # Ok(())
//! # }
//! ```
//!
//! Inside, each stage of an attempt has its own module, all working on one shared context (the
//! attempt's activity, home, library, random numbers, world and bindings): `bind` (furniture and
//! floors), `tidy` (clutter around them put away), `create` (the other objects), `order` (the one dependency order, for the initial
//! state and goal options alike), `place`, `states`, `verify` (the init check), `goal`.

mod bind;
mod create;
mod error;
mod facts;
mod goal;
mod instance;
mod instantiate;
mod order;
mod place;
mod states;
mod tidy;
mod verify;
mod way_out;

pub use error::{
    Literals, LoadError, NamedLiteral, RuledOut, SampleError, Unmet, Unreachable, Unsatisfied,
};
pub use facts::Fact;
pub use goal::{FEASIBILITY_OPTIONS, PHYSICAL_OPTIONS, goal_feasible};
pub use instance::{Created, Instance, SavedInstance, SavedObject, SavedParticles, SavedState};
pub use instantiate::{ATTEMPTS, SETTLE_STEPS, instantiate};
pub use verify::{InitCheck, LiteralCheck, LiteralKind, check_init};
