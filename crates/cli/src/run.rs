//! `behavior run`: an agent doing an activity, scored, optionally recorded and plotted.

use crate::episode::{Built, EpisodeArgs};
use crate::plot::plot_episode;
use crate::prelude::Prelude;
use crate::video::{Video, VideoArgs};
use anyhow::{Context, Result};
use behavior_env::record::{CHECKPOINT_EVERY, RecordingSetup};
use behavior_env::{Agent, EpisodeMetrics};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(clap::Args)]
pub struct RunArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    /// The agent: idle (all-zero actions) or random (uniform in [-1, 1], seeded by --seed).
    #[arg(long, default_value = "random")]
    agent: String,
    /// Action steps (1/30 s each) before the episode is truncated.
    #[arg(long, default_value_t = 300)]
    steps: u32,
    /// Record the episode to an MCAP file.
    #[arg(long, value_name = "FILE.mcap")]
    record: Option<PathBuf>,
    /// Full-state checkpoints in the recording every this many steps.
    #[arg(long, default_value_t = CHECKPOINT_EVERY)]
    checkpoint_every: u32,
    /// Draw Q and the efficiency metrics over time.
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    #[command(flatten)]
    video: VideoArgs,
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
    /// Frames in the `--video` file, when one was asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    video_frames: Option<u32>,
}

pub fn run(args: RunArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let e = &args.episode;
    let mut agent = Agent::named(&args.agent, e.seed)
        .with_context(|| format!("--agent must be idle or random, not `{}`", args.agent))?;
    let Built { mut env, source } = e.build(&prelude, |config| {
        config.max_steps = args.steps.max(1);
    })?;
    if let Some(path) = &args.record {
        env.record_to(
            path,
            RecordingSetup::new(&source.text, args.checkpoint_every),
        )?;
    }
    let mut video = args.video.start(&env, &prelude.knowledge().taxonomy)?;
    let bar = progress(args.steps, args.json);
    let dim = env.robot().map_or(0, |r| r.action_dim());
    let mut action = Vec::with_capacity(dim);
    let start = Instant::now();
    loop {
        agent.act(&env, &mut action);
        let step = env.step(&action)?;
        let last = step.terminated || step.truncated;
        if let Some(v) = &mut video {
            v.capture(&env, step.info.steps, step.info.score.q, last)?;
        }
        bar.set_message(format!("Q {:.3}", step.info.score.q));
        bar.inc(1);
        if last {
            break;
        }
    }
    let wall_s = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    env.finish_recording()?;
    let frames = video.map(Video::finish).transpose()?;
    let metrics = env.metrics().context("no episode")?;
    if let (Some(path), Some(series)) = (&args.plot, env.series()) {
        plot_episode(series, &e.activity, path)?;
    }
    let start = env.start().context("no episode")?;
    let report = RunReport {
        activity: e.activity.clone(),
        scene: start.instance.scene.name.clone(),
        seed: e.seed,
        robot: e.robot.clone(),
        agent: agent.name().to_string(),
        steps: metrics.steps,
        success: metrics.success,
        q_final: metrics.q_final,
        q_max: metrics.q_max,
        steps_per_second: f64::from(metrics.steps) / wall_s.max(1e-9),
        metrics,
        wall_s,
        video_frames: frames,
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
    if let (Some(path), Some(frames)) = (&args.video.video, r.video_frames) {
        println!("  video of {frames} frames in {}", path.display());
    }
}
