//! `behavior bddl ...`: check definitions, evaluate goals on states, list options, statistics and
//! the timing run used for the side-by-side comparison with the reference implementation.

use crate::prelude::Prelude;
use anyhow::{Context, Result, bail};
use behavior_bddl::domain::{is_domain_text, load_domain};
use behavior_bddl::options::options_with;
use behavior_bddl::{Counting, FactSet, GroundGoal, Optimizer};
use clap::{Args, Subcommand};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Subcommand)]
pub enum BddlCommand {
    /// Check definition files and print located diagnostics; exit status 1 if any has an error.
    Check {
        /// Problem or domain files to check (default: all official activities and the domain).
        paths: Vec<PathBuf>,
    },
    /// One row per official activity: objects, init literals, goal volume, success and Q at init.
    Stats {
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        counting: CountingFlag,
    },
    /// Evaluate a goal on a state: success, Q, volume and each top-level conjunct.
    Eval {
        /// A problem file, or the name of an official activity.
        file: String,
        /// JSON: {"facts": [["ontop", "apple.n.01_1", "table.n.02_1"], ["cooked", "apple.n.01_1"]]}.
        #[arg(long, value_name = "STATE.json")]
        state: PathBuf,
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        counting: CountingFlag,
    },
    /// List a goal's options (its disjunctive normal form), smallest first.
    Options {
        /// A problem file, or the name of an official activity.
        file: String,
        /// How many options to print.
        #[arg(long, default_value_t = 20)]
        limit: usize,
        /// Print only the number of consistent options (enumerates them all).
        #[arg(long)]
        count: bool,
        #[command(flatten)]
        counting: CountingFlag,
    },
    /// Time goal evaluation and Q on each official activity's initial state.
    Bench {
        #[arg(long)]
        json: bool,
        /// One short measurement per activity instead of seven.
        #[arg(long)]
        quick: bool,
        /// Comma-separated activity names (default: all).
        #[arg(long, value_delimiter = ',')]
        activities: Vec<String>,
        #[command(flatten)]
        counting: CountingFlag,
    },
}

/// How options count their literals: as sets unless `--reference-counting` is given.
#[derive(Args, Clone, Copy, Debug)]
pub struct CountingFlag {
    /// Count options as the reference implementation does: a literal written twice in an option
    /// counts twice (default: an option is a set of literals, as the paper defines Q and volume).
    #[arg(long)]
    reference_counting: bool,
}

impl CountingFlag {
    fn counting(self) -> Counting {
        if self.reference_counting {
            Counting::Reference
        } else {
            Counting::Set
        }
    }
}

pub fn run(command: BddlCommand, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    match command {
        BddlCommand::Check { paths } => check(&prelude, &paths),
        BddlCommand::Stats { json, counting } => stats(&prelude, json, counting.counting()),
        BddlCommand::Eval {
            file,
            state,
            json,
            counting,
        } => eval(&prelude, &file, &state, json, counting.counting()),
        BddlCommand::Options {
            file,
            limit,
            count,
            counting,
        } => list_options(&prelude, &file, limit, count, counting.counting()),
        BddlCommand::Bench {
            json,
            quick,
            activities,
            counting,
        } => bench(&prelude, json, quick, &activities, counting.counting()),
    }
}

fn check(prelude: &Prelude, paths: &[PathBuf]) -> Result<ExitCode> {
    let (data, knowledge) = (&prelude.data(), &prelude.knowledge());
    let paths: Vec<PathBuf> = if paths.is_empty() {
        let mut all: Vec<PathBuf> = data
            .activities()?
            .iter()
            .map(|a| data.problem_path(a))
            .collect::<Result<_, _>>()?;
        all.push(data.domain_path());
        all
    } else {
        paths.to_vec()
    };
    let (mut errors, mut warnings, mut failed_files) = (0, 0, 0);
    for path in &paths {
        let source = match behavior_bddl::load::read_source(path) {
            Ok(source) => source,
            Err(e) => {
                println!("{e}");
                errors += 1;
                failed_files += 1;
                continue;
            }
        };
        let loaded = if is_domain_text(&source.text) {
            load_domain(&source).map(|(_, warnings)| warnings)
        } else {
            knowledge.load(&source).map(|(_, warnings)| warnings)
        };
        let diagnostics = loaded.unwrap_or_else(|e| {
            failed_files += 1;
            e.diagnostics
        });
        errors += diagnostics.errors().count();
        warnings += diagnostics.warnings().count();
        print!("{}", diagnostics.render(&source));
    }
    println!(
        "checked {} file(s): {} with errors, {errors} error(s), {warnings} warning(s)",
        paths.len(),
        failed_files
    );
    Ok(if errors > 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

#[derive(Serialize)]
struct StatsRow {
    activity: String,
    objects: usize,
    init_literals: usize,
    volume: Option<u64>,
    success_at_init: bool,
    q_at_init: Option<f64>,
}

fn stats(prelude: &Prelude, json: bool, counting: Counting) -> Result<ExitCode> {
    let mut rows = Vec::new();
    for (name, activity) in prelude.official_activities()? {
        let goal = GroundGoal::new(&activity);
        let optimizer = Optimizer::with_counting(&goal, counting);
        let state: FactSet = activity.initial_facts().into_iter().collect();
        rows.push(StatsRow {
            activity: name,
            objects: activity.instances.len(),
            init_literals: activity.init.len(),
            volume: optimizer.volume(),
            success_at_init: goal.holds(&state),
            q_at_init: optimizer.q(&state).map(|q| q.to_f64()),
        });
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
        return Ok(ExitCode::SUCCESS);
    }
    println!(
        "{:<42} {:>7} {:>5} {:>6} {:>7} {:>6}",
        "activity", "objects", "init", "volume", "success", "Q"
    );
    for r in &rows {
        println!(
            "{:<42} {:>7} {:>5} {:>6} {:>7} {:>6}",
            r.activity,
            r.objects,
            r.init_literals,
            r.volume.map_or("-".into(), |v| v.to_string()),
            r.success_at_init,
            r.q_at_init.map_or("-".into(), |q| format!("{q:.3}")),
        );
    }
    Ok(ExitCode::SUCCESS)
}

#[derive(Serialize)]
struct ConjunctReport {
    formula: String,
    holds: bool,
}

#[derive(Serialize)]
struct EvalReport {
    success: bool,
    q: Option<f64>,
    /// Q as an exact fraction, e.g. "2/7".
    q_exact: Option<String>,
    volume: Option<u64>,
    conjuncts: Vec<ConjunctReport>,
}

fn eval(
    prelude: &Prelude,
    file: &str,
    state_path: &Path,
    json: bool,
    counting: Counting,
) -> Result<ExitCode> {
    let source = prelude.source(file)?;
    let activity = prelude.load_activity(&source)?;
    let text = std::fs::read_to_string(state_path)
        .with_context(|| format!("cannot read {}", state_path.display()))?;
    let state = FactSet::from_json(&activity, &text)
        .with_context(|| format!("{}", state_path.display()))?;
    let goal = GroundGoal::new(&activity);
    let optimizer = Optimizer::with_counting(&goal, counting);
    let q = optimizer.q(&state);
    let report = EvalReport {
        success: goal.holds(&state),
        q: q.map(|q| q.to_f64()),
        q_exact: q.map(|q| q.to_string()),
        volume: optimizer.volume(),
        conjuncts: activity
            .goal
            .iter()
            .zip(goal.conjuncts_hold(&state))
            .map(|(c, holds)| ConjunctReport {
                formula: one_line(&source.text[c.span.range()]),
                holds,
            })
            .collect(),
    };
    if json {
        println!("{}", serde_json::to_string_pretty(&report)?);
        return Ok(ExitCode::SUCCESS);
    }
    println!("activity  {}", activity.name);
    println!("success   {}", report.success);
    match q {
        Some(q) => println!("Q         {:.6} ({q})", q.to_f64()),
        None => println!("Q         undefined: the goal has no consistent option"),
    }
    match report.volume {
        Some(v) => println!("volume    {v}"),
        None => println!("volume    undefined: the goal has no consistent option"),
    }
    println!("conjuncts");
    for (i, c) in report.conjuncts.iter().enumerate() {
        let mark = if c.holds { "holds" } else { "fails" };
        println!("  {i:>3} {mark}  {}", c.formula);
    }
    Ok(ExitCode::SUCCESS)
}

/// Collapses whitespace so a multi-line formula prints on one line.
fn one_line(text: &str) -> String {
    let joined = text.split_whitespace().collect::<Vec<_>>().join(" ");
    joined.replace("( ", "(").replace(" )", ")")
}

fn list_options(
    prelude: &Prelude,
    file: &str,
    limit: usize,
    count: bool,
    counting: Counting,
) -> Result<ExitCode> {
    let activity = prelude.activity(file)?;
    let goal = GroundGoal::new(&activity);
    if count {
        println!("{}", options_with(&goal, counting).count());
        return Ok(ExitCode::SUCCESS);
    }
    match Optimizer::with_counting(&goal, counting).volume() {
        Some(volume) => println!("{}: volume {volume}", activity.name),
        None => {
            println!(
                "{}: the goal has no consistent option; it can never hold",
                activity.name
            );
            return Ok(ExitCode::SUCCESS);
        }
    }
    let mut listed = options_with(&goal, counting);
    for (i, option) in listed.by_ref().take(limit).enumerate() {
        let literals: Vec<String> = option.iter().map(|&l| activity.show_literal(l)).collect();
        println!("option {} ({} literals)", i + 1, option.len());
        for l in literals {
            println!("    {l}");
        }
    }
    if listed.next().is_some() {
        println!("(first {limit} shown; --limit N for more)");
    }
    Ok(ExitCode::SUCCESS)
}

#[derive(Serialize)]
struct BenchRow {
    activity: String,
    /// The status of every top-level conjunct: the work of the reference's
    /// `evaluate_goal_conditions`.
    goal_eval_ns: f64,
    /// Success alone, stopping at the first failing conjunct.
    success_ns: f64,
    q_ns: f64,
    success: bool,
    q: Option<f64>,
}

fn bench(
    prelude: &Prelude,
    json: bool,
    quick: bool,
    only: &[String],
    counting: Counting,
) -> Result<ExitCode> {
    let names = if only.is_empty() {
        prelude.data().activities()?
    } else {
        only.to_vec()
    };
    let mut rows = Vec::new();
    for name in names {
        let activity = prelude.load_activity(&prelude.official(&name)?)?;
        let goal = GroundGoal::new(&activity);
        let optimizer = Optimizer::with_counting(&goal, counting);
        let state: FactSet = activity.initial_facts().into_iter().collect();
        let goal_eval_ns = median_ns(quick, || goal.conjuncts_hold(&state).filter(|&h| h).count());
        let success_ns = median_ns(quick, || goal.holds(&state));
        let q_ns = median_ns(quick, || optimizer.q(&state));
        rows.push(BenchRow {
            activity: name,
            goal_eval_ns,
            success_ns,
            q_ns,
            success: goal.holds(&state),
            q: optimizer.q(&state).map(|q| q.to_f64()),
        });
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
        return Ok(ExitCode::SUCCESS);
    }
    println!("{:<42} {:>12} {:>12}", "activity", "goal eval ns", "Q ns");
    for r in &rows {
        println!(
            "{:<42} {:>12.0} {:>12.0}",
            r.activity, r.goal_eval_ns, r.q_ns
        );
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    println!(
        "median over activities: goal eval {:.0} ns, success {:.0} ns, Q {:.0} ns",
        median(rows.iter().map(|r| r.goal_eval_ns).collect()),
        median(rows.iter().map(|r| r.success_ns).collect()),
        median(rows.iter().map(|r| r.q_ns).collect()),
    );
    if rows.is_empty() {
        bail!("no activity was measured");
    }
    Ok(ExitCode::SUCCESS)
}

/// Median time per call over repeats that each last at least 20 ms (1 ms when `quick`), with the
/// calls per repeat found by doubling.
fn median_ns<T>(quick: bool, mut f: impl FnMut() -> T) -> f64 {
    let (target, repeats) = if quick { (1e-3, 1) } else { (20e-3, 7) };
    let mut calls = 1u64;
    loop {
        let start = Instant::now();
        for _ in 0..calls {
            std::hint::black_box(f());
        }
        if start.elapsed().as_secs_f64() >= target {
            break;
        }
        calls *= 2;
    }
    let mut samples: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..calls {
                std::hint::black_box(f());
            }
            start.elapsed().as_secs_f64() * 1e9 / calls as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::one_line;

    #[test]
    fn formulas_print_on_one_line() {
        assert_eq!(one_line("(and \n   (ontop a b)\n  )"), "(and (ontop a b))");
    }
}
