//! `behavior._core.Env`: one episode loop of `behavior-env`, stepped from Python with the
//! interpreter's lock released, observations handed over as numpy arrays that own the Rust
//! vectors (no copy). Optionally with the primitive action space ([`Primitives`]).

use crate::options::EnvOptions;
use crate::primitives::{Done, PrimitiveError, Primitives};
use crate::record::{self, record_error};
use behavior_env::{Checkpoint, Env, EnvError, Obs, Score};
use behavior_planning::RunError;
use behavior_render::Pixels;
use numpy::{AllowTypeChange, IntoPyArray, PyArrayLike1, PyArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// The episode (which records itself when asked: `Env::record_to`) and, when actions are
/// primitives, their space over its objects.
struct Episode {
    env: Env,
    primitives: Option<Primitives>,
}

/// A BEHAVIOR environment: `reset` and `step` as Gymnasium's, observations as a dict of numpy
/// arrays (`proprioception`, `task_obs`), info as a dict (`steps`, `q`, `success`,
/// `conjuncts`). The Gymnasium class `behavior.BehaviorEnv` wraps it.
/// Each action number's `(low, high)` for the robot of `env` (none without one).
pub(crate) fn action_bounds(env: &Env) -> Vec<(f32, f32)> {
    let bounds = env.robot().map_or(Vec::new(), |r| r.action_bounds());
    bounds.into_iter().map(|[lo, hi]| (lo, hi)).collect()
}

#[pyclass(module = "behavior._core", name = "Env")]
pub struct PyEnv {
    // Env is Send, not Sync: the lock makes the class shareable, as pyo3 asks.
    episode: Mutex<Episode>,
    /// Seconds spent inside the Rust `step`s so far, and how many: what a benchmark subtracts
    /// to find the binding's own cost per step.
    inside: Mutex<(f64, u64)>,
    action_dim: usize,
    action_bounds: Vec<(f32, f32)>,
    activity: String,
    robot: String,
    scene: String,
}

#[pymethods]
impl PyEnv {
    /// Builds the environment of `activity` with `options` (a dict with every field of
    /// [`EnvOptions`]; `behavior.BehaviorEnv` gives the defaults) and starts a first episode
    /// with its seed, so that the shapes are known.
    #[new]
    fn new(py: Python<'_>, activity: String, options: EnvOptions) -> PyResult<PyEnv> {
        let primitives = options
            .primitives
            .as_deref()
            .map(|set| Primitives::new(set, &options.primitive_mode))
            .transpose()
            .map_err(PyValueError::new_err)?;
        let built = py.detach(|| -> Result<(Episode, String), String> {
            let config = options.config(&activity)?;
            let scene = config
                .scenes
                .first()
                .map(|s| s.name.clone())
                .unwrap_or_default();
            let mut episode = Episode {
                env: Env::new(config),
                primitives,
            };
            episode.reset(options.seed).map_err(|e| e.to_string())?;
            Ok((episode, scene))
        });
        let (episode, scene) = built.map_err(PyValueError::new_err)?;
        Ok(PyEnv {
            action_dim: episode.env.robot().map_or(0, |r| r.action_dim()),
            action_bounds: action_bounds(&episode.env),
            episode: Mutex::new(episode),
            inside: Mutex::new((0.0, 0)),
            activity,
            robot: options.robot,
            scene,
        })
    }

    /// Starts an episode: a new instance sampled with `seed`. Returns `(obs, info)`; with
    /// primitives, info has the `action_mask` too.
    fn reset<'py>(
        &self,
        py: Python<'py>,
        seed: u64,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let mut guard = self.lock()?;
        let episode: &mut Episode = &mut guard;
        episode.stop_recording()?;
        let (obs, info) = py.detach(|| episode.reset(seed)).map_err(env_error)?;
        let dict = info_dict(py, info.steps, &info.score)?;
        episode.add_mask(py, &dict)?;
        Ok((obs_dict(py, obs)?, dict))
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
        let Episode { env, .. } = &mut *guard;
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

    /// One primitive action `a` of the primitive space, run to its end (object `a mod n`,
    /// primitive `a div n`). Returns `(obs, reward, terminated, truncated, info)`: the last
    /// step's observation, ΔQ over the whole primitive, and info with `primitive`, `object`,
    /// `hand`, `ok`, `reason` (why it failed, or `None`) and the next `action_mask`.
    #[allow(clippy::type_complexity)]
    fn step_primitive<'py>(
        &self,
        py: Python<'py>,
        a: usize,
    ) -> PyResult<(Bound<'py, PyDict>, f64, bool, bool, Bound<'py, PyDict>)> {
        let mut guard = self.lock()?;
        let Episode { env, primitives } = &mut *guard;
        let primitives = primitives.as_ref().ok_or_else(|| {
            PyValueError::new_err("this environment's actions are continuous, not primitives")
        })?;
        let done = py
            .detach(|| primitives.step(env, a))
            .map_err(primitive_error)?;
        let Done {
            step,
            reward,
            primitive,
            object,
            hand,
            failure,
        } = done;
        let info = info_dict(py, step.info.steps, &step.info.score)?;
        info.set_item("primitive", primitive)?;
        info.set_item("object", object)?;
        info.set_item("hand", hand)?;
        info.set_item("ok", failure.is_none())?;
        info.set_item("reason", failure)?;
        guard.add_mask(py, &info)?;
        Ok((
            obs_dict(py, step.obs)?,
            reward,
            step.terminated,
            step.truncated,
            info,
        ))
    }

    /// How many primitive actions (n × K; 0 without primitives).
    #[getter]
    fn primitive_count(&self) -> PyResult<usize> {
        Ok(self.lock()?.primitives.as_ref().map_or(0, Primitives::len))
    }

    /// What each primitive action does, in action order: `(primitive, object)` names (empty
    /// without primitives).
    fn primitive_actions(&self) -> PyResult<Vec<(&'static str, String)>> {
        let guard = self.lock()?;
        Ok(guard
            .primitives
            .as_ref()
            .map_or_else(Vec::new, |p| p.meanings(&guard.env)))
    }

    /// Whether each primitive action's preconditions hold now (for MaskablePPO).
    fn action_mask<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let guard = self.lock()?;
        Ok(guard.mask().into_pyarray(py).into_any())
    }

    /// Seconds spent inside Rust's `Env::step` (the world's step, observations and score) over
    /// the steps taken so far, and how many: `(seconds, steps)`.
    #[getter]
    fn rust_step_time(&self) -> PyResult<(f64, u64)> {
        Ok(*self.inside.lock().map_err(|_| broken())?)
    }

    /// How many numbers a continuous action has (26 for the BehaviorRobot, 11 for Fetch, 23
    /// for the R1).
    #[getter]
    fn action_dim(&self) -> usize {
        self.action_dim
    }

    /// Each action number's `(low, high)`: (−1, 1), or a joint's limits where the number is
    /// its position (the R1's); values beyond are clipped.
    #[getter]
    fn action_bounds(&self) -> Vec<(f32, f32)> {
        self.action_bounds.clone()
    }

    /// The activity's name.
    #[getter]
    fn activity(&self) -> &str {
        &self.activity
    }

    /// `behavior`, `fetch` or `r1`.
    #[getter]
    fn robot(&self) -> &str {
        &self.robot
    }

    /// The home episodes are sampled in.
    #[getter]
    fn scene(&self) -> &str {
        &self.scene
    }

    /// The episode as it is now, to go back to with `restore`.
    fn checkpoint(&self) -> PyResult<PyCheckpoint> {
        let guard = self.lock()?;
        let checkpoint = guard.env.checkpoint().ok_or_else(|| {
            PyValueError::new_err("there is no episode to checkpoint: reset first")
        })?;
        Ok(PyCheckpoint {
            checkpoint,
            owner: self.identity(),
        })
    }

    /// Goes back to `checkpoint` (of this environment's activity, robot and home); the episode
    /// continues from there bit for bit. Returns `(obs, info)` as `reset` does. Restoring a
    /// checkpoint taken just after `reset(seed)` is that reset without sampling again.
    fn restore<'py>(
        &self,
        py: Python<'py>,
        checkpoint: &PyCheckpoint,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        if checkpoint.owner != self.identity() {
            return Err(PyValueError::new_err(format!(
                "the checkpoint is of {}, not of this environment ({})",
                checkpoint.owner,
                self.identity()
            )));
        }
        let mut guard = self.lock()?;
        let episode: &mut Episode = &mut guard;
        episode.stop_recording()?;
        let obs = py
            .detach(|| episode.restore(&checkpoint.checkpoint))
            .map_err(env_error)?;
        let score = episode.env.score().cloned().unwrap_or_default();
        let dict = info_dict(py, episode.env.steps(), &score)?;
        episode.add_mask(py, &dict)?;
        Ok((obs_dict(py, obs)?, dict))
    }

    /// The episode recorded in `path` (by this activity, robot and home) as it stood after its
    /// step `step`, as a checkpoint of this environment to `restore`: a start state taken from
    /// a demonstration. Re-simulated from the recording's last saved state before the step,
    /// bit for bit at every checkpoint on the way.
    fn checkpoint_from_recording(
        &self,
        py: Python<'_>,
        path: PathBuf,
        step: u32,
    ) -> PyResult<PyCheckpoint> {
        let config = self.lock()?.env.config().clone();
        let checkpoint = py.detach(|| record::checkpoint_at(&path, step, &config, &self.scene))?;
        Ok(PyCheckpoint {
            checkpoint,
            owner: self.identity(),
        })
    }

    /// How many literals the goal's first option has (a smallest option): ΔQ times this
    /// counts goal literals reached, one each.
    #[getter]
    fn goal_literals(&self) -> PyResult<usize> {
        Ok(self.lock()?.env.goal_literals())
    }

    /// Records the episode from now on to `path` (MCAP; `behavior.replay` and `behavior replay`
    /// read it), a state digest every `checkpoint_every` steps; until `stop_recording`, the
    /// next `reset` or `restore`, or the environment's end. A recording under way is finished
    /// first.
    #[pyo3(signature = (path, checkpoint_every = 30))]
    fn record(&self, py: Python<'_>, path: PathBuf, checkpoint_every: u32) -> PyResult<()> {
        let mut guard = self.lock()?;
        let episode: &mut Episode = &mut guard;
        episode.stop_recording()?;
        let (env, activity) = (&mut episode.env, &self.activity);
        py.detach(move || record::start(&path, env, activity, checkpoint_every))
    }

    /// Finishes the recording under way (its summary and index written); nothing if none is.
    fn stop_recording(&self) -> PyResult<()> {
        self.lock()?.stop_recording()
    }

    /// Whether a recording is under way.
    #[getter]
    fn recording(&self) -> PyResult<bool> {
        Ok(self.lock()?.env.is_recording())
    }

    /// The episode's metrics so far (the per-episode JSON of `behavior run --json`), as a JSON
    /// string; `None` before the first reset.
    fn metrics_json(&self) -> PyResult<Option<String>> {
        let guard = self.lock()?;
        guard
            .env
            .metrics()
            .map(|m| serde_json::to_string(&m))
            .transpose()
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
}

impl Episode {
    /// A new episode; the primitives find its objects.
    fn reset(&mut self, seed: u64) -> Result<(Obs, behavior_env::Info), EnvError> {
        let started = self.env.reset(seed)?;
        if let Some(p) = &mut self.primitives {
            p.reset(&self.env);
        }
        Ok(started)
    }

    /// Finishes the recording under way, if any.
    fn stop_recording(&mut self) -> PyResult<()> {
        self.env.finish_recording().map_err(record_error)
    }

    /// Back to a checkpoint; the primitives find its objects.
    fn restore(&mut self, checkpoint: &Checkpoint) -> Result<Obs, EnvError> {
        self.env.restore(checkpoint);
        if let Some(p) = &mut self.primitives {
            p.reset(&self.env);
        }
        self.env.observe()
    }

    /// The primitive actions' mask (empty without primitives).
    fn mask(&self) -> Vec<bool> {
        self.primitives
            .as_ref()
            .map_or_else(Vec::new, |p| p.mask(&self.env))
    }

    /// Adds `action_mask` to `info` when actions are primitives.
    fn add_mask(&self, py: Python<'_>, info: &Bound<'_, PyDict>) -> PyResult<()> {
        if self.primitives.is_some() {
            info.set_item("action_mask", self.mask().into_pyarray(py))?;
        }
        Ok(())
    }
}

impl Drop for Episode {
    /// A recording still under way is finished when the environment goes; an error there has
    /// no one to go to, and the file still reads up to its last whole chunk.
    fn drop(&mut self) {
        let _ = self.env.finish_recording();
    }
}

/// An episode as it was at one step (`Env.checkpoint()`), for `Env.restore`. Opaque; only for
/// environments of the same activity, robot and home.
#[pyclass(module = "behavior._core", name = "Checkpoint", frozen)]
pub struct PyCheckpoint {
    checkpoint: Checkpoint,
    /// `activity / robot / home` of the environment it came from.
    owner: String,
}

impl PyEnv {
    /// What a checkpoint must have come from: `activity / robot / home`.
    fn identity(&self) -> String {
        format!("{} / {} / {}", self.activity, self.robot, self.scene)
    }

    /// The episode, or an error if a step panicked while holding it (it never should; the
    /// interpreter must not die of it either way).
    fn lock(&self) -> PyResult<MutexGuard<'_, Episode>> {
        self.episode.lock().map_err(|_| broken())
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
pub(crate) fn env_error(e: EnvError) -> PyErr {
    match e {
        EnvError::Action(_) | EnvError::EpisodeOver { .. } | EnvError::NotReset => {
            PyValueError::new_err(e.to_string())
        }
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// An action out of range is the caller's; the episode's refusals as [`env_error`].
fn primitive_error(e: PrimitiveError) -> PyErr {
    match e {
        PrimitiveError::Run(RunError::Env(e)) => env_error(e),
        PrimitiveError::Run(RunError::Record(e)) => record_error(e),
        other => PyValueError::new_err(other.to_string()),
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
