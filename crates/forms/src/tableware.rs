//! Round things to drink from, eat from and cook in: bottles, cans, cups, mugs, bowls, plates,
//! pots, buckets, cakes, jars and their lids, baking dishes, kettles, hamburgers and sushi
//! rolls, turned from profiles (`lathe.rs`) with handles swept as tubes.
//! Profiles are in units of the box (radius 1 at its widest, height 0 to 1) unless a handle needs
//! room beside the body, when the form is built at its true size.

use crate::lathe::{Pt, even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::rounded_box;
use crate::tone::Tone;
use crate::tube::tube;
use crate::{Ctx, Detail};
use rapier3d::math::Vector;
use std::f32::consts::{FRAC_PI_2, PI};

/// A profile turned and stretched to fill the box.
fn turned(profile: &[Pt], ctx: &Ctx) -> Mesh {
    revolve(profile, ctx.detail.around(), even).fit(ctx.half)
}

/// Body, shoulder, neck and a cap in a tone of its own.
pub(crate) fn bottle(ctx: Ctx) -> Mesh {
    let shoulder = ctx.dice.between(0.45, 0.58);
    let neck = ctx.dice.between(0.24, 0.38);
    let cap = [Tone::Dark, Tone::Metal, Tone::Light][ctx.dice.count(0, 2)];
    let top = [fold(neck + 0.05, 0.9), fold(neck + 0.05, 1.0), p(0.0, 1.0)].map(|pt| pt.tone(cap));
    let mut profile = vec![
        p(0.0, 0.015),
        p(0.88, 0.0),
        p(0.98, 0.025),
        p(1.0, 0.07),
        p(1.0, shoulder),
        p(0.94, shoulder + 0.08),
        p(0.72, shoulder + 0.16),
        p(neck + 0.06, shoulder + 0.23),
        p(neck, shoulder + 0.27),
        fold(neck, 0.9),
    ];
    profile.extend(top);
    turned(&profile, &ctx)
}

/// A tin with rolled metal rims and a recessed lid.
pub(crate) fn can(ctx: Ctx) -> Mesh {
    let bottom = [p(0.0, 0.015), fold(0.9, 0.0), fold(0.97, 0.03)].map(|pt| pt.tone(Tone::Metal));
    let top = [
        fold(1.0, 0.94),
        fold(0.97, 1.0),
        fold(0.9, 0.985),
        p(0.0, 0.985),
    ]
    .map(|pt| pt.tone(Tone::Metal));
    let mut profile = bottom.to_vec();
    profile.push(fold(1.0, 0.06));
    profile.extend(top);
    turned(&profile, &ctx)
}

/// A cup's profile: foot radius `base`, wall `wall` thick, floor at `floor`, rim at r = 1.
fn cup_profile(base: f32, wall: f32, floor: f32) -> Vec<Pt> {
    vec![
        p(0.0, 0.0),
        fold(base, 0.0),
        p(base + 0.5 * (1.0 - base) * 0.08, 0.04),
        fold(1.0, 1.0),
        fold(1.0 - wall, 1.0),
        p(base - wall, floor + 0.03),
        p(base - wall - 0.05, floor),
        p(0.0, floor),
    ]
}

/// A cup or drinking glass, tapering to its foot, open at the top.
pub(crate) fn cup(ctx: Ctx) -> Mesh {
    let base = ctx.dice.between(0.68, 0.86);
    turned(&cup_profile(base, 0.08, 0.08), &ctx)
}

/// A loop handle from the body's side at `x0` out to `x1` (x), between heights `z0` and `z1`, in
/// the plane `y = 0`: a half ellipse drawn on a little past its ends, so that they sink into the
/// body. The tube is a fifth of the room as thick, and the ellipse no more than 2.5 times as long
/// as it is wide, so that it bends everywhere more gently than the tube is thick.
fn side_loop(x0: f32, x1: f32, (z0, z1): (f32, f32), ctx: &Ctx) -> Mesh {
    let (room, height) = (x1 - x0, 0.5 * (z1 - z0));
    let thick = 0.2 * room.min(height);
    let mid = 0.5 * (z0 + z1);
    let rise = (height - thick).min(2.5 * (room - thick));
    let reach = (room - thick).min(2.5 * rise);
    let steps = (ctx.detail.around() / 2).max(8);
    let past = 0.35;
    let path: Vec<Vector> = (0..=steps)
        .map(|k| {
            let a = FRAC_PI_2 + past - (PI + 2.0 * past) * k as f32 / steps as f32;
            Vector::new(x0 + reach * a.cos(), 0.0, mid + rise * a.sin())
        })
        .collect();
    tube(
        &path,
        (ctx.detail.around() / 3).max(4),
        |_, _| thick,
        Tone::Body,
    )
}

/// A mug: a cup body against −x, its handle in the room left on +x.
pub(crate) fn mug(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let radius = h.y.min(0.78 * h.x);
    let centre = -h.x + radius;
    let mut body = revolve(
        &cup_profile(ctx.dice.between(0.88, 0.96), 0.1, 0.08),
        ctx.detail.around(),
        even,
    );
    body.stretch(
        Vector::new(radius, radius, 2.0 * h.z),
        Vector::new(centre, 0.0, -h.z),
    );
    let handle = side_loop(centre + radius, h.x, (-0.55 * h.z, 0.7 * h.z), &ctx);
    join([body, handle])
}

/// A bowl on a foot ring, its sides curving up to a thin rim.
pub(crate) fn bowl(ctx: Ctx) -> Mesh {
    let foot = ctx.dice.between(0.4, 0.55);
    let profile = [
        p(0.0, 0.03),
        fold(foot - 0.04, 0.03),
        fold(foot, 0.0),
        fold(foot + 0.08, 0.0),
        p(foot + 0.2, 0.12),
        p(0.8, 0.33),
        p(0.93, 0.6),
        p(0.99, 0.85),
        fold(1.0, 1.0),
        fold(0.95, 1.0),
        p(0.93, 0.85),
        p(0.87, 0.6),
        p(0.74, 0.36),
        p(0.5, 0.18),
        p(0.25, 0.11),
        p(0.0, 0.1),
    ];
    turned(&profile, &ctx)
}

/// A plate: a foot ring, a flat well and a rim rising to its edge.
pub(crate) fn plate(ctx: Ctx) -> Mesh {
    let well = ctx.dice.between(0.55, 0.7);
    let profile = [
        p(0.0, 0.1),
        fold(well - 0.1, 0.1),
        fold(well - 0.07, 0.0),
        fold(well, 0.0),
        p(well + 0.1, 0.22),
        p(0.95, 0.8),
        fold(1.0, 1.0),
        fold(0.96, 1.0),
        p(well + 0.08, 0.5),
        p(well, 0.45),
        p(0.0, 0.45),
    ];
    turned(&profile, &ctx)
}

/// A cooking pot with straight walls and a loop handle on each side.
pub(crate) fn pot(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let radius = h.y.min(0.82 * h.x);
    let mut body = revolve(&cup_profile(0.97, 0.05, 0.05), ctx.detail.around(), even);
    body.stretch(
        Vector::new(radius, radius, 2.0 * h.z),
        Vector::new(0.0, 0.0, -h.z),
    );
    let ear = |sign: f32| {
        let mut loop_ = side_loop(radius, h.x, (0.35 * h.z, 0.85 * h.z), &ctx);
        if sign < 0.0 {
            // Half a turn about z puts it on the other side and keeps its winding.
            loop_.turn_half();
        }
        loop_.toned(Tone::Dark)
    };
    join([body, ear(1.0), ear(-1.0)])
}

/// A bucket or bin: a tub narrowing to its base, with a rolled rim.
pub(crate) fn bucket(ctx: Ctx) -> Mesh {
    let base = ctx.dice.between(0.72, 0.88);
    let profile = [
        p(0.0, 0.0),
        fold(base, 0.0),
        p(0.96, 0.9),
        fold(0.97, 0.92),
        p(1.0, 0.96),
        fold(0.98, 1.0),
        fold(0.93, 1.0),
        p(base - 0.05, 0.06),
        p(0.0, 0.06),
    ];
    turned(&profile, &ctx)
}

/// A cake or round dish: soft-edged, with a pale top.
pub(crate) fn cake(ctx: Ctx) -> Mesh {
    let profile = [
        p(0.0, 0.0),
        fold(0.96, 0.0),
        p(1.0, 0.04),
        p(1.0, 0.82).tone(Tone::Light),
        p(0.97, 0.96).tone(Tone::Light),
        p(0.88, 1.0).tone(Tone::Light),
        p(0.0, 1.0).tone(Tone::Light),
    ];
    turned(&profile, &ctx)
}

/// A glass jar: a flat base, straight sides, a rounded shoulder and a short neck with a thread
/// (its lid is a part of its own, drawn as a [`lid`]).
pub(crate) fn jar(ctx: Ctx) -> Mesh {
    let shoulder = ctx.dice.between(0.68, 0.8);
    let neck = ctx.dice.between(0.72, 0.82);
    let profile = [
        p(0.0, 0.0),
        fold(0.92, 0.0),
        p(0.99, 0.03),
        p(1.0, 0.08),
        p(1.0, shoulder),
        p(0.96, shoulder + 0.08),
        p(neck + 0.04, shoulder + 0.14),
        fold(neck, shoulder + 0.16),
        fold(neck, 0.9),
        fold(neck + 0.03, 0.92),
        fold(neck + 0.03, 0.96),
        fold(neck, 0.97),
        fold(neck, 1.0),
        p(0.0, 1.0),
    ];
    turned(&profile, &ctx)
}

/// A jar's screw lid: a metal cap a little narrower than the jar's box, its edge knurled.
pub(crate) fn lid(ctx: Ctx) -> Mesh {
    let metal = |pt: Pt| pt.tone(Tone::Metal);
    let profile = [
        p(0.0, 0.0),
        fold(0.84, 0.0),
        fold(0.86, 0.1),
        fold(0.86, 0.8),
        p(0.83, 0.98),
        p(0.0, 1.0),
    ]
    .map(metal);
    let ridges = match ctx.detail {
        Detail::Fine => 0.012,
        Detail::Coarse => 0.0,
    };
    let knurl = move |phi: f32| 1.0 + ridges * (48.0 * phi).cos();
    let around = 2 * ctx.detail.around();
    let mut made = revolve(&profile, around, knurl);
    // The box's own proportions; the knurl's 1 % swell stays inside it.
    let h = ctx.half;
    made.stretch(
        Vector::new(h.x / 1.02, h.y / 1.02, 2.0 * h.z),
        Vector::new(0.0, 0.0, -h.z),
    );
    made
}

/// A baking dish with food in it: a pale dish with a rolled rim and a lug at each end (±x),
/// the food (in the object's colour, which cooking browns) filling it and domed a little.
pub(crate) fn casserole(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let lug = ctx.dice.between(0.07, 0.1);
    let dish_half = Vector::new(1.0 - lug, 0.5, 0.36);
    let dish = rounded_box(
        Vector::new(0.0, 0.0, 0.36),
        dish_half,
        0.12,
        rows,
        Tone::Light,
    );
    let food = rounded_box(
        Vector::new(0.0, 0.0, 0.74),
        Vector::new(dish_half.x - 0.05, 0.45, 0.26),
        0.12,
        rows,
        Tone::Body,
    );
    let lugs = [1.0f32, -1.0].map(|side| {
        rounded_box(
            Vector::new(side * (1.0 - lug), 0.0, 0.6),
            Vector::new(lug, 0.3, 0.05),
            0.03,
            rows,
            Tone::Light,
        )
    });
    let [a, b] = lugs;
    join([dish, food, a, b]).fit(ctx.half)
}

/// A hamburger: a bun in the object's colour (which cooking browns) around a dark patty and a
/// leaf of lettuce, its top domed.
pub(crate) fn burger(ctx: Ctx) -> Mesh {
    let patty = ctx.dice.between(0.14, 0.2);
    let bun = 0.25;
    let profile = [
        p(0.0, 0.0),
        fold(0.9, 0.0),
        p(0.97, 0.08),
        fold(0.96, bun),
        fold(1.0, bun + 0.01).tone(Tone::Stem),
        fold(1.0, bun + patty),
        fold(0.99, bun + patty + 0.01).tone(Tone::Leaf),
        fold(1.0, bun + patty + 0.05),
        fold(0.95, bun + patty + 0.07).tone(Tone::Body),
        p(0.98, bun + patty + 0.15),
        p(0.9, 0.84),
        p(0.6, 0.97),
        p(0.0, 1.0),
    ];
    turned(&profile, &ctx)
}

/// A sushi roll: dark seaweed around its side, pale rice on its top and bottom, the filling in
/// the object's colour at the centre of its top.
pub(crate) fn maki(ctx: Ctx) -> Mesh {
    let filling = ctx.dice.between(0.3, 0.45);
    let profile = [
        p(0.0, 0.0).tone(Tone::Light),
        fold(0.92, 0.0),
        fold(1.0, 0.04).tone(Tone::Dark),
        fold(1.0, 0.96),
        fold(0.92, 1.0).tone(Tone::Light),
        fold(filling, 1.0).tone(Tone::Body),
        p(0.0, 1.0),
    ];
    turned(&profile, &ctx)
}

/// A kettle: a body narrowing to a lid with a dark knob, a spout rising toward +x and a dark
/// handle arching over the lid along x.
pub(crate) fn kettle(ctx: Ctx) -> Mesh {
    let waist = ctx.dice.between(0.5, 0.62);
    let body = [
        p(0.0, 0.0),
        fold(0.68, 0.0),
        p(0.72, 0.05),
        p(0.7, 0.35),
        p(waist, 0.55),
        p(0.45, 0.64),
        fold(0.36, 0.68),
        fold(0.12, 0.7).tone(Tone::Dark),
        p(0.1, 0.76),
        p(0.0, 0.78),
    ];
    let sides = (ctx.detail.around() / 2).max(6);
    let spout = [
        Vector::new(0.5, 0.0, 0.2),
        Vector::new(0.8, 0.0, 0.42),
        Vector::new(0.95, 0.0, 0.6),
    ];
    let steps = ctx.detail.bands() / 2;
    let handle: Vec<Vector> = (0..=steps)
        .map(|k| {
            let a = PI * k as f32 / steps as f32;
            Vector::new(-0.07 + 0.38 * a.cos(), 0.0, 0.58 + 0.36 * a.sin())
        })
        .collect();
    join([
        revolve(&body, ctx.detail.around(), even),
        tube(&spout, sides, |i, _| 0.09 - 0.02 * i as f32, Tone::Body),
        tube(&handle, sides, |_, _| 0.05, Tone::Dark),
    ])
    .fit(ctx.half)
}
