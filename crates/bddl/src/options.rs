//! A lazy iterator over a goal's options, smallest first, for inspection.
//!
//! An option is one term of the goal's disjunctive normal form: literals whose conjunction
//! implies the goal. Options that contain a literal and its negation are skipped. Counts explode
//! (products over quantifiers), so options are produced on demand: for each size from the
//! smallest possible upwards, every way through the tree of exactly that size, found by splitting
//! the size among the children of each conjunction within their possible ranges.
//!
//! Under [`Counting::Reference`] an option is the list of leaves a way through the tree reaches,
//! and every way is listed. Under [`Counting::Set`] (the default) an option is the *set* of those
//! literals and each set is listed once. Sizes are then counted without twins and shared leaves
//! (module `sharing`), which a set may hold several times over: a way of such a *reduced*
//! size `r` gives a set of `r` to `r + (shared literals)` literals, so a set is held back until
//! every way that could give a smaller one has been seen. Two ways give the same set only with
//! the same reduced size, so duplicates are caught by remembering one size's sets at a time, and
//! not at all when the goal's shape rules them out.

use crate::activity::Literal;
use crate::bottom_up::node_values;
use crate::ground::{GroundGoal, Lit, Node, NodeId};
use crate::matching;
use crate::optimize::Counting;
use crate::sharing::{Leaf, Sharing, leaf_counts};
use itertools::{Either, Itertools};
use std::collections::{BTreeMap, HashSet, VecDeque};
use std::rc::Rc;

type Options<'g> = Box<dyn Iterator<Item = Vec<Lit>> + 'g>;

/// Every consistent option of the goal, as sets of literals ([`Counting::Set`]), in
/// nondecreasing size; ties in a fixed order.
pub fn options(goal: &GroundGoal) -> impl Iterator<Item = Vec<Literal>> + '_ {
    options_with(goal, Counting::Set)
}

/// Every consistent option of the goal under a counting, in nondecreasing size (as that
/// counting counts); ties in a fixed order. Literals keep the order in which the goal reaches
/// them.
pub fn options_with(
    goal: &GroundGoal,
    counting: Counting,
) -> impl Iterator<Item = Vec<Literal>> + '_ {
    let sharing = Sharing::new(goal, counting, &leaf_counts(goal));
    let sizes = Rc::new(Sizes::new(goal, &sharing));
    let plan = SetPlan::new(goal, &sharing, &sizes);
    let ways = ways_by_size(goal, sizes);
    let found = match counting {
        Counting::Reference => Either::Left(ways.map(|(_, way)| way).filter(|w| is_consistent(w))),
        Counting::Set => Either::Right(SetOptions::new(ways, plan)),
    };
    found.map(move |option| option.into_iter().map(|l| goal.literal(l)).collect())
}

/// Every way through the tree with its reduced size, smallest first.
fn ways_by_size<'g>(
    goal: &'g GroundGoal,
    sizes: Rc<Sizes>,
) -> impl Iterator<Item = (usize, Vec<Lit>)> + 'g {
    let root = goal.root;
    let range = sizes.range(root);
    range
        .into_iter()
        .flat_map(|(lo, hi)| lo..=hi)
        .flat_map(move |size| exact(goal, sizes.clone(), root, size).map(move |w| (size, w)))
}

fn is_consistent(option: &[Lit]) -> bool {
    let mut sorted: Vec<Lit> = option.to_vec();
    sorted.sort_unstable();
    sorted
        .windows(2)
        .all(|w| w[0].atom != w[1].atom || w[0].positive == w[1].positive)
}

/// The size each leaf adds, and the smallest and largest size of every node, ignoring
/// consistency.
struct Sizes {
    /// By node: 1, or 0 for a twin or shared leaf under set counting.
    leaf: Vec<u8>,
    min: Vec<Option<u64>>,
    max: Vec<Option<u64>>,
}

impl Sizes {
    fn new(goal: &GroundGoal, sharing: &Sharing) -> Sizes {
        let leaf: Vec<u8> = (0..goal.nodes.len() as u32)
            .map(|i| u8::from(sharing.leaf(NodeId(i)) == Leaf::Single))
            .collect();
        let extreme = |sign: i64| {
            let mut values = vec![None; goal.nodes.len()];
            node_values(
                goal,
                |id, _| Some(sign * i64::from(leaf[id.0 as usize])),
                &mut values,
            );
            values
                .into_iter()
                .map(|v| v.map(|v| (v * sign) as u64))
                .collect()
        };
        Sizes {
            min: extreme(-1),
            max: extreme(1),
            leaf,
        }
    }

    fn range(&self, id: NodeId) -> Option<(usize, usize)> {
        let i = id.0 as usize;
        Some((self.min[i]? as usize, self.max[i]? as usize))
    }
}

/// How set counting turns ways into options for one goal.
#[derive(Clone, Copy, Debug)]
struct SetPlan {
    /// Whether a way may reach a literal twice (through twins or shared leaves).
    repeats_within: bool,
    /// Whether two ways may reach the same set of literals.
    repeats_across: bool,
}

impl SetPlan {
    /// Two ways give different sets unless a literal has several leaves that are not twins, a
    /// negated pair quantifier's covers leave the same cells, or a choice is between children of
    /// which one may be empty (its way adds nothing to tell it apart).
    fn new(goal: &GroundGoal, sharing: &Sharing, sizes: &Sizes) -> SetPlan {
        let may_be_empty = |c: &NodeId| sizes.min[c.0 as usize] == Some(0);
        let ambiguous = goal.nodes.iter().any(|node| match node {
            Node::Lit(_) | Node::And(_) => false,
            Node::Or(children) | Node::AtLeast { children, .. } => {
                children.iter().any(may_be_empty)
            }
            Node::Pairs { cells, .. } => cells.iter().any(may_be_empty),
            Node::NoPairs { .. } => true,
        });
        SetPlan {
            repeats_within: sharing.twins || !sharing.literals.is_empty(),
            repeats_across: sharing.repeats || ambiguous,
        }
    }
}

/// Set counting over the ways, smallest reduced size first: each consistent way becomes a set,
/// repeated sets are dropped, and sets wait until nothing smaller can come.
struct SetOptions<I> {
    ways: I,
    plan: SetPlan,
    /// The reduced size of the ways being read; every way still to come has at least this size,
    /// so its set too. `usize::MAX` once all are read.
    level: usize,
    /// The sets (sorted) already found at this level, when ways may repeat a set.
    seen: HashSet<Vec<Lit>>,
    /// Sets found but larger than `level`, by size, in the order found.
    waiting: BTreeMap<usize, VecDeque<Vec<Lit>>>,
}

impl<I: Iterator<Item = (usize, Vec<Lit>)>> SetOptions<I> {
    fn new(ways: I, plan: SetPlan) -> Self {
        SetOptions {
            ways,
            plan,
            level: 0,
            seen: HashSet::new(),
            waiting: BTreeMap::new(),
        }
    }

    /// The first waiting set no larger than `level`.
    fn due(&mut self) -> Option<Vec<Lit>> {
        let mut entry = self.waiting.first_entry()?;
        if *entry.key() > self.level {
            return None;
        }
        let set = entry.get_mut().pop_front();
        if entry.get().is_empty() {
            entry.remove();
        }
        set
    }

    /// The way's set, if consistent and not found before.
    fn admit(&mut self, level: usize, way: Vec<Lit>) -> Option<Vec<Lit>> {
        if level != self.level {
            self.level = level;
            self.seen.clear();
        }
        if !is_consistent(&way) {
            return None;
        }
        let set = if self.plan.repeats_within {
            way.into_iter().unique().collect()
        } else {
            way
        };
        if self.plan.repeats_across {
            let mut key = set.clone();
            key.sort_unstable();
            if !self.seen.insert(key) {
                return None;
            }
        }
        Some(set)
    }
}

impl<I: Iterator<Item = (usize, Vec<Lit>)>> Iterator for SetOptions<I> {
    type Item = Vec<Lit>;

    fn next(&mut self) -> Option<Vec<Lit>> {
        loop {
            if let Some(set) = self.due() {
                return Some(set);
            }
            if self.level == usize::MAX {
                return None;
            }
            let Some((level, way)) = self.ways.next() else {
                self.level = usize::MAX;
                continue;
            };
            let Some(set) = self.admit(level, way) else {
                continue;
            };
            if set.len() == self.level && self.waiting.is_empty() {
                return Some(set);
            }
            self.waiting.entry(set.len()).or_default().push_back(set);
        }
    }
}

/// The ways through node `id` with exactly `size` (reduced) literals.
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
        Node::Lit(lit) => {
            let fits = size == usize::from(sizes.leaf[id.0 as usize]);
            Box::new(fits.then(|| vec![*lit]).into_iter())
        }
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

/// The ways through the conjunction of `group.nodes[start..end]` with exactly `size` literals,
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
