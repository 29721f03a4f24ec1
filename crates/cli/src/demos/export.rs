//! `behavior demos export --lerobot DIR [--format F] RECORDINGS...`: recordings made into a
//! LeRobot dataset for imitation learning, by `behavior_env::record::lerobot::export` (which
//! Python calls too).

use super::recordings_in;
use crate::prelude::Prelude;
use anyhow::Result;
use behavior_env::record::lerobot::{ExportOptions, Format, export};
use behavior_planning::RecordedCall;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct ExportArgs {
    /// The dataset's folder: made, and refused if it exists and is not empty.
    #[arg(long, value_name = "DIR")]
    lerobot: PathBuf,
    /// The recordings, one episode each (all of the same robot); a folder made by `demos
    /// generate` stands for its demonstrations, in its manifest's order.
    #[arg(required = true)]
    recordings: Vec<PathBuf>,
    /// The layout: lerobot-v3 (LeRobot 0.4, the BEHAVIOR Challenge's demonstrations) or
    /// lerobot-v2.1 (LeRobot 0.3).
    #[arg(long, default_value = "lerobot-v3", value_parser = format_named)]
    format: Format,
    /// Leave out the camera images (`observation.images.eye`).
    #[arg(long)]
    no_images: bool,
    /// The camera images' side, pixels.
    #[arg(long, default_value_t = behavior_render::EYE_SIZE)]
    image_size: u32,
    #[arg(long)]
    json: bool,
}

pub fn run(args: ExportArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let options = ExportOptions {
        image_side: (!args.no_images).then_some(args.image_size),
        format: args.format,
    };
    // The planner's primitives are the recorded edits of the world.
    let recordings = recordings_in(&args.recordings)?;
    let summary =
        export::<RecordedCall>(prelude.knowledge(), &recordings, &args.lerobot, &options)?;
    for (file, frames) in &summary.recordings {
        eprintln!("  {}: {frames} frames", file.display());
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&summary)?);
    } else {
        println!(
            "{}: LeRobot dataset ({}), {} episode(s), {} frames, {} of them teleoperated, {} the planner's{}",
            summary.dataset.display(),
            summary.format,
            summary.episodes,
            summary.frames,
            summary.teleoperated,
            summary.planned,
            if summary.images { "" } else { ", no images" }
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// The `--format` named.
fn format_named(name: &str) -> Result<Format, String> {
    Format::from_name(name).ok_or_else(|| format!("one of {}", Format::names()))
}
