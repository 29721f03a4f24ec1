//! Robot-relative predicates, as the original's object states (iGibson 2.0.3's `object_states/`),
//! for metrics and primitives. Each is computed from geometry now, with no memo.
//!
//! - in hand: a hand holds the object (any of its bodies) by an assisted grasp;
//! - in reach: the centre of the object's box is less than [`REACH_DISTANCE`] from the body's
//!   origin (the original measures from the object's centre of mass; our objects' origins may
//!   sit at their bottom, so the box centre is the better stand-in);
//! - in the same room: the room at the body's (x, y) is the room at the object's box centre,
//!   compared as room instances. The original compares the robot's room *instance* with a movable
//!   object's room *type*, so it is always false for movable objects (a documented bug we do not
//!   reproduce);
//! - in the field of view: **a geometric approximation** until cameras exist. The original asks
//!   whether any pixel of the object shows in an instance-segmentation image rendered from the
//!   eye (120° × 120°). Here: the centre of the object's box lies in the eye's 120° × 120° view
//!   pyramid, and a ray from the eye to it meets nothing but the object (or nothing: looking
//!   into an open box). An object whose centre is hidden while an edge shows counts as out of view.
//!
//! A sliced object answers as either of its halves.

use behavior_sim::{ObjectId, QueryFilter, World};
use rapier3d::math::{Pose, Vector};

/// Objects nearer than this to the body are in reach, m.
pub const REACH_DISTANCE: f32 = 2.0;
/// The eye's field of view, horizontal and vertical, rad (120°).
pub const EYE_FOV: f32 = 2.0 * std::f32::consts::FRAC_PI_3;

/// The object, or its halves if it was sliced.
fn pieces(world: &World, id: ObjectId) -> Vec<ObjectId> {
    match world.bodies().object(id).replaced_by {
        Some(halves) if !world.bodies().object(id).is_present() => halves.to_vec(),
        _ => vec![id],
    }
}

fn centre(world: &World, id: ObjectId) -> Vector {
    world.bodies().aabb(id).center()
}

/// Whether the object is within reach of a body at `at`.
pub(crate) fn in_reach(world: &World, at: Vector, object: ObjectId) -> bool {
    pieces(world, object)
        .into_iter()
        .any(|p| (centre(world, p) - at).length() < REACH_DISTANCE)
}

/// Whether the object is in the room that contains `at`.
pub(crate) fn in_same_room(world: &World, at: Vector, object: ObjectId) -> bool {
    let Some(here) = world.relations().room_at(at.x, at.y) else {
        return false;
    };
    pieces(world, object).into_iter().any(|p| {
        let c = centre(world, p);
        world
            .relations()
            .room_at(c.x, c.y)
            .is_some_and(|r| (r.kind, r.instance) == (here.kind, here.instance))
    })
}

/// Whether the object is seen from an eye at `eye` (see the module docs); `own` are the robot's
/// objects, which do not hide anything.
pub(crate) fn in_view(world: &World, eye: Pose, object: ObjectId, own: &[ObjectId]) -> bool {
    let filter = QueryFilter::excluding(own);
    let half = (0.5 * EYE_FOV).tan();
    let pieces = pieces(world, object);
    pieces.iter().any(|&p| {
        let target = centre(world, p);
        let local = eye.inverse_transform_point(target);
        let inside =
            local.x > 0.0 && local.y.abs() <= local.x * half && local.z.abs() <= local.x * half;
        if !inside {
            return false;
        }
        let direction = target - eye.translation;
        let hit = world
            .query()
            .cast_ray(eye.translation, direction, direction.length(), &filter);
        match hit {
            Ok(None) => true,
            Ok(Some(hit)) => hit.body.is_some_and(|b| pieces.contains(&b.object)),
            Err(_) => false,
        }
    })
}
