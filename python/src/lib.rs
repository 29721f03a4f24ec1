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

mod build;
mod env;
mod options;
mod primitives;
mod vector;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// Every official activity's name, in the manifest's order (the data is fetched from PyPI on
/// first use).
#[pyfunction]
fn activities(py: Python<'_>) -> PyResult<Vec<String>> {
    py.detach(build::activities)
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<env::PyEnv>()?;
    m.add_class::<vector::PyVecEnv>()?;
    m.add_function(wrap_pyfunction!(activities, m)?)?;
    Ok(())
}
