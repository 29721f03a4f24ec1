//! What every command that runs an episode takes — the activity or a saved instance, the home,
//! the seed, the robot, the physics step — and the environment built from it.

use crate::prelude::Prelude;
use anyhow::Result;
use behavior_bddl::Source;
use behavior_catalog::EnvSpec;
use behavior_env::{Env, EnvConfig};
use behavior_robots::RobotKind;
use behavior_sim::Substeps;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct EpisodeArgs {
    /// An official activity name, a problem file of one's own, or a saved instance
    /// (`INSTANCE.json`, from `behavior sample --out`).
    #[arg(default_value = "bringing_in_wood")]
    pub activity: String,
    /// A named home or a scene file (default: the first named home that covers the activity).
    #[arg(long)]
    pub scene: Option<String>,
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// The embodiment: behavior (the BehaviorRobot), fetch or r1 (the Galaxea R1 Pro).
    #[arg(long, default_value = "behavior")]
    pub robot: String,
    /// Physics time step: 1/300 or 1/120.
    #[arg(long, default_value = "1/300")]
    pub physics_dt: String,
    /// Start from a saved instance (`behavior sample --out`) instead of sampling one.
    #[arg(long, value_name = "FILE.json")]
    pub instance: Option<PathBuf>,
    /// Sample in the furniture-only home.
    #[arg(long)]
    pub no_clutter: bool,
}

/// An environment reset to its first episode, and the definition it runs (for recordings).
pub struct Built {
    pub env: Env,
    pub source: Source,
}

/// The physics step of `--physics-dt`.
pub(crate) fn physics(text: &str) -> Result<Substeps> {
    Ok(behavior_catalog::physics(text)?)
}

/// The robot of `--robot`.
pub(crate) fn robot_kind(name: &str) -> Result<RobotKind> {
    Ok(behavior_catalog::robot_kind(name)?)
}

impl EpisodeArgs {
    /// What the arguments name, for the catalog (`behavior-catalog`) to build.
    fn spec(&self) -> EnvSpec {
        EnvSpec {
            scene: self.scene.clone(),
            instance: self.instance.clone(),
            seed: self.seed,
            robot: self.robot.clone(),
            physics: self.physics_dt.clone(),
            clutter: !self.no_clutter,
            ..EnvSpec::new(&self.activity)
        }
    }

    /// Builds the environment (`configure` adjusts its configuration first) and resets it with
    /// the seed; the definition's warnings go to stderr.
    pub fn build(
        &self,
        prelude: &Prelude,
        configure: impl FnOnce(&mut EnvConfig),
    ) -> Result<Built> {
        let built = prelude.build(&self.spec(), configure)?;
        eprint!("{}", built.warnings);
        Ok(Built {
            env: built.env,
            source: built.source,
        })
    }
}
