//! The official BEHAVIOR-100 data: the 100 activity definitions, the domain file and the synset
//! taxonomy, from the MIT-licensed PyPI package `bddl==1.0.1`. They are never copied into the
//! repository; this crate finds them, or fetches them into a cache on first use.
//!
//! Where the data comes from, in order:
//! 1. an explicit directory (the CLI's `--data-dir`);
//! 2. the `BEHAVIOR_DATA_DIR` environment variable;
//! 3. the cache `$XDG_CACHE_HOME/behavior/bddl-1.0.1` (default `~/.cache/behavior/bddl-1.0.1`),
//!    filled on first use by `python3 -m pip download --no-deps --no-binary :all: bddl==1.0.1`
//!    and unpacked. Processes that start at once (parallel tests) fetch once: the first takes a
//!    lock file, the others wait for its result.
//!
//! A data directory is the package's `bddl/` folder: it holds `activity_definitions/<activity>/
//! problem0.bddl`, `activity_definitions/domain_igibson.bddl`, `hierarchy_owned.json` and
//! `activity_manifest.txt`. This crate hands out paths; reading them is the language's business
//! (`behavior-bddl`).

#![warn(missing_docs)]

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// The PyPI package holding the data.
pub const PACKAGE: &str = "bddl";
/// Its version.
pub const VERSION: &str = "1.0.1";
/// The environment variable naming a data directory.
pub const ENV_VAR: &str = "BEHAVIOR_DATA_DIR";
/// How long a process waits for another one's fetch before giving up.
const FETCH_WAIT: Duration = Duration::from_secs(300);

/// Why the data could not be found or fetched.
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
    /// pip, the network or unpacking failed.
    #[error(
        "could not fetch bddl=={VERSION} from PyPI: {reason}\n  Fetch it by hand with `python3 -m pip download --no-deps --no-binary :all: bddl=={VERSION}`, unpack it, and point {ENV_VAR} (or --data-dir) at its `bddl/` folder."
    )]
    Fetch {
        /// What went wrong.
        reason: String,
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

fn io_error(path: &Path) -> impl FnOnce(io::Error) -> DataError + '_ {
    move |source| DataError::Io {
        path: path.to_path_buf(),
        source,
    }
}

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
        let cache = cache_dir().ok_or_else(|| DataError::Fetch {
            reason: "no cache directory: neither XDG_CACHE_HOME nor HOME is set".into(),
        })?;
        if cache.join("hierarchy_owned.json").is_file() {
            return DataDir::open(&cache);
        }
        fetch_once(&cache, progress)?;
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

fn cache_dir() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .filter(|p| !p.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))?;
    Some(base.join("behavior").join(format!("{PACKAGE}-{VERSION}")))
}

/// Fills the cache unless another process is doing it; then waits for that one to finish.
fn fetch_once(cache: &Path, progress: impl FnOnce(&str)) -> Result<(), DataError> {
    let parent = cache.parent().ok_or_else(|| DataError::Fetch {
        reason: format!("{} has no parent directory", cache.display()),
    })?;
    fs::create_dir_all(parent).map_err(io_error(parent))?;
    let lock = parent.join(format!(".{PACKAGE}-{VERSION}.lock"));
    let started = Instant::now();
    loop {
        match fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&lock)
        {
            Ok(_) => break,
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                if cache.join("hierarchy_owned.json").is_file() {
                    return Ok(());
                }
                if started.elapsed() > FETCH_WAIT {
                    // The holder died without cleaning up: take over.
                    let _ = fs::remove_file(&lock);
                    continue;
                }
                std::thread::sleep(Duration::from_millis(200));
            }
            Err(e) => return Err(io_error(&lock)(e)),
        }
    }
    let result = if cache.join("hierarchy_owned.json").is_file() {
        Ok(())
    } else {
        progress(&format!(
            "fetching the official activity definitions (bddl=={VERSION} from PyPI) into {}",
            cache.display()
        ));
        fetch_into(cache)
    };
    let _ = fs::remove_file(&lock);
    result
}

/// Downloads the sdist with pip and unpacks its `bddl/` folder into `target`, atomically: the
/// data appears complete or not at all.
fn fetch_into(target: &Path) -> Result<(), DataError> {
    let parent = target.parent().ok_or_else(|| DataError::Fetch {
        reason: format!("{} has no parent directory", target.display()),
    })?;
    fs::create_dir_all(parent).map_err(io_error(parent))?;
    let work = parent.join(format!(".fetch-{}", std::process::id()));
    let result = download_and_unpack(&work, target);
    let _ = fs::remove_dir_all(&work);
    result
}

fn download_and_unpack(work: &Path, target: &Path) -> Result<(), DataError> {
    let download = work.join("download");
    fs::create_dir_all(&download).map_err(io_error(&download))?;
    let spec = format!("{PACKAGE}=={VERSION}");
    let output = Command::new("python3")
        .args(["-m", "pip", "download", "--no-deps", "--no-binary", ":all:"])
        .args(["--disable-pip-version-check", "--quiet", "-d"])
        .arg(&download)
        .arg(&spec)
        .output()
        .map_err(|e| DataError::Fetch {
            reason: format!("cannot run python3: {e}"),
        })?;
    if !output.status.success() {
        return Err(DataError::Fetch {
            reason: format!(
                "pip failed ({}): {}",
                output.status,
                String::from_utf8_lossy(&output.stderr).trim()
            ),
        });
    }
    let archive = download.join(format!("{PACKAGE}-{VERSION}.tar.gz"));
    if !archive.is_file() {
        return Err(DataError::Fetch {
            reason: format!(
                "pip reported success but saved no {}: {}",
                archive.display(),
                String::from_utf8_lossy(&output.stdout).trim()
            ),
        });
    }
    let file = fs::File::open(&archive).map_err(io_error(&archive))?;
    let unpacked = work.join("unpacked");
    tar::Archive::new(flate2::read::GzDecoder::new(file))
        .unpack(&unpacked)
        .map_err(|e| DataError::Fetch {
            reason: format!("cannot unpack {}: {e}", archive.display()),
        })?;
    let package = unpacked.join(format!("{PACKAGE}-{VERSION}")).join(PACKAGE);
    DataDir::open(&package)?;
    match fs::rename(&package, target) {
        Ok(()) => Ok(()),
        // Another process filled the cache meanwhile; its copy is as good as ours.
        Err(_) if target.join("hierarchy_owned.json").is_file() => Ok(()),
        Err(e) => Err(io_error(target)(e)),
    }
}
