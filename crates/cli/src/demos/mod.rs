//! `behavior demos`: datasets of demonstrations. `generate` makes the planner's physical
//! demonstrations in many homes and seeds, keeps those that end in success and replay bit for
//! bit, and writes a dataset card; `export` turns recordings into a LeRobot dataset.

mod card;
#[cfg(feature = "lerobot")]
mod export;
mod generate;

use anyhow::Result;
use std::path::Path;
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
