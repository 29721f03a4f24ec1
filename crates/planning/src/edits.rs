//! The planner's edits of the world between steps as values ([`RecordedCall`]): a symbolic
//! primitive's outcome, a switch thrown, a grasp forced where the hand closed, a hand put back
//! at its target, the home's doors opened. Each goes through [`Env::apply`], which does it and
//! records it when the episode records; a replay reads it back as the same type
//! ([`behavior_env::record::replay_with`]`::<RecordedCall>`) and does it again.

use crate::manipulation::FORCED_GRASP;
use crate::physical::{DOORS_OPENED, open_doors_in};
use crate::posed_hands::HAND_RESET;
use crate::primitive::{Call, Failure, Primitive};
use crate::symbolic;
use behavior_env::{Edit, Env, WorldEdit};
use behavior_robots::MagicError;
use behavior_sim::ObjectId;
use serde::{Deserialize, Serialize};

/// An edit as a recording says it: the primitive's name (or that of the planner's own edits:
/// [`FORCED_GRASP`], [`HAND_RESET`], [`DOORS_OPENED`]), the object's name and the hand.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct RecordedCall {
    /// [`Primitive::name`], or one of the planner's own edits.
    pub primitive: String,
    /// The world object's name (empty for an edit of no object).
    pub object: String,
    /// The hand.
    pub hand: usize,
    /// The object itself, where the edit is made live (a replay finds it by its name): not
    /// recorded.
    #[serde(skip)]
    id: Option<ObjectId>,
}

/// Why an edit could not be done.
#[derive(Debug, thiserror::Error)]
pub enum EditError {
    /// Its primitive is none this build knows.
    #[error("unknown primitive `{0}`")]
    UnknownPrimitive(String),
    /// Its object is not in the world.
    #[error("no object `{0}` in the world")]
    NoObject(String),
    /// The primitive failed: the world is as it was.
    #[error("{primitive} on {object}: {failure}")]
    Failed {
        /// The primitive.
        primitive: String,
        /// The object's name.
        object: String,
        /// Why.
        failure: Failure,
    },
    /// The robot refused (a forced grasp of something the hand does not touch, a hand reset).
    #[error("{0}")]
    Robot(#[from] MagicError),
    /// There was no closed door to open.
    #[error("no door was closed")]
    NoDoorClosed,
}

impl RecordedCall {
    /// The call as a recording says it.
    pub fn of(env: &Env, call: &Call) -> RecordedCall {
        let object = env
            .world()
            .map(|w| w.bodies().object(call.object).name.clone());
        RecordedCall {
            primitive: call.primitive.name().to_string(),
            object: object.unwrap_or_default(),
            hand: call.hand,
            id: Some(call.object),
        }
    }

    /// [`RecordedCall::of`] for one of the planner's own edits of an object, named `name`.
    pub(crate) fn own_of(env: &Env, name: &str, call: &Call) -> RecordedCall {
        RecordedCall {
            primitive: name.to_string(),
            ..RecordedCall::of(env, call)
        }
    }

    /// One of the planner's own edits, of no object.
    pub(crate) fn own(name: &str, hand: usize) -> RecordedCall {
        RecordedCall {
            primitive: name.to_string(),
            object: String::new(),
            hand,
            id: None,
        }
    }
}

impl WorldEdit for RecordedCall {
    type Error = EditError;

    fn apply(&self, edit: Edit<'_>) -> Result<(), EditError> {
        match self.primitive.as_str() {
            HAND_RESET => return Ok(edit.robot.reset_hand(edit.world, self.hand)?),
            DOORS_OPENED => {
                return match open_doors_in(edit.world, edit.bindings) {
                    true => Ok(()),
                    false => Err(EditError::NoDoorClosed),
                };
            }
            _ => {}
        }
        let object = (self
            .id
            .or_else(|| edit.world.bodies().object_named(&self.object)))
        .ok_or_else(|| EditError::NoObject(self.object.clone()))?;
        if self.primitive == FORCED_GRASP {
            return Ok(edit.robot.grasp_touching(edit.world, self.hand, object)?);
        }
        let primitive = Primitive::from_name(&self.primitive)
            .ok_or_else(|| EditError::UnknownPrimitive(self.primitive.clone()))?;
        let call = Call {
            primitive,
            object,
            hand: self.hand,
        };
        symbolic::apply(edit, &call).map_err(|failure| EditError::Failed {
            primitive: self.primitive.clone(),
            object: self.object.clone(),
            failure,
        })
    }
}
