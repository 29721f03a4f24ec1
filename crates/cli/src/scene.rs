//! `behavior scene ...`: the named homes, generating homes from seeds, maps, and which homes can
//! host which activities.

use crate::episode::{Built, EpisodeArgs};
use crate::prelude::{Prelude, named_homes};
use anyhow::{Context, Result, bail};
use behavior_assets::covering;
use behavior_assets::{Family, Library, NAMED_HOMES, Scene, generate, generate_family};
use clap::Subcommand;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Subcommand)]
pub enum SceneCommand {
    /// The named homes with their rooms.
    List,
    /// Generate a home from a seed and save it as a scene file, with clutter unless told not to.
    Generate {
        #[arg(long)]
        seed: u64,
        /// The plan family: corridor, central_hall, open_plan, l_shaped, two_wings or studio
        /// (default: the one the seed gives, cycling through them).
        #[arg(long)]
        family: Option<Family>,
        #[arg(long, value_name = "FILE.json")]
        out: PathBuf,
        /// Furniture only: no books, dishes, food and the like lying about.
        #[arg(long)]
        no_clutter: bool,
    },
    /// Draw a top-down map of a named home or a scene file.
    Show {
        /// A named home (see `scene list`) or a scene file.
        scene: String,
        #[arg(long, value_name = "OUT.png")]
        png: PathBuf,
        /// Pixels per metre.
        #[arg(long, default_value_t = 60.0)]
        scale: f32,
    },
    /// Maps of several homes on one sheet: the named homes, or two homes of each plan family
    /// from free seeds.
    Sheet {
        #[arg(long, value_name = "OUT.png")]
        png: PathBuf,
        /// Two homes of each family from seeds FIRST, FIRST+1, … instead of the named homes.
        #[arg(long, value_name = "FIRST")]
        families_from: Option<u64>,
        /// Maps per row.
        #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=8))]
        columns: u32,
    },
    /// For each official activity, the named homes holding every room and piece of furniture its
    /// `inroom` literals require.
    Coverage {
        #[arg(long)]
        json: bool,
    },
    /// Write a sampled instance of an activity — its home, its objects and the robot — as a
    /// binary glTF 2.0 file, with the meshes and materials the cameras draw (Blender and three.js
    /// editors open it).
    Export(ExportArgs),
}

#[derive(clap::Args)]
pub struct ExportArgs {
    #[command(flatten)]
    episode: EpisodeArgs,
    /// The file to write.
    #[arg(long, value_name = "OUT.glb")]
    gltf: PathBuf,
    /// Leave the robot out.
    #[arg(long)]
    no_robot: bool,
}

pub fn run(command: SceneCommand, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    let library = prelude.library();
    match command {
        SceneCommand::List => {
            println!(
                "{:<10} {:>5} {:<22} {:>8}  rooms",
                "home", "seed", "family", "objects"
            );
            for (name, seed) in NAMED_HOMES {
                let scene = generate(name, seed, &library)?;
                let rooms: Vec<String> = scene.rooms.iter().map(|r| r.label()).collect();
                println!(
                    "{name:<10} {seed:>5} {:<22} {:>8}  {}",
                    family_name(&scene),
                    scene.objects.len(),
                    rooms.join(", ")
                );
            }
        }
        SceneCommand::Generate {
            seed,
            family,
            out,
            no_clutter,
        } => {
            let family = family.unwrap_or(Family::of_seed(seed));
            let scene = generate_family(&format!("seed_{seed}"), seed, family, &library)?;
            let scene = with_clutter(scene, &library, !no_clutter)?;
            std::fs::write(&out, scene.to_json())
                .with_context(|| format!("cannot write {}", out.display()))?;
            eprintln!(
                "{}: a {} home, {} rooms, {} objects, {} things of clutter",
                out.display(),
                family_name(&scene),
                scene.rooms.len(),
                scene.objects.len(),
                scene.clutter.len()
            );
        }
        SceneCommand::Show { scene, png, scale } => {
            let scene = load_scene(&scene, &library)?;
            if !(scale.is_finite() && (5.0..=400.0).contains(&scale)) {
                anyhow::bail!("--scale must be between 5 and 400 pixels per metre");
            }
            crate::map::render(&scene, scale)
                .save(&png)
                .with_context(|| format!("cannot write {}", png.display()))?;
            eprintln!("{}: map of {}", png.display(), scene.name);
        }
        SceneCommand::Sheet {
            png,
            families_from,
            columns,
        } => {
            let homes = match families_from {
                None => named_homes(&library)?,
                Some(first) => two_of_each_family(first, &library)?,
            };
            crate::map::sheet(&homes, columns, (640, 520))
                .save(&png)
                .with_context(|| format!("cannot write {}", png.display()))?;
            eprintln!("{}: maps of {} homes", png.display(), homes.len());
        }
        SceneCommand::Coverage { json } => coverage(&prelude, &library, json)?,
        SceneCommand::Export(args) => export(&prelude, args)?,
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes a sampled instance as glTF.
fn export(prelude: &Prelude, args: ExportArgs) -> Result<()> {
    if args.gltf.extension().and_then(|e| e.to_str()) != Some("glb") {
        bail!(
            "--gltf {}: the file must end in .glb (binary glTF)",
            args.gltf.display()
        );
    }
    let Built { env, .. } = args.episode.build(prelude, |_| {})?;
    let world = env.world().context("no episode")?;
    let hidden: Vec<_> = match (args.no_robot, env.robot()) {
        (true, Some(robot)) => robot.objects(),
        _ => Vec::new(),
    };
    let file = behavior_render::to_glb(world, &hidden, &behavior_robots::shared_models());
    std::fs::write(&args.gltf, &file)
        .with_context(|| format!("cannot write {}", args.gltf.display()))?;
    eprintln!(
        "{}: {} objects, {:.1} MB",
        args.gltf.display(),
        world
            .bodies()
            .objects()
            .filter(|(id, o)| o.is_present() && !hidden.contains(id))
            .count(),
        file.len() as f64 / 1e6
    );
    Ok(())
}

/// Two homes of each plan family, from seeds `first`, `first + 1`, … (each family its own seeds).
fn two_of_each_family(first: u64, library: &Library) -> Result<Vec<Scene>> {
    let mut homes = Vec::new();
    for family in Family::ALL {
        for k in 0..2 {
            let seed = first.checked_add(k).context("the seed is too large")?;
            homes.push(generate_family(
                &format!("seed {seed}"),
                seed,
                family,
                library,
            )?);
        }
    }
    Ok(homes)
}

/// A home's plan family as `scene list` shows it.
fn family_name(scene: &Scene) -> &'static str {
    scene.family.map_or("-", |f| f.name())
}

/// For each official activity, the named homes that cover it.
fn coverage(prelude: &Prelude, library: &Library, json: bool) -> Result<()> {
    #[derive(Serialize)]
    struct Row {
        activity: String,
        scenes: Vec<String>,
    }
    let homes = named_homes(library)?;
    let mut rows = Vec::new();
    for (name, activity) in prelude.official_activities()? {
        let scenes = covering(&homes, &activity, &prelude.knowledge().taxonomy)
            .iter()
            .map(|h| h.name.clone())
            .collect();
        rows.push(Row {
            activity: name,
            scenes,
        });
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
    } else {
        for r in &rows {
            println!(
                "{:<42} {:>2}  {}",
                r.activity,
                r.scenes.len(),
                r.scenes.join(" ")
            );
        }
    }
    Ok(())
}

/// The home as it is used: with clutter when `on` (a home without any gets the clutter its own
/// seed gives; a scene file's own clutter is kept), furniture only when not.
pub(crate) fn with_clutter(scene: Scene, library: &Library, on: bool) -> Result<Scene> {
    let name = scene.name.clone();
    behavior_catalog::with_clutter(scene, library, on).with_context(|| format!("cluttering {name}"))
}

/// A named home, or a scene file.
pub(crate) fn load_scene(name: &str, library: &Library) -> Result<Scene> {
    Ok(behavior_catalog::load_scene(name, library)?)
}
