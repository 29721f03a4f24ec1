//! `behavior facts`: the logical state of a saved instance, every predicate that holds among the
//! activity's objects.

use crate::prelude::Prelude;
use anyhow::{Context, Result};
use behavior_sampling::{Fact, SavedInstance};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct FactsArgs {
    /// A saved instance (`behavior sample ... --out FILE.json`).
    instance: PathBuf,
    /// The activity's problem file, for an instance of one's own activity (default: the official
    /// activity the file names).
    #[arg(long, value_name = "FILE")]
    activity: Option<String>,
    #[arg(long)]
    json: bool,
}

/// The `--json` form, which `behavior bddl eval --state` reads back.
#[derive(Serialize)]
pub struct FactsReport<'f> {
    pub facts: &'f [Fact],
}

pub fn facts(args: FactsArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let text = std::fs::read_to_string(&args.instance)
        .with_context(|| format!("cannot read {}", args.instance.display()))?;
    let saved =
        SavedInstance::from_json(&text).with_context(|| format!("{}", args.instance.display()))?;
    let activity = match &args.activity {
        Some(file) => prelude.activity(file)?,
        None => prelude.activity(&prelude.official_activity(&saved.activity)?)?,
    };
    let instance = saved
        .load(&activity, &library)
        .with_context(|| format!("loading {}", args.instance.display()))?;
    let facts = instance.facts(&activity);
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&FactsReport { facts: &facts })?
        );
    } else {
        for fact in &facts {
            println!("{fact}");
        }
    }
    Ok(ExitCode::SUCCESS)
}
