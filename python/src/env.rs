//! `behavior._core.Env`: one episode loop of `behavior-env`, stepped from Python with the
//! interpreter's lock released, observations handed over as numpy arrays that own the Rust
//! vectors (no copy).

use crate::build::{Catalog, EnvSpec};
use behavior_env::{Env, EnvError, Obs, Score};
use behavior_render::Pixels;
use numpy::{AllowTypeChange, IntoPyArray, PyArrayLike1, PyArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// A BEHAVIOR environment: `reset` and `step` as Gymnasium's, observations as a dict of numpy
/// arrays (`proprioception`, `task_obs`), info as a dict (`steps`, `q`, `success`,
/// `conjuncts`). The Gymnasium class `behavior.BehaviorEnv` wraps it.
#[pyclass(module = "behavior._core", name = "Env")]
pub struct PyEnv {
    // Env is Send, not Sync: the lock makes the class shareable, as pyo3 asks.
    env: Mutex<Env>,
    /// Seconds spent inside the Rust `step`s so far, and how many: what a
    /// benchmark subtracts to find the binding's own cost per step.
    inside: Mutex<(f64, u64)>,
    action_dim: usize,
    activity: String,
    robot: String,
    scene: String,
}

#[pymethods]
impl PyEnv {
    /// Builds the environment and starts a first episode with `seed` (so that its shapes are
    /// known). `scene`: a named home, or `None` for the first that covers the activity.
    #[new]
    #[pyo3(signature = (activity, robot = "behavior".to_string(), scene = None, seed = 0, max_steps = None, clutter = true))]
    fn new(
        py: Python<'_>,
        activity: String,
        robot: String,
        scene: Option<String>,
        seed: u64,
        max_steps: Option<u32>,
        clutter: bool,
    ) -> PyResult<PyEnv> {
        let spec = EnvSpec {
            activity,
            robot,
            scene,
            clutter,
        };
        let built = py.detach(|| -> Result<(Env, usize, String), String> {
            let catalog = Catalog::load().map_err(|e| e.to_string())?;
            let mut config = catalog.config(&spec).map_err(|e| e.to_string())?;
            if let Some(max) = max_steps {
                config.max_steps = max;
            }
            let scene = config
                .scenes
                .first()
                .map(|s| s.name.clone())
                .unwrap_or_default();
            let mut env = Env::new(config);
            env.reset(seed).map_err(|e| e.to_string())?;
            let dim = env.robot().map_or(0, |r| r.action_dim());
            Ok((env, dim, scene))
        });
        let (env, action_dim, scene) = built.map_err(PyValueError::new_err)?;
        Ok(PyEnv {
            env: Mutex::new(env),
            inside: Mutex::new((0.0, 0)),
            action_dim,
            activity: spec.activity,
            robot: spec.robot,
            scene,
        })
    }

    /// Starts an episode: a new instance sampled with `seed`. Returns `(obs, info)`.
    fn reset<'py>(
        &self,
        py: Python<'py>,
        seed: u64,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let mut guard = self.lock()?;
        let env: &mut Env = &mut guard;
        let (obs, info) = py.detach(|| env.reset(seed)).map_err(env_error)?;
        Ok((obs_dict(py, obs)?, info_dict(py, info.steps, &info.score)?))
    }

    /// One action step (1/30 s). `action`: `action_dim` finite numbers. Returns `(obs, reward,
    /// terminated, truncated, info)`.
    #[allow(clippy::type_complexity)]
    fn step<'py>(
        &self,
        py: Python<'py>,
        action: PyArrayLike1<'py, f32, AllowTypeChange>,
    ) -> PyResult<(Bound<'py, PyDict>, f64, bool, bool, Bound<'py, PyDict>)> {
        let action = action.to_vec().map_err(|_| {
            PyValueError::new_err("the action must be a contiguous one-dimensional array")
        })?;
        let mut guard = self.lock()?;
        let env: &mut Env = &mut guard;
        // Timed inside, so that releasing and taking back the lock counts as the binding's.
        let (step, took) = py.detach(|| {
            let started = Instant::now();
            (env.step(&action), started.elapsed())
        });
        self.count(took);
        let step = step.map_err(env_error)?;
        let info = info_dict(py, step.info.steps, &step.info.score)?;
        Ok((
            obs_dict(py, step.obs)?,
            step.reward,
            step.terminated,
            step.truncated,
            info,
        ))
    }

    /// Seconds spent inside Rust's `Env::step` (the world's step, observations and score) over
    /// the steps taken so far, and how many: `(seconds, steps)`.
    #[getter]
    fn rust_step_time(&self) -> PyResult<(f64, u64)> {
        Ok(*self.inside.lock().map_err(|_| broken())?)
    }

    /// How many numbers an action has (26 for the BehaviorRobot, 11 for Fetch).
    #[getter]
    fn action_dim(&self) -> usize {
        self.action_dim
    }

    /// The activity's name.
    #[getter]
    fn activity(&self) -> &str {
        &self.activity
    }

    /// `behavior` or `fetch`.
    #[getter]
    fn robot(&self) -> &str {
        &self.robot
    }

    /// The home episodes are sampled in.
    #[getter]
    fn scene(&self) -> &str {
        &self.scene
    }

    /// The episode's metrics so far (the per-episode JSON of `behavior run --json`), as a JSON
    /// string; `None` before the first reset.
    fn metrics_json(&self) -> PyResult<Option<String>> {
        let env = self.lock()?;
        env.metrics()
            .map(|m| serde_json::to_string(&m))
            .transpose()
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
}

impl PyEnv {
    /// The environment, or an error if a step panicked while holding it (it never should; the
    /// interpreter must not die of it either way).
    fn lock(&self) -> PyResult<MutexGuard<'_, Env>> {
        self.env.lock().map_err(|_| broken())
    }

    /// Adds a step that took `took` to [`PyEnv::rust_step_time`].
    fn count(&self, took: Duration) {
        if let Ok(mut inside) = self.inside.lock() {
            inside.0 += took.as_secs_f64();
            inside.1 += 1;
        }
    }
}

fn broken() -> PyErr {
    PyRuntimeError::new_err("the environment was left broken by an earlier error")
}

/// Errors of the caller's making (an action, stepping an ended episode) are `ValueError`s;
/// the rest (sampling, sensors) `RuntimeError`s.
fn env_error(e: EnvError) -> PyErr {
    match e {
        EnvError::Action(_) | EnvError::EpisodeOver { .. } | EnvError::NotReset => {
            PyValueError::new_err(e.to_string())
        }
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// The observation as a dict of numpy arrays, each owning its vector.
fn obs_dict(py: Python<'_>, obs: Obs) -> PyResult<Bound<'_, PyDict>> {
    let dict = PyDict::new(py);
    if !obs.proprioception.is_empty() {
        dict.set_item("proprioception", obs.proprioception.into_pyarray(py))?;
    }
    if !obs.task_obs.is_empty() {
        dict.set_item("task_obs", obs.task_obs.into_pyarray(py))?;
    }
    for (name, reading) in obs.sensors {
        let shape = reading.shape;
        let array = match reading.data {
            Pixels::U8(v) => v.into_pyarray(py).reshape(shape)?.into_any(),
            Pixels::U16(v) => v.into_pyarray(py).reshape(shape)?.into_any(),
            Pixels::U32(v) => v.into_pyarray(py).reshape(shape)?.into_any(),
            Pixels::F32(v) => v.into_pyarray(py).reshape(shape)?.into_any(),
        };
        dict.set_item(name, array)?;
    }
    Ok(dict)
}

/// `steps`, `q`, `success` and `conjuncts` (whether each top-level conjunct of the goal holds).
fn info_dict<'py>(py: Python<'py>, steps: u32, score: &Score) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("steps", steps)?;
    dict.set_item("q", score.q)?;
    dict.set_item("success", score.success)?;
    dict.set_item("conjuncts", score.conjuncts.clone())?;
    Ok(dict)
}
