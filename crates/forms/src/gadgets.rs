//! Small machines and things worn: headphones, glasses, a computer mouse, office machines
//! (printers, scanners, fax machines), calculators, a blender and a smoke alarm. Each is built
//! in a frame of its own and stretched to fill its box, headphones excepted: their cups stay
//! round at their true size.

use crate::extrude::{prism, prism_across_y};
use crate::grid::{ball, signed_pow, sphere_grid};
use crate::lathe::{Pt, even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::{block, boxed, plain_box, rounded_box};
use crate::tone::Tone;
use crate::tube::{fillet, tube};
use crate::{Ctx, Detail};
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI, TAU};

/// Headphones standing on their cups: a band arching over the top and two round cups facing
/// each other along x, dark cushions on their inner faces, metal sliders between.
pub(crate) fn headphones(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    // Round where the box allows, taller than deep where it is low.
    let (radius, wide) = (h.y.min(0.45 * h.z), h.y);
    let depth = 0.24 * h.x;
    let centre_z = -h.z + radius;
    let cup_profile = [
        p(0.0, 0.0).tone(Tone::Dark),
        p(0.8, 0.0),
        p(0.97, 0.12),
        fold(1.0, 0.4).tone(Tone::Body),
        p(0.97, 0.8),
        p(0.8, 0.97),
        p(0.0, 1.0),
    ];
    let cup = |side: f32| {
        let mut made = revolve(&cup_profile, ctx.detail.around(), even);
        made.stretch(Vector::new(radius, wide, depth), Vector::ZERO);
        // About y by a quarter turn: the cup's axis (z) along +x, its cushion at its inner face.
        made.turn(
            Rotation::from_rotation_y(FRAC_PI_2),
            Vector::new(h.x - depth, 0.0, centre_z),
        );
        if side < 0.0 {
            made.turn_half();
        }
        made
    };
    let band_r = (0.14 * h.y).min(0.5 * depth).min(0.012);
    let reach = h.x - 0.5 * depth;
    let foot = centre_z + 0.6 * radius;
    let rise = h.z - band_r - foot;
    let steps = 2 * ctx.detail.bands();
    let arc: Vec<Vector> = (0..=steps)
        .map(|k| {
            let theta = PI * k as f32 / steps as f32;
            Vector::new(reach * theta.cos(), 0.0, foot + rise * theta.sin())
        })
        .collect();
    let sides = (ctx.detail.around() / 2).max(4);
    let mut pieces = vec![
        cup(1.0),
        cup(-1.0),
        tube(&arc, sides, |_, _| band_r, Tone::Body),
    ];
    for side in [-1.0, 1.0] {
        let slider = [
            Vector::new(side * reach, 0.0, centre_z + 0.5 * radius),
            Vector::new(side * reach, 0.0, foot + 0.02 * rise),
        ];
        pieces.push(tube(&slider, sides, |_, _| 0.7 * band_r, Tone::Metal));
    }
    join(pieces)
}

/// An ellipse's outline, counter-clockwise, `points` around.
fn ellipse(centre: (f32, f32), radii: (f32, f32), points: usize) -> Vec<(f32, f32)> {
    (0..points)
        .map(|k| {
            let a = TAU * k as f32 / points as f32;
            (centre.0 + radii.0 * a.cos(), centre.1 + radii.1 * a.sin())
        })
        .collect()
}

/// A pair of glasses: two dark lenses in rims toward −y, a bridge, and the temples running
/// back along +y with their ends bent down.
pub(crate) fn glasses(ctx: Ctx) -> Mesh {
    let points = 2 * ctx.detail.around() / 3;
    let tall = ctx.dice.between(0.5, 0.7);
    let mut pieces = Vec::new();
    for side in [-1.0f32, 1.0] {
        let centre = (side * 0.5, 0.0);
        let lens = ellipse(centre, (0.42, tall), points);
        pieces.push(prism_across_y(&lens, (-1.0, -0.9), Tone::Dark));
        let rim = ellipse(centre, (0.48, tall + 0.06), points);
        pieces.push(prism_across_y(&rim, (-0.98, -0.92), Tone::Body));
        pieces.push(rod(
            [side * 0.95, 0.02, 0.3],
            [0.04, 0.94, 0.05],
            ctx.detail,
        ));
        pieces.push(rod(
            [side * 0.95, 0.9, 0.05],
            [0.04, 0.06, 0.28],
            ctx.detail,
        ));
    }
    pieces.push(rod([0.0, -0.95, 0.3], [0.14, 0.03, 0.05], ctx.detail));
    join(pieces).fit(ctx.half)
}

/// A thin rounded bar of a frame (a plain one at the coarse level).
fn rod(centre: [f32; 3], half: [f32; 3], detail: Detail) -> Mesh {
    let (centre, half) = (Vector::from_array(centre), Vector::from_array(half));
    block(centre, half, 0.02, 1, detail, Tone::Body)
}

/// A computer mouse, its front toward +y: a dome higher toward its back and wider at it, and a
/// dark scroll wheel standing out of its top near the front.
pub(crate) fn mouse(ctx: Ctx) -> Mesh {
    let hump = ctx.dice.between(-0.35, -0.1);
    let top = move |u: f32| 0.55 + 0.45 * (1.0 - ((u - hump) / (1.0 - hump)).powi(2));
    let b = ctx.detail.bands();
    let shell = sphere_grid(b, 2 * b, |d| {
        let u = signed_pow(d.y, 0.6);
        let width = 0.5 * (0.86 - 0.14 * u);
        let z = if d.z >= 0.0 {
            0.1 + top(u) * signed_pow(d.z, 0.7)
        } else {
            0.1 + 0.1 * signed_pow(d.z, 0.5)
        };
        Vector::new(width * signed_pow(d.x, 0.6), 0.5 * u, z)
    });
    let mut wheel = crate::machines::wheel(Vector::ZERO, 0.09, 0.07, ctx.detail);
    // The wheel's axis from y to x, set into the shell where its top is.
    wheel.turn(
        Rotation::from_rotation_z(FRAC_PI_2),
        Vector::new(0.0, 0.25, 0.1 + top(0.5) - 0.04),
    );
    join([shell, wheel.toned(Tone::Dark)]).fit(ctx.half)
}

/// An office machine: a body with a dark seam under its lid, a sloping tray of paper at its
/// back (+y), a dark slot at its front and a panel of buttons on the lid.
pub(crate) fn office(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let lid = ctx.dice.between(0.05, 0.09);
    let mut pieces = vec![
        boxed([0.0, -0.1, 0.36], [1.0, 0.9, 0.36], 0.08, rows, Tone::Body),
        plain_box(
            Vector::new(0.0, -0.1, 0.735),
            Vector::new(0.97, 0.87, 0.02),
            Tone::Dark,
        ),
        boxed(
            [0.0, -0.1, 0.75 + lid],
            [1.0, 0.9, lid],
            0.5 * lid,
            rows,
            Tone::Body,
        ),
    ];
    // The tray, its outline in the y–z plane, laid across x.
    let tray = [(0.55, 0.7), (0.8, 0.7), (1.0, 1.0), (0.9, 1.0)];
    let sheets = prism(&tray, (-0.7, 0.7), Tone::Paper);
    pieces.push(sheets.lay_along_x());
    if ctx.detail == Detail::Fine {
        pieces.push(plain_box(
            Vector::new(0.0, -1.0, 0.42),
            Vector::new(0.6, 0.012, 0.03),
            Tone::Dark,
        ));
        let panel_z = 0.75 + 2.0 * lid;
        pieces.push(plain_box(
            Vector::new(0.62, -0.72, panel_z),
            Vector::new(0.3, 0.12, 0.012),
            Tone::Dark,
        ));
        for k in 0..3 {
            let x = 0.45 + 0.17 * k as f32;
            pieces.push(boxed(
                [x, -0.72, panel_z + 0.02],
                [0.05, 0.05, 0.02],
                0.015,
                1,
                Tone::Light,
            ));
        }
    }
    join(pieces).fit(ctx.half)
}

/// A calculator lying flat: a pale green display toward +y above four columns of five keys,
/// the last column dark.
pub(crate) fn keypad(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let key_rows = ctx.dice.count(4, 5);
    let mut pieces = vec![
        boxed([0.0, 0.0, 0.35], [1.0, 1.0, 0.35], 0.15, rows, Tone::Body),
        plain_box(
            Vector::new(0.0, 0.64, 0.72),
            Vector::new(0.8, 0.22, 0.04),
            Tone::Stalk,
        ),
    ];
    let pitch = 1.35 / key_rows as f32;
    for r in 0..key_rows {
        for c in 0..4 {
            let centre = Vector::new(-0.66 + 0.44 * c as f32, -0.85 + pitch * r as f32, 0.78);
            let half = Vector::new(0.16, 0.36 * pitch, 0.1);
            let tone = if c == 3 { Tone::Dark } else { Tone::Light };
            pieces.push(match ctx.detail {
                Detail::Fine => rounded_box(centre, half, 0.05, 1, tone),
                Detail::Coarse => plain_box(centre, half, tone),
            });
        }
    }
    join(pieces).fit(ctx.half)
}

/// A blender: a base with a dark knob at its front (−y), a jug widening upward with a dark lid,
/// and a dark handle on its side (+x).
pub(crate) fn blender(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let lid = |pt: Pt| pt.tone(Tone::Dark);
    let jug = [
        p(0.0, 0.24),
        fold(0.5, 0.24),
        p(0.56, 0.3),
        p(0.76, 0.84),
        lid(fold(0.78, 0.86)),
        lid(fold(0.8, 0.93)),
        lid(fold(0.2, 0.95)),
        lid(fold(0.2, 1.0)),
        lid(p(0.0, 1.0)),
    ];
    let sides = (ctx.detail.around() / 3).max(6);
    let grip = [
        Vector::new(0.6, 0.0, 0.8),
        Vector::new(0.92, 0.0, 0.76),
        Vector::new(0.92, 0.0, 0.44),
        Vector::new(0.5, 0.0, 0.38),
    ];
    join([
        boxed([0.0, 0.0, 0.13], [0.82, 0.82, 0.13], 0.1, rows, Tone::Body),
        boxed(
            [0.0, -0.84, 0.13],
            [0.12, 0.04, 0.06],
            0.03,
            rows,
            Tone::Dark,
        ),
        revolve(&jug, ctx.detail.around(), even),
        tube(&fillet(&grip, 0.1, 3), sides, |_, _| 0.06, Tone::Dark),
    ])
    .fit(ctx.half)
}

/// A smoke alarm lying on its back: a pale disc with a dark vent ring around a domed middle
/// and a red lamp on it.
pub(crate) fn detector(ctx: Ctx) -> Mesh {
    let dome = ctx.dice.between(0.8, 0.95);
    let profile = [
        p(0.0, 0.0),
        fold(0.97, 0.0),
        p(1.0, 0.1),
        p(1.0, 0.4),
        fold(0.92, 0.5),
        fold(0.9, 0.52).tone(Tone::Dark),
        fold(0.8, 0.52).tone(Tone::Body),
        p(0.72, 0.7),
        p(0.45, dome - 0.04),
        p(0.0, dome),
    ];
    join([
        revolve(&profile, ctx.detail.around(), even),
        ball(
            Vector::new(0.3, 0.0, dome - 0.06),
            0.07,
            ctx.detail,
            Tone::Clay,
        ),
    ])
    .fit(ctx.half)
}
