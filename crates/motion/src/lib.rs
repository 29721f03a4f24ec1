//! Motion planning for BEHAVIOR's robots: where a part of a robot may be, and a free way there.
//!
//! - **Configuration spaces** ([`Space`]): the base in (x, y, yaw) on the floor ([`BaseSpace`],
//!   swept by the original's base motion: turn, drive straight, turn), a hand as a free 6-D
//!   body within its reach of the shoulder ([`HandSpace`]), an arm in its joints ([`ArmSpace`],
//!   read through the robot's [`behavior_robots::Arm`]: Fetch's torso and seven arm joints);
//!   each checks a configuration with the world's overlap queries, without stepping, what the
//!   robot holds included.
//! - **Search**: [`plan`] finds a collision-free path between two configurations of any space
//!   the way the original does (iGibson 2.0.3's `envs/behavior_mp_env.py`, pybullet-planning's
//!   `birrt`): the direct path if free, else RRT-Connect with restarts, then shortcut
//!   smoothing, re-checked at half the space's resolution. Where its random samples miss the
//!   way (a door between rooms), [`lattice_plan`] searches a 0.1 m, eight-heading lattice of
//!   the base's space with A*.
//! - **Where to stand**: [`Standing`] is the robot as it stands (its footprint read from the
//!   world) and finds where its base may stand to act on an object (NAVIGATE_TO's pose search).
//!
//! It knows the world and the robots; it knows nothing of episodes, activities, primitives or
//! the task solver (`behavior-planning` builds those on it). The same seed, world and
//! endpoints always give the same path.
//!
//! ```
//! use behavior_core::rng::{SimRng, uniform};
//! use behavior_motion::{PlanParams, Space, plan};
//!
//! /// The unit square with a wall across x = 0.5 but for a gap at the top.
//! struct Walled;
//!
//! impl Space for Walled {
//!     type Config = [f32; 2];
//!     fn distance(&self, a: &[f32; 2], b: &[f32; 2]) -> f32 {
//!         (a[0] - b[0]).hypot(a[1] - b[1])
//!     }
//!     fn sample(&self, rng: &mut SimRng) -> [f32; 2] {
//!         [uniform(rng, 0.0, 1.0), uniform(rng, 0.0, 1.0)]
//!     }
//!     fn steps(&self, a: &[f32; 2], b: &[f32; 2], resolution: f32) -> Vec<[f32; 2]> {
//!         let n = (self.distance(a, b) / resolution).ceil().max(1.0) as usize;
//!         (1..=n)
//!             .map(|k| {
//!                 let t = k as f32 / n as f32;
//!                 [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
//!             })
//!             .collect()
//!     }
//!     fn free(&self, c: &[f32; 2]) -> bool {
//!         (c[0] - 0.5).abs() > 0.05 || c[1] > 0.8
//!     }
//!     fn resolution(&self) -> f32 {
//!         0.01
//!     }
//! }
//!
//! let params = PlanParams { iterations: 500, ..PlanParams::default() };
//! let planned = plan(&Walled, &[0.1, 0.1], &[0.9, 0.1], &params).expect("a way through the gap");
//! assert!(planned.path.iter().all(|c| Walled.free(c)));
//! assert!(planned.path.iter().any(|c| c[1] > 0.8), "it goes round through the gap");
//! ```
//!
//! Inside: `rrt.rs` (the search and smoothing), `lattice.rs`, `base.rs`, `hand.rs`, `arm.rs`
//! (the spaces and the bodies they check), `navigate.rs` (the robot standing, and where it may
//! stand), `error.rs`.

mod arm;
mod base;
mod error;
mod hand;
mod lattice;
mod navigate;
mod rrt;

pub use arm::{ArmBody, ArmSpace, any_config, closest_turn};
pub use base::{BaseConfig, BaseSpace, Footprint, home_extent, stands_inside};
pub use behavior_core::floor_gap;
pub use error::PlanError;
pub use hand::{HAND_RESOLUTION, HandBody, HandConfig, HandSpace};
pub use lattice::{Reachable, lattice_plan, reachable_from};
pub use navigate::{Standing, inflated, shapes_in};
pub use rrt::{Path, PlanParams, Planned, Space, plan, smooth, steps_along, valid};
