//! `behavior metrics`: the efficiency metrics of recorded episodes, each also as a fraction of
//! the best human demonstration's value (paper §5), with the demonstrations' statistics.
//!
//! Every recording is re-simulated (it must replay identically: otherwise its metrics would not
//! be the recorded episode's) and measured by the same metric code an episode runs. Each
//! reference is shown with who acted — a person (its header says so, or it holds `/device`
//! reports), the planner (its header says so: `demos generate`'s demonstrations), or unstated —
//! so that no one mistakes the planner's or an agent's episodes for human data. A folder made
//! by `demos generate` stands for its demonstrations.

use crate::demos::recordings_in;
use crate::prelude::Prelude;
use crate::replay::resimulate;
use anyhow::{Result, bail};
use behavior_env::metrics::{EpisodeMetrics, HumanReference, HumanStatistics, Normalized};
use behavior_env::record::{Provenance, read};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct MetricsArgs {
    /// Recordings of the episodes to measure (`behavior run --record`, `behavior serve`).
    #[arg(required = true, value_name = "RECORDING.mcap")]
    recordings: Vec<PathBuf>,
    /// Recordings of demonstrations (a person's, or a folder of the planner's from `demos
    /// generate`): each metric is also given as a fraction of the best of them on the same
    /// instance (home and seed), else on the same activity.
    #[arg(long, num_args = 1.., value_name = "DEMO.mcap|DIR")]
    reference: Vec<PathBuf>,
    #[arg(long)]
    json: bool,
}

/// One recording, measured.
#[derive(Serialize)]
struct Measured {
    file: PathBuf,
    activity: String,
    /// The instance: home and seed.
    instance: String,
    /// Teleoperated steps by device (`xr`, `keys`); empty for an agent's or a script's episode.
    teleoperated: BTreeMap<String, usize>,
    /// Who acted, as the recording's header says.
    provenance: Provenance,
    metrics: EpisodeMetrics,
}

impl Measured {
    /// Who acted, in words.
    fn who(&self) -> String {
        match &self.provenance {
            Provenance::Planner { mode, .. } => {
                format!("the task planner's ({mode} primitives), NOT a person's")
            }
            Provenance::Person => "a person's (teleoperated)".to_string(),
            Provenance::Unstated if !self.teleoperated.is_empty() => {
                "a person's (teleoperated)".to_string()
            }
            Provenance::Unstated => {
                "NOT teleoperated: an agent's or a script's episode, not a person's".to_string()
            }
        }
    }
}

/// An episode against the people.
#[derive(Serialize)]
struct Compared {
    #[serde(flatten)]
    episode: Measured,
    /// `instance` when a demonstration of the same instance exists, `activity` when only other
    /// instances of the activity were demonstrated, null without any.
    reference: Option<&'static str>,
    /// Each efficiency metric over the best human value (1: as efficient as the best person).
    normalized: Option<Normalized>,
    /// What the demonstrations of the activity say (their number, mean length, the episode
    /// limit of twice that).
    humans: Option<HumanStatistics>,
}

/// What `behavior metrics --json` prints.
#[derive(Serialize)]
struct MetricsOutput {
    references: Vec<Measured>,
    episodes: Vec<Compared>,
}

pub fn run(args: MetricsArgs, data_dir: Option<&Path>) -> Result<()> {
    let prelude = Prelude::load(data_dir)?;
    let references = recordings_in(&args.reference)?
        .iter()
        .map(|file| measure(file, &prelude))
        .collect::<Result<Vec<_>>>()?;
    let mut humans = HumanReference::new();
    for r in &references {
        humans.add(&r.activity, &r.instance, &r.metrics);
    }
    let mut episodes = Vec::new();
    for file in &args.recordings {
        let episode = measure(file, &prelude)?;
        let (reference, normalized) =
            match humans.normalize(&episode.activity, &episode.instance, &episode.metrics) {
                Some(n) => (Some("instance"), Some(n)),
                None => match humans.normalize_by_activity(&episode.activity, &episode.metrics) {
                    Some(n) => (Some("activity"), Some(n)),
                    None => (None, None),
                },
            };
        episodes.push(Compared {
            humans: humans.statistics(&episode.activity),
            episode,
            reference,
            normalized,
        });
    }
    let out = MetricsOutput {
        references,
        episodes,
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print(&out);
    }
    Ok(())
}

/// Reads and re-simulates one recording; its metrics are those at the end of the replay.
fn measure(file: &Path, prelude: &Prelude) -> Result<Measured> {
    let recording = read(file)?;
    if let Some(damage) = &recording.damage {
        bail!("{}: {damage}", file.display());
    }
    let report = resimulate(file, &recording, prelude)?;
    if !report.identical {
        bail!(
            "{} does not replay identically (from step {:?}'s checkpoint on): its metrics would \
             not be the recorded episode's",
            file.display(),
            report.first_difference
        );
    }
    let Some(metrics) = report.metrics else {
        bail!("{}: the replay left no episode to measure", file.display());
    };
    let h = &recording.header;
    Ok(Measured {
        file: file.to_path_buf(),
        activity: h.activity.clone(),
        instance: format!("{} seed {}", h.scene, h.seed),
        teleoperated: recording.device_steps(),
        provenance: recording.header.provenance.clone(),
        metrics,
    })
}

fn print(out: &MetricsOutput) {
    if !out.references.is_empty() {
        let teleoperated = out
            .references
            .iter()
            .filter(|r| !r.teleoperated.is_empty())
            .count();
        let planned = out
            .references
            .iter()
            .filter(|r| matches!(r.provenance, Provenance::Planner { .. }))
            .count();
        println!(
            "reference: {} recording(s), {teleoperated} of them teleoperated, {planned} the planner's",
            out.references.len()
        );
        for r in &out.references {
            println!(
                "  {} ({}, {}): {} steps, {}",
                r.file.display(),
                r.activity,
                r.instance,
                r.metrics.steps,
                r.who()
            );
        }
    }
    for e in &out.episodes {
        print_episode(e);
    }
}

fn print_episode(e: &Compared) {
    let m = &e.episode.metrics;
    println!(
        "{} ({}, {}): {} steps, success {}, Q {:.3}",
        e.episode.file.display(),
        e.episode.activity,
        e.episode.instance,
        m.steps,
        m.success,
        m.q_final
    );
    let n = e.normalized.unwrap_or_default();
    let rows = [
        ("simulated time", m.sim_time_s, "s", n.simulated_time),
        (
            "kinematic disarrangement",
            m.kinematic_disarrangement,
            "m",
            n.kinematic_disarrangement,
        ),
        (
            "logical disarrangement",
            f64::from(m.logical_disarrangement),
            "",
            n.logical_disarrangement,
        ),
        (
            "distance navigated",
            m.distance_navigated,
            "m",
            n.distance_navigated,
        ),
        (
            "displacement of hands",
            m.hand_displacement_left + m.hand_displacement_right,
            "m",
            n.displacement_of_hands,
        ),
    ];
    for (name, value, unit, ratio) in rows {
        let ratio = match (e.reference, ratio) {
            (None, _) => String::new(),
            (Some(_), Some(r)) => format!("  {r:.2} × the best reference's"),
            (Some(_), None) => "  (the best reference's is 0)".to_string(),
        };
        println!("  {name:<26}{value:>10.3} {unit:<2}{ratio}");
    }
    match (e.reference, e.humans) {
        (Some(scope), Some(h)) => println!(
            "  against the best reference on the same {scope}; {} demonstration(s) of the activity \
             ({} successful), mean {:.0} steps: an episode limit of {} steps",
            h.demonstrations, h.successes, h.mean_steps, h.step_limit
        ),
        _ => println!("  no demonstration of this activity was given (--reference)"),
    }
}
