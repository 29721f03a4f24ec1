//! Motion planning for BEHAVIOR's robots (issue 13, first part).
//!
//! [`plan`] finds a collision-free path between two configurations of any [`Space`] the way the
//! original does (reference §5, pybullet-planning's `birrt`): the direct path if it is free, else
//! bidirectional RRT (RRT-Connect) with restarts, then shortcut smoothing; every returned path is
//! checked again at half the space's resolution before it is handed out. [`BaseSpace`] is the
//! robot's base in (x, y, yaw): a footprint of shapes swept by the original's base motion (turn
//! toward the next point, drive straight, turn to the goal's heading) and checked with the
//! world's overlap queries, without stepping physics.
//!
//! [`Standing`] reads a robot's footprint, eye and what its checks ignore from the world, and
//! finds where its base may stand to act on an object (NAVIGATE_TO's pose search, §5).
//!
//! It owns the search and the spaces. It knows nothing of activities, episodes or rendering, and
//! does not drive robots: a caller executes the path.

mod action_space;
mod base;
mod error;
mod execute;
mod navigate;
mod physical;
mod primitive;
mod rrt;
mod symbolic;
mod task;

pub use action_space::{PrimitiveSet, PrimitiveSpace};
pub use base::{BaseConfig, BaseSpace, Footprint};
pub use error::PlanError;
pub use execute::{Mode, Outcome, RecordedCall, RunError, replay_edit, run};
pub use navigate::{STAND_CLEARANCE, STAND_DISTANCES, STAND_HEADINGS, Standing};
pub use physical::{
    BasePath, POSITION_TOLERANCE, STEPS_PER_WAYPOINT, YAW_TOLERANCE, base_config, drive_to,
};
pub use primitive::{Call, Failure, Primitive, WAIT_STEPS};
pub use rrt::{Path, PlanParams, Planned, Space, plan};
pub use symbolic::{ELEMENT_TRIES, FLOOR_STAND_TRIES, apply, check, within_reach};
pub use task::{Executed, GivenUp, Limits, Solution, Solver};
