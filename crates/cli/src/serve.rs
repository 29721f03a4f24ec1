//! `behavior serve` and `behavior view`: the browser viewer, teleoperation server and recording
//! player (crate `behavior-web`).

use crate::episode::{Built, EpisodeArgs};
use crate::prelude::Prelude;
use crate::replay::recorded_config;
use anyhow::{Context, Result, bail};
use behavior_env::Env;
use behavior_env::record::redo;
use behavior_env::record::{CHECKPOINT_EVERY, read};
use behavior_planning::RecordedCall;
use behavior_web::{Playback, ServeOptions, Session, serve as run_server, view as run_viewer};
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Where the page is served.
#[derive(clap::Args)]
struct Listen {
    /// The port to listen on (0: any free port).
    #[arg(long, default_value_t = 8080)]
    port: u16,
    /// The interface to listen on. The default, 127.0.0.1, admits only this machine; 0.0.0.0
    /// admits every network this machine is on (a headset on the same Wi-Fi, say).
    #[arg(long, default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    host: IpAddr,
}

impl Listen {
    fn options(&self) -> ServeOptions {
        ServeOptions {
            addr: SocketAddr::new(self.host, self.port),
        }
    }
}

#[derive(clap::Args)]
pub struct ServeArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    #[command(flatten)]
    listen: Listen,
    /// Where each episode's recording goes (one MCAP file per episode with steps).
    #[arg(long, default_value = "demos")]
    record_dir: PathBuf,
    /// Action steps (1/30 s each) before an episode is truncated.
    #[arg(long, default_value_t = behavior_env::DEFAULT_MAX_STEPS)]
    steps: u32,
}

pub fn serve(args: ServeArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    if args.episode.robot != "behavior" {
        bail!(
            "`behavior serve` drives the BehaviorRobot (the embodiment of the paper's demonstrations); leave out --robot"
        );
    }
    let prelude = Prelude::load(data_dir)?;
    let Built { env, source } = args.episode.build(&prelude, |config| {
        config.max_steps = args.steps.max(1);
    })?;
    let session = Session {
        env,
        definition: source.text.clone(),
        seed: args.episode.seed,
        record_dir: args.record_dir.clone(),
        checkpoint_every: CHECKPOINT_EVERY,
    };
    let written = run_server(session, &args.listen.options(), |addr| {
        println!(
            "serving {} on http://{addr}/ (Ctrl-C to stop)",
            args.episode.activity
        );
        println!("  recordings go to {}", args.record_dir.display());
    })
    .context("behavior serve")?;
    println!("stopped; {} recording(s) written", written.len());
    for path in written {
        println!("  {}", path.display());
    }
    Ok(ExitCode::SUCCESS)
}

#[derive(clap::Args)]
pub struct ViewArgs {
    /// A recording: `behavior serve`'s, `run --record`'s or `solve --record`'s.
    file: PathBuf,
    #[command(flatten)]
    listen: Listen,
}

/// `behavior view`: the recording re-simulated and played in the page, with a timeline.
pub fn view(args: ViewArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let recording = read(&args.file)?;
    if let Some(damage) = &recording.damage {
        eprintln!("warning: {damage}; playing the steps before it");
    }
    let prelude = Prelude::load(data_dir)?;
    let config = recorded_config(&args.file, &recording, &prelude)?;
    let name = args.file.file_name().map_or_else(
        || args.file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let h = &recording.header;
    let summary = format!(
        "{} in {} (seed {}), {} robot, {} steps",
        h.activity,
        h.scene,
        h.seed,
        h.robot,
        recording.frames.len()
    );
    let playback = Playback {
        env: Env::new(config),
        recording,
        editor: redo::<RecordedCall>,
        name,
    };
    run_viewer(playback, &args.listen.options(), |addr| {
        println!("playing {summary} on http://{addr}/ (Ctrl-C to stop)");
    })
    .context("behavior view")?;
    Ok(ExitCode::SUCCESS)
}
