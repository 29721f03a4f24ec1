//! Parser: the reader's lists to domain and problem syntax trees.
//!
//! It checks shape only (sections, operators and their operands, declarations, counts) and keeps
//! going after an error where it can, so one run reports every syntax problem of a file. Meaning
//! (which predicates exist, which names are declared) is the checker's business.

use crate::ast::*;
use crate::diagnostics::{Diagnostic, Diagnostics, Span};
use crate::sexpr::{self, List, SExpr};

/// Parses the text of a problem file (`(define (problem ...) (:domain ...) (:objects ...) ...)`).
pub fn parse_problem(text: &str) -> Result<ProblemFile, Diagnostics> {
    let root = sexpr::read(text)?;
    let mut p = Parser::default();
    let problem = p.problem(&root);
    match problem {
        Some(problem) if !p.diagnostics.has_errors() => Ok(problem),
        _ => Err(p.diagnostics),
    }
}

/// Parses the text of a domain file (`(define (domain ...) (:requirements ...) (:predicates ...))`).
pub fn parse_domain(text: &str) -> Result<DomainFile, Diagnostics> {
    let root = sexpr::read(text)?;
    let mut p = Parser::default();
    let domain = p.domain(&root);
    match domain {
        Some(domain) if !p.diagnostics.has_errors() => Ok(domain),
        _ => Err(p.diagnostics),
    }
}

#[derive(Default)]
struct Parser {
    diagnostics: Diagnostics,
}

fn name(atom: &sexpr::Atom) -> Name {
    Name {
        text: atom.text.clone(),
        span: atom.span,
    }
}

impl Parser {
    fn error(&mut self, span: Span, message: impl Into<String>, label: impl Into<String>) {
        self.diagnostics
            .push(Diagnostic::error(span, message).with_label(label));
    }

    /// Checks `(define (KIND NAME) section...)` and returns NAME and the sections.
    fn define<'a>(&mut self, root: &'a List, kind: &str) -> Option<(Name, &'a [SExpr])> {
        if root.head().map(|h| h.text.as_str()) != Some("define") {
            self.error(
                root.span,
                "expected `(define ...)`",
                "a BDDL file is one `define` form",
            );
            return None;
        }
        let header = root.items.get(1).and_then(SExpr::as_list);
        let header_ok = header.is_some_and(|h| {
            h.items.len() == 2
                && h.head().is_some_and(|a| a.text == kind)
                && h.items[1].as_atom().is_some()
        });
        if !header_ok {
            let span = root.items.get(1).map_or(root.span, SExpr::span);
            self.error(
                span,
                format!("expected `({kind} NAME)` after `define`"),
                "malformed header",
            );
            return None;
        }
        let header = header?;
        Some((name(header.items[1].as_atom()?), &root.items[2..]))
    }

    fn domain(&mut self, root: &List) -> Option<DomainFile> {
        let (domain_name, sections) = self.define(root, "domain")?;
        let mut requirements = Vec::new();
        let mut predicates = Vec::new();
        for section in sections {
            let Some(list) = self.section(section) else {
                continue;
            };
            let keyword = list.head()?.text.as_str();
            match keyword {
                ":requirements" => requirements.extend(self.atoms(&list.items[1..])),
                ":predicates" => {
                    for item in &list.items[1..] {
                        if let Some(decl) = self.predicate_decl(item) {
                            predicates.push(decl);
                        }
                    }
                }
                // PDDL sections BDDL does not use; accepted and ignored as by the reference.
                ":types" | ":constants" | ":action" => {}
                _ => self.error(
                    list.span,
                    format!("unknown domain section `{keyword}`"),
                    "expected :requirements or :predicates",
                ),
            }
        }
        Some(DomainFile {
            name: domain_name,
            requirements,
            predicates,
        })
    }

    fn predicate_decl(&mut self, item: &SExpr) -> Option<PredicateDecl> {
        let list = item.as_list();
        let Some(list) = list.filter(|l| l.head().is_some()) else {
            self.error(
                item.span(),
                "expected a predicate declaration `(name ?param...)`",
                "",
            );
            return None;
        };
        let params: Vec<Name> = self.atoms(&list.items[1..]);
        // PDDL typing `?a ?b - type` is allowed; only the parameters count for the arity.
        let mut kept = Vec::new();
        let mut skip_next = false;
        for p in params {
            if skip_next {
                skip_next = false;
            } else if p.text == "-" {
                skip_next = true;
            } else {
                kept.push(p);
            }
        }
        Some(PredicateDecl {
            name: name(list.head()?),
            params: kept,
            span: list.span,
        })
    }

    /// Atoms of a list of items; reports any nested list.
    fn atoms(&mut self, items: &[SExpr]) -> Vec<Name> {
        let mut names = Vec::new();
        for item in items {
            match item {
                SExpr::Atom(a) => names.push(name(a)),
                SExpr::List(l) => self.error(l.span, "expected a word, found a list", ""),
            }
        }
        names
    }

    /// A section is a list that starts with a `:keyword`.
    fn section<'a>(&mut self, item: &'a SExpr) -> Option<&'a List> {
        match item {
            SExpr::List(l) if l.head().is_some_and(|h| h.text.starts_with(':')) => Some(l),
            _ => {
                self.error(
                    item.span(),
                    "expected a section such as `(:objects ...)`",
                    "not a section",
                );
                None
            }
        }
    }

    fn problem(&mut self, root: &List) -> Option<ProblemFile> {
        let (problem_name, sections) = self.define(root, "problem")?;
        let mut domain = None;
        let mut objects = None;
        let mut init = None;
        let mut goal: Option<Option<Formula>> = None;
        for section in sections {
            let Some(list) = self.section(section) else {
                continue;
            };
            let keyword = list.head()?;
            let duplicate = match keyword.text.as_str() {
                ":domain" => {
                    let ok = list.items.len() == 2 && list.items[1].as_atom().is_some();
                    if !ok {
                        self.error(list.span, "expected `(:domain NAME)`", "");
                    }
                    let d = list.items.get(1).and_then(SExpr::as_atom).map(name);
                    domain.replace(d).is_some()
                }
                ":requirements" => false,
                ":objects" => {
                    let groups = self.objects(list);
                    objects.replace(groups).is_some()
                }
                ":init" => {
                    let literals = list.items[1..]
                        .iter()
                        .filter_map(|item| self.formula(item))
                        .collect();
                    init.replace(literals).is_some()
                }
                ":goal" => {
                    let formula = self.goal(list);
                    goal.replace(formula).is_some()
                }
                other => {
                    self.error(
                        keyword.span,
                        format!("unknown problem section `{other}`"),
                        "expected :domain, :objects, :init or :goal",
                    );
                    false
                }
            };
            if duplicate {
                self.error(
                    keyword.span,
                    format!("second `{}` section", keyword.text),
                    "",
                );
            }
        }
        let mut missing = |what: &str| {
            self.error(
                root.span,
                format!("missing `({what} ...)` section"),
                "in this definition",
            )
        };
        if domain.is_none() {
            missing(":domain");
        }
        if objects.is_none() {
            missing(":objects");
        }
        if init.is_none() {
            missing(":init");
        }
        if goal.is_none() {
            missing(":goal");
        }
        Some(ProblemFile {
            name: problem_name,
            domain: domain??,
            objects: objects?,
            init: init?,
            goal: goal??,
            span: root.span,
        })
    }

    fn goal(&mut self, list: &List) -> Option<Formula> {
        match &list.items[1..] {
            [formula] => self.formula(formula),
            [] => {
                self.error(list.span, "empty `:goal`", "expected one formula");
                None
            }
            [_, extra, ..] => {
                self.error(
                    extra.span(),
                    "`:goal` takes one formula",
                    "wrap several conditions in `(and ...)`",
                );
                None
            }
        }
    }

    fn objects(&mut self, list: &List) -> Vec<ObjectGroup> {
        let mut groups = Vec::new();
        let mut pending: Vec<Name> = Vec::new();
        let mut items = list.items[1..].iter();
        while let Some(item) = items.next() {
            let Some(atom) = item.as_atom() else {
                self.error(
                    item.span(),
                    "expected instance names, `-` and a category",
                    "a list here",
                );
                continue;
            };
            if atom.text != "-" {
                pending.push(name(atom));
                continue;
            }
            match items.next().and_then(SExpr::as_atom) {
                Some(category) if category.text != "-" => {
                    if pending.is_empty() {
                        self.error(
                            atom.span.to(category.span),
                            format!("category `{}` has no instances before it", category.text),
                            "expected `inst1 inst2 - category`",
                        );
                    }
                    groups.push(ObjectGroup {
                        instances: std::mem::take(&mut pending),
                        category: name(category),
                    });
                }
                _ => self.error(atom.span, "`-` must be followed by a category", ""),
            }
        }
        if let (Some(first), Some(last)) = (pending.first(), pending.last()) {
            self.error(
                first.span.to(last.span),
                "instances without a category",
                "add `- category` after them",
            );
        }
        groups
    }

    fn formula(&mut self, item: &SExpr) -> Option<Formula> {
        let list = match item {
            SExpr::List(l) => l,
            SExpr::Atom(a) => {
                self.error(
                    a.span,
                    format!("expected a formula `(...)`, found `{}`", a.text),
                    "",
                );
                return None;
            }
        };
        let Some(head) = list.head() else {
            self.error(
                list.span,
                "expected a formula: `(predicate args...)` or `(operator ...)`",
                "",
            );
            return None;
        };
        let span = list.span;
        let operands = &list.items[1..];
        let kind = match head.text.as_str() {
            "not" => FormulaKind::Not(Box::new(self.exactly_one(list, operands)?)),
            "and" => FormulaKind::And(self.formulas(operands)?),
            "or" => FormulaKind::Or(self.formulas(operands)?),
            "imply" | "iff" => {
                let [a, b] = operands else {
                    self.error(
                        span,
                        format!("`{}` takes two formulas", head.text),
                        format!("{} given", operands.len()),
                    );
                    return None;
                };
                let (a, b) = (self.formula(a), self.formula(b));
                let (a, b) = (Box::new(a?), Box::new(b?));
                if head.text == "imply" {
                    FormulaKind::Imply(a, b)
                } else {
                    FormulaKind::Iff(a, b)
                }
            }
            "forall" | "exists" => {
                let [decl, body] = operands else {
                    self.quantifier_shape(span, &head.text, "(?x - category) body");
                    return None;
                };
                let (decl, body) = (self.decl(decl), self.formula(body));
                let (decl, body) = (decl?, Box::new(body?));
                if head.text == "forall" {
                    FormulaKind::Forall(decl, body)
                } else {
                    FormulaKind::Exists(decl, body)
                }
            }
            "forn" => {
                let [count, decl, body] = operands else {
                    self.quantifier_shape(span, "forn", "(N) (?x - category) body");
                    return None;
                };
                let (c, d, b) = (self.count(count), self.decl(decl), self.formula(body));
                FormulaKind::ForN(c?, d?, Box::new(b?))
            }
            "forpairs" => {
                let [d1, d2, body] = operands else {
                    self.quantifier_shape(span, "forpairs", "(?x - a) (?y - b) body");
                    return None;
                };
                let (d1, d2, b) = (self.decl(d1), self.decl(d2), self.formula(body));
                FormulaKind::ForPairs(d1?, d2?, Box::new(b?))
            }
            "fornpairs" => {
                let [count, d1, d2, body] = operands else {
                    self.quantifier_shape(span, "fornpairs", "(N) (?x - a) (?y - b) body");
                    return None;
                };
                let (c, d1, d2, b) = (
                    self.count(count),
                    self.decl(d1),
                    self.decl(d2),
                    self.formula(body),
                );
                FormulaKind::ForNPairs(c?, d1?, d2?, Box::new(b?))
            }
            _ => {
                let mut args = Vec::new();
                for operand in operands {
                    match operand {
                        SExpr::Atom(a) => args.push(name(a)),
                        SExpr::List(l) => self.error(
                            l.span,
                            format!("arguments of `{}` must be names", head.text),
                            "a nested formula here",
                        ),
                    }
                }
                FormulaKind::Atom {
                    predicate: name(head),
                    args,
                }
            }
        };
        Some(Formula { kind, span })
    }

    fn formulas(&mut self, items: &[SExpr]) -> Option<Vec<Formula>> {
        let parsed: Vec<Option<Formula>> = items.iter().map(|i| self.formula(i)).collect();
        parsed.into_iter().collect()
    }

    fn exactly_one(&mut self, list: &List, operands: &[SExpr]) -> Option<Formula> {
        match operands {
            [one] => self.formula(one),
            _ => {
                self.error(
                    list.span,
                    "`not` takes one formula",
                    format!("{} given", operands.len()),
                );
                None
            }
        }
    }

    fn quantifier_shape(&mut self, span: Span, op: &str, shape: &str) {
        self.error(
            span,
            format!("malformed `{op}`"),
            format!("expected `({op} {shape})`"),
        );
    }

    fn decl(&mut self, item: &SExpr) -> Option<Decl> {
        let shape = item.as_list().and_then(|l| match l.items.as_slice() {
            [SExpr::Atom(var), SExpr::Atom(dash), SExpr::Atom(category)] if dash.text == "-" => {
                Some((var, category))
            }
            _ => None,
        });
        match shape {
            Some((var, category)) => Some(Decl {
                var: name(var),
                category: name(category),
                span: item.span(),
            }),
            None => {
                self.error(
                    item.span(),
                    "malformed variable declaration",
                    "expected `(?x - category)`",
                );
                None
            }
        }
    }

    fn count(&mut self, item: &SExpr) -> Option<Count> {
        let value = item.as_list().and_then(|l| match l.items.as_slice() {
            [SExpr::Atom(n)] => n.text.parse::<u32>().ok(),
            _ => None,
        });
        match value {
            Some(value) => Some(Count {
                value,
                span: item.span(),
            }),
            None => {
                self.error(
                    item.span(),
                    "malformed count",
                    "expected a non-negative whole number in parentheses, like `(2)`",
                );
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PROBLEM: &str = "(define (problem p_0) (:domain igibson)
        (:objects a.n.01_1 a.n.01_2 - a.n.01 t.n.01_1 - t.n.01)
        (:init (ontop a.n.01_1 t.n.01_1) (not (open t.n.01_1)))
        (:goal (and (forn (2) (?a.n.01 - a.n.01) (cooked ?a.n.01))
                    (forpairs (?a.n.01 - a.n.01) (?t.n.01 - t.n.01) (ontop ?a.n.01 ?t.n.01))
                    (imply (open ?t.n.01_1) (not (ontop ?a.n.01_1 ?t.n.01_1))))))";

    #[test]
    fn parses_every_section() {
        let p = parse_problem(PROBLEM).unwrap();
        assert_eq!(p.name.text, "p_0");
        assert_eq!(p.domain.text, "igibson");
        assert_eq!(p.objects.len(), 2);
        assert_eq!(p.objects[0].instances.len(), 2);
        assert_eq!(p.init.len(), 2);
        let FormulaKind::And(parts) = &p.goal.kind else {
            panic!("goal is not a conjunction")
        };
        assert!(matches!(&parts[0].kind, FormulaKind::ForN(c, _, _) if c.value == 2));
        assert!(matches!(&parts[1].kind, FormulaKind::ForPairs(..)));
        assert!(matches!(&parts[2].kind, FormulaKind::Imply(..)));
    }

    fn first_error(text: &str) -> String {
        parse_problem(text).unwrap_err().0[0].message.clone()
    }

    #[test]
    fn reports_malformed_shapes() {
        let base = |goal: &str| {
            format!(
                "(define (problem p) (:domain d) (:objects a.n.01_1 - a.n.01) (:init) (:goal {goal}))"
            )
        };
        assert_eq!(
            first_error(&base("(forn (x) (?a - a.n.01) (cooked ?a))")),
            "malformed count"
        );
        assert_eq!(
            first_error(&base("(forn (-1) (?a - a.n.01) (cooked ?a))")),
            "malformed count"
        );
        assert_eq!(
            first_error(&base("(forall (?a a.n.01) (cooked ?a))")),
            "malformed variable declaration"
        );
        assert_eq!(first_error(&base("(not)")), "`not` takes one formula");
        assert_eq!(
            first_error(&base("(cooked a) (cooked b)")),
            "`:goal` takes one formula"
        );
        assert_eq!(
            first_error("(define (problem p) (:domain d) (:objects a - ) (:init) (:goal (and)))"),
            "`-` must be followed by a category"
        );
        assert_eq!(
            first_error("(define (problem p) (:objects a - b) (:init) (:goal (and)))"),
            "missing `(:domain ...)` section"
        );
    }

    #[test]
    fn parses_a_domain() {
        let d = parse_domain(
            "(define (domain igibson) (:requirements :strips :adl) (:predicates (inside ?a ?b) (cooked ?a - object)))",
        )
        .unwrap();
        assert_eq!(d.name.text, "igibson");
        assert_eq!(d.predicates.len(), 2);
        assert_eq!(d.predicates[1].params.len(), 1);
    }
}
