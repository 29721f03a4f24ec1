//! `behavior run --video` and `behavior solve --video`: an episode for people to watch, the
//! robot's eye and an overview of the home side by side, captioned with the step and Q, over Q's
//! curve so far, as an animated GIF (through `gif`).
//!
//! A frame is drawn every [`FRAME_EVERY`] action steps (10 frames a second of simulated time),
//! by a renderer of its own, so the agent's observations are untouched. Frames go to the file as
//! they are drawn, under a temporary name that becomes the file's only once the video is whole:
//! a run that fails leaves whatever was at that path before.

use crate::map::text;
use crate::render::{OVERVIEW_FOV, draw};
use anyhow::{Context, Result, bail};
use behavior_bddl::Taxonomy;
use behavior_env::{Env, categories};
use behavior_render::{Camera, CategoryTable, ImageProfile, Modality, Pixels, Renderer, View};
use gif::{Encoder, Frame, Repeat};
use image::{Rgb, RgbImage};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Action steps (1/30 s) between frames: 10 frames per simulated second.
pub const FRAME_EVERY: u32 = 3;
/// The caption strip under the pictures, pixels.
const CAPTION: u32 = 20;
/// The strip under the caption where Q's curve is drawn, pixels.
const CURVE: u32 = 40;
/// GIF palette quantization speed (1 best … 30 fastest): 10 keeps a frame in milliseconds.
const QUANTIZE_SPEED: i32 = 10;
/// The sizes a picture may have, pixels.
const SIZES: std::ops::RangeInclusive<u32> = 64..=2048;

/// The command line's video options (`run`, `solve`).
#[derive(clap::Args)]
pub struct VideoArgs {
    /// A video of the episode: the robot's eye and an overview of the home side by side over
    /// Q's curve, 10 frames per simulated second, as an animated GIF.
    #[arg(long, value_name = "FILE.gif")]
    pub video: Option<PathBuf>,
    /// The video's pictures' width and height, pixels.
    #[arg(long, default_value_t = 256)]
    pub video_size: u32,
    /// How the video's pictures are drawn: realistic (materials, the home's sun with shadows,
    /// room lamps) or fast (flat colours).
    #[arg(long, default_value = "realistic")]
    pub profile: ImageProfile,
}

impl VideoArgs {
    /// The video asked for, started on `env`'s episode (its first frame drawn), or none.
    pub fn start(&self, env: &Env, taxonomy: &Taxonomy) -> Result<Option<Video>> {
        let Some(path) = &self.video else {
            return Ok(None);
        };
        let mut video = Video::create(
            path,
            env,
            (self.video_size, self.profile),
            categories(taxonomy),
        )?;
        video.capture(env, 0, env.score().map_or(0.0, |s| s.q), false)?;
        Ok(Some(video))
    }
}

/// An episode's video being written.
pub struct Video {
    renderer: Renderer,
    eye: View,
    overview: View,
    categories: CategoryTable,
    encoder: Encoder<BufWriter<File>>,
    /// Written here, renamed to `path` when whole.
    partial: PathBuf,
    path: PathBuf,
    frames: u32,
    /// Q at every frame so far.
    q: Vec<f32>,
}

impl Video {
    /// Starts a video of `env`'s episode (after its reset) at `path` (`.gif`), each picture
    /// `size` pixels square and drawn in `profile`.
    pub fn create(
        path: &Path,
        env: &Env,
        (size, profile): (u32, ImageProfile),
        categories: CategoryTable,
    ) -> Result<Video> {
        let is_gif = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("gif"));
        if !is_gif {
            bail!(
                "--video writes an animated GIF: name the file FILE.gif, not {}",
                path.display()
            );
        }
        if !SIZES.contains(&size) {
            bail!(
                "--video-size must be {}–{} pixels, not {size}",
                SIZES.start(),
                SIZES.end()
            );
        }
        let world = env.world().context("no episode")?;
        let robot = env.robot().context("no robot")?;
        let eye = View::with_profile(
            Camera {
                width: size,
                height: size,
                ..Camera::eye(robot.camera_pose(world))
            },
            profile,
        );
        let overview =
            View::with_profile(Camera::overview(world, size, size, OVERVIEW_FOV)?, profile);
        let partial = path.with_extension("gif.part");
        let cannot = || format!("cannot write {}", partial.display());
        let file = File::create(&partial).with_context(cannot)?;
        // Both sides fit in u16: SIZES keeps them under 4,200 pixels.
        let (width, height) = ((2 * size) as u16, (size + CAPTION + CURVE) as u16);
        let mut encoder =
            Encoder::new(BufWriter::new(file), width, height, &[]).with_context(cannot)?;
        encoder.set_repeat(Repeat::Infinite).with_context(cannot)?;
        let mut renderer = Renderer::new()?;
        renderer.set_models(behavior_robots::shared_models());
        Ok(Video {
            renderer,
            eye,
            overview,
            categories,
            encoder,
            partial,
            path: path.to_path_buf(),
            frames: 0,
            q: Vec::new(),
        })
    }

    /// Adds a frame of `env`'s state after `step` action steps, captioned with `q`, when `step`
    /// is one of every [`FRAME_EVERY`] or the episode's `last`.
    pub fn capture(&mut self, env: &Env, step: u32, q: f64, last: bool) -> Result<()> {
        if !step.is_multiple_of(FRAME_EVERY) && !last {
            return Ok(());
        }
        let world = env.world().context("no episode")?;
        self.eye.camera.pose = env.robot().context("no robot")?.camera_pose(world);
        let size = self.eye.camera.width;
        let mut picture =
            RgbImage::from_pixel(2 * size, size + CAPTION + CURVE, Rgb([255, 255, 255]));
        for (k, view) in [&mut self.eye, &mut self.overview].into_iter().enumerate() {
            let frame = draw(
                env,
                view,
                &mut self.renderer,
                &self.categories,
                &[Modality::Rgb],
            )?;
            let rgb = frame
                .images
                .into_iter()
                .find(|i| i.modality == Modality::Rgb);
            let Some(Pixels::U8(rgb)) = rgb.map(|i| i.pixels) else {
                bail!("the renderer returned no colour image");
            };
            let image = RgbImage::from_raw(size, size, rgb)
                .context("the colour image has the wrong size")?;
            image::imageops::replace(&mut picture, &image, i64::from(k as u32 * size), 0);
        }
        let (black, y) = (Rgb([0, 0, 0]), (size + CAPTION / 2) as f32);
        text(&mut picture, "eye", size as f32 * 0.25, y, 1, black);
        text(
            &mut picture,
            &format!("step {step}  Q {q:.3}"),
            size as f32,
            y,
            1,
            black,
        );
        text(&mut picture, "overview", size as f32 * 1.75, y, 1, black);
        self.q.push(q as f32);
        curve(&mut picture, &self.q, size + CAPTION);
        let (width, height) = (picture.width() as u16, picture.height() as u16);
        let mut frame = Frame::from_rgb_speed(width, height, picture.as_raw(), QUANTIZE_SPEED);
        // In hundredths of a second: 1/30 s per action step.
        frame.delay = (100 * FRAME_EVERY / 30) as u16;
        self.encoder
            .write_frame(&frame)
            .with_context(|| format!("cannot write {}", self.partial.display()))?;
        self.frames += 1;
        Ok(())
    }

    /// Finishes the file and gives it its name; returns the number of frames.
    pub fn finish(self) -> Result<u32> {
        let cannot = || format!("cannot write {}", self.partial.display());
        let mut writer = self.encoder.into_inner().with_context(cannot)?;
        writer.flush().with_context(cannot)?;
        drop(writer);
        std::fs::rename(&self.partial, &self.path).with_context(|| {
            format!(
                "cannot move {} to {}",
                self.partial.display(),
                self.path.display()
            )
        })?;
        Ok(self.frames)
    }
}

/// Q over the frames so far, in the strip from row `top` to the picture's bottom: the whole
/// episode so far across the picture's width, 0 at the strip's bottom and 1 at its top, on a
/// light grey ground with the two lines faint.
fn curve(picture: &mut RgbImage, q: &[f32], top: u32) {
    let (width, bottom) = (picture.width(), picture.height() - 3);
    let top = top + 3;
    for x in 0..width {
        for y in top - 3..picture.height() {
            picture.put_pixel(x, y, Rgb([236, 238, 240]));
        }
        picture.put_pixel(x, top, Rgb([200, 204, 210]));
        picture.put_pixel(x, bottom, Rgb([200, 204, 210]));
    }
    let row = |v: f32| bottom - ((bottom - top) as f32 * v.clamp(0.0, 1.0)).round() as u32;
    let last = q.len().saturating_sub(1).max(1) as f32;
    let mut previous: Option<(u32, u32)> = None;
    for (i, &v) in q.iter().enumerate() {
        let x = ((width - 1) as f32 * i as f32 / last).round() as u32;
        let y = row(v);
        // A vertical run joins each point to the one before, so steps in Q show as steps.
        let (from, to) = previous.map_or((y, y), |(_, py)| (py.min(y), py.max(y)));
        let from_x = previous.map_or(x, |(px, _)| px);
        for xx in from_x..=x {
            picture.put_pixel(xx, previous.map_or(y, |(_, py)| py), Rgb([30, 130, 70]));
        }
        for yy in from..=to {
            picture.put_pixel(x, yy, Rgb([30, 130, 70]));
        }
        previous = Some((x, y));
    }
}
