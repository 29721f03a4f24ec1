//! The syntax tree of domain and problem files, as written, with spans.
//!
//! Names are lower-cased and unresolved here: whether `?apple.n.01` is a variable or an instance,
//! and whether a predicate exists, is decided by the checker ([`crate::activity`]).

use crate::diagnostics::Span;

/// A word of the source, lower-cased.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Name {
    pub text: String,
    pub span: Span,
}

impl Name {
    /// The name without a leading `?` (BDDL writes both variables and goal instances with it).
    pub fn bare(&self) -> &str {
        self.text.strip_prefix('?').unwrap_or(&self.text)
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DomainFile {
    pub name: Name,
    pub requirements: Vec<Name>,
    pub predicates: Vec<PredicateDecl>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PredicateDecl {
    pub name: Name,
    pub params: Vec<Name>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProblemFile {
    pub name: Name,
    pub domain: Name,
    pub objects: Vec<ObjectGroup>,
    pub init: Vec<Formula>,
    pub goal: Formula,
    /// The span of the whole `(define ...)`.
    pub span: Span,
}

/// One `inst1 inst2 - category` run of an `:objects` section.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjectGroup {
    pub instances: Vec<Name>,
    pub category: Name,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Formula {
    pub kind: FormulaKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FormulaKind {
    Atom {
        predicate: Name,
        args: Vec<Name>,
    },
    Not(Box<Formula>),
    And(Vec<Formula>),
    Or(Vec<Formula>),
    Imply(Box<Formula>, Box<Formula>),
    /// Accepted though no official activity uses it.
    Iff(Box<Formula>, Box<Formula>),
    Forall(Decl, Box<Formula>),
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
    pub var: Name,
    pub category: Name,
    pub span: Span,
}

/// A quantifier's `(N)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Count {
    pub value: u32,
    pub span: Span,
}
