//! Edits of the world between two steps, as values: what an episode's recording keeps and a
//! replay does again.
//!
//! A symbolic action primitive teleports the robot, attaches what it grasps, sets an object's
//! state; a physical one forces a grasp where the hand closed. Such a change is outside physics
//! and actions, so a replay cannot re-simulate it: it must be told. Code that edits the world
//! describes the edit as a [`WorldEdit`] value and hands it to [`crate::Env::apply`], which does
//! it and, when the episode is recording, records it; [`crate::record::replay_with`] reads the
//! recorded values back as the same type and applies them again. This crate does not know what
//! an edit means (it knows no primitives): the type that made the edits does.

use behavior_robots::Robot;
use behavior_sim::{ObjectId, World};
use serde::Serialize;
use serde::de::DeserializeOwned;

/// What an edit may touch: the episode's world and robot, with what it needs to know.
pub struct Edit<'a> {
    /// The episode's world.
    pub world: &'a mut World,
    /// The robot in it.
    pub robot: &'a mut Robot,
    /// The object of each activity instance.
    pub bindings: &'a [Option<ObjectId>],
    /// The seed the episode was reset with, for edits that draw random numbers.
    pub seed: u64,
    /// Steps taken in the episode.
    pub steps: u32,
}

/// An edit of the world between steps, as a serializable value (see the module docs).
pub trait WorldEdit: Serialize + DeserializeOwned {
    /// Why it could not be done.
    type Error: std::error::Error + Send + Sync + 'static;

    /// Does it. An edit that fails leaves the world and the robot as they were, and is not
    /// recorded.
    fn apply(&self, edit: Edit<'_>) -> Result<(), Self::Error>;
}

/// The edits of an episode that has none: a recording that holds one is refused by
/// [`crate::record::replay`] (it cannot be read as this type), so that it is replayed with the
/// code that made the edits.
#[derive(Clone, Copy, Debug, serde::Serialize, serde::Deserialize)]
pub enum NoEdits {}

/// [`NoEdits`] is never applied: no value of it exists.
#[derive(Debug, thiserror::Error)]
#[error("no edit")]
pub struct NoEdit;

impl WorldEdit for NoEdits {
    type Error = NoEdit;

    fn apply(&self, _edit: Edit<'_>) -> Result<(), NoEdit> {
        match *self {}
    }
}
