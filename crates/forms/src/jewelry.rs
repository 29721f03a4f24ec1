//! Jewellery lying flat and a lipstick standing: a bangle, a ring with a stone, a necklace of
//! beads with a pendant, a lipstick in its case. Built in a frame of their own and stretched to
//! fill their box.

use crate::grid::ball;
use crate::lathe::{fold, p, revolve, torus};
use crate::mesh::{Mesh, join};
use crate::tone::Tone;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::TAU;

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
        fold(1.0, 0.0),
        fold(1.0, case),
        fold(0.92, case).tone(Tone::Metal),
        fold(0.92, case + 0.07),
        fold(0.7, case + 0.07).tone(Tone::Body),
        p(0.7, 0.86),
        p(0.5, 0.96),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), |_| 1.0).fit(ctx.half)
}
