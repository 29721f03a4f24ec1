//! Episode recordings: MCAP files that Foxglove and the `mcap` Python package read, and replay
//! that re-simulates them and checks bit-identity.
//!
//! **Schema.** Every message is JSON (MCAP message encoding `json`, each channel with a JSON
//! Schema), log time = step × 1/30 s in nanoseconds:
//!
//! | topic | when | content |
//! |---|---|---|
//! | `/header` | once, first | [`Header`]: format version, crate version, activity and its definition text, home, seed, robot, action space, physics and action time steps, step limit, the instance (the whole initial state), the world's object names, and who chose the actions ([`Provenance`]; absent where unstated) |
//! | `/action` | every step | `{"step", "values"}`: the action taken at that step |
//! | `/poses` | every step | `{"step", "objects", "poses"}`: the position and quaternion (x, y, z, qx, qy, qz, qw) after the step of each object in `objects` (indices in the header's object order): those whose pose changed since the last `/poses`, bit for bit; every object at the first |
//! | `/score` | every step | `{"step", "q", "success", "conjuncts"}` after the step |
//! | `/checkpoint` | step 0, every `checkpoint_every` steps, and the last step when the recording closes (unless an edit followed it) | `{"step", "digest"}`: SHA-256 of the full state (see `digest.rs`) |
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
pub use replay::{ReplayError, ReplayReport, redo, replay, replay_with, resume, state_at};
pub use writer::RecordError;
pub(crate) use writer::Recorder;

use behavior_sampling::SavedInstance;
use serde::{Deserialize, Serialize};

/// The version of this layout: 2 since `/poses` holds only the objects that moved. Files of
/// version 1 (every pose at every step) still read; a newer version is refused.
pub const FORMAT_VERSION: u32 = 2;
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
    /// Who chose the actions (absent in recordings made before it was kept: unstated).
    #[serde(default, skip_serializing_if = "Provenance::is_unstated")]
    pub provenance: Provenance,
}

/// Who chose a recording's actions: what a dataset of demonstrations must never blur, since a
/// planner's demonstrations are no evidence of what people do.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Provenance {
    /// Not said: an agent's or a script's episode, or one recorded before provenance was kept.
    #[default]
    Unstated,
    /// A person at a device (the browser's keyboard or a headset); `/device` holds what it
    /// reported.
    Person,
    /// This project's task planner, running its primitives in the mode named (`physical`,
    /// `symbolic`); `plan` says whose plan it carried out (`planner`: its own).
    Planner {
        /// The primitives' mode.
        mode: String,
        /// Whose plan: `planner` for the planner's own.
        plan: String,
    },
}

impl Provenance {
    /// Whether nothing is said.
    pub fn is_unstated(&self) -> bool {
        *self == Provenance::Unstated
    }
}

/// How to record an episode, besides where ([`crate::Env::record_to`]).
#[derive(Clone, Debug, PartialEq)]
pub struct RecordingSetup<'a> {
    /// The activity's definition (BDDL text), kept so that a replay needs no other file.
    pub definition: &'a str,
    /// A checkpoint (digest and full state) every this many steps.
    pub checkpoint_every: u32,
    /// Who chooses the actions.
    pub provenance: Provenance,
}

impl<'a> RecordingSetup<'a> {
    /// A recording of `definition`'s episode with a checkpoint every `checkpoint_every` steps,
    /// its provenance unstated.
    pub fn new(definition: &'a str, checkpoint_every: u32) -> Self {
        RecordingSetup {
            definition,
            checkpoint_every,
            provenance: Provenance::Unstated,
        }
    }

    /// The same, made by `provenance`.
    pub fn by(self, provenance: Provenance) -> Self {
        RecordingSetup { provenance, ..self }
    }
}
