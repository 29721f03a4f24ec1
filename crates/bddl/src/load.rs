//! Reading definitions from files: problem and domain sources, the taxonomy, and the
//! [`Knowledge`] (taxonomy + domain) that problems are checked against.
//!
//! Where the official files are, and fetching them, is not this crate's business: the
//! `behavior-data` crate hands out their paths.

use crate::activity::{Activity, CheckContext};
use crate::ast::DomainFile;
use crate::diagnostics::{Diagnostics, Source, SourceErrors};
use crate::taxonomy::{Taxonomy, TaxonomyError};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Why a definition, domain or taxonomy file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The system's error.
        source: io::Error,
    },
    /// The taxonomy file is malformed.
    #[error("{path}: {source}")]
    Taxonomy {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        source: TaxonomyError,
    },
    /// A definition has errors (located diagnostics).
    #[error(transparent)]
    Source(#[from] SourceErrors),
}

fn io_error(path: &Path) -> impl FnOnce(io::Error) -> LoadError + '_ {
    move |source| LoadError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Reads and folds a taxonomy file (`hierarchy_owned.json`).
pub fn read_taxonomy(path: &Path) -> Result<Taxonomy, LoadError> {
    let text = fs::read_to_string(path).map_err(io_error(path))?;
    Taxonomy::from_json(&text).map_err(|source| LoadError::Taxonomy {
        path: path.to_path_buf(),
        source,
    })
}

/// Reads and checks a domain file.
pub fn read_domain(path: &Path) -> Result<DomainFile, LoadError> {
    let source = read_source(path)?;
    Ok(crate::domain::load_domain(&source)?.0)
}

/// The taxonomy and domain that problems are checked against.
#[derive(Clone, Debug)]
pub struct Knowledge {
    /// The folded synset taxonomy (`hierarchy_owned.json`).
    pub taxonomy: Taxonomy,
    /// The domain file (`domain_igibson.bddl`), already checked.
    pub domain: DomainFile,
}

impl Knowledge {
    /// Reads the taxonomy and the domain file.
    pub fn read(taxonomy: &Path, domain: &Path) -> Result<Knowledge, LoadError> {
        Ok(Knowledge {
            taxonomy: read_taxonomy(taxonomy)?,
            domain: read_domain(domain)?,
        })
    }

    /// A context with both the taxonomy and the domain, so that synsets, abilities and
    /// `:domain` are all checked.
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
pub fn read_source(path: &Path) -> Result<Source, LoadError> {
    let bytes = fs::read(path).map_err(io_error(path))?;
    let name = path.display().to_string();
    source_from_bytes(name, bytes).map_err(LoadError::Source)
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
