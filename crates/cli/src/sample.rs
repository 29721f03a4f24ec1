//! `behavior sample` and `behavior sample-all`: instantiate activities in homes.

use crate::prelude::{Prelude, median, named_homes};
use crate::scene::with_clutter;
use anyhow::{Context, Result, bail};
use behavior_assets::covering;
use behavior_assets::{Library, Scene};
use behavior_bddl::{Activity, Taxonomy};
use behavior_core::WALL_SYNSET;
use behavior_sampling::{Fact, InitCheck, Instance, LiteralKind, instantiate};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(clap::Args)]
pub struct SampleArgs {
    /// An official activity name or a problem file of one's own.
    activity: String,
    /// A named home or a scene file (default: the first named home that covers the activity).
    #[arg(long)]
    scene: Option<String>,
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Save the instance (home, bindings, world state) as JSON.
    #[arg(long, value_name = "FILE.json")]
    out: Option<PathBuf>,
    /// Draw the home with the activity's objects marked.
    #[arg(long, value_name = "OUT.png")]
    png: Option<PathBuf>,
    /// Sample in the furniture-only home: no books, dishes, food and the like lying about.
    #[arg(long)]
    no_clutter: bool,
    #[arg(long)]
    json: bool,
}

#[derive(clap::Args)]
pub struct SampleAllArgs {
    /// Seeds per (activity, covering home), 1 to 1000.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=1000))]
    seeds: u64,
    /// Sample in the furniture-only homes: no books, dishes, food and the like lying about.
    #[arg(long)]
    no_clutter: bool,
    #[arg(long)]
    json: bool,
}

/// What `behavior sample` reports (its `--json` form).
#[derive(Serialize)]
struct SampleReport {
    activity: String,
    scene: String,
    seed: u64,
    seconds: f64,
    attempt: u32,
    objects: ObjectCount,
    init_check: InitReport,
    bindings: Vec<Binding>,
    /// Every predicate that holds among the activity's objects in the sampled world.
    facts: Vec<Fact>,
    /// Each instance's pose, by instance name.
    poses: BTreeMap<String, PoseReport>,
}

/// Where an object stands: position (m) and orientation (quaternion x, y, z, w).
#[derive(Serialize)]
struct PoseReport {
    position: [f32; 3],
    orientation: [f32; 4],
}

/// The objects of the instance's world, walls left out: what the original's homes are counted
/// by (134 to 216 objects in its benchmark scenes).
#[derive(Serialize)]
struct ObjectCount {
    /// All of them: furniture, doors and windows, floors, clutter and the activity's own.
    total: usize,
    /// The home's clutter.
    clutter: usize,
    /// Those the sampler created for the activity (the agent's stand-in included).
    created: usize,
}

impl ObjectCount {
    fn new(instance: &Instance) -> ObjectCount {
        let world = &instance.world;
        ObjectCount {
            total: world
                .bodies()
                .objects()
                .filter(|(_, o)| o.category != WALL_SYNSET)
                .count(),
            clutter: instance.scene.clutter.len(),
            created: instance.created.len(),
        }
    }
}

/// The init check run on the sampled instance: every `:init` literal re-evaluated.
#[derive(Serialize)]
struct InitReport {
    literals: usize,
    holding: usize,
    relations: usize,
    unary_states: usize,
    inroom: usize,
    failing: Vec<FailingLiteral>,
}

#[derive(Serialize)]
struct FailingLiteral {
    literal: String,
    why: String,
}

#[derive(Serialize)]
struct Binding {
    instance: String,
    object: String,
}

impl InitReport {
    fn new(check: &InitCheck) -> InitReport {
        InitReport {
            literals: check.literals.len(),
            holding: check.holding(),
            relations: check.count(LiteralKind::Relation),
            unary_states: check.count(LiteralKind::UnaryState),
            inroom: check.count(LiteralKind::InRoom),
            failing: check
                .failing()
                .map(|l| FailingLiteral {
                    literal: l.literal.to_string(),
                    why: l
                        .unmet
                        .as_ref()
                        .map(ToString::to_string)
                        .unwrap_or_default(),
                })
                .collect(),
        }
    }

    /// One line, then one per failing literal.
    fn print(&self) {
        println!(
            "init check: {} of {} init literals hold ({} relations, {} unary states, {} inroom)",
            self.holding, self.literals, self.relations, self.unary_states, self.inroom
        );
        for f in &self.failing {
            println!("  fails: {}: {}", f.literal, f.why);
        }
    }
}

pub fn sample(args: SampleArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let activity = prelude.activity(&args.activity)?;
    let scene = match &args.scene {
        Some(name) => crate::scene::load_scene(name, &library)?,
        None => first_covering(&activity, &library, &prelude.knowledge().taxonomy)?,
    };
    let scene = with_clutter(scene, &library, !args.no_clutter)?;
    let start = Instant::now();
    let instance = instantiate(
        &activity,
        &scene,
        args.seed,
        &library,
        &prelude.knowledge().taxonomy,
    )
    .with_context(|| format!("{} in {} (seed {})", args.activity, scene.name, args.seed))?;
    let seconds = start.elapsed().as_secs_f64();
    write_files(&args, &activity, &instance)?;
    let report = SampleReport {
        activity: args.activity.clone(),
        scene: scene.name.clone(),
        seed: args.seed,
        seconds,
        attempt: instance.attempt,
        objects: ObjectCount::new(&instance),
        init_check: InitReport::new(&instance.check_init(&activity)),
        bindings: bindings(&activity, &instance),
        facts: instance.facts(&activity),
        poses: poses(&activity, &instance),
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_report(&report);
    }
    Ok(if report.init_check.failing.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// Every named home that covers the activity, in order.
pub(crate) fn all_covering(
    activity: &Activity,
    library: &Library,
    taxonomy: &Taxonomy,
) -> Result<Vec<Scene>> {
    let homes = named_homes(library)?;
    Ok(covering(&homes, activity, taxonomy)
        .into_iter()
        .cloned()
        .collect())
}

/// The first named home that covers the activity.
pub(crate) fn first_covering(
    activity: &Activity,
    library: &Library,
    taxonomy: &Taxonomy,
) -> Result<Scene> {
    behavior_assets::first_covering(activity, library, taxonomy)?
        .with_context(|| format!("no named home covers {}", activity.name))
}

/// `--out` and `--png`, when asked for.
fn write_files(args: &SampleArgs, activity: &Activity, instance: &Instance) -> Result<()> {
    if let Some(out) = &args.out {
        std::fs::write(out, instance.save().to_json())
            .with_context(|| format!("cannot write {}", out.display()))?;
    }
    if let Some(png) = &args.png {
        let marked: Vec<(String, [f32; 3], [f32; 3])> = instance
            .bindings
            .iter()
            .zip(&activity.instances)
            .map(|(&id, i)| {
                let b = instance.world.bodies().aabb(id);
                (i.name.clone(), b.mins.to_array(), b.maxs.to_array())
            })
            .collect();
        crate::map::render_marked(&instance.scene, 60.0, &marked)
            .save(png)
            .with_context(|| format!("cannot write {}", png.display()))?;
    }
    Ok(())
}

/// Which object each instance is, by name.
fn bindings(activity: &Activity, instance: &Instance) -> Vec<Binding> {
    instance
        .bindings
        .iter()
        .zip(&activity.instances)
        .map(|(&id, i)| Binding {
            instance: i.name.clone(),
            object: instance.world.bodies().object(id).name.clone(),
        })
        .collect()
}

/// Each instance's pose, by name.
fn poses(activity: &Activity, instance: &Instance) -> BTreeMap<String, PoseReport> {
    instance
        .bindings
        .iter()
        .zip(&activity.instances)
        .map(|(&id, i)| {
            let pose = instance.world.bodies().pose(id);
            let report = PoseReport {
                position: pose.translation.to_array(),
                orientation: pose.rotation.to_array(),
            };
            (i.name.clone(), report)
        })
        .collect()
}

fn print_report(report: &SampleReport) {
    println!(
        "{} in {} (seed {}): sampled in {:.3} s, attempt {}",
        report.activity,
        report.scene,
        report.seed,
        report.seconds,
        report.attempt + 1
    );
    let o = &report.objects;
    println!(
        "home: {} objects ({} of them clutter, {} created for the activity), walls left out",
        o.total, o.clutter, o.created
    );
    report.init_check.print();
    for b in &report.bindings {
        println!("  {:<36} {}", b.instance, b.object);
    }
}

/// One (activity, home, seed) of `sample-all` and how it went (its `--json` form).
#[derive(Serialize)]
struct Attempt {
    activity: String,
    scene: String,
    seed: u64,
    ok: bool,
    seconds: f64,
    error: Option<String>,
}

/// One (activity, home, seed) to try.
struct Job<'a> {
    name: &'a str,
    activity: &'a Activity,
    home: &'a Scene,
    seed: u64,
}

pub fn sample_all(args: SampleAllArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let taxonomy = &prelude.knowledge().taxonomy;
    let homes = cluttered(named_homes(&library)?, &library, !args.no_clutter)?;
    let activities = prelude.official_activities()?;
    let mut jobs = Vec::new();
    for (name, activity) in &activities {
        for home in covering(&homes, activity, taxonomy) {
            jobs.extend((0..args.seeds).map(|seed| Job {
                name,
                activity,
                home,
                seed,
            }));
        }
    }
    if jobs.is_empty() {
        bail!("nothing to sample");
    }
    let results = run_jobs(&jobs, &library, taxonomy);
    if args.json {
        println!("{}", serde_json::to_string_pretty(&results)?);
    } else {
        print_summary(&activities, &results);
    }
    Ok(ExitCode::SUCCESS)
}

/// The homes with their clutter (or without, when `on` is false), behind a progress bar: each
/// takes a fraction of a second.
fn cluttered(homes: Vec<Scene>, library: &Library, on: bool) -> Result<Vec<Scene>> {
    let bar = ProgressBar::new(homes.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} cluttering {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let homes = homes
        .into_iter()
        .map(|home| {
            bar.set_message(home.name.clone());
            let home = with_clutter(home, library, on);
            bar.inc(1);
            home
        })
        .collect();
    bar.finish_and_clear();
    homes
}

/// Samples every job in turn, behind a progress bar.
fn run_jobs(jobs: &[Job], library: &Library, taxonomy: &Taxonomy) -> Vec<Attempt> {
    let bar = ProgressBar::new(jobs.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} [{elapsed} / ~{eta}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut results = Vec::with_capacity(jobs.len());
    for job in jobs {
        bar.set_message(job.name.to_string());
        let start = Instant::now();
        let outcome = instantiate(job.activity, job.home, job.seed, library, taxonomy);
        results.push(Attempt {
            activity: job.name.to_string(),
            scene: job.home.name.clone(),
            seed: job.seed,
            ok: outcome.is_ok(),
            seconds: start.elapsed().as_secs_f64(),
            error: outcome.err().map(|e| e.to_string()),
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    results
}

/// One row per activity (homes that worked, tries, median time), then the totals.
fn print_summary(activities: &[(String, Activity)], results: &[Attempt]) {
    println!(
        "{:<42} {:>8} {:>8} {:>10}",
        "activity", "homes ok", "tries", "median s"
    );
    let mut per_activity_ok = 0;
    for (name, _) in activities {
        let mine: Vec<&Attempt> = results.iter().filter(|r| r.activity == *name).collect();
        let mut homes_ok: Vec<&str> = mine
            .iter()
            .filter(|r| r.ok)
            .map(|r| r.scene.as_str())
            .collect();
        homes_ok.dedup();
        if homes_ok.len() >= 3 {
            per_activity_ok += 1;
        }
        let median = median(mine.iter().map(|r| r.seconds).collect());
        println!(
            "{name:<42} {:>8} {:>8} {:>10.3}",
            homes_ok.len(),
            mine.len(),
            median
        );
    }
    let ok = results.iter().filter(|r| r.ok).count();
    println!(
        "{ok} of {} attempts succeeded ({:.1} %); {per_activity_ok} of {} activities in at least 3 homes; median {:.3} s per instance",
        results.len(),
        100.0 * ok as f64 / results.len() as f64,
        activities.len(),
        median(results.iter().map(|r| r.seconds).collect())
    );
}
