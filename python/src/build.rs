//! An environment built from names, as `behavior run` builds one: the official data located
//! (fetched from PyPI on first use), the activity's definition loaded, the first of the named
//! homes that covers it, with its clutter; and the definitions the BDDL tools read.

use behavior_assets::{
    Library, NAMED_HOMES, clutter, covering, first_covering, named_home, named_homes,
};
use behavior_bddl::activity::Activity;
use behavior_bddl::load::read_source;
use behavior_bddl::{Knowledge, Source};
use behavior_data::DataDir;
use behavior_env::EnvConfig;
use behavior_robots::RobotKind;
use std::path::Path;
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
    #[error("`{0}` is not an official activity (behavior.activities() lists them)")]
    UnknownActivity(String),
    /// Neither a file nor an official activity.
    #[error("`{0}` is neither a file nor an official activity")]
    UnknownDefinition(String),
    /// A state given to evaluate a goal on is not one of the activity's.
    #[error("the state: {0}")]
    State(#[from] behavior_bddl::eval::StateError),
    /// Not a robot.
    #[error("robot must be one of {known}, not `{given}`")]
    UnknownRobot { given: String, known: String },
    /// Not a named home.
    #[error("scene must be one of the named homes ({known}), not `{given}`")]
    UnknownScene { given: String, known: String },
    /// No named home holds what the activity needs.
    #[error("no named home covers {0}")]
    NotCovered(String),
    /// A home could not be made.
    #[error("making the home: {0}")]
    Home(#[from] behavior_assets::AssetError),
    /// A home could not be cluttered.
    #[error("cluttering the home: {0}")]
    Clutter(#[from] behavior_assets::ClutterError),
}

/// What an environment is built from.
#[derive(Clone, Debug)]
pub struct EnvSpec {
    /// An official activity's name.
    pub activity: String,
    /// `behavior`, `fetch` or `r1`.
    pub robot: String,
    /// A named home; `None` for the first that covers the activity.
    pub scene: Option<String>,
    /// Whether the home has its everyday clutter.
    pub clutter: bool,
}

/// The official data and the knowledge loaded from it.
pub struct Catalog {
    data: DataDir,
    knowledge: Knowledge,
}

impl Catalog {
    /// Locates the data (see [`data_dir`]) and loads the taxonomy and domain.
    pub fn load() -> Result<Catalog, BuildError> {
        let data = data_dir()?;
        let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path())?;
        Ok(Catalog { data, knowledge })
    }

    /// The configuration of an environment of `spec`, with the defaults of [`EnvConfig::new`].
    pub fn config(&self, spec: &EnvSpec) -> Result<EnvConfig, BuildError> {
        let activity = self.activity(&spec.activity)?;
        let robot = RobotKind::from_name(&spec.robot).ok_or_else(|| BuildError::UnknownRobot {
            given: spec.robot.clone(),
            known: names(RobotKind::ALL.iter().map(|k| k.name())),
        })?;
        let library = Library::new(&self.knowledge.taxonomy);
        let home = match &spec.scene {
            Some(name) => {
                named_home(name, &library).ok_or_else(|| BuildError::UnknownScene {
                    given: name.clone(),
                    known: names(NAMED_HOMES.iter().map(|(n, _)| *n)),
                })??
            }
            None => first_covering(&activity, &library, &self.knowledge.taxonomy)?
                .ok_or_else(|| BuildError::NotCovered(spec.activity.clone()))?,
        };
        let home = if spec.clutter {
            clutter(&home, &library, home.seed)?
        } else {
            home.without_clutter()
        };
        let mut config = EnvConfig::new(
            Arc::new(activity),
            Arc::new(self.knowledge.taxonomy.clone()),
            vec![home],
        );
        config.robot = robot;
        Ok(config)
    }

    /// The named homes that hold what `activity` needs, in the order episodes use them (the
    /// first is where an environment without a `scene` samples).
    pub fn covering_homes(&self, activity: &str) -> Result<Vec<String>, BuildError> {
        let activity = self.activity(activity)?;
        let homes = named_homes(&Library::new(&self.knowledge.taxonomy))?;
        Ok(covering(&homes, &activity, &self.knowledge.taxonomy)
            .into_iter()
            .map(|h| h.name.clone())
            .collect())
    }

    /// The taxonomy and domain definitions are checked against.
    pub fn knowledge(&self) -> &Knowledge {
        &self.knowledge
    }

    /// The text of a definition: the file at `definition` if there is one, else the official
    /// activity of that name.
    pub fn source(&self, definition: &str) -> Result<Source, BuildError> {
        let path = Path::new(definition);
        if path.exists() {
            return Ok(read_source(path)?);
        }
        self.official_source(definition)?
            .ok_or_else(|| BuildError::UnknownDefinition(definition.to_string()))
    }

    /// The official activity of this name, loaded.
    fn activity(&self, name: &str) -> Result<Activity, BuildError> {
        let source = self
            .official_source(name)?
            .ok_or_else(|| BuildError::UnknownActivity(name.to_string()))?;
        let (activity, _warnings) = self.knowledge.load(&source)?;
        Ok(activity)
    }

    /// The text of the official activity of this name; `None` if there is none.
    fn official_source(&self, name: &str) -> Result<Option<Source>, BuildError> {
        if !self.data.activities()?.iter().any(|a| a == name) {
            return Ok(None);
        }
        Ok(Some(read_source(&self.data.problem_path(name)?)?))
    }
}

/// The official data: `$BEHAVIOR_DATA_DIR`, else the cache, filled from PyPI on first use
/// (saying so on stderr).
fn data_dir() -> Result<DataDir, BuildError> {
    Ok(DataDir::locate(None, |message| eprintln!("{message}"))?)
}

/// Every official activity's name, in the manifest's order.
pub fn activities() -> Result<Vec<String>, BuildError> {
    Ok(data_dir()?.activities()?)
}

fn names<'a>(all: impl Iterator<Item = &'a str>) -> String {
    all.collect::<Vec<_>>().join(", ")
}
