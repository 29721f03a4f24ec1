//! Exact success score Q and activity volume, without enumerating the goal's options.
//!
//! Both are optimisations over the options (the terms of the goal's disjunctive normal form, see
//! [`crate::ground`]) that contain no literal together with its negation:
//! - volume = the fewest literals in an option;
//! - Q = the largest fraction of an option's literals that hold in a state.
//!
//! Any objective that adds up per-literal weights is maximised over options by one bottom-up pass
//! over the ground tree (sum for `and`, best child for `or`, best `n` children for `forn`, a
//! maximum-weight assignment for pair quantifiers). Consistency is enforced by branch and bound:
//! when the best option uses both `a` and `not a`, search again with `a` restricted to one
//! polarity, then the other. Q is a ratio, so it is found by Dinkelbach's method: for a candidate
//! `λ = p/q`, maximise `Σ (q·[literal holds] − p)`; a positive maximum yields a better option whose
//! ratio becomes the next `λ`. All arithmetic is on integers, so results are exact.

use crate::eval::PredicateOracle;
use crate::ground::{AtomId, GroundGoal, Lit, Node, NodeId};
use crate::matching;
use std::cmp::Ordering;
use std::fmt;

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

/// Per-goal data for the optimisations, computed once.
#[derive(Clone, Debug)]
pub struct Optimizer<'g> {
    goal: &'g GroundGoal,
    /// For each atom: its slot among the atoms that occur with both polarities, if it does.
    conflict_slot: Vec<Option<u32>>,
    conflicts: usize,
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

/// The best option found for an objective: its value, and its literal counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Best {
    value: i64,
    satisfied: u64,
    size: u64,
}

impl<'g> Optimizer<'g> {
    /// Prepares the optimisations for a goal: finds the atoms it uses with both polarities, the
    /// only ones the branch and bound may have to split on. Cheap; no option is computed yet.
    pub fn new(goal: &'g GroundGoal) -> Optimizer<'g> {
        let mut polarity = vec![(false, false); goal.atoms.len()];
        for node in &goal.nodes {
            if let Node::Lit(lit) = node {
                let p = &mut polarity[lit.atom.0 as usize];
                if lit.positive {
                    p.0 = true;
                } else {
                    p.1 = true;
                }
            }
        }
        let mut conflicts = 0;
        let conflict_slot = polarity
            .iter()
            .map(|&(pos, neg)| {
                (pos && neg).then(|| {
                    conflicts += 1;
                    conflicts as u32 - 1
                })
            })
            .collect();
        Optimizer {
            goal,
            conflict_slot,
            conflicts,
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

    /// The smallest (or with `largest`, the largest) option size of every node, ignoring
    /// consistency; `None` for a node without options.
    pub(crate) fn unrestricted_sizes(&self, largest: bool) -> Vec<Option<u64>> {
        let none = vec![false; self.goal.atoms.len()];
        let base = if largest { 1 } else { -1 };
        let objective = Objective {
            truth: &none,
            hit: 0,
            base,
        };
        let mut values = vec![None; self.goal.nodes.len()];
        self.values(objective, &vec![Allowed::Both; self.conflicts], &mut values);
        values
            .into_iter()
            .map(|v| v.map(|v| (v * base) as u64))
            .collect()
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

    /// The best consistent option for an objective, by branch and bound over conflicting atoms.
    fn maximize(&self, objective: Objective) -> Option<Best> {
        let mut incumbent: Option<Best> = None;
        let mut stack = vec![vec![Allowed::Both; self.conflicts]];
        let mut values = vec![None; self.goal.nodes.len()];
        let mut option = Vec::new();
        while let Some(allowed) = stack.pop() {
            self.values(objective, &allowed, &mut values);
            let Some(bound) = values[self.goal.root.0 as usize] else {
                continue;
            };
            if incumbent.is_some_and(|best| best.value >= bound) {
                continue;
            }
            option.clear();
            self.collect(self.goal.root, &values, &mut option);
            match self.conflict_in(&option) {
                None => {
                    let satisfied = option.iter().filter(|&&l| objective.holds(l)).count();
                    incumbent = Some(Best {
                        value: bound,
                        satisfied: satisfied as u64,
                        size: option.len() as u64,
                    });
                }
                Some(slot) => {
                    for side in [Allowed::Negative, Allowed::Positive] {
                        let mut branch = allowed.clone();
                        branch[slot] = side;
                        stack.push(branch);
                    }
                }
            }
        }
        incumbent
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

    /// The best value of every node (children precede parents, so one forward pass suffices).
    fn values(&self, objective: Objective, allowed: &[Allowed], values: &mut [Option<i64>]) {
        for (i, node) in self.goal.nodes.iter().enumerate() {
            let value = |id: &NodeId| values[id.0 as usize];
            values[i] = match node {
                Node::Lit(lit) => self.allowed(allowed, *lit).then(|| objective.weight(*lit)),
                Node::And(children) => children.iter().map(value).sum(),
                Node::Or(children) => children.iter().filter_map(value).max(),
                Node::AtLeast { n, children } => {
                    let mut feasible: Vec<i64> = children.iter().filter_map(value).collect();
                    if feasible.len() < *n {
                        None
                    } else {
                        feasible.sort_unstable_by(|a, b| b.cmp(a));
                        Some(feasible[..*n].iter().sum())
                    }
                }
                Node::Pairs {
                    n,
                    rows,
                    cols,
                    cells,
                } => matching::best_matching(*rows, *cols, *n, |r, c| value(&cells[r * cols + c]))
                    .map(|(total, _)| total),
                Node::NoPairs {
                    n,
                    rows,
                    cols,
                    cells,
                } => best_cover(*n, *rows, *cols, cells, values).map(|(total, _)| total),
            };
        }
    }

    /// Appends the literals of the best option of `id`, following the choices `values` imply.
    fn collect(&self, id: NodeId, values: &[Option<i64>], out: &mut Vec<Lit>) {
        let value = |id: NodeId| values[id.0 as usize];
        match self.goal.node(id) {
            Node::Lit(lit) => out.push(*lit),
            Node::And(children) => {
                for &c in children {
                    self.collect(c, values, out);
                }
            }
            Node::Or(children) => {
                let best = children
                    .iter()
                    .copied()
                    .filter(|&c| value(c).is_some())
                    .max_by_key(|&c| (value(c), std::cmp::Reverse(c)));
                if let Some(best) = best {
                    self.collect(best, values, out);
                }
            }
            Node::AtLeast { n, children } => {
                let mut feasible: Vec<NodeId> = children
                    .iter()
                    .copied()
                    .filter(|&c| value(c).is_some())
                    .collect();
                feasible.sort_by_key(|&c| std::cmp::Reverse(value(c)));
                for &c in feasible.iter().take(*n) {
                    self.collect(c, values, out);
                }
            }
            Node::Pairs {
                n,
                rows,
                cols,
                cells,
            } => {
                let best =
                    matching::best_matching(*rows, *cols, *n, |r, c| value(cells[r * cols + c]));
                for (r, c) in best.map(|(_, pairs)| pairs).unwrap_or_default() {
                    self.collect(cells[r * cols + c], values, out);
                }
            }
            Node::NoPairs {
                n,
                rows,
                cols,
                cells,
            } => {
                let uncovered = best_cover(*n, *rows, *cols, cells, values).map(|(_, u)| u);
                for k in uncovered.unwrap_or_default() {
                    self.collect(cells[k], values, out);
                }
            }
        }
    }

    /// The slot of an atom the option uses with both polarities, if any.
    fn conflict_in(&self, option: &[Lit]) -> Option<usize> {
        if self.conflicts == 0 {
            return None;
        }
        let mut seen = vec![(false, false); self.conflicts];
        for lit in option {
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

/// The best way to leave cells uncovered by `n − 1` rows and columns: (value, uncovered cells).
fn best_cover(
    n: usize,
    rows: usize,
    cols: usize,
    cells: &[NodeId],
    values: &[Option<i64>],
) -> Option<(i64, Vec<usize>)> {
    if n == 0 {
        return None; // "no empty matching exists" is false
    }
    if n > rows.min(cols) {
        return Some((0, Vec::new())); // n disjoint pairs cannot exist: true
    }
    let mut best: Option<(i64, Vec<usize>)> = None;
    for uncovered in matching::covers(rows, cols, n - 1) {
        let total: Option<i64> = uncovered.iter().map(|&k| values[cells[k].0 as usize]).sum();
        if let Some(total) = total
            && best.as_ref().is_none_or(|(b, _)| total > *b)
        {
            best = Some((total, uncovered));
        }
    }
    best
}
