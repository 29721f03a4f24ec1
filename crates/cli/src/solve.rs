//! `behavior solve` and `behavior solve-all`: the task planner agent doing activities with
//! action primitives, scored by Q and the metrics, optionally recorded and filmed.

use crate::episode::EpisodeArgs;
use crate::prelude::{Prelude, counting_bar, median};
use crate::sample::all_covering;
use crate::scene::with_clutter;
use crate::video::{Video, VideoArgs};
use anyhow::{Context, Result, bail};
use behavior_env::record::{CHECKPOINT_EVERY, Provenance, RecordingSetup};
use behavior_env::{Env, EnvConfig, EpisodeMetrics};
use behavior_planning::{
    Executed, GivenUp, Limits, Mode, PrimitiveSet, PrimitiveSpace, RunError, Solution, Solver,
    Watcher,
};
use behavior_sim::STEP_SECONDS;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

/// The step limit of a solved episode: waits for cooking and freezing take many steps.
pub const SOLVE_MAX_STEPS: u32 = 20_000;
/// Seeds `solve-all` tries per home before it goes on to the next covering home.
const SEEDS: u64 = 5;

#[derive(clap::Args)]
pub struct SolveArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    /// symbolic (check, then set the outcome) or physical (plans run with physics).
    #[arg(long, default_value = "symbolic")]
    mode: String,
    /// Record the episode to an MCAP file (`behavior replay --verify` re-does it; `behavior
    /// view` plays it in the browser).
    #[arg(long)]
    record: Option<PathBuf>,
    #[command(flatten)]
    video: VideoArgs,
    /// Primitives run at most.
    #[arg(long, default_value_t = Limits::default().primitives)]
    max_primitives: usize,
    #[arg(long)]
    json: bool,
}

#[derive(clap::Args)]
pub struct SolveAllArgs {
    /// Only these activities (repeat the flag); default: every official one.
    #[arg(long = "activity", value_name = "NAME")]
    activities: Vec<String>,
    #[arg(long, default_value = "symbolic")]
    mode: String,
    /// The embodiment: behavior, fetch or r1.
    #[arg(long, default_value = "behavior")]
    robot: String,
    /// Seeds tried per activity, 0 first, in its first covering home: the next only where the
    /// last did not solve it (an activity counts as solved on any of them).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=100))]
    seeds: u64,
    #[arg(long)]
    json: bool,
}

/// What `behavior solve --json` prints, and each row of `solve-all --json`.
#[derive(Serialize)]
struct Report {
    activity: String,
    scene: String,
    seed: u64,
    robot: String,
    mode: &'static str,
    success: bool,
    q_final: f64,
    primitives: Vec<Executed>,
    given_up: Vec<GivenUp>,
    stopped: String,
    steps: u32,
    sim_time_s: f64,
    wall_s: f64,
    metrics: Option<EpisodeMetrics>,
}

fn mode(name: &str) -> Result<Mode> {
    Mode::from_name(name)
        .with_context(|| format!("--mode must be symbolic or physical, not `{name}`"))
}

pub fn solve(args: SolveArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let mode = mode(&args.mode)?;
    let prelude = Prelude::load(data_dir)?;
    let built = args.episode.build(&prelude, |c| {
        c.max_steps = SOLVE_MAX_STEPS;
        c.action_space = mode.action_space(c.robot);
    })?;
    let mut env = built.env;
    if let Some(path) = &args.record {
        let setup = RecordingSetup::new(&built.source.text, CHECKPOINT_EVERY).by(planner(mode));
        env.record_to(path, setup)?;
    }
    let mut video = args.video.start(&env, &prelude.knowledge().taxonomy)?;
    let limits = Limits {
        primitives: args.max_primitives,
        ..Limits::default()
    };
    let json = args.json;
    let mut print = |e: &Executed| {
        if !json {
            print_executed(e);
        }
    };
    let start = Instant::now();
    let watcher = video.as_mut().map(|v| v as &mut dyn Watcher);
    let solution = Solver::new(&mut env, mode, limits, watcher, &mut print).solve()?;
    let wall = start.elapsed().as_secs_f64();
    env.finish_recording()?;
    let frames = match video {
        Some(mut video) => {
            // The last state, whatever step it came at.
            video.capture(&env, env.steps(), env.score().map_or(0.0, |s| s.q), true)?;
            Some(video.finish()?)
        }
        None => None,
    };
    let report = report(&env, &args.episode.robot, mode, solution, wall);
    if json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_report(&report);
        if let Some(path) = &args.record {
            println!(
                "  recorded to {} (`behavior view` plays it in the browser)",
                path.display()
            );
        }
        if let (Some(path), Some(frames)) = (&args.video.video, frames) {
            println!("  video of {frames} frames in {}", path.display());
        }
    }
    Ok(if report.success {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// A solve's video sees every step.
impl Watcher for Video {
    fn stepped(&mut self, env: &Env, _action: &[f32]) -> Result<(), RunError> {
        let q = env.score().map_or(0.0, |s| s.q);
        self.capture(env, env.steps(), q, false)
            .map_err(|e| RunError::Watcher(format!("{e:#}")))
    }
}

fn report(env: &Env, robot: &str, mode: Mode, solution: Solution, wall_s: f64) -> Report {
    let start = env.start();
    let steps = env.steps();
    Report {
        activity: env.config().activity.name.clone(),
        scene: start
            .map(|s| s.instance.scene.name.clone())
            .unwrap_or_default(),
        seed: start.map_or(0, |s| s.seed),
        robot: robot.to_string(),
        mode: mode.name(),
        success: solution.success,
        q_final: solution.q_final,
        primitives: solution.primitives,
        given_up: solution.given_up,
        stopped: solution.stopped,
        steps,
        sim_time_s: f64::from(steps) * f64::from(STEP_SECONDS),
        wall_s,
        metrics: env.metrics(),
    }
}

fn print_executed(e: &Executed) {
    // A physical OPEN, CLOSE or toggle the hand could not do, set kinematically instead.
    let set = if e.set { ", set" } else { "" };
    let head = format!(
        "  {} {} (hand {}, {} steps{set})",
        e.name, e.object, e.hand, e.steps
    );
    match &e.reason {
        None => println!("{head}"),
        Some(why) => println!("{head}: FAILED: {why}"),
    }
}

fn print_report(r: &Report) {
    println!(
        "{} in {} (seed {}), {} robot, {} primitives: {}, Q = {:.3}, {} primitives, {} steps ({:.1} s simulated) in {:.2} s",
        r.activity,
        r.scene,
        r.seed,
        r.robot,
        r.mode,
        if r.success { "SUCCESS" } else { "not solved" },
        r.q_final,
        r.primitives.len(),
        r.steps,
        r.sim_time_s,
        r.wall_s,
    );
    println!("  stopped: {}", r.stopped);
    for g in &r.given_up {
        println!("  gave up {}: {}", g.literal, g.reason);
    }
}

/// What `behavior solve-all --json` prints.
#[derive(Serialize)]
struct AllReport {
    mode: &'static str,
    robot: String,
    activities: usize,
    /// Activities solved on one of the seeds tried (each stops at its first success).
    solved: usize,
    /// Seeds tried per activity at most.
    seeds: u64,
    /// Activities no seed could sample in any covering home.
    unsampled: Vec<String>,
    /// Over every primitive but waits: its check and outcome, not the step after it.
    median_primitive_ms: f64,
    max_primitive_ms: f64,
    /// The action mask of the whole primitive set (`PrimitiveSet::All`) at each start, ms.
    median_mask_ms: f64,
    max_mask_ms: f64,
    wall_s: f64,
    runs: Vec<Report>,
}

pub fn solve_all(args: SolveAllArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let mode = mode(&args.mode)?;
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let taxonomy = Arc::new(prelude.knowledge().taxonomy.clone());
    let names = prelude.activity_names(&args.activities)?;
    let bar = counting_bar(names.len(), args.json);
    let start = Instant::now();
    let mut runs = Vec::new();
    let mut unsampled = Vec::new();
    let mut primitive_ms = Vec::new();
    let mut mask_ms = Vec::new();
    for name in &names {
        bar.set_message(name.clone());
        let activity = Arc::new(prelude.activity(name)?);
        let homes = all_covering(&activity, &library, &prelude.knowledge().taxonomy)?;
        let Some(mut env) =
            first_sampled(&activity, homes, &library, &args.robot, &taxonomy, mode)?
        else {
            unsampled.push(name.clone());
            bar.inc(1);
            continue;
        };
        let masked = Instant::now();
        if let Some(space) = PrimitiveSpace::of(&env, PrimitiveSet::All) {
            std::hint::black_box(space.mask(&env));
            mask_ms.push(1000.0 * masked.elapsed().as_secs_f64());
        }
        for seed in 0..args.seeds {
            // A seed that samples no instance here is passed over (the first sampled one was
            // found above, and the episode stands reset to it).
            if env.start().is_none_or(|s| s.seed != seed) && env.reset(seed).is_err() {
                continue;
            }
            let began = Instant::now();
            let mut quiet = |_: &_| {};
            let solution =
                Solver::new(&mut env, mode, Limits::default(), None, &mut quiet).solve()?;
            let wall = began.elapsed().as_secs_f64();
            let primitives = solution.primitives.iter().filter(|p| p.name != "wait");
            primitive_ms.extend(primitives.map(|p| p.ms));
            let run = report(&env, &args.robot, mode, solution, wall);
            let success = run.success;
            runs.push(run);
            if success {
                break;
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let solved = runs.iter().filter(|r| r.success).count();
    let all = AllReport {
        mode: mode.name(),
        robot: args.robot.clone(),
        activities: names.len(),
        solved,
        seeds: args.seeds,
        unsampled,
        max_primitive_ms: primitive_ms.iter().copied().fold(0.0, f64::max),
        median_primitive_ms: median(primitive_ms),
        max_mask_ms: mask_ms.iter().copied().fold(0.0, f64::max),
        median_mask_ms: median(mask_ms),
        wall_s: start.elapsed().as_secs_f64(),
        runs,
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&all)?);
    } else {
        print_all(&all);
    }
    if all.activities == 0 {
        bail!("no activities");
    }
    Ok(ExitCode::SUCCESS)
}

/// An environment reset in the first of `homes` (with their clutter) where one of [`SEEDS`]
/// seeds samples an instance; `None` if none does.
fn first_sampled(
    activity: &Arc<behavior_bddl::Activity>,
    homes: Vec<behavior_assets::Scene>,
    library: &behavior_assets::Library,
    robot: &str,
    taxonomy: &Arc<behavior_bddl::Taxonomy>,
    mode: Mode,
) -> Result<Option<Env>> {
    for home in homes {
        let mut env = solve_env(activity, home, library, robot, taxonomy, mode)?;
        // Sampling fails now and then (0.3 % of attempts): the next seed, then the next home.
        if (0..SEEDS).any(|seed| env.reset(seed).is_ok()) {
            return Ok(Some(env));
        }
    }
    Ok(None)
}

/// An episode for the planner in `home` (with its clutter), `robot` acting in `mode`'s action
/// space, with [`SOLVE_MAX_STEPS`]; not reset yet.
pub fn solve_env(
    activity: &Arc<behavior_bddl::Activity>,
    home: behavior_assets::Scene,
    library: &behavior_assets::Library,
    robot: &str,
    taxonomy: &Arc<behavior_bddl::Taxonomy>,
    mode: Mode,
) -> Result<Env> {
    let home = with_clutter(home, library, true)?;
    let mut config = EnvConfig::new(activity.clone(), taxonomy.clone(), vec![home]);
    config.robot = crate::episode::robot_kind(robot)?;
    config.action_space = mode.action_space(config.robot);
    config.max_steps = SOLVE_MAX_STEPS;
    Ok(Env::new(config))
}

fn print_all(all: &AllReport) {
    println!(
        "{:<45} {:>4} {:>8} {:>6} {:>6} {:>7}  why not",
        "activity", "seed", "success", "Q", "prims", "wall s"
    );
    for r in &all.runs {
        let why = r
            .given_up
            .first()
            .map(|g| format!("{}: {}", g.literal, g.reason))
            .unwrap_or_else(|| {
                if r.success {
                    String::new()
                } else {
                    r.stopped.clone()
                }
            });
        println!(
            "{:<45} {:>4} {:>8} {:>6.3} {:>6} {:>7.2}  {}",
            r.activity,
            r.seed,
            if r.success { "yes" } else { "no" },
            r.q_final,
            r.primitives.len(),
            r.wall_s,
            why
        );
    }
    for name in &all.unsampled {
        println!("{name:<45} not sampled in any covering home ({SEEDS} seeds each)");
    }
    println!(
        "{} of {} solved ({} mode, {} robot, on one of {} seeds) in {:.0} s; a primitive took {:.3} ms median, {:.1} ms at most (the step after it not included)",
        all.solved,
        all.activities,
        all.mode,
        all.robot,
        all.seeds,
        all.wall_s,
        all.median_primitive_ms,
        all.max_primitive_ms
    );
    println!(
        "the action mask of every primitive on every object at the start: {:.2} ms median, {:.1} ms at most",
        all.median_mask_ms, all.max_mask_ms
    );
}

/// What a recording of the planner's own plan, in `mode`, says of who acted.
pub fn planner(mode: Mode) -> Provenance {
    Provenance::Planner {
        mode: mode.name().to_string(),
        plan: "planner".to_string(),
    }
}
