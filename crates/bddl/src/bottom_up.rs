//! One bottom-up pass over a ground goal: given a value for every leaf, the best value of every
//! node's options (sum for `and`, best child for `or`, best `n` children for `forn`, a
//! maximum-weight assignment for pair quantifiers, the best cover for negated ones), and the
//! leaves of the option that achieves the root's.
//!
//! A leaf's value is `None` where the leaf may not be used; a node without usable options is
//! `None` too. Values are a [`Value`]: `i64`, or `i128` for goals too large for the optimizer to
//! pack its count of forced leaves above the objective in 64 bits (see [`crate::optimize`]).

use crate::ground::{GroundGoal, Lit, Node, NodeId};
use crate::matching;
use std::cmp::Reverse;
use std::iter::Sum;
use std::ops::Add;

/// An integer type for node values, with room above every objective value for a count of forced
/// leaves, each worth [`Value::FORCED`].
pub(crate) trait Value:
    Copy + Ord + Add<Output = Self> + Sum + From<i64> + Into<i128>
{
    /// log2 of [`Value::FORCED`].
    const FORCED_BITS: u32;
    /// The bonus of one forced leaf; objective values stay below half of it in magnitude.
    const FORCED: Self;
}

impl Value for i64 {
    const FORCED_BITS: u32 = 40;
    const FORCED: i64 = 1 << 40;
}

impl Value for i128 {
    const FORCED_BITS: u32 = 64;
    const FORCED: i128 = 1 << 64;
}

/// Fills `values` (one per node) bottom-up; `leaf(id, lit)` values each leaf. Children precede
/// their parents in a ground goal, so one forward pass suffices.
pub(crate) fn node_values<V: Value>(
    goal: &GroundGoal,
    leaf: impl Fn(NodeId, Lit) -> Option<V>,
    values: &mut [Option<V>],
) {
    for (i, node) in goal.nodes.iter().enumerate() {
        values[i] = match node {
            Node::Lit(lit) => leaf(NodeId(i as u32), *lit),
            _ => combine(node, values),
        };
    }
}

/// The best value of an inner node from its children's.
fn combine<V: Value>(node: &Node, values: &[Option<V>]) -> Option<V> {
    let value = |id: &NodeId| values[id.0 as usize];
    match node {
        Node::Lit(_) => unreachable!("leaves are valued by the caller"),
        Node::And(children) => children.iter().map(value).sum(),
        Node::Or(children) => children.iter().filter_map(value).max(),
        Node::AtLeast { n, children } => {
            let mut feasible: Vec<V> = children.iter().filter_map(value).collect();
            if feasible.len() < *n {
                return None;
            }
            feasible.sort_unstable_by(|a, b| b.cmp(a));
            Some(feasible[..*n].iter().copied().sum())
        }
        Node::Pairs {
            n,
            rows,
            cols,
            cells,
        } => best_pairs(*n, *rows, *cols, cells, values).map(|(total, _)| total),
        Node::NoPairs {
            n,
            rows,
            cols,
            cells,
        } => best_cover(*n, *rows, *cols, cells, values).map(|(total, _)| total),
    }
}

/// Appends the leaves of the best option of `id`, following the choices `values` imply (ties go
/// to the earlier child).
pub(crate) fn collect<V: Value>(
    goal: &GroundGoal,
    id: NodeId,
    values: &[Option<V>],
    out: &mut Vec<NodeId>,
) {
    let value = |id: NodeId| values[id.0 as usize];
    match goal.node(id) {
        Node::Lit(_) => out.push(id),
        Node::And(children) => {
            for &c in children {
                collect(goal, c, values, out);
            }
        }
        Node::Or(children) => {
            let best = children
                .iter()
                .copied()
                .filter(|&c| value(c).is_some())
                .max_by_key(|&c| (value(c), Reverse(c)));
            if let Some(best) = best {
                collect(goal, best, values, out);
            }
        }
        node => {
            for c in chosen(node, values) {
                collect(goal, c, values, out);
            }
        }
    }
}

/// The children a counting node (`forn`, pair quantifiers) picks for its best option.
fn chosen<V: Value>(node: &Node, values: &[Option<V>]) -> Vec<NodeId> {
    let value = |id: NodeId| values[id.0 as usize];
    match node {
        Node::AtLeast { n, children } => {
            let mut feasible: Vec<NodeId> = children
                .iter()
                .copied()
                .filter(|&c| value(c).is_some())
                .collect();
            feasible.sort_by_key(|&c| Reverse(value(c)));
            feasible.truncate(*n);
            feasible
        }
        Node::Pairs {
            n,
            rows,
            cols,
            cells,
        } => best_pairs(*n, *rows, *cols, cells, values)
            .map(|(_, pairs)| pairs)
            .unwrap_or_default(),
        Node::NoPairs {
            n,
            rows,
            cols,
            cells,
        } => best_cover(*n, *rows, *cols, cells, values)
            .map(|(_, uncovered)| uncovered)
            .unwrap_or_default()
            .into_iter()
            .map(|k| cells[k])
            .collect(),
        Node::Lit(_) | Node::And(_) | Node::Or(_) => unreachable!("handled by collect"),
    }
}

/// The best `n` disjoint cells of a pair quantifier: (value, cells).
fn best_pairs<V: Value>(
    n: usize,
    rows: usize,
    cols: usize,
    cells: &[NodeId],
    values: &[Option<V>],
) -> Option<(V, Vec<NodeId>)> {
    let value = |r: usize, c: usize| values[cells[r * cols + c].0 as usize];
    let (_, pairs) = matching::best_matching(rows, cols, n, |r, c| value(r, c).map(Into::into))?;
    // The total again, in `V`: the matching works in `i128` whatever `V` is.
    let total = pairs.iter().map(|&(r, c)| value(r, c)).sum::<Option<V>>()?;
    Some((
        total,
        pairs.iter().map(|&(r, c)| cells[r * cols + c]).collect(),
    ))
}

/// The best way to leave cells uncovered by `n − 1` rows and columns: (value, uncovered cells).
fn best_cover<V: Value>(
    n: usize,
    rows: usize,
    cols: usize,
    cells: &[NodeId],
    values: &[Option<V>],
) -> Option<(V, Vec<usize>)> {
    if n == 0 {
        return None; // "no empty matching exists" is false
    }
    if n > rows.min(cols) {
        return Some((V::from(0), Vec::new())); // n disjoint pairs cannot exist: true
    }
    let mut best: Option<(V, Vec<usize>)> = None;
    for uncovered in matching::covers(rows, cols, n - 1) {
        let total: Option<V> = uncovered.iter().map(|&k| values[cells[k].0 as usize]).sum();
        if let Some(total) = total
            && best.as_ref().is_none_or(|(b, _)| total > *b)
        {
            best = Some((total, uncovered));
        }
    }
    best
}
