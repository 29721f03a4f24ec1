//! The BehaviorRobot's body and eye, and where its hands and eye may go relative to the body
//! (iGibson 2.0.3's `robots/behavior_robot.py`, tracked mode, the default).
//!
//! The body is a capsule of the original's bounding box (0.5 × 0.5 × 1.0 m) and mass (15 kg),
//! floating with its origin at [`BODY_HEIGHT`] above the floor by default. The eye is a frame,
//! not a body: the original's eye is a massless link teleported every step, which collides with
//! nothing, so nothing is lost by not simulating it. The head the eye looks out of is drawn, not
//! simulated either: a [`Ghost`] of the body, put round the eye after every step.

use crate::hand::Side;
use behavior_core::AGENT_SYNSET;
use behavior_sim::{BodyKind, Form, Ghost, Material, ObjectSpec, Part, Primitive, Visual};
use rapier3d::math::{Pose, Vector};

/// The body's mass, kg.
pub const BODY_MASS: f32 = 15.0;
/// The body capsule's radius, m (half the original's 0.5 m bounding box).
pub const BODY_RADIUS: f32 = 0.25;
/// The body capsule's total height, m (the original's bounding box).
pub const BODY_LENGTH: f32 = 1.0;
/// Height of the body's origin above the floor in the original's episodes, m (iGibson 2.0.3's
/// `initial_z_offset`): the capsule then spans 0.2–1.2 m, clear of the floor.
pub const BODY_HEIGHT: f32 = 0.7;
/// How far a hand may be from its shoulder, m.
pub const HAND_REACH: f32 = 1.2;
/// The body's and head's colour (sRGB).
const BODY_COLOR: [u8; 3] = [200, 204, 212];
/// How far the eye may be from the neck, m.
pub const EYE_REACH: f32 = 0.5;

/// A shoulder, in the body frame: the centre of its hand's reach sphere. (The original's
/// constants for tracked and untracked bodies are swapped in its code, twice, so that the net
/// effect is z = +0.3; this is that effect — iGibson 2.0.3's `robots/behavior_robot.py`.)
pub(crate) fn shoulder(side: Side) -> Vector {
    Vector::new(-0.15, side.sign() * 0.15, 0.3)
}

/// The neck, in the body frame: the centre of the eye's reach sphere.
pub(crate) const NECK: Vector = Vector::new(-0.15, 0.0, 0.3);

/// The eye's starting pose in the body frame: looking along the body's +x.
pub(crate) fn eye_rest() -> Pose {
    Pose::from_translation(Vector::new(0.05, 0.0, 0.4))
}

/// Half the head's size, m: about the original avatar's head.
pub const HEAD_HALF: Vector = Vector::new(0.1, 0.085, 0.11);

/// The head's centre in the eye's frame: the eye looks out of the front of the head, 4 cm
/// behind its face and a little above its middle, inside its box (a camera inside a shape does
/// not draw it, so the eye sees past its own head).
pub(crate) fn head_from_eye() -> Pose {
    Pose::from_translation(Vector::new(-0.06, 0.0, -0.03))
}

/// The head round an eye at `eye` (in the world): drawn in the body's colour, out of the physics.
pub(crate) fn head_round(eye: Pose) -> Ghost {
    Ghost {
        form: Form::Head,
        half_extents: HEAD_HALF,
        visual: Visual {
            color: BODY_COLOR,
            material: Material::Plastic,
        },
        pose: eye * head_from_eye(),
    }
}

/// A hand's starting pose in the body frame: palm down, fingers forward.
pub(crate) fn hand_rest(side: Side) -> Pose {
    Pose::from_translation(Vector::new(0.1, side.sign() * 0.12, 0.05))
}

/// The body capsule, upright, centred on the body's origin.
pub(crate) fn body_shape() -> Primitive {
    Primitive::Capsule {
        radius: BODY_RADIUS,
        half_height: 0.5 * BODY_LENGTH - BODY_RADIUS,
    }
}

/// The spec of the body standing at `pose`.
pub(crate) fn body_spec(name: &str, pose: Pose) -> ObjectSpec {
    let pi = std::f32::consts::PI;
    let (r, cylinder) = (BODY_RADIUS, BODY_LENGTH - 2.0 * BODY_RADIUS);
    let volume = pi * r * r * cylinder + 4.0 / 3.0 * pi * r.powi(3);
    let mut spec = ObjectSpec::new(name, AGENT_SYNSET, vec![Part::new(body_shape())])
        .body(BodyKind::KinematicVelocity)
        .looks(BODY_COLOR, Material::Plastic);
    // Drawn as a trunk with shoulders over its capsule, as the original's body mesh.
    spec.form = Form::Torso;
    spec.pose = pose;
    spec.density = BODY_MASS / volume;
    spec
}

/// `point` moved onto the sphere of `radius` around `centre` if it lies outside.
pub(crate) fn within(point: Vector, centre: Vector, radius: f32) -> Vector {
    let offset = point - centre;
    let distance = offset.length();
    if distance > radius {
        centre + offset * (radius / distance)
    } else {
        point
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::World;

    #[test]
    fn the_body_weighs_fifteen_kilograms_and_the_hands_start_within_reach() {
        let mut world = World::default();
        let spec = body_spec("body", Pose::IDENTITY).body(BodyKind::Dynamic);
        let body = world.add(spec).unwrap();
        assert!((world.bodies().mass(body) - BODY_MASS).abs() < 1e-3);
        for side in Side::BOTH {
            let hand = hand_rest(side).translation;
            assert!((hand - shoulder(side)).length() < HAND_REACH);
        }
        assert!((eye_rest().translation - NECK).length() < EYE_REACH);
        let far = within(Vector::new(5.0, 0.0, 0.0), Vector::ZERO, 1.2);
        assert!((far - Vector::new(1.2, 0.0, 0.0)).length() < 1e-6);
    }
}
