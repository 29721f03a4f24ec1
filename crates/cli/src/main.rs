//! `behavior`: the command-line front of BEHAVIOR in Rust.
//!
//! Each subcommand group lives in its own module; this file only parses arguments and reports
//! errors. Machine-readable output (`--json`) is documented per command in the README.

mod bddl;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "behavior",
    version,
    about = "BEHAVIOR in Rust: household activities for embodied AI"
)]
struct Cli {
    /// Directory holding the official bddl data (the `bddl/` folder of bddl 1.0.1). Default:
    /// $BEHAVIOR_DATA_DIR, else a cache filled from PyPI on first use.
    #[arg(long, global = true, value_name = "DIR")]
    data_dir: Option<PathBuf>,

    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Activity definitions: check, evaluate, list options, statistics.
    #[command(subcommand)]
    Bddl(bddl::BddlCommand),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Bddl(command) => bddl::run(command, cli.data_dir.as_deref()),
    };
    match result {
        Ok(code) => code,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::FAILURE
        }
    }
}
