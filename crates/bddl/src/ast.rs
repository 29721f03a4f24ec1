//! The syntax tree of domain and problem files, as written, with spans.
//!
//! Names are lower-cased and unresolved here: whether `?apple.n.01` is a variable or an instance,
//! and whether a predicate exists, is decided by the checker ([`crate::activity`]).

use crate::diagnostics::Span;

/// A word of the source, lower-cased.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Name {
    /// The word, lower-cased, with any leading `?` kept (see [`Name::bare`]).
    pub text: String,
    /// Where it is written, in its original spelling.
    pub span: Span,
}

impl Name {
    /// The name without a leading `?` (BDDL writes both variables and goal instances with it).
    pub fn bare(&self) -> &str {
        self.text.strip_prefix('?').unwrap_or(&self.text)
    }
}

/// A domain file: `(define (domain igibson) (:requirements …) (:predicates …))`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DomainFile {
    /// The domain's name, which problems give in `:domain`.
    pub name: Name,
    /// The `:requirements` flags, e.g. `:strips`: PDDL leftovers that BDDL 1.0 ignores, checked
    /// only against the list the reference accepts ([`crate::domain::REQUIREMENTS`]).
    pub requirements: Vec<Name>,
    /// The `:predicates` declarations, in file order.
    pub predicates: Vec<PredicateDecl>,
}

/// One `(ontop ?obj1 ?obj2)` of a domain's `:predicates`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PredicateDecl {
    /// The predicate; one outside the vocabulary is only a warning.
    pub name: Name,
    /// The parameter variables, PDDL `- type` annotations dropped; only their number matters (it
    /// must equal the predicate's arity).
    pub params: Vec<Name>,
    /// The whole declaration, parentheses included.
    pub span: Span,
}

/// A problem file (one activity definition):
/// `(define (problem name) (:domain d) (:objects …) (:init …) (:goal …))`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProblemFile {
    /// The problem's name, e.g. `packing_lunches_0`.
    pub name: Name,
    /// The domain it is for (`igibson` in the official files).
    pub domain: Name,
    /// The `:objects` runs, in file order.
    pub objects: Vec<ObjectGroup>,
    /// The `:init` entries as parsed; the checker requires each to be a literal.
    pub init: Vec<Formula>,
    /// The `:goal` formula; the conjuncts of an outermost `and` become the activity's top-level
    /// conditions.
    pub goal: Formula,
    /// The span of the whole `(define ...)`.
    pub span: Span,
}

/// One `inst1 inst2 - category` run of an `:objects` section.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjectGroup {
    /// The instance names before the `-`, e.g. `apple.n.01_1 apple.n.01_2`.
    pub instances: Vec<Name>,
    /// The synset after the `-`, e.g. `apple.n.01`.
    pub category: Name,
}

/// A formula of `:init` or `:goal`, as written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Formula {
    /// Which construct, with its operands.
    pub kind: FormulaKind,
    /// The whole parenthesised formula.
    pub span: Span,
}

/// The constructs of a BDDL formula. Operands are names, not yet resolved.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FormulaKind {
    /// `(predicate arg…)`, e.g. `(ontop ?apple.n.01 ?table.n.02_1)`.
    Atom {
        /// The predicate as written; it may be unknown or have the wrong arity.
        predicate: Name,
        /// The arguments as written: variables or instances, which the checker tells apart.
        args: Vec<Name>,
    },
    /// `(not f)`.
    Not(Box<Formula>),
    /// `(and f…)`, possibly empty (then true).
    And(Vec<Formula>),
    /// `(or f…)`, possibly empty (then false).
    Or(Vec<Formula>),
    /// `(imply a b)`.
    Imply(Box<Formula>, Box<Formula>),
    /// `(iff a b)`. Accepted though no official activity uses it.
    Iff(Box<Formula>, Box<Formula>),
    /// `(forall (?x - c) body)`: the body holds for every instance of `c`.
    Forall(Decl, Box<Formula>),
    /// `(exists (?x - c) body)`: the body holds for some instance of `c`.
    Exists(Decl, Box<Formula>),
    /// `(forn (N) (?x - c) body)`: at least N instances of `c` satisfy the body.
    ForN(Count, Decl, Box<Formula>),
    /// `(forpairs (?x - a) (?y - b) body)`: a one-to-one pairing covering the smaller category.
    ForPairs(Decl, Decl, Box<Formula>),
    /// `(fornpairs (N) (?x - a) (?y - b) body)`: at least N disjoint pairs satisfy the body.
    ForNPairs(Count, Decl, Decl, Box<Formula>),
}

/// A quantifier's `(?var - category)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Decl {
    /// The variable, normally with its `?` (the checker warns without); BDDL habitually names it
    /// after the category, as in `?apple.n.01`.
    pub var: Name,
    /// The category it ranges over, which must be declared in `:objects`.
    pub category: Name,
    /// The whole `(?var - category)`.
    pub span: Span,
}

/// A quantifier's `(N)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Count {
    /// N: a whole number, 0 allowed; one larger than can be met is only a warning.
    pub value: u32,
    /// The whole `(N)`, parentheses included.
    pub span: Span,
}
