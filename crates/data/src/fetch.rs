//! Fetching a source package from PyPI into a cache, once per machine: pip downloads the sdist,
//! the folders we need are unpacked from it, and the result appears whole or not at all.
//! Processes that start at once (parallel tests) fetch once: the first takes a lock file, the
//! others wait for its result.

use crate::DataError;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// How long a process waits for another one's fetch before giving up.
const FETCH_WAIT: Duration = Duration::from_secs(300);

/// A PyPI source package and what of it we keep.
pub(crate) struct Package {
    /// Its name on PyPI.
    pub(crate) name: &'static str,
    /// The pinned version.
    pub(crate) version: &'static str,
    /// The folder inside the package (below `<name>-<version>/`) that becomes the cache.
    pub(crate) folder: &'static str,
    /// Paths below `folder` that are kept (all of it when empty).
    pub(crate) keep: &'static [&'static str],
    /// A file below `folder` whose presence shows the cache is complete.
    pub(crate) marker: &'static str,
    /// How to use a copy fetched by hand, for the error when fetching fails.
    pub(crate) by_hand: &'static str,
}

impl Package {
    /// `name==version`, as pip takes it.
    pub(crate) fn spec(&self) -> String {
        format!("{}=={}", self.name, self.version)
    }

    /// The cache `$XDG_CACHE_HOME/behavior/<name>-<version>` (default `~/.cache/...`).
    pub(crate) fn cache(&self) -> Result<PathBuf, DataError> {
        let base = std::env::var_os("XDG_CACHE_HOME")
            .filter(|p| !p.is_empty())
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
            .ok_or_else(|| {
                self.failed("no cache directory: neither XDG_CACHE_HOME nor HOME is set")
            })?;
        Ok(base
            .join("behavior")
            .join(format!("{}-{}", self.name, self.version)))
    }

    fn failed(&self, reason: impl Into<String>) -> DataError {
        DataError::Fetch {
            package: self.spec(),
            reason: reason.into(),
            by_hand: self.by_hand,
        }
    }

    fn complete(&self, cache: &Path) -> bool {
        cache.join(self.marker).is_file()
    }

    /// The cache, filled first unless it is complete; `progress` hears one line before a fetch.
    pub(crate) fn cached(&self, progress: impl FnOnce(&str)) -> Result<PathBuf, DataError> {
        let cache = self.cache()?;
        if !self.complete(&cache) {
            self.fetch_once(&cache, progress)?;
        }
        Ok(cache)
    }

    /// Fills the cache unless another process is doing it; then waits for that one to finish.
    fn fetch_once(&self, cache: &Path, progress: impl FnOnce(&str)) -> Result<(), DataError> {
        let parent = cache
            .parent()
            .ok_or_else(|| self.failed(format!("{} has no parent directory", cache.display())))?;
        fs::create_dir_all(parent).map_err(io_error(parent))?;
        let lock = parent.join(format!(".{}-{}.lock", self.name, self.version));
        let started = Instant::now();
        loop {
            match fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(&lock)
            {
                Ok(_) => break,
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                    if self.complete(cache) {
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
        let result = if self.complete(cache) {
            Ok(())
        } else {
            progress(&format!(
                "fetching {} from PyPI into {}",
                self.spec(),
                cache.display()
            ));
            let work = parent.join(format!(".fetch-{}-{}", self.name, std::process::id()));
            let result = self.download_and_unpack(&work, cache);
            let _ = fs::remove_dir_all(&work);
            result
        };
        let _ = fs::remove_file(&lock);
        result
    }

    /// Downloads the sdist with pip into `work`, unpacks the kept paths and moves them to
    /// `target` in one rename.
    fn download_and_unpack(&self, work: &Path, target: &Path) -> Result<(), DataError> {
        let download = work.join("download");
        fs::create_dir_all(&download).map_err(io_error(&download))?;
        let output = Command::new("python3")
            .args(["-m", "pip", "download", "--no-deps", "--no-binary", ":all:"])
            .args(["--disable-pip-version-check", "--quiet", "-d"])
            .arg(&download)
            .arg(self.spec())
            .output()
            .map_err(|e| self.failed(format!("cannot run python3: {e}")))?;
        if !output.status.success() {
            return Err(self.failed(format!(
                "pip failed ({}): {}",
                output.status,
                String::from_utf8_lossy(&output.stderr).trim()
            )));
        }
        // sdists name their archive with the package's name normalised (`-` as `_`).
        let stem = format!("{}-{}", self.name.replace('-', "_"), self.version);
        let archive = download.join(format!("{stem}.tar.gz"));
        if !archive.is_file() {
            return Err(self.failed(format!(
                "pip reported success but saved no {}: {}",
                archive.display(),
                String::from_utf8_lossy(&output.stdout).trim()
            )));
        }
        let unpacked = work.join("unpacked");
        self.unpack(&archive, &Path::new(&stem).join(self.folder), &unpacked)?;
        let folder = unpacked.join(&stem).join(self.folder);
        if !self.complete(&folder) {
            return Err(self.failed(format!(
                "{} holds no {}/{}",
                archive.display(),
                self.folder,
                self.marker
            )));
        }
        match fs::rename(&folder, target) {
            Ok(()) => Ok(()),
            // Another process filled the cache meanwhile; its copy is as good as ours.
            Err(_) if self.complete(target) => Ok(()),
            Err(e) => Err(io_error(target)(e)),
        }
    }

    /// Unpacks the entries below `root/<kept path>` of a .tar.gz into `into`.
    fn unpack(&self, archive: &Path, root: &Path, into: &Path) -> Result<(), DataError> {
        let cannot =
            |e: io::Error| self.failed(format!("cannot unpack {}: {e}", archive.display()));
        fs::create_dir_all(into).map_err(io_error(into))?;
        let file = fs::File::open(archive).map_err(io_error(archive))?;
        let mut tar = tar::Archive::new(flate2::read::GzDecoder::new(file));
        for entry in tar.entries().map_err(cannot)? {
            let mut entry = entry.map_err(cannot)?;
            let path = entry.path().map_err(cannot)?.into_owned();
            let Ok(inside) = path.strip_prefix(root) else {
                continue;
            };
            let kept = self.keep.is_empty() || self.keep.iter().any(|k| inside.starts_with(k));
            if kept {
                // unpack_in refuses paths that would leave `into`.
                entry.unpack_in(into).map_err(cannot)?;
            }
        }
        Ok(())
    }
}

pub(crate) fn io_error(path: &Path) -> impl FnOnce(io::Error) -> DataError + '_ {
    move |source| DataError::Io {
        path: path.to_path_buf(),
        source,
    }
}
