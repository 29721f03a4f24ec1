//! `behavior demos export --lerobot DIR RECORDINGS...`: recordings made into a LeRobot dataset
//! for imitation learning, by `behavior_env::record::lerobot::export` (which Python calls too).

use crate::prelude::Prelude;
use anyhow::Result;
use behavior_env::record::lerobot::{ExportOptions, export};
use behavior_planning::RecordedCall;
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
    let prelude = Prelude::load(data_dir)?;
    let options = ExportOptions {
        image_side: (!args.no_images).then_some(args.image_size),
    };
    // The planner's primitives are the recorded edits of the world.
    let summary = export::<RecordedCall>(
        prelude.knowledge(),
        &args.recordings,
        &args.lerobot,
        &options,
    )?;
    for (file, frames) in &summary.recordings {
        eprintln!("  {}: {frames} frames", file.display());
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&summary)?);
    } else {
        println!(
            "{}: LeRobot dataset (v2.1), {} episode(s), {} frames, {} of them teleoperated{}",
            summary.dataset.display(),
            summary.episodes,
            summary.frames,
            summary.teleoperated,
            if summary.images { "" } else { ", no images" }
        );
    }
    Ok(ExitCode::SUCCESS)
}
