//! `behavior replay`: read a recording, and with `--verify` re-simulate it and compare every
//! checkpoint bit for bit.

use crate::prelude::Prelude;
use anyhow::{Context, Result};
use behavior_bddl::Source;
use behavior_env::EnvConfig;
use behavior_env::record::{Recording, ReplayReport, read, replay_with};
use behavior_planning::RecordedCall;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

#[derive(clap::Args)]
pub struct ReplayArgs {
    /// A recording made by `behavior run --record`.
    file: PathBuf,
    /// Re-simulate the episode and check the state at every checkpoint.
    #[arg(long)]
    verify: bool,
    #[arg(long)]
    json: bool,
}

/// What `behavior replay --json` prints.
#[derive(Serialize)]
struct ReplayOutput {
    activity: String,
    scene: String,
    seed: u64,
    robot: String,
    /// Steps in the file (whole chunks).
    frames: usize,
    /// Checkpoints in the file (with `--verify`: those compared).
    checkpoints: usize,
    /// With `--verify`: every compared checkpoint identical; without it: null.
    identical: Option<bool>,
    first_difference: Option<u32>,
    /// Where reading stopped on a damaged or cut file.
    damage: Option<String>,
    /// Teleoperated steps by the device that drove them (`xr`, `keys`), from the recording's
    /// device reports; empty for an agent's episode.
    devices: BTreeMap<String, usize>,
}

pub fn run(args: ReplayArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let recording = read(&args.file)?;
    let h = &recording.header;
    let mut out = ReplayOutput {
        activity: h.activity.clone(),
        scene: h.scene.clone(),
        seed: h.seed,
        robot: h.robot.clone(),
        frames: recording.frames.len(),
        checkpoints: recording.checkpoints.len(),
        identical: None,
        first_difference: None,
        damage: recording.damage.clone(),
        devices: recording.device_steps(),
    };
    if args.verify {
        let prelude = Prelude::load(data_dir)?;
        let report = resimulate(&args.file, &recording, &prelude)?;
        out.frames = report.frames as usize;
        out.checkpoints = report.checkpoints as usize;
        out.identical = Some(report.identical);
        out.first_difference = report.first_difference;
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print(&out);
    }
    let failed = out.damage.is_some() || out.identical == Some(false);
    Ok(if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

fn print(out: &ReplayOutput) {
    println!(
        "{} in {} (seed {}), {} robot: {} steps, {} checkpoints",
        out.activity, out.scene, out.seed, out.robot, out.frames, out.checkpoints
    );
    match (out.identical, out.first_difference) {
        (Some(true), _) => println!("  replay: identical at every checkpoint"),
        (Some(false), Some(step)) => println!("  replay: DIFFERS from step {step}'s checkpoint on"),
        (Some(false), None) => println!("  replay: differs"),
        (None, _) => println!("  (re-simulate with --verify)"),
    }
    if !out.devices.is_empty() {
        let by: Vec<String> = out
            .devices
            .iter()
            .map(|(device, steps)| format!("{steps} from {device}"))
            .collect();
        println!("  teleoperated steps: {}", by.join(", "));
    }
    if let Some(damage) = &out.damage {
        eprintln!("error: {damage}");
    }
}

/// Re-simulates a recording read from `file` in the environment its header describes; recorded
/// primitives are done again by the planner's code that did them.
pub(crate) fn resimulate(
    file: &Path,
    recording: &Recording,
    prelude: &Prelude,
) -> Result<ReplayReport> {
    let config = recorded_config(file, recording, prelude)?;
    replay_with::<RecordedCall>(recording, config)
        .with_context(|| format!("replaying {}", file.display()))
}

/// The environment a recording read from `file` was made in: its activity parsed from the
/// definition it carries.
pub(crate) fn recorded_config(
    file: &Path,
    recording: &Recording,
    prelude: &Prelude,
) -> Result<EnvConfig> {
    let h = &recording.header;
    let source = Source::new(&h.activity, &h.definition);
    let activity = prelude
        .load_activity(&source)
        .with_context(|| format!("the definition in {}", file.display()))?;
    let taxonomy = Arc::new(prelude.knowledge().taxonomy.clone());
    Ok(recording.config(Arc::new(activity), taxonomy)?)
}
