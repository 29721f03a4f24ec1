//! Environments built from names: the one place where "this activity, in this home, with this
//! robot" becomes an [`Env`], for the command line, the Python package and the web server alike.
//!
//! A [`Catalog`] holds the official data (located, or fetched from PyPI on first use) and the
//! knowledge loaded from it (taxonomy and domain). An [`EnvSpec`] names what an environment is
//! made of — an official activity, a definition file or a saved instance; a named home or a
//! scene file; the robot, the physics step, the step limit, the observations and the image
//! profile — and [`Catalog::config`] turns it into an [`EnvConfig`], [`Catalog::build`] into an
//! environment reset with the seed. Every name that is not one says which and what would be, in
//! a typed [`BuildError`].
//!
//! It knows nothing of command lines, Python or the browser: they parse their own arguments
//! into an [`EnvSpec`].
//!
//! ```no_run
//! use behavior_catalog::{Catalog, EnvSpec};
//!
//! let catalog = Catalog::load(None, |message| eprintln!("{message}"))?;
//! let spec = EnvSpec {
//!     robot: "fetch".into(),
//!     ..EnvSpec::new("bringing_in_wood")
//! };
//! let built = catalog.build(&spec, |_| {})?;
//! assert_eq!(built.env.steps(), 0);
//! # Ok::<(), behavior_catalog::BuildError>(())
//! ```

use behavior_assets::{
    Library, NAMED_HOMES, Scene, clutter, covering, first_covering, named_home, named_homes,
};
use behavior_bddl::activity::Activity;
use behavior_bddl::load::read_source;
use behavior_bddl::{Knowledge, Source};
use behavior_data::DataDir;
use behavior_env::{
    CameraConfig, Env, EnvConfig, EnvError, FixedCamera, Instances, Observations, Placement,
};
use behavior_render::{ImageProfile, Modality};
use behavior_robots::RobotKind;
use behavior_sampling::SavedInstance;
use behavior_sim::Substeps;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Why an environment could not be built. Each says which name or file was at fault.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// The official data could not be located or fetched.
    #[error("the official BEHAVIOR data: {0}")]
    Data(#[from] behavior_data::DataError),
    /// The taxonomy or domain, or a definition file, did not load.
    #[error("{0}")]
    Load(#[from] behavior_bddl::load::LoadError),
    /// The definition has errors (rendered with where they are).
    #[error("{0}")]
    Definition(#[from] behavior_bddl::SourceErrors),
    /// Not an official activity.
    #[error("`{0}` is not an official activity")]
    UnknownActivity(String),
    /// Neither a file nor an official activity.
    #[error("`{0}` is neither a file nor an official activity")]
    UnknownDefinition(String),
    /// A saved instance's problem is of no official activity.
    #[error("`{0}` is not an official activity's problem: give its definition file")]
    UnknownProblem(String),
    /// Not a robot.
    #[error("robot must be one of {known}, not `{given}`")]
    UnknownRobot {
        /// The name given.
        given: String,
        /// The robots there are.
        known: String,
    },
    /// Not a physics step.
    #[error("the physics step must be 1/300 or 1/120, not `{0}`")]
    UnknownPhysics(String),
    /// Neither a named home nor a scene file.
    #[error("scene must be one of the named homes ({known}) or a scene file, not `{given}`")]
    UnknownScene {
        /// The name given.
        given: String,
        /// The named homes.
        known: String,
    },
    /// A file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A scene file is not a scene.
    #[error("{path}: {source}")]
    SceneFile {
        /// The file.
        path: PathBuf,
        /// Why.
        source: behavior_assets::SceneError,
    },
    /// A saved instance does not read.
    #[error("{path}: {source}")]
    InstanceFile {
        /// The file.
        path: PathBuf,
        /// Why.
        source: behavior_sampling::LoadError,
    },
    /// No named home holds what the activity needs.
    #[error("no named home covers {0}")]
    NotCovered(String),
    /// A home could not be made.
    #[error("making the home: {0}")]
    Home(#[from] behavior_assets::AssetError),
    /// A home could not be cluttered.
    #[error("cluttering the home: {0}")]
    Clutter(#[from] behavior_assets::ClutterError),
    /// An observation that is none.
    #[error("{0}; or one of proprioception, task_obs, lidar (observations)")]
    UnknownObservation(behavior_render::UnknownModality),
    /// An image profile that is none.
    #[error("{0} (image profile)")]
    UnknownProfile(behavior_render::UnknownProfile),
    /// An image of no pixels.
    #[error("image sizes must be at least 1 pixel")]
    EmptyImage,
    /// The environment's first reset failed.
    #[error("starting {activity} (seed {seed}): {source}")]
    Reset {
        /// The activity.
        activity: String,
        /// The seed.
        seed: u64,
        /// Why.
        source: EnvError,
    },
}

/// What an environment observes, by name.
#[derive(Clone, Debug, PartialEq)]
pub struct ObservationSpec {
    /// `proprioception`, `task_obs`, `lidar`, and the robot camera's modalities (`rgb`,
    /// `depth`, `normal`, `seg`, `ins_seg`, `highlight`, `flow`, `scene_flow`).
    pub names: Vec<String>,
    /// The robot camera's images' side, pixels.
    pub image_size: u32,
    /// How the cameras draw colour: `realistic` or `fast`.
    pub image_profile: String,
    /// The side of a fixed overview camera's colour image named [`RENDER_CAMERA`], or `None`
    /// for no such camera.
    pub render_size: Option<u32>,
}

/// The name of the fixed overview camera [`ObservationSpec::render_size`] adds.
pub const RENDER_CAMERA: &str = "render";
/// Its vertical field of view, rad.
const RENDER_FOV: f32 = std::f32::consts::FRAC_PI_3;
/// Observations besides the images' modalities.
const STATE: [&str; 3] = ["proprioception", "task_obs", "lidar"];

/// What an environment is built from, by name (see the crate docs).
#[derive(Clone, Debug, PartialEq)]
pub struct EnvSpec {
    /// An official activity's name, a definition (problem) file, or a saved instance
    /// (`INSTANCE.json`, from `behavior sample --out`).
    pub activity: String,
    /// A named home or a scene file; `None` for the first named home that covers the activity.
    pub scene: Option<String>,
    /// A saved instance to start from instead of sampling one.
    pub instance: Option<PathBuf>,
    /// The first episode's seed.
    pub seed: u64,
    /// `behavior`, `fetch` or `r1`.
    pub robot: String,
    /// The physics step: `1/300` or `1/120`.
    pub physics: String,
    /// Whether the home has its everyday clutter.
    pub clutter: bool,
    /// The step limit; `None` for the default.
    pub max_steps: Option<u32>,
    /// What the agent observes; `None` for [`EnvConfig::new`]'s defaults.
    pub observations: Option<ObservationSpec>,
}

impl EnvSpec {
    /// The activity with every default: its first covering home, cluttered, the
    /// BehaviorRobot, 1/300 s, seed 0.
    pub fn new(activity: &str) -> EnvSpec {
        EnvSpec {
            activity: activity.to_string(),
            scene: None,
            instance: None,
            seed: 0,
            robot: RobotKind::default().name().to_string(),
            physics: "1/300".to_string(),
            clutter: true,
            max_steps: None,
            observations: None,
        }
    }

    /// The saved instance to start from: `instance`, or `activity` when it names a `.json`
    /// file.
    fn saved(&self) -> Result<Option<SavedInstance>, BuildError> {
        let positional = Path::new(&self.activity);
        match &self.instance {
            Some(path) => read_instance(path).map(Some),
            None if is_json(positional) => read_instance(positional).map(Some),
            None => Ok(None),
        }
    }
}

/// An environment reset to its first episode, the definition it runs (for recordings) and the
/// definition's warnings, rendered with where they are (empty without any).
pub struct Built {
    /// The environment.
    pub env: Env,
    /// The activity's definition.
    pub source: Source,
    /// Its warnings, rendered.
    pub warnings: String,
}

/// The official data and the knowledge loaded from it.
pub struct Catalog {
    data: DataDir,
    knowledge: Knowledge,
}

impl Catalog {
    /// Locates the data (`data_dir`, else `$BEHAVIOR_DATA_DIR`, else the cache, filled from PyPI
    /// on first use with one message to `say`) and loads the taxonomy and domain.
    pub fn load(data_dir: Option<&Path>, say: impl FnOnce(&str)) -> Result<Catalog, BuildError> {
        let data = DataDir::locate(data_dir, say)?;
        let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path())?;
        Ok(Catalog { data, knowledge })
    }

    /// The official data.
    pub fn data(&self) -> &DataDir {
        &self.data
    }

    /// The taxonomy and domain definitions are checked against.
    pub fn knowledge(&self) -> &Knowledge {
        &self.knowledge
    }

    /// The object library over the taxonomy.
    pub fn library(&self) -> Library<'_> {
        Library::new(&self.knowledge.taxonomy)
    }

    /// The configuration `spec` names, with the definition it runs and its rendered warnings.
    pub fn config(&self, spec: &EnvSpec) -> Result<(EnvConfig, Source, String), BuildError> {
        let saved = spec.saved()?;
        let name = match &saved {
            Some(s) if is_json(Path::new(&spec.activity)) => self.official_activity(&s.activity)?,
            _ => spec.activity.clone(),
        };
        let source = self.source(&name)?;
        let (activity, warnings) = self.knowledge.load(&source)?;
        let warnings = match warnings.0.is_empty() {
            true => String::new(),
            false => warnings.render(&source),
        };
        let library = self.library();
        // A saved instance holds its home; otherwise sample in the home asked for.
        let scenes = match (&saved, &spec.scene) {
            (Some(_), _) => Vec::new(),
            (None, Some(name)) => {
                vec![with_clutter(
                    load_scene(name, &library)?,
                    &library,
                    spec.clutter,
                )?]
            }
            (None, None) => {
                let home = first_covering(&activity, &library, &self.knowledge.taxonomy)?
                    .ok_or_else(|| BuildError::NotCovered(activity.name.clone()))?;
                vec![with_clutter(home, &library, spec.clutter)?]
            }
        };
        let mut config = EnvConfig::new(
            Arc::new(activity),
            Arc::new(self.knowledge.taxonomy.clone()),
            scenes,
        );
        config.robot = robot_kind(&spec.robot)?;
        config.physics = physics(&spec.physics)?;
        if let Some(saved) = saved {
            config.instances = Instances::Saved(vec![saved]);
        }
        if let Some(max) = spec.max_steps {
            config.max_steps = max;
        }
        if let Some(observations) = &spec.observations {
            observe(observations, &mut config.observations)?;
        }
        Ok((config, source, warnings))
    }

    /// The environment `spec` names (`configure` adjusts its configuration first), reset with
    /// its seed.
    pub fn build(
        &self,
        spec: &EnvSpec,
        configure: impl FnOnce(&mut EnvConfig),
    ) -> Result<Built, BuildError> {
        let (mut config, source, warnings) = self.config(spec)?;
        configure(&mut config);
        let mut env = Env::new(config);
        env.reset(spec.seed).map_err(|source| BuildError::Reset {
            activity: spec.activity.clone(),
            seed: spec.seed,
            source,
        })?;
        Ok(Built {
            env,
            source,
            warnings,
        })
    }

    /// A definition: the file at `definition` if there is one, else the official activity of
    /// that name.
    pub fn source(&self, definition: &str) -> Result<Source, BuildError> {
        let path = Path::new(definition);
        if path.exists() {
            return Ok(read_source(path)?);
        }
        self.official_source(definition)?
            .ok_or_else(|| BuildError::UnknownDefinition(definition.to_string()))
    }

    /// The text of the official activity of this name; `None` if there is none.
    pub fn official_source(&self, name: &str) -> Result<Option<Source>, BuildError> {
        if !self.data.activities()?.iter().any(|a| a == name) {
            return Ok(None);
        }
        Ok(Some(read_source(&self.data.problem_path(name)?)?))
    }

    /// The official activity of this name, loaded.
    pub fn activity(&self, name: &str) -> Result<Activity, BuildError> {
        let source = self
            .official_source(name)?
            .ok_or_else(|| BuildError::UnknownActivity(name.to_string()))?;
        Ok(self.knowledge.load(&source)?.0)
    }

    /// The named homes that hold what the official `activity` needs, in the order episodes use
    /// them (the first is where an environment without a scene samples).
    pub fn covering_homes(&self, activity: &str) -> Result<Vec<String>, BuildError> {
        let activity = self.activity(activity)?;
        let homes = named_homes(&self.library())?;
        let covering = covering(&homes, &activity, &self.knowledge.taxonomy);
        Ok(covering.into_iter().map(|h| h.name.clone()).collect())
    }

    /// The official activity a saved problem name is of, as the data spells it (problem names
    /// are lower case: `filling_a_christmas_stocking_0` is of `filling_a_Christmas_stocking`).
    pub fn official_activity(&self, problem: &str) -> Result<String, BuildError> {
        let name = official_name(problem);
        let activities = self.data.activities()?;
        activities
            .into_iter()
            .find(|a| a.eq_ignore_ascii_case(name))
            .ok_or_else(|| BuildError::UnknownProblem(problem.to_string()))
    }
}

/// A named home, or a scene file (`behavior scene generate --out`).
pub fn load_scene(name: &str, library: &Library) -> Result<Scene, BuildError> {
    if let Some(home) = named_home(name, library) {
        return Ok(home?);
    }
    let path = Path::new(name);
    if !path.is_file() {
        return Err(BuildError::UnknownScene {
            given: name.to_string(),
            known: names(NAMED_HOMES.iter().map(|(n, _)| *n)),
        });
    }
    Scene::from_json(&read(path)?).map_err(|source| BuildError::SceneFile {
        path: path.to_path_buf(),
        source,
    })
}

/// The activity a problem is of: `packing_lunches_0` → `packing_lunches`.
pub fn official_name(problem: &str) -> &str {
    match problem.rsplit_once('_') {
        Some((name, index)) if !index.is_empty() && index.bytes().all(|b| b.is_ascii_digit()) => {
            name
        }
        _ => problem,
    }
}

/// The robot of this name.
pub fn robot_kind(name: &str) -> Result<RobotKind, BuildError> {
    RobotKind::from_name(name).ok_or_else(|| BuildError::UnknownRobot {
        given: name.to_string(),
        known: names(RobotKind::ALL.iter().map(|k| k.name())),
    })
}

/// The physics step of this name: `1/300` or `1/120`.
pub fn physics(name: &str) -> Result<Substeps, BuildError> {
    match name {
        "1/300" => Ok(Substeps::Hz300),
        "1/120" => Ok(Substeps::Hz120),
        other => Err(BuildError::UnknownPhysics(other.to_string())),
    }
}

/// `scene` with its everyday clutter (made from its seed where it has none yet) or without.
pub fn with_clutter(scene: Scene, library: &Library, on: bool) -> Result<Scene, BuildError> {
    if !on {
        return Ok(scene.without_clutter());
    }
    if !scene.clutter.is_empty() {
        return Ok(scene);
    }
    Ok(clutter(&scene, library, scene.seed)?)
}

/// Sets what the episode observes.
fn observe(spec: &ObservationSpec, observations: &mut Observations) -> Result<(), BuildError> {
    let wanted = |name: &str| spec.names.iter().any(|o| o == name);
    let mut modalities = Vec::new();
    for name in &spec.names {
        if STATE.contains(&name.as_str()) {
            continue;
        }
        let modality: Modality = name.parse().map_err(BuildError::UnknownObservation)?;
        if !modalities.contains(&modality) {
            modalities.push(modality);
        }
    }
    if spec.image_size == 0 || spec.render_size == Some(0) {
        return Err(BuildError::EmptyImage);
    }
    let profile: ImageProfile = (spec.image_profile.parse()).map_err(BuildError::UnknownProfile)?;
    observations.proprioception = wanted("proprioception");
    observations.task_obs = wanted("task_obs");
    observations.lidar = wanted("lidar");
    observations.camera = (!modalities.is_empty()).then(|| CameraConfig {
        modalities,
        width: spec.image_size,
        height: spec.image_size,
        profile,
        ..CameraConfig::default()
    });
    if let Some(size) = spec.render_size {
        observations.fixed_cameras.push(FixedCamera {
            name: RENDER_CAMERA.to_string(),
            placement: Placement::Overview,
            config: CameraConfig {
                modalities: vec![Modality::Rgb],
                width: size,
                height: size,
                vertical_fov: RENDER_FOV,
                profile,
            },
        });
    }
    Ok(())
}

fn is_json(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "json")
}

fn read(path: &Path) -> Result<String, BuildError> {
    std::fs::read_to_string(path).map_err(|source| BuildError::Read {
        path: path.to_path_buf(),
        source,
    })
}

fn read_instance(path: &Path) -> Result<SavedInstance, BuildError> {
    SavedInstance::from_json(&read(path)?).map_err(|source| BuildError::InstanceFile {
        path: path.to_path_buf(),
        source,
    })
}

fn names<'a>(all: impl Iterator<Item = &'a str>) -> String {
    all.collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_official_name_drops_the_problem_index() {
        assert_eq!(official_name("packing_lunches_0"), "packing_lunches");
        assert_eq!(
            official_name("re-shelving_library_books_0"),
            "re-shelving_library_books"
        );
        assert_eq!(official_name("mine"), "mine");
        assert_eq!(official_name("mine_"), "mine_");
    }

    #[test]
    fn names_that_are_none_say_what_would_be() {
        let robot = robot_kind("r2d2").unwrap_err().to_string();
        assert!(
            robot.contains("behavior, fetch, r1") && robot.contains("r2d2"),
            "{robot}"
        );
        assert_eq!(physics("1/120").unwrap(), Substeps::Hz120);
        assert!(
            physics("1/60")
                .unwrap_err()
                .to_string()
                .contains("1/300 or 1/120")
        );
        let spec = ObservationSpec {
            names: vec!["rgb".into(), "sonar".into()],
            image_size: 64,
            image_profile: "fast".into(),
            render_size: None,
        };
        let mut observations = Observations::default();
        let unknown = observe(&spec, &mut observations).unwrap_err().to_string();
        assert!(
            unknown.contains("sonar") && unknown.contains("task_obs"),
            "{unknown}"
        );
        let fine = ObservationSpec {
            names: vec!["rgb".into(), "task_obs".into()],
            ..spec
        };
        observe(&fine, &mut observations).unwrap();
        assert!(observations.task_obs && !observations.proprioception);
        assert_eq!(observations.camera.map(|c| c.width), Some(64));
    }
}
