//! Fetch's joints, links and numbers (from Fetch's own URDF), its forward
//! kinematics, and the world objects its parts are built as.
//!
//! Frames as in the URDF: x forward, y left, z up; every link frame sits on its joint, so a
//! chain is a product of "go to the joint's origin, then move along or about its axis". The
//! robot's origin (`base_link`) is on the floor between the wheels.
//!
//! Shapes are our own primitives with the bounding boxes of the real links (Fetch's URDF and its
//! STL meshes): the base a cylinder (raised 3 cm, as iGibson raises its base mesh), the torso and
//! head boxes, the arm segments capsules along x, the palm a box, each finger a pad box. The
//! wheels, the laser and the head camera are frames, not bodies: the wheels lie inside the base's
//! cylinder. The head tilt has no +15° offset (Fetch's URDF; iGibson's own copy adds one).

use crate::kinematic_links::{part_volume, parts_centre};
use behavior_core::AGENT_SYNSET;
use behavior_sim::{
    BodyKind, Form, JointKind, JointModel, JointSpec, LinkSpec, Material, ObjectSpec, Part,
    Primitive,
};
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::FRAC_PI_2;

/// The joints Fetch reports and drives, in iGibson's order (its `ordered_joints`): the order of
/// proprioception.
#[derive(
    serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord,
)]
pub enum FetchJoint {
    /// The right wheel (at −y), continuous.
    RightWheel,
    /// The left wheel (at +y), continuous.
    LeftWheel,
    /// The torso lift, prismatic along z.
    TorsoLift,
    /// Head pan, about z.
    HeadPan,
    /// Head tilt, about y; positive looks down.
    HeadTilt,
    /// Shoulder pan, about z.
    ShoulderPan,
    /// Shoulder lift, about y; positive pitches down.
    ShoulderLift,
    /// Upper-arm roll, about x, continuous.
    UpperarmRoll,
    /// Elbow flex, about y.
    ElbowFlex,
    /// Forearm roll, about x, continuous.
    ForearmRoll,
    /// Wrist flex, about y.
    WristFlex,
    /// Wrist roll, about x, continuous.
    WristRoll,
    /// The right finger (URDF `r_gripper_finger_joint`; it sits at +y), prismatic, 0 closed.
    RightFinger,
    /// The left finger (at −y), prismatic, 0 closed.
    LeftFinger,
}

/// How many joints Fetch reports.
pub const FETCH_JOINTS: usize = 14;

/// One joint's numbers from Fetch's URDF.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointInfo {
    /// The URDF name.
    pub name: &'static str,
    /// Revolute (a continuous joint is revolute without limits) or prismatic.
    pub kind: JointKind,
    /// Where the joint sits in its parent link's frame.
    pub origin: Vector,
    /// The axis in the joint's frame.
    pub axis: Vector,
    /// Lower and upper position, or `None` for a continuous joint.
    pub limits: Option<[f32; 2]>,
    /// rad/s or m/s.
    pub max_velocity: f32,
    /// N·m or N.
    pub max_effort: f32,
}

const fn joint(
    name: &'static str,
    kind: JointKind,
    origin: [f32; 3],
    axis: [f32; 3],
    limits: Option<[f32; 2]>,
    [max_velocity, max_effort]: [f32; 2],
) -> JointInfo {
    JointInfo {
        name,
        kind,
        origin: Vector::new(origin[0], origin[1], origin[2]),
        axis: Vector::new(axis[0], axis[1], axis[2]),
        limits,
        max_velocity,
        max_effort,
    }
}

const REV: JointKind = JointKind::Revolute;
const PRIS: JointKind = JointKind::Prismatic;
const X: [f32; 3] = [1.0, 0.0, 0.0];
const Y: [f32; 3] = [0.0, 1.0, 0.0];
const Z: [f32; 3] = [0.0, 0.0, 1.0];

/// Fetch's joints in [`FetchJoint`] order (Fetch's URDF).
const JOINTS: [JointInfo; FETCH_JOINTS] = [
    joint(
        "r_wheel_joint",
        REV,
        [0.0012914, -0.18738, 0.055325],
        Y,
        None,
        [17.4, 8.85],
    ),
    joint(
        "l_wheel_joint",
        REV,
        [0.0012914, 0.18738, 0.055325],
        Y,
        None,
        [17.4, 8.85],
    ),
    joint(
        "torso_lift_joint",
        PRIS,
        [-0.086875, 0.0, 0.37743],
        Z,
        Some([0.0, 0.38615]),
        [0.1, 450.0],
    ),
    joint(
        "head_pan_joint",
        REV,
        [0.053125, 0.0, 0.603001],
        Z,
        Some([-1.57, 1.57]),
        [1.57, 0.32],
    ),
    joint(
        "head_tilt_joint",
        REV,
        [0.14253, 0.0, 0.057999],
        Y,
        Some([-0.76, 1.45]),
        [1.57, 0.68],
    ),
    joint(
        "shoulder_pan_joint",
        REV,
        [0.119525, 0.0, 0.34858],
        Z,
        Some([-1.6056, 1.6056]),
        [1.256, 33.82],
    ),
    joint(
        "shoulder_lift_joint",
        REV,
        [0.117, 0.0, 0.06],
        Y,
        Some([-1.221, 1.518]),
        [1.454, 131.76],
    ),
    joint(
        "upperarm_roll_joint",
        REV,
        [0.219, 0.0, 0.0],
        X,
        None,
        [1.571, 76.94],
    ),
    joint(
        "elbow_flex_joint",
        REV,
        [0.133, 0.0, 0.0],
        Y,
        Some([-2.251, 2.251]),
        [1.521, 66.18],
    ),
    joint(
        "forearm_roll_joint",
        REV,
        [0.197, 0.0, 0.0],
        X,
        None,
        [1.571, 29.35],
    ),
    joint(
        "wrist_flex_joint",
        REV,
        [0.1245, 0.0, 0.0],
        Y,
        Some([-2.16, 2.16]),
        [2.268, 25.7],
    ),
    joint(
        "wrist_roll_joint",
        REV,
        [0.1385, 0.0, 0.0],
        X,
        None,
        [2.268, 7.36],
    ),
    joint(
        "r_gripper_finger_joint",
        PRIS,
        [0.0, 0.015425, 0.0],
        Y,
        Some([0.0, FINGER_OPEN]),
        [0.05, 60.0],
    ),
    joint(
        "l_gripper_finger_joint",
        PRIS,
        [0.0, -0.015425, 0.0],
        [0.0, -1.0, 0.0],
        Some([0.0, FINGER_OPEN]),
        [0.05, 60.0],
    ),
];

impl FetchJoint {
    /// Every joint, in proprioception's order.
    pub const ALL: [FetchJoint; FETCH_JOINTS] = [
        FetchJoint::RightWheel,
        FetchJoint::LeftWheel,
        FetchJoint::TorsoLift,
        FetchJoint::HeadPan,
        FetchJoint::HeadTilt,
        FetchJoint::ShoulderPan,
        FetchJoint::ShoulderLift,
        FetchJoint::UpperarmRoll,
        FetchJoint::ElbowFlex,
        FetchJoint::ForearmRoll,
        FetchJoint::WristFlex,
        FetchJoint::WristRoll,
        FetchJoint::RightFinger,
        FetchJoint::LeftFinger,
    ];

    /// The 7 arm joints, shoulder to wrist (iGibson's arm order).
    pub const ARM: [FetchJoint; 7] = [
        FetchJoint::ShoulderPan,
        FetchJoint::ShoulderLift,
        FetchJoint::UpperarmRoll,
        FetchJoint::ElbowFlex,
        FetchJoint::ForearmRoll,
        FetchJoint::WristFlex,
        FetchJoint::WristRoll,
    ];

    /// Its numbers from the URDF.
    pub fn info(self) -> &'static JointInfo {
        &JOINTS[self as usize]
    }

    /// Its position in proprioception's order.
    pub fn index(self) -> usize {
        self as usize
    }

    /// Where the joint puts its child at position `q`, in the parent's frame.
    pub(crate) fn transform(self, q: f32) -> Pose {
        let info = self.info();
        let motion = match info.kind {
            JointKind::Prismatic => Pose::from_translation(info.axis * q),
            _ => Pose::from_rotation(Rotation::from_axis_angle(info.axis, q)),
        };
        Pose::from_translation(info.origin) * motion
    }

    /// `q` within the joint's limits.
    pub(crate) fn clamp(self, q: f32) -> f32 {
        self.info().limits.map_or(q, |[lo, hi]| q.clamp(lo, hi))
    }
}

/// A finger's open position, m (each finger travels 0–0.05 m; the gap is then ≈ 0.099 m).
pub const FINGER_OPEN: f32 = 0.05;
/// Where the end effector (`gripper_link`, at the finger-joint line, x pointing out of the
/// gripper) sits in the wrist-roll frame.
pub const GRIPPER_OFFSET: Vector = Vector::new(0.16645, 0.0, 0.0);
/// iGibson's "gripper centre", where grasp candidates are measured from, in the eef frame.
pub const GRIPPER_CENTRE: Vector = Vector::new(0.1, 0.0, 0.0);
/// The head camera in the head-tilt frame; it looks along its +x.
pub const CAMERA_OFFSET: Vector = Vector::new(0.055, 0.0, 0.0225);
/// The base laser's place in the base frame, m (Fetch's URDF: `laser_link`).
pub(crate) const LASER_OFFSET: Vector = Vector::new(0.235, 0.0, 0.2878);
/// The wheels' radius and the distance between them, m (Fetch's URDF).
pub const WHEEL_RADIUS: f32 = 0.0603;
/// The distance between the wheels, m.
pub const WHEEL_SEPARATION: f32 = 2.0 * 0.18738;
/// The base's radius, m (its collision cylinder; Fetch's costmap uses 0.30).
pub const BASE_RADIUS: f32 = 0.28;
/// The whole robot's mass as built, kg (the URDF's links; the real robot ≈ 113 kg).
pub const FETCH_MASS: f32 = 121.0;

/// The arm joints of iGibson's BEHAVIOR start pose, `diagonal30` (iGibson 2.0.3's
/// `robots/fetch_gripper_robot.py`): the gripper in front of the robot, pointing down and 30°
/// toward +y.
pub const DIAGONAL30: [f32; 7] = [
    -1.06595, -0.22184, 1.53448, 1.46076, -0.84995, 1.36904, 1.90996,
];
/// The torso height of iGibson's BEHAVIOR configs, m (0.3 + `trunk_offset` 0.085).
pub const START_TORSO: f32 = 0.385;
/// The head tilt of iGibson's untucked poses, rad (down).
pub const START_TILT: f32 = 0.45;

/// The positions of the joints Fetch moves kinematically: torso, head and arm (the wheels are
/// the base's motion, the fingers are simulated).
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct FetchJoints {
    /// Torso lift, m.
    pub torso: f32,
    /// Head pan and tilt, rad.
    pub head: [f32; 2],
    /// The arm, shoulder pan to wrist roll, rad.
    pub arm: [f32; 7],
}

impl Default for FetchJoints {
    /// iGibson's BEHAVIOR start: torso 0.385 m, head (0, 0.45), arm `diagonal30`.
    fn default() -> Self {
        FetchJoints {
            torso: START_TORSO,
            head: [0.0, START_TILT],
            arm: DIAGONAL30,
        }
    }
}

/// Fetch's kinematic links, each a world object ([`crate::FetchParts`]).
#[derive(
    serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord,
)]
pub enum FetchLink {
    /// The base with the fixed part of the torso.
    Base,
    /// The moving torso.
    Torso,
    /// The head's pan link.
    HeadPan,
    /// The head's tilt link (the camera's).
    HeadTilt,
    /// Shoulder pan.
    ShoulderPan,
    /// Shoulder lift.
    ShoulderLift,
    /// Upper-arm roll.
    UpperarmRoll,
    /// Elbow flex.
    ElbowFlex,
    /// Forearm roll.
    ForearmRoll,
    /// Wrist flex.
    WristFlex,
    /// The wrist roll with the gripper's palm and fingers, in the end-effector frame.
    Gripper,
}

/// How many kinematic links (world objects) Fetch has.
pub const FETCH_LINKS: usize = 11;

impl FetchLink {
    /// Every link, base first.
    pub const ALL: [FetchLink; FETCH_LINKS] = [
        FetchLink::Base,
        FetchLink::Torso,
        FetchLink::HeadPan,
        FetchLink::HeadTilt,
        FetchLink::ShoulderPan,
        FetchLink::ShoulderLift,
        FetchLink::UpperarmRoll,
        FetchLink::ElbowFlex,
        FetchLink::ForearmRoll,
        FetchLink::WristFlex,
        FetchLink::Gripper,
    ];

    /// Its world object's name.
    pub fn name(self) -> &'static str {
        [
            "fetch_base",
            "fetch_torso",
            "fetch_head_pan",
            "fetch_head_tilt",
            "fetch_shoulder_pan",
            "fetch_shoulder_lift",
            "fetch_upperarm_roll",
            "fetch_elbow_flex",
            "fetch_forearm_roll",
            "fetch_wrist_flex",
            "fetch_gripper",
        ][self as usize]
    }
}

impl FetchJoints {
    /// The same positions, each within its joint's limits.
    pub fn clamped(self) -> FetchJoints {
        FetchJoints {
            torso: FetchJoint::TorsoLift.clamp(self.torso),
            head: [
                FetchJoint::HeadPan.clamp(self.head[0]),
                FetchJoint::HeadTilt.clamp(self.head[1]),
            ],
            arm: std::array::from_fn(|k| FetchJoint::ARM[k].clamp(self.arm[k])),
        }
    }

    /// Whether every position is a finite number.
    pub fn is_finite(&self) -> bool {
        self.torso.is_finite()
            && self.head.iter().all(|x| x.is_finite())
            && self.arm.iter().all(|x| x.is_finite())
    }

    /// The position of a kinematic joint (`None` for the wheels and fingers).
    pub fn get(&self, joint: FetchJoint) -> Option<f32> {
        match joint {
            FetchJoint::TorsoLift => Some(self.torso),
            FetchJoint::HeadPan => Some(self.head[0]),
            FetchJoint::HeadTilt => Some(self.head[1]),
            j => FetchJoint::ARM
                .iter()
                .position(|&a| a == j)
                .map(|k| self.arm[k]),
        }
    }

    /// Every kinematic link's pose in the base frame, in [`FetchLink::ALL`] order.
    pub fn link_poses(&self) -> [Pose; FETCH_LINKS] {
        let torso = FetchJoint::TorsoLift.transform(self.torso);
        let pan = torso * FetchJoint::HeadPan.transform(self.head[0]);
        let tilt = pan * FetchJoint::HeadTilt.transform(self.head[1]);
        let mut out = [Pose::IDENTITY; FETCH_LINKS];
        out[1..4].copy_from_slice(&[torso, pan, tilt]);
        let mut frame = torso;
        for (k, joint) in FetchJoint::ARM.iter().enumerate() {
            frame *= joint.transform(self.arm[k]);
            if k < 6 {
                out[4 + k] = frame;
            }
        }
        out[10] = frame * Pose::from_translation(GRIPPER_OFFSET);
        out
    }

    /// The end effector's pose in the base frame.
    pub fn eef(&self) -> Pose {
        self.link_poses()[FetchLink::Gripper as usize]
    }

    /// The head camera's pose in the base frame: it looks along its +x.
    pub fn camera(&self) -> Pose {
        self.link_poses()[FetchLink::HeadTilt as usize] * Pose::from_translation(CAMERA_OFFSET)
    }
}

/// Link masses from the URDF, kg (Fetch's URDF and its STL meshes): the base with its wheels and
/// fixed torso, the wrist roll with the palm.
const MASSES: [f32; FETCH_LINKS] = [
    70.13 + 2.0 * 4.354 + 13.28,
    10.78,
    2.256,
    0.909,
    2.559,
    2.662,
    2.331,
    2.130,
    1.656,
    1.725,
    0.135 + 1.518,
];
/// A finger's mass, kg.
pub const FETCH_FINGER_MASS: f32 = 0.0798;
/// Friction of the palm and fingers (iGibson's is 500, a way of saying "does not slip"; the
/// assisted grasp holds, so a firm ordinary value does).
pub const GRIPPER_FRICTION: f32 = 1.5;

/// A link's mass, kg.
pub fn link_mass(link: FetchLink) -> f32 {
    MASSES[link as usize]
}

fn cuboid(min: [f32; 3], max: [f32; 3]) -> Part {
    let centre = Vector::from(min).midpoint(Vector::from(max));
    let half = (Vector::from(max) - Vector::from(min)) * 0.5;
    Part::at(Primitive::Box { half_extents: half }, centre)
}

/// A capsule along x from `x0` to `x1` (ends included) of `radius`.
fn capsule_x(x0: f32, x1: f32, radius: f32) -> Part {
    let capsule = Primitive::Capsule {
        radius,
        half_height: 0.5 * (x1 - x0) - radius,
    };
    let offset = Pose::from_parts(
        Vector::new(0.5 * (x0 + x1), 0.0, 0.0),
        Rotation::from_rotation_y(FRAC_PI_2),
    );
    Part {
        primitive: capsule,
        offset,
        visual: None,
        form: Form::Primitive,
    }
}

/// The base's collision cylinder: r 0.28 m, from 3 cm above the floor to 0.36 m.
fn base_cylinder() -> Part {
    Part::at(
        Primitive::Cylinder {
            radius: BASE_RADIUS,
            half_height: 0.165,
        },
        Vector::new(0.0, 0.0, 0.195),
    )
}

/// A link's collision parts in its own frame (bounding boxes of Fetch's URDF and its STL meshes).
pub(crate) fn link_parts(link: FetchLink) -> Vec<Part> {
    use FetchLink as L;
    match link {
        L::Base => {
            // The fixed torso's box, moved from its joint (−0.086875, 0, 0.377425) to the base.
            let (x, z) = (-0.086875, 0.377425);
            let torso = cuboid(
                [x - 0.168, -0.155, z - 0.019],
                [x - 0.032, 0.155, z + 0.443],
            );
            vec![base_cylinder(), torso]
        }
        L::Torso => vec![cuboid([-0.185, -0.171, 0.029], [0.172, 0.171, 0.603])],
        L::HeadPan => vec![cuboid([-0.125, -0.143, -0.003], [0.198, 0.143, 0.113])],
        L::HeadTilt => vec![cuboid([-0.055, -0.105, -0.055], [0.055, 0.105, 0.055])],
        L::ShoulderPan => vec![cuboid([-0.052, -0.075, -0.048], [0.178, 0.052, 0.121])],
        L::ShoulderLift => vec![capsule_x(-0.060, 0.172, 0.055)],
        L::UpperarmRoll => vec![capsule_x(-0.048, 0.185, 0.052)],
        L::ElbowFlex => vec![capsule_x(-0.052, 0.166, 0.052)],
        L::ForearmRoll => vec![capsule_x(-0.032, 0.177, 0.052)],
        L::WristFlex => vec![capsule_x(-0.052, 0.117, 0.052)],
        L::Gripper => {
            // The wrist roll's cylinder (x −0.023..0.020 in its frame, 0.16645 behind the eef).
            let wrist = Part {
                primitive: Primitive::Cylinder {
                    radius: 0.052,
                    half_height: 0.0215,
                },
                offset: Pose::from_parts(
                    Vector::new(-0.16645 - 0.0015, 0.0, 0.0),
                    Rotation::from_rotation_y(FRAC_PI_2),
                ),
                visual: None,
                form: Form::Primitive,
            };
            vec![
                wrist,
                cuboid([-0.154, -0.063, -0.040], [-0.032, 0.063, 0.040]),
            ]
        }
    }
}

/// A finger pad's half size (the URDF mesh's 0.060 × 0.0143 × 0.0263 m pad).
const PAD_HALF: Vector = Vector::new(0.030, 0.00715, 0.01315);
/// The pad's inner face is this far inside the finger joint's position, m.
const PAD_INSET: f32 = 0.0004;

/// A finger's link: its pad at the closed position (joint 0), on a prismatic joint driven by
/// the robot (see `fetch.rs`). `sign` is +1 for the right finger (at +y), −1 for the left.
fn finger_link(joint: FetchJoint, sign: f32) -> LinkSpec {
    let info = joint.info();
    let centre = Vector::new(0.001, sign * (PAD_HALF.y - PAD_INSET), 0.0);
    let part = Part::at(
        Primitive::Box {
            half_extents: PAD_HALF,
        },
        centre,
    );
    LinkSpec {
        name: info.name.trim_end_matches("_joint").to_string(),
        parts: vec![part],
        parent: None,
        joint: JointSpec {
            kind: JointKind::Prismatic,
            model: JointModel::Impulse,
            anchor: info.origin,
            axis: info.axis,
            limits: info.limits,
            damping: 0.0,
        },
        density: FETCH_FINGER_MASS / (8.0 * PAD_HALF.x * PAD_HALF.y * PAD_HALF.z),
    }
}

/// The shapes that must not move into fixed bodies, in a link's frame: its parts, and for the
/// gripper also the box the finger pads sweep over their whole travel (the fingers are dynamic
/// links, which the kinematic palm would otherwise drive into a table).
pub(crate) fn blocking_parts(link: FetchLink) -> Vec<Part> {
    let mut parts = link_parts(link);
    if link == FetchLink::Gripper {
        let y = FINGER_OPEN + 2.0 * PAD_HALF.y;
        let (x, z) = (PAD_HALF.x, PAD_HALF.z);
        parts.push(cuboid([0.001 - x, -y, -z], [0.001 + x, y, z]));
    }
    parts
}

/// The finger links' indices in the gripper object, right then left.
pub(crate) const FINGER_LINKS: [usize; 2] = [0, 1];

/// A finger pad's inner face centre in its link's frame (the link frame is the gripper frame at
/// a closed finger), for the finger `k` (0 right, 1 left).
pub(crate) fn pad_face(k: usize) -> Vector {
    let sign = if k == 0 { 1.0 } else { -1.0 };
    Vector::new(0.001 + PAD_HALF.x, -sign * PAD_INSET, 0.0)
}

/// A link's centre of mass in its own frame: the centroid of its parts, by volume.
pub(crate) fn link_centre(link: FetchLink) -> Vector {
    parts_centre(&link_parts(link))
}

/// The spec of a kinematic link standing at `pose`: a velocity-driven kinematic body of the
/// link's real mass (see `Fetch` for why not position-driven); the gripper carries the two
/// fingers as dynamic links.
pub(crate) fn link_spec(link: FetchLink, pose: Pose) -> ObjectSpec {
    let parts = link_parts(link);
    let total: f32 = parts.iter().map(part_volume).sum();
    let colour = match link {
        FetchLink::Base | FetchLink::Torso | FetchLink::HeadTilt => [235, 235, 235],
        _ => [60, 80, 160],
    };
    let mut spec = ObjectSpec::new(link.name(), AGENT_SYNSET, parts)
        .body(BodyKind::KinematicVelocity)
        .looks(colour, Material::Plastic);
    spec.model = Some(crate::fetch_model::fetch_piece(link));
    spec.pose = pose;
    spec.density = link_mass(link) / total;
    if link == FetchLink::Gripper {
        spec.friction = GRIPPER_FRICTION;
        spec = spec
            .link(finger_link(FetchJoint::RightFinger, 1.0))
            .link(finger_link(FetchJoint::LeftFinger, -1.0));
    }
    spec
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vector, b: [f32; 3], tolerance: f32) -> bool {
        (a - Vector::from(b)).length() < tolerance
    }

    #[test]
    fn forward_kinematics_matches_the_reference_poses() {
        // All zero: the eef at (1.128, 0, 0.786 + q), pointing +x (Fetch's URDF).
        let zero = FetchJoints {
            torso: 0.1,
            head: [0.0; 2],
            arm: [0.0; 7],
        };
        let eef = zero.eef();
        assert!(
            close(eef.translation, [1.1281, 0.0, 0.886], 1e-3),
            "{eef:?}"
        );
        // diagonal30 at torso 0.385: (0.553, −0.127, 0.982), pointing down (iGibson 2.0.3's
        // `robots/fetch_gripper_robot.py`).
        let start = FetchJoints::default().eef();
        assert!(
            close(start.translation, [0.553, -0.127, 0.982], 2e-3),
            "{start:?}"
        );
        // Its x axis points down, tilted 30° toward +y.
        let x = start.rotation * Vector::X;
        assert!(close(x, [0.0, 0.5, -0.866], 0.02), "{x:?}");
        // The camera: the tilt axis at (0.1088, 0, 1.0384 + q) (Fetch's URDF) plus the
        // camera's offset turned 0.45 rad down. (§1.4's "≈ (0.165, 0, 1.405)" disagrees with
        // its own axis by 1.5 cm in z; the axis follows from the joint table.)
        let camera = FetchJoints::default().camera();
        let (s, c) = START_TILT.sin_cos();
        let offset = [0.055 * c + 0.0225 * s, 0.0, -0.055 * s + 0.0225 * c];
        let expected = [0.1088 + offset[0], 0.0, 1.0384 + START_TORSO + offset[2]];
        assert!(close(camera.translation, expected, 1e-3), "{camera:?}");
        let look = camera.rotation * Vector::X;
        assert!((look.z.asin().to_degrees() + 25.8).abs() < 0.1, "{look:?}");
    }

    #[test]
    fn the_links_weigh_what_the_urdf_says() {
        let total: f32 = FetchLink::ALL.iter().map(|&l| link_mass(l)).sum();
        assert!(
            (total + 2.0 * FETCH_FINGER_MASS - FETCH_MASS).abs() < 1.0,
            "{total}"
        );
        assert_eq!(
            FetchJoint::ALL.map(FetchJoint::index),
            std::array::from_fn(|k| k)
        );
    }
}
