//! What the subcommands start from, written once: locate the official data, load the knowledge
//! (taxonomy and domain) and, for those that build worlds, the object library and the named
//! homes.

use anyhow::{Context, Result};
use behavior_assets::{Library, Scene};
use behavior_bddl::{Activity, Source};
use behavior_catalog::Catalog;
use std::path::Path;

/// The official data and the knowledge loaded from it: the catalog environments are built
/// from (`behavior-catalog`), with what the subcommands read of it.
pub struct Prelude {
    catalog: Catalog,
}

impl std::ops::Deref for Prelude {
    type Target = Catalog;

    fn deref(&self) -> &Catalog {
        &self.catalog
    }
}

impl Prelude {
    /// Locates the data (`--data-dir`, `$BEHAVIOR_DATA_DIR`, else the cache, filled on first
    /// use with a progress message) and loads the knowledge.
    pub fn load(data_dir: Option<&Path>) -> Result<Prelude> {
        let catalog = Catalog::load(data_dir, |message| eprintln!("{message}"))?;
        Ok(Prelude { catalog })
    }

    /// The definition of an official activity.
    pub fn official(&self, name: &str) -> Result<Source> {
        let source = self.official_source(name)?;
        source.with_context(|| format!("`{name}` is not an official activity"))
    }

    /// Loads a definition, printing its warnings (with their locations) to stderr.
    pub fn load_activity(&self, source: &Source) -> Result<Activity> {
        let (activity, warnings) = self.knowledge().load(source)?;
        if !warnings.0.is_empty() {
            eprint!("{}", warnings.render(source));
        }
        Ok(activity)
    }

    /// The definition at `file` (see [`Catalog::source`]).
    pub fn activity(&self, file: &str) -> Result<Activity> {
        self.load_activity(&self.source(file)?)
    }

    /// Every official activity, by name, in the manifest's order.
    /// `chosen` if it names any activity, else every official one's name.
    pub fn activity_names(&self, chosen: &[String]) -> Result<Vec<String>> {
        if !chosen.is_empty() {
            return Ok(chosen.to_vec());
        }
        Ok(self
            .official_activities()?
            .into_iter()
            .map(|(n, _)| n)
            .collect())
    }

    pub fn official_activities(&self) -> Result<Vec<(String, Activity)>> {
        self.data()
            .activities()?
            .into_iter()
            .map(|name| {
                let activity = self.load_activity(&self.official(&name)?)?;
                Ok((name, activity))
            })
            .collect()
    }
}

/// The fifteen named homes, generated in their fixed order.
pub fn named_homes(library: &Library) -> Result<Vec<Scene>> {
    Ok(behavior_assets::named_homes(library)?)
}

/// A progress bar over `len` items, hidden when the output is JSON.
pub(crate) fn counting_bar(len: usize, hidden: bool) -> indicatif::ProgressBar {
    if hidden {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(len as u64)
    }
}

/// The median (upper, for an even count); NaN when there is nothing.
pub(crate) fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}
