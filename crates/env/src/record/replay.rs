//! Replay: the episode begun again from the header, every recorded action taken again, the
//! state compared with the recording at every checkpoint.

use super::reader::{Frame, Recording};
use super::state_digest;
use crate::config::{EnvConfig, Instances};
use crate::edit::{NoEdits, WorldEdit};
use crate::env::{Env, EnvError};
use crate::episode::Start;
use crate::metrics::EpisodeMetrics;
use behavior_robots::{ActionSpace, RobotKind};
use behavior_sim::Substeps;
use serde::Serialize;

/// Why a recording could not be replayed.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError {
    /// The header names something this build does not have.
    #[error("the recording's {field} `{value}` is not one this build knows")]
    Unknown {
        /// Which header field.
        field: &'static str,
        /// Its value.
        value: String,
    },
    /// The recording's definition does not load.
    #[error("the recording's definition: {0}")]
    Definition(behavior_bddl::SourceErrors),
    /// The recording has no checkpoint at the step asked to resume from.
    #[error("the recording has no checkpoint at step {0}")]
    NoCheckpoint(u32),
    /// The step asked for is past the recording's last.
    #[error("the recording ends at step {last}; it has no step {step}")]
    PastTheEnd {
        /// The step asked for.
        step: u32,
        /// The recording's last step.
        last: u32,
    },
    /// Re-simulated to a checkpoint, the state differs from the recording's.
    #[error("the state re-simulated to step {0} differs from the recording's checkpoint")]
    Differs(u32),
    /// The saved state at the checkpoint does not load.
    #[error("the state saved at step {step}: {source}")]
    State {
        /// The checkpoint's step.
        step: u32,
        /// Why.
        source: crate::CheckpointError,
    },
    /// The recording edits the world between steps in words this replay's edit type does not
    /// read: replay it with the type that made the edits (a plain [`replay`] reads none).
    #[error(
        "the world was edited after step {step} ({edit}), in a way this replay does not read \
         ({source}): replay it with the code that made the edits"
    )]
    UnreadableEdit {
        /// The step after which the edit was made.
        step: u32,
        /// What the recording says was done.
        edit: String,
        /// Why it does not read as an edit of the replay's type.
        source: serde_json::Error,
    },
    /// A recorded edit could not be done again.
    #[error("the world was edited after step {step} ({edit}); done again, it failed: {source}")]
    Edit {
        /// The step after which the edit was made.
        step: u32,
        /// What the recording says was done.
        edit: String,
        /// Why it was not done again.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// Resuming at a step re-simulates from the start, which cannot redo edits: resume at a
    /// checkpoint whose full state was saved.
    #[error(
        "the world was edited after step {step} ({edit}), before the checkpoint asked for, \
         which has no saved state to resume from"
    )]
    EditBeforeResume {
        /// The step after which the edit was made.
        step: u32,
        /// What the recording says was done.
        edit: String,
    },
    /// The environment refused the start or a step.
    #[error("replaying step {step}: {source}")]
    Env {
        /// The step (0: the reset).
        step: u32,
        /// Why.
        source: EnvError,
    },
}

/// What a replay found.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct ReplayReport {
    /// Steps replayed.
    pub frames: u32,
    /// Checkpoints compared.
    pub checkpoints: u32,
    /// Whether every compared checkpoint matched bit for bit.
    pub identical: bool,
    /// The first checkpoint step that differed.
    pub first_difference: Option<u32>,
    /// Q at the end of the replay.
    pub q_final: f64,
    /// The episode's metrics at the end of the replay (those of the recorded episode when the
    /// replay is identical): what `behavior metrics` reports.
    pub metrics: Option<EpisodeMetrics>,
}

impl Recording {
    /// [`Recording::config`] for the activity of the recording's own definition, parsed with
    /// `knowledge` (its warnings dropped).
    pub fn config_from(
        &self,
        knowledge: &behavior_bddl::Knowledge,
    ) -> Result<EnvConfig, ReplayError> {
        let source = behavior_bddl::Source::new(&self.header.activity, &self.header.definition);
        let (activity, _warnings) = knowledge.load(&source).map_err(ReplayError::Definition)?;
        let taxonomy = std::sync::Arc::new(knowledge.taxonomy.clone());
        self.config(std::sync::Arc::new(activity), taxonomy)
    }

    /// The environment the recording was made in, for its activity (parsed from
    /// [`super::Header::definition`] by the caller, who has the taxonomy).
    pub fn config(
        &self,
        activity: std::sync::Arc<behavior_bddl::Activity>,
        taxonomy: std::sync::Arc<behavior_bddl::Taxonomy>,
    ) -> Result<EnvConfig, ReplayError> {
        let h = &self.header;
        let unknown = |field, value: &str| ReplayError::Unknown {
            field,
            value: value.to_string(),
        };
        let robot = RobotKind::from_name(&h.robot).ok_or_else(|| unknown("robot", &h.robot))?;
        let action_space = ActionSpace::from_name(&h.action_space)
            .ok_or_else(|| unknown("action space", &h.action_space))?;
        let physics = [Substeps::Hz300, Substeps::Hz120]
            .into_iter()
            .find(|s| s.count() * h.action_hz == h.physics_hz && h.action_hz == 30)
            .ok_or_else(|| unknown("physics rate", &h.physics_hz.to_string()))?;
        let mut config = EnvConfig::new(activity, taxonomy, Vec::new());
        config.instances = Instances::Saved(vec![h.instance.clone()]);
        config.robot = robot;
        config.action_space = action_space;
        config.physics = physics;
        config.max_steps = h.max_steps;
        Ok(config)
    }
}

/// Replays a recording in `config` (see [`Recording::config`]), comparing the state digest at
/// every checkpoint. A recording with edits of the world between steps needs
/// [`replay_with`] and the type of its edits.
pub fn replay(recording: &Recording, config: EnvConfig) -> Result<ReplayReport, ReplayError> {
    replay_with::<NoEdits>(recording, config)
}

/// [`replay`], reading every recorded edit as an `E` and applying it again
/// ([`crate::Env::apply`]) after the step it followed.
pub fn replay_with<E: WorldEdit>(
    recording: &Recording,
    config: EnvConfig,
) -> Result<ReplayReport, ReplayError> {
    let mut env = Env::new(config);
    env.reset_to(start_of(recording))
        .map_err(|source| ReplayError::Env { step: 0, source })?;
    let mut report = ReplayReport {
        identical: true,
        ..ReplayReport::default()
    };
    let mut checkpoints = recording.checkpoints.iter().peekable();
    let mut check = |env: &Env, report: &mut ReplayReport| {
        while let Some((step, digest)) = checkpoints.next_if(|(s, _)| *s <= env.steps()) {
            if *step != env.steps() {
                continue;
            }
            let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
                return;
            };
            report.checkpoints += 1;
            if state_digest(world, robot, env.steps()) != *digest && report.identical {
                report.identical = false;
                report.first_difference = Some(*step);
            }
        }
    };
    check(&env, &mut report);
    let mut edits = recording.edits.iter().peekable();
    for frame in &recording.frames {
        take_frame::<E>(&mut env, frame, &mut edits)?;
        report.frames += 1;
        check(&env, &mut report);
    }
    report.q_final = env.score().map_or(0.0, |s| s.q);
    report.metrics = env.metrics();
    Ok(report)
}

/// Reads the edit recorded after step `step` as an `E` and does it again: what a replay does
/// between two recorded steps, for code that walks a recording its own way (an exporter, a
/// viewer).
pub fn redo<E: WorldEdit>(
    env: &mut Env,
    step: u32,
    recorded: &serde_json::Value,
) -> Result<(), ReplayError> {
    let edit = E::deserialize(recorded).map_err(|source| ReplayError::UnreadableEdit {
        step,
        edit: recorded.to_string(),
        source,
    })?;
    let failed = |source: Box<dyn std::error::Error + Send + Sync>| ReplayError::Edit {
        step,
        edit: recorded.to_string(),
        source,
    };
    let done = env.apply(&edit).map_err(|e| failed(Box::new(e)))?;
    done.map_err(|e| failed(Box::new(e)))
}

/// Resumes a recorded episode at one of its checkpoints: loads the full state saved there (or,
/// in a recording without one, re-simulates from the header up to `step`), checks it against
/// the checkpoint's digest bit for bit, and hands back the environment there, ready to
/// continue (with the recorded actions it continues as recorded; with others it branches off).
pub fn resume(recording: &Recording, config: EnvConfig, step: u32) -> Result<Env, ReplayError> {
    if !recording.checkpoints.iter().any(|(s, _)| *s == step) {
        return Err(ReplayError::NoCheckpoint(step));
    }
    let mut env = Env::new(config);
    match recording.states.iter().find(|(s, _)| *s == step) {
        Some((_, bytes)) => load_state(&mut env, recording, step, bytes)?,
        None => {
            resimulate(&mut env, recording, start_of(recording), step)?;
            if env.steps() != step {
                return Err(ReplayError::Differs(step));
            }
            check_digest(&env, recording)?;
        }
    }
    Ok(env)
}

/// The recorded episode as it stood after its step `step` (0: just after the reset), at any
/// step, not only a checkpoint: resumed at the last full state saved at or before it (checked
/// against its digest), then the recorded actions taken again up to `step`, every recorded
/// edit between them done again as an `E` (the type that made them), and every checkpoint
/// passed on the way compared bit for bit. What an experiment starting "k seconds before a
/// demonstration's success" starts from.
pub fn state_at<E: WorldEdit>(
    recording: &Recording,
    config: EnvConfig,
    step: u32,
) -> Result<Env, ReplayError> {
    let last = recording.frames.last().map_or(0, |f| f.step);
    if step > last {
        return Err(ReplayError::PastTheEnd { step, last });
    }
    let mut env = Env::new(config);
    let saved = (recording.states.iter())
        .filter(|(s, _)| *s <= step)
        .max_by_key(|(s, _)| *s);
    let from = match saved {
        Some((at, bytes)) => {
            load_state(&mut env, recording, *at, bytes)?;
            *at
        }
        None => {
            env.reset_to(start_of(recording))
                .map_err(|source| ReplayError::Env { step: 0, source })?;
            check_digest(&env, recording)?;
            0
        }
    };
    // A state saved at a step precedes the edits made after that step.
    let mut edits = (recording.edits.iter())
        .filter(|(s, _)| *s >= from)
        .peekable();
    for frame in (recording.frames.iter()).filter(|f| f.step > from && f.step <= step) {
        take_frame::<E>(&mut env, frame, &mut edits)?;
        check_digest(&env, recording)?;
    }
    Ok(env)
}

/// Takes a recorded frame again: the edits recorded before its step (those `edits` has left),
/// then its action.
fn take_frame<'r, E: WorldEdit>(
    env: &mut Env,
    frame: &Frame,
    edits: &mut std::iter::Peekable<impl Iterator<Item = &'r (u32, serde_json::Value)>>,
) -> Result<(), ReplayError> {
    while let Some((at, edit)) = edits.next_if(|(s, _)| *s < frame.step) {
        redo::<E>(env, *at, edit)?;
    }
    env.step(&frame.action).map_err(|source| ReplayError::Env {
        step: frame.step,
        source,
    })?;
    Ok(())
}

/// How the recorded episode began.
fn start_of(recording: &Recording) -> Start {
    Start {
        seed: recording.header.seed,
        instance: recording.header.instance.clone(),
    }
}

/// Loads the full state saved at `step` into `env` and checks it against that step's digest.
fn load_state(
    env: &mut Env,
    recording: &Recording,
    step: u32,
    bytes: &[u8],
) -> Result<(), ReplayError> {
    env.restore_bytes(start_of(recording), bytes)
        .map_err(|source| ReplayError::State { step, source })?;
    if env.steps() != step {
        return Err(ReplayError::Differs(step));
    }
    check_digest(env, recording)
}

/// Compares the state `env` stands at with the recording's checkpoint at that step, where it
/// has one.
fn check_digest(env: &Env, recording: &Recording) -> Result<(), ReplayError> {
    let step = env.steps();
    let Some((_, digest)) = recording.checkpoints.iter().find(|(s, _)| *s == step) else {
        return Ok(());
    };
    let same = match (env.world(), env.robot()) {
        (Some(world), Some(robot)) => state_digest(world, robot, step) == *digest,
        _ => false,
    };
    if same {
        Ok(())
    } else {
        Err(ReplayError::Differs(step))
    }
}

/// Begins the episode again and takes the recorded actions up to `step`.
fn resimulate(
    env: &mut Env,
    recording: &Recording,
    start: Start,
    step: u32,
) -> Result<(), ReplayError> {
    if let Some((at, edit)) = recording.edits.iter().find(|(s, _)| *s < step) {
        return Err(ReplayError::EditBeforeResume {
            step: *at,
            edit: edit.to_string(),
        });
    }
    env.reset_to(start)
        .map_err(|source| ReplayError::Env { step: 0, source })?;
    for frame in recording.frames.iter().take_while(|f| f.step <= step) {
        env.step(&frame.action).map_err(|source| ReplayError::Env {
            step: frame.step,
            source,
        })?;
    }
    Ok(())
}
