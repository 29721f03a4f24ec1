//! The bridge to a world: a [`PredicateOracle`] answers whether a ground atom holds now.
//!
//! A simulator implements the oracle over its objects (after binding instances to them); this
//! module also provides [`FactSet`], a closed-world set of true atoms, used by tests, the CLI's
//! `eval` and the benchmarks.

use crate::activity::{Activity, Atom};
use crate::predicate::Predicate;
use serde::Deserialize;

pub use behavior_core::PredicateOracle;

/// A state as the set of atoms that are true; every other atom is false.
///
/// Kept as a sorted vector: states are small (tens of facts) and read far more often than
/// written, and a binary search over contiguous atoms beats a tree or a hash here.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FactSet {
    facts: Vec<Atom>,
}

impl PredicateOracle for FactSet {
    fn holds(&self, atom: Atom) -> bool {
        self.facts.binary_search(&atom).is_ok()
    }
}

impl FromIterator<Atom> for FactSet {
    fn from_iter<I: IntoIterator<Item = Atom>>(iter: I) -> Self {
        let mut facts: Vec<Atom> = iter.into_iter().collect();
        facts.sort_unstable();
        facts.dedup();
        FactSet { facts }
    }
}

/// Why a state file could not be read into a [`FactSet`] (see [`FactSet::from_json`]).
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum StateError {
    /// The text is not JSON of the form `{"facts": [[predicate, instance…], …]}`; the string is
    /// serde's message, with its line and column.
    #[error(
        "the state is not JSON of the form {{\"facts\": [[\"ontop\", \"a.n.01_1\", \"b.n.01_1\"], ...]}}: {0}"
    )]
    Json(String),
    /// One fact cannot be resolved against the activity.
    #[error("fact {index} ({fact}): {reason}")]
    Fact {
        /// Its position in `facts`, counted from 0.
        index: usize,
        /// The fact as given, debug-formatted (`["ontop", "a.n.01_1"]`).
        fact: String,
        /// What is wrong: empty, an unknown predicate, `inroom`, the wrong number of arguments or
        /// an object the activity does not declare.
        reason: String,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StateFile {
    facts: Vec<Vec<String>>,
}

impl FactSet {
    /// Makes `atom` true; false if it already was.
    pub fn insert(&mut self, atom: Atom) -> bool {
        match self.facts.binary_search(&atom) {
            Ok(_) => false,
            Err(at) => {
                self.facts.insert(at, atom);
                true
            }
        }
    }

    /// Makes `atom` false; false if it already was.
    pub fn remove(&mut self, atom: Atom) -> bool {
        match self.facts.binary_search(&atom) {
            Ok(at) => {
                self.facts.remove(at);
                true
            }
            Err(_) => false,
        }
    }

    /// The number of true atoms.
    pub fn len(&self) -> usize {
        self.facts.len()
    }

    /// Whether no atom is true.
    pub fn is_empty(&self) -> bool {
        self.facts.is_empty()
    }

    /// The true atoms, in sorted order.
    pub fn iter(&self) -> impl Iterator<Item = Atom> + '_ {
        self.facts.iter().copied()
    }

    /// Reads `{"facts": [["ontop", "apple.n.01_1", "table.n.02_1"], ["cooked", "apple.n.01_1"]]}`,
    /// resolving names against the activity. Each bad fact is named by its position. `inroom`
    /// facts (`["inroom", "table.n.02_1", "kitchen"]`, as `behavior facts` prints them) are checked
    /// and accepted, but kept out of the set: the home fixes them and goals never ask.
    pub fn from_json(activity: &Activity, text: &str) -> Result<FactSet, StateError> {
        let file: StateFile =
            serde_json::from_str(text).map_err(|e| StateError::Json(e.to_string()))?;
        let mut facts = Vec::with_capacity(file.facts.len());
        for (index, fact) in file.facts.iter().enumerate() {
            let fail = |reason: String| StateError::Fact {
                index,
                fact: format!("{fact:?}"),
                reason,
            };
            let Some((name, args)) = fact.split_first() else {
                return Err(fail("empty fact".into()));
            };
            let predicate = Predicate::from_name(&name.to_lowercase())
                .ok_or_else(|| fail(format!("unknown predicate `{name}`")))?;
            if predicate == Predicate::InRoom {
                // Fixed by the home and never part of a goal: checked, then left out of the set.
                check_inroom(activity, args).map_err(fail)?;
                continue;
            }
            if args.len() != predicate.arity() {
                return Err(fail(format!(
                    "`{predicate}` takes {} argument(s), {} given",
                    predicate.arity(),
                    args.len()
                )));
            }
            let ids = args
                .iter()
                .map(|a| {
                    activity
                        .instance_named(&a.to_lowercase())
                        .ok_or_else(|| fail(format!("`{a}` is not an object of {}", activity.name)))
                })
                .collect::<Result<Vec<_>, _>>()?;
            facts.push(Atom {
                predicate,
                subject: ids[0],
                object: ids.get(1).copied(),
            });
        }
        Ok(facts.into_iter().collect())
    }
}

/// Checks an `inroom` fact's arguments: an object of the activity and a room type.
fn check_inroom(activity: &Activity, args: &[String]) -> Result<(), String> {
    let [object, room] = args else {
        return Err(format!("`inroom` takes 2 arguments, {} given", args.len()));
    };
    if activity.instance_named(&object.to_lowercase()).is_none() {
        return Err(format!("`{object}` is not an object of {}", activity.name));
    }
    room.to_lowercase()
        .parse::<behavior_core::RoomType>()
        .map(|_| ())
        .map_err(|e| e.to_string())
}
