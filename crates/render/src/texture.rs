//! The realistic profile's patterns baked into images, for drawers that take textures (glTF
//! export and the browser viewer), and where on them each point of a part lies.
//!
//! The cameras' shader (`realistic.wgsl`) draws a pattern from the part's own 3-D coordinates;
//! an image is 2-D and repeats. So a pattern is baked over a tile of its own size (floor boards
//! 2.8 × 1.12 m, tiles 1.2 m, weave 25 cm) with the same noise made periodic over the tile
//! (its lattice wrapped), the same arithmetic and the same constants, and a part's triangles
//! are mapped onto it by box projection: each triangle onto the plane of its part's frame that
//! faces it most, wood with its grain along the part's longest side as the shader turns it.
//! What this changes against the shader: wood shows straight-grained boards on every face
//! (the shader's end grain shows rings), the image repeats where the shader never does, and a
//! triangle's texture jumps where its neighbour projects onto another plane (on round things,
//! where noise hides it). Each object shifts the image by its seed, so two chairs' grain
//! differs, as in the shader.
//!
//! What an image holds: the pattern's *tint*, which multiplies the part's colour, divided by
//! its largest value (so that it fits in 0–1; a material's colour factor is multiplied back),
//! and where the pattern has relief (boards' seams, grout, weave, pile) a normal map from its
//! height. Roughness stays the material's: the shader's small roughness changes (grout,
//! brushed streaks) are not baked. Printed paper is the one pattern whose colours are the
//! object's own (a label band in a second colour), so its image is baked per object.

use crate::finish::Pattern;
use image::RgbImage;
use rapier3d::math::Vector;

/// Which image: a pattern's (shared by every part drawn with it) or one object's print.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum TextureKey {
    Pattern {
        pattern: u32,
        /// Tiles: 30 cm (0) or 20 cm (1), as the shader picks by the floor's seed.
        variant: u32,
        seed: u32,
    },
    /// Printed paper for an object's seed and colour (linear RGB's bits).
    Print { seed: u32, base: [u32; 3] },
}

impl TextureKey {
    /// The image of `pattern` for a part of seed `part_seed` and linear colour `base`, in a
    /// home of seed `home`; none where the pattern has no texture (glass: a flat tint).
    pub(crate) fn of(pattern: Pattern, part_seed: u32, base: [f32; 3], home: u32) -> Option<Self> {
        match pattern {
            Pattern::Glass => None,
            Pattern::Print => Some(TextureKey::Print {
                seed: part_seed,
                base: base.map(f32::to_bits),
            }),
            _ => Some(TextureKey::Pattern {
                pattern: pattern as u32,
                variant: if pattern == Pattern::Tiles {
                    part_seed & 1
                } else {
                    0
                },
                seed: home ^ (pattern as u32).wrapping_mul(0x9e37_79b9),
            }),
        }
    }
}

/// A baked pattern.
pub(crate) struct Texture {
    /// sRGB-encoded: the tint divided by [`Texture::reference`]'s inverse (see there).
    pub(crate) color: RgbImage,
    /// Tangent-space normals (+x along u, +y toward the image's top), where the pattern has
    /// relief.
    pub(crate) normal: Option<RgbImage>,
    /// The linear colour the image was made for: a part of linear colour `c` takes the colour
    /// factor `c / reference` (1 / the tint's top for patterns; the object's own colour for
    /// print, whose image holds its colours).
    pub(crate) reference: [f32; 3],
}

/// How a part's points map onto its image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Mapping {
    /// Metres the image spans along u and v.
    span: [f32; 2],
    /// The part's axis its grain runs along (wood), if any.
    grain: Option<usize>,
    /// Print: the part's half height, m (the image spans its height once).
    print_height: Option<f32>,
    /// Where the object's image starts (its seed), in images.
    offset: [f32; 2],
}

/// Glass has no image: a flat 0.6 of its colour, as the shader's tint.
pub(crate) const GLASS_TINT: f32 = 0.6;

impl Mapping {
    /// How a part drawn with `pattern`, of half size `extent` (m), of an object of seed `seed`,
    /// maps onto its image.
    pub(crate) fn of(pattern: Pattern, extent: [f32; 3], seed: u32) -> Mapping {
        let longest = (0..3).fold(0, |best, k| if extent[k] > extent[best] { k } else { best });
        let unit = |salt: u32| (mix_bits(seed ^ salt) >> 8) as f32 / 16_777_216.0;
        Mapping {
            span: tile(pattern).span,
            grain: (pattern == Pattern::Wood).then_some(longest),
            print_height: (pattern == Pattern::Print).then_some(extent[2].max(1e-3)),
            offset: [unit(0x51ed), unit(0x2c1b)],
        }
    }

    /// Which axis of the part's frame a triangle of normal `n` is projected along: the one it
    /// faces most.
    pub(crate) fn facing(&self, n: [f32; 3]) -> usize {
        (0..3).fold(
            0,
            |best, k| {
                if n[k].abs() > n[best].abs() { k } else { best }
            },
        )
    }

    /// The part's axes that u and v follow on a triangle projected along `facing`.
    fn plane(&self, facing: usize) -> (usize, usize) {
        let (a, b) = match facing {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        if self.grain == Some(b) {
            (b, a)
        } else {
            (a, b)
        }
    }

    /// The texture coordinates of a point `p` (m, in the part's frame) on a triangle projected
    /// along `facing`.
    pub(crate) fn uv(&self, p: [f32; 3], facing: usize) -> [f32; 2] {
        let (a, b) = self.plane(facing);
        let u = p[a] / self.span[0] + self.offset[0];
        let v = match self.print_height {
            // Top of the part at the image's top.
            Some(h) => 0.5 - 0.5 * (p[2] / h).clamp(-1.0, 1.0),
            None => p[b] / self.span[1] + self.offset[1],
        };
        [u, v]
    }

    /// The part's directions (unit axes of its frame) in which u grows and toward the image's
    /// top, on a triangle projected along `facing`.
    pub(crate) fn axes(&self, facing: usize) -> (Vector, Vector) {
        let (a, b) = self.plane(facing);
        let axis =
            |k: usize| Vector::from_array(std::array::from_fn(|i| if i == k { 1.0 } else { 0.0 }));
        // v grows down the image: its top is where v falls (along -b; up the part for print).
        let up = if self.print_height.is_some() {
            axis(2)
        } else {
            -axis(b)
        };
        (axis(a), up)
    }

    /// The mapping and a part's size `scale` as bits, for telling meshes apart.
    pub(crate) fn bits(&self, scale: Vector) -> [u32; 9] {
        let f = f32::to_bits;
        [
            f(scale.x),
            f(scale.y),
            f(scale.z),
            f(self.span[0]),
            f(self.span[1]),
            self.grain.map_or(3, |g| g as u32),
            self.print_height.map_or(0, f),
            f(self.offset[0]),
            f(self.offset[1]),
        ]
    }
}

/// A pattern's tile: metres spanned along u and v, and pixels.
struct Tile {
    span: [f32; 2],
    pixels: [u32; 2],
}

fn tile(pattern: Pattern) -> Tile {
    let (span, pixels) = match pattern {
        Pattern::Plain => ([1.0, 1.0], [128, 128]),
        Pattern::Wood => ([2.0, 0.5], [256, 256]),
        Pattern::Planks => ([2.0 * BOARD_LENGTH, 8.0 * BOARD_WIDTH], [512, 512]),
        Pattern::Tiles => ([1.2, 1.2], [512, 512]),
        Pattern::Carpet => ([0.5, 0.5], [512, 512]),
        Pattern::Plaster => ([1.0, 1.0], [256, 256]),
        Pattern::Marble => ([std::f32::consts::PI, std::f32::consts::PI], [512, 512]),
        Pattern::Fabric => ([WEAVE_TILE, WEAVE_TILE], [256, 256]),
        Pattern::Brushed => ([1.0, 0.1], [256, 256]),
        Pattern::Print => ([0.5, 1.0], [128, 128]),
        Pattern::Skin => ([0.4, 0.4], [512, 512]),
        Pattern::Glass => ([1.0, 1.0], [1, 1]),
    };
    Tile { span, pixels }
}

/// Floor boards: 14 cm wide, up to 1.4 m long (the shader's constants).
const BOARD_WIDTH: f32 = 0.14;
const BOARD_LENGTH: f32 = 1.4;
/// The weave's threads repeat every 2π / 250 m; ten of them.
const WEAVE_TILE: f32 = 10.0 * std::f32::consts::TAU / 250.0;

/// Bakes `key`'s image.
pub(crate) fn bake(key: TextureKey) -> Texture {
    match key {
        TextureKey::Pattern {
            pattern,
            variant,
            seed,
        } => baked(pattern_of(pattern), variant, seed),
        TextureKey::Print { seed, base } => print_image(seed, base.map(f32::from_bits)),
    }
}

fn pattern_of(number: u32) -> Pattern {
    use Pattern::*;
    [
        Plain, Wood, Planks, Tiles, Carpet, Plaster, Marble, Fabric, Brushed, Print, Skin, Glass,
    ]
    .into_iter()
    .find(|p| *p as u32 == number)
    .unwrap_or(Plain)
}

/// A pattern's tint and height (m) at a point of its tile.
type Sample = (f32, f32);

fn baked(pattern: Pattern, variant: u32, seed: u32) -> Texture {
    let Tile { span, pixels } = tile(pattern);
    let [w, h] = pixels;
    let mut tints = Vec::with_capacity((w * h) as usize);
    let mut heights = Vec::with_capacity((w * h) as usize);
    for j in 0..h {
        for i in 0..w {
            let x = (i as f32 + 0.5) / w as f32 * span[0];
            let y = (j as f32 + 0.5) / h as f32 * span[1];
            let (tint, height) = sample(pattern, variant, span, x, y, seed);
            tints.push(tint);
            heights.push(height);
        }
    }
    let top = tints.iter().copied().fold(1e-3, f32::max);
    let color = RgbImage::from_fn(w, h, |i, j| {
        let c = srgb_byte(tints[(j * w + i) as usize] / top);
        image::Rgb([c; 3])
    });
    let relief = heights.iter().any(|&z| z != heights[0]);
    let step = [span[0] / w as f32, span[1] / h as f32];
    Texture {
        color,
        normal: relief.then(|| normal_map(&heights, [w, h], step)),
        reference: [1.0 / top; 3],
    }
}

/// Normals of a height field that repeats, by central differences.
fn normal_map(heights: &[f32], [w, h]: [u32; 2], step: [f32; 2]) -> RgbImage {
    let at = |i: i64, j: i64| {
        let (i, j) = (i.rem_euclid(w as i64), j.rem_euclid(h as i64));
        heights[(j * w as i64 + i) as usize]
    };
    RgbImage::from_fn(w, h, |i, j| {
        let (i, j) = (i64::from(i), i64::from(j));
        let dx = (at(i + 1, j) - at(i - 1, j)) / (2.0 * step[0]);
        // Rows run down the image; the normal's y points up it.
        let dy = (at(i, j + 1) - at(i, j - 1)) / (2.0 * step[1]);
        let n = [-dx, dy, 1.0];
        let len = (n[0] * n[0] + n[1] * n[1] + 1.0).sqrt();
        image::Rgb(n.map(|c| ((c / len * 0.5 + 0.5) * 255.0).round() as u8))
    })
}

fn srgb_byte(linear: f32) -> u8 {
    let c = linear.clamp(0.0, 1.0);
    let s = if c <= 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round() as u8
}

/// The pattern at (x, y) of its tile, as `texel` in `realistic.wgsl` computes it on the
/// part's z = 0 plane, its noise periodic over the tile.
fn sample(pattern: Pattern, variant: u32, span: [f32; 2], x: f32, y: f32, seed: u32) -> Sample {
    // Value noise at `freq` cycles a metre, rounded so that the tile holds whole cycles.
    let n = |fx: f32, fy: f32, seed: u32| {
        let px = (fx * span[0]).round().max(1.0);
        let py = (fy * span[1]).round().max(1.0);
        noise(
            [x * px / span[0], y * py / span[1]],
            [px as i32, py as i32],
            seed,
        )
    };
    match pattern {
        Pattern::Wood => {
            let a = n(1.5, 6.0, seed);
            let b = n(4.0, 120.0, seed.wrapping_add(7));
            (rings(y, a, b, span[1]), 0.0003 * b)
        }
        Pattern::Planks => planks(x, y, seed),
        Pattern::Tiles => {
            let size = if variant == 1 { 0.2 } else { 0.3 };
            let count = (span[0] / size).round() as i32;
            let cell = [(x / size).floor() as i32, (y / size).floor() as i32];
            let f = [(x / size).fract(), (y / size).fract()];
            let edge = f[0].min(1.0 - f[0]).min(f[1].min(1.0 - f[1])) * size;
            let grout = smoothstep(0.002, 0.004, edge);
            let cell = [cell[0].rem_euclid(count), cell[1].rem_euclid(count)];
            let speck = n(60.0, 60.0, seed);
            let tone = 0.92 + 0.1 * lattice([cell[0], cell[1], 5], seed) - 0.04 * speck;
            // The grout 0.55 grey against the tile's tone (the shader mixes colours; here one
            // tint, the grout's a little warm in the shader, grey here).
            let tint = 0.54 + (tone - 0.54) * grout;
            (tint, 0.002 * smoothstep(0.002, 0.014, edge))
        }
        Pattern::Carpet => {
            let a = n(220.0, 220.0, seed);
            let b = n(3.0, 3.0, seed.wrapping_add(7));
            (0.78 + 0.22 * a + 0.12 * (b - 0.5), 0.0015 * a)
        }
        Pattern::Plaster => {
            let a = n(7.0, 7.0, seed);
            let b = n(19.0, 19.0, seed.wrapping_add(7));
            let m = 0.65 * a + 0.35 * b;
            (1.0 + 0.06 * (m - 0.5), 0.0004 * m)
        }
        Pattern::Marble => {
            let a = n(3.0, 3.0, seed);
            let b = n(40.0, 40.0, seed.wrapping_add(7));
            let vein = 1.0 - (x * 4.0 + y * 2.0 + a * 7.0).sin().abs();
            let v4 = vein.powi(4);
            (1.0 - v4 * v4 * 0.45 + 0.05 * (b - 0.5), 0.0)
        }
        Pattern::Fabric => {
            let a = n(30.0, 30.0, seed);
            let weave = 0.5 + 0.5 * (250.0 * x).sin() * (250.0 * y).sin();
            (0.82 + 0.12 * weave + 0.1 * (a - 0.5), 0.0004 * weave)
        }
        Pattern::Brushed => {
            let a = n(4.0, 400.0, seed);
            (0.9 + 0.12 * a, 0.0)
        }
        Pattern::Skin => {
            let a = n(25.0, 25.0, seed);
            let b = n(300.0, 300.0, seed.wrapping_add(7));
            let spot = if b >= 0.93 { 0.25 } else { 0.0 };
            (0.85 + 0.3 * a - spot, 0.0005 * a)
        }
        Pattern::Glass => (GLASS_TINT, 0.0),
        Pattern::Plain | Pattern::Print => (0.97 + 0.06 * n(12.0, 12.0, seed), 0.0),
    }
}

/// Growth rings across a board seen from its face: stripes across v about 2 cm apart, wavy
/// by `wobble`, with fibres (the shader's rings at its frame's z = 0, whole over the tile).
fn rings(y: f32, wobble: f32, fibre: f32, span: f32) -> f32 {
    let per_metre = (20.0 * span).round() / span;
    let r = (y * per_metre + wobble * 2.5).rem_euclid(1.0);
    1.0 - smoothstep(0.55, 0.95, r) * 0.28 - fibre * 0.1
}

/// Floor boards over a tile of two boards' length and eight rows: each row's boards shifted
/// by the row's seed, each board its own shade and grain, seams 2 mm deep.
fn planks(x: f32, y: f32, seed: u32) -> Sample {
    let row = (y / BOARD_WIDTH).floor() as i32;
    let shift = lattice([row, 0, 0], seed) * BOARD_LENGTH;
    let board = ((x + shift) / BOARD_LENGTH).floor() as i32;
    let along = (x + shift).rem_euclid(BOARD_LENGTH);
    let across = (y / BOARD_WIDTH).fract();
    // Each board's grain from a seed of its own (a board wrapping round the tile's end keeps
    // its seed: boards are counted modulo two).
    let own = seed ^ mix_bits((row as u32).wrapping_mul(31) ^ (board.rem_euclid(2) as u32));
    let a = noise([along * 1.5, across * BOARD_WIDTH * 6.0], [0, 0], own);
    let b = noise(
        [along * 4.0, across * BOARD_WIDTH * 120.0],
        [0, 0],
        own.wrapping_add(7),
    );
    let grain = rings(across * BOARD_WIDTH, a, b, 1.0);
    let seam = (across.min(1.0 - across) * BOARD_WIDTH)
        .min((along / BOARD_LENGTH).min(1.0 - along / BOARD_LENGTH) * BOARD_LENGTH);
    let groove = 1.0 - 0.45 * (1.0 - smoothstep(0.0, 0.003, seam));
    let tone = 0.82 + 0.3 * lattice([row, board.rem_euclid(2), 3], seed);
    (grain * tone * groove, 0.0015 * smoothstep(0.0, 0.008, seam))
}

/// Printed paper: a label band in a second colour with lines of print around it, top to bottom
/// of the part (rows) and along its width (columns, where the ink comes and goes like words).
fn print_image(seed: u32, base: [f32; 3]) -> Texture {
    let Tile { span, pixels } = tile(Pattern::Print);
    let [w, h] = pixels;
    let hue = [[1, 2, 3], [4, 5, 6], [7, 8, 9]].map(|c| lattice(c, seed));
    let accent: [f32; 3] = std::array::from_fn(|k| hue[k] * hue[k] / base[k].max(0.05));
    let low = -0.2 + 0.3 * hue[0];
    let words = (90.0 * span[0]).round() as i32;
    let color = RgbImage::from_fn(w, h, |i, j| {
        let height = 1.0 - 2.0 * (j as f32 + 0.5) / h as f32;
        let line_index = (height * 14.0).floor();
        let x = (i as f32 + 0.5) / w as f32 * words as f32;
        let ink = noise([x, line_index], [words, 0], seed);
        let band = if (low..=low + 0.45).contains(&height) {
            1.0
        } else {
            0.0
        };
        let line = if (height * 14.0).rem_euclid(1.0) >= 0.55 && ink >= 0.35 {
            1.0
        } else {
            0.0
        };
        image::Rgb(std::array::from_fn(|k| {
            let tint = (1.0 + (accent[k] - 1.0) * band) * (1.0 - 0.5 * line * (1.0 - band));
            srgb_byte(base[k] * tint)
        }))
    });
    Texture {
        color,
        normal: None,
        reference: base.map(|c| c.max(1e-3)),
    }
}

fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

// ---- noise, as realistic.wgsl's ----

fn mix_bits(x: u32) -> u32 {
    let mut v = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    v = ((v >> ((v >> 28) + 4)) ^ v).wrapping_mul(277_803_737);
    (v >> 22) ^ v
}

/// A number in [0, 1] for a lattice point and a seed.
fn lattice(c: [i32; 3], seed: u32) -> f32 {
    let h = mix_bits(
        (c[0] as u32).wrapping_mul(73_856_093)
            ^ (c[1] as u32).wrapping_mul(19_349_663)
            ^ (c[2] as u32).wrapping_mul(83_492_791)
            ^ seed,
    );
    (h >> 8) as f32 * (1.0 / 16_777_215.0)
}

/// Smooth value noise in [0, 1] on the z = 0 plane, its lattice wrapped every `period` cells
/// along x and y (0: not wrapped).
fn noise(p: [f32; 2], period: [i32; 2], seed: u32) -> f32 {
    let wrap = |c: i32, k: usize| {
        if period[k] > 0 {
            c.rem_euclid(period[k])
        } else {
            c
        }
    };
    let i = [p[0].floor() as i32, p[1].floor() as i32];
    let f = [p[0] - i[0] as f32, p[1] - i[1] as f32];
    let u = f.map(|t| t * t * (3.0 - 2.0 * t));
    let at = |dx: i32, dy: i32| lattice([wrap(i[0] + dx, 0), wrap(i[1] + dy, 1), 0], seed);
    let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
    let bottom = lerp(at(0, 0), at(1, 0), u[0]);
    let top = lerp(at(0, 1), at(1, 1), u[0]);
    lerp(bottom, top, u[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(pattern: Pattern, seed: u32) -> TextureKey {
        TextureKey::of(pattern, seed, [0.5; 3], 77).unwrap()
    }

    #[test]
    fn every_pattern_image_repeats_without_a_seam_and_varies_with_the_home() {
        for pattern in [
            Pattern::Plain,
            Pattern::Wood,
            Pattern::Planks,
            Pattern::Tiles,
            Pattern::Carpet,
            Pattern::Plaster,
            Pattern::Marble,
            Pattern::Fabric,
            Pattern::Brushed,
            Pattern::Skin,
        ] {
            let t = bake(key(pattern, 3));
            let img = &t.color;
            let (w, h) = img.dimensions();
            // Across the wrap, neighbouring pixels differ no more than neighbours inside do.
            let step = |a: &image::Rgb<u8>, b: &image::Rgb<u8>| a[0].abs_diff(b[0]);
            let inside = (0..h)
                .map(|j| {
                    (1..w)
                        .map(|i| step(img.get_pixel(i - 1, j), img.get_pixel(i, j)))
                        .max()
                        .unwrap()
                })
                .max()
                .unwrap();
            let across = (0..h)
                .map(|j| step(img.get_pixel(w - 1, j), img.get_pixel(0, j)))
                .max()
                .unwrap();
            assert!(
                across <= inside.max(2),
                "{pattern:?}: a seam of {across} where neighbours differ by {inside}"
            );
            let down = (0..w)
                .map(|i| {
                    (1..h)
                        .map(|j| step(img.get_pixel(i, j - 1), img.get_pixel(i, j)))
                        .max()
                        .unwrap()
                })
                .max()
                .unwrap();
            let wrap = (0..w)
                .map(|i| step(img.get_pixel(i, h - 1), img.get_pixel(i, 0)))
                .max()
                .unwrap();
            assert!(
                wrap <= down.max(2),
                "{pattern:?}: a seam of {wrap} down, where neighbours differ by {down}"
            );
            // Not flat, and the tint's top is the image's white.
            let values: Vec<u8> = img.pixels().map(|p| p[0]).collect();
            let (lo, hi) = (values.iter().min().unwrap(), values.iter().max().unwrap());
            assert!(hi - lo >= 4, "{pattern:?}: a flat image ({lo}..{hi})");
            assert!(
                *hi >= 250,
                "{pattern:?}: its brightest pixel is {hi}, not the tint's top"
            );
            assert!(
                t.reference[0] > 0.5 && t.reference[0] <= 1.0 / 0.9,
                "{pattern:?}: {:?}",
                t.reference
            );
            // Another home, another image; the same home, the same.
            let other = TextureKey::of(pattern, 3, [0.5; 3], 78).unwrap();
            assert_ne!(
                bake(other).color,
                t.color,
                "{pattern:?}: the same in two homes"
            );
            assert_eq!(
                bake(key(pattern, 3)).color,
                t.color,
                "{pattern:?}: not repeatable"
            );
        }
    }

    #[test]
    fn relief_becomes_a_normal_map_and_flat_patterns_have_none() {
        let tiles = bake(key(Pattern::Tiles, 0));
        let normal = tiles.normal.expect("tiles' grout has relief");
        // Inside a tile the normal faces out (z up); at the grout's edge it tilts.
        let centre = normal.get_pixel(64, 64);
        assert!(centre[2] > 250 && centre[0].abs_diff(128) < 3, "{centre:?}");
        assert!(
            normal.pixels().any(|p| p[0].abs_diff(128) > 20),
            "no tilt at the grout"
        );
        assert!(bake(key(Pattern::Marble, 0)).normal.is_none());
        assert!(TextureKey::of(Pattern::Glass, 0, [0.5; 3], 0).is_none());
    }

    #[test]
    fn a_print_carries_its_objects_colours_and_a_band_of_a_second() {
        let base = [0.6, 0.2, 0.1];
        let t = bake(TextureKey::of(Pattern::Print, 9, base, 0).unwrap());
        assert_eq!(t.reference, base);
        let colours: std::collections::BTreeSet<[u8; 3]> = t.color.pixels().map(|p| p.0).collect();
        assert!(
            colours.contains(&base.map(srgb_byte)),
            "the paper's own colour is in it"
        );
        assert!(
            colours.len() >= 3,
            "{} colours: no band and no print",
            colours.len()
        );
    }

    #[test]
    fn wood_runs_along_the_part_and_print_spans_its_height() {
        let m = Mapping::of(Pattern::Wood, [0.05, 0.6, 0.02], 1);
        // A face looking up (z): the grain (u) along y, the part's longest side.
        let a = m.uv([0.0, 0.0, 0.02], m.facing([0.0, 0.0, 1.0]));
        let b = m.uv([0.0, 0.5, 0.02], m.facing([0.0, 0.0, 1.0]));
        assert!(
            (b[0] - a[0] - 0.5 / 2.0).abs() < 1e-6 && (b[1] - a[1]).abs() < 1e-6,
            "{a:?} {b:?}"
        );
        let p = Mapping::of(Pattern::Print, [0.1, 0.1, 0.2], 1);
        assert_eq!(p.uv([0.05, 0.1, 0.2], 1)[1], 0.0);
        assert_eq!(p.uv([0.05, 0.1, -0.2], 1)[1], 1.0);
        assert_ne!(
            Mapping::of(Pattern::Wood, [0.05, 0.6, 0.02], 2).offset,
            m.offset,
            "objects' grain differs"
        );
    }
}
