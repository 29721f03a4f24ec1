//! What can go wrong when sampling or loading an instance, as values that say where and why.
//!
//! The literal at fault is kept as the BDDL type ([`InitLiteral`]) together with the names of
//! the instances it mentions, so that a caller can match on it and a reader sees it as the
//! definition writes it. The world's own errors ([`PlacementError`], [`StateError`],
//! [`WorldError`]) are kept as they came.
//!
//! The errors of this module print their cause as part of their message and do not also return
//! it from [`std::error::Error::source`]: `to_string()` is then a complete sentence, and a report
//! that walks the chain of sources (as `anyhow`'s `{:#}` does) does not print the cause twice.

use behavior_assets::{AssetError, SceneError};
use behavior_bddl::activity::{Activity, InitLiteral, Literal};
use behavior_bddl::{Predicate, RoomType};
use behavior_sim::{PlacementError, StateError, WorldError};
use std::fmt;

/// A literal of an activity with the names of the instances it mentions, so that it can be shown
/// as the definition writes it — `(ontop apple.n.01_1 table.n.02_1)` — without the activity.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NamedLiteral {
    /// The literal as the activity holds it; `inroom` included.
    pub literal: InitLiteral,
    /// The name of its first argument.
    pub subject: String,
    /// The name of its second argument when that is an instance (not for unary predicates, nor
    /// for `inroom`, whose room is part of [`NamedLiteral::literal`]).
    pub object: Option<String>,
}

impl NamedLiteral {
    /// An `:init` literal of `activity`, with its names.
    pub fn new(activity: &Activity, literal: &InitLiteral) -> NamedLiteral {
        match literal {
            InitLiteral::Atom(l) => NamedLiteral::atom(activity, *l),
            InitLiteral::InRoom { instance, .. } => NamedLiteral {
                literal: literal.clone(),
                subject: activity.instance(*instance).name.clone(),
                object: None,
            },
        }
    }

    /// A literal over instances (of `:init` or of a goal option) of `activity`, with its names.
    pub fn atom(activity: &Activity, literal: Literal) -> NamedLiteral {
        NamedLiteral {
            literal: InitLiteral::Atom(literal),
            subject: activity.instance(literal.atom.subject).name.clone(),
            object: literal
                .atom
                .object
                .map(|o| activity.instance(o).name.clone()),
        }
    }

    /// Whether the literal is stated positively (not under `not`).
    pub fn positive(&self) -> bool {
        match &self.literal {
            InitLiteral::Atom(l) => l.positive,
            InitLiteral::InRoom { positive, .. } => *positive,
        }
    }
}

impl fmt::Display for NamedLiteral {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.positive() {
            f.write_str("(not ")?;
        }
        match &self.literal {
            InitLiteral::Atom(l) => write!(f, "({} {}", l.atom.predicate, self.subject)?,
            InitLiteral::InRoom { .. } => write!(f, "(inroom {}", self.subject)?,
        }
        match (&self.literal, &self.object) {
            (InitLiteral::InRoom { room, .. }, _) => write!(f, " {room})")?,
            (_, Some(object)) => write!(f, " {object})")?,
            (_, None) => f.write_str(")")?,
        }
        if !self.positive() {
            f.write_str(")")?;
        }
        Ok(())
    }
}

/// Literals that fail together — an object placed by all of its literals at once fails by all
/// of them — shown joined by `and`: `(under a b) and (onfloor a c)`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Literals(pub Vec<NamedLiteral>);

impl Literals {
    /// Literals over instances of `activity`, with their names.
    pub fn of<'a>(
        activity: &Activity,
        literals: impl IntoIterator<Item = &'a Literal>,
    ) -> Literals {
        Literals(
            literals
                .into_iter()
                .map(|l| NamedLiteral::atom(activity, *l))
                .collect(),
        )
    }
}

impl fmt::Display for Literals {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, literal) in self.0.iter().enumerate() {
            if k > 0 {
                f.write_str(" and ")?;
            }
            write!(f, "{literal}")?;
        }
        Ok(())
    }
}

/// Why a literal that was made true is found false when checked ([`crate::InitCheck`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Unmet {
    /// A relation or unary state that the world does not show (after settling, when sampling).
    #[error("it does not hold in the settled world")]
    False,
    /// An object that stands in another room (or in none) than its `inroom` literal says.
    #[error("it stands in {}", .room.map_or("no room", |r| r.name()))]
    Room {
        /// The room type it stands in, if any.
        room: Option<RoomType>,
    },
}

/// Furniture candidates ruled out by placement probes in a scratch copy of the home.
#[derive(Debug, thiserror::Error)]
#[error("{kept} of the {candidates} {synset} in {scene}'s {room}s can take it: {cause}")]
pub struct RuledOut {
    /// How many candidates could host every probe.
    pub kept: usize,
    /// How many candidates the room type offered.
    pub candidates: usize,
    /// The synset the instance is declared as.
    pub synset: String,
    /// The home's name.
    pub scene: String,
    /// The room type of its `inroom` literal.
    pub room: RoomType,
    /// Why the last rejected candidate could not host.
    pub cause: PlacementError,
}

/// Why init literals could not be made true.
#[derive(Debug, thiserror::Error)]
pub enum Unsatisfied {
    /// Probes ruled out too many of the furniture the instance could have been bound to
    /// (boxed: it is much larger than the other reasons).
    #[error("{0}")]
    NotHosted(Box<RuledOut>),
    /// The world found no pose where all of an object's placement literals hold.
    #[error("{0}")]
    Placement(PlacementError),
    /// The world could not set a unary state.
    #[error("{0}")]
    State(StateError),
    /// The literal was made true but the settled world shows otherwise.
    #[error("{0}")]
    Unmet(Unmet),
}

/// Why a goal option could not be reached.
#[derive(Debug, thiserror::Error)]
pub enum Unreachable {
    /// Something the option moves goes on, in or under two things that stay too far apart.
    #[error("it would have to be in two places at once")]
    TwoPlaces,
    /// A box (sorted extents, m) that fits in no orientation in its container's.
    #[error("its box {object:.2?} does not fit in {container:.2?}")]
    DoesNotFit {
        /// The object's extents, smallest first.
        object: [f32; 3],
        /// The container's extents, smallest first.
        container: [f32; 3],
    },
    /// An object whose narrowest side exceeds its support's widest.
    #[error("its narrower side {side:.2} exceeds the support's widest {widest:.2}")]
    TooWide {
        /// The object's smallest extent (m).
        side: f32,
        /// The support's largest extent (m).
        widest: f32,
    },
    /// An object larger than what it should go under.
    #[error("it is larger than what it should go under")]
    TooLarge,
    /// The world found no pose where all of an object's literals of the option hold.
    #[error("{0}")]
    Placement(PlacementError),
    /// An object to be moved could not be lifted out of the copy of the world.
    #[error("{0}")]
    Lift(WorldError),
}

/// Why an activity could not be instantiated in a home.
#[derive(Debug, thiserror::Error)]
pub enum SampleError {
    /// The home has too few rooms of a type, or objects of a kind in them, for the `inroom`
    /// literals (see `behavior_assets::covering` for which homes do).
    #[error("{scene} has no {room} with a {synset} free for {instance}")]
    NoFurniture {
        /// The home's name.
        scene: String,
        /// The activity's instance left unbound.
        instance: String,
        /// Its synset.
        synset: String,
        /// The room type its `inroom` literal asks for.
        room: RoomType,
    },
    /// Init literals could not be made true (on the last attempt).
    #[error("{literals} could not be satisfied: {why}")]
    Literal {
        /// The literals as the definition writes them.
        literals: Literals,
        /// Why.
        why: Unsatisfied,
    },
    /// An object of the activity (or a probe of it) could not be added to the world.
    #[error("{instance} could not be added to the world: {cause}")]
    Add {
        /// The activity's instance.
        instance: String,
        /// The world's reason.
        cause: WorldError,
    },
    /// No placement literal of `:init` relates the object to anything placed, so there is
    /// nowhere to put it.
    #[error(
        "{instance} could not be placed: no `ontop`, `inside`, `under`, `nextto`, `touching` or \
         `onfloor` literal places it relative to placed objects"
    )]
    Unanchored {
        /// The activity's instance.
        instance: String,
    },
    /// No goal option that was tried could be reached; the literals and reason are the first
    /// option's.
    #[error("no goal option can be reached in this home: {literals}: {why}")]
    Infeasible {
        /// The option's literals at fault, as the goal writes them.
        literals: Literals,
        /// Why.
        why: Unreachable,
    },
    /// The goal has no consistent option at all (every option contradicts itself or asks an
    /// object to be on, in or next to itself).
    #[error("no goal option can be reached in this home: the goal has no consistent option")]
    NoGoalOption,
    /// An object's synset has no archetype in the library.
    #[error(transparent)]
    Asset(#[from] AssetError),
    /// The home could not be built.
    #[error(transparent)]
    Scene(#[from] SceneError),
}

impl SampleError {
    /// Whether fresh randomness might succeed: sizes, poses and tie-breaks are drawn afresh on
    /// each attempt, so a failed placement, state, check or goal may come out otherwise.
    pub fn retryable(&self) -> bool {
        matches!(
            self,
            SampleError::Literal { .. }
                | SampleError::Add { .. }
                | SampleError::Infeasible { .. }
                | SampleError::NoGoalOption
        )
    }
}

/// Why a saved instance could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The text is not JSON of a saved instance.
    #[error("the instance file is not valid: {0}")]
    Json(serde_json::Error),
    /// The file is an instance of another activity.
    #[error("the file is an instance of {saved}, not of {activity}")]
    WrongActivity {
        /// The activity the file names.
        saved: String,
        /// The activity it was loaded for.
        activity: String,
    },
    /// The file binds another number of objects than the activity has instances.
    #[error("the file binds {bindings} objects, but {activity} has {instances} instances")]
    BindingCount {
        /// The activity.
        activity: String,
        /// Bindings in the file.
        bindings: usize,
        /// Instances in the activity.
        instances: usize,
    },
    /// A saved object's name is not in the rebuilt world.
    #[error("saved object `{name}` is not in the rebuilt world")]
    UnknownObject {
        /// The name in the file.
        name: String,
    },
    /// An instance is bound to a name that is not in the rebuilt world.
    #[error("{instance} is bound to `{name}`, which is not in the rebuilt world")]
    UnknownBinding {
        /// The activity's instance.
        instance: String,
        /// The name in the file.
        name: String,
    },
    /// A created object could not be rebuilt.
    #[error("created object {instance}: {cause}")]
    Add {
        /// The activity's instance.
        instance: String,
        /// The world's reason.
        cause: WorldError,
    },
    /// A saved pose or joint position could not be set.
    #[error("object `{name}`: {cause}")]
    Pose {
        /// The object's name.
        name: String,
        /// The world's reason.
        cause: WorldError,
    },
    /// A saved unary state could not be set.
    #[error("object `{name}`: {cause}")]
    State {
        /// The object's name.
        name: String,
        /// The world's reason.
        cause: StateError,
    },
    /// A saved object lists a unary predicate that its restored state does not make hold, or
    /// leaves out one that it does: the file contradicts itself.
    #[error(
        "object `{name}`: the file says `{predicate}` is {listed}, but its saved state says otherwise"
    )]
    StateMismatch {
        /// The object's name.
        name: String,
        /// The predicate.
        predicate: Predicate,
        /// Whether the file lists it as true.
        listed: bool,
    },
    /// The rebuilt world breaks an init literal: the file does not describe a valid instance.
    #[error("{literal} does not hold in the loaded instance: {why}")]
    InitBroken {
        /// The first init literal that fails.
        literal: NamedLiteral,
        /// What was found instead.
        why: Unmet,
    },
    /// A created object's archetype is not in the library.
    #[error(transparent)]
    Asset(#[from] AssetError),
    /// The home could not be built.
    #[error(transparent)]
    Scene(#[from] SceneError),
}

// By hand rather than `#[from]`, which would also make the JSON error the source and print it
// twice under `{:#}`.
impl From<serde_json::Error> for LoadError {
    fn from(error: serde_json::Error) -> LoadError {
        LoadError::Json(error)
    }
}
