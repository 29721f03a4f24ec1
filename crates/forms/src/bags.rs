//! Bags and cases: a backpack standing and a duffel bag lying along x (soft bodies with dark
//! straps and handles), a briefcase and a pencil case. The backpack is built at its true size
//! (its edges rounded alike on every side); the others in a frame of their own, and all are
//! stretched to fill their box.

use crate::grid::{signed_pow, sphere_grid};
use crate::mesh::{Mesh, join};
use crate::rounded::rounded_box;
use crate::tone::Tone;
use crate::tube::tube;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::PI;

/// A strap swept through `points`, `radius` thick, in `tone`.
fn strap(points: &[[f32; 3]], radius: f32, detail: Detail, tone: Tone) -> Mesh {
    let path: Vec<Vector> = points.iter().map(|&p| Vector::from_array(p)).collect();
    tube(&path, (detail.around() / 3).max(6), |_, _| radius, tone)
}

/// An arc from `from` to `to` (at equal height) rising `rise` at its middle, as points.
fn arc(from: [f32; 3], to: [f32; 3], rise: f32, steps: usize) -> Vec<[f32; 3]> {
    (0..=steps)
        .map(|k| {
            let t = k as f32 / steps as f32;
            let mix = |a: f32, b: f32| a + (b - a) * t;
            [
                mix(from[0], to[0]),
                mix(from[1], to[1]),
                from[2] + rise * (PI * t).sin(),
            ]
        })
        .collect()
}

/// A backpack: a soft body flat enough on top for its flap (a lid of its own) to lie on, a
/// pocket on its front (−y), two dark shoulder straps down its back (+y) and a carrying loop
/// rising from the back of its top.
/// Its body is as wide and deep as its box at the top, where the flap lies.
pub(crate) fn backpack(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let rows = ctx.detail.bevel_rows();
    let pocket = ctx.dice.between(0.2, 0.3);
    // Built at its true size, so that its edges are rounded alike on every side: a point of
    // the frame (x and y from −1 to 1, z from 0 to 1) in metres.
    let at = |x: f32, y: f32, z: f32| Vector::new(x * h.x, y * h.y, (2.0 * z - 1.0) * h.z);
    let soft = |centre: Vector, half: Vector| {
        rounded_box(centre, half, 0.3 * half.x.min(half.y), rows, Tone::Body)
    };
    let mut pieces = vec![
        soft(at(0.0, 0.19, 0.5), Vector::new(h.x, 0.81 * h.y, h.z)),
        soft(
            at(0.0, -0.6, 0.08 + pocket),
            Vector::new(0.7 * h.x, 0.35 * h.y, 2.0 * pocket * h.z),
        ),
    ];
    let thick = 0.06 * h.y.min(h.x);
    let strap = |points: &[[f32; 3]], radius: f32| {
        let points: Vec<[f32; 3]> = points
            .iter()
            .map(|&[x, y, z]| at(x, y, z).to_array())
            .collect();
        strap(&points, radius, ctx.detail, Tone::Dark)
    };
    for side in [-1.0f32, 1.0] {
        let x = side * 0.5;
        let points = [
            [x * 0.8, 0.85, 0.9],
            [x, 0.95, 0.6],
            [x * 1.1, 0.95, 0.3],
            [x * 1.2, 0.88, 0.1],
        ];
        pieces.push(strap(&points, thick));
    }
    let steps = ctx.detail.bands() / 2;
    let rise = 0.09 * h.z;
    let mut top = arc([-0.18, 0.8, 0.97], [0.18, 0.8, 0.97], 0.0, steps);
    for (k, point) in top.iter_mut().enumerate() {
        point[2] += rise / (2.0 * h.z) * (PI * k as f32 / steps as f32).sin();
    }
    pieces.push(strap(&top, 0.5 * thick));
    join(pieces).fit(h)
}

/// A duffel bag: a soft roll lying along x, flat ends, a flatter bottom, a dark zip along its
/// top and two handles arching over it.
pub(crate) fn duffel(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let fat = ctx.dice.between(0.75, 0.85);
    // Poles toward ±x: (d.x, d.y, d.z) → (x from d.z, y from d.x, z from d.y), a turn.
    let roll = sphere_grid(b, 2 * b, |d| {
        let up = if d.y >= 0.0 { 0.7 } else { 0.35 };
        Vector::new(
            signed_pow(d.z, 0.25),
            fat * signed_pow(d.x, 0.7),
            0.42 + 0.42 * signed_pow(d.y, up),
        )
    });
    let mut pieces = vec![
        roll,
        rounded_box(
            Vector::new(0.0, 0.0, 0.84),
            Vector::new(0.7, 0.02, 0.012),
            0.008,
            1,
            Tone::Dark,
        ),
    ];
    for y in [-0.2f32, 0.2] {
        let handle = arc([-0.32, y, 0.8], [0.32, y, 0.8], 0.17, b / 2);
        pieces.push(strap(&handle, 0.03, ctx.detail, Tone::Dark));
    }
    join(pieces).fit(ctx.half)
}

/// A briefcase lying flat: a case with rounded edges (its lid is a part of its own, on top), a
/// dark handle at its front (−y) and two metal latches either side of it.
pub(crate) fn briefcase(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let steps = ctx.detail.bands() / 2;
    let handle: Vec<[f32; 3]> = (0..=steps)
        .map(|k| {
            let a = PI * k as f32 / steps as f32;
            [-0.22 * a.cos(), -0.86 - 0.1 * a.sin(), 0.55]
        })
        .collect();
    let mut pieces = vec![
        rounded_box(
            Vector::new(0.0, 0.07, 0.5),
            Vector::new(1.0, 0.93, 0.5),
            0.12,
            rows,
            Tone::Body,
        ),
        strap(&handle, 0.06, ctx.detail, Tone::Dark),
    ];
    for side in [-1.0f32, 1.0] {
        pieces.push(rounded_box(
            Vector::new(side * 0.55, -0.86, 0.75),
            Vector::new(0.07, 0.02, 0.12),
            0.01,
            1,
            Tone::Metal,
        ));
    }
    join(pieces).fit(ctx.half)
}

/// A pencil case lying along x: a soft box with a dark zip along its top and a metal pull.
pub(crate) fn pencil_case(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let pull = ctx.dice.between(0.5, 0.8);
    join([
        rounded_box(
            Vector::new(0.0, 0.0, 0.47),
            Vector::new(1.0, 1.0, 0.47),
            0.35,
            rows,
            Tone::Body,
        ),
        rounded_box(
            Vector::new(0.0, 0.0, 0.93),
            Vector::new(0.85, 0.06, 0.03),
            0.01,
            1,
            Tone::Dark,
        ),
        rounded_box(
            Vector::new(pull, 0.0, 0.97),
            Vector::new(0.08, 0.1, 0.03),
            0.01,
            1,
            Tone::Metal,
        ),
    ])
    .fit(ctx.half)
}
