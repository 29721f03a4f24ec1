//! The official data as the Python functions open it: environments are built from names by
//! `behavior-catalog`, the library the command line and the viewer's server use too.

use behavior_catalog::{BuildError, Catalog};
use behavior_data::DataDir;

/// The catalog: `$BEHAVIOR_DATA_DIR`, else the cache, filled from PyPI on first use (saying so
/// on stderr).
pub fn catalog() -> Result<Catalog, BuildError> {
    Catalog::load(None, |message| eprintln!("{message}"))
}

/// Every official activity's name, in the manifest's order.
pub fn activities() -> Result<Vec<String>, BuildError> {
    let data = DataDir::locate(None, |message| eprintln!("{message}"))?;
    Ok(data.activities()?)
}
