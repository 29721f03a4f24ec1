//! A top-down map of a home as a PNG: rooms coloured and labelled by type, walls, doors and
//! windows, wide openings between rooms (dashed), furniture outlines with their names, and a dot
//! for each thing of its clutter; and a sheet of several homes' maps side by side.

use behavior_assets::Scene;
use behavior_core::{DOOR_SYNSET, WINDOW_SYNSET};
use font8x8::legacy::BASIC_LEGACY;
use image::{Rgb, RgbImage};

const MARGIN: f32 = 0.6;

fn room_color(kind: behavior_core::RoomType) -> Rgb<u8> {
    Rgb(match kind.name() {
        "kitchen" => [255, 236, 179],
        "living_room" => [200, 230, 201],
        "bedroom" => [187, 222, 251],
        "bathroom" => [178, 235, 242],
        "dining_room" => [255, 224, 178],
        "garage" => [215, 204, 200],
        "home_office" => [225, 190, 231],
        "storage_room" => [207, 216, 220],
        "utility_room" => [240, 244, 195],
        "closet" => [248, 187, 208],
        "corridor" => [238, 238, 238],
        _ => [255, 255, 255],
    })
}

/// Draws the scene, then marks and labels the given boxes (name, min, max) in red.
pub fn render_marked(
    scene: &Scene,
    scale: f32,
    marked: &[(String, [f32; 3], [f32; 3])],
) -> RgbImage {
    let mut img = render(scene, scale);
    let (lo, hi) = extent(scene);
    let px = |x: f32, y: f32| ((x - lo[0] + MARGIN) * scale, (hi[1] - y + MARGIN) * scale);
    for (name, min, max) in marked {
        let red = Rgb([220, 30, 30]);
        outline(&mut img, px(min[0], max[1]), px(max[0], min[1]), red);
        let (cx, cy) = px((min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0);
        text(&mut img, name, cx, cy - 10.0, 1, red);
    }
    img
}

/// The scene's bounding rectangle in x, y.
fn extent(scene: &Scene) -> ([f32; 2], [f32; 2]) {
    let (mut lo, mut hi) = ([f32::MAX; 2], [f32::MIN; 2]);
    for r in scene.rooms.iter().flat_map(|r| r.rects()) {
        for k in 0..2 {
            lo[k] = lo[k].min(r.min[k]);
            hi[k] = hi[k].max(r.max[k]);
        }
    }
    if scene.rooms.is_empty() {
        ([0.0; 2], [1.0; 2])
    } else {
        (lo, hi)
    }
}

/// Draws the scene at `scale` pixels per metre.
pub fn render(scene: &Scene, scale: f32) -> RgbImage {
    draw(scene, scale, true)
}

/// Draws the scene at `scale` pixels per metre; with `names`, furniture named, room labels large
/// and a title, else room labels small, furniture as outlines only and no title (for a sheet of
/// many homes, which captions each).
fn draw(scene: &Scene, scale: f32, names: bool) -> RgbImage {
    let (lo, hi) = extent(scene);
    let width = ((hi[0] - lo[0] + 2.0 * MARGIN) * scale).ceil() as u32;
    let height = ((hi[1] - lo[1] + 2.0 * MARGIN) * scale).ceil() as u32;
    let mut img = RgbImage::from_pixel(
        width.clamp(1, 8000),
        height.clamp(1, 8000),
        Rgb([255, 255, 255]),
    );
    // World (x, y) to pixel; y grows up in the world and down in the image.
    let px = |x: f32, y: f32| ((x - lo[0] + MARGIN) * scale, (hi[1] - y + MARGIN) * scale);
    let fill = |img: &mut RgbImage, min: [f32; 2], max: [f32; 2], color: Rgb<u8>| {
        let (x0, y1) = px(min[0], min[1]);
        let (x1, y0) = px(max[0], max[1]);
        for y in (y0.floor().max(0.0) as u32)..(y1.ceil() as u32).min(img.height()) {
            for x in (x0.floor().max(0.0) as u32)..(x1.ceil() as u32).min(img.width()) {
                img.put_pixel(x, y, color);
            }
        }
    };
    for r in &scene.rooms {
        for rect in r.rects() {
            fill(&mut img, rect.min, rect.max, room_color(r.kind));
        }
        // Rugs in their own colour, paled so that furniture on them still shows.
        for rug in &r.rugs {
            let pale = Rgb(rug.color.map(|c| ((u16::from(c) + 2 * 235) / 3) as u8));
            fill(&mut img, rug.min, rug.max, pale);
        }
    }
    for w in &scene.walls {
        fill(
            &mut img,
            [w.min[0], w.min[1]],
            [w.max[0], w.max[1]],
            Rgb([60, 60, 60]),
        );
    }
    for o in &scene.objects {
        let (w, d) = if o.yaw_quarter_turns % 2 == 0 {
            (o.size[0], o.size[1])
        } else {
            (o.size[1], o.size[0])
        };
        let min = [o.position[0] - w / 2.0, o.position[1] - d / 2.0];
        let max = [o.position[0] + w / 2.0, o.position[1] + d / 2.0];
        let color = match o.synset.as_str() {
            DOOR_SYNSET => Rgb([141, 90, 50]),
            WINDOW_SYNSET => Rgb([66, 165, 245]),
            _ => Rgb([90, 90, 90]),
        };
        outline(&mut img, px(min[0], max[1]), px(max[0], min[1]), color);
        let (cx, cy) = px(o.position[0], o.position[1]);
        if names && !matches!(o.synset.as_str(), DOOR_SYNSET | WINDOW_SYNSET) {
            text(&mut img, &o.name, cx, cy, 1, Rgb([30, 30, 30]));
        }
    }
    // Clutter is small and plentiful: a dot each, under the labels.
    let dot = 0.03;
    for c in &scene.clutter {
        let [x, y, _] = c.position;
        fill(
            &mut img,
            [x - dot, y - dot],
            [x + dot, y + dot],
            Rgb([230, 120, 30]),
        );
    }
    for (from, to) in openings(scene) {
        dashed(
            &mut img,
            px(from[0], from[1]),
            px(to[0], to[1]),
            Rgb([120, 120, 120]),
        );
    }
    let size = if names { 2 } else { 1 };
    for r in &scene.rooms {
        let (cx, _) = px((r.min[0] + r.max[0]) / 2.0, r.max[1]);
        let (_, top) = px(r.min[0], r.max[1] - 0.25);
        text(
            &mut img,
            &r.label(),
            cx,
            top + 10.0,
            size,
            Rgb([20, 20, 120]),
        );
    }
    if names {
        let family = scene.family.map_or(String::new(), |f| format!(", {f}"));
        text(
            &mut img,
            &format!("{} (seed {}{family})", scene.name, scene.seed),
            width as f32 / 2.0,
            10.0,
            2,
            Rgb([0, 0, 0]),
        );
    }
    img
}

/// Where two rooms meet with no wall between them: each stretch of a room's edge, in 10 cm
/// steps, that lies on another room's edge and under no wall.
fn openings(scene: &Scene) -> Vec<([f32; 2], [f32; 2])> {
    let walled = |x: f32, y: f32| {
        scene.walls.iter().any(|w| {
            (w.min[0] - 0.01..=w.max[0] + 0.01).contains(&x)
                && (w.min[1] - 0.01..=w.max[1] + 0.01).contains(&y)
        })
    };
    // Every rectangle of every room, with its room: an L-shaped room's own rectangles meet
    // with no wall between, and that is no opening.
    let rects: Vec<(usize, behavior_sim::FloorRect)> = scene
        .rooms
        .iter()
        .enumerate()
        .flat_map(|(i, r)| r.rects().map(move |rect| (i, rect)))
        .collect();
    let mut out = Vec::new();
    for (k, (i, a)) in rects.iter().enumerate() {
        for (_, b) in rects[k + 1..].iter().filter(|(j, _)| j != i) {
            for (across, along) in [(0, 1), (1, 0)] {
                let at = if (a.max[across] - b.min[across]).abs() < 1e-3 {
                    a.max[across]
                } else if (a.min[across] - b.max[across]).abs() < 1e-3 {
                    a.min[across]
                } else {
                    continue;
                };
                let (lo, hi) = (
                    a.min[along].max(b.min[along]),
                    a.max[along].min(b.max[along]),
                );
                let mut t = lo + 0.05;
                while t < hi {
                    let p = if across == 0 { [at, t] } else { [t, at] };
                    let q = if across == 0 {
                        [at, (t + 0.1).min(hi)]
                    } else {
                        [(t + 0.1).min(hi), at]
                    };
                    if !walled(p[0], p[1]) {
                        out.push((p, q));
                    }
                    t += 0.1;
                }
            }
        }
    }
    out
}

/// A dashed line from `a` to `b` (pixels), two pixels wide.
fn dashed(img: &mut RgbImage, a: (f32, f32), b: (f32, f32), color: Rgb<u8>) {
    let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as u32).max(1);
    for k in 0..=steps {
        if (k / 3) % 2 == 1 {
            continue;
        }
        let t = k as f32 / steps as f32;
        let (x, y) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
        for (dx, dy) in [(0, 0), (1, 0), (0, 1)] {
            let (x, y) = (x as i64 + dx, y as i64 + dy);
            if x >= 0 && y >= 0 && (x as u32) < img.width() && (y as u32) < img.height() {
                img.put_pixel(x as u32, y as u32, color);
            }
        }
    }
}

/// The maps of `scenes` side by side, `columns` to a row, each scaled to fit a cell of
/// `cell` pixels (width, height), captioned with its name, family and number of rooms.
pub fn sheet(scenes: &[Scene], columns: u32, cell: (u32, u32)) -> RgbImage {
    let rows = (scenes.len() as u32).div_ceil(columns.max(1));
    let mut img = RgbImage::from_pixel(columns * cell.0, rows * cell.1, Rgb([255, 255, 255]));
    for (k, scene) in scenes.iter().enumerate() {
        let (lo, hi) = extent(scene);
        let fit = ((cell.0 as f32 - 20.0) / (hi[0] - lo[0] + 2.0 * MARGIN))
            .min((cell.1 as f32 - 40.0) / (hi[1] - lo[1] + 2.0 * MARGIN))
            .clamp(5.0, 400.0);
        let map = draw(scene, fit, false);
        let (x0, y0) = ((k as u32 % columns) * cell.0, (k as u32 / columns) * cell.1);
        let dx = (cell.0.saturating_sub(map.width())) / 2;
        for (x, y, p) in map.enumerate_pixels() {
            let (tx, ty) = (x0 + dx + x, y0 + 24 + y);
            if x < cell.0 && y + 24 < cell.1 && tx < img.width() && ty < img.height() {
                img.put_pixel(tx, ty, *p);
            }
        }
        let family = scene.family.map_or("-", |f| f.name());
        let caption = format!("{}: {family}, {} rooms", scene.name, scene.rooms.len());
        text(
            &mut img,
            &caption,
            (x0 + cell.0 / 2) as f32,
            (y0 + 14) as f32,
            2,
            Rgb([0, 0, 0]),
        );
    }
    img
}

fn outline(img: &mut RgbImage, (x0, y0): (f32, f32), (x1, y1): (f32, f32), color: Rgb<u8>) {
    let (x0, y0, x1, y1) = (
        x0.max(0.0) as u32,
        y0.max(0.0) as u32,
        x1.max(0.0) as u32,
        y1.max(0.0) as u32,
    );
    for x in x0..=x1.min(img.width().saturating_sub(1)) {
        for y in [y0, y1] {
            if y < img.height() {
                img.put_pixel(x, y, color);
            }
        }
    }
    for y in y0..=y1.min(img.height().saturating_sub(1)) {
        for x in [x0, x1] {
            if x < img.width() {
                img.put_pixel(x, y, color);
            }
        }
    }
}

/// ASCII text centred on (cx, cy), with 8×8 glyphs scaled by `size`, on a white band so it reads
/// over outlines.
pub(crate) fn text(img: &mut RgbImage, s: &str, cx: f32, cy: f32, size: u32, color: Rgb<u8>) {
    let glyph = 8 * size;
    let width = s.chars().count() as u32 * glyph;
    let x0 = cx as i64 - i64::from(width / 2);
    let y0 = cy as i64 - i64::from(glyph / 2);
    for y in (y0 - 1).max(0)..(y0 + i64::from(glyph) + 1).min(i64::from(img.height())) {
        for x in (x0 - 2).max(0)..(x0 + i64::from(width) + 2).min(i64::from(img.width())) {
            img.put_pixel(x as u32, y as u32, Rgb([255, 255, 255]));
        }
    }
    for (i, ch) in s.chars().enumerate() {
        let bitmap = BASIC_LEGACY[(ch as usize).min(127)];
        for (row, bits) in bitmap.iter().enumerate() {
            for col in 0..8 {
                if bits >> col & 1 == 0 {
                    continue;
                }
                for dy in 0..size {
                    for dx in 0..size {
                        let x = x0 + i64::from(i as u32 * glyph + col * size + dx);
                        let y = y0 + i64::from(row as u32 * size + dy);
                        if x >= 0 && y >= 0 && (x as u32) < img.width() && (y as u32) < img.height()
                        {
                            img.put_pixel(x as u32, y as u32, color);
                        }
                    }
                }
            }
        }
    }
}
