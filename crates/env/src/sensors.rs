//! The sensors an [`crate::EnvConfig`] asks for: the robot's camera (the BehaviorRobot's eye,
//! Fetch's head camera) and fixed cameras in the home (an overview for people, or at a pose),
//! drawn by `behavior-render`, and a lidar.
//!
//! The camera highlights the activity's objects (its `highlight` mask) and labels pixels from one
//! category table for every activity: the taxonomy's synsets plus the homes' structural ones
//! ([`categories`]), so the same category has the same id in every home.

use crate::observation::{Reading, Sensor, SensorInput};
use behavior_bddl::Taxonomy;
use behavior_core::{AGENT_SYNSET, DOOR_SYNSET, FLOOR_SYNSET, WALL_SYNSET, WINDOW_SYNSET};
use behavior_render::{
    Camera, CategoryTable, ImageProfile, Lidar, Modality, Pattern, Pixels, RenderError, Renderer,
    Scene, View,
};
use behavior_robots::Scan;
use behavior_sim::QueryFilter;
use rapier3d::math::Pose;

/// Categories of the homes' structure, beside the taxonomy's.
const STRUCTURE: [&str; 6] = [
    WALL_SYNSET,
    FLOOR_SYNSET,
    "ceiling.n.01",
    DOOR_SYNSET,
    WINDOW_SYNSET,
    AGENT_SYNSET,
];

/// The semantic segmentation's category table for a taxonomy: the same for every activity and
/// home of one BDDL version.
pub fn categories(taxonomy: &Taxonomy) -> CategoryTable {
    let names = taxonomy.ids().map(|id| taxonomy.name(id).to_string());
    CategoryTable::new(names.chain(STRUCTURE.map(String::from)))
}

/// What the robot's camera delivers.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraConfig {
    /// The images, each under its modality's name in [`crate::Obs::sensors`].
    pub modalities: Vec<Modality>,
    /// Pixels.
    pub width: u32,
    /// Pixels.
    pub height: u32,
    /// rad.
    pub vertical_fov: f32,
    /// How the colour image is drawn: realistic (the default) or fast. Depth, segmentation
    /// and flow are the same in both.
    pub profile: ImageProfile,
}

impl Default for CameraConfig {
    /// The original's onboard-sensing camera: 128², 120° vertically, RGB, depth and semantic
    /// segmentation, colour in the realistic profile.
    fn default() -> Self {
        CameraConfig {
            modalities: vec![Modality::Rgb, Modality::Depth, Modality::Seg],
            width: behavior_render::EYE_SIZE,
            height: behavior_render::EYE_SIZE,
            vertical_fov: behavior_render::EYE_FOV,
            profile: ImageProfile::default(),
        }
    }
}

/// Where an extra camera stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Placement {
    /// Above the home, looking down on all of it with the config's field of view
    /// ([`Camera::overview`]): for people watching an episode. Placed anew at each reset, as
    /// homes differ.
    Overview,
    /// Fixed in the world at this pose (camera frame: x forward, y left, z up).
    At(Pose),
}

/// A camera beside the robot's, fixed in the home.
#[derive(Clone, Debug, PartialEq)]
pub struct FixedCamera {
    /// Its readings are under `NAME/MODALITY` (`overview/rgb`).
    pub name: String,
    /// Where it stands.
    pub placement: Placement,
    /// What it delivers.
    pub config: CameraConfig,
}

/// One camera: where it is, what it delivers, what it saw last.
struct Rig {
    /// Prepended to its readings' keys (empty for the robot's camera).
    prefix: String,
    /// Where it stands: on the robot when `None`.
    placement: Option<Placement>,
    config: CameraConfig,
    view: View,
    /// Whether an overview was placed in this episode's home.
    placed: bool,
}

impl Rig {
    fn new(
        prefix: String,
        placement: Option<Placement>,
        config: CameraConfig,
    ) -> Result<Rig, RenderError> {
        let camera = Camera {
            pose: match placement {
                Some(Placement::At(pose)) => pose,
                None | Some(Placement::Overview) => Pose::IDENTITY,
            },
            width: config.width,
            height: config.height,
            vertical_fov: config.vertical_fov,
        };
        camera.check()?;
        Ok(Rig {
            prefix,
            placement,
            view: View::with_profile(camera, config.profile),
            config,
            placed: false,
        })
    }

    /// Moves the camera to where it stands now (the robot moves; an overview is placed once per
    /// home).
    fn place(&mut self, input: &SensorInput) -> Result<(), RenderError> {
        let camera = &mut self.view.camera;
        match self.placement {
            None => camera.pose = input.robot.camera_pose(input.world),
            Some(Placement::Overview) if !self.placed => {
                let (w, h, fov) = (camera.width, camera.height, camera.vertical_fov);
                *camera = Camera::overview(input.world, w, h, fov)?;
            }
            Some(Placement::Overview | Placement::At(_)) => {}
        }
        self.placed = true;
        Ok(())
    }
}

/// The cameras of an [`crate::EnvConfig`] as one [`Sensor`]: the robot's and the fixed ones,
/// drawn by one renderer.
pub struct CameraSensor {
    renderer: Renderer,
    rigs: Vec<Rig>,
    categories: CategoryTable,
}

impl CameraSensor {
    /// The robot's camera (`robot`, its readings under the modalities' names) and `fixed`
    /// cameras, rendering their ids from `categories`.
    pub fn new(
        robot: Option<CameraConfig>,
        fixed: &[FixedCamera],
        categories: CategoryTable,
    ) -> Result<CameraSensor, RenderError> {
        let mut rigs = Vec::new();
        if let Some(config) = robot {
            rigs.push(Rig::new(String::new(), None, config)?);
        }
        for camera in fixed {
            let prefix = format!("{}/", camera.name);
            rigs.push(Rig::new(
                prefix,
                Some(camera.placement),
                camera.config.clone(),
            )?);
        }
        let mut renderer = Renderer::new()?;
        // Robots in their makers' meshes where this process has them (fetched at first use).
        renderer.set_models(behavior_robots::shared_models());
        Ok(CameraSensor {
            renderer,
            rigs,
            categories,
        })
    }
}

impl Sensor for CameraSensor {
    fn name(&self) -> &str {
        "camera"
    }

    fn reset(&mut self) {
        for rig in &mut self.rigs {
            rig.view.forget();
            rig.placed = false;
        }
    }

    fn observe(
        &mut self,
        input: &SensorInput,
        out: &mut Vec<(String, Reading)>,
    ) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        let highlight: Vec<_> = input.bindings.iter().flatten().copied().collect();
        let scene = Scene {
            world: input.world,
            categories: &self.categories,
            highlight: &highlight,
            hidden: &[],
        };
        for rig in &mut self.rigs {
            rig.place(input)?;
            let frame = self
                .renderer
                .render(&scene, &mut rig.view, &rig.config.modalities)?;
            out.extend(frame.images.into_iter().map(|image| {
                let reading = Reading {
                    shape: image.shape,
                    data: image.pixels,
                };
                (format!("{}{}", rig.prefix, image.modality.name()), reading)
            }));
        }
        Ok(())
    }
}

/// A lidar on the robot: Fetch's base laser (220 beams over 220°, 0.05–25 m), or for the
/// BehaviorRobot, which has none in the original, a 16 × 360 multi-beam scan (30° vertically,
/// 0.05–25 m) from its eye. Its reading `lidar` is the range image (`[rows, columns]`, m, 0 for no
/// return); it does not see the robot itself.
pub struct LidarSensor;

impl LidarSensor {
    fn lidar(input: &SensorInput) -> Lidar {
        let mount = input.robot.lidar(input.world);
        let pattern = match mount.scan {
            Scan::Fan { beams, fov } => Pattern::Planar { beams, fov },
            Scan::AllRound {
                rows,
                columns,
                vertical_fov,
            } => Pattern::MultiBeam {
                rows,
                columns,
                vertical_fov,
            },
        };
        Lidar {
            pose: mount.pose,
            pattern,
            min_range: mount.min_range,
            max_range: mount.max_range,
        }
    }
}

impl Sensor for LidarSensor {
    fn name(&self) -> &str {
        "lidar"
    }

    fn observe(
        &mut self,
        input: &SensorInput,
        out: &mut Vec<(String, Reading)>,
    ) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        let filter = QueryFilter::excluding(&input.robot.objects());
        let scan = Self::lidar(input).scan(input.world, &filter)?;
        let reading = Reading {
            shape: vec![scan.rows, scan.columns],
            data: Pixels::F32(scan.ranges),
        };
        out.push(("lidar".to_string(), reading));
        Ok(())
    }
}
