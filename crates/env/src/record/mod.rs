//! Episode recordings: MCAP files that Foxglove and the `mcap` Python package read, and replay
//! that re-simulates them and checks bit-identity.
//!
//! **Schema.** Every message is JSON (MCAP message encoding `json`, each channel with a JSON
//! Schema), log time = step × 1/30 s in nanoseconds:
//!
//! | topic | when | content |
//! |---|---|---|
//! | `/header` | once, first | [`Header`]: format version, crate version, activity and its definition text, home, seed, robot, action space, physics and action time steps, step limit, the instance (the whole initial state), the world's object names |
//! | `/action` | every step | `{"step", "values"}`: the action taken at that step |
//! | `/poses` | every step | `{"step", "poses"}`: every object's position and quaternion (x, y, z, qx, qy, qz, qw), in the header's object order, after the step |
//! | `/score` | every step | `{"step", "q", "success", "conjuncts"}` after the step |
//! | `/checkpoint` | step 0 and every `checkpoint_every` steps | `{"step", "digest"}`: SHA-256 of the full state (see `digest.rs`) |
//! | `/edit` | after a step (or the reset) when the world was edited before the next ([`crate::Env::apply`]) | `{"step", "edit"}`: what was done, a [`crate::WorldEdit`] value in its own words (a symbolic primitive: `{"primitive", "object", "hand"}`) |
//! | `/device` | before a teleoperated step | `{"step", "device"}`: what the person's device reported for that step (a headset's raw poses, keyboard rates), in the teleoperator's words; a replay does not need it |
//! | `/state` | with each checkpoint | the full state as bytes (encoding [`STATE_ENCODING`], no schema): the world (`World::to_bytes`), the robot, the bindings, the running metrics; an episode resumes from it |
//!
//! Chunks are zstd-compressed and appended as they fill ([`CHUNK_BYTES`]), and the file is
//! flushed at every checkpoint: a killed process leaves a file readable up to its last whole
//! chunk. Reading stops at the first damaged record with an error naming the last whole step.

mod digest;
#[cfg(feature = "lerobot")]
pub mod lerobot;
mod reader;
mod replay;
mod writer;

pub use digest::state_digest;
pub use reader::{Frame, ReadError, Recording, read};
pub use replay::{ReplayError, ReplayReport, redo, replay, replay_with, resume};
pub use writer::RecordError;
pub(crate) use writer::Recorder;

use behavior_sampling::SavedInstance;
use serde::{Deserialize, Serialize};

/// The version of this layout; a file of another version is refused.
pub const FORMAT_VERSION: u32 = 1;
/// Chunks are written once they hold this many bytes (before compression).
pub const CHUNK_BYTES: u64 = 256 * 1024;
/// The MCAP message encoding of `/state`: an episode checkpoint's bytes
/// ([`crate::Checkpoint::to_bytes`]).
pub const STATE_ENCODING: &str = "behavior-episode-checkpoint";
/// Checkpoints every this many steps by default.
pub const CHECKPOINT_EVERY: u32 = 100;

/// What a recording starts with: everything a replay needs to begin the episode again.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// [`FORMAT_VERSION`].
    pub format_version: u32,
    /// The version of the crate that wrote it.
    pub crate_version: String,
    /// The activity's problem name.
    pub activity: String,
    /// The activity's definition (BDDL text), so a replay needs no other file.
    pub definition: String,
    /// The home's name.
    pub scene: String,
    /// The seed of the reset.
    pub seed: u64,
    /// The robot (`behavior`, `fetch`).
    pub robot: String,
    /// The action space (`full`, `navigation`, `mobile_manipulation`, `tabletop_manipulation`).
    pub action_space: String,
    /// Physics substeps per second (300 or 120).
    pub physics_hz: u32,
    /// Action steps per second (30).
    pub action_hz: u32,
    /// The episode's step limit.
    pub max_steps: u32,
    /// Checkpoint period, steps.
    pub checkpoint_every: u32,
    /// The initial state.
    pub instance: SavedInstance,
    /// The world's objects at the start, in the order `/poses` lists them.
    pub objects: Vec<String>,
}
