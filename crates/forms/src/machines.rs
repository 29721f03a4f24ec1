//! Big things on wheels or legs: a car, a kettle barbecue, an upright vacuum cleaner. A car is
//! built at its true size (round wheels under a long body); the others in a frame of their own
//! and stretched to fill their box.

use crate::extrude::prism_across_y;
use crate::lathe::{even, fold, p, revolve};
use crate::mesh::{Mesh, join};
use crate::rounded::{boxed, rounded_box};
use crate::tone::Tone;
use crate::tube::tube;
use crate::{Ctx, Detail};
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, TAU};

/// A wheel of radius `radius` and width `width` about the y axis, centred at `at`: a dark tyre
/// with a metal hub on both faces.
pub(crate) fn wheel(at: Vector, radius: f32, width: f32, detail: Detail) -> Mesh {
    let profile = [
        p(0.0, 0.0).tone(Tone::Metal),
        fold(0.6, 0.0).tone(Tone::Dark),
        p(0.93, 0.04),
        p(1.0, 0.5),
        p(0.93, 0.96),
        fold(0.6, 1.0).tone(Tone::Metal),
        p(0.0, 1.0),
    ];
    let mut made = revolve(&profile, detail.around(), even);
    made.stretch(
        Vector::new(radius, radius, width),
        Vector::new(0.0, 0.0, -0.5 * width),
    );
    // About x by a quarter turn: the axis (z) now runs along −y.
    made.turn(Rotation::from_rotation_x(FRAC_PI_2), at);
    made
}

/// A car, its front toward +x, built as a van: a rounded body on four wheels and a cabin of
/// dark glass up to the top of the box, divided into windows by pillars in the body's colour,
/// its windscreen sloping toward the front; headlights at the front and red lights at the
/// back. (A car here is a lidded box whose lid is its roof, lying over the whole body: a
/// cabin over part of it would leave the roof overhanging a bonnet.)
pub(crate) fn car(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let rows = ctx.detail.bevel_rows();
    let height = 2.0 * h.z;
    let radius = (0.22 * height).min(0.45 * h.y).min(0.2 * h.x);
    let width = (0.28 * radius).min(0.12 * h.y);
    let floor = -h.z;
    let sill = floor + 0.5 * radius;
    let belt = floor + ctx.dice.between(0.5, 0.58) * height;
    let lower = Vector::new(h.x, h.y - 0.5 * width, 0.5 * (belt - sill));
    let mut pieces = vec![rounded_box(
        Vector::new(0.0, 0.0, 0.5 * (belt + sill)),
        lower,
        0.45 * lower.z,
        rows,
        Tone::Body,
    )];
    let slope = ctx.dice.between(0.1, 0.2);
    let glass = 0.97 * lower.y;
    let cabin = [
        (-0.97 * h.x, belt - 0.01 * height),
        (0.97 * h.x, belt - 0.01 * height),
        ((0.97 - slope) * h.x, h.z),
        (-0.95 * h.x, h.z),
    ];
    pieces.push(prism_across_y(&cabin, (-glass, glass), Tone::Dark));
    // Pillars across the cabin, standing a little proud of the glass, back to front.
    let pillar = 0.035 * h.x;
    for x in [-0.93, -0.35, 0.25] {
        pieces.push(rounded_box(
            Vector::new(x * h.x, 0.0, 0.5 * (belt + h.z)),
            Vector::new(pillar, lower.y, 0.5 * (h.z - belt)),
            0.5 * pillar,
            rows,
            Tone::Body,
        ));
    }
    for x in [-0.64 * h.x, 0.62 * h.x] {
        for side in [-1.0, 1.0] {
            let at = Vector::new(x, side * (h.y - 0.5 * width), floor + radius);
            pieces.push(wheel(at, radius, width, ctx.detail));
        }
    }
    if ctx.detail == Detail::Fine {
        let lamp = Vector::new(0.01 * h.x, 0.12 * h.y, 0.05 * height);
        let z = belt - 0.25 * (belt - sill);
        for side in [-1.0, 1.0] {
            let y = side * 0.68 * h.y;
            let front_lamp = Vector::new(h.x - lamp.x, y, z);
            let back_lamp = Vector::new(-h.x + lamp.x, y, z);
            pieces.push(rounded_box(front_lamp, lamp, 0.5 * lamp.x, 1, Tone::Light));
            pieces.push(rounded_box(back_lamp, lamp, 0.5 * lamp.x, 1, Tone::Clay));
        }
    }
    join(pieces)
}

/// A kettle barbecue: a round bowl and a domed lid meeting at a dark seam, a handle on the
/// lid, three splayed legs braced by a rack.
pub(crate) fn grill(ctx: Ctx) -> Mesh {
    let seam = ctx.dice.between(0.7, 0.76);
    let kettle = [
        p(0.0, 0.5),
        p(0.45, 0.52),
        p(0.8, 0.57),
        p(0.97, seam - 0.08),
        fold(1.0, seam).tone(Tone::Dark),
        fold(1.0, seam + 0.02).tone(Tone::Body),
        p(0.95, seam + 0.1),
        p(0.75, 0.92),
        p(0.4, 0.96),
        p(0.0, 0.97),
    ];
    let sides = (ctx.detail.around() / 3).max(6);
    let leg = |angle: f32, z: f32| {
        let r = 0.95 - 0.4 * (z / 0.56);
        Vector::new(r * angle.cos(), r * angle.sin(), z)
    };
    let mut pieces = vec![revolve(&kettle, ctx.detail.around(), even)];
    let angles = [0.25, 0.25 + 1.0 / 3.0, 0.25 + 2.0 / 3.0].map(|a| TAU * a);
    for (k, &a) in angles.iter().enumerate() {
        let path = [leg(a, 0.0), leg(a, 0.56)];
        pieces.push(tube(&path, sides, |_, _| 0.03, Tone::Dark));
        let next = angles[(k + 1) % 3];
        // Ending inside the legs: two ends at one point would make an open seam.
        let (from, to) = (leg(a, 0.2), leg(next, 0.2));
        let rack = [from + (to - from) * 0.03, to + (from - to) * 0.03];
        pieces.push(tube(&rack, sides, |_, _| 0.015, Tone::Metal));
    }
    pieces.push(rounded_box(
        Vector::new(0.0, 0.0, 0.985),
        Vector::new(0.16, 0.04, 0.015),
        0.01,
        ctx.detail.bevel_rows(),
        Tone::Dark,
    ));
    join(pieces).fit(ctx.half)
}

/// An upright vacuum cleaner: a wide floor head toward −y with a dark bumper, a rounded body
/// with a dark dust bin behind it on two wheels, a pole and a grip at the top.
pub(crate) fn vacuum(ctx: Ctx) -> Mesh {
    let rows = ctx.detail.bevel_rows();
    let lean = ctx.dice.between(0.05, 0.2);
    let boxed = |centre, half, radius, tone| boxed(centre, half, radius, rows, tone);
    let sides = (ctx.detail.around() / 2).max(4);
    let wheel_at = |x: f32| Vector::new(x, 0.72, 0.09);
    let mut pieces = vec![
        boxed([0.0, -0.35, 0.06], [1.0, 0.6, 0.06], 0.04, Tone::Body),
        boxed([0.0, -0.93, 0.05], [0.97, 0.05, 0.045], 0.02, Tone::Dark),
        boxed([0.0, 0.45, 0.4], [0.55, 0.4, 0.3], 0.2, Tone::Body),
        boxed([0.0, 0.02, 0.42], [0.38, 0.1, 0.2], 0.06, Tone::Dark),
        boxed(
            [0.0, 0.6 + lean, 0.965],
            [0.22, 0.1, 0.035],
            0.03,
            Tone::Dark,
        ),
    ];
    let pole = [
        Vector::new(0.0, 0.5, 0.66),
        Vector::new(0.0, 0.6 + lean, 0.95),
    ];
    pieces.push(tube(&pole, sides, |_, _| 0.05, Tone::Metal));
    for x in [-0.85, 0.85] {
        let mut w = wheel(Vector::ZERO, 0.09, 0.15, ctx.detail);
        // The wheel's axis from y to x.
        w.turn(Rotation::from_rotation_z(FRAC_PI_2), wheel_at(x));
        pieces.push(w);
    }
    join(pieces).fit(ctx.half)
}
