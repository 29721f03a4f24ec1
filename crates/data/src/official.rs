//! The official BEHAVIOR-100 data: the 100 activity definitions, the domain file and the synset
//! taxonomy, from the MIT-licensed PyPI package `bddl==1.0.1`.
//!
//! Where the data comes from, in order:
//! 1. an explicit directory (the CLI's `--data-dir`);
//! 2. the `BEHAVIOR_DATA_DIR` environment variable;
//! 3. the cache `$XDG_CACHE_HOME/behavior/bddl-1.0.1` (default `~/.cache/behavior/bddl-1.0.1`),
//!    filled on first use from the sdist (`python3 -m pip download --no-deps --no-binary :all:
//!    bddl==1.0.1`).
//!
//! A data directory is the package's `bddl/` folder: it holds `activity_definitions/<activity>/
//! problem0.bddl`, `activity_definitions/domain_igibson.bddl`, `hierarchy_owned.json` and
//! `activity_manifest.txt`.

use crate::DataError;
use crate::fetch::{Package, io_error};
use std::fs;
use std::path::{Path, PathBuf};

/// The PyPI package holding the data.
pub const PACKAGE: &str = "bddl";
/// Its version.
pub const VERSION: &str = "1.0.1";
/// The environment variable naming a data directory.
pub const ENV_VAR: &str = "BEHAVIOR_DATA_DIR";

const BDDL: Package = Package {
    name: PACKAGE,
    version: VERSION,
    folder: "bddl",
    keep: &[],
    marker: "hierarchy_owned.json",
    by_hand: "point BEHAVIOR_DATA_DIR (or --data-dir) at its `bddl/` folder",
};

/// A located data directory.
#[derive(Clone, Debug)]
pub struct DataDir {
    root: PathBuf,
}

impl DataDir {
    /// Finds the data: `explicit`, else `BEHAVIOR_DATA_DIR`, else the cache, fetching if needed.
    /// `progress` receives one line before a fetch starts (it takes a few seconds).
    pub fn locate(
        explicit: Option<&Path>,
        progress: impl FnOnce(&str),
    ) -> Result<DataDir, DataError> {
        if let Some(path) = explicit {
            return DataDir::open(path);
        }
        if let Some(path) = std::env::var_os(ENV_VAR).filter(|p| !p.is_empty()) {
            return DataDir::open(Path::new(&path));
        }
        let cache = BDDL.cached(progress)?;
        DataDir::open(&cache)
    }

    /// Uses `path` as a data directory, checking that it has the expected files.
    pub fn open(path: &Path) -> Result<DataDir, DataError> {
        for needed in [
            "hierarchy_owned.json",
            "activity_definitions/domain_igibson.bddl",
        ] {
            if !path.join(needed).is_file() {
                return Err(DataError::NotADataDir {
                    path: path.to_path_buf(),
                    missing: needed.to_string(),
                });
            }
        }
        Ok(DataDir {
            root: path.to_path_buf(),
        })
    }

    /// The `bddl/` folder.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The official activity names, sorted.
    pub fn activities(&self) -> Result<Vec<String>, DataError> {
        let dir = self.root.join("activity_definitions");
        let mut names = Vec::new();
        for entry in fs::read_dir(&dir).map_err(io_error(&dir))? {
            let entry = entry.map_err(io_error(&dir))?;
            if entry.path().join("problem0.bddl").is_file() {
                names.push(entry.file_name().to_string_lossy().into_owned());
            }
        }
        names.sort();
        Ok(names)
    }

    /// The definition of an official activity, `activity_definitions/<activity>/problem0.bddl`.
    pub fn problem_path(&self, activity: &str) -> Result<PathBuf, DataError> {
        let path = self
            .root
            .join("activity_definitions")
            .join(activity)
            .join("problem0.bddl");
        // A name with a separator could reach outside the data; it is no activity's name.
        let plain = !activity.is_empty() && !activity.contains(['/', '\\']) && activity != "..";
        if plain && path.is_file() {
            Ok(path)
        } else {
            Err(DataError::UnknownActivity(activity.to_string()))
        }
    }

    /// The domain file, `activity_definitions/domain_igibson.bddl`.
    pub fn domain_path(&self) -> PathBuf {
        self.root.join("activity_definitions/domain_igibson.bddl")
    }

    /// The synset taxonomy with abilities, `hierarchy_owned.json`.
    pub fn taxonomy_path(&self) -> PathBuf {
        self.root.join("hierarchy_owned.json")
    }
}
