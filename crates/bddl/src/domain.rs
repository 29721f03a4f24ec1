//! Checking a domain file against the predicate vocabulary that simulators implement.
//!
//! In BDDL 1.0 the domain only names the predicates; its `:requirements` are PDDL leftovers. A
//! predicate the vocabulary lacks is a warning (no simulator could evaluate it), a known predicate
//! declared with the wrong number of parameters an error.

use crate::ast::DomainFile;
use crate::diagnostics::{Diagnostic, Diagnostics, Source, SourceErrors};
use crate::parser;
use crate::predicate::Predicate;

/// The requirement flags the reference implementation accepts.
pub const REQUIREMENTS: [&str; 4] = [":strips", ":negative-preconditions", ":typing", ":adl"];

/// Diagnostics about a parsed domain.
pub fn check_domain(domain: &DomainFile) -> Diagnostics {
    let mut diagnostics = Diagnostics::default();
    for requirement in &domain.requirements {
        if !REQUIREMENTS.contains(&requirement.text.as_str()) {
            diagnostics.push(
                Diagnostic::error(
                    requirement.span,
                    format!("unknown requirement `{}`", requirement.text),
                )
                .with_note(format!("accepted: {}", REQUIREMENTS.join(" "))),
            );
        }
    }
    let mut seen: Vec<&str> = Vec::new();
    for decl in &domain.predicates {
        let name = decl.name.text.as_str();
        if seen.contains(&name) {
            diagnostics.push(
                Diagnostic::warning(decl.name.span, format!("predicate `{name}` declared twice"))
                    .with_label("again here"),
            );
        }
        seen.push(name);
        match Predicate::from_name(name) {
            None => diagnostics.push(
                Diagnostic::warning(decl.name.span, format!("no simulator implements `{name}`"))
                    .with_label("not in the BEHAVIOR predicate vocabulary"),
            ),
            Some(p) if p.arity() != decl.params.len() => diagnostics.push(
                Diagnostic::error(
                    decl.span,
                    format!(
                        "`{name}` takes {} parameter(s), declared with {}",
                        p.arity(),
                        decl.params.len()
                    ),
                )
                .with_label("wrong arity"),
            ),
            Some(_) => {}
        }
    }
    diagnostics
}

/// Whether a text is a domain file (`(define (domain ...) ...)`) rather than a problem.
pub fn is_domain_text(text: &str) -> bool {
    crate::sexpr::read(text).is_ok_and(|root| {
        root.items
            .get(1)
            .and_then(crate::sexpr::SExpr::as_list)
            .and_then(|header| header.head())
            .is_some_and(|head| head.text == "domain")
    })
}

/// Parses and checks a domain source; warnings come back with the domain.
pub fn load_domain(source: &Source) -> Result<(DomainFile, Diagnostics), SourceErrors> {
    let fail = |diagnostics| SourceErrors {
        source: source.clone(),
        diagnostics,
    };
    let domain = parser::parse_domain(&source.text).map_err(fail)?;
    let diagnostics = check_domain(&domain);
    if diagnostics.has_errors() {
        return Err(fail(diagnostics));
    }
    Ok((domain, diagnostics))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tells_domains_from_problems() {
        assert!(is_domain_text("(define (domain igibson) (:predicates))"));
        assert!(!is_domain_text("(define (problem p) (:domain igibson))"));
        assert!(!is_domain_text("(define (domain"));
    }

    #[test]
    fn reports_unknown_requirements_predicates_and_arity() {
        let text = "(define (domain d) (:requirements :strips :fluents)
            (:predicates (inside ?a ?b) (cooked ?a ?b) (levitating ?a)))";
        let err = load_domain(&Source::new("d.bddl", text)).unwrap_err();
        let messages: Vec<&str> = err
            .diagnostics
            .0
            .iter()
            .map(|d| d.message.as_str())
            .collect();
        assert_eq!(
            messages,
            [
                "unknown requirement `:fluents`",
                "`cooked` takes 1 parameter(s), declared with 2",
                "no simulator implements `levitating`"
            ]
        );
    }
}
