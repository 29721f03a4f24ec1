//! Fronts and fittings of furniture and appliances: door leaves and drawer fronts with their
//! pulls and knobs, glazed doors, doors hinged at the bottom (ovens, dishwashers), a washer's
//! porthole, control panels with knobs and a display, a stove's top with its burners, and a
//! sink's tap.
//!
//! A front faces −y, as the furniture it closes does, and is thinnest along y: its panel fills
//! the back of the box and its fittings stand proud of the panel in the front of it
//! ([`proud`]), so that the whole stays inside the collider it draws and nothing sticks out
//! where a hand or a door would not meet it.

use crate::lathe::{even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::{block, plain_box};
use crate::tone::Tone;
use crate::{Ctx, Detail, Form, bevel};
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::FRAC_PI_2;

/// How far fittings stand proud of a front's panel: two fifths of its thickness, at most 12 mm.
fn proud(h: Vector) -> f32 {
    (0.8 * h.y).min(0.012)
}

/// Rows through the rounded edges of a fitting at the fine level: one (a pull or a raised
/// panel is a few pixels thick wherever a panel's rounding shows, and a front is drawn often).
const FITTING_ROWS: usize = 1;

/// The box of a front's panel, as its centre and half size: the front's box less the front
/// `proud` m (where the fittings are) and the top `rim` m (a stove's burners).
fn panel_box(h: Vector, proud: f32, rim: f32) -> (Vector, Vector) {
    let half = Vector::new(h.x, h.y - 0.5 * proud, h.z - 0.5 * rim);
    (Vector::new(0.0, 0.5 * proud, -0.5 * rim), half)
}

/// The panel behind a front's fittings (less a stove's burners' `rim` on top), its edges
/// rounded.
fn panel(h: Vector, face: Face, rim: f32) -> Mesh {
    let (centre, half) = panel_box(h, face.proud, rim);
    let detail = face.detail;
    block(
        centre,
        half,
        bevel(half),
        detail.bevel_rows(),
        detail,
        Tone::Body,
    )
}

/// How far a stove's burners stand on its top, m.
fn burner_rim(h: Vector) -> f32 {
    (0.1 * h.z).min(0.008)
}

/// The box inside a front's panel (or a stove's body), as its centre and half size: what
/// [`crate::solid_core`] says of the fronts.
pub(crate) fn panel_core(form: Form, h: Vector) -> (Vector, Vector) {
    let rim = if form == Form::Cooktop {
        burner_rim(h)
    } else {
        0.0
    };
    let (centre, half) = panel_box(h, proud(h), rim);
    (centre, half - Vector::splat(bevel(half)))
}

/// Where a front's fittings stand: the face of its panel (y) and how far in front of it they
/// may reach.
#[derive(Clone, Copy)]
struct Face {
    y: f32,
    proud: f32,
    detail: Detail,
}

impl Face {
    fn of(h: Vector, detail: Detail) -> Face {
        let proud = proud(h);
        Face {
            y: -h.y + proud,
            proud,
            detail,
        }
    }

    /// How thick a bar pull's grip is across its length, m.
    fn thick(self) -> f32 {
        (1.1 * self.proud).clamp(0.005, 0.016)
    }

    /// A bar pull centred at (x, z) = `at`, `length` m long, upright or lying along x: a metal
    /// grip on two posts.
    fn bar(self, at: (f32, f32), length: f32, upright: bool) -> Mesh {
        let grip_depth = 0.45 * self.proud;
        let thick = self.thick();
        let along = |a: f32, across: f32| {
            if upright { (across, a) } else { (a, across) }
        };
        let (hx, hz) = along(0.5 * length, 0.5 * thick);
        let grip = block(
            Vector::new(at.0, self.y - self.proud + 0.5 * grip_depth, at.1),
            Vector::new(hx, 0.5 * grip_depth, hz),
            0.45 * grip_depth.min(thick),
            FITTING_ROWS,
            self.detail,
            Tone::Metal,
        );
        let post_depth = self.proud - grip_depth;
        let posts = [-1.0f32, 1.0].map(|side| {
            let (px, pz) = along(side * (0.5 * length - thick), 0.0);
            let (sx, sz) = along(0.35 * thick, 0.35 * thick);
            // Into the panel and the grip by half a millimetre, so no crack shows.
            plain_box(
                Vector::new(at.0 + px, self.y - 0.5 * post_depth, at.1 + pz),
                Vector::new(sx, 0.5 * post_depth + 0.0005, sz),
                Tone::Metal,
            )
        });
        let [a, b] = posts;
        join([grip, a, b])
    }

    /// A round knob of `radius` centred at (x, z) = `at`, mushroom-shaped, facing −y.
    fn knob(self, at: (f32, f32), radius: f32, tone: Tone) -> Mesh {
        let depth = self.proud;
        if self.detail == Detail::Coarse {
            // A few pixels across, a knob is a dot: its box.
            return plain_box(
                Vector::new(at.0, self.y - 0.5 * depth + 0.00025, at.1),
                Vector::new(0.8 * radius, 0.5 * depth + 0.00025, 0.8 * radius),
                tone,
            );
        }
        let profile = [
            p(0.0, -0.0005),
            fold(0.45 * radius, -0.0005),
            p(0.4 * radius, 0.35 * depth),
            fold(radius, 0.55 * depth),
            p(radius, 0.85 * depth),
            fold(0.8 * radius, depth),
            p(0.0, depth),
        ]
        .map(|pt| pt.tone(tone));
        self.facing(revolve(&profile, self.detail.around(), even), at)
    }

    /// A dark glass pane over (x, z) in `lo..hi`, a little proud of the panel.
    fn window(self, lo: (f32, f32), hi: (f32, f32)) -> Mesh {
        let depth = 0.3 * self.proud;
        let half = Vector::new(
            0.5 * (hi.0 - lo.0),
            0.5 * depth + 0.0005,
            0.5 * (hi.1 - lo.1),
        );
        block(
            Vector::new(
                0.5 * (lo.0 + hi.0),
                self.y - 0.5 * depth + 0.0005,
                0.5 * (lo.1 + hi.1),
            ),
            half,
            0.4 * depth,
            1,
            self.detail,
            Tone::Dark,
        )
    }

    /// A round window of `radius` at (x, z) = `at` in a metal ring a fifth as wide.
    fn porthole(self, at: (f32, f32), radius: f32) -> Mesh {
        let (depth, inner) = (self.proud, 0.8 * radius);
        let ring = [
            fold(inner, -0.0005),
            fold(radius, -0.0005),
            fold(radius, 0.6 * depth),
            fold(inner, depth),
        ]
        .map(|pt| pt.tone(Tone::Metal));
        let glass = [
            p(0.0, -0.0005),
            fold(1.01 * inner, -0.0005),
            fold(1.01 * inner, 0.5 * depth),
            p(0.0, 0.5 * depth),
        ]
        .map(|pt| pt.tone(Tone::Dark));
        let around = self.detail.around();
        let ring = self.facing(revolve(&ring, around, even), at);
        let glass = self.facing(revolve(&glass, around, even), at);
        join([ring, glass])
    }

    /// A solid built about +z from z = 0, turned to stand out of the face toward −y at
    /// (x, z) = `at`.
    fn facing(self, mut mesh: Mesh, at: (f32, f32)) -> Mesh {
        mesh.turn(
            Rotation::from_rotation_x(FRAC_PI_2),
            Vector::new(at.0, self.y, at.1),
        );
        mesh
    }
}

/// Which pull a front has, by its seed: a bar or a knob.
fn bar_or_knob(ctx: &mut Ctx) -> bool {
    ctx.dice.between(0.0, 1.0) < 0.6
}

/// A knob's radius on a front of half size `h`.
fn knob_radius(h: Vector) -> f32 {
    (0.15 * h.x.min(h.z)).clamp(0.004, 0.018)
}

/// A side-hinged door leaf (hinge on −x): a panel, raised in its middle on some seeds, and by
/// its free (+x) edge a knob or an upright bar near the top of a low door, a bar at a hand's
/// height (1 m over the leaf's foot) on a tall one.
pub(crate) fn door(mut ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let mut pieces = vec![panel(h, face, 0.0)];
    let inset = (0.12 * h.x.min(h.z) * 2.0)
        .clamp(0.02, 0.1)
        .min(0.3 * h.x.min(h.z));
    if ctx.dice.between(0.0, 1.0) < 0.5 {
        pieces.push(raised(h, face, inset));
    }
    // Tall doors (a fridge's, a home's) always have a bar.
    let bar = bar_or_knob(&mut ctx) || h.z > 0.6;
    let length = (0.6 * h.z).clamp(0.08, 0.6).min(1.6 * h.z);
    // How far the pull reaches from its centre across the door and up it.
    let (across, up) = if bar {
        (0.5 * face.thick(), 0.5 * length)
    } else {
        (knob_radius(h), knob_radius(h))
    };
    let x = h.x - (0.5 * inset).max(across).min(0.5 * h.x);
    let z = if h.z > 0.6 {
        (-h.z + 1.0).min(h.z - up)
    } else {
        (h.z - 0.5 * inset - up).max(0.0)
    };
    pieces.push(if bar {
        face.bar((x, z), length, true)
    } else {
        face.knob((x, z), knob_radius(h), Tone::Metal)
    });
    join(pieces)
}

/// A raised middle panel, `inset` m in from every edge, standing a third of the fittings'
/// depth proud.
fn raised(h: Vector, face: Face, inset: f32) -> Mesh {
    let depth = face.proud / 3.0;
    let half = Vector::new(h.x - inset, 0.5 * depth + 0.0005, h.z - inset);
    let centre = Vector::new(0.0, face.y - 0.5 * depth + 0.0005, 0.0);
    block(
        centre,
        half,
        0.8 * depth,
        FITTING_ROWS,
        face.detail,
        Tone::Body,
    )
}

/// A side-hinged door glazed over most of its width (a microwave's): a dark window toward the
/// hinge, an upright bar by the free edge.
pub(crate) fn glass_door(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let margin = (0.12 * h.z).max(0.01);
    let split = h.x - 2.0 * h.x * ctx.dice.between(0.25, 0.32);
    let window = face.window((-h.x + margin, -h.z + margin), (split, h.z - margin));
    let bar = face.bar((0.5 * (split + h.x), 0.0), 1.4 * h.z, true);
    join([panel(h, face, 0.0), window, bar])
}

/// A drawer's front: a panel with a lying bar or a knob at its middle, a little above.
pub(crate) fn drawer_front(mut ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let z = 0.25 * h.z;
    let pull = if bar_or_knob(&mut ctx) {
        let length = (0.6 * h.x).clamp(0.06, 0.3).min(1.6 * h.x);
        face.bar((0.0, z), length, false)
    } else {
        face.knob((0.0, z), knob_radius(h), Tone::Metal)
    };
    join([panel(h, face, 0.0), pull])
}

/// A door hinged at its bottom edge (a dishwasher's): a panel with a lying bar along its top.
pub(crate) fn drop_door(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let bar = face.bar((0.0, top_bar(h, face)), 1.5 * h.x, false);
    join([panel(h, face, 0.0), bar])
}

/// Where a bar along the top of a door hinged at its bottom lies: 85 % of the way up, and
/// wholly on the door.
fn top_bar(h: Vector, face: Face) -> f32 {
    (0.85 * h.z).min(h.z - face.thick())
}

/// An oven's door: a drop-down door with a dark window under its bar.
pub(crate) fn oven_door(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let (wx, top) = (0.72 * h.x, ctx.dice.between(0.45, 0.6) * h.z);
    let window = face.window((-wx, -0.55 * h.z), (wx, top));
    let bar = face.bar((0.0, top_bar(h, face)), 1.5 * h.x, false);
    join([panel(h, face, 0.0), window, bar])
}

/// A washer's or dryer's door: a panel with a round window in a metal ring, a little above
/// the middle, and a small bar by the free (+x) edge.
pub(crate) fn porthole(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let radius = 0.62 * h.x.min(h.z) * ctx.dice.between(0.9, 1.0);
    let window = face.porthole((-0.1 * h.x, 0.1 * h.z), radius);
    let bar = face.bar((0.85 * h.x, 0.1 * h.z), 0.5 * radius, true);
    join([panel(h, face, 0.0), window, bar])
}

/// A control panel: a block with a row of three to five knobs and a dark display on its front.
pub(crate) fn controls(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let face = Face::of(h, ctx.detail);
    let knobs = ctx.dice.count(3, 5);
    let row = 1.2 * h.x;
    let step = row / knobs as f32;
    let radius = (0.35 * step).min(0.6 * h.z).min(0.02);
    let mut pieces = vec![panel(h, face, 0.0)];
    for k in 0..knobs {
        let x = -h.x + 0.1 * h.x + step * (k as f32 + 0.5);
        pieces.push(face.knob((x, 0.0), radius, Tone::Dark));
    }
    let display = (0.45 * h.z).min(0.02);
    pieces.push(face.window(
        (0.4 * h.x, -display),
        (0.4 * h.x + (0.45 * h.x).min(4.0 * display), display),
    ));
    join(pieces)
}

/// A stove: a block whose top holds four burners where the archetype puts its heating
/// elements (a quarter of the width and a fifth of the depth off the centre), and an oven's
/// window and bar on its front.
pub(crate) fn cooktop(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let rim = burner_rim(h);
    let face = Face::of(h, ctx.detail);
    let body = panel(h, face, rim);
    let radius = (0.4 * h.x).min(0.5 * h.y).min(0.11) * ctx.dice.between(0.85, 1.0);
    let mut pieces = vec![body];
    for (fx, fy) in [(-0.5, -0.4), (0.5, -0.4), (-0.5, 0.4), (0.5, 0.4)] {
        pieces.push(burner(
            Vector::new(fx * h.x, fy * h.y, h.z - rim),
            radius,
            rim,
            ctx.detail,
        ));
    }
    let (wx, wz) = (0.7 * h.x, 0.45 * h.z);
    pieces.push(face.window((-wx, -h.z + 0.3 * h.z), (wx, -h.z + 0.3 * h.z + 2.0 * wz)));
    pieces.push(face.bar((0.0, 0.62 * h.z), 1.5 * h.x, false));
    join(pieces)
}

/// A burner standing `rim` m on a stove's top at `at`: a dark plate under a metal ring.
fn burner(at: Vector, radius: f32, rim: f32, detail: Detail) -> Mesh {
    let plate = [
        p(0.0, -0.0005),
        fold(radius, -0.0005),
        fold(radius, 0.5 * rim),
        p(0.0, 0.5 * rim),
    ]
    .map(|pt| pt.tone(Tone::Dark));
    let ring = [
        fold(0.55 * radius, 0.0),
        fold(0.7 * radius, 0.0),
        fold(0.7 * radius, rim),
        fold(0.55 * radius, rim),
    ]
    .map(|pt| pt.tone(Tone::Metal));
    let around = detail.around();
    let mut both = match detail {
        Detail::Fine => join([revolve(&plate, around, even), revolve(&ring, around, even)]),
        // A few pixels across, the plate alone.
        Detail::Coarse => revolve(&plate, around, even),
    };
    both.turn(Rotation::IDENTITY, at);
    both
}

/// A sink's tap: a metal column on a round foot, capped by a wider head.
pub(crate) fn tap(ctx: Ctx) -> Mesh {
    let head = ctx.dice.between(0.8, 0.9);
    let profile = [
        p(0.0, 0.0),
        fold(1.0, 0.0),
        p(1.0, 0.03),
        fold(0.55, 0.06),
        p(0.5, head - 0.02),
        fold(0.85, head),
        p(0.85, 0.97),
        fold(0.75, 1.0),
        p(0.0, 1.0),
    ]
    .map(|pt| pt.tone(Tone::Metal));
    revolve(&profile, ctx.detail.around(), even).fit(ctx.half)
}
