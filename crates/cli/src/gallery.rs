//! `behavior gallery`: a contact sheet of every archetype of the catalog, each in two variants
//! (the shape's two variants where it has them, a small and a large size, two seeds), drawn on
//! a floor under the realistic profile and labelled with its synset: what the agent's camera
//! shows of each kind of object, on one page. With `--robots`, the robots instead, each from
//! the front left and from behind, in their makers' meshes where this machine has them.

use crate::map::text;
use crate::prelude::Prelude;
use anyhow::{Context, Result, bail};
use behavior_assets::{Archetype, CATALOG};
use behavior_core::FLOOR_SYNSET;
use behavior_env::categories;
use behavior_render::{
    Camera, CategoryTable, ImageProfile, Modality, Pixels, Renderer, Scene, View,
};
use behavior_robots::{ActionSpace, Robot, RobotKind};
use behavior_sim::{Material, ObjectSpec, Part, Primitive, World};
use image::{Rgb, RgbImage};
use rapier3d::math::Vector;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Tiles a row of the sheet: six archetypes, two variants each.
const COLUMNS: u32 = 12;
/// The caption strip under each tile, pixels.
const CAPTION: u32 = 14;
/// The camera's vertical field of view, rad (40°).
const FOV: f32 = 0.7;

#[derive(clap::Args)]
pub struct GalleryArgs {
    /// The contact sheet (PNG).
    #[arg(long, value_name = "SHEET.png")]
    out: PathBuf,
    /// Each picture's width and height, pixels.
    #[arg(long, default_value_t = 160, value_parser = clap::value_parser!(u32).range(32..=1024))]
    tile: u32,
    /// How the pictures are drawn.
    #[arg(long, default_value = "realistic")]
    profile: ImageProfile,
    /// Only archetypes whose synset contains this text (repeat the flag for several).
    #[arg(long, value_name = "TEXT")]
    only: Vec<String>,
    /// Draw the robots instead of the archetypes: each embodiment from the front left and
    /// from behind.
    #[arg(long, conflicts_with = "only")]
    robots: bool,
}

/// One picture of the sheet.
enum Subject {
    Archetype(Sitter),
    /// A robot, seen from the front left (side 0) or from behind on its right (side 1).
    Robot {
        kind: RobotKind,
        side: u32,
    },
}

impl Subject {
    fn world(&self, prelude: &Prelude, tile: u32) -> Result<(World, Camera)> {
        match self {
            Subject::Archetype(sitter) => sitter.world(prelude, tile),
            &Subject::Robot { kind, side } => robot_world(kind, side, tile),
        }
    }

    /// The caption: the synset or the robot's name.
    fn label(&self, tile: u32) -> String {
        match self {
            Subject::Archetype(sitter) => label(sitter.archetype.synset, tile),
            Subject::Robot { kind, .. } => label(kind.name(), tile),
        }
    }
}

/// A floor `half` metres from the origin each way, in a light wood.
fn floor(half: f32) -> ObjectSpec {
    ObjectSpec::new(
        "floor",
        FLOOR_SYNSET,
        vec![Part::new(Primitive::Box {
            half_extents: Vector::new(half, half, 0.05),
        })],
    )
    .looks([170, 140, 110], Material::Wood)
    .at(Vector::new(0.0, 0.0, -0.05))
    .fixed()
}

/// A robot standing on a floor facing +x, and a camera that frames it from one side.
fn robot_world(kind: RobotKind, side: u32, tile: u32) -> Result<(World, Camera)> {
    let mut world = World::default();
    world.add(floor(3.0))?;
    let pose = Robot::standing_pose(kind, Vector::ZERO, 0.0);
    Robot::add(kind, ActionSpace::Full, &mut world, pose)
        .with_context(|| format!("adding the {} robot", kind.name()))?;
    // Both robots are about 1.1-1.5 m tall and 0.6 m wide.
    let centre = Vector::new(0.1, 0.0, 0.7);
    let direction = match side {
        0 => Vector::new(1.0, 0.7, 0.45),
        _ => Vector::new(-1.0, -0.5, 0.6),
    };
    let distance = 1.0 / (0.5 * FOV).tan();
    let from = centre + direction.normalize() * distance;
    Ok((world, Camera::looking_at(from, centre, tile, tile, FOV)))
}

/// One picture of the sheet: an archetype in one of its two variants.
struct Sitter {
    archetype: &'static Archetype,
    /// 0: the first variant, small; 1: the second, large.
    variant: u32,
}

impl Sitter {
    /// Its size: 30 % or 80 % of the way from the archetype's smallest to its largest.
    fn size(&self) -> Vector {
        let t = if self.variant == 0 { 0.3 } else { 0.8 };
        let (lo, hi) = (self.archetype.min, self.archetype.max);
        Vector::from_array(std::array::from_fn(|k| lo[k] + t * (hi[k] - lo[k])))
    }

    /// A world of this object standing on a floor, and a camera that frames it from the front
    /// left and above.
    fn world(&self, prelude: &Prelude, tile: u32) -> Result<(World, Camera)> {
        let size = self.size();
        let mut world = World::default();
        world.add(floor(size.x.max(size.y) + 1.0))?;
        let synset = self.archetype.synset;
        let name = format!("{synset}_{}", self.variant + 1);
        let spec = prelude
            .library()
            .instance_of(self.archetype, synset, &name, size, self.variant)
            .fixed();
        world
            .add(spec)
            .with_context(|| format!("building {synset}"))?;
        let centre = Vector::new(0.0, 0.0, 0.5 * size.z);
        let radius = 0.5 * size.length();
        let distance = 1.25 * radius / (0.5 * FOV).tan();
        let from = centre + Vector::new(-0.55, -0.8, 0.45).normalize() * distance;
        Ok((world, Camera::looking_at(from, centre, tile, tile, FOV)))
    }
}

pub fn gallery(args: GalleryArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let is_png = args
        .out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        bail!(
            "--out writes a PNG: name it SHEET.png, not {}",
            args.out.display()
        );
    }
    let prelude = Prelude::load(data_dir)?;
    let table = categories(&prelude.knowledge().taxonomy);
    let sitters: Vec<Subject> = if args.robots {
        RobotKind::ALL
            .into_iter()
            .flat_map(|kind| (0..2).map(move |side| Subject::Robot { kind, side }))
            .collect()
    } else {
        CATALOG
            .iter()
            .filter(|a| {
                args.only.is_empty() || args.only.iter().any(|o| a.synset.contains(o.as_str()))
            })
            .flat_map(|archetype| {
                (0..2).map(move |variant| Subject::Archetype(Sitter { archetype, variant }))
            })
            .collect()
    };
    if sitters.is_empty() {
        bail!(
            "no archetype's synset contains `{}`",
            args.only.join("` or `")
        );
    }
    let mut renderer = Renderer::new()?;
    renderer.set_models(behavior_robots::shared_models());
    let tile = args.tile;
    let rows = (sitters.len() as u32).div_ceil(COLUMNS);
    let columns = COLUMNS.min(sitters.len() as u32);
    let mut sheet = RgbImage::from_pixel(columns * tile, rows * (tile + CAPTION), Rgb([255; 3]));
    for (k, sitter) in sitters.iter().enumerate() {
        let picture = draw(
            sitter,
            &prelude,
            &mut renderer,
            &table,
            (tile, args.profile),
        )?;
        let (x, y) = (
            k as u32 % COLUMNS * tile,
            k as u32 / COLUMNS * (tile + CAPTION),
        );
        image::imageops::replace(&mut sheet, &picture, i64::from(x), i64::from(y));
        let label = sitter.label(tile);
        text(
            &mut sheet,
            &label,
            x as f32 + tile as f32 / 2.0,
            (y + tile + CAPTION / 2) as f32,
            1,
            Rgb([20, 20, 20]),
        );
    }
    let partial = args.out.with_extension("png.part");
    sheet
        .save_with_format(&partial, image::ImageFormat::Png)
        .with_context(|| format!("cannot write {}", partial.display()))?;
    std::fs::rename(&partial, &args.out)
        .with_context(|| format!("cannot write {}", args.out.display()))?;
    println!(
        "{} pictures of {} {} ({} profile) in {}",
        sitters.len(),
        sitters.len() / 2,
        if args.robots { "robots" } else { "archetypes" },
        args.profile,
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// One sitter's picture.
fn draw(
    sitter: &Subject,
    prelude: &Prelude,
    renderer: &mut Renderer,
    table: &CategoryTable,
    (tile, profile): (u32, ImageProfile),
) -> Result<RgbImage> {
    let (world, camera) = sitter.world(prelude, tile)?;
    let scene = Scene {
        world: &world,
        categories: table,
        highlight: &[],
        hidden: &[],
    };
    let frame = renderer.render(
        &scene,
        &mut View::with_profile(camera, profile),
        &[Modality::Rgb],
    )?;
    let image = frame.get(Modality::Rgb).context("no colour image")?;
    let Pixels::U8(rgb) = &image.pixels else {
        bail!("the colour image is not bytes");
    };
    RgbImage::from_raw(tile, tile, rgb.clone()).context("a colour image of the wrong size")
}

/// A synset's name without its `.n.NN` ending, cut to what fits under a tile of `tile` pixels
/// (8 a character), a `~` marking the cut.
fn label(synset: &str, tile: u32) -> String {
    let name = synset
        .trim_end_matches(char::is_numeric)
        .trim_end_matches(".n.");
    let fits = (tile / 8).saturating_sub(1).max(2) as usize;
    if name.chars().count() <= fits {
        return name.to_string();
    }
    let cut: String = name.chars().take(fits - 1).collect();
    format!("{cut}~")
}

#[cfg(test)]
mod tests {
    use super::label;

    #[test]
    fn labels_drop_the_sense_and_fit_their_tile() {
        assert_eq!(label("apple.n.01", 128), "apple");
        assert_eq!(label("electric_refrigerator.n.01", 128), "electric_refri~");
        assert_eq!(label("electric_refrigerator.n.01", 128).len(), 15);
    }
}
