//! The native module `behavior._core` of the Python package `behavior` (see `python/README`
//! in the repository's README, "Python"): the Rust environment of `behavior-env` built from an
//! activity's name as `behavior run` builds it, stepped with the interpreter's lock released,
//! observations as numpy arrays. The Gymnasium classes and registration are Python
//! (`python/behavior/`); this crate knows nothing of Gymnasium.
//!
//! Bad input never panics: an unknown activity, robot or home, a wrong action (length, NaN) or a
//! step after the episode ended is a `ValueError` saying which and why.

// mimalloc: faster with the allocations of a step, and with several threads (Cargo.toml).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

mod bddl;
mod build;
mod env;
mod options;
mod primitives;
mod record;
mod vector;

use behavior_env::EpisodeMetrics;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

/// Every official activity's name, in the manifest's order (the data is fetched from PyPI on
/// first use).
#[pyfunction]
fn activities(py: Python<'_>) -> PyResult<Vec<String>> {
    py.detach(build::activities)
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// The named homes that hold what `activity` needs, in order: the first is where environments
/// sample by default; the benchmark protocol's unseen-furniture episodes use the second.
#[pyfunction]
fn covering_homes(py: Python<'_>, activity: String) -> PyResult<Vec<String>> {
    py.detach(|| build::catalog()?.covering_homes(&activity))
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The benchmark protocol's summary (BEHAVIOR's `behavior/benchmark/behavior_benchmark.py`) of
/// episodes, each `(activity, metrics)` with the metrics as `Env.metrics_json()` gives them: a JSON
/// object (success score, its top 5 per-activity means, and the efficiency metrics' means).
#[pyfunction]
fn aggregate(episodes: Vec<(String, String)>) -> PyResult<String> {
    let parsed = episodes
        .into_iter()
        .enumerate()
        .map(|(i, (activity, json))| {
            serde_json::from_str::<EpisodeMetrics>(&json)
                .map(|m| (activity, m))
                .map_err(|e| PyValueError::new_err(format!("episode {i}'s metrics: {e}")))
        })
        .collect::<PyResult<Vec<_>>>()?;
    serde_json::to_string(&behavior_env::metrics::aggregate(&parsed))
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// Each episode's efficiency metrics relative to the best reference on its activity and
/// instance, else on its activity (`behavior_env::metrics::HumanReference`). `references` and
/// `episodes` are `(activity, instance, metrics JSON)`; returns a JSON list, one
/// `{"reference": "instance"|"activity"|null, "relative": {…}|null}` per episode.
#[pyfunction]
fn relative_metrics(
    references: Vec<(String, String, String)>,
    episodes: Vec<(String, String, String)>,
) -> PyResult<String> {
    let metrics = |what: &str, i: usize, json: &str| {
        serde_json::from_str::<EpisodeMetrics>(json)
            .map_err(|e| PyValueError::new_err(format!("{what} {i}'s metrics: {e}")))
    };
    let mut best = behavior_env::metrics::HumanReference::new();
    for (i, (activity, instance, json)) in references.iter().enumerate() {
        best.add(activity, instance, &metrics("reference", i, json)?);
    }
    let mut out = Vec::new();
    for (i, (activity, instance, json)) in episodes.iter().enumerate() {
        let episode = metrics("episode", i, json)?;
        let (reference, relative) = match best.normalize(activity, instance, &episode) {
            Some(n) => (Some("instance"), Some(n)),
            None => match best.normalize_by_activity(activity, &episode) {
                Some(n) => (Some("activity"), Some(n)),
                None => (None, None),
            },
        };
        out.push(serde_json::json!({"reference": reference, "relative": relative}));
    }
    Ok(serde_json::Value::Array(out).to_string())
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<env::PyEnv>()?;
    m.add_class::<env::PyCheckpoint>()?;
    m.add_class::<vector::PyVecEnv>()?;
    m.add_function(wrap_pyfunction!(activities, m)?)?;
    m.add_function(wrap_pyfunction!(covering_homes, m)?)?;
    m.add_function(wrap_pyfunction!(aggregate, m)?)?;
    m.add_function(wrap_pyfunction!(relative_metrics, m)?)?;
    m.add_function(wrap_pyfunction!(record::replay, m)?)?;
    m.add_function(wrap_pyfunction!(record::export_lerobot, m)?)?;
    m.add_function(wrap_pyfunction!(bddl::bddl_check, m)?)?;
    m.add_function(wrap_pyfunction!(bddl::bddl_evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(bddl::bddl_options, m)?)?;
    Ok(())
}
