//! Data fetched from PyPI at first use and never copied into the repository: the official
//! BEHAVIOR-100 activity definitions ([`DataDir`], from `bddl==1.0.1`) and robots' real meshes
//! ([`RobotAssets`], from `gymnasium-robotics==1.4.2`). This crate finds them, or fetches them into
//! a cache (`$XDG_CACHE_HOME/behavior/`, default `~/.cache/behavior/`) with pip; it hands out
//! paths, and reading them is the business of the crates that understand them (`behavior-bddl`,
//! `behavior-robots`).
//!
//! ```
//! use behavior_data::DataDir;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! // The cache, or an explicit folder or `BEHAVIOR_DATA_DIR`; fetched from PyPI if absent.
//! let data = DataDir::locate(None, |message| eprintln!("{message}"))?;
//! assert!(data.taxonomy_path().is_file());
//! assert!(data.problem_path("bottling_fruit")?.is_file());
//! # Ok(())
//! # }
//! ```

mod fetch;
mod official;
mod robot_assets;

pub use official::{DataDir, ENV_VAR, PACKAGE, VERSION};
pub use robot_assets::{ROBOT_ASSETS_ENV_VAR, RobotAssets};

use std::io;
use std::path::PathBuf;

/// Why data could not be found or fetched.
#[derive(Debug, thiserror::Error)]
pub enum DataError {
    /// The directory lacks a file every data directory has.
    #[error(
        "{path} is not a bddl data directory: {missing} is missing (expected the `bddl/` folder of the bddl {VERSION} package)"
    )]
    NotADataDir {
        /// The directory given.
        path: PathBuf,
        /// The file it lacks, relative to it.
        missing: String,
    },
    /// The directory lacks a file of the robots' assets.
    #[error(
        "{path} is not gymnasium-robotics' assets folder: {missing} is missing (expected the `gymnasium_robotics/envs/assets` folder of gymnasium-robotics {version}, or `none` in {ROBOT_ASSETS_ENV_VAR})",
        version = robot_assets::VERSION
    )]
    NotRobotAssets {
        /// The directory given.
        path: PathBuf,
        /// The file it lacks, relative to it.
        missing: String,
    },
    /// pip, the network or unpacking failed.
    #[error(
        "could not fetch {package} from PyPI: {reason}\n  Fetch it by hand with `python3 -m pip download --no-deps --no-binary :all: {package}`, unpack it, and {by_hand}."
    )]
    Fetch {
        /// `name==version`.
        package: String,
        /// What went wrong.
        reason: String,
        /// Where to point the program at a copy fetched by hand.
        by_hand: &'static str,
    },
    /// A file or directory could not be read or written.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The path involved.
        path: PathBuf,
        /// The system's error.
        source: io::Error,
    },
    /// No official activity has this name.
    #[error("no official activity named `{0}` (see activity_manifest.txt)")]
    UnknownActivity(String),
}
