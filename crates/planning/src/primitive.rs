//! The action primitives (iGibson 2.0.3's `envs/behavior_mp_env.py` and OmniGibson's symbolic set)
//! and why one fails.

use behavior_sim::{ObjectId, PlacementError, Relation, StateError};
use serde::{Deserialize, Serialize};

/// An action primitive: what the agent asks for, on one object, with one hand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Primitive {
    /// Stand where the object is in reach and in view.
    NavigateTo,
    /// Take the object in the hand.
    Grasp,
    /// Put what the hand holds on the object.
    PlaceOnTop,
    /// Put what the hand holds in the object (open, or not openable).
    PlaceInside,
    /// Open the object fully.
    Open,
    /// Close the object.
    Close,
    /// Switch the object on.
    ToggleOn,
    /// Switch the object off.
    ToggleOff,
    /// Slice the object with the slicer the hand holds.
    Slice,
    /// Clean the object's dust, or stains with a soaked tool, with the tool the hand holds.
    Wipe,
    /// Soak what the hand holds in the water of the object (a running water source).
    Soak,
    /// Put what the hand holds next to the object.
    PlaceNextTo,
    /// Put what the hand holds under the object.
    PlaceUnder,
    /// Put what the hand holds on the object, a room's floor.
    PlaceOnFloor,
    /// Let time pass ([`WAIT_STEPS`] steps): heating, freezing, soaking go on.
    Wait,
}

/// Steps one [`Primitive::Wait`] lasts (one second).
pub const WAIT_STEPS: u32 = 30;

impl Primitive {
    /// The paper's six (commit 3f9313bc), in its order: the first of [`Primitive::ALL`].
    pub const PAPER: &'static [Primitive] = Primitive::ALL.as_slice().split_at(6).0;

    /// Every primitive: the paper's six, then what the activities need beyond them.
    pub const ALL: [Primitive; 15] = [
        Primitive::NavigateTo,
        Primitive::Grasp,
        Primitive::PlaceOnTop,
        Primitive::PlaceInside,
        Primitive::Open,
        Primitive::Close,
        Primitive::ToggleOn,
        Primitive::ToggleOff,
        Primitive::Slice,
        Primitive::Wipe,
        Primitive::Soak,
        Primitive::PlaceNextTo,
        Primitive::PlaceUnder,
        Primitive::PlaceOnFloor,
        Primitive::Wait,
    ];

    /// Its name, as in recordings and the command line.
    pub fn name(self) -> &'static str {
        match self {
            Primitive::NavigateTo => "navigate_to",
            Primitive::Grasp => "grasp",
            Primitive::PlaceOnTop => "place_ontop",
            Primitive::PlaceInside => "place_inside",
            Primitive::Open => "open",
            Primitive::Close => "close",
            Primitive::ToggleOn => "toggle_on",
            Primitive::ToggleOff => "toggle_off",
            Primitive::Slice => "slice",
            Primitive::Wipe => "wipe",
            Primitive::Soak => "soak",
            Primitive::PlaceNextTo => "place_nextto",
            Primitive::PlaceUnder => "place_under",
            Primitive::PlaceOnFloor => "place_onfloor",
            Primitive::Wait => "wait",
        }
    }

    /// The primitive of a name.
    pub fn from_name(name: &str) -> Option<Primitive> {
        Primitive::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The relation a placing primitive makes.
    pub fn relation(self) -> Option<Relation> {
        match self {
            Primitive::PlaceOnTop => Some(Relation::OnTop),
            Primitive::PlaceInside => Some(Relation::Inside),
            Primitive::PlaceNextTo => Some(Relation::NextTo),
            Primitive::PlaceUnder => Some(Relation::Under),
            Primitive::PlaceOnFloor => Some(Relation::OnFloor),
            _ => None,
        }
    }

    /// Whether it only switches a state of the object (`open`, `close`, `toggle_on`,
    /// `toggle_off`).
    pub fn is_switch(self) -> bool {
        matches!(
            self,
            Primitive::Open | Primitive::Close | Primitive::ToggleOn | Primitive::ToggleOff
        )
    }

    /// Whether it uses a hand (holding, or acting with what it holds).
    pub fn uses_hand(self) -> bool {
        self == Primitive::Grasp
            || self.relation().is_some()
            || matches!(self, Primitive::Slice | Primitive::Wipe | Primitive::Soak)
    }
}

/// One primitive asked for: on which object, with which hand (0 left, 1 right for the
/// BehaviorRobot, whose paper version always uses the right; 0 for Fetch).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Call {
    /// What to do.
    pub primitive: Primitive,
    /// To what.
    pub object: ObjectId,
    /// With which hand.
    pub hand: usize,
}

/// Why a primitive failed. Nothing changed, but where it says otherwise.
#[derive(Debug, thiserror::Error)]
pub enum Failure {
    /// The object is farther than the robot reaches (its box 2 m from the base, across the
    /// floor).
    #[error("out of reach")]
    Unreachable,
    /// No place to stand within 2.4 m that is clear and sees the object.
    #[error("no place to stand that is clear and sees it")]
    NoPlaceToStand,
    /// Executing a plan, the robot did not reach a configuration of it (something stopped it).
    #[error("blocked at {at:?} on the way to {toward:?}")]
    Blocked {
        /// Where the base stopped.
        at: behavior_motion::BaseConfig,
        /// Where it was going.
        toward: behavior_motion::BaseConfig,
    },
    /// Executing a hand or arm plan, it did not reach a configuration of it (a fixed body
    /// stopped it, or the reach did).
    #[error("the hand was stopped on its planned path")]
    HandBlocked,
    /// No pose of the hand over the object (or above the placement) is free and within reach.
    #[error("no free hand pose within reach for it")]
    NoHandPose,
    /// The hand closed on the object but the assisted grasp did not take it.
    #[error("the hand closed but did not hold it")]
    Missed,
    /// The motion planner found no collision-free path.
    #[error("no collision-free path: {0}")]
    NoPath(#[from] behavior_motion::PlanError),
    /// The robot has no such hand.
    #[error("the robot has no hand {0}")]
    NoHand(usize),
    /// The hand already holds something.
    #[error("the hand is full (it holds {0})")]
    HandFull(String),
    /// The hand holds nothing to place, soak, slice or wipe with.
    #[error("the hand is empty")]
    HandEmpty,
    /// Placing what the hand holds on, in, next to or under itself.
    #[error("the held object is the target")]
    SameObject,
    /// The object cannot be held: fixed, a robot's, too heavy (over the grasp rules' mass).
    #[error("not graspable: {0}")]
    NotGraspable(&'static str),
    /// Its container is closed.
    #[error("its container {0} is closed")]
    ContainerClosed(String),
    /// The object lacks what the primitive needs of it.
    #[error("the object {what}")]
    Unable {
        /// What it is not (`is not openable`, `is not a water source`…).
        what: &'static str,
    },
    /// What the hand holds lacks what the primitive needs of it.
    #[error("the held object {what}")]
    WrongTool {
        /// What it is not (`is not a slicer`…).
        what: &'static str,
    },
    /// A water source that is off.
    #[error("the water source is off")]
    WaterOff,
    /// The object is already in the state asked for.
    #[error("already {0}")]
    Already(&'static str),
    /// The world's sampler found no pose for the placement.
    #[error("no pose found: {0}")]
    Placement(#[from] PlacementError),
    /// The world refused a state change.
    #[error("{0}")]
    State(#[from] StateError),
    /// The robot refused a move.
    #[error("{0}")]
    Robot(#[from] behavior_robots::MagicError),
    /// The primitive did all its motions but the world's rule it relies on did not act: no
    /// drop reached the tool held under the tap, the dirt stayed where the tool went.
    #[error("no effect: {0}")]
    NoEffect(&'static str),
    /// This primitive is not available in this mode or for this robot yet.
    #[error("not available: {0}")]
    Unavailable(&'static str),
}
