//! `behavior sample` and `behavior sample-all`: instantiate activities in homes.

use anyhow::{Context, Result, bail};
use behavior_assets::coverage::{missing, requirements};
use behavior_assets::{Library, NAMED_HOMES, Scene, generate};
use behavior_bddl::Knowledge;
use behavior_data::DataDir;
use behavior_sampling::instantiate;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
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
    #[arg(long)]
    json: bool,
}

#[derive(clap::Args)]
pub struct SampleAllArgs {
    /// Seeds per (activity, covering home), 1 to 1000.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=1000))]
    seeds: u64,
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Attempt {
    activity: String,
    scene: String,
    seed: u64,
    ok: bool,
    seconds: f64,
    error: Option<String>,
}

fn named_homes(library: &Library) -> Result<Vec<Scene>> {
    Ok(NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, library))
        .collect::<Result<_, _>>()?)
}

pub fn sample(args: SampleArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let data = DataDir::locate(data_dir, |message| eprintln!("{message}"))?;
    let knowledge = behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path())?;
    let library = Library::new(&knowledge.taxonomy);
    let (activity, _) = knowledge.load(&crate::bddl::source_of(&data, &args.activity)?)?;
    let scene = match &args.scene {
        Some(name) => crate::scene::load_scene(name, &library)?,
        None => {
            let needs = requirements(&activity);
            named_homes(&library)?
                .into_iter()
                .find(|h| missing(h, &needs, &knowledge.taxonomy).is_empty())
                .with_context(|| format!("no named home covers {}", args.activity))?
        }
    };
    let start = Instant::now();
    let instance = instantiate(&activity, &scene, args.seed, &library, &knowledge.taxonomy)
        .with_context(|| format!("{} in {} (seed {})", args.activity, scene.name, args.seed))?;
    let seconds = start.elapsed().as_secs_f64();
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
                let b = instance.world.core().aabb(id);
                (i.name.clone(), b.mins.to_array(), b.maxs.to_array())
            })
            .collect();
        crate::map::render_marked(&scene, 60.0, &marked)
            .save(png)
            .with_context(|| format!("cannot write {}", png.display()))?;
    }
    let bindings: Vec<(String, String)> = instance
        .bindings
        .iter()
        .zip(&activity.instances)
        .map(|(&id, i)| (i.name.clone(), instance.world.object(id).name.clone()))
        .collect();
    if args.json {
        let report = serde_json::json!({
            "activity": args.activity, "scene": scene.name, "seed": args.seed, "seconds": seconds,
            "attempt": instance.attempt, "init_check": "every init literal holds",
            "bindings": bindings.iter().map(|(i, o)| serde_json::json!({"instance": i, "object": o})).collect::<Vec<_>>(),
        });
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        println!(
            "{} in {} (seed {}): sampled in {:.3} s, attempt {}",
            args.activity,
            scene.name,
            args.seed,
            seconds,
            instance.attempt + 1
        );
        println!("init check: every init literal holds in the settled world");
        for (i, o) in &bindings {
            println!("  {i:<36} {o}");
        }
    }
    Ok(ExitCode::SUCCESS)
}

pub fn sample_all(args: SampleAllArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let data = DataDir::locate(data_dir, |message| eprintln!("{message}"))?;
    let knowledge = behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path())?;
    let library = Library::new(&knowledge.taxonomy);
    let homes = named_homes(&library)?;
    let mut jobs: Vec<(String, usize, u64)> = Vec::new();
    let activities = load_all(&data, &knowledge)?;
    for (name, activity) in &activities {
        let needs = requirements(activity);
        for (h, home) in homes.iter().enumerate() {
            if missing(home, &needs, &knowledge.taxonomy).is_empty() {
                jobs.extend((0..args.seeds).map(|seed| (name.clone(), h, seed)));
            }
        }
    }
    if jobs.is_empty() {
        bail!("nothing to sample");
    }
    let bar = ProgressBar::new(jobs.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} [{elapsed} / ~{eta}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut results = Vec::with_capacity(jobs.len());
    for (name, h, seed) in jobs {
        bar.set_message(name.clone());
        let activity = &activities
            .iter()
            .find(|(n, _)| *n == name)
            .expect("loaded")
            .1;
        let start = Instant::now();
        let outcome = instantiate(activity, &homes[h], seed, &library, &knowledge.taxonomy);
        results.push(Attempt {
            activity: name,
            scene: homes[h].name.clone(),
            seed,
            ok: outcome.is_ok(),
            seconds: start.elapsed().as_secs_f64(),
            error: outcome.err().map(|e| e.to_string()),
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    if args.json {
        println!("{}", serde_json::to_string_pretty(&results)?);
        return Ok(ExitCode::SUCCESS);
    }
    println!(
        "{:<42} {:>8} {:>8} {:>10}",
        "activity", "homes ok", "tries", "median s"
    );
    let mut per_activity_ok = 0;
    for (name, _) in &activities {
        let mine: Vec<&Attempt> = results.iter().filter(|r| r.activity == *name).collect();
        let mut homes_ok: Vec<&str> = mine
            .iter()
            .filter(|r| r.ok)
            .map(|r| r.scene.as_str())
            .collect();
        homes_ok.dedup();
        let mut times: Vec<f64> = mine.iter().map(|r| r.seconds).collect();
        times.sort_by(f64::total_cmp);
        let median = times.get(times.len() / 2).copied().unwrap_or(f64::NAN);
        if homes_ok.len() >= 3 {
            per_activity_ok += 1;
        }
        println!(
            "{name:<42} {:>8} {:>8} {:>10.3}",
            homes_ok.len(),
            mine.len(),
            median
        );
    }
    let ok = results.iter().filter(|r| r.ok).count();
    let mut times: Vec<f64> = results.iter().map(|r| r.seconds).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "{ok} of {} attempts succeeded ({:.1} %); {per_activity_ok} of {} activities in at least 3 homes; median {:.3} s per instance",
        results.len(),
        100.0 * ok as f64 / results.len() as f64,
        activities.len(),
        times[times.len() / 2]
    );
    Ok(ExitCode::SUCCESS)
}

fn load_all(
    data: &DataDir,
    knowledge: &Knowledge,
) -> Result<Vec<(String, behavior_bddl::Activity)>> {
    data.activities()?
        .into_iter()
        .map(|name| {
            let (activity, _) = knowledge.load(&behavior_bddl::load::read_source(
                &data.problem_path(&name)?,
            )?)?;
            Ok((name, activity))
        })
        .collect()
}
