//! `behavior demos export --lerobot DIR RECORDINGS...`: recordings made into a LeRobot dataset
//! for imitation learning (`lerobot.rs` writes it).
//!
//! Each recording is re-simulated (the episode begun again, every recorded action and edit done
//! again, as `behavior replay` does), so the dataset carries what the agent observed at every
//! step — proprioception, `task_obs` and, unless `--no-images`, the robot's camera rendered
//! again — though the recording keeps only actions. A recording that does not re-simulate
//! identically (a checkpoint's digest differs) or is cut is refused, naming the file: a dataset
//! must hold the episodes as they happened. The dataset is written beside DIR and moved there
//! only when whole, so a failed export leaves nothing half-written and overwrites nothing.

use crate::lerobot::{Dataset, Episode, Shapes};
use crate::prelude::Prelude;
use crate::replay::recorded_config;
use anyhow::{Context, Result, bail};
use behavior_env::record::redo;
use behavior_env::record::{Recording, read, state_digest};
use behavior_env::{CameraConfig, Env, Obs, Start};
use behavior_planning::RecordedCall;
use behavior_render::Modality;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Subcommand)]
pub enum DemosCommand {
    /// Recordings (teleoperated, an agent's, the planner's) as a LeRobot dataset (format v2.1):
    /// one Parquet file per episode, the metadata, the robot's camera re-rendered as PNG.
    Export(ExportArgs),
}

#[derive(clap::Args)]
pub struct ExportArgs {
    /// The dataset's folder: made, and refused if it exists and is not empty.
    #[arg(long, value_name = "DIR")]
    lerobot: PathBuf,
    /// The recordings, one episode each (all of the same robot).
    #[arg(required = true)]
    recordings: Vec<PathBuf>,
    /// Leave out the camera images (`observation.images.eye`).
    #[arg(long)]
    no_images: bool,
    /// The camera images' side, pixels.
    #[arg(long, default_value_t = behavior_render::EYE_SIZE)]
    image_size: u32,
    #[arg(long)]
    json: bool,
}

pub fn run(command: DemosCommand, data_dir: Option<&Path>) -> Result<ExitCode> {
    let DemosCommand::Export(args) = command;
    if !(16..=1024).contains(&args.image_size) {
        bail!(
            "--image-size must be 16–1024 pixels, not {}",
            args.image_size
        );
    }
    if args
        .lerobot
        .read_dir()
        .is_ok_and(|mut d| d.next().is_some())
    {
        bail!(
            "{} exists and is not empty: give a new folder (nothing there is overwritten)",
            args.lerobot.display()
        );
    }
    let prelude = Prelude::load(data_dir)?;
    let partial = args
        .lerobot
        .with_extension(format!("partial-{}", std::process::id()));
    let exported = export(&args, &prelude, &partial);
    let (episodes, frames, teleoperated) = match exported {
        Ok(counts) => counts,
        Err(e) => {
            let _ = std::fs::remove_dir_all(&partial);
            return Err(e);
        }
    };
    if args.lerobot.exists() {
        std::fs::remove_dir(&args.lerobot)
            .with_context(|| format!("cannot replace the empty {}", args.lerobot.display()))?;
    }
    std::fs::rename(&partial, &args.lerobot).with_context(|| {
        format!(
            "cannot move {} to {}",
            partial.display(),
            args.lerobot.display()
        )
    })?;
    let dir = args.lerobot.display();
    if args.json {
        let out = json!({"dataset": dir.to_string(), "format": "lerobot v2.1", "episodes": episodes,
            "frames": frames, "teleoperated": teleoperated, "images": !args.no_images});
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        println!(
            "{dir}: LeRobot dataset (v2.1), {episodes} episode(s), {frames} frames, {teleoperated} of them teleoperated{}",
            if args.no_images { ", no images" } else { "" }
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes every recording into `dir`; returns the episodes, frames and teleoperated episodes.
fn export(args: &ExportArgs, prelude: &Prelude, dir: &Path) -> Result<(usize, usize, usize)> {
    let mut dataset: Option<Dataset> = None;
    let mut teleoperated = 0;
    for file in &args.recordings {
        let recording = read(file)?;
        if let Some(damage) = &recording.damage {
            bail!(
                "{}: {damage}; a dataset takes only whole episodes",
                file.display()
            );
        }
        let image = (!args.no_images).then_some(args.image_size);
        let (episode, shapes) = resimulate(file, &recording, prelude, image)?;
        let robot = &recording.header.robot;
        let dataset = match &mut dataset {
            Some(d) => d,
            None => dataset.insert(Dataset::create(dir, robot, shapes)?),
        };
        if dataset.shapes() != shapes || dataset.robot() != robot {
            bail!(
                "{}: a {robot} robot's episode with {shapes:?}; the dataset's first episode is a \
                 {} robot's with {:?} (one dataset, one robot and one set of shapes)",
                file.display(),
                dataset.robot(),
                dataset.shapes()
            );
        }
        dataset
            .add(&episode)
            .with_context(|| format!("{}", file.display()))?;
        teleoperated += usize::from(!recording.devices.is_empty());
        eprintln!("  {}: {} frames", file.display(), episode.action.len());
    }
    let (episodes, frames) = dataset.context("no recordings")?.finish()?;
    write_card(dir, &args.recordings, teleoperated, episodes)?;
    Ok((episodes, frames, teleoperated))
}

/// One recording re-simulated into an episode's frames.
fn resimulate(
    file: &Path,
    recording: &Recording,
    prelude: &Prelude,
    image: Option<u32>,
) -> Result<(Episode, Shapes)> {
    let mut config = recorded_config(file, recording, prelude)?;
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
        .with_context(|| format!("{}: the recorded start", file.display()))?;
    let mut episode = Episode {
        task: task_text(&h.activity),
        provenance: json!({"recording": file.display().to_string(), "activity": h.activity,
            "scene": h.scene, "seed": h.seed, "teleoperated": recording.device_steps()}),
        ..Episode::default()
    };
    let mut q = env.score().map_or(0.0, |s| s.q);
    let mut edits = recording.edits.iter().peekable();
    for frame in &recording.frames {
        let mut edited = false;
        while let Some((step, edit)) = edits.next_if(|(s, _)| *s < frame.step) {
            redo::<RecordedCall>(&mut env, *step, edit)
                .with_context(|| format!("{}: replaying", file.display()))?;
            edited = true;
        }
        // An edit (a symbolic primitive) moved things: observe them as they are now.
        if edited {
            obs = env.observe()?;
        }
        push_observation(&mut episode, &obs, image.is_some())?;
        let step = env
            .step(&frame.action)
            .with_context(|| format!("{}: step {}", file.display(), frame.step))?;
        episode.action.push(frame.action.clone());
        episode.reward.push((step.info.score.q - q) as f32);
        episode.success.push(step.info.score.success);
        q = step.info.score.q;
        obs = step.obs;
        check(file, recording, &env)?;
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

fn push_observation(episode: &mut Episode, obs: &Obs, images: bool) -> Result<()> {
    episode.state.push(obs.proprioception.clone());
    episode.environment.push(obs.task_obs.clone());
    if images {
        let rgb = match obs.get("rgb").map(|r| &r.data) {
            Some(behavior_render::Pixels::U8(rgb)) => rgb.clone(),
            _ => bail!("the camera gave no colour image"),
        };
        episode.images.push(rgb);
    }
    Ok(())
}

/// The state against the recording's checkpoint at this step, if it has one.
fn check(file: &Path, recording: &Recording, env: &Env) -> Result<()> {
    let step = env.steps();
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Ok(());
    };
    for (_, digest) in recording.checkpoints.iter().filter(|(s, _)| *s == step) {
        if *digest != state_digest(world, robot, step) {
            bail!(
                "{}: re-simulated to step {step}, the state differs from the recording's; \
                 it is not exported (recorded with another build?)",
                file.display()
            );
        }
    }
    Ok(())
}

/// The dataset's README: where its episodes came from, and whether people made them.
fn write_card(
    dir: &Path,
    recordings: &[PathBuf],
    teleoperated: usize,
    episodes: usize,
) -> Result<()> {
    let who = if teleoperated == 0 {
        "None of them was teleoperated: they are agents' or the planner's episodes, NOT human \
         demonstrations."
            .to_string()
    } else {
        format!(
            "{teleoperated} of them were teleoperated (their recordings hold device reports); the \
             other {} are agents' or the planner's episodes, not human demonstrations.",
            episodes - teleoperated
        )
    };
    let list: String = recordings
        .iter()
        .enumerate()
        .map(|(i, r)| format!("- episode {i}: `{}`\n", r.display()))
        .collect();
    let text = format!(
        "# BEHAVIOR episodes (LeRobot v2.1)\n\nExported by `behavior demos export --lerobot` from \
         {episodes} recording(s), each re-simulated. {who} Each episode's `provenance` in \
         `meta/episodes.jsonl` says which.\n\n{list}"
    );
    std::fs::write(dir.join("README.md"), text)
        .with_context(|| format!("cannot write {}", dir.join("README.md").display()))
}
