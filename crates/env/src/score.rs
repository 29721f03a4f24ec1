//! The activity's goal scored in a world: the success score Q, success, which top-level
//! conjuncts hold, and the original's first-option potential.

use behavior_bddl::options::options;
use behavior_bddl::{Activity, GroundGoal, Literal, Optimizer, PredicateOracle};
use serde::{Deserialize, Serialize};

/// How the goal stands at one step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Score {
    /// The success score: the best fraction of satisfied literals over the goal's options, exact
    /// (the paper's Q, options counted as sets).
    pub q: f64,
    /// Whether the whole goal holds.
    pub success: bool,
    /// Whether each top-level conjunct of `:goal` holds, in file order (the original's goal
    /// status).
    pub conjuncts: Vec<bool>,
}

/// The grounded goal of an activity, ready to be scored every step.
#[derive(Clone, Debug)]
pub(crate) struct Scorer {
    goal: GroundGoal,
    /// The goal's first option (the original's potential reward reads only this one).
    first_option: Vec<Literal>,
}

impl Scorer {
    pub(crate) fn new(activity: &Activity) -> Scorer {
        let goal = GroundGoal::new(activity);
        let first_option = options(&goal).next().unwrap_or_default();
        Scorer { goal, first_option }
    }

    /// Scores the goal in the state `oracle` answers for; `last` holds the atoms' truth when
    /// `previous` was scored, and is updated. When no atom changed, the score is `previous`.
    pub(crate) fn rescore(
        &self,
        oracle: &impl PredicateOracle,
        last: &mut Vec<bool>,
        previous: &Score,
    ) -> Score {
        let truth = self.goal.atom_truth(oracle);
        if truth == *last {
            return previous.clone();
        }
        let score = self.score_truth(&truth);
        *last = truth;
        score
    }

    /// Every atom's truth in the state `oracle` answers for.
    pub(crate) fn atoms(&self, oracle: &impl PredicateOracle) -> Vec<bool> {
        self.goal.atom_truth(oracle)
    }

    /// Scores the goal in the state `oracle` answers for.
    pub(crate) fn score(&self, oracle: &impl PredicateOracle) -> Score {
        self.score_truth(&self.goal.atom_truth(oracle))
    }

    /// The score given every atom's truth.
    fn score_truth(&self, truth: &[bool]) -> Score {
        let holds = |a: behavior_bddl::ground::AtomId| truth[a.0 as usize];
        let conjuncts = self
            .goal
            .conjuncts
            .iter()
            .map(|&c| self.goal.node_holds(c, &holds))
            .collect();
        // A goal with no consistent option can never hold: its Q is 0.
        let q = Optimizer::new(&self.goal)
            .q_with_truth(truth)
            .map_or(0.0, |r| r.to_f64());
        Score {
            q,
            success: self.goal.node_holds(self.goal.root, &holds),
            conjuncts,
        }
    }

    /// How many literals the first option has.
    pub(crate) fn first_option_len(&self) -> usize {
        self.first_option.len()
    }

    /// The fraction of the first option's literals that hold (1 for an empty option).
    pub(crate) fn first_option(&self, oracle: &impl PredicateOracle) -> f64 {
        if self.first_option.is_empty() {
            return 1.0;
        }
        let holding = self
            .first_option
            .iter()
            .filter(|l| oracle.holds(l.atom) == l.positive)
            .count();
        holding as f64 / self.first_option.len() as f64
    }
}
