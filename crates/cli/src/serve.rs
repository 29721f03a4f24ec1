//! `behavior serve`: the browser viewer and teleoperation server (crate `behavior-web`).

use crate::episode::{Built, EpisodeArgs};
use crate::prelude::Prelude;
use anyhow::{Context, Result, bail};
use behavior_env::record::CHECKPOINT_EVERY;
use behavior_web::{ServeOptions, Session, serve as run_server};
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct ServeArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    /// The port to listen on (0: any free port).
    #[arg(long, default_value_t = 8080)]
    port: u16,
    /// The interface to listen on. The default, 127.0.0.1, admits only this machine; 0.0.0.0
    /// admits every network this machine is on (a headset on the same Wi-Fi, say).
    #[arg(long, default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    host: IpAddr,
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
    let options = ServeOptions {
        addr: SocketAddr::new(args.host, args.port),
    };
    let written = run_server(session, &options, |addr| {
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
