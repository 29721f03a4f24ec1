//! The checker: a problem's syntax tree becomes an [`Activity`] whose names are all resolved —
//! instances and categories to ids, predicates to the vocabulary, variables to their binders — or a
//! list of located diagnostics saying what is wrong.

use crate::ast::{self, FormulaKind, Name, ProblemFile};
use crate::diagnostics::{Diagnostic, Diagnostics, Source, SourceErrors, Span};
use crate::parser;
use crate::predicate::Predicate;
use crate::taxonomy::{SynsetId, Taxonomy, is_synset_name};
use behavior_core::RoomType;
pub use behavior_core::{Atom, InstanceId};
use std::collections::HashMap;
use std::fmt;

/// Goals that ground to more nodes than this are rejected: they would exhaust memory or time, and
/// no household activity comes near (the largest official goal, `packing_picnics`, grounds to 112).
pub const MAX_GROUND_NODES: u64 = 5_000_000;

/// Index of a declared category (`apple.n.01`) in its activity, in `:objects` order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct CategoryId(pub u32);

/// An object declared in `:objects` (`apple.n.01_1`), indexed by [`InstanceId`] in declaration
/// order. A simulator binds each to one of its objects.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Instance {
    /// The name as declared, lower-cased; in an activity that passed the checker it is
    /// `<category>_<n>` with n ≥ 1, e.g. `apple.n.01_1`.
    pub name: String,
    /// The category it was declared under, whose name prefixes its own.
    pub category: CategoryId,
}

/// A category of `:objects` (the `apple.n.01` after the `-`): the domain that quantifiers over it
/// range over.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Category {
    /// The synset name as written, lower-cased, e.g. `apple.n.01`.
    pub name: String,
    /// `None` when checked without a taxonomy.
    pub synset: Option<SynsetId>,
    /// The instances declared under this category, in declaration order, from every line that
    /// declares it. Quantifiers range over exactly these: instances of a more specific synset,
    /// declared under their own category, are not included.
    pub instances: Vec<InstanceId>,
}

/// A ground atom or its negation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Literal {
    /// The atom asserted (or denied), over instance ids.
    pub atom: Atom,
    /// `false` for `(not atom)`.
    pub positive: bool,
}

/// A literal of `:init`. `inroom` names a room type, not an instance, so it has its own case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InitLiteral {
    /// `(ontop apple.n.01_1 table.n.02_1)` or `(not (open fridge.n.01_1))`: a fact about the
    /// initial state. The positive ones make up [`Activity::initial_facts`].
    Atom(Literal),
    /// `(inroom table.n.02_1 kitchen)`: the instance is one of the home's own objects in a room of
    /// that type, which sampling binds it to rather than placing it. Room membership is fixed by the
    /// scene, so this is never a state fact nor part of a goal.
    InRoom {
        /// The instance to bind: a piece of furniture or a floor.
        instance: InstanceId,
        /// The room type; one of the eleven that homes have, since any other name is a checker
        /// error (no home has such a room, so no instance of the activity could be sampled).
        room: RoomType,
        /// `false` for `(not (inroom …))`, which no official activity writes.
        positive: bool,
    },
}

/// An argument of a goal atom.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Term {
    /// A declared instance named directly; goals usually write it with a `?`, as in
    /// `?table.n.02_1`.
    Instance(InstanceId),
    /// A quantified variable: the index of its binder, counted from the outermost (0) inward.
    Var(u32),
}

/// A resolved goal formula; quantifiers range over the instances of a declared category.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Goal {
    /// `(ontop ?apple.n.01 ?table.n.02_1)`: a predicate applied to terms.
    Atom {
        /// Any predicate of the vocabulary except `inroom`, which may appear only in `:init`.
        predicate: Predicate,
        /// As many terms as the predicate's arity: the subject, then the object of a binary one.
        args: Vec<Term>,
    },
    /// `(not g)`.
    Not(Box<Goal>),
    /// `(and g…)`: every part holds; `(and)` is true.
    And(Vec<Goal>),
    /// `(or g…)`: some part holds; `(or)` is false.
    Or(Vec<Goal>),
    /// `(imply a b)`: `b` holds wherever `a` does, i.e. `(or (not a) b)`.
    Imply(Box<Goal>, Box<Goal>),
    /// `(iff a b)`: both hold or neither. Accepted though no official activity uses it.
    Iff(Box<Goal>, Box<Goal>),
    /// `(forall (?x - c) body)`: the body holds for every instance of `c`; true when `c` has none.
    Forall(CategoryId, Box<Goal>),
    /// `(exists (?x - c) body)`: the body holds for some instance of `c`.
    Exists(CategoryId, Box<Goal>),
    /// `(forn (N) (?x - c) body)`: at least N instances of `c` satisfy the body (the reference
    /// implementation requires exactly N).
    ForN(u32, CategoryId, Box<Goal>),
    /// `(forpairs (?x - a) (?y - b) body)`: a one-to-one pairing of the instances of `a` with those
    /// of `b`, with the body true on each pair, covers every instance of the smaller category (a
    /// maximum bipartite matching). The first category binds the outer variable; with `a = b`, the
    /// pair `(x, x)` is allowed.
    ForPairs(CategoryId, CategoryId, Box<Goal>),
    /// `(fornpairs (N) (?x - a) (?y - b) body)`: at least N *disjoint* pairs (no instance in two of
    /// them) satisfy the body.
    ForNPairs(u32, CategoryId, CategoryId, Box<Goal>),
}

/// One top-level condition of the goal (a conjunct of its outermost `and`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Conjunct {
    /// The resolved condition.
    pub goal: Goal,
    /// Where it is written in the problem source, so reports can quote it.
    pub span: Span,
}

/// A checked problem: every name resolved, ready to ground and evaluate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Activity {
    /// The problem name, e.g. `packing_lunches_0`.
    pub name: String,
    /// The domain named by `:domain` (`igibson` for the official activities); compared with the
    /// domain file's name only when checked against one.
    pub domain: String,
    /// Every declared instance, indexed by [`InstanceId`], in `:objects` order.
    pub instances: Vec<Instance>,
    /// Every declared category, indexed by [`CategoryId`], in order of first declaration.
    pub categories: Vec<Category>,
    /// The `:init` literals in file order, `inroom` included.
    pub init: Vec<InitLiteral>,
    /// The goal is the conjunction of these.
    pub goal: Vec<Conjunct>,
}

/// What the checker may consult. Without a taxonomy, synsets and abilities go unchecked; without a
/// domain, the problem's `:domain` is not compared.
#[derive(Clone, Copy, Default)]
pub struct CheckContext<'a> {
    /// The synsets that categories must name, with the abilities that state predicates need (a
    /// missing ability is a warning). Without it only the `lemma.n.NN` shape of category names is
    /// checked.
    pub taxonomy: Option<&'a Taxonomy>,
    /// The domain file whose name the problem's `:domain` must equal.
    pub domain: Option<&'a ast::DomainFile>,
}

impl Activity {
    /// Parses and checks a problem's source. Warnings come back with the activity; errors (with
    /// the source, for rendering) instead of it.
    pub fn load(
        source: &Source,
        context: CheckContext,
    ) -> Result<(Activity, Diagnostics), SourceErrors> {
        let fail = |diagnostics| SourceErrors {
            source: source.clone(),
            diagnostics,
        };
        let problem = parser::parse_problem(&source.text).map_err(fail)?;
        let (activity, diagnostics) = check(&problem, context);
        match activity {
            Some(activity) if !diagnostics.has_errors() => Ok((activity, diagnostics)),
            _ => Err(fail(diagnostics)),
        }
    }

    /// The instance with that id. Panics on an id that is not of this activity.
    pub fn instance(&self, id: InstanceId) -> &Instance {
        &self.instances[id.0 as usize]
    }

    /// The category with that id. Panics on an id that is not of this activity.
    pub fn category(&self, id: CategoryId) -> &Category {
        &self.categories[id.0 as usize]
    }

    /// The instance declared as `name`, which must be lower-case and without `?`
    /// (`apple.n.01_1`). A linear search: for reading states and command lines, not inner loops.
    pub fn instance_named(&self, name: &str) -> Option<InstanceId> {
        self.instances
            .iter()
            .position(|i| i.name == name)
            .map(|i| InstanceId(i as u32))
    }

    /// The goal as one formula.
    pub fn goal_formula(&self) -> Goal {
        Goal::And(self.goal.iter().map(|c| c.goal.clone()).collect())
    }

    /// Displays an atom with instance names, e.g. `(ontop apple.n.01_1 table.n.02_1)`.
    pub fn show_atom(&self, atom: Atom) -> impl fmt::Display + '_ {
        ShowAtom(self, atom)
    }

    /// Displays a literal with instance names, e.g. `(not (open fridge.n.01_1))`.
    pub fn show_literal(&self, literal: Literal) -> String {
        if literal.positive {
            self.show_atom(literal.atom).to_string()
        } else {
            format!("(not {})", self.show_atom(literal.atom))
        }
    }

    /// The facts that hold at the start: the positive literals of `:init`, without `inroom`.
    pub fn initial_facts(&self) -> Vec<Atom> {
        self.init
            .iter()
            .filter_map(|l| match l {
                InitLiteral::Atom(l) if l.positive => Some(l.atom),
                _ => None,
            })
            .collect()
    }
}

struct ShowAtom<'a>(&'a Activity, Atom);

impl fmt::Display for ShowAtom<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ShowAtom(activity, atom) = self;
        write!(
            f,
            "({} {}",
            atom.predicate,
            activity.instance(atom.subject).name
        )?;
        if let Some(object) = atom.object {
            write!(f, " {}", activity.instance(object).name)?;
        }
        f.write_str(")")
    }
}

/// Checks a parsed problem. Returns the activity when it could be built (possibly with errors
/// still to report) and every diagnostic found.
pub fn check(problem: &ProblemFile, context: CheckContext) -> (Option<Activity>, Diagnostics) {
    let mut checker = Checker {
        context,
        diagnostics: Diagnostics::default(),
        instances: Vec::new(),
        categories: Vec::new(),
        instance_ids: HashMap::new(),
        category_ids: HashMap::new(),
        scope: Vec::new(),
    };
    if let Some(domain) = context.domain
        && domain.name.text != problem.domain.text
    {
        checker.diagnostics.push(
            Diagnostic::error(
                problem.domain.span,
                format!(
                    "problem is for domain `{}` but the domain file defines `{}`",
                    problem.domain.text, domain.name.text
                ),
            )
            .with_label("domain name"),
        );
    }
    for group in &problem.objects {
        checker.object_group(group);
    }
    let init = problem
        .init
        .iter()
        .filter_map(|f| checker.init_literal(f))
        .collect();
    let conjuncts: Vec<&ast::Formula> = match &problem.goal.kind {
        FormulaKind::And(parts) => parts.iter().collect(),
        _ => vec![&problem.goal],
    };
    let goal: Vec<Option<Conjunct>> = conjuncts
        .into_iter()
        .map(|f| checker.goal(f).map(|goal| Conjunct { goal, span: f.span }))
        .collect();
    let goal: Option<Vec<Conjunct>> = goal.into_iter().collect();
    if let Some(goal) = &goal {
        let nodes = goal
            .iter()
            .map(|c| ground_cost(&c.goal, &checker.categories, true))
            .fold(1u64, u64::saturating_add);
        if nodes > MAX_GROUND_NODES {
            checker.diagnostics.push(
                Diagnostic::error(
                    problem.goal.span,
                    format!(
                        "the goal is too large to ground over these objects: about {nodes} formulas (limit {MAX_GROUND_NODES})"
                    ),
                )
                .with_label("nested quantifiers multiply")
                .with_note(
                    "a negated pair quantifier also counts the ways to cover N−1 of its rows and columns",
                )
                .with_note("split the goal or declare fewer instances"),
            );
        }
    }
    let activity = goal.map(|goal| Activity {
        name: problem.name.text.clone(),
        domain: problem.domain.text.clone(),
        instances: checker.instances,
        categories: checker.categories,
        init,
        goal,
    });
    (activity, checker.diagnostics)
}

/// How much grounding `goal` (or its negation, when `positive` is false) creates: its nodes, plus,
/// for a negated pair quantifier, the row-and-column covers its options range over. An upper
/// bound, saturating.
fn ground_cost(goal: &Goal, categories: &[Category], positive: bool) -> u64 {
    let count = |c: &CategoryId| categories[c.0 as usize].instances.len() as u64;
    let cost = |g: &Goal, positive: bool| ground_cost(g, categories, positive);
    1u64.saturating_add(match goal {
        Goal::Atom { .. } => 0,
        Goal::Not(g) => cost(g, !positive),
        Goal::And(gs) | Goal::Or(gs) => gs
            .iter()
            .map(|g| cost(g, positive))
            .fold(0, u64::saturating_add),
        Goal::Imply(a, b) => cost(a, !positive).saturating_add(cost(b, positive)),
        Goal::Iff(a, b) => [cost(a, true), cost(a, false), cost(b, true), cost(b, false)]
            .into_iter()
            .fold(0, u64::saturating_add),
        Goal::Forall(c, g) | Goal::Exists(c, g) | Goal::ForN(_, c, g) => {
            count(c).saturating_mul(cost(g, positive))
        }
        Goal::ForPairs(a, b, g) | Goal::ForNPairs(_, a, b, g) => {
            let (rows, cols) = (count(a), count(b));
            let n = match goal {
                Goal::ForNPairs(n, ..) => u64::from(*n),
                _ => rows.min(cols),
            };
            let cells = rows.saturating_mul(cols);
            let covers = if !positive && n >= 1 && n <= rows.min(cols) {
                binomial(rows + cols, n - 1).saturating_mul(cells)
            } else {
                0
            };
            cells
                .saturating_mul(cost(g, positive))
                .saturating_add(covers)
        }
    })
}

fn binomial(n: u64, k: u64) -> u64 {
    if k > n {
        return 0;
    }
    let mut result: u64 = 1;
    for i in 0..k.min(n - k) {
        // Exact at every step: the running product of i+1 consecutive numbers divides by (i+1)!.
        result = match result.checked_mul(n - i) {
            Some(r) => r / (i + 1),
            None => return u64::MAX,
        };
    }
    result
}

struct Checker<'a> {
    context: CheckContext<'a>,
    diagnostics: Diagnostics,
    instances: Vec<Instance>,
    categories: Vec<Category>,
    instance_ids: HashMap<String, InstanceId>,
    category_ids: HashMap<String, CategoryId>,
    /// Quantified variables in scope, outermost first: (label without `?`, category if valid).
    scope: Vec<(String, Option<CategoryId>)>,
}

impl Checker<'_> {
    fn error(&mut self, span: Span, message: String, label: &str) {
        self.diagnostics
            .push(Diagnostic::error(span, message).with_label(label));
    }

    fn object_group(&mut self, group: &ast::ObjectGroup) {
        let category = &group.category;
        let synset = self.synset(category);
        let id = match self.category_ids.get(&category.text) {
            Some(&id) => {
                self.diagnostics.push(
                    Diagnostic::warning(
                        category.span,
                        format!("category `{}` is declared on two lines", category.text),
                    )
                    .with_label("declared again here")
                    .with_note(
                        "both lines' instances are kept; the reference implementation keeps only the last line's",
                    ),
                );
                id
            }
            None => {
                let id = CategoryId(self.categories.len() as u32);
                self.categories.push(Category {
                    name: category.text.clone(),
                    synset,
                    instances: Vec::new(),
                });
                self.category_ids.insert(category.text.clone(), id);
                id
            }
        };
        for instance in &group.instances {
            let suffix = instance
                .text
                .strip_prefix(category.text.as_str())
                .and_then(|rest| rest.strip_prefix('_'));
            let numbered = suffix.is_some_and(|n| {
                !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) && !n.starts_with('0')
            });
            if !numbered {
                self.diagnostics.push(
                    Diagnostic::error(
                        instance.span,
                        format!(
                            "instance name `{}` does not match its declared category `{}`",
                            instance.text, category.text
                        ),
                    )
                    .with_label(format!("expected `{}_<n>` with n ≥ 1", category.text)),
                );
            }
            if self.instance_ids.contains_key(&instance.text) {
                self.error(
                    instance.span,
                    format!("instance `{}` is declared twice", instance.text),
                    "second declaration",
                );
                continue;
            }
            let iid = InstanceId(self.instances.len() as u32);
            self.instances.push(Instance {
                name: instance.text.clone(),
                category: id,
            });
            self.categories[id.0 as usize].instances.push(iid);
            self.instance_ids.insert(instance.text.clone(), iid);
        }
    }

    fn synset(&mut self, category: &Name) -> Option<SynsetId> {
        if !is_synset_name(&category.text) {
            self.error(
                category.span,
                format!("`{}` is not a synset name", category.text),
                "expected `lemma.n.NN`, e.g. `apple.n.01`",
            );
            return None;
        }
        let taxonomy = self.context.taxonomy?;
        let id = taxonomy.get(&category.text);
        if id.is_none() {
            self.error(
                category.span,
                format!("unknown synset `{}`", category.text),
                "not in the taxonomy",
            );
        }
        id
    }

    fn predicate(&mut self, name: &Name, arity: usize) -> Option<Predicate> {
        let Some(predicate) = Predicate::from_name(&name.text) else {
            let known: Vec<&str> = Predicate::ALL.iter().map(|p| p.name()).collect();
            self.diagnostics.push(
                Diagnostic::error(name.span, format!("unknown predicate `{}`", name.text))
                    .with_label("not a BDDL predicate")
                    .with_note(format!("known predicates: {}", known.join(", "))),
            );
            return None;
        };
        if predicate.arity() != arity {
            self.error(
                name.span,
                format!(
                    "`{}` takes {} argument{}, {} given",
                    predicate,
                    predicate.arity(),
                    if predicate.arity() == 1 { "" } else { "s" },
                    arity
                ),
                "wrong arity",
            );
            return None;
        }
        Some(predicate)
    }

    fn init_literal(&mut self, formula: &ast::Formula) -> Option<InitLiteral> {
        let (positive, atom) = match &formula.kind {
            FormulaKind::Not(inner) => (false, inner.as_ref()),
            _ => (true, formula),
        };
        let FormulaKind::Atom { predicate, args } = &atom.kind else {
            self.error(
                formula.span,
                "`:init` holds only literals".into(),
                "expected `(predicate args...)` or `(not (predicate args...))`",
            );
            return None;
        };
        let predicate = self.predicate(predicate, args.len())?;
        if predicate == Predicate::InRoom {
            let instance = self.instance(&args[0])?;
            // An unknown room type is an error: no home has such a room, so no instance of the
            // activity could ever be sampled.
            let room = match args[1].text.parse::<RoomType>() {
                Ok(room) => room,
                Err(unknown) => {
                    let names: Vec<&str> = RoomType::ALL.iter().map(|r| r.name()).collect();
                    self.diagnostics.push(
                        Diagnostic::error(
                            args[1].span,
                            format!("unknown room type `{}`", unknown.0),
                        )
                        .with_label("homes have no such room")
                        .with_note(format!("room types: {}", names.join(", "))),
                    );
                    return None;
                }
            };
            return Some(InitLiteral::InRoom {
                instance,
                room,
                positive,
            });
        }
        let ids: Vec<Option<InstanceId>> = args.iter().map(|a| self.instance(a)).collect();
        let ids: Vec<InstanceId> = ids.into_iter().collect::<Option<_>>()?;
        self.ability_warning(
            predicate,
            &args[0],
            Some(self.instances[ids[0].0 as usize].category),
        );
        let atom = Atom {
            predicate,
            subject: ids[0],
            object: ids.get(1).copied(),
        };
        Some(InitLiteral::Atom(Literal { atom, positive }))
    }

    /// Resolves a name that must be a declared instance (outside any quantifier).
    fn instance(&mut self, name: &Name) -> Option<InstanceId> {
        if let Some(&id) = self.instance_ids.get(name.bare()) {
            return Some(id);
        }
        self.unresolved(name);
        None
    }

    fn unresolved(&mut self, name: &Name) {
        let bare = name.bare();
        if self.category_ids.contains_key(bare) || is_synset_name(bare) {
            self.error(
                name.span,
                format!("unbound variable `{}`", name.text),
                "no enclosing quantifier binds it",
            );
        } else {
            self.error(
                name.span,
                format!("undeclared instance `{}`", name.text),
                "not declared in :objects",
            );
        }
    }

    fn ability_warning(&mut self, predicate: Predicate, arg: &Name, category: Option<CategoryId>) {
        let (Some(ability), Some(taxonomy), Some(category)) = (
            predicate.required_ability(),
            self.context.taxonomy,
            category,
        ) else {
            return;
        };
        let category = &self.categories[category.0 as usize];
        let Some(synset) = category.synset else {
            return;
        };
        if !taxonomy.has_ability(synset, ability) {
            let message = format!(
                "`{predicate}` applied to `{}`, but synset `{}` is not {ability}",
                arg.bare(),
                category.name
            );
            self.diagnostics.push(
                Diagnostic::warning(arg.span, message)
                    .with_label(format!("lacks the `{ability}` ability")),
            );
        }
    }

    fn term(&mut self, name: &Name) -> Option<(Term, Option<CategoryId>)> {
        let bare = name.bare();
        if let Some(depth) = self.scope.iter().rposition(|(label, _)| label == bare) {
            return Some((Term::Var(depth as u32), self.scope[depth].1));
        }
        let id = self.instance(name)?;
        Some((
            Term::Instance(id),
            Some(self.instances[id.0 as usize].category),
        ))
    }

    fn quantified_category(&mut self, decl: &ast::Decl) -> Option<CategoryId> {
        if !decl.var.text.starts_with('?') {
            self.diagnostics.push(
                Diagnostic::warning(decl.var.span, "quantified variable without `?`")
                    .with_label(format!("write `?{}`", decl.var.text)),
            );
        }
        match self.category_ids.get(&decl.category.text) {
            Some(&id) => Some(id),
            None => {
                let message = format!(
                    "quantifier over category `{}`, which is not declared in :objects",
                    decl.category.text
                );
                self.error(decl.category.span, message, "undeclared category");
                None
            }
        }
    }

    /// Checks a body with the given variables bound.
    fn bind(
        &mut self,
        decls: &[(&ast::Decl, Option<CategoryId>)],
        body: &ast::Formula,
    ) -> Option<Goal> {
        for (decl, category) in decls {
            self.scope.push((decl.var.bare().to_string(), *category));
        }
        let goal = self.goal(body);
        self.scope.truncate(self.scope.len() - decls.len());
        goal
    }

    fn count(&mut self, count: &ast::Count, available: usize, what: &str) {
        if count.value as usize > available {
            self.diagnostics.push(
                Diagnostic::warning(
                    count.span,
                    format!(
                        "asks for {} {what} but only {available} can be formed; it can never hold",
                        count.value
                    ),
                )
                .with_label("count too large"),
            );
        }
    }

    fn goal(&mut self, formula: &ast::Formula) -> Option<Goal> {
        let boxed = |g: Goal| Box::new(g);
        Some(match &formula.kind {
            FormulaKind::Atom { predicate, args } => {
                let predicate = self.predicate(predicate, args.len())?;
                if predicate == Predicate::InRoom {
                    self.error(
                        formula.span,
                        "`inroom` may appear only in `:init`".into(),
                        "room membership is fixed by the scene",
                    );
                    return None;
                }
                let terms: Vec<Option<(Term, Option<CategoryId>)>> =
                    args.iter().map(|a| self.term(a)).collect();
                let terms: Vec<(Term, Option<CategoryId>)> =
                    terms.into_iter().collect::<Option<_>>()?;
                self.ability_warning(predicate, &args[0], terms[0].1);
                Goal::Atom {
                    predicate,
                    args: terms.into_iter().map(|(t, _)| t).collect(),
                }
            }
            FormulaKind::Not(f) => Goal::Not(boxed(self.goal(f)?)),
            FormulaKind::And(fs) | FormulaKind::Or(fs) => {
                let parts: Vec<Option<Goal>> = fs.iter().map(|f| self.goal(f)).collect();
                let parts = parts.into_iter().collect::<Option<Vec<_>>>()?;
                if matches!(formula.kind, FormulaKind::And(_)) {
                    Goal::And(parts)
                } else {
                    Goal::Or(parts)
                }
            }
            FormulaKind::Imply(a, b) | FormulaKind::Iff(a, b) => {
                let (a, b) = (self.goal(a), self.goal(b));
                let (a, b) = (boxed(a?), boxed(b?));
                if matches!(formula.kind, FormulaKind::Imply(..)) {
                    Goal::Imply(a, b)
                } else {
                    Goal::Iff(a, b)
                }
            }
            FormulaKind::Forall(decl, body) | FormulaKind::Exists(decl, body) => {
                let c = self.quantified_category(decl);
                let body = self.bind(&[(decl, c)], body);
                let (c, body) = (c?, boxed(body?));
                if matches!(formula.kind, FormulaKind::Forall(..)) {
                    Goal::Forall(c, body)
                } else {
                    Goal::Exists(c, body)
                }
            }
            FormulaKind::ForN(count, decl, body) => {
                let c = self.quantified_category(decl);
                let body = self.bind(&[(decl, c)], body);
                let c = c?;
                let n = self.categories[c.0 as usize].instances.len();
                self.count(count, n, "instances");
                Goal::ForN(count.value, c, boxed(body?))
            }
            FormulaKind::ForPairs(d1, d2, body) => {
                let (a, b) = (self.quantified_category(d1), self.quantified_category(d2));
                let body = self.bind(&[(d1, a), (d2, b)], body);
                Goal::ForPairs(a?, b?, boxed(body?))
            }
            FormulaKind::ForNPairs(count, d1, d2, body) => {
                let (a, b) = (self.quantified_category(d1), self.quantified_category(d2));
                let body = self.bind(&[(d1, a), (d2, b)], body);
                let (a, b) = (a?, b?);
                let pairs = self.categories[a.0 as usize]
                    .instances
                    .len()
                    .min(self.categories[b.0 as usize].instances.len());
                self.count(count, pairs, "disjoint pairs");
                Goal::ForNPairs(count.value, a, b, boxed(body?))
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::taxonomy::tests::SMALL;

    fn load(text: &str) -> Result<(Activity, Diagnostics), SourceErrors> {
        let taxonomy = Taxonomy::from_json(SMALL).unwrap();
        let context = CheckContext {
            taxonomy: Some(&taxonomy),
            domain: None,
        };
        Activity::load(&Source::new("test.bddl", text), context)
    }

    fn problem(objects: &str, init: &str, goal: &str) -> String {
        format!(
            "(define (problem t_0) (:domain igibson)\n (:objects {objects})\n (:init {init})\n (:goal {goal}))"
        )
    }

    const OBJECTS: &str = "apple.n.01_1 apple.n.01_2 - apple.n.01 table.n.02_1 - table.n.02";

    fn errors(text: &str) -> Vec<String> {
        let err = load(text).unwrap_err();
        err.diagnostics
            .errors()
            .map(|d| d.message.clone())
            .collect()
    }

    #[test]
    fn resolves_variables_and_instances() {
        let text = problem(
            OBJECTS,
            "(ontop apple.n.01_1 table.n.02_1) (inroom table.n.02_1 kitchen)",
            "(and (forall (?apple.n.01 - apple.n.01) (ontop ?apple.n.01 ?table.n.02_1)) (cooked apple.n.01_2))",
        );
        let (activity, warnings) = load(&text).unwrap();
        assert!(warnings.0.is_empty(), "{warnings:?}");
        assert_eq!(activity.instances.len(), 3);
        assert_eq!(activity.goal.len(), 2);
        assert_eq!(
            activity.goal[0].goal,
            Goal::Forall(
                CategoryId(0),
                Box::new(Goal::Atom {
                    predicate: Predicate::OnTop,
                    args: vec![Term::Var(0), Term::Instance(InstanceId(2))],
                })
            )
        );
        assert_eq!(activity.initial_facts().len(), 1);
    }

    #[test]
    fn each_kind_of_error_is_reported_with_its_location() {
        let e = errors(&problem(OBJECTS, "", "(ontopp apple.n.01_1 table.n.02_1)"));
        assert_eq!(e, ["unknown predicate `ontopp`"]);
        let e = errors(&problem(OBJECTS, "", "(cooked apple.n.01_1 table.n.02_1)"));
        assert_eq!(e, ["`cooked` takes 1 argument, 2 given"]);
        let e = errors(&problem(OBJECTS, "", "(cooked apple.n.01_3)"));
        assert_eq!(e, ["undeclared instance `apple.n.01_3`"]);
        let e = errors(&problem(OBJECTS, "", "(cooked ?apple.n.01)"));
        assert_eq!(e, ["unbound variable `?apple.n.01`"]);
        let e = errors(&problem(
            OBJECTS,
            "",
            "(exists (?p - plate.n.04) (cooked ?p))",
        ));
        assert_eq!(
            e,
            ["quantifier over category `plate.n.04`, which is not declared in :objects"]
        );
        let e = errors(&problem(
            "apple.n.01_1 - table.n.02",
            "",
            "(cooked apple.n.01_1)",
        ));
        assert_eq!(
            e[0],
            "instance name `apple.n.01_1` does not match its declared category `table.n.02`"
        );
        let e = errors(&problem("pear.n.01_1 - pear.n.01", "", "(and)"));
        assert_eq!(e, ["unknown synset `pear.n.01`"]);
        let e = errors(&problem(OBJECTS, "(and (cooked apple.n.01_1))", "(and)"));
        assert_eq!(e, ["`:init` holds only literals"]);
        let e = errors(&problem(OBJECTS, "", "(inroom table.n.02_1 kitchen)"));
        assert_eq!(e, ["`inroom` may appear only in `:init`"]);
        let err = load(&problem(OBJECTS, "", "(cooked apple.n.01_3)")).unwrap_err();
        let rendered = err.to_string();
        assert!(
            rendered.starts_with("test.bddl:4:17: error: undeclared instance"),
            "{rendered}"
        );
        assert!(rendered.contains("^^^^"), "{rendered}");
    }

    #[test]
    fn an_unknown_room_type_is_an_error_at_the_room_word() {
        // No home has a ballroom, so no instance of the activity could be sampled: an error, not a
        // warning.
        let text = problem(OBJECTS, "(inroom table.n.02_1 ballroom)", "(and)");
        let err = load(&text).unwrap_err();
        let errors: Vec<&Diagnostic> = err.diagnostics.errors().collect();
        assert_eq!(errors.len(), 1, "{err}");
        let error = errors[0];
        assert!(
            error.message.contains("unknown room type `ballroom`"),
            "{}",
            error.message
        );
        let at = text.find("ballroom").unwrap();
        assert_eq!(error.span, Span::new(at, at + "ballroom".len()));
        for room in RoomType::ALL {
            assert!(
                error.notes.iter().any(|n| n.contains(room.name())),
                "`{}` missing from {:?}",
                room.name(),
                error.notes
            );
        }
        let rendered = err.to_string();
        assert!(
            rendered.starts_with("test.bddl:3:30: error: unknown room type `ballroom`"),
            "{rendered}"
        );

        let text = problem(OBJECTS, "(inroom table.n.02_1 kitchen)", "(and)");
        let (activity, warnings) = load(&text).unwrap();
        assert!(warnings.0.is_empty(), "{warnings:?}");
        let table = activity.instance_named("table.n.02_1").unwrap();
        assert!(
            matches!(
                activity.init[..],
                [InitLiteral::InRoom {
                    instance,
                    room: RoomType::Kitchen,
                    positive: true,
                }] if instance == table
            ),
            "{:?}",
            activity.init
        );
        assert!(activity.initial_facts().is_empty());
    }

    #[test]
    fn a_goal_too_large_to_ground_is_an_error() {
        let objects: Vec<String> = (1..=40).map(|i| format!("apple.n.01_{i}")).collect();
        let objects = format!("{} - apple.n.01", objects.join(" "));
        let mut goal = "(cooked ?v0)".to_string();
        for depth in 0..5 {
            goal = format!("(forall (?v{depth} - apple.n.01) {goal})");
        }
        let e = errors(&problem(&objects, "", &goal));
        assert_eq!(
            e,
            [
                "the goal is too large to ground over these objects: about 105025642 formulas (limit 5000000)"
            ]
        );
        // 20 × 20 cells are few, but their negation ranges over C(40, 19) row-and-column covers.
        let apples: Vec<String> = (1..=20).map(|i| format!("apple.n.01_{i}")).collect();
        let tables: Vec<String> = (1..=20).map(|i| format!("table.n.02_{i}")).collect();
        let objects = format!(
            "{} - apple.n.01 {} - table.n.02",
            apples.join(" "),
            tables.join(" ")
        );
        let pairs = "(forpairs (?apple.n.01 - apple.n.01) (?table.n.02 - table.n.02) (ontop ?apple.n.01 ?table.n.02))";
        assert!(load(&problem(&objects, "", pairs)).is_ok());
        let e = errors(&problem(&objects, "", &format!("(not {pairs})")));
        assert!(e[0].starts_with("the goal is too large to ground"), "{e:?}");
    }

    #[test]
    fn binomials() {
        assert_eq!(binomial(5, 2), 10);
        assert_eq!(binomial(40, 19), 131_282_408_400);
        assert_eq!(binomial(3, 0), 1);
        assert_eq!(binomial(3, 5), 0);
        assert_eq!(binomial(1000, 500), u64::MAX);
    }

    #[test]
    fn warns_about_a_state_on_a_synset_without_its_ability() {
        let text = problem(OBJECTS, "(dusty apple.n.01_1)", "(cooked table.n.02_1)");
        let (_, warnings) = load(&text).unwrap();
        let messages: Vec<_> = warnings.0.iter().map(|d| d.message.as_str()).collect();
        assert_eq!(
            messages,
            [
                "`dusty` applied to `apple.n.01_1`, but synset `apple.n.01` is not dustyable",
                "`cooked` applied to `table.n.02_1`, but synset `table.n.02` is not cookable"
            ]
        );
    }
}
