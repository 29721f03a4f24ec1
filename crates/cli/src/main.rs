//! `behavior`: the command-line front of BEHAVIOR in Rust.
//!
//! Each subcommand group lives in its own module, all starting from the same [`prelude`] (data,
//! knowledge, library, named homes); this file only parses arguments and reports errors. Machine-readable output (`--json`) is documented per command in the README.

mod bddl;
mod bench_env;
mod bench_plan;
mod demos;
mod episode;
mod facts;
mod gallery;
mod map;
mod metrics;
mod plot;
mod prelude;
mod render;
mod replay;
mod run;
mod sample;
mod scene;
#[cfg(feature = "web")]
mod serve;
mod solve;
mod video;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "behavior",
    version,
    about = "BEHAVIOR in Rust: household activities for embodied AI"
)]
struct Cli {
    /// Directory holding the official bddl data (the `bddl/` folder of bddl 1.0.1). Default:
    /// $BEHAVIOR_DATA_DIR, else a cache filled from PyPI on first use.
    #[arg(long, global = true, value_name = "DIR")]
    data_dir: Option<PathBuf>,

    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Activity definitions: check, evaluate, list options, statistics.
    #[command(subcommand)]
    Bddl(bddl::BddlCommand),
    /// Homes: the named ones, generating from seeds, maps, activity coverage.
    #[command(subcommand)]
    Scene(scene::SceneCommand),
    /// Sample an instance of an activity in a home: bindings, time taken, init check.
    Sample(sample::SampleArgs),
    /// Try every official activity in every named home that covers it.
    SampleAll(sample::SampleAllArgs),
    /// The logical state of a saved instance: every predicate that holds among its objects.
    Facts(facts::FactsArgs),
    /// Run an agent in an activity: a robot in a sampled home, scored by Q and the metrics.
    Run(run::RunArgs),
    /// What a camera sees: every image modality as PNG and .npy, with a legend of the ids.
    Render(render::RenderArgs),
    /// A contact sheet of every archetype in two variants, labelled with its synset.
    Gallery(gallery::GalleryArgs),
    /// The task planner doing an activity with action primitives: the plan as it runs, then
    /// success, Q and the metrics.
    Solve(solve::SolveArgs),
    /// The task planner on every activity in its first covering home: a summary table.
    SolveAll(solve::SolveAllArgs),
    /// Read a recording; with --verify, re-simulate it and check it bit for bit.
    Replay(replay::ReplayArgs),
    /// The efficiency metrics of recorded episodes, each also as a fraction of the best human
    /// demonstration's (--reference).
    Metrics(metrics::MetricsArgs),
    /// The browser viewer: the home in 3-D, live, with the goal's checklist and the metrics;
    /// drive the BehaviorRobot from the keyboard, a gamepad or a WebXR headset; every episode
    /// recorded.
    #[cfg(feature = "web")]
    Serve(serve::ServeArgs),
    /// A recording played in the browser viewer with a timeline: play, pause, scrub; the
    /// checklist, Q and the metrics at every step.
    #[cfg(feature = "web")]
    View(serve::ViewArgs),
    /// Demonstration datasets: the planner's demonstrations generated, recordings exported for
    /// imitation learning.
    #[command(subcommand)]
    Demos(demos::DemosCommand),
    /// Benchmarks of the whole system.
    #[command(subcommand)]
    Bench(BenchCommand),
}

#[derive(Subcommand)]
enum BenchCommand {
    /// Environment steps per second: every robot, idle and random agents, 1/300 and 1/120 s.
    Env(bench_env::BenchEnvArgs),
    /// The base planner in furnished homes: a place to stand near each activity object, and a
    /// path there.
    Plan(bench_plan::BenchPlanArgs),
}

fn main() -> ExitCode {
    // Like other Unix tools, end quietly when the reader of our output goes away (`| head`).
    #[cfg(unix)]
    // SAFETY: restoring the default disposition of SIGPIPE before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Bddl(command) => bddl::run(command, cli.data_dir.as_deref()),
        Command::Scene(command) => scene::run(command, cli.data_dir.as_deref()),
        Command::Sample(args) => sample::sample(args, cli.data_dir.as_deref()),
        Command::SampleAll(args) => sample::sample_all(args, cli.data_dir.as_deref()),
        Command::Facts(args) => facts::facts(args, cli.data_dir.as_deref()),
        Command::Run(args) => run::run(args, cli.data_dir.as_deref()),
        Command::Render(args) => render::render(args, cli.data_dir.as_deref()),
        Command::Gallery(args) => gallery::gallery(args, cli.data_dir.as_deref()),
        Command::Solve(args) => solve::solve(args, cli.data_dir.as_deref()),
        Command::SolveAll(args) => solve::solve_all(args, cli.data_dir.as_deref()),
        Command::Replay(args) => replay::run(args, cli.data_dir.as_deref()),
        Command::Metrics(args) => {
            metrics::run(args, cli.data_dir.as_deref()).map(|()| ExitCode::SUCCESS)
        }
        #[cfg(feature = "web")]
        Command::Serve(args) => serve::serve(args, cli.data_dir.as_deref()),
        #[cfg(feature = "web")]
        Command::View(args) => serve::view(args, cli.data_dir.as_deref()),
        Command::Demos(command) => demos::run(command, cli.data_dir.as_deref()),
        Command::Bench(BenchCommand::Env(args)) => bench_env::run(args, cli.data_dir.as_deref()),
        Command::Bench(BenchCommand::Plan(args)) => bench_plan::run(args, cli.data_dir.as_deref()),
    };
    match result {
        Ok(code) => code,
        Err(error) => {
            eprintln!("error: {}", report(&error));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes, as `{:#}` writes them but without a cause whose words the message
/// already holds (typed errors here say their cause in their own message).
fn report(error: &anyhow::Error) -> String {
    let mut text = error.to_string();
    for cause in error.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text.push_str(": ");
            text.push_str(&cause);
        }
    }
    text
}
