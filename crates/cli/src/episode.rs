//! What every command that runs an episode takes — the activity or a saved instance, the home,
//! the seed, the robot, the physics step — and the environment built from it.

use crate::prelude::Prelude;
use crate::sample::first_covering;
use crate::scene::{load_scene, with_clutter};
use anyhow::{Context, Result, bail};
use behavior_bddl::Source;
use behavior_env::{Env, EnvConfig, Instances};
use behavior_robots::RobotKind;
use behavior_sampling::SavedInstance;
use behavior_sim::Substeps;
use std::path::{Path, PathBuf};
use std::sync::Arc;

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

fn read_instance(path: &Path) -> Result<SavedInstance> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    SavedInstance::from_json(&text).with_context(|| path.display().to_string())
}

impl EpisodeArgs {
    /// The saved instance to start from: `--instance`, or the positional argument when it names
    /// a `.json` file.
    fn saved(&self) -> Result<Option<SavedInstance>> {
        let positional = Path::new(&self.activity);
        match &self.instance {
            Some(path) => read_instance(path).map(Some),
            None if positional.extension().is_some_and(|e| e == "json") => {
                read_instance(positional).map(Some)
            }
            None => Ok(None),
        }
    }

    /// Builds the environment (`configure` adjusts its configuration first) and resets it with
    /// the seed.
    pub fn build(
        &self,
        prelude: &Prelude,
        configure: impl FnOnce(&mut EnvConfig),
    ) -> Result<Built> {
        let library = prelude.library();
        let saved = self.saved()?;
        let name = match &saved {
            Some(s)
                if Path::new(&self.activity)
                    .extension()
                    .is_some_and(|e| e == "json") =>
            {
                official_activity(prelude, &s.activity)?
            }
            _ => self.activity.clone(),
        };
        let source = prelude.source(&name)?;
        let activity = prelude.load_activity(&source)?;
        // A saved instance holds its home; otherwise sample in the home asked for.
        let scenes = match (&saved, &self.scene) {
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
            .map(|s| with_clutter(s, &library, !self.no_clutter))
            .collect::<Result<Vec<_>>>()?;
        let mut config = EnvConfig::new(
            Arc::new(activity),
            Arc::new(prelude.knowledge.taxonomy.clone()),
            scenes,
        );
        config.robot = robot_kind(&self.robot)?;
        config.physics = physics(&self.physics_dt)?;
        if let Some(saved) = saved {
            config.instances = Instances::Saved(vec![saved]);
        }
        configure(&mut config);
        let mut env = Env::new(config);
        env.reset(self.seed)
            .with_context(|| format!("starting {} (seed {})", self.activity, self.seed))?;
        Ok(Built { env, source })
    }
}

/// The official activity a saved problem name is of, as the data spells it (problem names are
/// lower case: `filling_a_christmas_stocking_0` is of `filling_a_Christmas_stocking`).
pub(crate) fn official_activity(prelude: &Prelude, problem: &str) -> Result<String> {
    let name = official_name(problem);
    let activities = prelude.data.activities()?;
    activities
        .into_iter()
        .find(|a| a.eq_ignore_ascii_case(name))
        .with_context(|| {
            format!(
                "`{problem}` is not an official activity's problem: give its file with --activity"
            )
        })
}

/// The activity a problem is of: `packing_lunches_0` → `packing_lunches`.
pub(crate) fn official_name(problem: &str) -> &str {
    match problem.rsplit_once('_') {
        Some((name, index)) if !index.is_empty() && index.bytes().all(|b| b.is_ascii_digit()) => {
            name
        }
        _ => problem,
    }
}
