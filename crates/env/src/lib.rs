//! The BEHAVIOR episode: a robot in an activity instance, stepped at 30 Hz through Gymnasium's
//! contract (`reset(seed)`, `step(action)` → observation, reward, terminated, truncated, info),
//! scored every step by the success score Q and the paper's metrics, recorded to MCAP and
//! replayed bit for bit.
//!
//! It owns the episode: where initial states come from (sampled, saved, a pool), the robot put
//! in the place of the activity's `agent.n.01`, observations (proprioception, `task_obs`, the
//! robot's camera and lidar from `behavior-render`, and [`Sensor`]s others add), reward,
//! termination, the metrics and recordings. It knows nothing of Python or the command line; it
//! builds on the world (`behavior-sim`), the robots, the sampler, the renderer and BDDL's goal
//! evaluation.
//!
//! ```
//! use behavior_env::{Agent, Env, EnvConfig, EnvError};
//!
//! /// A random agent's episode in an environment made from `config` (an activity, its
//! /// homes, a robot: see [`EnvConfig::new`]); returns the final Q.
//! fn random_episode(config: EnvConfig, seed: u64) -> Result<f64, EnvError> {
//!     let mut env = Env::new(config);
//!     env.reset(seed)?;
//!     let mut agent = Agent::named("random", seed).expect("a built-in agent");
//!     let mut action = Vec::new();
//!     loop {
//!         agent.act(&env, &mut action);
//!         let step = env.step(&action)?;
//!         if step.terminated || step.truncated {
//!             return Ok(step.info.score.q);
//!         }
//!     }
//! }
//! ```
//!
//! Inside: `config.rs` (what an env is made of), `env.rs` (reset and step), `episode.rs` (an
//! episode's state, the robot replacing the agent), `observation.rs`, `sensors.rs` (the
//! camera and lidar), `score.rs` (Q and goal
//! status), `metrics/` (one module per metric, the benchmark's aggregate and human
//! normalization), `record/` (MCAP recordings and replay), `timing.rs`, `agent.rs` (idle and
//! random agents).

mod agent;
mod config;
mod edit;
mod env;
mod episode;
pub mod metrics;
mod observation;
pub mod record;
mod score;
mod sensors;
mod timing;

pub use agent::Agent;
pub use config::{DEFAULT_MAX_STEPS, EnvConfig, Instances, Observations, Reward};
pub use edit::{Edit, NoEdit, NoEdits, WorldEdit};
pub use env::{Checkpoint, Env, EnvError, Info, SAMPLE_TRIES, SETTLE_STEPS, Step, derived_seed};
pub use episode::{CHECKPOINT_FORMAT_VERSION, CheckpointError, Start};
pub use metrics::{EpisodeMetrics, Series};
pub use observation::{
    Obs, Reading, Sensor, SensorInput, TASK_OBJECT_DIM, TASK_OBJECTS, TASK_OBS_DIM,
};
pub use score::Score;
pub use sensors::{CameraConfig, CameraSensor, FixedCamera, LidarSensor, Placement, categories};
pub use timing::StepTimings;
