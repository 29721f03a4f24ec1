//! `behavior._core.VecEnv`: N environments of one activity stepped together, the first on the
//! calling thread and each other one on a thread of a pool (rayon), while the interpreter's
//! lock is released, observations batched into `(N, …)` numpy arrays. Ended episodes reset on
//! the next step, as Gymnasium 1.x's vector environments do by default (autoreset "next
//! step"): that step ignores the environment's action and returns the new episode's first
//! observation, reward 0, neither terminated nor truncated.
//!
//! Seeds: `reset(seed)` starts environment k with `seed + k` (Gymnasium's convention); the
//! e-th episode environment k starts by itself after that has the seed [`derived_seed`] of its
//! last reset seed and e, so a run is the same for the same seed and actions.

use crate::env::env_error;
use crate::options::EnvOptions;
use behavior_env::{Env, EnvError, Obs, Score, derived_seed};
use behavior_render::Pixels;
use numpy::{AllowTypeChange, IntoPyArray, PyArrayLike2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Mutex;

/// One environment of the batch and where its episodes stand.
struct Slot {
    env: Env,
    /// Its episode ended at the last step: the next step resets it.
    ended: bool,
    /// The seed of its last `reset`, and how many episodes it started by itself since.
    seed: u64,
    episodes: u64,
}

/// What one environment gave back for one step (or reset).
struct Outcome {
    obs: Obs,
    reward: f64,
    terminated: bool,
    truncated: bool,
    steps: u32,
    score: Score,
}

/// N environments of one activity, stepped in parallel (see the module docs).
#[pyclass(module = "behavior._core", name = "VecEnv")]
pub struct PyVecEnv {
    slots: Mutex<Vec<Slot>>,
    pool: rayon::ThreadPool,
    action_dim: usize,
    action_bounds: Vec<(f32, f32)>,
}

#[pymethods]
impl PyVecEnv {
    /// Builds `num_envs` environments of `activity` with `options` (as `Env`'s; continuous
    /// actions) and resets environment k with `seed + k`.
    #[new]
    fn new(
        py: Python<'_>,
        activity: String,
        num_envs: usize,
        options: EnvOptions,
    ) -> PyResult<PyVecEnv> {
        if num_envs == 0 {
            return Err(PyValueError::new_err("num_envs must be at least 1"));
        }
        if options.primitives.is_some() {
            return Err(PyValueError::new_err(
                "the vector environment takes continuous actions, not primitives",
            ));
        }
        // The calling thread steps the first environment itself (see `each`).
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(num_envs.min(available_cores()).saturating_sub(1).max(1))
            .build()
            .map_err(|e| PyRuntimeError::new_err(format!("starting threads: {e}")))?;
        let seed = options.seed;
        let slots = py.detach(|| -> Result<Vec<Slot>, String> {
            let config = options.config(&activity)?;
            let mut slots: Vec<Slot> = (0..num_envs as u64)
                .map(|k| Slot {
                    env: Env::new(config.clone()),
                    ended: false,
                    seed: seed.wrapping_add(k),
                    episodes: 0,
                })
                .collect();
            each(&pool, &mut slots, |_, s| s.env.reset(s.seed).map(drop))
                .into_iter()
                .collect::<Result<(), EnvError>>()
                .map_err(|e| e.to_string())?;
            Ok(slots)
        });
        let slots = slots.map_err(PyValueError::new_err)?;
        let action_dim = slots[0].env.robot().map_or(0, |r| r.action_dim());
        let action_bounds = crate::env::action_bounds(&slots[0].env);
        Ok(PyVecEnv {
            slots: Mutex::new(slots),
            pool,
            action_dim,
            action_bounds,
        })
    }

    /// Resets every environment, k with `seed + k`. Returns `(obs, info)`, batched.
    fn reset<'py>(
        &self,
        py: Python<'py>,
        seed: u64,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let mut slots = self.slots.lock().map_err(|_| broken())?;
        let slots: &mut Vec<Slot> = &mut slots;
        let outcomes = py.detach(|| {
            each(&self.pool, slots, |k, s| {
                s.seed = seed.wrapping_add(k as u64);
                s.episodes = 0;
                s.ended = false;
                restart(s, s.seed)
            })
            .into_iter()
            .collect::<Result<Vec<Outcome>, EnvError>>()
        });
        let outcomes = outcomes.map_err(env_error)?;
        Ok((batch_obs(py, &outcomes)?, batch_info(py, &outcomes)?))
    }

    /// One step of every environment: `actions` is `(num_envs, action_dim)`. Returns `(obs,
    /// rewards, terminated, truncated, info)`, batched; an environment whose episode ended at
    /// the last step is reset instead (see the module docs).
    #[allow(clippy::type_complexity)]
    fn step<'py>(
        &self,
        py: Python<'py>,
        actions: PyArrayLike2<'py, f32, AllowTypeChange>,
    ) -> PyResult<(
        Bound<'py, PyDict>,
        Bound<'py, PyAny>,
        Bound<'py, PyAny>,
        Bound<'py, PyAny>,
        Bound<'py, PyDict>,
    )> {
        let mut slots = self.slots.lock().map_err(|_| broken())?;
        let shape = actions.shape();
        if shape != [slots.len(), self.action_dim] {
            return Err(PyValueError::new_err(format!(
                "actions must have shape ({}, {}), not {shape:?}",
                slots.len(),
                self.action_dim
            )));
        }
        let rows: Vec<Vec<f32>> = actions
            .as_array()
            .outer_iter()
            .map(|r| r.to_vec())
            .collect();
        // Checked for all before any steps: a bad action leaves every environment as it was.
        if let Some((k, i, v)) = first_not_finite(&rows) {
            return Err(PyValueError::new_err(format!(
                "action value [{k}, {i}] is {v}; every value must be a finite number"
            )));
        }
        let slots: &mut Vec<Slot> = &mut slots;
        let outcomes = py.detach(|| {
            each(&self.pool, slots, |k, s| step_one(s, &rows[k]))
                .into_iter()
                .collect::<Result<Vec<Outcome>, EnvError>>()
        });
        let outcomes = outcomes.map_err(env_error)?;
        let rewards: Vec<f64> = outcomes.iter().map(|o| o.reward).collect();
        let terminated: Vec<bool> = outcomes.iter().map(|o| o.terminated).collect();
        let truncated: Vec<bool> = outcomes.iter().map(|o| o.truncated).collect();
        Ok((
            batch_obs(py, &outcomes)?,
            rewards.into_pyarray(py).into_any(),
            terminated.into_pyarray(py).into_any(),
            truncated.into_pyarray(py).into_any(),
            batch_info(py, &outcomes)?,
        ))
    }

    /// How many environments.
    #[getter]
    fn num_envs(&self) -> PyResult<usize> {
        Ok(self.slots.lock().map_err(|_| broken())?.len())
    }

    /// Each action number's `(low, high)` (see `Env.action_bounds`).
    #[getter]
    fn action_bounds(&self) -> Vec<(f32, f32)> {
        self.action_bounds.clone()
    }

    /// How many numbers one environment's action has.
    #[getter]
    fn action_dim(&self) -> usize {
        self.action_dim
    }
}

/// `work` done on every slot at once, its results in the slots' order: the first slot on the
/// calling thread, the others on the pool's threads. (Waiting idle in the pool's `install`
/// while its threads stepped both was slower: 6,583 against 8,042 environment steps a second
/// for a vector of two on two cores, in one pair of runs of the same script.)
fn each<T: Send>(
    pool: &rayon::ThreadPool,
    slots: &mut [Slot],
    work: impl Fn(usize, &mut Slot) -> T + Sync,
) -> Vec<T> {
    let mut out: Vec<Option<T>> = slots.iter().map(|_| None).collect();
    let work = &work;
    pool.in_place_scope(|scope| {
        let mut jobs = slots.iter_mut().zip(out.iter_mut()).enumerate();
        let first = jobs.next();
        for (k, (slot, result)) in jobs {
            scope.spawn(move |_| *result = Some(work(k, slot)));
        }
        if let Some((k, (slot, result))) = first {
            *result = Some(work(k, slot));
        }
    });
    out.into_iter()
        .map(|r| r.expect("the scope ends after every job has run"))
        .collect()
}

/// The first value that is NaN or infinite: environment, index, value.
fn first_not_finite(rows: &[Vec<f32>]) -> Option<(usize, usize, f32)> {
    rows.iter().enumerate().find_map(|(k, row)| {
        row.iter()
            .position(|v| !v.is_finite())
            .map(|i| (k, i, row[i]))
    })
}

/// Steps one environment, or restarts it if its episode ended at the last step.
fn step_one(slot: &mut Slot, action: &[f32]) -> Result<Outcome, EnvError> {
    if slot.ended {
        slot.ended = false;
        slot.episodes += 1;
        let seed = derived_seed(slot.seed, slot.episodes);
        return restart(slot, seed);
    }
    let step = slot.env.step(action)?;
    slot.ended = step.terminated || step.truncated;
    Ok(Outcome {
        obs: step.obs,
        reward: step.reward,
        terminated: step.terminated,
        truncated: step.truncated,
        steps: step.info.steps,
        score: step.info.score,
    })
}

/// A new episode of the slot's environment with `seed`.
fn restart(slot: &mut Slot, seed: u64) -> Result<Outcome, EnvError> {
    let (obs, info) = slot.env.reset(seed)?;
    Ok(Outcome {
        obs,
        reward: 0.0,
        terminated: false,
        truncated: false,
        steps: info.steps,
        score: info.score,
    })
}

fn available_cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn broken() -> PyErr {
    PyRuntimeError::new_err("the environments were left broken by an earlier error")
}

/// Which of an observation's vectors.
type VectorOf = fn(&Obs) -> &Vec<f32>;

/// Each observation key as one `(N, …)` array (the environments' readings have the same
/// shapes: one activity, one robot, the same sensors).
fn batch_obs<'py>(py: Python<'py>, outcomes: &[Outcome]) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let n = outcomes.len();
    let first = &outcomes[0].obs;
    let vectors: [(&str, VectorOf); 2] = [
        ("proprioception", |o| &o.proprioception),
        ("task_obs", |o| &o.task_obs),
    ];
    for (name, of) in vectors {
        let width = of(first).len();
        if width > 0 {
            let all: Vec<f32> = outcomes
                .iter()
                .flat_map(|o| of(&o.obs).iter().copied())
                .collect();
            dict.set_item(name, all.into_pyarray(py).reshape([n, width])?)?;
        }
    }
    for (k, (name, reading)) in first.sensors.iter().enumerate() {
        let mut shape = vec![n];
        shape.extend(&reading.shape);
        let readings = outcomes.iter().map(|o| &o.obs.sensors[k].1.data);
        let array = match &reading.data {
            Pixels::U8(_) => stack(readings, |p| match p {
                Pixels::U8(v) => Some(v),
                _ => None,
            })
            .into_pyarray(py)
            .reshape(shape)?
            .into_any(),
            Pixels::U16(_) => stack(readings, |p| match p {
                Pixels::U16(v) => Some(v),
                _ => None,
            })
            .into_pyarray(py)
            .reshape(shape)?
            .into_any(),
            Pixels::U32(_) => stack(readings, |p| match p {
                Pixels::U32(v) => Some(v),
                _ => None,
            })
            .into_pyarray(py)
            .reshape(shape)?
            .into_any(),
            Pixels::F32(_) => stack(readings, |p| match p {
                Pixels::F32(v) => Some(v),
                _ => None,
            })
            .into_pyarray(py)
            .reshape(shape)?
            .into_any(),
        };
        dict.set_item(name, array)?;
    }
    Ok(dict)
}

/// The readings of one kind, one after the other.
fn stack<'a, T: Copy + 'a>(
    readings: impl Iterator<Item = &'a Pixels>,
    of: impl Fn(&'a Pixels) -> Option<&'a Vec<T>>,
) -> Vec<T> {
    readings
        .filter_map(of)
        .flat_map(|v| v.iter().copied())
        .collect()
}

/// `steps`, `q`, `success` as arrays over the environments (Gymnasium's vector info), each with
/// its `_name` mask (every environment has them).
fn batch_info<'py>(py: Python<'py>, outcomes: &[Outcome]) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let all = vec![true; outcomes.len()];
    let steps: Vec<u32> = outcomes.iter().map(|o| o.steps).collect();
    let q: Vec<f64> = outcomes.iter().map(|o| o.score.q).collect();
    let success: Vec<bool> = outcomes.iter().map(|o| o.score.success).collect();
    dict.set_item("steps", steps.into_pyarray(py))?;
    dict.set_item("q", q.into_pyarray(py))?;
    dict.set_item("success", success.into_pyarray(py))?;
    for name in ["_steps", "_q", "_success"] {
        dict.set_item(name, all.clone().into_pyarray(py))?;
    }
    Ok(dict)
}
