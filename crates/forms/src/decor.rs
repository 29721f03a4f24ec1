//! Things that make a home: a framed picture, a wreath, a teddy bear, a bow, a spool of ribbon,
//! a Christmas stocking, a candle. The picture is built at its true size (its frame as wide on
//! every side); the others in a frame of their own and stretched to fill their box.

use crate::extrude::prism;
use crate::grid::{ball, sphere_grid};
use crate::lathe::{Pt, even, fold, p, revolve, torus};
use crate::mesh::{Mesh, join};
use crate::rounded::{block, boxed, plain_box};
use crate::tone::Tone;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::{PI, TAU};

/// A framed picture lying flat: a moulded frame (wood or black by the seed) around a canvas of
/// the object's colour, on which two green hills and a pale sun are painted in relief.
pub(crate) fn painting(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let f = 0.12 * h.x.min(h.y);
    let wood = if ctx.dice.between(0.0, 1.0) < 0.6 {
        Tone::Stem
    } else {
        Tone::Dark
    };
    let bar = |centre: [f32; 3], half: [f32; 3]| {
        block(
            Vector::from_array(centre),
            Vector::from_array(half),
            0.4 * f,
            ctx.detail.bevel_rows(),
            ctx.detail,
            wood,
        )
    };
    let inner = Vector::new(h.x - f, h.y - f, h.z);
    let mut pieces = vec![
        bar([0.0, inner.y + 0.5 * f, 0.0], [h.x, 0.5 * f, h.z]),
        bar([0.0, -inner.y - 0.5 * f, 0.0], [h.x, 0.5 * f, h.z]),
        // The sides reach into the top and bottom bars: faces shared would be open seams.
        bar(
            [inner.x + 0.5 * f, 0.0, 0.0],
            [0.5 * f, inner.y + 0.25 * f, h.z],
        ),
        bar(
            [-inner.x - 0.5 * f, 0.0, 0.0],
            [0.5 * f, inner.y + 0.25 * f, h.z],
        ),
        plain_box(
            Vector::new(0.0, 0.0, -0.2 * h.z),
            Vector::new(inner.x + 0.1 * f, inner.y + 0.1 * f, 0.6 * h.z),
            Tone::Body,
        ),
    ];
    let canvas = 0.4 * h.z;
    let points = ctx.detail.around() / 2;
    let hill = |from: f32, to: f32, tall: f32, raise: f32, tone: Tone| {
        let (mid, half_width) = (0.5 * (from + to), 0.5 * (to - from));
        let outline: Vec<(f32, f32)> = (0..=points)
            .map(|k| {
                let a = PI * k as f32 / points as f32;
                (
                    mid + half_width * a.cos(),
                    -inner.y - 0.1 * f + tall * a.sin(),
                )
            })
            .collect();
        prism(&outline, (canvas - 0.01 * h.z, canvas + raise * h.z), tone)
    };
    let top = ctx.dice.between(0.4, 0.6) * inner.y;
    pieces.push(hill(-0.98 * inner.x, 0.3 * inner.x, top, 0.1, Tone::Leaf));
    pieces.push(hill(
        -0.2 * inner.x,
        0.98 * inner.x,
        0.7 * top,
        0.2,
        Tone::Stalk,
    ));
    let sun_r = 0.14 * inner.x.min(inner.y);
    let sun: Vec<(f32, f32)> = (0..points)
        .map(|k| {
            let a = TAU * k as f32 / points as f32;
            (
                0.5 * inner.x + sun_r * a.cos(),
                0.5 * inner.y + sun_r * a.sin(),
            )
        })
        .collect();
    pieces.push(prism(
        &sun,
        (canvas - 0.01 * h.z, canvas + 0.1 * h.z),
        Tone::Light,
    ));
    join(pieces)
}

/// A wreath lying flat: a thick green ring in the object's colour, leafy clusters around it,
/// red-brown berries among them and a bow at its bottom (−y).
pub(crate) fn wreath(ctx: Ctx) -> Mesh {
    let clusters = match ctx.detail {
        Detail::Fine => ctx.dice.count(12, 16),
        Detail::Coarse => 8,
    };
    let mut pieces = vec![torus(0.72, 0.2, ctx.detail)];
    for k in 0..clusters {
        let a = TAU * (k as f32 + 0.5) / clusters as f32;
        let r = if k % 2 == 0 { 0.62 } else { 0.82 };
        let at = Vector::new(r * a.cos(), r * a.sin(), 0.06);
        let leaf = sphere_grid((ctx.detail.bands() / 2).max(3), ctx.detail.bands(), |d| {
            at + Vector::new(0.17 * d.x, 0.17 * d.y, 0.12 * d.z)
        });
        pieces.push(leaf.toned(Tone::Leaf));
        if ctx.detail == Detail::Fine && k % 3 == 1 {
            let berry = Vector::new(0.72 * a.cos(), 0.72 * a.sin(), 0.2);
            pieces.push(ball(berry, 0.06, ctx.detail, Tone::Clay));
        }
    }
    // The bow: two loops either side of a knot, pointing out and down.
    for side in [-1.0f32, 1.0] {
        let loop_ = [
            (side * 0.02, -0.82),
            (side * 0.3, -0.98),
            (side * 0.32, -0.7),
        ];
        pieces.push(prism(&loop_, (0.1, 0.22), Tone::Clay));
    }
    pieces.push(ball(
        Vector::new(0.0, -0.82, 0.18),
        0.07,
        ctx.detail,
        Tone::Clay,
    ));
    join(pieces).fit(ctx.half)
}

/// An ellipsoid of half axes `radii` at `centre`, in `tone`.
fn blob(centre: [f32; 3], radii: [f32; 3], bands: usize, tone: Tone) -> Mesh {
    let (c, r) = (Vector::from_array(centre), Vector::from_array(radii));
    sphere_grid(bands, 2 * bands, |d| c + d * r).toned(tone)
}

/// A teddy bear sitting, facing −y: a round body and head, ears, a pale muzzle with a dark
/// nose, dark eyes, arms at its sides and legs stretched out in front.
pub(crate) fn teddy(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let small = (b / 2).max(3);
    let tilt = ctx.dice.between(-0.04, 0.04);
    let body = Tone::Body;
    let mut pieces = vec![
        blob([0.0, 0.05, 0.3], [0.42, 0.36, 0.32], b, body),
        blob([tilt, -0.02, 0.75], [0.3, 0.27, 0.26], b, body),
    ];
    for side in [-1.0f32, 1.0] {
        pieces.push(blob(
            [side * 0.24 + tilt, 0.0, 0.97],
            [0.1, 0.05, 0.1],
            small,
            body,
        ));
        pieces.push(blob(
            [side * 0.4, -0.05, 0.38],
            [0.12, 0.12, 0.22],
            small,
            body,
        ));
        pieces.push(blob(
            [side * 0.22, -0.35, 0.12],
            [0.14, 0.24, 0.12],
            small,
            body,
        ));
        pieces.push(blob(
            [side * 0.11 + tilt, -0.25, 0.82],
            [0.035, 0.035, 0.035],
            small,
            Tone::Dark,
        ));
    }
    pieces.push(blob(
        [tilt, -0.27, 0.7],
        [0.13, 0.08, 0.1],
        small,
        Tone::Light,
    ));
    pieces.push(blob(
        [tilt, -0.35, 0.74],
        [0.04, 0.03, 0.03],
        small,
        Tone::Dark,
    ));
    join(pieces).fit(ctx.half)
}

/// A bow lying flat: two loops either side of a knot, two tails hanging toward −y.
pub(crate) fn bow(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let spread = ctx.dice.between(0.5, 0.65);
    let mut pieces = Vec::new();
    for side in [-1.0f32, 1.0] {
        let at = Vector::new(side * 0.48, 0.15, 0.0);
        // A loop: a lobe thinner toward the knot, lifted at its far end.
        pieces.push(sphere_grid((b / 2).max(3), b, move |d| {
            let out = (d.x * side).max(0.0);
            at + Vector::new(0.5 * d.x, 0.4 * d.y, 0.55 * d.z * (0.6 + 0.4 * out))
        }));
        let tail = [
            (side * 0.05, -0.05),
            (side * spread, -0.95),
            (side * (spread - 0.22), -1.0),
        ];
        pieces.push(prism(&tail, (-0.12, 0.12), Tone::Body));
    }
    pieces.push(ball(
        Vector::new(0.0, 0.1, 0.0),
        0.2,
        ctx.detail,
        Tone::Body,
    ));
    join(pieces).fit(ctx.half)
}

/// A spool of ribbon: the ribbon wound in the object's colour between two pale flanges, a
/// hole through the middle.
pub(crate) fn spool(ctx: Ctx) -> Mesh {
    let hole = ctx.dice.between(0.22, 0.3);
    let flange = |pt: Pt| pt.tone(Tone::Light);
    let profile = [
        flange(fold(hole, 0.0)),
        fold(1.0, 0.0),
        fold(1.0, 0.08),
        fold(0.9, 0.08).tone(Tone::Body),
        flange(fold(0.9, 0.92)),
        fold(1.0, 0.92),
        fold(1.0, 1.0),
        fold(hole, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even).fit(ctx.half)
}

/// A Christmas stocking hanging: a leg in the object's colour, its foot toward +x, under a
/// pale cuff.
pub(crate) fn stocking(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let toe = ctx.dice.between(0.85, 1.0);
    let part = |centre, half, radius, tone| boxed(centre, half, radius, rows, tone);
    join([
        part([-0.3, 0.0, 0.52], [0.42, 0.85, 0.36], 0.3, Tone::Body),
        part(
            [0.5 * (toe - 0.72), 0.0, 0.17],
            [0.5 * (toe + 0.72), 0.85, 0.17],
            0.16,
            Tone::Body,
        ),
        part([-0.3, 0.0, 0.88], [0.5, 1.0, 0.12], 0.1, Tone::Light),
    ])
    .fit(ctx.half)
}

/// A candle: a pillar in the object's colour, its top rim softened and dipped toward a dark wick
/// that stands out of its middle.
pub(crate) fn candle(ctx: Ctx) -> Mesh {
    let wick = ctx.dice.between(0.06, 0.09);
    let profile = [
        p(0.0, 0.0),
        fold(1.0, 0.0),
        p(1.0, 1.0 - wick - 0.06),
        p(0.94, 1.0 - wick - 0.01),
        p(0.7, 1.0 - wick - 0.02),
        fold(0.1, 1.0 - wick - 0.035),
        fold(0.06, 1.0 - wick - 0.035).tone(Tone::Dark),
        p(0.05, 0.99),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even).fit(ctx.half)
}
