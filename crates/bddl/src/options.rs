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
            groups.flat_map(move |group| match Group::new(group, &sizes) {
                Some(group) => {
                    let end = group.nodes.len();
                    conjunction(goal, sizes.clone(), Rc::new(group), 0, end, size)
                }
                None => Box::new(std::iter::empty()),
            }),
        )
    };
    match goal.node(id) {
        Node::Lit(lit) => Box::new((size == 1).then(|| vec![*lit]).into_iter()),
        Node::And(children) => all(Box::new(std::iter::once(children.clone()))),
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

/// Nodes to be conjoined, with prefix sums of their size ranges.
struct Group {
    nodes: Vec<NodeId>,
    /// `min[i]`, `max[i]`: total smallest and largest size of `nodes[..i]`.
    min: Vec<usize>,
    max: Vec<usize>,
}

impl Group {
    /// `None` when some node has no option at all (then neither has the conjunction).
    fn new(nodes: Vec<NodeId>, sizes: &Sizes) -> Option<Group> {
        let (mut min, mut max) = (vec![0], vec![0]);
        for &n in &nodes {
            let (lo, hi) = sizes.range(n)?;
            min.push(min.last()? + lo);
            max.push(max.last()? + hi);
        }
        Some(Group { nodes, min, max })
    }
}

/// The options of the conjunction of `group.nodes[start..end]` with exactly `size` literals,
/// splitting the range in halves so the nesting of iterators stays logarithmic in its length.
fn conjunction<'g>(
    goal: &'g GroundGoal,
    sizes: Rc<Sizes>,
    group: Rc<Group>,
    start: usize,
    end: usize,
    size: usize,
) -> Options<'g> {
    let span = |a: usize, b: usize| (group.min[b] - group.min[a], group.max[b] - group.max[a]);
    let (lo, hi) = span(start, end);
    if !(lo..=hi).contains(&size) {
        return Box::new(std::iter::empty());
    }
    match end - start {
        0 => return Box::new(std::iter::once(Vec::new())),
        1 => return exact(goal, sizes, group.nodes[start], size),
        _ => {}
    }
    let mid = start + (end - start) / 2;
    let ((left_lo, left_hi), (right_lo, right_hi)) = (span(start, mid), span(mid, end));
    let from = left_lo.max(size.saturating_sub(right_hi));
    let to = left_hi.min(size.saturating_sub(right_lo));
    Box::new((from..=to).flat_map(move |left_size| {
        let (sizes, group) = (sizes.clone(), group.clone());
        conjunction(goal, sizes.clone(), group.clone(), start, mid, left_size).flat_map(
            move |left| {
                conjunction(
                    goal,
                    sizes.clone(),
                    group.clone(),
                    mid,
                    end,
                    size - left_size,
                )
                .map(move |right| {
                    let mut option = left.clone();
                    option.extend(right);
                    option
                })
            },
        )
    }))
}
