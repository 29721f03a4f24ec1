//! What a Python environment is built with: one plain struct, read from the dict the Python
//! classes pass (they own the defaults and the documentation), turned into an [`EnvConfig`].

use crate::build::catalog;
use behavior_catalog::{EnvSpec, ObservationSpec};
use behavior_env::EnvConfig;
use behavior_planning::Mode;
use pyo3::FromPyObject;

/// The environment's options (every key of the dict must be there).
#[derive(Clone, Debug, FromPyObject)]
#[pyo3(from_item_all)]
pub struct EnvOptions {
    /// `behavior`, `fetch` or `r1`.
    pub robot: String,
    /// A named home, or `None` for the first that covers the activity.
    pub scene: Option<String>,
    /// The first episode's seed.
    pub seed: u64,
    /// The step limit, or `None` for the default.
    pub max_steps: Option<u32>,
    /// Whether the home has its everyday clutter.
    pub clutter: bool,
    /// What the agent observes: `proprioception`, `task_obs`, `lidar`, and the robot camera's
    /// modalities (`rgb`, `depth`, `normal`, `seg`, `ins_seg`, `highlight`, `flow`,
    /// `scene_flow`).
    pub observations: Vec<String>,
    /// The robot camera's images' side, pixels.
    pub image_size: u32,
    /// How the cameras draw colour: `realistic` or `fast`.
    pub image_profile: String,
    /// The side of the overview camera's colour image that `render()` returns, or `None` for
    /// no such camera.
    pub render_size: Option<u32>,
    /// `None` for continuous actions, else the primitive set (`paper`, `two_hands`, `all`).
    pub primitives: Option<String>,
    /// `symbolic` or `physical`.
    pub primitive_mode: String,
}

impl EnvOptions {
    /// The configuration of `activity` with these options, from the official data.
    pub fn config(&self, activity: &str) -> Result<EnvConfig, String> {
        let spec = EnvSpec {
            scene: self.scene.clone(),
            seed: self.seed,
            robot: self.robot.clone(),
            clutter: self.clutter,
            max_steps: self.max_steps,
            observations: Some(ObservationSpec {
                names: self.observations.clone(),
                image_size: self.image_size,
                image_profile: self.image_profile.clone(),
                render_size: self.render_size,
            }),
            ..EnvSpec::new(activity)
        };
        let catalog = catalog().map_err(|e| e.to_string())?;
        let (mut config, _, _) = catalog.config(&spec).map_err(|e| e.to_string())?;
        // Primitives drive the robot through the space their mode needs (Fetch's arm joint by
        // joint when physical); continuous actions are the robot's full space.
        if self.primitives.is_some() {
            let mode = Mode::from_name(&self.primitive_mode)
                .ok_or_else(|| format!("unknown primitive_mode `{}`", self.primitive_mode))?;
            config.action_space = mode.action_space(config.robot);
        }
        Ok(config)
    }
}
