//! Checking an activity's initial condition in a world: every `:init` literal, positive and
//! negative, `inroom` included, evaluated through the same BDDL oracle the goal is.
//!
//! The sampler runs it on every attempt after settling, loading runs it on a rebuilt world, and
//! callers run it to report what holds (`behavior sample` prints it).

use crate::error::{NamedLiteral, Unmet};
use behavior_bddl::PredicateOracle;
use behavior_bddl::activity::{Activity, InitLiteral};
use behavior_sim::{BoundWorld, ObjectId, World};

/// The kind of an `:init` literal, for summaries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum LiteralKind {
    /// A binary predicate between two instances: `ontop`, `inside`, `nextto`, …
    Relation,
    /// A unary state: `cooked`, `open`, `dusty`, …
    UnaryState,
    /// `inroom`: which room type an instance stands in.
    InRoom,
}

/// One `:init` literal and whether it holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LiteralCheck {
    /// The literal, as the definition writes it.
    pub literal: NamedLiteral,
    /// `None` when it holds; else what the world shows instead.
    pub unmet: Option<Unmet>,
}

impl LiteralCheck {
    /// Whether the literal holds.
    pub fn holds(&self) -> bool {
        self.unmet.is_none()
    }

    /// Whether it is a relation, a unary state or an `inroom`.
    pub fn kind(&self) -> LiteralKind {
        match &self.literal.literal {
            InitLiteral::Atom(l) if l.atom.object.is_some() => LiteralKind::Relation,
            InitLiteral::Atom(_) => LiteralKind::UnaryState,
            InitLiteral::InRoom { .. } => LiteralKind::InRoom,
        }
    }
}

/// Every `:init` literal of an activity, in the definition's order, each with whether it holds
/// in a world.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct InitCheck {
    /// One entry per `:init` literal.
    pub literals: Vec<LiteralCheck>,
}

impl InitCheck {
    /// How many literals hold.
    pub fn holding(&self) -> usize {
        self.literals.iter().filter(|l| l.holds()).count()
    }

    /// The literals that do not hold, in the definition's order.
    pub fn failing(&self) -> impl Iterator<Item = &LiteralCheck> {
        self.literals.iter().filter(|l| !l.holds())
    }

    /// Whether every literal holds.
    pub fn all_hold(&self) -> bool {
        self.failing().next().is_none()
    }

    /// How many literals are of `kind`.
    pub fn count(&self, kind: LiteralKind) -> usize {
        self.literals.iter().filter(|l| l.kind() == kind).count()
    }
}

/// Evaluates every `:init` literal of `activity` in `world`, where instance `i` is the object
/// `bindings[i]` (in `:objects` order).
pub fn check_init(activity: &Activity, world: &World, bindings: &[ObjectId]) -> InitCheck {
    let bound: Vec<Option<ObjectId>> = bindings.iter().copied().map(Some).collect();
    let oracle = BoundWorld {
        world,
        bindings: &bound,
    };
    let literals = activity
        .init
        .iter()
        .map(|literal| LiteralCheck {
            literal: NamedLiteral::new(activity, literal),
            unmet: unmet(&oracle, bindings, literal),
        })
        .collect();
    InitCheck { literals }
}

/// Why `literal` fails in the oracle's world, or `None` when it holds.
fn unmet(oracle: &BoundWorld<'_>, bindings: &[ObjectId], literal: &InitLiteral) -> Option<Unmet> {
    match literal {
        InitLiteral::Atom(l) => (oracle.holds(l.atom) != l.positive).then_some(Unmet::False),
        InitLiteral::InRoom {
            instance,
            room,
            positive,
        } => {
            let here = oracle
                .world
                .relations()
                .room_of(bindings[instance.0 as usize]);
            ((here == Some(*room)) != *positive).then_some(Unmet::Room { room: here })
        }
    }
}
