//! A BehaviorRobot hand, built from our own shapes with the original's mass: one dynamic body of
//! 2 kg (the original's 1 kg palm and five fingers of two 0.1 kg phalanges), made of a palm (a
//! box) and five fingers (capsules), friction 2.5 (iGibson 2.0.3's `robots/behavior_robot.py`). Its
//! mass is spread over the shapes by volume.
//!
//! The hand's frame: x along the fingers, y to the hand's left, z out of its back; the palm faces
//! −z. At rest the fingers lie straight in the palm's plane and the thumb sticks out sideways and
//! forward. Each finger turns about its knuckle toward `trigger × closed`: 1.2 rad for the
//! fingers, 0.6 rad for the thumb (the original's close positions), at most [`FINGER_SPEED`]. The
//! fingers close toward −z, the thumb swings down beside the palm.
//!
//! Why the fingers are shapes of the hand's body, turned in place each substep
//! ([`behavior_sim::Bodies::set_part_offset`]), rather than links on joints as the original's:
//! the fingers do not hold anything — the assisted grasp does ([`crate::GraspRules`]) — so they
//! are there to be seen and to touch, and ten jointed finger bodies were most of what a moving
//! robot cost the solver (about 40 % of a step under random actions). The price: a finger does
//! not bend back against what it presses on; the hand as a whole yields instead (its servo is
//! force-limited, see `follow.rs`), and a closing finger pushes a movable object aside.
//!
//! The palm is servoed onto its target (see `follow.rs`), carrying its fingers.

use behavior_core::AGENT_SYNSET;
use behavior_sim::{Form, Material, ObjectId, ObjectSpec, Part, Primitive, World};
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

/// The hand's mass, kg: the original's palm (1 kg) and five fingers (0.2 kg each).
pub const HAND_MASS: f32 = 2.0;
/// Friction coefficient of the palm and fingers.
pub const HAND_FRICTION: f32 = 2.5;
/// A finger's angle at a full trigger, rad.
pub const FINGER_CLOSED: f32 = 1.2;
/// The thumb's angle at a full trigger, rad.
pub const THUMB_CLOSED: f32 = 0.6;
/// How fast a finger turns, rad/s: closed in 0.2 s. Faster than a trigger can ask (its
/// fraction changes by at most 0.05 a step), so it binds only when the trigger jumps (a restored
/// or reset robot).
pub const FINGER_SPEED: f32 = 6.0;
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
/// Each finger's distance from the hand's middle line, index first, toward the thumb's side.
const FINGER_OFFSETS: [f32; 4] = [0.0315, 0.0105, -0.0105, -0.0315];

/// The angle a trigger fraction asks of a finger.
pub(crate) fn closed_angle(finger: usize, trigger: f32) -> f32 {
    let closed = if finger == THUMB {
        THUMB_CLOSED
    } else {
        FINGER_CLOSED
    };
    trigger * closed
}

/// Where a finger starts and which way it points, in the hand frame at rest.
fn finger_line(side: Side, finger: usize) -> (Vector, Vector) {
    let t = side.thumb_sign();
    if finger == THUMB {
        let direction = Vector::new(0.5, t * 0.866_025_4, 0.0);
        (Vector::new(-0.01, t * PALM_HALF.y, 0.0), direction)
    } else {
        let knuckle = Vector::new(PALM_HALF.x, t * FINGER_OFFSETS[finger], 0.0);
        (knuckle, Vector::X)
    }
}

fn finger_size(finger: usize) -> (f32, f32) {
    if finger == THUMB {
        (THUMB_LENGTH, THUMB_RADIUS)
    } else {
        (FINGER_LENGTH, FINGER_RADIUS)
    }
}

/// The middle of the palm's inner face, in the hand frame: where grasps are measured from.
pub(crate) const PALM_CENTRE: Vector = Vector::new(0.0, 0.0, -PALM_HALF.z);
/// Near the wrist on the palm's inner face.
pub(crate) const PALM_BASE: Vector = Vector::new(-0.7 * PALM_HALF.x, 0.0, -PALM_HALF.z);

/// The part index of a finger's capsule in the hand's body: the palm is part 0.
fn part(finger: usize) -> usize {
    1 + finger
}

/// A finger's knuckle and the axis it turns about, in the hand frame. Fingers curl about the
/// hand's y axis toward −z; the thumb turns about x, down beside the palm.
fn knuckle(side: Side, finger: usize) -> (Vector, Vector) {
    let (start, _) = finger_line(side, finger);
    let axis = if finger == THUMB {
        Vector::new(-side.thumb_sign(), 0.0, 0.0)
    } else {
        Vector::Y
    };
    (start, axis)
}

/// A finger capsule's pose in the hand frame, turned `angle` about its knuckle. The capsule runs
/// along its own z, from the knuckle to the tip.
fn finger_offset(side: Side, finger: usize, angle: f32) -> Pose {
    let (start, direction) = finger_line(side, finger);
    let (anchor, axis) = knuckle(side, finger);
    let centre = start + direction * (0.5 * finger_size(finger).0);
    let rest = Pose::from_parts(centre, Rotation::from_rotation_arc(Vector::Z, direction));
    let turn = Rotation::from_axis_angle(axis, angle);
    let about_knuckle = Pose::from_parts(anchor - turn * anchor, turn);
    about_knuckle * rest
}

/// A point on a finger's line, `along` its length from the knuckle (0) to the tip (1), in the
/// frame of the finger's capsule.
fn on_finger(finger: usize, along: f32) -> Vector {
    Vector::new(0.0, 0.0, (along - 0.5) * finger_size(finger).0)
}

fn finger_part(side: Side, finger: usize) -> Part {
    let (length, radius) = finger_size(finger);
    Part {
        primitive: Primitive::Capsule {
            radius,
            half_height: 0.5 * length - radius,
        },
        offset: finger_offset(side, finger, 0.0),
        visual: None,
        form: Form::Primitive,
    }
}

fn capsule_volume(length: f32, radius: f32) -> f32 {
    let pi = std::f32::consts::PI;
    pi * radius * radius * (length - 2.0 * radius) + 4.0 / 3.0 * pi * radius.powi(3)
}

/// The hand's volume: the palm and its five fingers, m³.
fn hand_volume() -> f32 {
    let palm = 8.0 * PALM_HALF.x * PALM_HALF.y * PALM_HALF.z;
    let fingers: f32 = (0..FINGERS)
        .map(|f| {
            let (length, radius) = finger_size(f);
            capsule_volume(length, radius)
        })
        .sum();
    palm + fingers
}

/// The spec of a hand standing at `pose`, its fingers straight.
pub(crate) fn hand_spec(name: &str, side: Side, pose: Pose) -> ObjectSpec {
    let palm = Part::new(Primitive::Box {
        half_extents: PALM_HALF,
    });
    let fingers = (0..FINGERS).map(|f| finger_part(side, f));
    let mut spec = ObjectSpec::new(
        name,
        AGENT_SYNSET,
        std::iter::once(palm).chain(fingers).collect(),
    )
    .looks([230, 190, 160], Material::Plastic);
    spec.pose = pose;
    spec.density = HAND_MASS / hand_volume();
    spec.friction = HAND_FRICTION;
    spec
}

/// The shape that must not move into fixed things: the palm with its fingers straight, and its
/// pose in the hand frame. A planner that keeps this shape clear of fixed bodies plans nothing
/// the robot refuses (see `motion.rs`).
pub fn sweep_shape() -> (Primitive, Pose) {
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

/// A hand's fingers: their angles, and how they turn toward what the trigger asks.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Fingers {
    /// Each finger's angle now, rad: index, middle, ring, little finger, thumb.
    pub(crate) angles: [f32; FINGERS],
}

impl Fingers {
    /// Straight.
    pub(crate) const OPEN: Fingers = Fingers {
        angles: [0.0; FINGERS],
    };

    /// The angles a trigger fraction asks for.
    pub(crate) fn for_trigger(trigger: f32) -> [f32; FINGERS] {
        std::array::from_fn(|f| closed_angle(f, trigger))
    }

    /// Turns each finger toward `wanted` by at most [`FINGER_SPEED`] · `dt`, and moves the
    /// hand's capsules to match; whether any finger moved.
    pub(crate) fn advance(
        &mut self,
        world: &mut World,
        (hand, side): (ObjectId, Side),
        wanted: &[f32; FINGERS],
        dt: f32,
    ) -> bool {
        if self.angles == *wanted {
            return false;
        }
        let most = FINGER_SPEED * dt;
        for (f, (angle, &goal)) in self.angles.iter_mut().zip(wanted).enumerate() {
            if *angle == goal {
                continue;
            }
            *angle += (goal - *angle).clamp(-most, most);
            // A finite angle makes a finite pose of an existing part: the world cannot refuse.
            let _ =
                world
                    .bodies_mut()
                    .set_part_offset(hand, part(f), finger_offset(side, f, *angle));
        }
        true
    }
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
    /// Where the hand's fingers are in the world (read from its parts, so always as built).
    pub(crate) fn of(world: &World, hand: ObjectId) -> HandPoints {
        let palm = world.bodies().pose(hand);
        let parts = &world.bodies().object(hand).parts;
        let at = |f: usize, along: f32| {
            let finger = palm * parts[part(f)].offset;
            finger.transform_point(on_finger(f, along))
        };
        HandPoints {
            palm_centre: palm.transform_point(PALM_CENTRE),
            origins: [
                palm.transform_point(PALM_CENTRE),
                palm.transform_point(PALM_BASE),
                at(THUMB, 0.5),
                at(THUMB, 1.0),
            ],
            tips: std::array::from_fn(|f| at(f, 1.0)),
        }
    }

    /// The points that press buttons: the palm centre and the five fingertips.
    pub(crate) fn pressing(world: &World, hand: ObjectId) -> [Vector; 6] {
        let points = HandPoints::of(world, hand);
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
        assert!((world.bodies().mass(hand) - HAND_MASS).abs() < 1e-4);
        assert_eq!(world.bodies().object(hand).parts.len(), 1 + FINGERS);
        assert!(world.bodies().object(hand).links.is_empty());
        // The thumb of a right hand, palm down, is on its left.
        let points = HandPoints::of(&world, hand);
        assert!(points.origins[3].y > 0.0);
        // A capsule 0.08 m long of radius 0.009: a 0.062 m cylinder and a ball.
        let expected =
            std::f32::consts::PI * (0.009f32.powi(2) * 0.062 + 4.0 / 3.0 * 0.009f32.powi(3));
        assert!((capsule_volume(0.08, 0.009) - expected).abs() < 1e-9);
    }

    #[test]
    fn a_finger_turns_about_its_knuckle_toward_the_palm_side() {
        for side in Side::BOTH {
            for f in 0..FINGERS {
                let (anchor, _) = knuckle(side, f);
                let tip =
                    |angle: f32| finger_offset(side, f, angle).transform_point(on_finger(f, 1.0));
                let knuckle_point = finger_offset(side, f, 0.9).transform_point(on_finger(f, 0.0));
                // The knuckle stays; the tip keeps its distance from it and goes toward −z.
                assert!((knuckle_point - anchor).length() < 1e-6);
                let length = finger_size(f).0;
                assert!(((tip(0.9) - anchor).length() - length).abs() < 1e-5);
                assert!(
                    tip(0.9).z < -0.5 * length,
                    "{side:?} finger {f}: {:?}",
                    tip(0.9)
                );
                assert!(tip(0.0).z.abs() < 1e-6);
            }
        }
    }
}
