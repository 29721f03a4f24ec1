//! Exact success score Q and activity volume, without enumerating the goal's options.
//!
//! Both are optimisations over the options (the terms of the goal's disjunctive normal form, see
//! [`crate::ground`]) that contain no literal together with its negation:
//! - volume = the fewest literals in an option;
//! - Q = the largest fraction of an option's literals that hold in a state.
//!
//! How an option's literals are counted is a [`Counting`]: as a set by default (the paper's
//! definition: a literal written twice counts once), or as the reference implementation's list.
//!
//! Any objective that adds up per-leaf weights is maximised over options by one bottom-up pass
//! over the ground tree (module `bottom_up`). Two things make that pass only a bound, and a
//! branch and bound closes the gap:
//! - **consistency**: when the best option uses both `a` and `not a`, search again with `a`
//!   restricted to one polarity, then the other;
//! - **set counting**: a literal whose leaves can meet in one option (module `sharing`; twins
//!   that always meet count once by construction) is charged an admissible share at each leaf —
//!   its full weight when the weight is positive, `1/most` of it when negative, `most` being the
//!   most of its leaves one option can hold — so the pass never underestimates an option. When
//!   the best option's true value falls short of the bound, one of its leaves of a literal so
//!   charged is split on: options that hold that leaf (then the literal is charged exactly once,
//!   there) and options that do not. A forced leaf is enforced inside the same pass by a bonus
//!   per forced leaf above any objective value (2^40 in `i64` arithmetic, or 2^64 in `i128` for
//!   goals too large for that), so the best option holds every forced leaf whenever some does.
//!
//! Q is a ratio, so it is found by Dinkelbach's method: for a candidate `λ = p/q`, maximise
//! `Σ (q·[literal holds] − p)` over the option's literals; a positive maximum yields a better
//! option whose ratio becomes the next `λ`. All arithmetic is on integers, so results are exact.

use crate::bottom_up::{Value, collect, node_values};
use crate::eval::PredicateOracle;
use crate::ground::{AtomId, GroundGoal, Lit, Node, NodeId};
use crate::sharing::{Leaf, Sharing, leaf_counts};
use std::cmp::Ordering;
use std::fmt;

/// How the literals of an option are counted, for Q, volume and the options listed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Counting {
    /// As a set, as the paper defines Q ("|·| is set cardinality"): a literal written twice, or
    /// reached through two quantifier instantiations, counts once, and options with the same
    /// literals are one option.
    #[default]
    Set,
    /// As the list the reference implementation (Python `bddl` 1.0.1) builds: a literal counts
    /// each time it is reached, and options are listed as often as they are built. For
    /// comparing with the reference.
    Reference,
}

/// An exact fraction `num / den` with `den > 0`, in lowest terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ratio {
    /// The numerator, sharing no factor with `den` when made by [`Ratio::new`] (so for Q it is
    /// not necessarily a count of literals).
    pub num: u64,
    /// The denominator, positive.
    pub den: u64,
}

impl Ratio {
    /// `num / den` in lowest terms, so that the derived `==` agrees with the value order.
    /// Panics if `den` is 0.
    pub fn new(num: u64, den: u64) -> Ratio {
        assert!(den > 0, "a ratio needs a positive denominator");
        let g = gcd(num, den);
        Ratio {
            num: num / g,
            den: den / g,
        }
    }

    /// The nearest `f64`, for display and JSON; compare ratios exactly with `Ord` instead.
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

impl PartialOrd for Ratio {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ratio {
    fn cmp(&self, other: &Self) -> Ordering {
        (u128::from(self.num) * u128::from(other.den))
            .cmp(&(u128::from(other.num) * u128::from(self.den)))
    }
}

impl fmt::Display for Ratio {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.num, self.den)
    }
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

/// Which polarities of each conflicting atom an option may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Allowed {
    Both,
    Positive,
    Negative,
}

/// Whether an option of a branch must, may or may not hold a shared leaf.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Occurrence {
    Free,
    Forced,
    Forbidden,
}

/// One subproblem of the branch and bound: the options it covers.
#[derive(Clone, Debug)]
struct Branch {
    /// By conflicting atom.
    polarity: Vec<Allowed>,
    /// By shared leaf ([`Sharing::occurrences`]).
    occurrence: Vec<Occurrence>,
    /// By shared literal: whether one of its leaves is forced (it is then charged there only).
    forced: Vec<bool>,
}

/// Per-goal data for the optimisations, computed once.
#[derive(Clone, Debug)]
pub struct Optimizer<'g> {
    goal: &'g GroundGoal,
    /// For each atom: its slot among the atoms that occur with both polarities, if it does.
    conflict_slot: Vec<Option<u32>>,
    conflicts: usize,
    sharing: Sharing,
    /// Every weight is multiplied by this, a multiple of each shared literal's `most` where
    /// small enough, so that the shares of a negative weight are whole numbers.
    scale: i64,
    /// Whether node values fit `i64` with room for the forced leaves' bonus: every option value
    /// is at most (leaves × largest weight × scale) in magnitude, the largest weight is at most
    /// the number of leaves, and at most one leaf per shared literal is forced.
    narrow: bool,
}

/// The per-literal objective: `weight(lit) = hit · [lit holds] + base`.
#[derive(Clone, Copy)]
struct Objective<'a> {
    truth: &'a [bool],
    hit: i64,
    base: i64,
}

impl Objective<'_> {
    fn holds(&self, lit: Lit) -> bool {
        self.truth[lit.atom.0 as usize] == lit.positive
    }

    fn weight(&self, lit: Lit) -> i64 {
        self.base + if self.holds(lit) { self.hit } else { 0 }
    }
}

/// An option found for an objective: its value (scaled), and its literal counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Best {
    value: i128,
    satisfied: u64,
    size: u64,
}

/// The state of a search: the best option so far, the branches left, and scratch space.
struct Search<V> {
    incumbent: Option<Best>,
    stack: Vec<Branch>,
    values: Vec<Option<V>>,
    option: Vec<NodeId>,
}

impl<'g> Optimizer<'g> {
    /// Prepares the optimisations for a goal, counting options as sets ([`Counting::Set`]).
    pub fn new(goal: &'g GroundGoal) -> Optimizer<'g> {
        Optimizer::with_counting(goal, Counting::Set)
    }

    /// Prepares the optimisations for a goal under a counting: finds the atoms it uses with both
    /// polarities and, for sets, the literals whose leaves can meet in one option — the only
    /// things the branch and bound may split on. Cheap; no option is computed yet.
    pub fn with_counting(goal: &'g GroundGoal, counting: Counting) -> Optimizer<'g> {
        let counts = leaf_counts(goal);
        let (conflict_slot, conflicts) = conflict_slots(&counts);
        let sharing = Sharing::new(goal, counting, &counts);
        let scale = sharing
            .literals
            .iter()
            .fold(1, |scale, l| lcm(scale, l.most).min(MAX_SCALE));
        let leaves: u64 = counts.iter().map(|&c| u64::from(c)).sum();
        let largest = leaves.saturating_mul(leaves).saturating_mul(scale as u64);
        let narrow = largest < 1 << (i64::FORCED_BITS - 1) && sharing.literals.len() < 1 << 20;
        Optimizer {
            goal,
            conflict_slot,
            conflicts,
            sharing,
            scale,
            narrow,
        }
    }

    /// The number of literals in the smallest consistent option; `None` if the goal has no
    /// consistent option (it can never hold).
    pub fn volume(&self) -> Option<u64> {
        let none = vec![false; self.goal.atoms.len()];
        let objective = Objective {
            truth: &none,
            hit: 0,
            base: -1,
        };
        self.maximize(objective).map(|best| best.size)
    }

    /// The exact success score Q in the state given by `oracle`.
    pub fn q(&self, oracle: &impl PredicateOracle) -> Option<Ratio> {
        self.q_with_truth(&self.goal.atom_truth(oracle))
    }

    /// Q given the truth of every atom (by [`AtomId`]).
    pub fn q_with_truth(&self, truth: &[bool]) -> Option<Ratio> {
        // A true goal has a fully true option, and a fully true option makes the goal true.
        if self
            .goal
            .node_holds(self.goal.root, &|a: AtomId| truth[a.0 as usize])
        {
            return Some(Ratio::new(1, 1));
        }
        let mut lambda = Ratio::new(0, 1);
        loop {
            let objective = Objective {
                truth,
                hit: lambda.den as i64,
                base: -(lambda.num as i64),
            };
            let best = self.maximize(objective)?;
            if best.value <= 0 {
                return Some(lambda);
            }
            // best.size ≥ 1: an empty option would have made the goal true above.
            lambda = Ratio::new(best.satisfied, best.size);
        }
    }

    /// The best consistent option for an objective, by branch and bound over conflicting atoms
    /// and shared leaves, in `i64` where the goal is small enough (every official one is).
    fn maximize(&self, objective: Objective) -> Option<Best> {
        if self.narrow {
            self.maximize_in::<i64>(objective)
        } else {
            self.maximize_in::<i128>(objective)
        }
    }

    fn maximize_in<V: Value>(&self, objective: Objective) -> Option<Best> {
        let mut search = Search::<V> {
            incumbent: None,
            stack: vec![Branch {
                polarity: vec![Allowed::Both; self.conflicts],
                occurrence: vec![Occurrence::Free; self.sharing.occurrences],
                forced: vec![false; self.sharing.literals.len()],
            }],
            values: vec![None; self.goal.nodes.len()],
            option: Vec::with_capacity(64),
        };
        while let Some(branch) = search.stack.pop() {
            self.explore(branch, &objective, &mut search);
        }
        search.incumbent
    }

    /// Bounds one branch; records its best option if that is consistent, and splits the branch
    /// if the bound may still hide a better one.
    fn explore<V: Value>(&self, branch: Branch, objective: &Objective, search: &mut Search<V>) {
        node_values(
            self.goal,
            |id, lit| self.leaf_value(id, lit, objective, &branch),
            &mut search.values,
        );
        let Some(bound) = self.bound(search.values[self.goal.root.0 as usize], &branch) else {
            return;
        };
        if search.incumbent.is_some_and(|best| best.value >= bound) {
            return;
        }
        search.option.clear();
        collect(
            self.goal,
            self.goal.root,
            &search.values,
            &mut search.option,
        );
        if let Some(slot) = self.conflict_in(&search.option) {
            for side in [Allowed::Negative, Allowed::Positive] {
                let mut split = branch.clone();
                split.polarity[slot] = side;
                search.stack.push(split);
            }
            return;
        }
        let found = self.evaluate(&search.option, objective);
        if search.incumbent.is_none_or(|best| found.value > best.value) {
            search.incumbent = Some(found);
        }
        if found.value < bound {
            self.split_on_shared(branch, objective, search);
        }
    }

    /// Splits a branch whose best option was overcharged or undercharged for a shared literal:
    /// on one of that literal's leaves in the option, held or not.
    fn split_on_shared<V>(&self, branch: Branch, objective: &Objective, search: &mut Search<V>) {
        let Some((literal, occurrence)) = self.inexact(&search.option, objective, &branch) else {
            debug_assert!(
                false,
                "a bound above its option's value comes from a shared literal"
            );
            return;
        };
        let mut without = branch.clone();
        without.occurrence[occurrence] = Occurrence::Forbidden;
        let mut with = branch;
        with.occurrence[occurrence] = Occurrence::Forced;
        with.forced[literal] = true;
        search.stack.push(without);
        search.stack.push(with);
    }

    /// A leaf's value in a branch: its weight, the share of it a shared leaf is charged, or
    /// `None` where the branch excludes the leaf.
    fn leaf_value<V: Value>(
        &self,
        id: NodeId,
        lit: Lit,
        objective: &Objective,
        branch: &Branch,
    ) -> Option<V> {
        if !self.allowed(&branch.polarity, lit) {
            return None;
        }
        let weight = objective.weight(lit) * self.scale;
        let value = match self.sharing.leaf(id) {
            Leaf::Single => weight,
            Leaf::Twin => 0,
            Leaf::Shared {
                literal,
                occurrence,
            } => match branch.occurrence[occurrence] {
                Occurrence::Forbidden => return None,
                Occurrence::Forced => return Some(V::FORCED + V::from(weight)),
                Occurrence::Free if branch.forced[literal] => 0,
                Occurrence::Free => self.share(weight, literal),
            },
        };
        Some(V::from(value))
    }

    /// What each leaf of a shared literal is charged while none is forced: never less in total
    /// than the literal's weight, whichever of its leaves an option holds.
    fn share(&self, weight: i64, literal: usize) -> i64 {
        if weight >= 0 {
            weight
        } else {
            let most = self.sharing.literals[literal].most;
            -((-weight) / most) // rounded towards zero: up, for a negative weight
        }
    }

    /// The root's value without the forced leaves' bonus; `None` if no option holds them all.
    fn bound<V: Value>(&self, root: Option<V>, branch: &Branch) -> Option<i128> {
        let root: i128 = root?.into();
        // The nearest multiple of the bonus, by a shift: objective values stay below half of it.
        let forced = (root + (V::FORCED.into() >> 1)) >> V::FORCED_BITS;
        let required = branch.forced.iter().filter(|&&f| f).count() as i128;
        (forced == required).then_some(root - (forced << V::FORCED_BITS))
    }

    /// The true value and counts of an option given by its leaves: twins and repeated shared
    /// leaves count once; under reference counting every leaf counts.
    fn evaluate(&self, option: &[NodeId], objective: &Objective) -> Best {
        let mut seen = vec![false; self.sharing.literals.len()];
        let (mut satisfied, mut size) = (0u64, 0u64);
        for &id in option {
            let counted = match self.sharing.leaf(id) {
                Leaf::Single => true,
                Leaf::Twin => false,
                Leaf::Shared { literal, .. } => !std::mem::replace(&mut seen[literal], true),
            };
            if counted {
                size += 1;
                satisfied += u64::from(objective.holds(self.lit(id)));
            }
        }
        let value = i128::from(objective.hit) * i128::from(satisfied)
            + i128::from(objective.base) * i128::from(size);
        Best {
            value: value * i128::from(self.scale),
            satisfied,
            size,
        }
    }

    /// A shared literal (not forced) that the option was charged for other than its weight, and
    /// its first leaf in the option.
    fn inexact(
        &self,
        option: &[NodeId],
        objective: &Objective,
        branch: &Branch,
    ) -> Option<(usize, usize)> {
        let mut held: Vec<(i64, usize)> = vec![(0, 0); self.sharing.literals.len()];
        for &id in option {
            if let Leaf::Shared {
                literal,
                occurrence,
            } = self.sharing.leaf(id)
                && !branch.forced[literal]
            {
                let (count, first) = &mut held[literal];
                if *count == 0 {
                    *first = occurrence;
                }
                *count += 1;
            }
        }
        held.iter()
            .enumerate()
            .find_map(|(literal, &(count, first))| {
                let lit = self.lit(self.sharing.literals[literal].leaves[0]);
                let weight = objective.weight(lit) * self.scale;
                (count > 0 && count * self.share(weight, literal) != weight)
                    .then_some((literal, first))
            })
    }

    fn lit(&self, id: NodeId) -> Lit {
        match self.goal.node(id) {
            Node::Lit(lit) => *lit,
            _ => unreachable!("options are made of leaves"),
        }
    }

    fn allowed(&self, allowed: &[Allowed], lit: Lit) -> bool {
        match self.conflict_slot[lit.atom.0 as usize] {
            None => true,
            Some(slot) => match allowed[slot as usize] {
                Allowed::Both => true,
                Allowed::Positive => lit.positive,
                Allowed::Negative => !lit.positive,
            },
        }
    }

    /// The slot of an atom the option uses with both polarities, if any.
    fn conflict_in(&self, option: &[NodeId]) -> Option<usize> {
        if self.conflicts == 0 {
            return None;
        }
        let mut seen = vec![(false, false); self.conflicts];
        for &id in option {
            let lit = self.lit(id);
            if let Some(slot) = self.conflict_slot[lit.atom.0 as usize] {
                let s = &mut seen[slot as usize];
                if lit.positive {
                    s.0 = true;
                } else {
                    s.1 = true;
                }
                if s.0 && s.1 {
                    return Some(slot as usize);
                }
            }
        }
        None
    }
}

/// The largest weight scale: beyond it a share is rounded (up), which keeps the bound admissible.
const MAX_SCALE: i64 = 720;

/// For each atom, its slot among the atoms the goal uses with both polarities; and their number.
/// `counts` are the goal's leaves per literal, negative then positive for each atom.
fn conflict_slots(counts: &[u32]) -> (Vec<Option<u32>>, usize) {
    let mut conflicts = 0;
    let slots = counts
        .chunks_exact(2)
        .map(|c| {
            (c[0] > 0 && c[1] > 0).then(|| {
                conflicts += 1;
                conflicts as u32 - 1
            })
        })
        .collect();
    (slots, conflicts)
}

fn lcm(a: i64, b: i64) -> i64 {
    let (mut x, mut y) = (a, b);
    while y != 0 {
        (x, y) = (y, x % y);
    }
    a / x * b
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Activity, CheckContext, Source};

    /// The `i128` arithmetic kept for goals too large for `i64` gives what `i64` gives, on a goal
    /// with shared literals (`(open b1)` once per child of a `forn (2)`, and also negated;
    /// `(cooked a1)` in a child and in the `or`), in every state of its four atoms.
    #[test]
    fn wide_values_agree_with_narrow_ones() {
        let text = "(define (problem p_0) (:domain igibson)
          (:objects a.n.01_1 a.n.01_2 a.n.01_3 - a.n.01 b.n.01_1 - b.n.01) (:init)
          (:goal (and (forn (2) (?a.n.01 - a.n.01) (and (cooked ?a.n.01) (open b.n.01_1)))
                      (or (not (open b.n.01_1)) (cooked a.n.01_1)))))";
        let (activity, _) = Activity::load(&Source::new("p.bddl", text), CheckContext::default())
            .unwrap_or_else(|e| panic!("{e}"));
        let goal = GroundGoal::new(&activity);
        let narrow = Optimizer::new(&goal);
        assert!(narrow.narrow);
        assert_eq!(narrow.sharing.literals.len(), 2); // (open b1), and (cooked a1) twice
        assert_eq!(narrow.conflicts, 1);
        let wide = Optimizer {
            narrow: false,
            ..narrow.clone()
        };
        // {cooked a1, cooked a_j, open b1}; as a list `open b1` counts twice.
        assert_eq!((narrow.volume(), wide.volume()), (Some(3), Some(3)));
        assert_eq!(
            Optimizer::with_counting(&goal, Counting::Reference).volume(),
            Some(5)
        );
        assert_eq!(goal.atoms.len(), 4);
        for bits in 0..16u32 {
            let truth: Vec<bool> = (0..4).map(|k| bits & (1 << k) != 0).collect();
            assert_eq!(
                narrow.q_with_truth(&truth),
                wide.q_with_truth(&truth),
                "{bits:04b}"
            );
        }
    }
}
