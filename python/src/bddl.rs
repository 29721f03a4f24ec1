//! The BDDL tools for Python (`behavior.bddl`), as `behavior bddl` offers them: check definition
//! files with located diagnostics, evaluate a goal on a state (success, Q, volume, each
//! top-level conjunct), list a goal's options. A definition is an official activity's name or a
//! file's path. Results cross as plain values (counts, strings, JSON); the Python module shapes
//! them.

use crate::build::catalog;
use behavior_bddl::domain::{is_domain_text, load_domain};
use behavior_bddl::options::options_with;
use behavior_bddl::{Counting, FactSet, GroundGoal, Optimizer};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde_json::json;

/// Why a BDDL tool failed: the data, the definition or the state given.
type Failed = Box<dyn std::error::Error + Send + Sync>;

fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Checks a problem or domain file: `(errors, warnings, rendered diagnostics)`.
#[pyfunction]
pub fn bddl_check(py: Python<'_>, definition: String) -> PyResult<(usize, usize, String)> {
    py.detach(|| -> Result<_, Failed> {
        let catalog = catalog()?;
        let source = catalog.source(&definition)?;
        let diagnostics = if is_domain_text(&source.text) {
            load_domain(&source).map(|(_, warnings)| warnings)
        } else {
            catalog
                .knowledge()
                .load(&source)
                .map(|(_, warnings)| warnings)
        }
        .unwrap_or_else(|e| e.diagnostics);
        Ok((
            diagnostics.errors().count(),
            diagnostics.warnings().count(),
            diagnostics.render(&source),
        ))
    })
    .map_err(value_error)
}

/// Evaluates a definition's goal on a state (`{"facts": [[predicate, object, ...], ...]}`, the
/// facts that hold): a JSON object with `success`, `q`, `q_exact` (a fraction), `volume` and
/// `conjuncts` (each top-level conjunct's text and whether it holds).
#[pyfunction]
pub fn bddl_evaluate(py: Python<'_>, definition: String, state: String) -> PyResult<String> {
    py.detach(|| -> Result<String, Failed> {
        let catalog = catalog()?;
        let source = catalog.source(&definition)?;
        let (activity, _warnings) = catalog.knowledge().load(&source)?;
        let facts = FactSet::from_json(&activity, &state).map_err(|e| format!("the state: {e}"))?;
        let goal = GroundGoal::new(&activity);
        let optimizer = Optimizer::with_counting(&goal, Counting::Set);
        let q = optimizer.q(&facts);
        let conjuncts: Vec<_> = activity
            .goal
            .iter()
            .zip(goal.conjuncts_hold(&facts))
            .map(|(c, holds)| json!({"formula": one_line(&source.text[c.span.range()]), "holds": holds}))
            .collect();
        Ok(json!({
            "success": goal.holds(&facts),
            "q": q.map(|q| q.to_f64()),
            "q_exact": q.map(|q| q.to_string()),
            "volume": optimizer.volume(),
            "conjuncts": conjuncts,
        })
        .to_string())
    })
    .map_err(value_error)
}

/// A goal's volume (the fewest literals of an option; `None` if it can never hold) and its first
/// `limit` options, smallest first, each a list of literals (`(ontop plywood.n.01_1
/// floor.n.01_1)`, `(not (open door.n.01_1))`).
#[pyfunction]
pub fn bddl_options(
    py: Python<'_>,
    definition: String,
    limit: usize,
) -> PyResult<(Option<u64>, Vec<Vec<String>>)> {
    py.detach(|| -> Result<_, Failed> {
        let catalog = catalog()?;
        let (activity, _warnings) = catalog.knowledge().load(&catalog.source(&definition)?)?;
        let goal = GroundGoal::new(&activity);
        let volume = Optimizer::with_counting(&goal, Counting::Set).volume();
        let options = options_with(&goal, Counting::Set)
            .take(limit)
            .map(|option| option.iter().map(|&l| activity.show_literal(l)).collect())
            .collect();
        Ok((volume, options))
    })
    .map_err(value_error)
}

/// Collapses whitespace so a multi-line formula reads on one line.
fn one_line(text: &str) -> String {
    let joined = text.split_whitespace().collect::<Vec<_>>().join(" ");
    joined.replace("( ", "(").replace(" )", ")")
}
