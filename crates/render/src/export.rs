//! Images to files: a PNG for people (false colour for all but RGB) and a `.npy` array of the
//! exact numbers, for numpy.

use crate::modality::{Image, Modality, Pixels};
use std::path::Path;

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The file could not be written.
    #[error("writing {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Why.
        source: std::io::Error,
    },
    /// The PNG encoder failed.
    #[error("encoding {path}: {source}")]
    Png {
        /// The file.
        path: String,
        /// Why.
        source: image::ImageError,
    },
}

/// A colour for an id: spread around the hue circle by the golden ratio, 0 black.
fn id_color(id: u32) -> [u8; 3] {
    if id == 0 {
        return [0, 0, 0];
    }
    let hue = (id as f32 * 0.618_034).fract();
    hsv(hue, 0.65, 0.95)
}

fn hsv(h: f32, s: f32, v: f32) -> [u8; 3] {
    let i = (h * 6.0).floor();
    let f = h * 6.0 - i;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - f * s), v * (1.0 - (1.0 - f) * s));
    let (r, g, b) = match i as i32 % 6 {
        0 => (v, t, p),
        1 => (q, v, p),
        2 => (p, v, t),
        3 => (p, q, v),
        4 => (t, p, v),
        _ => (v, p, q),
    };
    [r, g, b].map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
}

/// Near red through yellow and green to far blue; nothing seen (0) black.
fn depth_color(d: f32, far: f32) -> [u8; 3] {
    if d <= 0.0 {
        return [0, 0, 0];
    }
    hsv(0.66 * (d / far).clamp(0.0, 1.0), 0.9, 0.95)
}

/// The image as 8-bit RGB for people.
pub fn to_rgb(image: &Image) -> Vec<u8> {
    match (&image.pixels, image.modality) {
        (Pixels::U8(p), Modality::Rgb) => p.clone(),
        (Pixels::U8(p), _) => p
            .iter()
            .flat_map(|&m| [if m > 0 { 255 } else { 0 }; 3])
            .collect(),
        (Pixels::U16(p), _) => p.iter().flat_map(|&i| id_color(u32::from(i))).collect(),
        (Pixels::U32(p), _) => p.iter().flat_map(|&i| id_color(i)).collect(),
        (Pixels::F32(p), Modality::Depth) => {
            let far = p.iter().copied().fold(0.0f32, f32::max).max(1e-3);
            p.iter().flat_map(|&d| depth_color(d, far)).collect()
        }
        (Pixels::F32(p), Modality::Flow) => {
            let most = p
                .chunks(2)
                .map(|f| f[0].hypot(f[1]))
                .fold(0.0f32, f32::max)
                .max(1e-3);
            p.chunks(2)
                .flat_map(|f| {
                    let angle = f[1].atan2(f[0]) / std::f32::consts::TAU + 0.5;
                    hsv(angle, 1.0, f[0].hypot(f[1]) / most)
                })
                .collect()
        }
        (Pixels::F32(p), Modality::SceneFlow) => {
            let most = p.iter().map(|v| v.abs()).fold(0.0f32, f32::max).max(1e-6);
            p.iter().map(|v| (v.abs() / most * 255.0) as u8).collect()
        }
        // Normals: each axis from −1..1 to 0..255.
        (Pixels::F32(p), _) => p
            .iter()
            .map(|v| ((v * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0) as u8)
            .collect(),
    }
}

/// Writes the image as a PNG (false colour: see [`to_rgb`]).
pub fn save_png(image: &Image, path: &Path) -> Result<(), ExportError> {
    let (h, w) = (image.shape[0] as u32, image.shape[1] as u32);
    let rgb = image::RgbImage::from_raw(w, h, to_rgb(image)).ok_or_else(|| ExportError::Io {
        path: path.display().to_string(),
        source: std::io::Error::other("the image's numbers do not fill its shape"),
    })?;
    rgb.save(path).map_err(|source| ExportError::Png {
        path: path.display().to_string(),
        source,
    })
}

/// Writes the image's exact numbers as a `.npy` array of its shape and type.
pub fn save_npy(image: &Image, path: &Path) -> Result<(), ExportError> {
    let io = |source| ExportError::Io {
        path: path.display().to_string(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    let shape: Vec<u64> = image.shape.iter().map(|&d| d as u64).collect();
    let out = std::io::BufWriter::new(file);
    match &image.pixels {
        Pixels::U8(p) => write(out, &shape, p.iter().copied()),
        Pixels::U16(p) => write(out, &shape, p.iter().copied()),
        Pixels::U32(p) => write(out, &shape, p.iter().copied()),
        Pixels::F32(p) => write(out, &shape, p.iter().copied()),
    }
    .map_err(io)
}

fn write<T: npyz::AutoSerialize, W: std::io::Write>(
    out: W,
    shape: &[u64],
    values: impl IntoIterator<Item = T>,
) -> std::io::Result<()> {
    use npyz::WriterBuilder;
    let mut writer = npyz::WriteOptions::new()
        .default_dtype()
        .shape(shape)
        .writer(out)
        .begin_nd()?;
    writer.extend(values)?;
    writer.finish()
}
