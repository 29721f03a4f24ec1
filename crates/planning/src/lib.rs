//! Action primitives, the task planner agent that solves activities with them, and motion
//! planning for BEHAVIOR's robots (issue 13).
//!
//! - **Primitives** ([`Primitive`], [`Call`]): the paper's six and what the activities need
//!   beyond them. In symbolic mode ([`check`], [`apply`]) the original's feasibility checks, then
//!   the outcome set at once; a refusal is a [`Failure`] that says why and changes nothing.
//!   [`run`] does one in an episode between two steps ([`behavior_env::Env::edit`]), followed by
//!   one still step, recording it for [`replay_edit`] to do again. In physical mode
//!   navigation ([`drive_to`]) and grasps and placements ([`grasp`], [`place`]) are planned
//!   and executed by the robot's own actions with physics; grasps and placements, and whether
//!   a hand [`reaches`], through the robot's manipulator (`manipulation.rs`): hands posed
//!   directly (`posed_hands.rs`, the BehaviorRobot's) or on a jointed arm (`jointed_arm.rs`,
//!   Fetch's).
//! - **The action space** ([`PrimitiveSpace`]): the original's `Discrete(n × K)` with a mask.
//! - **The task planner** ([`Solver`]): goal options, the next literal, the primitives that make
//!   it true, re-planning from the facts after each.
//! - **Motion planning**: [`plan`] finds a collision-free path between two configurations of any
//!   [`Space`] the way the original does (iGibson 2.0.3's `envs/behavior_mp_env.py`,
//!   pybullet-planning's `birrt`): the direct path if free, else RRT-Connect with restarts, then
//!   shortcut smoothing, re-checked at half the space's resolution. [`BaseSpace`] is the base in
//!   (x, y, yaw), swept by the original's base motion and checked with the world's overlap
//!   queries without stepping; where RRT-Connect finds no base path in physical mode,
//!   [`lattice_plan`] searches a 0.1 m,
//!   eight-heading lattice of the same space with A* (the way through a door that random
//!   samples miss, or a fast "none" where the goal's cells are cut off). [`Standing`]
//!   finds where the base may stand to act on an object (NAVIGATE_TO's pose search).
//!   [`HandSpace`] is the BehaviorRobot's hand as a free 6-D body with what it holds, within its
//!   reach of the shoulder.
//!
//! It builds on the episode (`behavior-env`), the robots and the world; it knows nothing of
//! Python, the command line or rendering.
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
mod arm;
mod base;
mod error;
mod execute;
mod hand;
mod jointed_arm;
mod lattice;
mod manipulation;
mod navigate;
mod physical;
mod posed_hands;
mod primitive;
mod rrt;
mod symbolic;
mod task;

pub use action_space::{PrimitiveSet, PrimitiveSpace};
pub use arm::{ARM_RESOLUTION, ArmBody, ArmConfig, ArmSpace};
pub use base::{BaseConfig, BaseSpace, Footprint, home_extent};
pub use error::PlanError;
pub use execute::{ARM_REACH, Mode, Outcome, RecordedCall, RunError, Watcher, replay_edit, run};
pub use hand::{HAND_MARGIN, HAND_RESOLUTION, HAND_WEIGHTS, HandBody, HandConfig, HandSpace};
pub use jointed_arm::{ArmPath, FETCH_APPROACH, FETCH_DESCENT};
pub use jointed_arm::{grasp as arm_grasp, place as arm_place};
pub use lattice::{LATTICE_CELL, LATTICE_EXPANSIONS, LATTICE_HEADINGS, lattice_plan};
pub use manipulation::{
    CLOSE_STEPS, FORCED_GRASP, GRASP_INSET, GRASP_JITTER, PLACE_HEIGHT, PLACE_TRIES, RELEASE_STEPS,
    SETTLE_STEPS, grasp, place, reaches,
};
pub use navigate::{STAND_CLEARANCE, STAND_DISTANCES, STAND_HEADINGS, Standing};
pub use physical::{
    BasePath, DOORS_OPENED, PHYSICAL_BUDGET, POSITION_TOLERANCE, STAND_PLANS, STEPS_PER_WAYPOINT,
    YAW_TOLERANCE, base_config, drive_to,
};
pub use posed_hands::{
    APPROACH_HEIGHT, CROUCH, DESCENT_STEP, DESCENT_STEPS, GRASP_HEADINGS, HAND_RESET, HandPath,
    RISE, approach_plan, grasp as hand_grasp, hand_body, place as hand_place,
};
pub use primitive::{Call, Failure, Primitive, WAIT_STEPS};
pub use rrt::{Path, PlanParams, Planned, Space, plan};
pub use symbolic::{ELEMENT_TRIES, FLOOR_STAND_TRIES, WIDE_OPEN, apply, check, within_reach};
pub use task::{Executed, GivenUp, Limits, Solution, Solver};
