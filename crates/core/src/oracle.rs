//! The bridge between an activity's ground goal and a world: atoms over instances, and the trait a
//! world implements to say which are true.

use crate::Predicate;

/// Index of an object instance (`apple.n.01_1`) in its activity, in `:objects` order.
///
/// The language grounds goals over these; a world binds each to one of its objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct InstanceId(pub u32);

/// A ground atomic formula over an activity's instances: `(ontop apple.n.01_1 table.n.02_1)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Atom {
    /// What is asserted.
    pub predicate: Predicate,
    /// The first argument.
    pub subject: InstanceId,
    /// The second argument of a binary predicate.
    pub object: Option<InstanceId>,
}

impl Atom {
    /// `(predicate subject)`, e.g. `(cooked apple.n.01_1)`.
    pub fn unary(predicate: Predicate, subject: InstanceId) -> Atom {
        Atom {
            predicate,
            subject,
            object: None,
        }
    }

    /// `(predicate subject object)`, e.g. `(ontop apple.n.01_1 table.n.02_1)`.
    pub fn binary(predicate: Predicate, subject: InstanceId, object: InstanceId) -> Atom {
        Atom {
            predicate,
            subject,
            object: Some(object),
        }
    }
}

/// Answers the truth of ground atoms in the current state.
///
/// The language evaluates goals, Q and options through this trait only, so the same evaluation
/// runs over a set of facts in a test and over a physical world in an episode.
pub trait PredicateOracle {
    /// Whether `atom` is true now.
    fn holds(&self, atom: Atom) -> bool;
}

impl<F: Fn(Atom) -> bool> PredicateOracle for F {
    fn holds(&self, atom: Atom) -> bool {
        self(atom)
    }
}
