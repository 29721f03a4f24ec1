//! Recordings as a LeRobot dataset (format v3.0 or v2.1, [`Format`]), for imitation learning:
//! [`export`].
//!
//! Each recording is re-simulated (the episode begun again, every recorded action and edit done
//! again, as [`super::replay_with`] does), so the dataset carries what the agent observed at
//! every step — proprioception, `task_obs` and, with images, the robot's camera rendered again —
//! though the recording keeps only actions. A recording that does not re-simulate identically
//! (a checkpoint's digest differs) or is cut is refused, naming the file: a dataset must hold
//! the episodes as they happened. The dataset is written beside its folder and moved there only
//! when whole, so a failed export leaves nothing half-written and overwrites nothing.
//!
//! The command line (`behavior demos export --lerobot`) and Python
//! (`behavior.recording.export_lerobot`) both call [`export`].

mod dataset;
mod stats;
mod v30;

pub use dataset::Shapes;

use super::{Provenance, ReadError, Recording, ReplayError, read, redo, state_digest};
use crate::edit::WorldEdit;
use crate::env::Env;
use crate::episode::Start;
use crate::observation::Obs;
use crate::sensors::CameraConfig;
use behavior_bddl::Knowledge;
use behavior_render::{Modality, Pixels};
use dataset::{Dataset, Episode, write_error};
use serde::Serialize;
use serde_json::json;
use std::path::{Path, PathBuf};

/// The camera images' side may be this many pixels at least …
pub const MIN_IMAGE_SIDE: u32 = 16;
/// … and this many at most.
pub const MAX_IMAGE_SIDE: u32 = 1024;

/// Which of LeRobot's dataset layouts to write.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Format {
    /// v3.0: many episodes to a file, the episodes' metadata as Parquet; what LeRobot 0.4 reads
    /// and the BEHAVIOR Challenge's demonstrations use.
    #[default]
    V30,
    /// v2.1: an episode to a file, JSON-lines metadata; what LeRobot 0.3 reads.
    V21,
}

impl Format {
    /// Every format, by the names [`Format::from_name`] takes.
    pub const ALL: [Format; 2] = [Format::V30, Format::V21];

    /// The format's name: `lerobot-v3` or `lerobot-v2.1`.
    pub fn name(self) -> &'static str {
        match self {
            Format::V30 => "lerobot-v3",
            Format::V21 => "lerobot-v2.1",
        }
    }

    /// Every format's name, for a message: `lerobot-v3, lerobot-v2.1`.
    pub fn names() -> String {
        let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
        names.join(", ")
    }

    /// The format named `name` (`lerobot-v3.0` is taken for `lerobot-v3` too).
    pub fn from_name(name: &str) -> Option<Format> {
        match name {
            "lerobot-v3" | "lerobot-v3.0" => Some(Format::V30),
            "lerobot-v2.1" => Some(Format::V21),
            _ => None,
        }
    }
}

/// How to export.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportOptions {
    /// The side of the robot's camera images (`observation.images.eye`), pixels; `None` leaves
    /// the images out.
    pub image_side: Option<u32>,
    /// The dataset's layout.
    pub format: Format,
}

impl Default for ExportOptions {
    fn default() -> Self {
        ExportOptions {
            image_side: Some(behavior_render::EYE_SIZE),
            format: Format::default(),
        }
    }
}

/// What an export wrote.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ExportSummary {
    /// The dataset's folder.
    pub dataset: PathBuf,
    /// The format written.
    pub format: &'static str,
    /// Episodes written, one per recording.
    pub episodes: usize,
    /// Frames written, over all episodes.
    pub frames: usize,
    /// Episodes whose recordings hold a person's device reports.
    pub teleoperated: usize,
    /// Episodes whose recordings say the planner chose their actions.
    pub planned: usize,
    /// Whether the camera images were written.
    pub images: bool,
    /// Each recording and its frames, in the dataset's order.
    pub recordings: Vec<(PathBuf, usize)>,
}

/// Why an export failed; nothing was left under the dataset's name.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The dataset's folder is already there with something in it.
    #[error("{} exists and is not empty: give a new folder (nothing there is overwritten)", .0.display())]
    NotEmpty(PathBuf),
    /// The image side asked for is out of range.
    #[error("the images' side must be {MIN_IMAGE_SIDE}–{MAX_IMAGE_SIDE} pixels, not {0}")]
    ImageSide(u32),
    /// No recording was given.
    #[error("no recordings to export")]
    NoRecordings,
    /// A recording could not be read.
    #[error("{}: {source}", file.display())]
    Read {
        /// The recording.
        file: PathBuf,
        /// Why.
        source: ReadError,
    },
    /// A recording is cut or damaged.
    #[error("{}: {damage}; a dataset takes only whole episodes", file.display())]
    Damaged {
        /// The recording.
        file: PathBuf,
        /// Where reading stopped.
        damage: String,
    },
    /// A recording could not be re-simulated, or re-simulated differently (recorded with
    /// another build?).
    #[error("{}: {source}; it is not exported", file.display())]
    Replay {
        /// The recording.
        file: PathBuf,
        /// Why.
        source: ReplayError,
    },
    /// The camera gave no colour image.
    #[error("{}: the robot's camera gave no colour image", .0.display())]
    NoImage(PathBuf),
    /// A recording is not of the dataset's robot or shapes.
    #[error(
        "{}: {found}; the dataset's first episode is {expected} (one dataset, one robot and one \
         set of shapes)",
        file.display()
    )]
    Mixed {
        /// The recording.
        file: PathBuf,
        /// Its robot and shapes, in words.
        found: String,
        /// The dataset's robot and shapes, in words.
        expected: String,
    },
    /// An episode's columns do not agree in length or size (a fault of this module).
    #[error("an episode's frames do not line up: {0}")]
    Shape(String),
    /// A file or folder could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// Which.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A Parquet file could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Parquet {
        /// Which.
        path: PathBuf,
        /// Why.
        source: parquet::errors::ParquetError,
    },
}

/// Writes `recordings` (one episode each, all of one robot) as a LeRobot dataset in the
/// folder `dataset`, which must not exist or be empty. `E` reads the recordings' edits of the
/// world (the planner's primitives: `behavior_planning::RecordedCall`); `knowledge` parses
/// each recording's definition.
pub fn export<E: WorldEdit>(
    knowledge: &Knowledge,
    recordings: &[PathBuf],
    dataset: &Path,
    options: &ExportOptions,
) -> Result<ExportSummary, ExportError> {
    if let Some(side) = options.image_side
        && !(MIN_IMAGE_SIDE..=MAX_IMAGE_SIDE).contains(&side)
    {
        return Err(ExportError::ImageSide(side));
    }
    if recordings.is_empty() {
        return Err(ExportError::NoRecordings);
    }
    if dataset.read_dir().is_ok_and(|mut d| d.next().is_some()) {
        return Err(ExportError::NotEmpty(dataset.to_path_buf()));
    }
    let partial = dataset.with_extension(format!("partial-{}", std::process::id()));
    let written = write::<E>(knowledge, recordings, &partial, options)
        .and_then(|summary| move_into(&partial, dataset).map(|()| summary));
    match written {
        Ok(mut summary) => {
            summary.dataset = dataset.to_path_buf();
            Ok(summary)
        }
        Err(e) => {
            let _ = std::fs::remove_dir_all(&partial);
            Err(e)
        }
    }
}

/// The whole dataset at `partial` moved to `dataset` (an empty folder there replaced).
fn move_into(partial: &Path, dataset: &Path) -> Result<(), ExportError> {
    if dataset.exists() {
        std::fs::remove_dir(dataset).map_err(write_error(dataset))?;
    }
    std::fs::rename(partial, dataset).map_err(write_error(dataset))
}

/// Writes every recording into `dir`.
fn write<E: WorldEdit>(
    knowledge: &Knowledge,
    recordings: &[PathBuf],
    dir: &Path,
    options: &ExportOptions,
) -> Result<ExportSummary, ExportError> {
    let mut dataset: Option<Dataset> = None;
    let mut summary = ExportSummary {
        dataset: dir.to_path_buf(),
        format: options.format.name(),
        episodes: 0,
        frames: 0,
        teleoperated: 0,
        planned: 0,
        images: options.image_side.is_some(),
        recordings: Vec::new(),
    };
    for file in recordings {
        let recording = read(file).map_err(|source| ExportError::Read {
            file: file.clone(),
            source,
        })?;
        if let Some(damage) = &recording.damage {
            return Err(ExportError::Damaged {
                file: file.clone(),
                damage: damage.to_string(),
            });
        }
        let (episode, shapes) = resimulate::<E>(file, &recording, knowledge, options.image_side)?;
        let robot = &recording.header.robot;
        let dataset = match &mut dataset {
            Some(d) => d,
            None => dataset.insert(Dataset::create(dir, options.format, robot, shapes)?),
        };
        if dataset.shapes() != shapes || dataset.robot() != robot {
            let described =
                |robot: &str, shapes: Shapes| format!("a {robot} robot's with {shapes:?}");
            return Err(ExportError::Mixed {
                file: file.clone(),
                found: described(robot, shapes),
                expected: described(dataset.robot(), dataset.shapes()),
            });
        }
        dataset.add(&episode)?;
        summary.teleoperated += usize::from(!recording.devices.is_empty());
        summary.planned += usize::from(matches!(
            recording.header.provenance,
            Provenance::Planner { .. }
        ));
        summary
            .recordings
            .push((file.clone(), episode.action.len()));
    }
    let dataset = dataset.ok_or(ExportError::NoRecordings)?;
    (summary.episodes, summary.frames) = dataset.finish()?;
    write_card(dir, &summary)?;
    Ok(summary)
}

/// One recording re-simulated into an episode's frames.
fn resimulate<E: WorldEdit>(
    file: &Path,
    recording: &Recording,
    knowledge: &Knowledge,
    image: Option<u32>,
) -> Result<(Episode, Shapes), ExportError> {
    let replay = |source| ExportError::Replay {
        file: file.to_path_buf(),
        source,
    };
    let mut config = recording.config_from(knowledge).map_err(replay)?;
    config.observations.camera = image.map(|side| CameraConfig {
        modalities: vec![Modality::Rgb],
        width: side,
        height: side,
        ..CameraConfig::default()
    });
    let h = &recording.header;
    let mut env = Env::new(config);
    let start = Start {
        seed: h.seed,
        instance: h.instance.clone(),
    };
    let (mut obs, _) = env
        .reset_to(start)
        .map_err(|source| replay(ReplayError::Env { step: 0, source }))?;
    let mut episode = Episode {
        task: task_text(&h.activity),
        provenance: json!({"recording": file.display().to_string(), "activity": h.activity,
            "scene": h.scene, "seed": h.seed, "by": h.provenance,
            "teleoperated": recording.device_steps()}),
        ..Episode::default()
    };
    let mut q = env.score().map_or(0.0, |s| s.q);
    let mut edits = recording.edits.iter().peekable();
    for frame in &recording.frames {
        let mut edited = false;
        while let Some((step, edit)) = edits.next_if(|(s, _)| *s < frame.step) {
            redo::<E>(&mut env, *step, edit).map_err(replay)?;
            edited = true;
        }
        // An edit (a symbolic primitive) moved things: observe them as they are now.
        if edited {
            obs = env.observe().map_err(|source| {
                replay(ReplayError::Env {
                    step: frame.step,
                    source,
                })
            })?;
        }
        push_observation(file, &mut episode, &obs, image.is_some())?;
        let step = env.step(&frame.action).map_err(|source| {
            replay(ReplayError::Env {
                step: frame.step,
                source,
            })
        })?;
        episode.action.push(frame.action.clone());
        episode.reward.push((step.info.score.q - q) as f32);
        episode.success.push(step.info.score.success);
        q = step.info.score.q;
        obs = step.obs;
        check(recording, &env).map_err(replay)?;
    }
    let shapes = Shapes {
        state: episode.state.first().map_or(0, Vec::len),
        environment: episode.environment.first().map_or(0, Vec::len),
        action: episode.action.first().map_or(0, Vec::len),
        image,
    };
    Ok((episode, shapes))
}

/// The task as LeRobot's language-conditioned policies read it: the activity's name in words,
/// without the problem's instance number (`throwing_away_leftovers_0` → `throwing away
/// leftovers`).
fn task_text(activity: &str) -> String {
    let name = match activity.rsplit_once('_') {
        Some((stem, n)) if !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) => stem,
        _ => activity,
    };
    name.replace('_', " ")
}

fn push_observation(
    file: &Path,
    episode: &mut Episode,
    obs: &Obs,
    images: bool,
) -> Result<(), ExportError> {
    episode.state.push(obs.proprioception.clone());
    episode.environment.push(obs.task_obs.clone());
    if images {
        let Some(Pixels::U8(rgb)) = obs.get("rgb").map(|r| &r.data) else {
            return Err(ExportError::NoImage(file.to_path_buf()));
        };
        episode.images.push(rgb.clone());
    }
    Ok(())
}

/// The state against the recording's checkpoint at this step, if it has one.
fn check(recording: &Recording, env: &Env) -> Result<(), ReplayError> {
    let step = env.steps();
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Ok(());
    };
    for (_, digest) in recording.checkpoints.iter().filter(|(s, _)| *s == step) {
        if *digest != state_digest(world, robot, step) {
            return Err(ReplayError::Differs(step));
        }
    }
    Ok(())
}

/// The dataset's README: where its episodes came from, and whether people made them.
fn write_card(dir: &Path, summary: &ExportSummary) -> Result<(), ExportError> {
    let (episodes, teleoperated, planned) =
        (summary.episodes, summary.teleoperated, summary.planned);
    let other = episodes - teleoperated - planned;
    let who = format!(
        "{teleoperated} of them were teleoperated by a person (their recordings hold device \
         reports); {planned} were made by the task planner, NOT by people; {other} are agents' \
         or of unstated provenance."
    );
    let list: String = summary
        .recordings
        .iter()
        .enumerate()
        .map(|(i, (r, _))| format!("- episode {i}: `{}`\n", r.display()))
        .collect();
    let (version, meta) = match summary.format {
        "lerobot-v2.1" => ("v2.1", "`meta/episodes.jsonl`"),
        _ => ("v3.0", "the `provenance` column of `meta/episodes/`"),
    };
    let text = format!(
        "# BEHAVIOR episodes (LeRobot {version})\n\nExported from {episodes} recording(s), each \
         re-simulated. {who} Each episode's `provenance` in {meta} says which.\n\n{list}"
    );
    let path = dir.join("README.md");
    std::fs::write(&path, text).map_err(write_error(&path))
}

#[cfg(test)]
mod tests {
    use super::task_text;

    #[test]
    fn the_task_is_the_activity_in_words_without_its_instance_number() {
        assert_eq!(
            task_text("throwing_away_leftovers_0"),
            "throwing away leftovers"
        );
        assert_eq!(task_text("bringing_in_wood"), "bringing in wood");
        assert_eq!(task_text("my_task_v2"), "my task v2");
    }
}
