//! The predicate vocabulary of BEHAVIOR-100 lives in `behavior-core`, shared with the world.
//!
//! The set is closed on purpose: a simulator must implement every predicate an activity may use, so
//! the checker rejects names outside it instead of deferring the failure to run time. The domain
//! file `domain_igibson.bddl` declares 17 of these; `onfloor`, `touching` and `inroom` are used by
//! the official activities without being declared there, as in the original simulator.

pub use behavior_core::Predicate;
