//! Action primitives and the task planner agent that solves activities with them (issue 13),
//! built on the motion planner of `behavior-motion`.
//!
//! - **Primitives** ([`Primitive`], [`Call`]): the paper's six and what the activities need
//!   beyond them. In symbolic mode ([`check`], [`apply`]) the original's feasibility checks, then
//!   the outcome set at once; a refusal is a [`Failure`] that says why and changes nothing.
//!   [`run`] does one in an episode between two steps as a [`RecordedCall`] (an edit of the
//!   world the episode records, [`behavior_env::Env::apply`], and a replay does again),
//!   followed by one still step. In physical mode
//!   navigation ([`drive_to`]) and grasps and placements ([`grasp`], [`place`]) are planned
//!   and executed by the robot's own actions with physics; grasps and placements, and whether
//!   a hand [`reaches`], through the robot's manipulator (`manipulation.rs`): hands posed
//!   directly (`posed_hands.rs`, read through the robot's [`behavior_robots::PosedHand`]: the
//!   BehaviorRobot's) or on a jointed arm (`jointed_arm.rs`, read through its
//!   [`behavior_robots::Arm`]: Fetch's and the R1's). Neither names a robot: a new robot implements one of
//!   the two interfaces.
//! - **The action space** ([`PrimitiveSpace`]): the original's `Discrete(n × K)` with a mask.
//! - **The task planner** ([`Solver`]): goal options, the next literal, the primitives that make
//!   it true, re-planning from the facts after each.
//! - **Physical primitives** plan with `behavior-motion` (the base's, a hand's and an arm's
//!   spaces, RRT-Connect, the lattice, where to stand) and execute each plan step by step.
//!
//! It builds on the episode (`behavior-env`), the motion planner, the robots and the world; it
//! knows nothing of Python, the command line or rendering.
//!
//! ```
//! use behavior_env::{Env, EnvConfig};
//! use behavior_planning::{Limits, Mode, RunError, Solver};
//!
//! /// Solves an episode of `config` (an activity, its homes, a robot: see [`EnvConfig::new`])
//! /// with symbolic primitives; whether the goal was reached, and by how many primitives.
//! fn solve(config: EnvConfig, seed: u64) -> Result<(bool, usize), RunError> {
//!     let mut env = Env::new(config);
//!     env.reset(seed)?;
//!     let limits = Limits::default();
//!     let solution = Solver::new(&mut env, Mode::Symbolic, limits, None, &mut |_| {}).solve()?;
//!     Ok((solution.success, solution.primitives.len()))
//! }
//! ```

mod action_space;
mod doors;
mod edits;
mod execute;
mod jointed_arm;
mod manipulation;
mod physical;
mod posed_hands;
mod primitive;
mod symbolic;
mod task;
mod tools;
mod tuning;

pub use action_space::{PrimitiveSet, PrimitiveSpace};
pub use edits::{EditError, RecordedCall};
pub use execute::{ARM_REACH, Mode, Outcome, RunError, Watcher, run, run_with};
pub use manipulation::{FORCED_GRASP, grasp, place, press, reaches, swing, use_tool};
pub use physical::{BasePath, DOORS_OPENED, base_config, drive_to};
pub use posed_hands::{
    HAND_RESET, HandPath, approach_plan, grasp as hand_grasp, hand_body, place as hand_place,
};
pub use primitive::{Call, Failure, Primitive, WAIT_STEPS};
pub use symbolic::{apply, check, within_reach};
pub use task::{Executed, GivenUp, Limits, Solution, Solver};
pub use tuning::Tuning;
