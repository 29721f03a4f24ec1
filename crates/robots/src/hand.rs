//! A BehaviorRobot hand, built from our own shapes with the original's masses: a palm (a box of
//! 1 kg) and five fingers (capsules of 0.2 kg each: the original's two 0.1 kg phalanges per
//! finger, merged), friction 2.5 (reference §2.1, §2.3).
//!
//! The hand's frame: x along the fingers, y to the hand's left, z out of its back; the palm faces
//! −z. At rest the fingers lie straight in the palm's plane and the thumb sticks out sideways and
//! forward. Each finger turns on one revolute joint at its knuckle, position-driven (at most
//! 3 N·m, the original's motor force) toward `trigger × closed`: 1.2 rad for the fingers, 0.6 rad
//! for the thumb (the original's close positions). The fingers close toward −z, the thumb swings
//! down beside the palm.
//!
//! Why one joint per finger and not the original's two: every finger joint is a body and a
//! constraint the solver pays for in every substep while the hand moves, and the fingers do not
//! hold anything — the assisted grasp does ([`crate::GraspRules`]). Five joints per hand keep the
//! look (fingers close with the trigger, touch what they close on) at half the cost.
//!
//! The palm is a dynamic body servoed onto its target (see `follow.rs`); the fingers are dynamic
//! links on impulse joints, so they yield against what they press on (a table, the object being
//! grasped).

use behavior_core::AGENT_SYNSET;
use behavior_sim::{
    BodyRef, JointKind, JointModel, JointSpec, LinkSpec, Material, ObjectId, ObjectSpec, Part,
    Primitive, World,
};
use rapier3d::math::{Pose, Rotation, Vector};

/// Which hand.
#[derive(
    serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash,
)]
pub enum Side {
    /// The left hand (first in actions and proprioception).
    Left,
    /// The right hand.
    Right,
}

impl Side {
    /// Both, left first.
    pub const BOTH: [Side; 2] = [Side::Left, Side::Right];

    /// 0 for the left hand, 1 for the right.
    pub fn index(self) -> usize {
        match self {
            Side::Left => 0,
            Side::Right => 1,
        }
    }

    /// +1 for the left (the body's +y side), −1 for the right.
    pub(crate) fn sign(self) -> f32 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }

    /// The side of the hand its thumb is on, palm down: toward the body's middle.
    fn thumb_sign(self) -> f32 {
        -self.sign()
    }

    /// The other hand.
    pub fn other(self) -> Side {
        match self {
            Side::Left => Side::Right,
            Side::Right => Side::Left,
        }
    }
}

/// The palm's mass, kg.
pub const PALM_MASS: f32 = 1.0;
/// Each finger's mass, kg (two phalanges of 0.1 kg).
pub const FINGER_MASS: f32 = 0.2;
/// Friction coefficient of the palm and fingers.
pub const HAND_FRICTION: f32 = 2.5;
/// A finger's joint angle at a full trigger, rad.
pub const FINGER_CLOSED: f32 = 1.2;
/// The thumb's joint angle at a full trigger, rad.
pub const THUMB_CLOSED: f32 = 0.6;
/// The most torque a finger's drive applies, N·m.
pub const FINGER_TORQUE: f32 = 3.0;
/// Finger links: index, middle, ring, little finger, then the thumb.
pub const FINGERS: usize = 5;
/// The thumb's link index.
pub(crate) const THUMB: usize = 4;

/// Half the palm's size along x, y and z.
pub(crate) const PALM_HALF: Vector = Vector::new(0.05, 0.045, 0.015);
const FINGER_LENGTH: f32 = 0.08;
const FINGER_RADIUS: f32 = 0.009;
const THUMB_LENGTH: f32 = 0.06;
const THUMB_RADIUS: f32 = 0.01;
/// Fingers may be bent back this far by what they press on, rad.
const HYPEREXTENSION: f32 = -0.3;
/// Finger drive gains: stiff enough to hold a finger against gravity within 0.02 rad, damped
/// near critically for a finger's inertia about its knuckle (about 4·10⁻⁴ kg·m²).
pub(crate) const FINGER_STIFFNESS: f32 = 5.0;
pub(crate) const FINGER_DAMPING: f32 = 0.1;
/// Each finger's distance from the hand's middle line, index first, toward the thumb's side.
const FINGER_OFFSETS: [f32; 4] = [0.0315, 0.0105, -0.0105, -0.0315];

/// The joint angle a trigger fraction asks of a finger link.
pub(crate) fn closed_angle(link: usize, trigger: f32) -> f32 {
    let closed = if link == THUMB {
        THUMB_CLOSED
    } else {
        FINGER_CLOSED
    };
    trigger * closed
}

/// Where a finger starts and which way it points, in the hand frame at rest.
fn finger_line(side: Side, link: usize) -> (Vector, Vector) {
    let t = side.thumb_sign();
    if link == THUMB {
        let direction = Vector::new(0.5, t * 0.866_025_4, 0.0);
        (Vector::new(-0.01, t * PALM_HALF.y, 0.0), direction)
    } else {
        let knuckle = Vector::new(PALM_HALF.x, t * FINGER_OFFSETS[link], 0.0);
        (knuckle, Vector::X)
    }
}

fn finger_size(link: usize) -> (f32, f32) {
    if link == THUMB {
        (THUMB_LENGTH, THUMB_RADIUS)
    } else {
        (FINGER_LENGTH, FINGER_RADIUS)
    }
}

/// A finger's tip in the hand frame at rest (its link's frame).
pub(crate) fn fingertip(side: Side, link: usize) -> Vector {
    let (start, direction) = finger_line(side, link);
    start + direction * finger_size(link).0
}

/// A point halfway along the thumb, in its link's frame.
pub(crate) fn thumb_middle(side: Side) -> Vector {
    let (start, direction) = finger_line(side, THUMB);
    start + direction * (0.5 * THUMB_LENGTH)
}

/// The middle of the palm's inner face, in the hand frame: where grasps are measured from.
pub(crate) const PALM_CENTRE: Vector = Vector::new(0.0, 0.0, -PALM_HALF.z);
/// Near the wrist on the palm's inner face.
pub(crate) const PALM_BASE: Vector = Vector::new(-0.7 * PALM_HALF.x, 0.0, -PALM_HALF.z);

fn capsule_volume(length: f32, radius: f32) -> f32 {
    let pi = std::f32::consts::PI;
    pi * radius * radius * (length - 2.0 * radius) + 4.0 / 3.0 * pi * radius.powi(3)
}

/// A finger's centre of mass in the hand frame at rest (its link's frame).
pub(crate) fn finger_centre(side: Side, link: usize) -> Vector {
    let (start, direction) = finger_line(side, link);
    start + direction * (0.5 * finger_size(link).0)
}

/// A finger joint's anchor and axis in the hand frame. Fingers curl about the hand's y axis
/// toward −z; the thumb turns about x, down beside the palm.
pub(crate) fn finger_joint(side: Side, link: usize) -> (Vector, Vector) {
    let (start, _) = finger_line(side, link);
    let axis = if link == THUMB {
        Vector::new(-side.thumb_sign(), 0.0, 0.0)
    } else {
        Vector::Y
    };
    (start, axis)
}

fn finger_link(side: Side, link: usize) -> LinkSpec {
    let (_, direction) = finger_line(side, link);
    let (length, radius) = finger_size(link);
    let capsule = Primitive::Capsule {
        radius,
        half_height: 0.5 * length - radius,
    };
    let part = Part {
        primitive: capsule,
        offset: Pose::from_parts(
            finger_centre(side, link),
            Rotation::from_rotation_arc(Vector::Z, direction),
        ),
        visual: None,
    };
    let (anchor, axis) = finger_joint(side, link);
    LinkSpec {
        name: ["index", "middle", "ring", "little", "thumb"][link].to_string(),
        parts: vec![part],
        parent: None,
        joint: JointSpec {
            kind: JointKind::Revolute,
            model: JointModel::Impulse,
            anchor,
            axis,
            limits: Some([HYPEREXTENSION, closed_angle(link, 1.0)]),
            damping: 0.0,
        },
        density: FINGER_MASS / capsule_volume(length, radius),
    }
}

/// The spec of a hand standing at `pose`.
pub(crate) fn hand_spec(name: &str, side: Side, pose: Pose) -> ObjectSpec {
    let palm = Primitive::Box {
        half_extents: PALM_HALF,
    };
    let mut spec = ObjectSpec::new(name, AGENT_SYNSET, vec![Part::new(palm)])
        .looks([230, 190, 160], Material::Plastic);
    spec.pose = pose;
    spec.density = PALM_MASS / (8.0 * PALM_HALF.x * PALM_HALF.y * PALM_HALF.z);
    spec.friction = HAND_FRICTION;
    (0..FINGERS).fold(spec, |spec, link| spec.link(finger_link(side, link)))
}

/// The shape that must not move into fixed things: the palm with its fingers straight, and its
/// pose in the hand frame.
pub(crate) fn sweep_shape() -> (Primitive, Pose) {
    let half = Vector::new(
        0.5 * (2.0 * PALM_HALF.x + FINGER_LENGTH),
        PALM_HALF.y,
        PALM_HALF.z,
    );
    let centre = Vector::new(0.5 * FINGER_LENGTH, 0.0, 0.0);
    (
        Primitive::Box { half_extents: half },
        Pose::from_translation(centre),
    )
}

/// Every body of a hand: the palm, then its fingers.
pub(crate) fn bodies(hand: ObjectId) -> impl Iterator<Item = BodyRef> {
    std::iter::once(BodyRef::from(hand)).chain((0..FINGERS).map(move |l| BodyRef::link(hand, l)))
}

/// The hand's points in the world now: the palm centre, and the palm, thumb and fingertip points
/// the assisted grasp casts its rays between.
pub(crate) struct HandPoints {
    /// The middle of the palm's inner face.
    pub(crate) palm_centre: Vector,
    /// Ray origins: the palm's centre and base, the thumb's middle and tip.
    pub(crate) origins: [Vector; 4],
    /// Ray ends: the four fingertips.
    pub(crate) tips: [Vector; 4],
}

impl HandPoints {
    pub(crate) fn of(world: &World, hand: ObjectId, side: Side) -> HandPoints {
        let palm = world.pose(hand);
        let link = |l: usize| world.core().link_pose(hand, l);
        let thumb = link(THUMB);
        HandPoints {
            palm_centre: palm.transform_point(PALM_CENTRE),
            origins: [
                palm.transform_point(PALM_CENTRE),
                palm.transform_point(PALM_BASE),
                thumb.transform_point(thumb_middle(side)),
                thumb.transform_point(fingertip(side, THUMB)),
            ],
            tips: std::array::from_fn(|l| link(l).transform_point(fingertip(side, l))),
        }
    }

    /// The points that press buttons: the palm centre and the five fingertips.
    pub(crate) fn pressing(world: &World, hand: ObjectId, side: Side) -> [Vector; 6] {
        let points = HandPoints::of(world, hand, side);
        let [a, b, c, d] = points.tips;
        [points.palm_centre, a, b, c, d, points.origins[3]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hand_weighs_what_the_original_does() {
        let mut world = World::default();
        let hand = world
            .add(hand_spec("hand", Side::Right, Pose::IDENTITY))
            .unwrap();
        assert!((world.core().mass(hand) - PALM_MASS).abs() < 1e-4);
        assert_eq!(world.object(hand).links.len(), FINGERS);
        // The thumb of a right hand, palm down, is on its left.
        assert!(fingertip(Side::Right, THUMB).y > 0.0);
        assert!(fingertip(Side::Left, THUMB).y < 0.0);
        // A capsule 0.08 m long of radius 0.009: a 0.062 m cylinder and a ball.
        let expected =
            std::f32::consts::PI * (0.009f32.powi(2) * 0.062 + 4.0 / 3.0 * 0.009f32.powi(3));
        assert!((capsule_volume(0.08, 0.009) - expected).abs() < 1e-9);
    }
}
