//! The goal as a checklist of ground literals.
//!
//! A goal with quantifiers or disjunctions can be met in many ways: its options (each a set of
//! ground literals, smallest first, from the BDDL crate). The page lists the literals of the
//! option closest to holding — the largest fraction of its literals true, the smaller option on
//! a tie: the one that gives Q — so ticks appear as the person makes progress, whichever way
//! they go.

use behavior_bddl::options::options;
use behavior_bddl::{Activity, GroundGoal, Literal, PredicateOracle};
use behavior_sim::{BoundWorld, ObjectId, World};
use serde::Serialize;
use std::collections::BTreeMap;

/// Options considered: a goal's first options in size order (some goals have millions).
pub(crate) const MAX_OPTIONS: usize = 256;

/// The goal's literals and its first options, as indices into them.
#[derive(Clone, Debug)]
pub(crate) struct Checklist {
    literals: Vec<Literal>,
    texts: Vec<String>,
    options: Vec<Vec<usize>>,
}

/// Where the checklist stands.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub(crate) struct ChecklistStatus {
    /// The literals (indices into the scene's `literals`) of the option closest to holding.
    pub(crate) option: Vec<usize>,
    /// Whether each of the scene's literals holds.
    pub(crate) holds: Vec<bool>,
}

impl Checklist {
    pub(crate) fn new(activity: &Activity) -> Checklist {
        let goal = GroundGoal::new(activity);
        let mut index: BTreeMap<String, usize> = BTreeMap::new();
        let mut literals = Vec::new();
        let mut texts = Vec::new();
        let options = options(&goal)
            .take(MAX_OPTIONS)
            .map(|option| {
                option
                    .into_iter()
                    .map(|literal| {
                        let text = activity.show_literal(literal);
                        *index.entry(text.clone()).or_insert_with(|| {
                            literals.push(literal);
                            texts.push(text);
                            literals.len() - 1
                        })
                    })
                    .collect()
            })
            .collect();
        Checklist {
            literals,
            texts,
            options,
        }
    }

    /// Every literal's text, e.g. `(ontop apple.n.01_1 table.n.02_1)`.
    pub(crate) fn texts(&self) -> &[String] {
        &self.texts
    }

    /// Which literals hold in `world`, and the option with the largest fraction of them.
    pub(crate) fn status(&self, world: &World, bindings: &[Option<ObjectId>]) -> ChecklistStatus {
        let oracle = BoundWorld { world, bindings };
        let holds: Vec<bool> = self
            .literals
            .iter()
            .map(|l| oracle.holds(l.atom) == l.positive)
            .collect();
        let met = |option: &Vec<usize>| option.iter().filter(|&&i| holds[i]).count();
        // met(a) / |a| against met(b) / |b| without division; among equals, the first
        // (smallest) option.
        let best = self
            .options
            .iter()
            .enumerate()
            .max_by(|(i, a), (j, b)| (met(a) * b.len()).cmp(&(met(b) * a.len())).then(j.cmp(i)))
            .map(|(_, option)| option.clone())
            .unwrap_or_default();
        ChecklistStatus {
            option: best,
            holds,
        }
    }
}
