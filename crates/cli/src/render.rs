//! `behavior render`: what a camera sees in an activity's first state (or after some random
//! steps), every modality asked for as a PNG for people and a `.npy` array for programs, with a
//! legend of the ids.

use crate::episode::{Built, EpisodeArgs};
use crate::prelude::Prelude;
use anyhow::{Context, Result, bail};
use behavior_env::{Agent, Env, categories};
use behavior_render::{
    Camera, CategoryTable, Frame, ImageProfile, Modality, Pixels, Renderer, Scene, View, save_npy,
    save_png,
};
use behavior_sim::World;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The overview camera's vertical field of view, rad (60°).
pub const OVERVIEW_FOV: f32 = std::f32::consts::FRAC_PI_3;

#[derive(clap::Args)]
pub struct RenderArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    /// eye (the robot's camera: the BehaviorRobot's eye, Fetch's head camera) or overview (above
    /// the home, looking down on all of it).
    #[arg(long, default_value = "eye")]
    camera: String,
    /// Image width and height, pixels.
    #[arg(long, default_value_t = 128)]
    size: u32,
    /// Comma-separated: rgb, depth, normal, seg, ins_seg, highlight, flow, scene_flow.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "rgb,depth,normal,seg,ins_seg,highlight,flow,scene_flow"
    )]
    modalities: Vec<String>,
    /// How colour is drawn: realistic (materials, the home's sun with shadows, room lamps) or
    /// fast (flat colours); the other modalities are the same in both.
    #[arg(long, default_value = "realistic")]
    profile: ImageProfile,
    /// Random action steps before the picture (the flow modalities show the last one's motion).
    #[arg(long, default_value_t = 0)]
    steps: u32,
    /// The folder the files go to (made if missing).
    #[arg(long)]
    out: PathBuf,
    #[arg(long)]
    json: bool,
}

/// An object's line in the legend.
#[derive(Serialize)]
struct Named {
    name: String,
    category: String,
}

/// What ids in `ins_seg` and `seg` stand for.
#[derive(Serialize)]
struct Legend {
    /// `ins_seg` value (object id + 1) → the object.
    instances: BTreeMap<u32, Named>,
    /// `seg` value → category, for the categories in the picture.
    categories: BTreeMap<u16, String>,
}

#[derive(Serialize)]
struct Report {
    adapter: String,
    files: Vec<String>,
    legend: Legend,
}

fn camera(args: &RenderArgs, env: &Env) -> Result<Camera> {
    let (world, robot) = (
        env.world().context("no episode")?,
        env.robot().context("no robot")?,
    );
    match args.camera.as_str() {
        "eye" => Ok(Camera {
            pose: robot.camera_pose(world),
            width: args.size,
            height: args.size,
            vertical_fov: behavior_render::EYE_FOV,
        }),
        "overview" => Ok(Camera::overview(world, args.size, args.size, OVERVIEW_FOV)?),
        other => bail!("--camera must be eye or overview, not `{other}`"),
    }
}

/// Draws `env`'s world from `view`, the activity's objects highlighted.
pub fn draw(
    env: &Env,
    view: &mut View,
    renderer: &mut Renderer,
    table: &CategoryTable,
    modalities: &[Modality],
) -> Result<Frame> {
    let world = env.world().context("no episode")?;
    let highlight: Vec<_> = env
        .bindings()
        .unwrap_or_default()
        .iter()
        .flatten()
        .copied()
        .collect();
    let scene = Scene {
        world,
        categories: table,
        highlight: &highlight,
        hidden: &[],
    };
    Ok(renderer.render(&scene, view, modalities)?)
}

pub fn render(args: RenderArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let modalities = args
        .modalities
        .iter()
        .map(|m| m.trim().parse::<Modality>())
        .collect::<Result<Vec<_>, _>>()?;
    let prelude = Prelude::load(data_dir)?;
    let Built { mut env, .. } = args.episode.build(&prelude, |_| {})?;
    let mut renderer = Renderer::new()?;
    renderer.set_models(behavior_robots::shared_models());
    let table = categories(&prelude.knowledge().taxonomy);
    let mut view = View::with_profile(camera(&args, &env)?, args.profile);
    let mut agent = Agent::named("random", args.episode.seed).context("the random agent")?;
    let mut action = Vec::new();
    for k in 0..args.steps {
        if k + 1 == args.steps {
            // The frame before the last step, so that the flow shows that step's motion.
            view.camera = camera(&args, &env)?;
            draw(&env, &mut view, &mut renderer, &table, &modalities)?;
        }
        agent.act(&env, &mut action);
        env.step(&action)?;
    }
    view.camera = camera(&args, &env)?;
    let frame = draw(&env, &mut view, &mut renderer, &table, &modalities)?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot make {}", args.out.display()))?;
    let mut files = Vec::new();
    for image in &frame.images {
        let name = image.modality.name();
        let (png, npy) = (
            args.out.join(format!("{name}.png")),
            args.out.join(format!("{name}.npy")),
        );
        save_png(image, &png)?;
        save_npy(image, &npy)?;
        files.extend([png, npy].map(|p| p.display().to_string()));
    }
    let legend = legend(env.world().context("no episode")?, &frame, &table);
    let path = args.out.join("legend.json");
    std::fs::write(&path, serde_json::to_string_pretty(&legend)?)
        .with_context(|| format!("cannot write {}", path.display()))?;
    files.push(path.display().to_string());
    let report = Report {
        adapter: renderer.adapter(),
        files,
        legend,
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        println!(
            "{} images of {}×{} from the {} camera ({}) in {}",
            frame.images.len(),
            frame.width,
            frame.height,
            args.camera,
            report.adapter,
            args.out.display()
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Every object of the world by its `ins_seg` value, and the categories the picture shows.
fn legend(world: &World, frame: &Frame, table: &CategoryTable) -> Legend {
    let instances = world
        .bodies()
        .objects()
        .map(|(id, o)| {
            let named = Named {
                name: o.name.clone(),
                category: o.category.clone(),
            };
            (id.0 + 1, named)
        })
        .collect();
    let mut categories = BTreeMap::new();
    if let Some(Pixels::U16(seg)) = frame.get(Modality::Seg).map(|i| &i.pixels) {
        for &id in seg.iter().filter(|&&id| id > 0) {
            if let Some(name) = table.name(id) {
                categories.entry(id).or_insert_with(|| name.to_string());
            }
        }
    }
    Legend {
        instances,
        categories,
    }
}
