//! Food that grows: fruit, vegetables and a loaf, as turned profiles with a little wobble, tubes
//! and clusters of balls, each stretched to fill its box; and a roast chicken, a whole fish, a
//! bunch of herbs, a tea bag.

use crate::Ctx;
use crate::extrude::prism;
use crate::grid::{signed_pow, sphere_grid};
use crate::lathe::{Pt, even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::plain_box;
use crate::tone::Tone;
use crate::tube::tube;
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::{PI, TAU};

/// Points of a round profile from the bottom (z = 0) to the top (z = 1), `radius(z)` wide, in
/// `steps` even steps of angle.
fn rounded_profile(steps: usize, radius: impl Fn(f32, f32) -> f32) -> Vec<Pt> {
    (0..=steps)
        .map(|k| {
            let theta = PI * k as f32 / steps as f32;
            let z = 0.5 - 0.5 * theta.cos();
            let r = if k == 0 || k == steps {
                0.0
            } else {
                radius(theta.sin(), z)
            };
            p(r, z)
        })
        .collect()
}

/// Stretches the mesh to its box; built upright, it is laid along x first when the box is
/// longer than it is tall (a lemon or an egg lying on its side).
fn settle(mesh: Mesh, ctx: &Ctx) -> Mesh {
    let lying = ctx.half.x > ctx.half.z * 1.1 && ctx.half.x >= ctx.half.y;
    let mesh = if lying { mesh.lay_along_x() } else { mesh };
    mesh.fit(ctx.half)
}

/// A smooth ball or ellipsoid.
pub(crate) fn round(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    sphere_grid(b, 2 * b, |d| d).fit(ctx.half)
}

/// A stem: a short tube rising from `from`, bent over by `lean` of its length.
fn stem(from: Vector, (length, thick, lean): (f32, f32, f32), ctx: &Ctx) -> Mesh {
    let path = [
        from - Vector::Z * (2.0 * thick),
        from + Vector::new(0.0, 0.0, 0.5 * length),
        from + Vector::new(lean * length, 0.0, length),
    ];
    tube(
        &path,
        (ctx.detail.around() / 4).max(4),
        |_, _| thick,
        Tone::Stem,
    )
}

/// An apple: dimpled top and bottom, five faint lobes, a stem.
pub(crate) fn apple(ctx: Ctx) -> Mesh {
    let lobes = ctx.dice.between(0.01, 0.035);
    let turn = ctx.dice.between(0.0, TAU);
    let lean = ctx.dice.between(0.1, 0.5);
    let profile = [
        p(0.0, 0.07),
        p(0.25, 0.02),
        p(0.6, 0.06),
        p(0.9, 0.25),
        p(1.0, 0.48),
        p(0.95, 0.72),
        p(0.78, 0.9),
        p(0.5, 0.97),
        p(0.22, 0.93),
        p(0.0, 0.84),
    ];
    let body = revolve(&profile, ctx.detail.around(), |phi| {
        1.0 + lobes * (5.0 * phi + turn).cos()
    });
    let stem = stem(Vector::new(0.0, 0.0, 0.84), (0.24, 0.035, lean), &ctx);
    join([body, stem]).fit(ctx.half)
}

/// An orange, a tomato, a peach: a ball a little flattened, with a green calyx on top.
pub(crate) fn fruit(ctx: Ctx) -> Mesh {
    let flat = ctx.dice.between(0.82, 1.0);
    let mut profile = rounded_profile(ctx.detail.bands(), |s, _| s);
    for pt in &mut profile {
        pt.z *= flat;
    }
    let top = profile.len() - 1;
    profile[top].z = 0.97 * flat;
    let body = revolve(&profile, ctx.detail.around(), even);
    let calyx = [
        p(0.0, 0.93 * flat),
        fold(0.16, 0.95 * flat),
        fold(0.1, flat),
        p(0.0, flat),
    ]
    .map(|pt| pt.tone(Tone::Leaf));
    let calyx = revolve(&calyx, ctx.detail.around() / 2, |phi| {
        1.0 + 0.3 * (5.0 * phi).cos()
    });
    join([body, calyx]).fit(ctx.half)
}

/// A lemon: an ellipsoid drawn out to a point at each end.
pub(crate) fn lemon(ctx: Ctx) -> Mesh {
    let mut profile = vec![p(0.0, 0.0), p(0.1, 0.04)];
    let steps = ctx.detail.bands();
    for k in 1..steps {
        let theta = PI * k as f32 / steps as f32;
        profile.push(p(theta.sin(), 0.1 + 0.8 * (0.5 - 0.5 * theta.cos())));
    }
    profile.extend([p(0.1, 0.96), p(0.0, 1.0)]);
    settle(revolve(&profile, ctx.detail.around(), even), &ctx)
}

/// An egg: fuller at one end.
pub(crate) fn egg(ctx: Ctx) -> Mesh {
    let profile = rounded_profile(ctx.detail.bands(), |s, z| s * (1.1 - 0.25 * z));
    settle(revolve(&profile, ctx.detail.around(), even), &ctx)
}

/// Broccoli: a pale stalk under a dome of florets.
pub(crate) fn florets(ctx: Ctx) -> Mesh {
    let stalk = [
        p(0.0, 0.0),
        fold(0.24, 0.0),
        p(0.2, 0.3),
        p(0.3, 0.55),
        fold(0.3, 0.6),
        p(0.0, 0.6),
    ]
    .map(|pt| pt.tone(Tone::Stalk));
    let mut pieces = vec![revolve(&stalk, ctx.detail.around() / 2, even)];
    let count = ctx.dice.count(6, 9);
    let bands = (ctx.detail.bands() / 2).max(4);
    let spin = ctx.dice.between(0.0, TAU);
    for k in 0..=count {
        let (at, size) = if k == count {
            (Vector::new(0.0, 0.0, 0.85), 0.42)
        } else {
            let a = spin + TAU * k as f32 / count as f32;
            let lift = ctx.dice.between(0.62, 0.76);
            (
                Vector::new(0.55 * a.cos(), 0.55 * a.sin(), lift),
                ctx.dice.between(0.3, 0.38),
            )
        };
        let lump = 0.08 * ctx.dice.between(0.5, 1.0);
        pieces.push(sphere_grid(bands, 2 * bands, |d| {
            at + d * size * (1.0 + lump * (7.0 * d.x).sin() * (7.0 * d.y).cos())
        }));
    }
    join(pieces).fit(ctx.half)
}

/// A mushroom: a domed cap over a pale stalk.
pub(crate) fn mushroom(ctx: Ctx) -> Mesh {
    let cap = [
        p(0.0, 0.42),
        p(0.6, 0.45),
        fold(0.95, 0.52),
        p(1.0, 0.62),
        p(0.86, 0.84),
        p(0.5, 0.97),
        p(0.0, 1.0),
    ];
    let stalk = [
        p(0.0, 0.0),
        fold(0.3, 0.0),
        p(0.26, 0.25),
        p(0.24, 0.5),
        p(0.0, 0.5),
    ]
    .map(|pt| pt.tone(Tone::Light));
    let around = ctx.detail.around();
    join([
        revolve(&cap, around, even),
        revolve(&stalk, around / 2, even),
    ])
    .fit(ctx.half)
}

/// A strawberry: a rounded cone, tip down, under a leafy top.
pub(crate) fn berry(ctx: Ctx) -> Mesh {
    let profile = [
        p(0.0, 0.0),
        p(0.22, 0.08),
        p(0.6, 0.38),
        p(0.92, 0.7),
        p(0.96, 0.85),
        p(0.75, 0.95).tone(Tone::Leaf),
        p(0.4, 0.99).tone(Tone::Leaf),
        p(0.0, 1.0).tone(Tone::Leaf),
    ];
    revolve(&profile, ctx.detail.around(), |phi| {
        1.0 + 0.04 * (6.0 * phi).cos()
    })
    .fit(ctx.half)
}

/// A banana lying along x: a ridged tube bending up at both ends, tapering to a dark stem.
pub(crate) fn banana(ctx: Ctx) -> Mesh {
    let bend = ctx.dice.between(0.5, 0.8);
    let steps = ctx.detail.around() / 2;
    let path: Vec<Vector> = (0..=steps)
        .map(|k| {
            let t = -bend + 2.0 * bend * k as f32 / steps as f32;
            Vector::new(t.sin(), 0.0, 1.0 - t.cos())
        })
        .collect();
    let last = path.len() - 1;
    let taper = |i: usize| {
        let u = i as f32 / last as f32;
        0.12 * (0.25 + 0.75 * (PI * u).sin().max(0.0).powf(0.6))
    };
    let sides = (ctx.detail.around() / 2).max(5);
    let body = tube(
        &path,
        sides,
        |i, theta| taper(i) * (1.0 + 0.07 * (5.0 * theta).cos()),
        Tone::Body,
    );
    let end = path[last];
    let out = (path[last] - path[last - 1]).normalize();
    let stem_path = [end - out * 0.02, end + out * 0.08];
    let stem = tube(&stem_path, sides.min(6), |_, _| 0.035, Tone::Stem);
    join([body, stem]).fit(ctx.half)
}

/// A carrot lying along x: a long taper with the stub of its leaves.
pub(crate) fn carrot(ctx: Ctx) -> Mesh {
    let profile = [
        p(0.0, 0.0),
        p(0.1, 0.06),
        p(0.45, 0.45),
        p(0.8, 0.82),
        p(0.98, 0.93),
        fold(0.9, 0.98),
        p(0.0, 0.99),
    ];
    let leaves = [p(0.0, 0.95), fold(0.4, 0.95), fold(0.3, 1.06), p(0.0, 1.06)]
        .map(|pt| pt.tone(Tone::Leaf));
    let around = ctx.detail.around();
    let wobble = |phi: f32| 1.0 + 0.03 * (3.0 * phi).sin();
    join([
        revolve(&profile, around, wobble),
        revolve(&leaves, around / 2, even),
    ])
    .lay_along_x()
    .fit(ctx.half)
}

/// A loaf: square-ish below, domed above.
pub(crate) fn loaf(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let dome = ctx.dice.between(0.55, 0.8);
    sphere_grid(b, 2 * b, |d| {
        let top = if d.z > 0.0 { dome } else { 0.25 };
        Vector::new(
            signed_pow(d.x, 0.3),
            signed_pow(d.y, 0.35),
            signed_pow(d.z, top),
        )
    })
    .fit(ctx.half)
}

/// A roast chicken: a plump body, two drumsticks toward +x with their bones' ends showing, and
/// the wings' bumps at its sides.
pub(crate) fn roast(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let lump = |centre: Vector, half: Vector, turn: f32, tone: Tone| {
        let mut m = sphere_grid(b, 2 * b, |d| d * half).toned(tone);
        m.turn(Rotation::from_rotation_z(turn), centre);
        m
    };
    let plump = ctx.dice.between(0.36, 0.42);
    let mut pieces = vec![lump(
        Vector::new(-0.1, 0.0, plump),
        Vector::new(0.5, 0.45, plump),
        0.0,
        Tone::Body,
    )];
    for side in [-1.0f32, 1.0] {
        pieces.push(lump(
            Vector::new(0.4, side * 0.28, 0.3),
            Vector::new(0.3, 0.14, 0.14),
            side * 0.35,
            Tone::Body,
        ));
        pieces.push(lump(
            Vector::new(0.7, side * 0.4, 0.34),
            Vector::new(0.05, 0.05, 0.05),
            0.0,
            Tone::Light,
        ));
        pieces.push(lump(
            Vector::new(-0.15, side * 0.42, 0.45),
            Vector::new(0.25, 0.1, 0.15),
            0.0,
            Tone::Body,
        ));
    }
    join(pieces).fit(ctx.half)
}

/// A whole fish lying on its side along x: a body deepest behind its head (−x), a dark eye on
/// each side, a fin along its back (+y) and a forked tail at +x.
pub(crate) fn fish(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let deep = ctx.dice.between(0.42, 0.52);
    // Poles toward ±x: (d.x, d.y, d.z) → (x from d.z, y from d.x, z from d.y), a turn.
    let body = sphere_grid(b, 2 * b, |d| {
        let s = d.z;
        let taper = 1.0 - 0.35 * s;
        Vector::new(-0.225 + 0.775 * s, deep * taper * d.x, 0.2 * taper * d.y)
    });
    let flat = (-0.04, 0.04);
    let mut pieces = vec![
        body,
        prism(
            &[(0.42, -0.02), (0.86, 0.05), (1.0, 0.42)],
            flat,
            Tone::Body,
        ),
        prism(
            &[(0.42, 0.02), (1.0, -0.42), (0.86, -0.05)],
            flat,
            Tone::Body,
        ),
        prism(
            &[(-0.4, 0.3), (0.1, 0.28), (-0.05, 0.5)],
            (-0.02, 0.02),
            Tone::Body,
        ),
    ];
    let small = (b / 3).max(3);
    for side in [-1.0f32, 1.0] {
        let eye = Vector::new(-0.75, 0.08, side * 0.15);
        pieces.push(sphere_grid(small, 2 * small, |d| eye + d * 0.05).toned(Tone::Dark));
    }
    join(pieces).fit(ctx.half)
}

/// A bunch of herbs standing: pale stalks gathered low and spreading, a leafy sprig on each.
pub(crate) fn herbs(ctx: Ctx) -> Mesh {
    let stalks = ctx.dice.count(6, 9);
    let spin = ctx.dice.between(0.0, TAU);
    let sides = (ctx.detail.around() / 4).max(5);
    let bands = (ctx.detail.bands() / 2).max(3);
    let mut pieces = Vec::new();
    for k in 0..stalks {
        let a = spin + TAU * k as f32 / stalks as f32;
        let spread = ctx.dice.between(0.35, 0.6);
        let tip = Vector::new(
            spread * a.cos(),
            spread * a.sin(),
            ctx.dice.between(0.55, 0.7),
        );
        let path = [
            Vector::new(0.06 * a.cos(), 0.06 * a.sin(), 0.0),
            Vector::new(0.04 * a.cos(), 0.04 * a.sin(), 0.25),
            tip,
        ];
        pieces.push(tube(&path, sides, |_, _| 0.035, Tone::Stalk));
        let at = tip + Vector::new(0.0, 0.0, 0.12);
        let lump = ctx.dice.between(0.1, 0.2);
        pieces.push(sphere_grid(bands, 2 * bands, |d| {
            let bumpy = 1.0 + lump * (6.0 * d.x).sin() * (5.0 * d.y).cos();
            at + Vector::new(0.3 * d.x, 0.3 * d.y, 0.2 * d.z) * bumpy
        }));
    }
    join(pieces).fit(ctx.half)
}

/// A tea bag lying flat: a paper pouch toward −y in the object's colour, a string from its top
/// to a paper tag toward +y.
pub(crate) fn tea_bag(ctx: Ctx) -> Mesh {
    let b = ctx.detail.bands();
    let pouch = sphere_grid(b, 2 * b, |d| {
        Vector::new(
            0.8 * signed_pow(d.x, 0.3),
            -0.35 + 0.65 * signed_pow(d.y, 0.3),
            0.5 * d.z,
        )
    });
    let string = plain_box(
        Vector::new(0.0, 0.5, 0.2),
        Vector::new(0.015, 0.25, 0.03),
        Tone::Paper,
    );
    let tag = prism(
        &[(-0.3, 0.7), (0.3, 0.7), (0.3, 1.0), (-0.3, 1.0)],
        (0.15, 0.3),
        Tone::Paper,
    );
    join([pouch, string, tag]).fit(ctx.half)
}
