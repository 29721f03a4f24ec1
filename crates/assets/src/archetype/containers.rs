//! Containers with real walls, so that `inside` is physical: open ones (bowls, baskets, bins)
//! and ones with a hinged lid (boxes, backpacks, cars).

use super::geometry::{span, tub, v};
use super::{Blank, Built};
use behavior_sim::{JointKind, JointSpec, LinkSpec};

/// A bottom and four walls filling the box (variant 0), or a tray-like basin of the same
/// footprint at 60 % of the height (variant 1).
pub(super) fn open(b: &Blank) -> Built {
    let (min, max) = (b.min, b.max);
    if b.variant == 1 {
        b.body(tub(min, v(max.x, max.y, 0.6 * b.h), b.t))
    } else {
        b.body(tub(min, max, b.t))
    }
}

/// An open container with a lid on top, hinged at its back edge (variant 0) or at its
/// right-hand side (variant 1).
pub(super) fn lidded(b: &Blank) -> Built {
    let (min, max, h, t) = (b.min, b.max, b.h, b.t);
    let (anchor, axis) = if b.variant == 0 {
        (v(0.0, max.y, h), v(-1.0, 0.0, 0.0))
    } else {
        (v(max.x, 0.0, h), v(0.0, 1.0, 0.0))
    };
    let lid = LinkSpec {
        name: "lid".into(),
        parts: vec![span(v(min.x, min.y, h), v(max.x, max.y, h + t))],
        parent: None,
        joint: JointSpec::opening(JointKind::Revolute, anchor, axis, 1.9, 1.0),
        density: b.density,
    };
    b.body(tub(min, max, t)).with_link(lid)
}
