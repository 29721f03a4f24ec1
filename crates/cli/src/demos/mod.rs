//! `behavior demos`: datasets of demonstrations. `generate` makes the planner's physical
//! demonstrations in many homes and seeds, keeps those that end in success and replay bit for
//! bit, and writes a dataset card; `export` turns recordings into a LeRobot dataset.

mod card;
#[cfg(feature = "lerobot")]
mod export;
mod generate;

use anyhow::{Context, Result};
use generate::{MANIFEST, Manifest};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Subcommand)]
pub enum DemosCommand {
    /// The planner's physical demonstrations, several per activity in varied homes and seeds:
    /// each recorded (MCAP), kept only if it ends in success and replays bit for bit, with a
    /// dataset card (statistics per activity, plots). Rerun with the same folder to resume.
    Generate(generate::GenerateArgs),
    /// Recordings (teleoperated, an agent's, the planner's; or every recording in a folder such
    /// as `generate`'s) as a LeRobot dataset (v3.0 or v2.1): the frames as Parquet, the
    /// metadata, the robot's camera re-rendered as PNG.
    #[cfg(feature = "lerobot")]
    Export(export::ExportArgs),
}

pub fn run(command: DemosCommand, data_dir: Option<&Path>) -> Result<ExitCode> {
    match command {
        DemosCommand::Generate(args) => generate::run(args, data_dir),
        #[cfg(feature = "lerobot")]
        DemosCommand::Export(args) => export::run(args, data_dir),
    }
}

/// The recordings named: files as they are, a folder made by `demos generate` as the files its
/// manifest lists, in its order.
pub(crate) fn recordings_in(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for path in paths {
        if !path.is_dir() {
            files.push(path.clone());
            continue;
        }
        let manifest = path.join(MANIFEST);
        let text = std::fs::read_to_string(&manifest).with_context(|| {
            format!(
                "{} is a folder without a {MANIFEST} (made by `behavior demos generate`): name \
                 its recordings instead",
                path.display()
            )
        })?;
        let demos: Manifest = serde_json::from_str(&text)
            .with_context(|| format!("{} is not a demonstrations manifest", manifest.display()))?;
        files.extend(demos.demos.iter().map(|d| path.join(&d.file)));
    }
    Ok(files)
}
