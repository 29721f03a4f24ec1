//! `behavior bench env`: environment steps per second for every robot, idle and random agents,
//! physics at 1/300 and 1/120 s, state only; then the BehaviorRobot with its eye camera's RGB,
//! depth and segmentation at 128² and 512², in the image profiles asked for (realistic and fast
//! by default) side by side, rendered on whatever adapter there is (lavapipe on a CPU). On the
//! original's speed-benchmark activities in a covering home with clutter; the time split as the
//! original reports it (the images are the observation time), and memory per env.

use crate::episode::{physics, robot_kind};
use crate::prelude::Prelude;
use crate::sample::first_covering;
use crate::scene::with_clutter;
use anyhow::{Context, Result};
use behavior_core::WALL_SYNSET;
use behavior_env::{Agent, CameraConfig, Env, EnvConfig, Instances};
use behavior_render::ImageProfile;
use behavior_robots::RobotKind;
use indicatif::ProgressBar;
use serde::Serialize;
use std::path::Path;
use std::process::ExitCode;
use std::sync::Arc;

/// The original's runtime activities (iGibson's speed benchmark, `envs/benchmark_env.py`).
const ACTIVITIES: [&str; 3] = [
    "bringing_in_wood",
    "re-shelving_library_books",
    "laying_tile_floors",
];
/// Steps before timing starts, as the original discards its first 900 of 1000.
const WARMUP: u32 = 100;
/// The eye camera's default sizes in the image configurations: the original's 128², and 512².
const IMAGE_SIZES: [u32; 2] = [128, 512];

#[derive(clap::Args)]
pub struct BenchEnvArgs {
    /// Timed steps per configuration.
    #[arg(long, default_value_t = 1000)]
    steps: u32,
    /// Timed steps per configuration with images (the eye's RGB, depth and segmentation).
    #[arg(long, default_value_t = 300)]
    image_steps: u32,
    /// Only these activities (repeat the flag for several); default: the three of the original.
    #[arg(long = "activity", value_name = "NAME")]
    activities: Vec<String>,
    /// Only the state-only configurations: no rendering.
    #[arg(long, conflicts_with = "images_only")]
    state_only: bool,
    /// Only the configurations with images.
    #[arg(long)]
    images_only: bool,
    /// The image profiles to time (repeat the flag for several); default: realistic and fast,
    /// side by side.
    #[arg(long = "profile", value_name = "PROFILE")]
    profiles: Vec<ImageProfile>,
    /// The eye camera's image sizes, square (repeat the flag for several); default: 128 and 512.
    #[arg(long = "image-size", value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    image_sizes: Vec<u32>,
    /// The robots to time, behavior, fetch or r1 (repeat the flag for several); default: every
    /// robot without images, the BehaviorRobot with images.
    #[arg(long = "robot", value_name = "ROBOT")]
    robots: Vec<String>,
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Row {
    activity: String,
    scene: String,
    objects: usize,
    robot: String,
    agent: String,
    physics_dt: String,
    /// `none`, or the eye camera's image size (RGB, depth and segmentation).
    images: String,
    /// The image profile (`-` without images).
    profile: String,
    steps_per_second: f64,
    /// Mean per step, µs.
    physics_us: f64,
    rules_us: f64,
    scoring_us: f64,
    observing_us: f64,
    total_us: f64,
    /// The goal check and the metrics as a share of the step.
    scoring_share: f64,
}

#[derive(Serialize)]
struct Report {
    steps: u32,
    image_steps: u32,
    rows: Vec<Row>,
    /// Resident memory added per environment (world, robot, metrics, instance), MB: the growth
    /// of the process's resident set over eight environments kept alive, divided by eight.
    memory_per_env_mb: f64,
    /// The same with the eye camera's 128² images in the first profile timed (each env its own
    /// renderer), MB.
    memory_per_env_with_images_mb: Option<f64>,
}

fn resident_mb() -> f64 {
    let statm = std::fs::read_to_string("/proc/self/statm").unwrap_or_default();
    let pages: f64 = statm
        .split_whitespace()
        .nth(1)
        .and_then(|p| p.parse().ok())
        .unwrap_or(0.0);
    pages * 4096.0 / 1e6
}

pub fn run(args: BenchEnvArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    let taxonomy = Arc::new(prelude.knowledge().taxonomy.clone());
    let mut rows = Vec::new();
    let mut memory = 0.0f64;
    let mut memory_images: Option<f64> = None;
    let profiles = if args.profiles.is_empty() {
        ImageProfile::ALL.to_vec()
    } else {
        args.profiles.clone()
    };
    let names: Vec<&str> = if args.activities.is_empty() {
        ACTIVITIES.to_vec()
    } else {
        args.activities.iter().map(String::as_str).collect()
    };
    let sizes = if args.image_sizes.is_empty() {
        IMAGE_SIZES.to_vec()
    } else {
        args.image_sizes.clone()
    };
    for robot in &args.robots {
        robot_kind(robot)?;
    }
    let robot_count = args.robots.len() as u64;
    let bar = if args.json {
        ProgressBar::hidden()
    } else {
        let state = match (args.images_only, robot_count) {
            (true, _) => 0,
            (false, 0) => 8,
            (false, n) => 4 * n,
        };
        let images = if args.state_only {
            0
        } else {
            2 * robot_count.max(1) * (sizes.len() * profiles.len()) as u64
        };
        ProgressBar::new(names.len() as u64 * (state + images))
    };
    for name in names {
        let activity = Arc::new(prelude.activity(name)?);
        let home = first_covering(&activity, &library, &prelude.knowledge().taxonomy)?;
        let home = with_clutter(home, &library, true)?;
        let base = EnvConfig::new(activity.clone(), taxonomy.clone(), vec![home.clone()]);
        // Sample once; every configuration starts from the same instance.
        let mut sampler = Env::new(base.clone());
        sampler
            .reset(0)
            .with_context(|| format!("sampling {name}"))?;
        let instance = sampler.start().context("no episode")?.instance.clone();
        memory = memory.max(memory_per_env(&base, &instance)?);
        if !args.state_only {
            let mut with_images = base.clone();
            with_images.observations.camera = Some(CameraConfig {
                profile: profiles[0],
                ..CameraConfig::default()
            });
            let grown = memory_per_env(&with_images, &instance)?;
            memory_images = Some(memory_images.map_or(grown, |m| m.max(grown)));
        }
        let objects = sampler.world().map_or(0, |w| {
            w.bodies()
                .objects()
                .filter(|(_, o)| o.category != WALL_SYNSET)
                .count()
        });
        drop(sampler);
        let both = RobotKind::ALL.map(|kind| kind.name().to_string());
        let state_robots: &[String] = match (args.images_only, args.robots.is_empty()) {
            (true, _) => &[],
            (false, true) => &both,
            (false, false) => &args.robots,
        };
        for robot in state_robots {
            for agent in ["idle", "random"] {
                for dt in ["1/300", "1/120"] {
                    let mut config = base.clone();
                    config.instances = Instances::Saved(vec![instance.clone()]);
                    config.robot = robot_kind(robot)?;
                    config.physics = physics(dt)?;
                    config.max_steps = u32::MAX;
                    let row = measure(config, agent, args.steps)?;
                    rows.push(Row {
                        activity: name.to_string(),
                        scene: home.name.clone(),
                        objects,
                        robot: robot.to_string(),
                        agent: agent.to_string(),
                        physics_dt: dt.to_string(),
                        images: "none".into(),
                        profile: "-".into(),
                        ..row
                    });
                    bar.inc(1);
                }
            }
        }
        if args.state_only {
            continue;
        }
        // Profiles side by side: each size's and agent's rows of every profile together.
        let image_robots = if args.robots.is_empty() {
            vec!["behavior".to_string()]
        } else {
            args.robots.clone()
        };
        let image_rows = image_robots
            .iter()
            .flat_map(|r| sizes.iter().map(move |s| (r, s)))
            .flat_map(|(r, s)| ["idle", "random"].map(|a| (r, s, a)))
            .flat_map(|(r, s, a)| profiles.iter().map(move |p| (r, s, a, p)));
        for (robot, &size, agent, &profile) in image_rows {
            let mut config = base.clone();
            config.instances = Instances::Saved(vec![instance.clone()]);
            config.robot = robot_kind(robot)?;
            config.max_steps = u32::MAX;
            config.observations.camera = Some(CameraConfig {
                width: size,
                height: size,
                profile,
                ..CameraConfig::default()
            });
            let row = measure(config, agent, args.image_steps)?;
            rows.push(Row {
                activity: name.to_string(),
                scene: home.name.clone(),
                objects,
                robot: robot.clone(),
                agent: agent.to_string(),
                physics_dt: "1/300".into(),
                images: format!("{size}²"),
                profile: profile.to_string(),
                ..row
            });
            bar.inc(1);
        }
    }
    bar.finish_and_clear();
    let report = Report {
        steps: args.steps,
        image_steps: args.image_steps,
        rows,
        memory_per_env_mb: memory,
        memory_per_env_with_images_mb: memory_images,
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print(&report);
    }
    Ok(ExitCode::SUCCESS)
}

/// The resident memory eight environments of `instance` add, each reset and stepped, per env.
fn memory_per_env(base: &EnvConfig, instance: &behavior_sampling::SavedInstance) -> Result<f64> {
    const ENVS: usize = 8;
    let before = resident_mb();
    let mut envs = Vec::with_capacity(ENVS);
    for _ in 0..ENVS {
        let mut config = base.clone();
        config.instances = Instances::Saved(vec![instance.clone()]);
        let mut env = Env::new(config);
        env.reset(0)?;
        for _ in 0..30 {
            env.step(&[0.0; 26])?;
        }
        envs.push(env);
    }
    let grown = resident_mb() - before;
    drop(envs);
    Ok(grown / ENVS as f64)
}

/// Steps one configuration: the warm-up, then `steps` timed.
fn measure(config: EnvConfig, agent: &str, steps: u32) -> Result<Row> {
    let mut env = Env::new(config);
    env.reset(0)?;
    let mut agent = Agent::named(agent, 0).context("agent")?;
    let dim = env.robot().map_or(0, |r| r.action_dim());
    let mut action = Vec::with_capacity(dim);
    for k in 0..WARMUP + steps {
        if k == WARMUP {
            env.take_timings();
        }
        agent.act(&env, &mut action);
        env.step(&action)?;
    }
    let t = env.take_timings();
    let per = |d: std::time::Duration| d.as_secs_f64() * 1e6 / f64::from(t.steps.max(1));
    Ok(Row {
        activity: String::new(),
        scene: String::new(),
        objects: 0,
        robot: String::new(),
        agent: String::new(),
        physics_dt: String::new(),
        images: String::new(),
        profile: String::new(),
        steps_per_second: f64::from(t.steps) / t.total.as_secs_f64().max(1e-12),
        physics_us: per(t.physics),
        rules_us: per(t.rules),
        scoring_us: per(t.scoring),
        observing_us: per(t.observing),
        total_us: per(t.total),
        scoring_share: t.scoring.as_secs_f64() / t.total.as_secs_f64().max(1e-12),
    })
}

fn print(report: &Report) {
    println!(
        "{:<27} {:>7} {:<8} {:<6} {:<6} {:<6} {:<9} {:>9} {:>9} {:>8} {:>9} {:>7} {:>7}",
        "activity",
        "objects",
        "robot",
        "agent",
        "dt",
        "images",
        "profile",
        "steps/s",
        "physics",
        "rules",
        "Q+metrics",
        "obs",
        "share"
    );
    for r in &report.rows {
        println!(
            "{:<27} {:>7} {:<8} {:<6} {:<6} {:<6} {:<9} {:>9.0} {:>7.0}µs {:>6.0}µs {:>7.1}µs {:>5.0}µs {:>6.1}%",
            r.activity,
            r.objects,
            r.robot,
            r.agent,
            r.physics_dt,
            r.images,
            r.profile,
            r.steps_per_second,
            r.physics_us,
            r.rules_us,
            r.scoring_us,
            r.observing_us,
            r.scoring_share * 100.0
        );
    }
    println!(
        "{} timed steps per row ({} with images) after {WARMUP} warm-up steps; memory per env ≈ {:.0} MB",
        report.steps, report.image_steps, report.memory_per_env_mb
    );
    if let Some(mb) = report.memory_per_env_with_images_mb {
        println!("memory per env with the eye's 128² images ≈ {mb:.0} MB");
    }
}
