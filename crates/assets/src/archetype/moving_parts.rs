//! Links on joints that open an object: side-hinged doors, drop-down doors and drawers. Each is
//! given in the object's frame, closed (at joint position 0), hanging from the object's body,
//! its front drawn in the form given (a door with its pull, a glazed door, a drawer's front).

use super::geometry::{span, tub, v};
use behavior_sim::{Form, JointKind, JointSpec, LinkSpec};
use rapier3d::math::Vector;

/// The gap a door leaves at its free edge, m: a door as wide as its carcass, its free edge flush
/// with a neighbour that stands out past it (a cabinet deeper than the fridge beside it),
/// scrapes the neighbour's corner as it starts to swing and jams there, where a hand pulls it.
const DOOR_GAP: f32 = 0.005;

/// A door covering the front of `min..max` but a [`DOOR_GAP`] at its free edge, hinged on its
/// left edge (opens outward, to −y), drawn as `form`.
pub(super) fn side_door(form: Form, min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    let edge = max.x - DOOR_GAP;
    LinkSpec {
        name: "door".into(),
        parts: vec![span(v(min.x, min.y - t, min.z), v(edge, min.y, max.z)).with_form(form)],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(min.x, min.y - t, 0.0),
            v(0.0, 0.0, -1.0),
            1.9,
            2.0,
        ),
        density,
    }
}

/// A door covering the front of `min..max` but a [`DOOR_GAP`] at its free (top) edge, hinged
/// at its bottom edge (ovens, dishwashers), drawn as `form`.
pub(super) fn drop_door(form: Form, min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    let edge = max.z - DOOR_GAP;
    LinkSpec {
        name: "door".into(),
        parts: vec![span(v(min.x, min.y - t, min.z), v(max.x, min.y, edge)).with_form(form)],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.0, min.y - t, min.z),
            v(1.0, 0.0, 0.0),
            1.5,
            2.0,
        ),
        density,
    }
}

/// A drawer filling `min..max` of a carcass, sliding out to −y.
pub(super) fn drawer(name: &str, min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    let mut parts = tub(
        v(min.x + t, min.y, min.z + t),
        v(max.x - t, max.y - t, max.z - t),
        t,
    );
    // Its front panel closes the carcass.
    parts.push(
        span(v(min.x, min.y - t, min.z), v(max.x, min.y, max.z)).with_form(Form::DrawerFront),
    );
    LinkSpec {
        name: name.into(),
        parts,
        parent: None,
        joint: JointSpec::opening(
            JointKind::Prismatic,
            Vector::ZERO,
            v(0.0, -1.0, 0.0),
            0.8 * (max.y - min.y),
            2.0,
        ),
        density,
    }
}
