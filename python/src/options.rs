//! What a Python environment is built with: one plain struct, read from the dict the Python
//! classes pass (they own the defaults and the documentation), turned into an [`EnvConfig`].

use crate::build::{Catalog, EnvSpec};
use behavior_env::{CameraConfig, EnvConfig, FixedCamera, Placement};
use behavior_planning::Mode;
use behavior_render::{ImageProfile, Modality};
use pyo3::FromPyObject;

/// Names of the observations besides the images' modalities.
const STATE: [&str; 3] = ["proprioception", "task_obs", "lidar"];
/// The key prefix of the camera that `render()` reads; its readings are no observation.
pub const RENDER_CAMERA: &str = "render";
/// Its vertical field of view, rad (as `behavior run --video`'s overview).
const RENDER_FOV: f32 = std::f32::consts::FRAC_PI_3;

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
            activity: activity.to_string(),
            robot: self.robot.clone(),
            scene: self.scene.clone(),
            clutter: self.clutter,
        };
        let catalog = Catalog::load().map_err(|e| e.to_string())?;
        let mut config = catalog.config(&spec).map_err(|e| e.to_string())?;
        if let Some(max) = self.max_steps {
            config.max_steps = max;
        }
        // Primitives drive the robot through the space their mode needs (Fetch's arm joint by
        // joint when physical); continuous actions are the robot's full space.
        if self.primitives.is_some() {
            let mode = Mode::from_name(&self.primitive_mode)
                .ok_or_else(|| format!("unknown primitive_mode `{}`", self.primitive_mode))?;
            config.action_space = mode.action_space(config.robot);
        }
        self.observe(&mut config)?;
        Ok(config)
    }

    /// Sets what the episode observes.
    fn observe(&self, config: &mut EnvConfig) -> Result<(), String> {
        let wanted = |name: &str| self.observations.iter().any(|o| o == name);
        let mut modalities = Vec::new();
        for name in &self.observations {
            if STATE.contains(&name.as_str()) {
                continue;
            }
            let modality: Modality = name.parse().map_err(|e| {
                format!("{e}; or one of proprioception, task_obs, lidar (observations)")
            })?;
            if !modalities.contains(&modality) {
                modalities.push(modality);
            }
        }
        if self.image_size == 0 || self.render_size == Some(0) {
            return Err("image_size and render_size must be at least 1 pixel".into());
        }
        let profile: ImageProfile = self
            .image_profile
            .parse()
            .map_err(|e| format!("{e} (image_profile)"))?;
        let observations = &mut config.observations;
        observations.proprioception = wanted("proprioception");
        observations.task_obs = wanted("task_obs");
        observations.lidar = wanted("lidar");
        observations.camera = (!modalities.is_empty()).then(|| CameraConfig {
            modalities,
            width: self.image_size,
            height: self.image_size,
            profile,
            ..CameraConfig::default()
        });
        if let Some(size) = self.render_size {
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
}
