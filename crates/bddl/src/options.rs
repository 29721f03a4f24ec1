//! A lazy iterator over a goal's options, smallest first, for inspection.
//!
//! An option is one term of the goal's disjunctive normal form: a list of ground literals whose
//! conjunction implies the goal. Options that contain a literal and its negation are skipped.
//! Counts explode (products over quantifiers), so options are produced on demand: for each size
//! from the smallest possible upwards, every option of exactly that size, found by splitting the
//! size among the children of each conjunction within their possible ranges.

use crate::activity::Literal;
use crate::ground::{GroundGoal, Lit, Node, NodeId};
use crate::matching;
use crate::optimize::Optimizer;
use itertools::Itertools;
use std::rc::Rc;

type Options<'g> = Box<dyn Iterator<Item = Vec<Lit>> + 'g>;

/// Every consistent option of the goal, in nondecreasing size; ties in a fixed order.
pub fn options(goal: &GroundGoal) -> impl Iterator<Item = Vec<Literal>> + '_ {
    let optimizer = Optimizer::new(goal);
    let sizes = Rc::new(Sizes {
        min: optimizer.unrestricted_sizes(false),
        max: optimizer.unrestricted_sizes(true),
    });
    let root = goal.root;
    let range = sizes.range(root);
    range
        .into_iter()
        .flat_map(|(lo, hi)| lo..=hi)
        .flat_map(move |size| exact(goal, sizes.clone(), root, size))
        .filter(|option| is_consistent(option))
        .map(move |option| option.into_iter().map(|l| goal.literal(l)).collect())
}

/// The smallest and largest option size of every node, ignoring consistency.
struct Sizes {
    min: Vec<Option<u64>>,
    max: Vec<Option<u64>>,
}

impl Sizes {
    fn range(&self, id: NodeId) -> Option<(usize, usize)> {
        let i = id.0 as usize;
        Some((self.min[i]? as usize, self.max[i]? as usize))
    }
}

fn is_consistent(option: &[Lit]) -> bool {
    let mut sorted: Vec<Lit> = option.to_vec();
    sorted.sort_unstable();
    sorted
        .windows(2)
        .all(|w| w[0].atom != w[1].atom || w[0].positive == w[1].positive)
}

/// The options of node `id` with exactly `size` literals.
fn exact<'g>(goal: &'g GroundGoal, sizes: Rc<Sizes>, id: NodeId, size: usize) -> Options<'g> {
    match sizes.range(id) {
        Some((lo, hi)) if (lo..=hi).contains(&size) => {}
        _ => return Box::new(std::iter::empty()),
    }
    let all = |groups: Box<dyn Iterator<Item = Vec<NodeId>> + 'g>| -> Options<'g> {
        let sizes = sizes.clone();
        Box::new(
            groups.flat_map(move |group| conjunction(goal, sizes.clone(), Rc::new(group), 0, size)),
        )
    };
    match goal.node(id) {
        Node::Lit(lit) => Box::new((size == 1).then(|| vec![*lit]).into_iter()),
        Node::And(children) => conjunction(goal, sizes, Rc::new(children.clone()), 0, size),
        Node::Or(children) => {
            let children = children.clone();
            Box::new(
                children
                    .into_iter()
                    .flat_map(move |c| exact(goal, sizes.clone(), c, size)),
            )
        }
        Node::AtLeast { n, children } => {
            all(Box::new(children.clone().into_iter().combinations(*n)))
        }
        Node::Pairs {
            n,
            rows,
            cols,
            cells,
        } => {
            let cells = cells.clone();
            let groups = matching::matchings(*rows, *cols, *n)
                .map(move |m| m.into_iter().map(|k| cells[k]).collect());
            all(Box::new(groups))
        }
        Node::NoPairs {
            n,
            rows,
            cols,
            cells,
        } => {
            if *n > (*rows).min(*cols) {
                return Box::new((size == 0).then(Vec::new).into_iter());
            }
            let cells = cells.clone();
            let groups = matching::covers(*rows, *cols, n - 1)
                .map(move |u| u.into_iter().map(|k| cells[k]).collect());
            all(Box::new(groups))
        }
    }
}

/// The options of the conjunction of `children[start..]` with exactly `size` literals.
fn conjunction<'g>(
    goal: &'g GroundGoal,
    sizes: Rc<Sizes>,
    children: Rc<Vec<NodeId>>,
    start: usize,
    size: usize,
) -> Options<'g> {
    let Some(&first) = children.get(start) else {
        return Box::new((size == 0).then(Vec::new).into_iter());
    };
    let mut rest = (0usize, 0usize);
    for &c in &children[start + 1..] {
        let Some((lo, hi)) = sizes.range(c) else {
            return Box::new(std::iter::empty());
        };
        rest = (rest.0 + lo, rest.1 + hi);
    }
    let Some((lo, hi)) = sizes.range(first) else {
        return Box::new(std::iter::empty());
    };
    let from = lo.max(size.saturating_sub(rest.1));
    let to = hi.min(size.saturating_sub(rest.0));
    if from > to || size < rest.0 {
        return Box::new(std::iter::empty());
    }
    Box::new((from..=to).flat_map(move |head_size| {
        let (sizes, children) = (sizes.clone(), children.clone());
        exact(goal, sizes.clone(), first, head_size).flat_map(move |head| {
            conjunction(
                goal,
                sizes.clone(),
                children.clone(),
                start + 1,
                size - head_size,
            )
            .map(move |tail| {
                let mut option = head.clone();
                option.extend(tail);
                option
            })
        })
    }))
}
