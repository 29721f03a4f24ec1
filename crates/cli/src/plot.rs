//! `behavior run --plot`: Q and the efficiency metrics of an episode over time, one panel each,
//! as the paper's figure of an episode.

use crate::map::text;
use anyhow::{Context, Result};
use behavior_env::Series;
use image::{Rgb, RgbImage};
use std::path::Path;

const WIDTH: u32 = 900;
const PANEL: u32 = 150;
const MARGIN: u32 = 40;

/// Draws the four panels (Q, cumulative kinematic disarrangement, distance navigated, hand
/// displacement) into a PNG.
pub fn plot_episode(series: &Series, title: &str, path: &Path) -> Result<()> {
    let cumulative = |v: &[f32]| -> Vec<f32> {
        v.iter()
            .scan(0.0, |sum, x| {
                *sum += x;
                Some(*sum)
            })
            .collect()
    };
    let panels = [
        ("success score Q", series.q.clone(), [30, 110, 200]),
        (
            "kinematic disarrangement (m, cumulative)",
            cumulative(&series.kinematic),
            [200, 90, 40],
        ),
        (
            "distance navigated (m)",
            cumulative(&series.distance),
            [40, 150, 70],
        ),
        (
            "hand displacement in contact (m)",
            cumulative(&series.hands),
            [150, 60, 160],
        ),
    ];
    let height = MARGIN + panels.len() as u32 * (PANEL + MARGIN);
    let mut img = RgbImage::from_pixel(WIDTH, height, Rgb([255, 255, 255]));
    text(&mut img, title, WIDTH as f32 / 2.0, 16.0, 2, Rgb([0, 0, 0]));
    for (k, (name, values, color)) in panels.iter().enumerate() {
        let top = MARGIN + k as u32 * (PANEL + MARGIN) + 16;
        panel(&mut img, top, name, values, Rgb(*color));
    }
    img.save(path)
        .with_context(|| format!("cannot write {}", path.display()))
}

/// One panel: a frame, the curve scaled to its largest value, its name and that value.
fn panel(img: &mut RgbImage, top: u32, name: &str, values: &[f32], color: Rgb<u8>) {
    let (left, right) = (MARGIN, WIDTH - MARGIN);
    let grey = Rgb([160, 160, 160]);
    for x in left..=right {
        img.put_pixel(x, top, grey);
        img.put_pixel(x, top + PANEL, grey);
    }
    for y in top..=top + PANEL {
        img.put_pixel(left, y, grey);
        img.put_pixel(right, y, grey);
    }
    let max = values.iter().copied().fold(0.0f32, f32::max);
    let scale = if max > 0.0 { max } else { 1.0 };
    let n = values.len().max(2) - 1;
    let mut previous: Option<(u32, u32)> = None;
    for (i, &v) in values.iter().enumerate() {
        let x = left + ((right - left) as f32 * i as f32 / n as f32) as u32;
        let y = top + PANEL - ((v / scale).clamp(0.0, 1.0) * PANEL as f32) as u32;
        let (x0, y0) = previous.unwrap_or((x, y));
        for yy in y0.min(y)..=y0.max(y) {
            img.put_pixel(x, yy, color);
        }
        for xx in x0..=x {
            img.put_pixel(xx, y, color);
        }
        previous = Some((x, y));
    }
    let label = format!("{name}: max {max:.3} over {} steps", values.len());
    text(
        img,
        &label,
        WIDTH as f32 / 2.0,
        top as f32 - 8.0,
        1,
        Rgb([0, 0, 0]),
    );
}
