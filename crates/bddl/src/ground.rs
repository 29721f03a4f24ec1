//! Grounding: a goal becomes a tree over ground literals in negation normal form, ready for fast
//! truth evaluation and for the option computations.
//!
//! Negation is pushed to the atoms: De Morgan for `and`/`or`, duality for `forall`/`exists`,
//! `not (forn N)` over k instances is `forn (k−N+1)` of the negated body, and a negated pair
//! quantifier ("no N disjoint pairs satisfy the body") becomes, by König's theorem, "some N−1 rows
//! and columns cover every pair that satisfies it". The tree's disjunctive normal form is the
//! goal's set of *options*.

use crate::activity::{Activity, Atom, Goal, InstanceId, Literal, Term};
use crate::eval::PredicateOracle;
use crate::matching;
use std::collections::HashMap;

/// Index of a node in a [`GroundGoal`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NodeId(pub u32);

/// Index of a distinct atom of a [`GroundGoal`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct AtomId(pub u32);

/// A literal as the option computations see it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Lit {
    /// The atom, an index into [`GroundGoal::atoms`].
    pub atom: AtomId,
    /// `false` for the atom's negation.
    pub positive: bool,
}

/// A node of a ground goal. The tree is in negation normal form: negation appears only in
/// literals, so every node's options are built from its children's without complementing them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Node {
    /// True when its atom's truth equals its polarity. Repeated occurrences of one atom are
    /// separate nodes sharing an [`AtomId`].
    Lit(Lit),
    /// True when all children are; `And([])` is true.
    And(Vec<NodeId>),
    /// True when some child is; `Or([])` is false.
    Or(Vec<NodeId>),
    /// True when at least `n` children are.
    AtLeast {
        /// How many children must hold; 0 makes the node true, more than there are children false.
        n: usize,
        /// One per instance of the quantified category, in declaration order.
        children: Vec<NodeId>,
    },
    /// True when `n` disjoint (row, column) pairs have true cells. Cells are row-major.
    Pairs {
        /// How many disjoint pairs must hold: the smaller of `rows` and `cols` for `forpairs`,
        /// N for `fornpairs`.
        n: usize,
        /// The number of instances of the first (outer) category.
        rows: usize,
        /// The number of instances of the second category.
        cols: usize,
        /// `rows × cols` nodes: cell `(r, c)`, at `r * cols + c`, is the body with the r-th row
        /// instance and the c-th column instance bound.
        cells: Vec<NodeId>,
    },
    /// True when *no* `n` disjoint pairs have false cells: the cells hold the negated bodies of a
    /// `Pairs`, so this is its negation. Its options: each way to cover `n − 1` rows and columns,
    /// with every uncovered cell true.
    NoPairs {
        /// The `n` of the negated `Pairs`: the node is true when fewer than `n` disjoint pairs
        /// satisfy the body.
        n: usize,
        /// The number of instances of the first (outer) category.
        rows: usize,
        /// The number of instances of the second category.
        cols: usize,
        /// `rows × cols` nodes, row-major as in `Pairs`, each the *negated* body.
        cells: Vec<NodeId>,
    },
}

/// A goal ground over one activity's instances. Children always precede their parents.
#[derive(Clone, Debug)]
pub struct GroundGoal {
    /// Every node, indexed by [`NodeId`], each child before its parents, so one forward pass
    /// can evaluate the whole tree bottom-up.
    pub nodes: Vec<Node>,
    /// Every distinct atom the goal mentions, indexed by [`AtomId`], each once, in order of first
    /// occurrence.
    pub atoms: Vec<Atom>,
    /// One root per top-level conjunct of the goal.
    pub conjuncts: Vec<NodeId>,
    /// The conjunction of `conjuncts`.
    pub root: NodeId,
}

impl GroundGoal {
    /// Grounds an activity's goal over its declared instances, one root per conjunct, pushing
    /// negations to the atoms. Nested quantifiers multiply its size; the checker rejects goals that
    /// would exceed [`crate::activity::MAX_GROUND_NODES`] nodes, but an activity built by hand is
    /// not bounded.
    pub fn new(activity: &Activity) -> GroundGoal {
        let mut builder = Builder {
            activity,
            nodes: Vec::new(),
            atoms: Vec::new(),
            atom_ids: HashMap::new(),
            env: Vec::new(),
        };
        let conjuncts: Vec<NodeId> = activity
            .goal
            .iter()
            .map(|c| builder.ground(&c.goal, true))
            .collect();
        let root = builder.push(Node::And(conjuncts.clone()));
        GroundGoal {
            nodes: builder.nodes,
            atoms: builder.atoms,
            conjuncts,
            root,
        }
    }

    /// The node with that id. Panics on an id from another goal that is out of range.
    pub fn node(&self, id: NodeId) -> &Node {
        &self.nodes[id.0 as usize]
    }

    /// The atom, over instances, that an id stands for.
    pub fn atom(&self, id: AtomId) -> Atom {
        self.atoms[id.0 as usize]
    }

    /// The literal over instances that a [`Lit`] stands for, e.g. for display with
    /// [`Activity::show_literal`].
    pub fn literal(&self, lit: Lit) -> Literal {
        Literal {
            atom: self.atom(lit.atom),
            positive: lit.positive,
        }
    }

    /// The same goal with some atoms known to be false in any world (an object on top of itself):
    /// its options then never ask for them. Truth is unchanged wherever those atoms are false.
    pub fn assuming_false(&self, impossible: impl Fn(Atom) -> bool) -> GroundGoal {
        let mut goal = self.clone();
        for node in &mut goal.nodes {
            if let Node::Lit(lit) = *node
                && impossible(self.atom(lit.atom))
            {
                *node = if lit.positive {
                    Node::Or(Vec::new())
                } else {
                    Node::And(Vec::new())
                };
            }
        }
        goal
    }

    /// Whether the whole goal holds.
    pub fn holds(&self, oracle: &impl PredicateOracle) -> bool {
        self.node_holds(self.root, &|a| oracle.holds(self.atom(a)))
    }

    /// Whether each top-level conjunct holds, in order (evaluated as the iterator advances).
    pub fn conjuncts_hold<'a>(
        &'a self,
        oracle: &'a impl PredicateOracle,
    ) -> impl Iterator<Item = bool> + 'a {
        self.conjuncts
            .iter()
            .map(move |&c| self.node_holds(c, &|a| oracle.holds(self.atom(a))))
    }

    /// The truth of every atom, by [`AtomId`].
    pub fn atom_truth(&self, oracle: &impl PredicateOracle) -> Vec<bool> {
        self.atoms.iter().map(|&a| oracle.holds(a)).collect()
    }

    /// Truth of a node given atom truths; children are evaluated lazily.
    pub fn node_holds(&self, id: NodeId, truth: &impl Fn(AtomId) -> bool) -> bool {
        match self.node(id) {
            Node::Lit(lit) => truth(lit.atom) == lit.positive,
            Node::And(children) => children.iter().all(|&c| self.node_holds(c, truth)),
            Node::Or(children) => children.iter().any(|&c| self.node_holds(c, truth)),
            Node::AtLeast { n, children } => {
                let mut remaining = children.len();
                let mut count = 0;
                for &c in children {
                    if count >= *n || count + remaining < *n {
                        break;
                    }
                    remaining -= 1;
                    count += usize::from(self.node_holds(c, truth));
                }
                count >= *n
            }
            Node::Pairs {
                n,
                rows,
                cols,
                cells,
            } => {
                let hold: Vec<bool> = cells.iter().map(|&c| self.node_holds(c, truth)).collect();
                matching::max_matching(*rows, *cols, |i, j| hold[i * cols + j]) >= *n
            }
            Node::NoPairs {
                n,
                rows,
                cols,
                cells,
            } => {
                // A cell's body holds when its negation (what the cell stores) does not.
                let body: Vec<bool> = cells.iter().map(|&c| !self.node_holds(c, truth)).collect();
                matching::max_matching(*rows, *cols, |i, j| body[i * cols + j]) < *n
            }
        }
    }
}

struct Builder<'a> {
    activity: &'a Activity,
    nodes: Vec<Node>,
    atoms: Vec<Atom>,
    atom_ids: HashMap<Atom, AtomId>,
    /// Instances bound to the quantified variables in scope, outermost first.
    env: Vec<InstanceId>,
}

impl Builder<'_> {
    fn push(&mut self, node: Node) -> NodeId {
        self.nodes.push(node);
        NodeId(self.nodes.len() as u32 - 1)
    }

    fn resolve(&self, term: Term) -> InstanceId {
        match term {
            Term::Instance(id) => id,
            Term::Var(depth) => self.env[depth as usize],
        }
    }

    /// A conjunction (`all`) or disjunction of children, flattening nested ones of the same kind
    /// and collapsing a single child; neither changes the options.
    fn junction(&mut self, all: bool, children: Vec<NodeId>) -> NodeId {
        let mut flat = Vec::with_capacity(children.len());
        for c in children {
            match &self.nodes[c.0 as usize] {
                Node::And(grand) if all => flat.extend_from_slice(grand),
                Node::Or(grand) if !all => flat.extend_from_slice(grand),
                _ => flat.push(c),
            }
        }
        if flat.len() == 1 {
            return flat[0];
        }
        self.push(if all { Node::And(flat) } else { Node::Or(flat) })
    }

    fn each(
        &mut self,
        category: crate::activity::CategoryId,
        body: &Goal,
        positive: bool,
    ) -> Vec<NodeId> {
        let instances = self.activity.category(category).instances.clone();
        instances
            .into_iter()
            .map(|instance| {
                self.env.push(instance);
                let node = self.ground(body, positive);
                self.env.pop();
                node
            })
            .collect()
    }

    /// Grounds `goal` (or its negation when `positive` is false) in negation normal form.
    fn ground(&mut self, goal: &Goal, positive: bool) -> NodeId {
        match goal {
            Goal::Atom { predicate, args } => {
                let atom = Atom {
                    predicate: *predicate,
                    subject: self.resolve(args[0]),
                    object: args.get(1).map(|&t| self.resolve(t)),
                };
                let next = AtomId(self.atoms.len() as u32);
                let id = *self.atom_ids.entry(atom).or_insert(next);
                if id == next {
                    self.atoms.push(atom);
                }
                self.push(Node::Lit(Lit { atom: id, positive }))
            }
            Goal::Not(inner) => self.ground(inner, !positive),
            Goal::And(parts) | Goal::Or(parts) => {
                let children = parts.iter().map(|p| self.ground(p, positive)).collect();
                let conjunction = matches!(goal, Goal::And(_)) == positive;
                self.junction(conjunction, children)
            }
            Goal::Imply(a, c) => {
                // a → c  ≡  ¬a ∨ c;  ¬(a → c)  ≡  a ∧ ¬c
                let a = self.ground(a, !positive);
                let c = self.ground(c, positive);
                self.junction(!positive, vec![a, c])
            }
            Goal::Iff(a, b) => {
                // a ↔ b ≡ (a ∧ b) ∨ (¬a ∧ ¬b);  ¬(a ↔ b) ≡ (a ∧ ¬b) ∨ (¬a ∧ b)
                let a_pos = self.ground(a, true);
                let b_same = self.ground(b, positive);
                let both = self.junction(true, vec![a_pos, b_same]);
                let a_neg = self.ground(a, false);
                let b_other = self.ground(b, !positive);
                let neither = self.junction(true, vec![a_neg, b_other]);
                self.junction(false, vec![both, neither])
            }
            Goal::Forall(c, body) | Goal::Exists(c, body) => {
                let children = self.each(*c, body, positive);
                let conjunction = matches!(goal, Goal::Forall(..)) == positive;
                self.junction(conjunction, children)
            }
            Goal::ForN(n, c, body) => {
                let children = self.each(*c, body, positive);
                let n = *n as usize;
                // not (at least n of k)  ≡  at least k − n + 1 of the negations
                let n = if positive {
                    n
                } else {
                    (children.len() + 1).saturating_sub(n)
                };
                self.push(Node::AtLeast { n, children })
            }
            Goal::ForPairs(a, b, body) => {
                let n = self
                    .activity
                    .category(*a)
                    .instances
                    .len()
                    .min(self.activity.category(*b).instances.len());
                self.pairs(n, *a, *b, body, positive)
            }
            Goal::ForNPairs(n, a, b, body) => self.pairs(*n as usize, *a, *b, body, positive),
        }
    }

    fn pairs(
        &mut self,
        n: usize,
        a: crate::activity::CategoryId,
        b: crate::activity::CategoryId,
        body: &Goal,
        positive: bool,
    ) -> NodeId {
        let rows = self.activity.category(a).instances.clone();
        let cols = self.activity.category(b).instances.clone();
        let mut cells = Vec::with_capacity(rows.len() * cols.len());
        for &row in &rows {
            for &col in &cols {
                self.env.push(row);
                self.env.push(col);
                cells.push(self.ground(body, positive));
                self.env.truncate(self.env.len() - 2);
            }
        }
        let (rows, cols) = (rows.len(), cols.len());
        self.push(if positive {
            Node::Pairs {
                n,
                rows,
                cols,
                cells,
            }
        } else {
            Node::NoPairs {
                n,
                rows,
                cols,
                cells,
            }
        })
    }
}
