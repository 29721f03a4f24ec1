//! Things with a handle, lying along x: knives (blade toward +x, where the archetypes put the
//! slicing edge), forks and spoons (head toward +x), brooms and brushes (bristles toward −x,
//! where the archetypes put the cleaning area), hammers, screwdrivers, toothbrushes, a closed
//! umbrella, saws, scrapers; and, not lying along x, a scrubbing brush and a dustpan. Each is
//! built in a frame of its own, x from 0 to 1, and stretched to fill its box (an umbrella's
//! hook excepted: it is bent at its true size).

use crate::extrude::prism;
use crate::grid::sphere_grid;
use crate::lathe::{Pt, even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::{block, plain_box, rounded_box};
use crate::tone::Tone;
use crate::tube::tube;
use crate::{Ctx, Detail};
use rapier3d::math::{Rotation, Vector};

/// A handle from x = `from` to `to`, `width` and `thick` across (both as fractions of the
/// frame's y and z), in `tone`, its edges rounded.
fn handle(from: f32, to: f32, (width, thick): (f32, f32), detail: Detail, tone: Tone) -> Mesh {
    let half = Vector::new(0.5 * (to - from), 0.5 * width, 0.5 * thick);
    rounded_box(
        Vector::new(0.5 * (from + to), 0.0, 0.0),
        half,
        0.45 * half.y.min(half.z),
        detail.bevel_rows(),
        tone,
    )
}

/// A knife: a dark handle, a metal bolster and a blade whose spine runs straight to the point
/// and whose edge curves up to it.
pub(crate) fn knife(ctx: Ctx) -> Mesh {
    let grip = ctx.dice.between(0.34, 0.42);
    let blade = [
        (grip + 0.04, -0.5),
        (0.82, -0.46),
        (0.95, -0.15),
        (1.0, 0.5),
        (grip + 0.04, 0.5),
    ];
    join([
        handle(0.0, grip, (0.8, 1.0), ctx.detail, Tone::Dark),
        handle(
            grip - 0.01,
            grip + 0.05,
            (0.9, 0.8),
            ctx.detail,
            Tone::Metal,
        ),
        prism(&blade, (-0.12, 0.12), Tone::Metal),
    ])
    .fit(ctx.half)
}

/// A fork: a handle widening toward its end and rising off the table, a neck, and a head of
/// four tines lying on it (a few pixels across, the coarse level, one blade where the tines
/// are). Thin: the box's height is mostly the handle's rise.
pub(crate) fn fork(ctx: Ctx) -> Mesh {
    let neck = ctx.dice.between(0.6, 0.66);
    let head_end = match ctx.detail {
        Detail::Fine => 0.8,
        Detail::Coarse => 1.0,
    };
    let flat = (-0.5, -0.2);
    // Into the neck by 2 % of the length: pieces may overlap, not share a face.
    let mut stick = prism(
        &[
            (0.0, -0.2),
            (neck + 0.02, -0.09),
            (neck + 0.02, 0.09),
            (0.0, 0.2),
        ],
        flat,
        Tone::Body,
    );
    for p in &mut stick.positions {
        p.z += 0.7 * (1.0 - p.x / neck).max(0.0);
    }
    let mut pieces = vec![
        stick,
        prism(
            &[
                (neck, -0.1),
                (0.76, -0.5),
                (head_end, -0.5),
                (head_end, 0.5),
                (0.76, 0.5),
                (neck, 0.1),
            ],
            flat,
            Tone::Body,
        ),
    ];
    let tines = if ctx.detail == Detail::Fine { 4 } else { 0 };
    for k in 0..tines {
        let y = -0.5 + 0.29 * k as f32;
        pieces.push(prism(
            &[
                (0.79, y),
                (1.0, y + 0.02),
                (1.0, y + 0.12),
                (0.79, y + 0.14),
            ],
            flat,
            Tone::Body,
        ));
    }
    join(pieces).fit(ctx.half)
}

/// A spoon: a slender handle and an oval bowl.
pub(crate) fn spoon(ctx: Ctx) -> Mesh {
    let neck = ctx.dice.between(0.58, 0.64);
    let stick = prism(
        &[
            (0.0, -0.16),
            (neck, -0.07),
            (neck + 0.04, 0.0),
            (neck, 0.07),
            (0.0, 0.16),
        ],
        (-0.3, 0.1),
        Tone::Body,
    );
    let bands = ctx.detail.bands();
    let length = 1.0 - neck;
    let mut bowl = sphere_grid(bands, 2 * bands, |d| {
        Vector::new(0.5 * length * d.x, 0.5 * d.y, 0.5 * d.z)
    });
    bowl.turn(
        Rotation::IDENTITY,
        Vector::new(neck + 0.5 * length, 0.0, 0.0),
    );
    join([stick, bowl.toned(Tone::Body)]).fit(ctx.half)
}

/// A broom or a brush: a block of bristles at −x under a stock, and a handle to +x, as long as
/// the box allows (a broom's is most of it, a hand brush's a little over half).
pub(crate) fn broom(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    // The head is about as long as the box is wide, at most 30 cm, and at most half of it.
    let head = ((2.5 * h.y).min(0.3) / (2.0 * h.x)).min(0.5);
    let stock = handle(0.0, head, (1.0, 0.45), ctx.detail, Tone::Body);
    let bristles = rounded_box(
        Vector::new(0.5 * head, 0.0, -0.3),
        Vector::new(0.48 * head, 0.47, 0.2),
        0.02,
        1,
        Tone::Dark,
    );
    let mut stick = handle(head - 0.01, 1.0, (0.5, 0.5), ctx.detail, Tone::Body);
    stick.turn(Rotation::IDENTITY, Vector::new(0.0, 0.0, 0.1));
    join([stock, bristles, stick]).fit(h)
}

/// A hammer: a handle along x and at its +x end a metal head across it, its face toward −y and
/// its claw toward +y.
pub(crate) fn hammer(ctx: Ctx) -> Mesh {
    let neck = ctx.dice.between(0.8, 0.86);
    let head_half = Vector::new(0.5 * (1.0 - neck), 0.4, 0.5);
    let head = rounded_box(
        Vector::new(0.5 * (1.0 + neck), -0.1, 0.0),
        head_half,
        0.3 * head_half.x,
        ctx.detail.bevel_rows(),
        Tone::Metal,
    );
    let claw = prism(
        &[
            (neck + 0.02, 0.25),
            (0.98, 0.25),
            (0.95, 0.5),
            (neck + 0.06, 0.5),
        ],
        (-0.35, 0.35),
        Tone::Metal,
    );
    join([
        handle(0.0, neck + 0.02, (0.24, 0.8), ctx.detail, Tone::Body),
        head,
        claw,
    ])
    .fit(ctx.half)
}

/// A screwdriver: a fat handle toward −x, a metal shaft and a tip toward +x.
pub(crate) fn screwdriver(ctx: Ctx) -> Mesh {
    let grip = ctx.dice.between(0.38, 0.46);
    let metal = |pt: Pt| pt.tone(Tone::Metal);
    let profile = [
        p(0.0, 0.0),
        fold(0.85, 0.0),
        p(1.0, 0.08),
        p(1.0, grip - 0.08),
        fold(0.7, grip),
        metal(fold(0.18, grip)),
        metal(p(0.18, 0.93)),
        metal(fold(0.06, 1.0)),
        metal(p(0.0, 1.0)),
    ];
    revolve(&profile, ctx.detail.around(), even)
        .lay_along_x()
        .fit(ctx.half)
}

/// A toothbrush: a slender handle and a head toward +x with a block of white bristles on it.
pub(crate) fn toothbrush(ctx: Ctx) -> Mesh {
    let neck = ctx.dice.between(0.72, 0.78);
    let rows = ctx.detail.bevel_rows();
    let stick = rounded_box(
        Vector::new(0.5 * neck, 0.0, -0.3),
        Vector::new(0.5 * neck, 0.32, 0.2),
        0.1,
        rows,
        Tone::Body,
    );
    let head = rounded_box(
        Vector::new(0.5 * (1.0 + neck) - 0.01, 0.0, -0.35),
        Vector::new(0.5 * (1.0 - neck) + 0.01, 0.45, 0.15),
        0.1,
        rows,
        Tone::Body,
    );
    let bristles = rounded_box(
        Vector::new(0.5 * (1.0 + neck) + 0.01, 0.0, 0.1),
        Vector::new(0.5 * (1.0 - neck) - 0.02, 0.4, 0.4),
        0.05,
        1,
        Tone::Light,
    );
    join([stick, head, bristles]).fit(ctx.half)
}

/// A closed umbrella: a J-shaped dark hook toward −x, a metal shaft, and the furled canopy in
/// eight folds narrowing to its tip toward +x. The hook is bent at its true size (stretching a
/// bent tube into a long thin box would fold its surface over).
pub(crate) fn umbrella(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let fullest = ctx.dice.between(0.4, 0.5);
    let profile = [
        p(0.0, 0.0),
        fold(0.25, 0.0),
        p(0.5, fullest),
        p(0.3, 0.8),
        fold(0.08, 0.96),
        p(0.0, 0.97),
    ];
    let folds = |phi: f32| 1.0 - 0.12 * (4.0 * phi).sin().abs();
    let canopy = revolve(&profile, ctx.detail.around(), folds).lay_along_x();
    let shaft = handle(-0.3, 1.0, (0.1, 0.1), ctx.detail, Tone::Metal);
    // The hook takes the first fifth of the length, at most 14 cm.
    let hook = (0.4 * h.x).min(0.14);
    let mut furled = join([shaft, canopy]).fit(Vector::new(h.x - 0.5 * hook, h.y, h.z));
    furled.turn(Rotation::IDENTITY, Vector::new(0.5 * hook, 0.0, 0.0));
    // A straight grip along the axis, then a half circle down and back, then a short tail.
    let r = 0.15 * h.y.min(h.z);
    let bend = 0.5 * (h.z - r);
    let centre = Vector::new(-h.x + r + bend, 0.0, -bend);
    let mut path = vec![Vector::new(-h.x + 1.1 * hook, 0.0, 0.0)];
    for k in 0..=8 {
        let angle = std::f32::consts::FRAC_PI_2 + std::f32::consts::PI * k as f32 / 8.0;
        path.push(centre + Vector::new(bend * angle.cos(), 0.0, bend * angle.sin()));
    }
    path.push(centre + Vector::new(0.3 * hook, 0.0, -bend));
    let sides = (ctx.detail.around() / 3).max(4);
    join([tube(&path, sides, |_, _| r, Tone::Dark), furled])
}

/// A hand saw: a wooden (or dark) handle at −x with a hole for the hand, and a metal blade
/// whose back falls from the handle to the toe at +x over a straight edge of teeth (−y).
pub(crate) fn saw(ctx: Ctx) -> Mesh {
    let toe = ctx.dice.between(0.25, 0.4);
    let grip = if ctx.dice.between(0.0, 1.0) < 0.5 {
        Tone::Stem
    } else {
        Tone::Dark
    };
    let flat = (-0.08, 0.08);
    let blade = [(0.28, -0.42), (1.0, -0.42), (1.0, -0.42 + toe), (0.28, 0.5)];
    let mut pieces = vec![prism(&blade, flat, Tone::Metal)];
    // The handle: four bars round the hole.
    let bars = [
        (0.0, 0.09, -0.35, 0.45),
        (0.0, 0.3, 0.3, 0.5),
        (0.0, 0.3, -0.5, -0.28),
        (0.2, 0.32, -0.5, 0.5),
    ];
    for (x0, x1, y0, y1) in bars {
        let half = Vector::new(0.5 * (x1 - x0), 0.5 * (y1 - y0), 0.5);
        pieces.push(rounded_box(
            Vector::new(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.0),
            half,
            0.4 * half.x.min(half.y),
            ctx.detail.bevel_rows(),
            grip,
        ));
    }
    if ctx.detail == Detail::Fine {
        for k in 0..24 {
            let x = 0.33 + 0.0275 * k as f32;
            let tooth = [(x, -0.42), (x + 0.012, -0.5), (x + 0.024, -0.42)];
            pieces.push(prism(&tooth, flat, Tone::Metal));
        }
    }
    join(pieces).fit(ctx.half)
}

/// A scraper: a dark handle toward −x and a flat blade widening to a straight edge at +x.
pub(crate) fn scraper(ctx: Ctx) -> Mesh {
    let neck = ctx.dice.between(0.45, 0.55);
    let blade = [
        (neck - 0.05, -0.25),
        (1.0, -0.5),
        (1.0, 0.5),
        (neck - 0.05, 0.25),
    ];
    join([
        handle(0.0, neck, (0.32, 0.9), ctx.detail, Tone::Dark),
        prism(&blade, (-0.5, -0.2), Tone::Body),
    ])
    .fit(ctx.half)
}

/// A scrubbing brush: a stock in the object's colour, pinched at its waist for the fingers, on
/// tufts of dark bristles (one block of them at the coarse level).
pub(crate) fn scrub_brush(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let waist = ctx.dice.between(0.65, 0.8);
    let mut pieces = vec![
        rounded_box(
            Vector::new(0.0, 0.0, 0.55),
            Vector::new(1.0, waist, 0.12),
            0.08,
            rows,
            Tone::Body,
        ),
        rounded_box(
            Vector::new(0.0, 0.0, 0.78),
            Vector::new(0.8, 0.5 * waist, 0.2),
            0.15,
            rows,
            Tone::Body,
        ),
    ];
    match ctx.detail {
        Detail::Fine => {
            for i in 0..7 {
                for j in 0..3 {
                    let at = Vector::new(
                        -0.84 + 0.28 * i as f32,
                        (j as f32 - 1.0) * 0.42 * waist,
                        0.22,
                    );
                    let tuft = Vector::new(0.1, 0.16 * waist, 0.22);
                    pieces.push(plain_box(at, tuft, Tone::Dark));
                }
            }
        }
        Detail::Coarse => pieces.push(plain_box(
            Vector::new(0.0, 0.0, 0.22),
            Vector::new(0.94, 0.6 * waist, 0.22),
            Tone::Dark,
        )),
    }
    join(pieces).fit(ctx.half)
}

/// A dustpan: a flat floor open toward −y, side walls rising toward a back wall at +y, and a
/// handle reaching back from the wall.
pub(crate) fn dustpan(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let wall = ctx.dice.between(0.75, 0.95);
    let part = |centre: [f32; 3], half: [f32; 3], radius: f32| {
        block(
            Vector::from_array(centre),
            Vector::from_array(half),
            radius,
            rows,
            ctx.detail,
            Tone::Body,
        )
    };
    let mut pieces = vec![
        part([0.0, -0.325, 0.03], [0.97, 0.675, 0.03], 0.02),
        part([0.0, 0.3, 0.5 * wall], [0.99, 0.05, 0.5 * wall], 0.03),
        part([0.0, 0.66, 0.45 * wall], [0.13, 0.34, 0.07], 0.05),
    ];
    // The side walls, their outline in the y–z plane, laid across x at the pan's sides.
    let side = [(-1.0, 0.0), (0.35, 0.0), (0.35, wall), (-1.0, 0.06)];
    for (from, to) in [(0.93, 1.0), (-1.0, -0.93)] {
        pieces.push(prism(&side, (from, to), Tone::Body).lay_along_x());
    }
    join(pieces).fit(ctx.half)
}
