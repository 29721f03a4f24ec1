//! BDDL, the BEHAVIOR Domain Definition Language: from activity definition text to exact goal
//! evaluation.
//!
//! The pipeline, one module per step:
//! [`load`] reads files → [`sexpr`] reads text → [`parser`] builds the
//! [`ast`] → [`activity`] checks it against the [`taxonomy`] and the [`predicate`] vocabulary
//! ([`domain`] checks domain files against the same vocabulary) →
//! [`ground`] grounds the goal over the activity's instances → [`eval`], [`optimize`] and
//! [`options`] evaluate success, Q, volume and list options against a [`eval::PredicateOracle`].
//! Options count their literals as sets by default (the paper's Q), or as the reference
//! implementation's lists with [`Counting::Reference`].
//!
//! This crate knows nothing of physics or rendering: a simulator answers predicates through the
//! oracle trait, and everything here works the same over an in-memory [`eval::FactSet`].
//!
//! ```
//! use behavior_bddl::{Activity, CheckContext, FactSet, GroundGoal, Optimizer, Source};
//!
//! let text = "(define (problem demo_0) (:domain igibson)
//!     (:objects apple.n.01_1 apple.n.01_2 - apple.n.01 table.n.02_1 - table.n.02)
//!     (:init (ontop apple.n.01_1 table.n.02_1))
//!     (:goal (forall (?apple.n.01 - apple.n.01) (ontop ?apple.n.01 ?table.n.02_1))))";
//! let (activity, _warnings) =
//!     Activity::load(&Source::new("demo.bddl", text), CheckContext::default()).unwrap();
//! let goal = GroundGoal::new(&activity);
//! let state: FactSet = activity.initial_facts().into_iter().collect();
//! let optimizer = Optimizer::new(&goal);
//! assert!(!goal.holds(&state));
//! assert_eq!(optimizer.q(&state).unwrap().to_f64(), 0.5);
//! assert_eq!(optimizer.volume(), Some(2));
//! ```

pub mod activity;
pub mod ast;
mod bottom_up;
pub mod diagnostics;
pub mod domain;
pub mod eval;
pub mod ground;
pub mod load;
pub mod matching;
pub mod optimize;
pub mod options;
pub mod parser;
pub mod predicate;
pub mod sexpr;
mod sharing;
pub mod taxonomy;

pub use activity::{Activity, CheckContext, Literal};
pub use behavior_core::{Atom, InstanceId, RoomType};
pub use diagnostics::{Diagnostic, Diagnostics, Source, SourceErrors};
pub use eval::{FactSet, PredicateOracle};
pub use ground::GroundGoal;
pub use load::{Knowledge, LoadError};
pub use optimize::{Counting, Optimizer, Ratio};
pub use predicate::Predicate;
pub use taxonomy::Taxonomy;
