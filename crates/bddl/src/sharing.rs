//! Which leaves of a ground goal can put the same literal into one option twice, so that options
//! can be counted as sets (the paper's Q and volume) with a per-leaf, additive objective wherever
//! that is exact, and with a branch and bound only where it is not.
//!
//! A literal reaches several leaves when it is written twice or reached through different
//! quantifier instantiations. Under [`Counting::Set`] every leaf is one of three kinds:
//! - a **twin** repeats an earlier leaf of the same literal that hangs from the same conjunction
//!   through conjunctions only. Every option holding one holds the other, so the twin adds
//!   nothing (`(forall (?b - bowl) (and (inside ?b ?c) (not (inside cup_1 ?c))))` writes the
//!   second literal once per bowl; `cleaning_kitchen_cupboard` is the official case);
//! - a **single** leaf is the only leaf of its literal that any option can hold: its literal has
//!   no other leaf apart from twins, or its other leaves sit in other branches of an `or`, in other
//!   cells of the same row or column of a pair quantifier, or among the children of a `forn (1)`
//!   (`preparing_salad` writes `(sliced ?apple)` in every cell of a row of a `forpairs`);
//! - a **shared** leaf is one of several that can meet in one option. Only these make an additive
//!   objective count a literal more than once; the optimizer settles them by branch and bound.
//!
//! Under [`Counting::Reference`] every leaf is single: a repeated literal counts each time.

use crate::bottom_up::node_values;
use crate::ground::{GroundGoal, Lit, Node, NodeId};
use crate::optimize::Counting;

/// How a leaf counts when options are sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Leaf {
    /// The only leaf of its literal in any option that holds it: counted where it stands.
    Single,
    /// Always accompanied by an earlier leaf of the same literal: counts nothing.
    Twin,
    /// One of several leaves of a literal that can meet in one option.
    Shared {
        /// Index into [`Sharing::literals`].
        literal: usize,
        /// Index of this leaf among all shared leaves (see [`Sharing::occurrences`]).
        occurrence: usize,
    },
}

/// A literal with several leaves that one option can hold together.
#[derive(Clone, Debug)]
pub(crate) struct SharedLiteral {
    /// Its leaves other than twins, in node order.
    pub leaves: Vec<NodeId>,
    /// The most of these leaves one option can hold (consistency aside), at least 2: the
    /// optimizer charges each leaf `1/most` of a cost, so that any option holding the literal is
    /// charged at most its full cost.
    pub most: i64,
}

/// The kinds of every leaf of one goal under one counting.
#[derive(Clone, Debug, Default)]
pub(crate) struct Sharing {
    /// By node; empty when every leaf is single (the common case, kept allocation-free).
    leaf: Vec<Leaf>,
    /// The literals with shared leaves.
    pub literals: Vec<SharedLiteral>,
    /// The number of shared leaves over all literals.
    pub occurrences: usize,
    /// Whether some literal has several leaves that are not twins (shared, or in exclusive
    /// branches): then two different ways through the tree may give the same set of literals.
    pub repeats: bool,
    /// Whether there is a twin: then a list of leaves may hold a literal twice.
    pub twins: bool,
}

impl Sharing {
    /// The kinds of every leaf of `goal`, given its [`leaf_counts`]; cheap when no literal has
    /// two leaves.
    pub fn new(goal: &GroundGoal, counting: Counting, counts: &[u32]) -> Sharing {
        if counting == Counting::Reference || counts.iter().all(|&c| c < 2) {
            return Sharing::default();
        }
        let repeated = repeated_literals(goal, counts);
        let tree = Tree::new(goal);
        let mut sharing = Sharing {
            leaf: vec![Leaf::Single; goal.nodes.len()],
            ..Sharing::default()
        };
        for leaves in repeated {
            sharing.classify(goal, &tree, leaves);
        }
        sharing
    }

    /// The kind of a leaf (any node id; non-leaves read as single).
    pub fn leaf(&self, id: NodeId) -> Leaf {
        self.leaf
            .get(id.0 as usize)
            .copied()
            .unwrap_or(Leaf::Single)
    }

    /// Sorts the leaves of one literal into twins, and singles or shared leaves.
    fn classify(&mut self, goal: &GroundGoal, tree: &Tree, leaves: Vec<NodeId>) {
        let mut kept: Vec<NodeId> = Vec::with_capacity(leaves.len());
        for id in leaves.into_iter().filter(|&id| tree.reachable(id)) {
            if kept.iter().any(|&k| tree.and_top(k) == tree.and_top(id)) {
                self.leaf[id.0 as usize] = Leaf::Twin;
                self.twins = true;
            } else {
                kept.push(id);
            }
        }
        if kept.len() < 2 {
            return;
        }
        self.repeats = true;
        let exclusive = kept
            .iter()
            .enumerate()
            .all(|(i, &a)| kept[i + 1..].iter().all(|&b| tree.exclusive(goal, a, b)));
        if exclusive {
            return;
        }
        let most = most_together(goal, &kept);
        if most < 2 {
            return; // never together after all (e.g. a pair quantifier's matching keeps them apart)
        }
        let literal = self.literals.len();
        for &id in &kept {
            self.leaf[id.0 as usize] = Leaf::Shared {
                literal,
                occurrence: self.occurrences,
            };
            self.occurrences += 1;
        }
        self.literals.push(SharedLiteral { leaves: kept, most });
    }
}

/// Where a literal's count is in [`leaf_counts`].
pub(crate) fn literal_key(lit: Lit) -> usize {
    lit.atom.0 as usize * 2 + usize::from(lit.positive)
}

/// How many leaves each literal has, by [`literal_key`].
pub(crate) fn leaf_counts(goal: &GroundGoal) -> Vec<u32> {
    let mut counts = vec![0u32; goal.atoms.len() * 2];
    for node in &goal.nodes {
        if let Node::Lit(lit) = node {
            counts[literal_key(*lit)] += 1;
        }
    }
    counts
}

/// The leaves of each literal that has more than one, in node order.
fn repeated_literals(goal: &GroundGoal, count: &[u32]) -> Vec<Vec<NodeId>> {
    let key = literal_key;
    let mut group = vec![usize::MAX; count.len()];
    let mut groups: Vec<Vec<NodeId>> = Vec::new();
    for (i, node) in goal.nodes.iter().enumerate() {
        if let Node::Lit(lit) = node
            && count[key(*lit)] > 1
        {
            let g = &mut group[key(*lit)];
            if *g == usize::MAX {
                *g = groups.len();
                groups.push(Vec::new());
            }
            groups[*g].push(NodeId(i as u32));
        }
    }
    groups
}

/// The most of `leaves` that one option holds, consistency aside: a bottom-up pass counting 1
/// per such leaf and 0 per other leaf. A goal without options reads as all of them.
fn most_together(goal: &GroundGoal, leaves: &[NodeId]) -> i64 {
    let mut values = vec![None; goal.nodes.len()];
    node_values(
        goal,
        |id, _| Some(i64::from(leaves.contains(&id))),
        &mut values,
    );
    values[goal.root.0 as usize].unwrap_or(leaves.len() as i64)
}

/// The shape of the reachable tree: parents, depths, and the conjunction each node hangs from.
struct Tree {
    parent: Vec<u32>,
    depth: Vec<u32>,
    /// The highest ancestor reached from the node through conjunctions only (itself if its
    /// parent is not a conjunction).
    and_top: Vec<u32>,
}

const UNREACHED: u32 = u32::MAX;

impl Tree {
    /// Walks down from the root. Grounding leaves unreachable nodes behind (conjunctions merged
    /// into their parents), so parents are read from the walk, not from every node.
    fn new(goal: &GroundGoal) -> Tree {
        let n = goal.nodes.len();
        let root = goal.root.0;
        let mut tree = Tree {
            parent: vec![UNREACHED; n],
            depth: vec![0; n],
            and_top: vec![UNREACHED; n],
        };
        tree.and_top[root as usize] = root;
        let mut stack = vec![root];
        while let Some(id) = stack.pop() {
            let node = goal.node(NodeId(id));
            for &child in children(node) {
                let c = child.0 as usize;
                tree.parent[c] = id;
                tree.depth[c] = tree.depth[id as usize] + 1;
                tree.and_top[c] = if matches!(node, Node::And(_)) {
                    tree.and_top[id as usize]
                } else {
                    child.0
                };
                stack.push(child.0);
            }
        }
        tree
    }

    fn reachable(&self, id: NodeId) -> bool {
        self.and_top[id.0 as usize] != UNREACHED
    }

    fn and_top(&self, id: NodeId) -> u32 {
        self.and_top[id.0 as usize]
    }

    /// Whether no option can hold both leaves: their lowest common ancestor picks one branch
    /// (`or`, `forn` of at most 1, a pair quantifier of at most one pair, or two cells of one
    /// row or column of a pair quantifier, which a matching never pairs both).
    fn exclusive(&self, goal: &GroundGoal, a: NodeId, b: NodeId) -> bool {
        let (mut x, mut y) = (a.0, b.0);
        let (mut below_x, mut below_y) = (x, y);
        while self.depth[x as usize] > self.depth[y as usize] {
            (below_x, x) = (x, self.parent[x as usize]);
        }
        while self.depth[y as usize] > self.depth[x as usize] {
            (below_y, y) = (y, self.parent[y as usize]);
        }
        while x != y {
            (below_x, x) = (x, self.parent[x as usize]);
            (below_y, y) = (y, self.parent[y as usize]);
        }
        match goal.node(NodeId(x)) {
            Node::Or(_) => true,
            Node::AtLeast { n, .. } => *n <= 1,
            Node::Pairs { n, cols, cells, .. } => {
                let at = |id: u32| cells.iter().position(|c| c.0 == id);
                let (Some(i), Some(j)) = (at(below_x), at(below_y)) else {
                    return false;
                };
                *n <= 1 || i / cols == j / cols || i % cols == j % cols
            }
            _ => false,
        }
    }
}

/// The children of a node, in order.
fn children(node: &Node) -> &[NodeId] {
    match node {
        Node::Lit(_) => &[],
        Node::And(c) | Node::Or(c) => c,
        Node::AtLeast { children, .. } => children,
        Node::Pairs { cells, .. } | Node::NoPairs { cells, .. } => cells,
    }
}
