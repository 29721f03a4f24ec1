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
        None => prelude.activity(&official_activity(&prelude, &saved.activity)?)?,
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

/// The official activity a saved problem name is of, as the data spells it (problem names are
/// lower case: `filling_a_christmas_stocking_0` is of `filling_a_Christmas_stocking`).
fn official_activity(prelude: &Prelude, problem: &str) -> Result<String> {
    let name = official_name(problem);
    let activities = prelude.data.activities()?;
    activities
        .into_iter()
        .find(|a| a.eq_ignore_ascii_case(name))
        .with_context(|| {
            format!(
                "`{problem}` is not an official activity's problem: give its file with --activity"
            )
        })
}

/// The activity a problem is of: `packing_lunches_0` → `packing_lunches`.
fn official_name(problem: &str) -> &str {
    match problem.rsplit_once('_') {
        Some((name, index)) if !index.is_empty() && index.bytes().all(|b| b.is_ascii_digit()) => {
            name
        }
        _ => problem,
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_official_name_drops_the_problem_index() {
        assert_eq!(super::official_name("packing_lunches_0"), "packing_lunches");
        assert_eq!(
            super::official_name("re-shelving_library_books_0"),
            "re-shelving_library_books"
        );
        assert_eq!(super::official_name("mine"), "mine");
        assert_eq!(super::official_name("mine_"), "mine_");
    }
}
