//! Solid movable things, one primitive each: balls, blocks, cylinders, slabs and rods in their
//! variants, the plain box that countertops and floors are, and the agent's stand-in capsule.

use super::geometry::{chamfered, ellipsoid, hull, prism, span, v};
use super::{Blank, Built};
use behavior_sim::{Form, Part, Primitive};
use rapier3d::math::{Pose, Rotation};

/// A sphere as big as the box allows (variant 0), or an ellipsoid filling the box (variant 1:
/// pears, eggs, lemons).
pub(super) fn ball(b: &Blank) -> Built {
    let (w, d, h) = (b.w, b.d, b.h);
    if b.variant == 0 {
        b.body(vec![Part::at(
            Primitive::Sphere {
                radius: w.min(d).min(h) / 2.0,
            },
            v(0.0, 0.0, w.min(d).min(h) / 2.0),
        )])
    } else {
        b.body(vec![hull(ellipsoid(b.size, |_| true))])
    }
}

/// A box (variant 0), or a worn one with every edge chamfered by a fifth of its thinnest side
/// (variant 1).
pub(super) fn block(b: &Blank) -> Built {
    if b.variant == 1 {
        let (w, d, h) = (b.w, b.d, b.h);
        b.body(vec![hull(chamfered(b.min, b.max, 0.2 * w.min(d).min(h)))])
    } else {
        solid(b)
    }
}

/// A flat box (variant 0) or disc (variant 1).
pub(super) fn slab(b: &Blank) -> Built {
    if b.variant == 1 {
        b.body(vec![standing_cylinder(b)])
    } else {
        solid(b)
    }
}

/// A long box (variant 0), or round in section (variant 1): a capsule lying along x.
pub(super) fn rod(b: &Blank) -> Built {
    if b.variant != 1 {
        return solid(b);
    }
    let radius = b.d.min(b.h) / 2.0;
    let lying = Pose::from_parts(
        v(0.0, 0.0, radius),
        Rotation::from_rotation_y(std::f32::consts::FRAC_PI_2),
    );
    b.body(vec![Part {
        primitive: Primitive::Capsule {
            radius,
            half_height: (b.w / 2.0 - radius).max(0.001),
        },
        offset: lying,
        visual: None,
        form: Form::Primitive,
    }])
}

/// A round cylinder (variant 0), or a faceted one: an octagonal prism (variant 1: jars, tins,
/// candles).
pub(super) fn cylinder(b: &Blank) -> Built {
    if b.variant == 0 {
        b.body(vec![standing_cylinder(b)])
    } else {
        b.body(vec![hull(prism(b.w.min(b.d) / 2.0, b.h, 8, |_| true))])
    }
}

/// The box itself: countertops, floors, and the plain variant of blocks, slabs and rods.
pub(super) fn solid(b: &Blank) -> Built {
    b.body(vec![span(b.min, b.max)])
}

/// An upright capsule standing in for the robot until embodiments exist.
pub(super) fn agent(b: &Blank) -> Built {
    let (w, d, h) = (b.w, b.d, b.h);
    b.body(vec![Part::at(
        Primitive::Capsule {
            radius: w.min(d) / 2.0,
            half_height: (h - w.min(d)).max(0.01) / 2.0,
        },
        v(0.0, 0.0, h / 2.0),
    )])
}

/// The largest upright cylinder in the box.
fn standing_cylinder(b: &Blank) -> Part {
    Part::at(
        Primitive::Cylinder {
            radius: b.w.min(b.d) / 2.0,
            half_height: b.h / 2.0,
        },
        v(0.0, 0.0, b.h / 2.0),
    )
}
