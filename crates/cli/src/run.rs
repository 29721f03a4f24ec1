//! `behavior run`: an agent doing an activity, scored, optionally recorded and plotted.

use crate::plot::plot_episode;
use crate::prelude::Prelude;
use crate::sample::first_covering;
use crate::scene::{load_scene, with_clutter};
use anyhow::{Context, Result, bail};
use behavior_env::record::{CHECKPOINT_EVERY, Recorder};
use behavior_env::{Agent, Env, EnvConfig, EpisodeMetrics, Instances};
use behavior_robots::RobotKind;
use behavior_sampling::SavedInstance;
use behavior_sim::Substeps;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

#[derive(clap::Args)]
pub struct RunArgs {
    /// An official activity name or a problem file of one's own.
    #[arg(default_value = "bringing_in_wood")]
    activity: String,
    /// A named home or a scene file (default: the first named home that covers the activity).
    #[arg(long)]
    scene: Option<String>,
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// The embodiment: behavior (the BehaviorRobot) or fetch.
    #[arg(long, default_value = "behavior")]
    robot: String,
    /// The agent: idle (all-zero actions) or random (uniform in [-1, 1], seeded by --seed).
    #[arg(long, default_value = "random")]
    agent: String,
    /// Action steps (1/30 s each) before the episode is truncated.
    #[arg(long, default_value_t = 300)]
    steps: u32,
    /// Physics time step: 1/300 or 1/120.
    #[arg(long, default_value = "1/300")]
    physics_dt: String,
    /// Start from a saved instance (`behavior sample --out`) instead of sampling one.
    #[arg(long, value_name = "FILE.json")]
    instance: Option<PathBuf>,
    /// Record the episode to an MCAP file.
    #[arg(long, value_name = "FILE.mcap")]
    record: Option<PathBuf>,
    /// Full-state checkpoints in the recording every this many steps.
    #[arg(long, default_value_t = CHECKPOINT_EVERY)]
    checkpoint_every: u32,
    /// Draw Q and the efficiency metrics over time.
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Sample in the furniture-only home.
    #[arg(long)]
    no_clutter: bool,
    #[arg(long)]
    json: bool,
}

/// What `behavior run --json` prints.
#[derive(Serialize)]
struct RunReport {
    activity: String,
    scene: String,
    seed: u64,
    robot: String,
    agent: String,
    steps: u32,
    success: bool,
    q_final: f64,
    q_max: f64,
    metrics: EpisodeMetrics,
    wall_s: f64,
    steps_per_second: f64,
}

pub(crate) fn physics(text: &str) -> Result<Substeps> {
    match text {
        "1/300" => Ok(Substeps::Hz300),
        "1/120" => Ok(Substeps::Hz120),
        other => bail!("--physics-dt must be 1/300 or 1/120, not `{other}`"),
    }
}

pub(crate) fn robot_kind(name: &str) -> Result<RobotKind> {
    RobotKind::from_name(name).with_context(|| {
        let known: Vec<&str> = RobotKind::ALL.iter().map(|k| k.name()).collect();
        format!("--robot must be one of {}, not `{name}`", known.join(", "))
    })
}

pub fn run(args: RunArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let source = prelude.source(&args.activity)?;
    let activity = prelude.load_activity(&source)?;
    let mut agent = Agent::named(&args.agent, args.seed)
        .with_context(|| format!("--agent must be idle or random, not `{}`", args.agent))?;
    // A saved instance holds its home; otherwise sample in the home asked for.
    let scenes = match (&args.instance, &args.scene) {
        (Some(_), _) => Vec::new(),
        (None, Some(name)) => vec![load_scene(name, &library)?],
        (None, None) => vec![first_covering(
            &activity,
            &library,
            &prelude.knowledge.taxonomy,
        )?],
    };
    let scenes = scenes
        .into_iter()
        .map(|s| with_clutter(s, &library, !args.no_clutter))
        .collect::<Result<Vec<_>>>()?;
    let mut config = EnvConfig::new(
        Arc::new(activity),
        Arc::new(prelude.knowledge.taxonomy.clone()),
        scenes,
    );
    config.robot = robot_kind(&args.robot)?;
    config.physics = physics(&args.physics_dt)?;
    config.max_steps = args.steps.max(1);
    if let Some(path) = &args.instance {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        let saved = SavedInstance::from_json(&text).with_context(|| path.display().to_string())?;
        config.instances = Instances::Saved(vec![saved]);
    }
    let mut env = Env::new(config);
    env.reset(args.seed)
        .with_context(|| format!("starting {} (seed {})", args.activity, args.seed))?;
    let mut recorder = match &args.record {
        Some(path) => Some(Recorder::create(
            path,
            &env,
            &source.text,
            args.checkpoint_every,
        )?),
        None => None,
    };
    let bar = progress(args.steps, args.json);
    let dim = env.robot().map_or(0, |r| r.action_dim());
    let mut action = Vec::with_capacity(dim);
    let start = Instant::now();
    loop {
        agent.act(dim, &mut action);
        let step = env.step(&action)?;
        if let Some(r) = &mut recorder {
            r.record(&env, &action)?;
        }
        bar.set_message(format!("Q {:.3}", step.info.score.q));
        bar.inc(1);
        if step.terminated || step.truncated {
            break;
        }
    }
    let wall_s = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    if let Some(r) = recorder {
        r.finish()?;
    }
    let metrics = env.metrics().context("no episode")?;
    if let (Some(path), Some(series)) = (&args.plot, env.series()) {
        plot_episode(series, &args.activity, path)?;
    }
    let start = env.start().context("no episode")?;
    let report = RunReport {
        activity: args.activity.clone(),
        scene: start.instance.scene.name.clone(),
        seed: args.seed,
        robot: args.robot.clone(),
        agent: agent.name().to_string(),
        steps: metrics.steps,
        success: metrics.success,
        q_final: metrics.q_final,
        q_max: metrics.q_max,
        steps_per_second: f64::from(metrics.steps) / wall_s.max(1e-9),
        metrics,
        wall_s,
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_report(&report, &args);
    }
    Ok(ExitCode::SUCCESS)
}

fn progress(steps: u32, hidden: bool) -> ProgressBar {
    if hidden {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(u64::from(steps));
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} steps {msg} ({eta})") {
        bar.set_style(style);
    }
    bar
}

fn print_report(r: &RunReport, args: &RunArgs) {
    let m = &r.metrics;
    println!(
        "{} in {} (seed {}), {} robot, {} agent: {} steps in {:.2} s ({:.0} steps/s)",
        r.activity, r.scene, r.seed, r.robot, r.agent, r.steps, r.wall_s, r.steps_per_second
    );
    println!(
        "  success {}   Q final {:.3}   Q max {:.3}",
        r.success, r.q_final, r.q_max
    );
    println!(
        "  simulated time {:.2} s   kinematic disarrangement {:.3} m   logical disarrangement {}",
        m.sim_time_s, m.kinematic_disarrangement, m.logical_disarrangement
    );
    println!(
        "  distance navigated {:.3} m   hand displacement left {:.3} m, right {:.3} m   work {:.1} J",
        m.distance_navigated, m.hand_displacement_left, m.hand_displacement_right, m.work
    );
    if let Some(path) = &args.record {
        println!("  recorded to {}", path.display());
    }
    if let Some(path) = &args.plot {
        println!("  plotted to {}", path.display());
    }
}
