//! Jewellery lying flat and a lipstick standing: a bangle, a ring with a stone, a necklace of
//! beads with a pendant, a lipstick in its case. Built in a frame of their own and stretched to
//! fill their box. Also the shared small pieces: a ring about z ([`torus`]) and a ball.

use crate::grid::sphere_grid;
use crate::lathe::{Pt, p, revolve};
use crate::mesh::{Mesh, join};
use crate::tone::Tone;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::TAU;

/// A ring about z: its tube's centre `radius` from the axis, the tube `thick` in radius.
pub(crate) fn torus(radius: f32, thick: f32, detail: Detail) -> Mesh {
    let points = detail.around() / 2;
    // Counter-clockwise in (r, z): out along the bottom, up the outside, in over the top.
    let profile: Vec<Pt> = (0..points)
        .map(|k| {
            let a = TAU * k as f32 / points as f32 - 0.5 * TAU / 2.0;
            p(radius + thick * a.cos(), thick * a.sin())
        })
        .collect();
    revolve(&profile, 2 * detail.around(), |_| 1.0)
}

/// A ball of radius `radius` at `at`.
pub(crate) fn ball(at: Vector, radius: f32, detail: Detail, tone: Tone) -> Mesh {
    let b = (detail.bands() / 2).max(3);
    sphere_grid(b, 2 * b, |d| at + d * radius).toned(tone)
}

/// A bangle: a ring of rounded section, flatter or rounder by the seed.
pub(crate) fn bangle(ctx: Ctx) -> Mesh {
    let thick = ctx.dice.between(0.1, 0.16);
    torus(1.0 - thick, thick, ctx.detail).fit(ctx.half)
}

/// A finger ring lying flat, a pale stone set on its band toward +x.
pub(crate) fn ring(ctx: Ctx) -> Mesh {
    let stone = ctx.dice.between(0.14, 0.2);
    join([
        torus(0.62, 0.12, ctx.detail),
        ball(Vector::new(0.86, 0.0, 0.0), stone, ctx.detail, Tone::Light),
    ])
    .fit(ctx.half)
}

/// A necklace lying flat: beads around an oval, a pale pendant at its bottom (−y).
pub(crate) fn necklace(ctx: Ctx) -> Mesh {
    let beads = match ctx.detail {
        Detail::Fine => ctx.dice.count(22, 30),
        Detail::Coarse => 12,
    };
    let size = 0.9 * TAU / beads as f32;
    let mut pieces: Vec<Mesh> = (0..beads)
        .map(|k| {
            let a = TAU * k as f32 / beads as f32;
            let at = Vector::new(0.8 * a.cos(), 0.7 * a.sin() + 0.1, 0.0);
            ball(at, 0.5 * size, ctx.detail, Tone::Body)
        })
        .collect();
    pieces.push(ball(
        Vector::new(0.0, -0.72, 0.0),
        0.18,
        ctx.detail,
        Tone::Light,
    ));
    join(pieces).fit(ctx.half)
}

/// A lipstick standing: a dark case, a metal ring, and the stick in the object's colour with
/// a rounded tip.
pub(crate) fn lipstick(ctx: Ctx) -> Mesh {
    let case = ctx.dice.between(0.5, 0.6);
    let profile = [
        p(0.0, 0.0).tone(Tone::Dark),
        crate::lathe::fold(1.0, 0.0),
        crate::lathe::fold(1.0, case),
        crate::lathe::fold(0.92, case).tone(Tone::Metal),
        crate::lathe::fold(0.92, case + 0.07),
        crate::lathe::fold(0.7, case + 0.07).tone(Tone::Body),
        p(0.7, 0.86),
        p(0.5, 0.96),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), |_| 1.0).fit(ctx.half)
}
