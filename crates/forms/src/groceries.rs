//! Food as it is bought and served: gable-top cartons, jugs, crimped bags of crisps, paper
//! sacks of flour, steaks, wrapped sweets, sandwiches, salads in a bowl, cookies. Each is built
//! in a frame of its own (x and y from −1 to 1, z from 0 to 1 unless it says otherwise) and
//! stretched to fill its box.

use crate::extrude::{prism, prism_across_y};
use crate::grid::{ball, signed_pow, sphere_grid};
use crate::lathe::{cylinder, even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::{plain_box, rounded_box};
use crate::tone::Tone;
use crate::tube::tube;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::{PI, TAU};

/// A box of the frame: `centre` and `half` as arrays.
fn slab(centre: [f32; 3], half: [f32; 3], tone: Tone) -> Mesh {
    plain_box(Vector::from_array(centre), Vector::from_array(half), tone)
}

/// A gable-top carton (milk, juice): a box, a roof of two slopes meeting at a sealed fin along
/// y, and a pale cap on the front slope.
pub(crate) fn carton(ctx: Ctx) -> Mesh {
    let eaves = ctx.dice.between(0.74, 0.8);
    let roof = [(-1.0, eaves), (1.0, eaves), (0.0, 0.94)];
    let mut cap = cylinder(ctx.detail.around() / 2);
    let cap_at = Vector::new(0.5, -0.35, eaves + 0.03);
    cap.stretch(Vector::new(0.2, 0.2, 0.1), cap_at);
    // The box reaches a little into the roof: faces shared would be open seams.
    let mut pieces = vec![
        slab(
            [0.0, 0.0, 0.5 * eaves + 0.01],
            [1.0, 1.0, 0.5 * eaves + 0.01],
            Tone::Body,
        ),
        prism_across_y(&roof, (-1.0, 1.0), Tone::Body),
    ];
    if ctx.detail == Detail::Fine {
        pieces.push(slab([0.0, 0.0, 0.96], [0.05, 0.98, 0.04], Tone::Body));
        pieces.push(cap.toned(Tone::Light));
    }
    join(pieces).fit(ctx.half)
}

/// A jug (detergent): a rounded body, a handle over the back of its top and a dark cap at the
/// front.
pub(crate) fn jug(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let steps = ctx.detail.bands() / 2;
    let grip: Vec<Vector> = (0..=steps)
        .map(|k| {
            let a = PI * k as f32 / steps as f32;
            Vector::new(0.55 + 0.32 * a.cos(), 0.0, 0.78 + 0.14 * a.sin())
        })
        .collect();
    let mut cap = cylinder(ctx.detail.around() / 2);
    cap.stretch(Vector::new(0.28, 0.28, 0.16), Vector::new(-0.5, 0.0, 0.82));
    join([
        rounded_box(
            Vector::new(0.0, 0.0, 0.42),
            Vector::new(1.0, 1.0, 0.42),
            0.25,
            rows,
            Tone::Body,
        ),
        tube(
            &grip,
            (ctx.detail.around() / 3).max(6),
            |_, _| 0.08,
            Tone::Body,
        ),
        cap.toned(Tone::Dark),
    ])
    .fit(ctx.half)
}

/// A bag of crisps or snacks standing: a puffed pillow, thickest at its middle (y), crimped
/// flat at its top and bottom.
pub(crate) fn pouch(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let puff = ctx.dice.between(0.8, 1.0);
    let pillow = sphere_grid(b, 2 * b, |d| {
        Vector::new(
            0.97 * signed_pow(d.x, 0.35),
            puff * d.y,
            0.5 + 0.41 * signed_pow(d.z, 0.35),
        )
    });
    join([
        pillow,
        slab([0.0, 0.0, 0.95], [1.0, 0.05, 0.05], Tone::Body),
        slab([0.0, 0.0, 0.05], [1.0, 0.05, 0.05], Tone::Body),
    ])
    .fit(ctx.half)
}

/// A paper sack (flour, sugar): a box with soft edges, its top rolled down across x.
pub(crate) fn sack(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let roll = [Vector::new(-0.96, 0.0, 0.86), Vector::new(0.96, 0.0, 0.86)];
    let radius = ctx.dice.between(0.1, 0.14);
    join([
        rounded_box(
            Vector::new(0.0, 0.0, 0.43),
            Vector::new(1.0, 0.9, 0.43),
            0.12,
            rows,
            Tone::Body,
        ),
        tube(
            &roll,
            (ctx.detail.around() / 2).max(8),
            |_, _| radius,
            Tone::Body,
        ),
    ])
    .fit(ctx.half)
}

/// A steak lying flat (beef, meat, pork): a thick slab with a lumpy outline and a pale rim of
/// fat along one side (−y).
pub(crate) fn steak(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let phase = ctx.dice.between(0.0, TAU);
    let meat = sphere_grid(b, 2 * b, |d| {
        let phi = d.y.atan2(d.x);
        let r = 1.0 + 0.07 * (3.0 * phi + phase).sin() + 0.04 * (5.0 * phi).cos();
        Vector::new(
            r * signed_pow(d.x, 0.8),
            0.8 * r * signed_pow(d.y, 0.8),
            0.5 * signed_pow(d.z, 0.5),
        )
    });
    let fat = sphere_grid((b / 2).max(3), b, |d| {
        Vector::new(0.7 * d.x, -0.5 + 0.36 * d.y, 0.47 * signed_pow(d.z, 0.6))
    });
    join([meat, fat.toned(Tone::Light)]).fit(ctx.half)
}

/// A wrapped sweet lying along x: a round middle and the wrapper twisted at both ends into
/// fans.
pub(crate) fn sweet(ctx: Ctx) -> Mesh {
    let fan = ctx.dice.between(0.6, 0.8);
    let profile = [
        p(0.0, 0.0),
        fold(fan, 0.0),
        p(0.15, 0.2),
        p(0.6, 0.28),
        p(1.0, 0.5),
        p(0.6, 0.72),
        p(0.15, 0.8),
        fold(fan, 1.0),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even)
        .lay_along_x()
        .fit(ctx.half)
}

/// A sandwich cut corner to corner, lying flat: two slices of bread in the object's colour
/// with lettuce and a slice of tomato between (the bread alone at the coarse level).
pub(crate) fn sandwich(ctx: Ctx) -> Mesh {
    let half = [(-1.0f32, -1.0f32), (1.0, -1.0), (-1.0, 1.0)];
    // The filling a little wider than the bread, so that it shows at the sides.
    let grown = |by: f32| half.map(|(x, y)| (by * x, by * y));
    let filling = ctx.dice.between(0.12, 0.2);
    let top = 0.4 + filling;
    let mut pieces = vec![
        prism(&half, (0.0, 0.4), Tone::Body),
        prism(&half, (top, 1.0), Tone::Body),
    ];
    if ctx.detail == Detail::Fine {
        pieces.push(prism(&grown(1.05), (0.39, 0.4 + 0.5 * filling), Tone::Leaf));
        pieces.push(prism(
            &grown(1.025),
            (0.38 + 0.5 * filling, top + 0.01),
            Tone::Clay,
        ));
    }
    join(pieces).fit(ctx.half)
}

/// A salad: a pale bowl heaped with leaves in the object's colour.
pub(crate) fn salad(ctx: Ctx) -> Mesh {
    let bowl = [
        p(0.0, 0.0),
        fold(0.45, 0.0),
        p(0.5, 0.08),
        p(0.85, 0.45),
        fold(1.0, 0.68),
        fold(0.95, 0.7),
        p(0.0, 0.7),
    ]
    .map(|pt| pt.tone(Tone::Light));
    let mut pieces = vec![revolve(&bowl, ctx.detail.around(), even)];
    let leaves = match ctx.detail {
        Detail::Fine => ctx.dice.count(7, 10),
        Detail::Coarse => 4,
    };
    let bands = (ctx.detail.bands() / 2).max(3);
    let spin = ctx.dice.between(0.0, TAU);
    for k in 0..leaves {
        let a = spin + TAU * k as f32 / leaves as f32;
        let r = if k % 2 == 0 { 0.55 } else { 0.25 };
        let at = Vector::new(r * a.cos(), r * a.sin(), 0.72);
        let lump = ctx.dice.between(0.1, 0.2);
        pieces.push(sphere_grid(bands, 2 * bands, |d| {
            let bumpy = 1.0 + lump * (5.0 * d.x).sin() * (6.0 * d.y).cos();
            at + Vector::new(0.38 * d.x, 0.38 * d.y, 0.26 * d.z) * bumpy
        }));
    }
    join(pieces).fit(ctx.half)
}

/// A cookie: a flat round with a soft edge, dark chips pressed into its top.
pub(crate) fn cookie(ctx: Ctx) -> Mesh {
    let profile = [
        p(0.0, 0.0),
        fold(0.95, 0.0),
        p(1.0, 0.3),
        p(0.97, 0.75),
        p(0.85, 0.95),
        p(0.0, 1.0),
    ];
    let mut pieces = vec![revolve(&profile, ctx.detail.around(), even)];
    let chips = match ctx.detail {
        Detail::Fine => ctx.dice.count(5, 8),
        Detail::Coarse => 0,
    };
    for _ in 0..chips {
        let (a, r) = (ctx.dice.between(0.0, TAU), ctx.dice.between(0.1, 0.7));
        let at = Vector::new(r * a.cos(), r * a.sin(), 0.93);
        pieces.push(ball(at, 0.1, ctx.detail, Tone::Dark));
    }
    join(pieces).fit(ctx.half)
}
