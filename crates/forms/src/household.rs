//! Made things about the house: rounded boards and cushions, turned legs, books, folded cloth,
//! pens, table lamps, potted plants and a Christmas tree, shoes and hats, a coat hanger (its
//! wire at its true size), a squeezed tube, a mousetrap.

use crate::extrude::prism;
use crate::grid::{signed_pow, sphere_grid};
use crate::lathe::{even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::rounded_box;
use crate::tone::Tone;
use crate::tube::{fillet, tube};
use crate::{Ctx, Detail, bevel};
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI, TAU};

/// A box with rounded edges ([`bevel`]).
pub(crate) fn rounded(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    rounded_box(
        Vector::ZERO,
        h,
        bevel(h),
        ctx.detail.bevel_rows(),
        Tone::Body,
    )
}

/// A box rounded like a cushion: its edges round over most of its thinnest side.
pub(crate) fn soft(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let radius = (0.8 * h.min_element()).min(0.4 * h.max_element());
    rounded_box(
        Vector::ZERO,
        h,
        radius,
        ctx.detail.bevel_rows() + 1,
        Tone::Body,
    )
}

/// A turned post: a foot, a taper, a bead and a collar under a square-ish top.
pub(crate) fn turned(ctx: Ctx) -> Mesh {
    let bead = ctx.dice.between(0.55, 0.75);
    let profile = [
        p(0.0, 0.0),
        fold(0.62, 0.0),
        p(0.7, 0.04),
        p(0.6, 0.1),
        p(0.5, bead - 0.2),
        p(0.78, bead),
        p(0.55, bead + 0.05),
        p(0.7, 0.86),
        fold(0.72, 0.88),
        fold(1.0, 0.9),
        fold(1.0, 1.0),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even).fit(ctx.half)
}

/// A book lying flat: two boards and a spine (on −x) around a block of pages.
pub(crate) fn book(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let board = (0.15 * h.z).clamp(0.0008, 0.003).min(0.3 * h.z);
    let rows = ctx.detail.bevel_rows();
    let edge = |half: Vector| 0.45 * half.min_element();
    let cover = |z: f32| {
        let half = Vector::new(h.x, h.y, board);
        rounded_box(Vector::new(0.0, 0.0, z), half, edge(half), rows, Tone::Body)
    };
    // A hair short of the covers' width, so that no corner of the two coincides.
    let spine_half = Vector::new(board, 0.995 * h.y, h.z);
    let spine = rounded_box(
        Vector::new(-h.x + board, 0.0, 0.0),
        spine_half,
        edge(spine_half),
        rows,
        Tone::Body,
    );
    let inset = ctx.dice.between(0.02, 0.05) * h.y.min(h.x);
    let pages_half = Vector::new(h.x - board - 0.5 * inset, h.y - inset, h.z - 1.5 * board);
    let pages = rounded_box(
        Vector::new(board - 0.5 * inset, 0.0, 0.0),
        pages_half,
        0.1 * pages_half.min_element(),
        1,
        Tone::Paper,
    );
    join([cover(-h.z + board), cover(h.z - board), spine, pages])
}

/// Folded cloth: two to four soft layers, each a little smaller and off-centre.
pub(crate) fn folded(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let layers = ctx.dice.count(2, 4);
    let thick = h.z / layers as f32;
    let rows = ctx.detail.bevel_rows() + 1;
    let pieces: Vec<Mesh> = (0..layers)
        .map(|k| {
            let shrink = 1.0 - 0.04 * k as f32;
            let half = Vector::new(h.x * shrink, h.y * (1.0 - 0.03 * k as f32), thick);
            let room = h.truncate() - half.truncate();
            let shift = Vector::new(
                ctx.dice.between(-1.0, 1.0) * room.x,
                ctx.dice.between(-1.0, 1.0) * room.y,
                -h.z + thick * (2 * k + 1) as f32,
            );
            rounded_box(shift, half, 0.9 * thick, rows, Tone::Body)
        })
        .collect();
    join(pieces)
}

/// A pen, pencil or marker lying along x: a dark tip, a barrel, a capped end.
pub(crate) fn pen(ctx: Ctx) -> Mesh {
    let tip = ctx.dice.between(0.08, 0.16);
    let profile = [
        p(0.0, 0.0).tone(Tone::Dark),
        p(0.2, 0.01).tone(Tone::Dark),
        fold(0.45, tip * 0.5),
        fold(0.9, tip),
        p(1.0, tip + 0.02),
        fold(1.0, 0.93),
        p(0.9, 0.98),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even)
        .lay_along_x()
        .fit(ctx.half)
}

/// A table lamp: a round base and a metal stem under a pale shade.
pub(crate) fn lamp(ctx: Ctx) -> Mesh {
    let flare = ctx.dice.between(0.0, 0.2);
    let stand = [
        p(0.0, 0.0),
        fold(0.75, 0.0),
        p(0.75, 0.04),
        fold(0.65, 0.08),
        fold(0.1, 0.1).tone(Tone::Metal),
        p(0.06, 0.14).tone(Tone::Metal),
        p(0.06, 0.66).tone(Tone::Metal),
        p(0.0, 0.66).tone(Tone::Metal),
    ];
    // The shade is a ring: a closed loop of the profile that never meets the axis.
    let shade = [
        fold(0.78 + flare, 0.5),
        fold(0.82 + flare, 0.5),
        fold(0.58, 1.0),
        fold(0.54, 1.0),
    ]
    .map(|pt| pt.tone(Tone::Light));
    let around = ctx.detail.around();
    join([revolve(&stand, around, even), revolve(&shade, around, even)]).fit(ctx.half)
}

/// A plant in a clay pot: a tapered pot filled with soil and a crown of leaves.
pub(crate) fn plant(ctx: Ctx) -> Mesh {
    let pot = [
        p(0.0, 0.0),
        fold(0.42, 0.0),
        p(0.5, 0.36),
        fold(0.52, 0.4),
        fold(0.47, 0.4).tone(Tone::Soil),
        p(0.0, 0.38).tone(Tone::Soil),
    ]
    .map(|pt| {
        if pt.tone == Tone::Body {
            pt.tone(Tone::Clay)
        } else {
            pt
        }
    });
    let mut pieces = vec![revolve(&pot, ctx.detail.around(), even)];
    if ctx.detail == Detail::Coarse {
        // A few pixels across, the leaves are one leafy crown.
        let crown = Vector::new(0.5, 0.5, 0.32);
        let mut bush = sphere_grid(4, 8, |d| d * crown);
        bush.turn(Rotation::IDENTITY, Vector::new(0.0, 0.0, 0.68));
        pieces.push(bush);
        return join(pieces).fit(ctx.half);
    }
    let leaves = ctx.dice.count(6, 10);
    let spin = ctx.dice.between(0.0, TAU);
    // An odd count of bands, so that no ring of vertices lies on a leaf's thin rim, where
    // smoothing would stand their normals square to both faces.
    let bands = (ctx.detail.bands() / 2) | 1;
    for k in 0..leaves {
        let heading = spin + TAU * k as f32 / leaves as f32;
        let tilt = ctx.dice.between(0.35, 1.1);
        let length = ctx.dice.between(0.32, 0.5);
        let leaf_half = Vector::new(length, 0.4 * length, 0.2 * length);
        let mut leaf = sphere_grid(bands, 4 * bands, |d| d * leaf_half);
        let turn = Rotation::from_rotation_z(heading) * Rotation::from_rotation_y(-tilt);
        let reach = turn * Vector::new(length, 0.0, 0.0);
        leaf.turn(turn, Vector::new(0.0, 0.0, 0.42) + reach);
        pieces.push(leaf);
    }
    join(pieces).fit(ctx.half)
}

/// A person's trunk: rounded hips, a waist, a chest widening to the shoulders, a neck; round in
/// its profile and flattened front to back, as deep as 0.6 of its width (the BehaviorRobot's
/// body, whose collider is a round capsule), its neck a little under the box's top. Seeds vary
/// the chest and the shoulders' slope.
pub(crate) fn torso(ctx: Ctx) -> Mesh {
    let chest = ctx.dice.between(0.39, 0.44);
    let shoulders = ctx.dice.between(0.74, 0.8);
    let profile = [
        p(0.0, 0.0),
        p(0.22, 0.015),
        p(0.34, 0.09),
        p(0.35, 0.2),
        p(0.31, 0.36),
        p(chest, 0.56),
        p(0.49, shoulders - 0.06),
        p(0.47, shoulders),
        p(0.36, shoulders + 0.05),
        p(0.18, 0.86),
        p(0.14, 0.89),
        p(0.13, 0.97),
        p(0.0, 1.0),
    ];
    // Its neck stops 8 % of the height under the box's top, where the head (an object of its
    // own, round the eye) sits over it.
    let h = ctx.half;
    let flat = Vector::new(0.6 * h.x, h.y, 0.92 * h.z);
    let mut trunk = revolve(&profile, ctx.detail.around(), even).fit(flat);
    trunk.stretch(Vector::ONE, Vector::new(0.0, 0.0, -0.08 * h.z));
    trunk
}

/// The BehaviorRobot's head, its face toward +x: a rounded head, fuller at the back, with a
/// dark visor wrapping its face as the original's avatar wears one. Seeds vary the visor's
/// depth.
pub(crate) fn head(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let visor = ctx.dice.between(0.3, 0.38);
    let skull = sphere_grid(b, 2 * b, |d| {
        let back = if d.x < 0.0 { 1.0 } else { 0.92 };
        Vector::new(back * d.x, 0.9 * d.y, d.z)
    });
    let glass = sphere_grid((b / 2).max(3), 2 * b, |d| {
        Vector::new(0.3 + 0.66 * d.x, 0.84 * d.y, 0.12 + visor * d.z)
    });
    join([skull, glass.toned(Tone::Dark)]).fit(ctx.half)
}

/// A Christmas tree: a stand, a short trunk and four to six tiers of boughs, each flaring out
/// and stepping in under the next, up to a point.
pub(crate) fn conifer(ctx: Ctx) -> Mesh {
    let stand =
        [p(0.0, 0.0), fold(0.3, 0.0), fold(0.32, 0.08), p(0.0, 0.08)].map(|pt| pt.tone(Tone::Clay));
    let trunk = [p(0.0, 0.07), fold(0.07, 0.07), fold(0.07, 0.2), p(0.0, 0.2)]
        .map(|pt| pt.tone(Tone::Stem));
    let tiers = ctx.dice.count(4, 6);
    let mut boughs = vec![p(0.0, 0.15), fold(1.0, 0.16)];
    for k in 1..tiers {
        let z = 0.16 + 0.8 * k as f32 / tiers as f32;
        let reach = 1.0 - 0.8 * k as f32 / tiers as f32;
        boughs.push(fold(0.55 * reach, z));
        boughs.push(fold(reach, z + 0.01));
    }
    boughs.push(p(0.0, 1.0));
    let boughs: Vec<_> = boughs.into_iter().map(|pt| pt.tone(Tone::Leaf)).collect();
    let around = ctx.detail.around();
    join([
        revolve(&stand, around, even),
        revolve(&trunk, around, even),
        revolve(&boughs, around, even),
    ])
    .fit(ctx.half)
}

/// A shoe, its toe toward +y: a pale sole and an upper that rises from a low toe to the collar
/// at the heel (a sandal's box makes it low).
pub(crate) fn shoe(ctx: Ctx) -> Mesh {
    let collar = ctx.dice.between(0.85, 1.0);
    let sole = [
        (0.0, -0.33),
        (0.3, -0.45),
        (0.75, -0.5),
        (0.95, -0.36),
        (1.0, 0.0),
        (0.95, 0.36),
        (0.75, 0.5),
        (0.3, 0.45),
        (0.0, 0.33),
    ];
    let sole = prism(&sole, (0.0, 0.16), Tone::Light);
    let b = ctx.detail.bands();
    let round = |x: f32| signed_pow(x, 0.5);
    let upper = sphere_grid(b, 2 * b, |d| {
        let x = 0.5 + 0.47 * round(d.x);
        // From the collar's height at the heel (x = 0) to under half of it at the toe.
        let top = 0.4 + (collar - 0.4) * (1.0 - x).powf(0.7);
        let z = if d.z >= 0.0 {
            0.12 + round(d.z) * (top - 0.12)
        } else {
            0.12 + round(d.z) * 0.04
        };
        Vector::new(x, 0.43 * round(d.y), z)
    });
    let mut shoe = join([sole, upper]);
    shoe.turn(Rotation::from_rotation_z(FRAC_PI_2), Vector::ZERO);
    shoe.fit(ctx.half)
}

/// A hat, brim down: a flat brim, a dark band and a crown rounded at its top.
pub(crate) fn hat(ctx: Ctx) -> Mesh {
    let crown = ctx.dice.between(0.5, 0.62);
    let profile = [
        p(0.0, 0.0),
        fold(1.0, 0.0),
        fold(1.0, 0.05),
        fold(crown + 0.02, 0.06).tone(Tone::Dark),
        fold(crown + 0.01, 0.22).tone(Tone::Body),
        p(crown - 0.02, 0.75),
        p(crown - 0.1, 0.95),
        p(0.3, 1.0),
        p(0.0, 1.0),
    ];
    revolve(&profile, ctx.detail.around(), even).fit(ctx.half)
}

/// A coat hanger lying flat, at its true size: a wire of the box's thickness bent into a
/// triangle whose bar runs along −y, and a hook rising from its apex and curling over toward +x.
pub(crate) fn hanger(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let r = h.z.min(0.1 * h.y);
    let sides = (ctx.detail.around() / 2).max(4);
    let wire = |path: &[Vector]| tube(path, sides, |_, _| r, Tone::Body);
    let bar = -(h.y - r);
    let apex = Vector::new(0.0, bar + ctx.dice.between(0.42, 0.5) * 2.0 * h.y, 0.0);
    let corner = Vector::new(h.x - r, bar, 0.0);
    let left = Vector::new(-corner.x, bar, 0.0);
    // The hook: a circle of radius `bend` whose top touches the box, its left side over the apex.
    let bend = (0.17 * 2.0 * h.y).min(0.5 * (h.x - r));
    let centre = Vector::new(bend, h.y - r - bend, 0.0);
    let steps = ctx.detail.bands();
    let mut hook = vec![apex - Vector::new(0.0, 0.5 * r, 0.0)];
    hook.extend((0..=steps).map(|k| {
        let a = PI - (PI + PI / 6.0) * k as f32 / steps as f32;
        centre + Vector::new(bend * a.cos(), bend * a.sin(), 0.0)
    }));
    // The triangle as one run with rounded corners, its ends passing each other along the
    // bar from the apex (a ring on a ring would be an open seam), and the hook rising from
    // inside the wire at the apex.
    let along = (corner - apex).normalize();
    let triangle = [
        apex + along * 0.5 * r,
        corner,
        left,
        apex,
        apex + along * 2.5 * r,
    ];
    let mut hanger = join([wire(&fillet(&triangle, 2.5 * r, steps / 2)), wire(&hook)]);
    // The rounded corners stop short of the box's ends: the hanger is widened to reach them.
    let (lo, hi) = hanger.bounds();
    let widen = h.x / lo.x.abs().max(hi.x).max(1e-9);
    hanger.stretch(Vector::new(widen, 1.0, 1.0), Vector::ZERO);
    hanger
}

/// A squeezed tube lying along x: a round cap toward −x, a body flattening from round at the
/// cap to flat at the other end, and a crimped seal there.
pub(crate) fn squeeze_tube(ctx: Ctx) -> Mesh {
    let cap_end = ctx.dice.between(0.1, 0.14);
    let b = ctx.detail.bands();
    // Poles toward ±x: (d.x, d.y, d.z) → (x from d.z, y from d.x, z from d.y), a turn.
    let body = sphere_grid(b, 2 * b, |d| {
        let t = 0.5 * (signed_pow(d.z, 0.4) + 1.0);
        let (wide, flat) = (0.36 + 0.14 * t, 0.34 * (1.0 - t).powf(0.7) + 0.02);
        Vector::new(
            cap_end + (0.93 - cap_end) * t,
            wide * signed_pow(d.x, 0.6),
            flat * signed_pow(d.y, 0.6),
        )
    });
    let seal = rounded_box(
        Vector::new(0.955, 0.0, 0.0),
        Vector::new(0.045, 0.5, 0.025),
        0.01,
        1,
        Tone::Body,
    );
    let profile = [
        p(0.0, 0.0),
        fold(0.85, 0.0),
        p(1.0, 0.12),
        p(1.0, 0.88),
        fold(0.85, 1.0),
        p(0.0, 1.0),
    ]
    .map(|pt| pt.tone(Tone::Dark));
    let mut cap = revolve(&profile, ctx.detail.around(), even);
    cap.stretch(Vector::new(0.3, 0.3, cap_end + 0.02), Vector::ZERO);
    // The cap's axis from z to x.
    cap.turn(Rotation::from_rotation_y(FRAC_PI_2), Vector::ZERO);
    join([body, seal, cap]).fit(ctx.half)
}

/// A mousetrap: a wooden board, a metal bait plate, and a wire bar (its springs coiled at the
/// middle) lying open across it.
pub(crate) fn mousetrap(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let r = 0.06;
    let sides = (ctx.detail.around() / 3).max(6);
    let bar = [
        Vector::new(0.02, -0.78, 0.55),
        Vector::new(0.8, -0.78, 0.55),
        Vector::new(0.8, 0.78, 0.55),
        Vector::new(0.02, 0.78, 0.55),
    ];
    let mut pieces = vec![
        rounded_box(
            Vector::new(0.0, 0.0, 0.22),
            Vector::new(1.0, 1.0, 0.22),
            0.1,
            rows,
            Tone::Body,
        ),
        tube(&fillet(&bar, 0.2, 3), sides, |_, _| r, Tone::Metal),
        rounded_box(
            Vector::new(-0.5, 0.0, 0.47),
            Vector::new(0.24, 0.3, 0.04),
            0.02,
            1,
            Tone::Metal,
        ),
    ];
    for side in [-1.0f32, 1.0] {
        let coil = [
            Vector::new(0.0, side * 0.15, 0.55),
            Vector::new(0.0, side * 0.6, 0.55),
        ];
        pieces.push(tube(&coil, sides, |_, _| 0.14, Tone::Metal));
    }
    join(pieces).fit(ctx.half)
}
