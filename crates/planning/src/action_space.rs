//! The primitive action space of the original (iGibson 2.0.3's `envs/behavior_mp_env.py`):
//! `Discrete(n × K)` over the activity's objects and a set of primitives, action `a` meaning object
//! `a mod n` and primitive `a div n`, with a mask of the actions whose preconditions hold now (for
//! sb3-contrib's MaskablePPO).
//!
//! PLACE_ONTOP on a room's floor places on the floor (the `onfloor` relation), as the
//! original's does on a RoomFloor: the paper's six have no other way to put a thing down on a
//! floor, which `bringing_in_wood` and others ask for.

use crate::primitive::{Call, Primitive};
use crate::symbolic::check;
use behavior_core::{AGENT_SYNSET, FLOOR_SYNSET};
use behavior_env::Env;
use behavior_sim::ObjectId;

/// Which primitives the space offers, and with which hands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrimitiveSet {
    /// The paper's six (K = 6), always with the right hand (Fetch: its gripper).
    Paper,
    /// The 2.0.x releases' nine: NAVIGATE_TO, LEFT_GRASP, RIGHT_GRASP, LEFT_PLACE_ONTOP,
    /// RIGHT_PLACE_ONTOP, LEFT_PLACE_INSIDE, RIGHT_PLACE_INSIDE, OPEN, CLOSE (Fetch: the
    /// paper's six, having one hand).
    TwoHands,
    /// Every [`Primitive`], those that use a hand once per hand.
    All,
}

impl PrimitiveSet {
    /// Its name (`paper`, `two_hands`, `all`).
    pub fn name(self) -> &'static str {
        match self {
            PrimitiveSet::Paper => "paper",
            PrimitiveSet::TwoHands => "two_hands",
            PrimitiveSet::All => "all",
        }
    }

    /// The set of a name.
    pub fn from_name(name: &str) -> Option<PrimitiveSet> {
        [
            PrimitiveSet::Paper,
            PrimitiveSet::TwoHands,
            PrimitiveSet::All,
        ]
        .into_iter()
        .find(|s| s.name() == name)
    }

    /// The (primitive, hand) pairs in order, for a robot with `hands` hands.
    fn choices(self, hands: usize) -> Vec<(Primitive, usize)> {
        let right = hands.saturating_sub(1);
        let every_hand = |p: Primitive| -> Vec<(Primitive, usize)> {
            if p.uses_hand() {
                (0..hands).map(|h| (p, h)).collect()
            } else {
                vec![(p, right)]
            }
        };
        match self {
            PrimitiveSet::Paper => Primitive::PAPER.iter().map(|&p| (p, right)).collect(),
            PrimitiveSet::TwoHands => Primitive::PAPER
                .iter()
                .flat_map(|&p| every_hand(p))
                .collect(),
            PrimitiveSet::All => Primitive::ALL.iter().flat_map(|&p| every_hand(p)).collect(),
        }
    }
}

/// An episode's primitive action space.
#[derive(Clone, Debug, PartialEq)]
pub struct PrimitiveSpace {
    /// The activity's objects (its floors included, the agent left out), in `:objects` order.
    objects: Vec<ObjectId>,
    /// Whether each object is a room's floor.
    floors: Vec<bool>,
    /// The primitives with their hands, in order.
    choices: Vec<(Primitive, usize)>,
}

impl PrimitiveSpace {
    /// The space of the episode `env` runs (after a reset: the objects are its bindings);
    /// `None` before the first reset.
    pub fn of(env: &Env, set: PrimitiveSet) -> Option<PrimitiveSpace> {
        let (bindings, robot) = (env.bindings()?, env.robot()?);
        let activity = &env.config().activity;
        let (objects, floors) = activity
            .instances
            .iter()
            .zip(bindings)
            .filter_map(|(i, b)| {
                let category = &activity.category(i.category).name;
                let object = (*b)?;
                (category != AGENT_SYNSET).then_some((object, category == FLOOR_SYNSET))
            })
            .unzip();
        Some(PrimitiveSpace {
            objects,
            floors,
            choices: set.choices(robot.hands()),
        })
    }

    /// How many objects (n).
    pub fn objects(&self) -> &[ObjectId] {
        &self.objects
    }

    /// The (primitive, hand) pairs (K of them), in the order `a div n` counts.
    pub fn choices(&self) -> &[(Primitive, usize)] {
        &self.choices
    }

    /// How many actions (n × K).
    pub fn len(&self) -> usize {
        self.objects.len() * self.choices.len()
    }

    /// Whether there is no action at all (an activity without objects).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The call action `a` stands for: object `a mod n`, primitive `a div n` (PLACE_ONTOP on a
    /// floor is PLACE_ONFLOOR); `None` out of range.
    pub fn decode(&self, a: usize) -> Option<Call> {
        let n = self.objects.len();
        let i = a.checked_rem(n)?;
        let (&object, &(primitive, hand)) = (self.objects.get(i)?, self.choices.get(a / n)?);
        let primitive = match primitive {
            Primitive::PlaceOnTop if self.floors[i] => Primitive::PlaceOnFloor,
            p => p,
        };
        Some(Call {
            primitive,
            object,
            hand,
        })
    }

    /// For every action, whether its preconditions hold in the episode now ([`check`]): what
    /// only doing it can tell (a place to stand, a pose for a placement) is not known yet.
    /// All false before a reset.
    pub fn mask(&self, env: &Env) -> Vec<bool> {
        let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
            return vec![false; self.len()];
        };
        (0..self.len())
            .map(|a| {
                self.decode(a)
                    .is_some_and(|call| check(world, robot, &call).is_ok())
            })
            .collect()
    }
}
