//! Recording episodes from Python and replaying recordings, as `behavior run --record` and
//! `behavior replay --verify` do: an episode's actions (continuous, or those its primitives
//! took, with the symbolic primitives' edits of the world) to MCAP, with state digests at
//! checkpoints; a replay re-simulates it and compares every checkpoint bit for bit. A
//! recording's episode at any of its steps becomes a checkpoint of a Python environment (the
//! start states of Table 1's oracle rows).

use crate::build::catalog;
use behavior_env::record::lerobot::{ExportError, ExportOptions, Format, export};
use behavior_env::record::{ReadError, RecordError, RecordingSetup, read, replay_with, state_at};
use behavior_env::{Checkpoint, Env, EnvConfig};
use behavior_planning::RecordedCall;
use pyo3::exceptions::{PyFileExistsError, PyOSError, PyValueError};
use pyo3::prelude::*;
use serde_json::json;
use std::path::{Path, PathBuf};

/// Starts recording `env`'s episode of the official `activity`, as it is now, to `path`.
pub fn start(path: &Path, env: &mut Env, activity: &str, checkpoint_every: u32) -> PyResult<()> {
    let catalog = catalog().map_err(|e| PyValueError::new_err(e.to_string()))?;
    let definition = catalog
        .source(activity)
        .map_err(|e| PyValueError::new_err(e.to_string()))?
        .text;
    env.record_to(path, RecordingSetup::new(&definition, checkpoint_every))
        .map_err(record_error)
}

/// A recording that could not be written: an `OSError` saying which file and why.
pub fn record_error(e: RecordError) -> PyErr {
    match e {
        RecordError::NoEpisode => PyValueError::new_err(e.to_string()),
        other => PyOSError::new_err(other.to_string()),
    }
}

/// Reads a recording and, with `verify`, re-simulates it: a JSON object with the header's
/// `activity`, `scene`, `seed`, `robot`, `action_space`, the `frames` (steps) and `checkpoints`
/// read (replayed, with `verify`), `q` after each step, `identical` and `first_difference`
/// (with `verify`), `q_final`, `damage` (where reading stopped in a cut or damaged file), the
/// header's `provenance` (who acted) and, with `verify`, the episode's `metrics` at the end.
#[pyfunction]
pub fn replay(py: Python<'_>, path: PathBuf, verify: bool) -> PyResult<String> {
    py.detach(|| -> PyResult<String> {
        let recording = read(&path).map_err(read_error)?;
        let h = &recording.header;
        let mut out = json!({
            "activity": h.activity,
            "scene": h.scene,
            "seed": h.seed,
            "robot": h.robot,
            "action_space": h.action_space,
            "frames": recording.frames.len(),
            "checkpoints": recording.checkpoints.len(),
            "q": recording.frames.iter().map(|f| f.q).collect::<Vec<_>>(),
            "q_final": recording.frames.last().and_then(|f| f.q).or(recording.start_q),
            "identical": null,
            "first_difference": null,
            "damage": recording.damage,
            "provenance": h.provenance,
            "metrics": null,
        });
        if verify {
            let catalog = catalog().map_err(|e| PyValueError::new_err(e.to_string()))?;
            let invalid = |e: behavior_env::record::ReplayError| {
                PyValueError::new_err(format!("replaying {}: {e}", path.display()))
            };
            let config = recording
                .config_from(catalog.knowledge())
                .map_err(invalid)?;
            // Recorded primitives are done again by the planner's code that did them.
            let report = replay_with::<RecordedCall>(&recording, config).map_err(invalid)?;
            out["frames"] = json!(report.frames);
            out["checkpoints"] = json!(report.checkpoints);
            out["identical"] = json!(report.identical);
            out["first_difference"] = json!(report.first_difference);
            out["q_final"] = json!(report.q_final);
            out["metrics"] = json!(report.metrics);
        }
        Ok(out.to_string())
    })
}

/// Writes `recordings` as a LeRobot dataset in the folder `dataset`, in `format`
/// (`lerobot-v3` or `lerobot-v2.1`), with the robot's camera re-rendered at `image_size` pixels
/// (none: no images), as `behavior demos export --lerobot` does; returns its summary as JSON.
#[pyfunction]
#[pyo3(signature = (dataset, recordings, image_size, format))]
pub fn export_lerobot(
    py: Python<'_>,
    dataset: PathBuf,
    recordings: Vec<PathBuf>,
    image_size: Option<u32>,
    format: &str,
) -> PyResult<String> {
    let format = Format::from_name(format).ok_or_else(|| {
        PyValueError::new_err(format!(
            "format must be one of {}, not {format:?}",
            Format::names()
        ))
    })?;
    py.detach(|| -> PyResult<String> {
        let catalog = catalog().map_err(|e| PyValueError::new_err(e.to_string()))?;
        let options = ExportOptions {
            image_side: image_size,
            format,
        };
        let summary = export::<RecordedCall>(catalog.knowledge(), &recordings, &dataset, &options)
            .map_err(export_error)?;
        Ok(serde_json::to_string(&summary).expect("the summary serializes"))
    })
}

/// The episode recorded in `path` as it stood after its step `step`, as a checkpoint for an
/// environment built as `config` (the same activity, robot, home, action space and physics, or
/// a `ValueError` naming what differs): the recording is resumed at its last saved state
/// before the step and its actions (and the planner's edits) taken again up to it, checked bit
/// for bit at every checkpoint on the way.
pub fn checkpoint_at(
    path: &Path,
    step: u32,
    config: &EnvConfig,
    scene: &str,
) -> PyResult<Checkpoint> {
    let recording = read(path).map_err(read_error)?;
    let catalog = catalog().map_err(|e| PyValueError::new_err(e.to_string()))?;
    let invalid = |what: String| PyValueError::new_err(format!("{}: {what}", path.display()));
    let recorded =
        (recording.config_from(catalog.knowledge())).map_err(|e| invalid(e.to_string()))?;
    let h = &recording.header;
    let differences = [
        (
            "activity",
            recorded.activity.name.clone(),
            config.activity.name.clone(),
        ),
        (
            "robot",
            format!("{:?}", recorded.robot),
            format!("{:?}", config.robot),
        ),
        ("home", h.scene.clone(), scene.to_string()),
        (
            "action space",
            format!("{:?}", recorded.action_space),
            format!("{:?}", config.action_space),
        ),
        (
            "physics",
            format!("{:?}", recorded.physics),
            format!("{:?}", config.physics),
        ),
    ];
    if let Some((what, theirs, ours)) = differences.iter().find(|(_, a, b)| a != b) {
        return Err(invalid(format!(
            "the recording's {what} is {theirs}, this environment's {ours}"
        )));
    }
    // Recorded primitives' edits are done again by the planner's code that did them.
    let env =
        state_at::<RecordedCall>(&recording, recorded, step).map_err(|e| invalid(e.to_string()))?;
    env.checkpoint()
        .ok_or_else(|| invalid(format!("no episode at step {step}")))
}

/// An export that failed: `FileExistsError` for a dataset folder in the way, `OSError` for
/// files that could not be read or written, `ValueError` for recordings that cannot be
/// exported.
fn export_error(e: ExportError) -> PyErr {
    match e {
        ExportError::NotEmpty(_) => PyFileExistsError::new_err(e.to_string()),
        ExportError::Write { .. } | ExportError::Parquet { .. } => {
            PyOSError::new_err(e.to_string())
        }
        ExportError::Read {
            source: ReadError::Io { .. },
            ..
        } => PyOSError::new_err(e.to_string()),
        other => PyValueError::new_err(other.to_string()),
    }
}

fn read_error(e: ReadError) -> PyErr {
    match e {
        ReadError::Io { .. } => PyOSError::new_err(e.to_string()),
        other => PyValueError::new_err(other.to_string()),
    }
}
