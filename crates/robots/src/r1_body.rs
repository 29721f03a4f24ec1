//! The R1's links as world objects: which links there are, where its joints put them, their
//! shapes and masses, and its two parallel grippers (`docs/r1-pro-facts.md`).
//!
//! Shapes are our own primitives with the bounding boxes of the real links' visual meshes
//! (facts sheet §2): the base a cylinder round the three wheels (its mesh's size is not
//! published; the wheels' steering axes are 0.327 m from the centre and the chassis' sensors
//! 0.33 m to the side), every torso and arm link a box, the head camera a box on the torso's top
//! link, the palm a box and each finger a pad box on a prismatic joint. The wheels and steering
//! motors are inside the base's cylinder and are not bodies: the base is holonomic and moves as
//! told (as OmniGibson drives its virtual base joints).
//!
//! Every kinematic link sits in its URDF frame, except the grippers, which sit in the end
//! effector's frame (x out along the fingers at the middle of their pads, the fingers closing
//! along y): the frame Fetch's gripper uses, so that an arm planner reads both alike.

use crate::chain::Chain;
use crate::gripper::GripperSpec;
use crate::hand::Side;
use crate::kinematic_links::{part_volume, parts_centre};
use crate::r1_kinematics::{
    R1_ARM_JOINTS, R1_FINGER_OPEN, R1_START_TORSO, R1_TORSO_JOINTS, arm_chain, torso_chain,
};
use behavior_core::AGENT_SYNSET;
use behavior_sim::{
    BodyKind, JointKind, JointModel, JointSpec, LinkSpec, Material, ObjectSpec, Part, Primitive,
};
use rapier3d::math::{Pose, Vector};

/// How many kinematic links (world objects) the R1 has: the base, four torso links, and per arm
/// seven links and the gripper.
pub const R1_LINKS: usize = 1 + R1_TORSO_JOINTS + 2 * (R1_ARM_JOINTS + 1);

/// The base's collision cylinder's radius, m: round the wheels (see the module docs).
pub const R1_BASE_RADIUS: f32 = 0.33;

/// The positions of the joints the R1 moves kinematically: torso and arms (the base's motion is
/// its pose, the fingers are simulated).
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct R1Joints {
    /// The torso, from the base up, rad.
    pub torso: [f32; R1_TORSO_JOINTS],
    /// The arms (left, right), each from the shoulder, rad.
    pub arms: [[f32; R1_ARM_JOINTS]; 2],
}

impl Default for R1Joints {
    /// The BEHAVIOR Challenge's reset: the torso half bent ([`R1_START_TORSO`]), the arms
    /// hanging.
    fn default() -> Self {
        R1Joints {
            torso: R1_START_TORSO,
            arms: [[0.0; R1_ARM_JOINTS]; 2],
        }
    }
}

impl R1Joints {
    /// The same positions, each within its joint's limits.
    pub fn clamped(self) -> R1Joints {
        let torso = torso_chain();
        R1Joints {
            torso: std::array::from_fn(|k| torso.joints[k].clamp(self.torso[k])),
            arms: Side::BOTH.map(|side| {
                let arm = crate::r1_kinematics::arm_joints(side);
                std::array::from_fn(|k| arm[k].clamp(self.arms[side.index()][k]))
            }),
        }
    }

    /// Whether every position is a finite number.
    pub fn is_finite(&self) -> bool {
        self.torso
            .iter()
            .chain(self.arms.iter().flatten())
            .all(|x| x.is_finite())
    }

    /// The arm of `side` as a chain from its mount, the torso where these joints put it.
    pub fn arm_chain(&self, side: Side) -> Chain {
        arm_chain(side, &self.torso)
    }

    /// Every link's pose in the base frame, in [`R1Link`] order: the base, the torso, the left
    /// arm and gripper, the right arm and gripper.
    pub fn link_poses(&self) -> Vec<Pose> {
        let mut out = Vec::with_capacity(R1_LINKS);
        out.push(Pose::IDENTITY);
        out.extend(torso_chain().link_poses(&self.torso));
        for side in Side::BOTH {
            let arm = self.arm_chain(side);
            let q = &self.arms[side.index()];
            out.extend(arm.link_poses(q));
            out.push(arm.tip(q));
        }
        out
    }

    /// The end effector of `side` in the base frame (its gripper object's pose).
    pub fn eef(&self, side: Side) -> Pose {
        self.arm_chain(side).tip(&self.arms[side.index()])
    }
}

/// An R1 link's index among its objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum R1Link {
    /// The base, with its wheels.
    Base,
    /// Torso link 1 to 4 (0 to 3); the fourth carries the head camera and the arms' mounts.
    Torso(usize),
    /// Arm link 1 to 7 (0 to 6) of a side.
    Arm(Side, usize),
    /// The gripper of a side: the palm, in the end effector's frame, with its two fingers.
    Gripper(Side),
}

impl R1Link {
    /// Its index among the R1's objects (see [`R1Joints::link_poses`]).
    pub fn index(self) -> usize {
        let arm_start = |side: Side| 1 + R1_TORSO_JOINTS + side.index() * (R1_ARM_JOINTS + 1);
        match self {
            R1Link::Base => 0,
            R1Link::Torso(k) => 1 + k,
            R1Link::Arm(side, k) => arm_start(side) + k,
            R1Link::Gripper(side) => arm_start(side) + R1_ARM_JOINTS,
        }
    }

    /// The link of index `index`.
    pub fn of(index: usize) -> R1Link {
        let arms = 1 + R1_TORSO_JOINTS;
        match index {
            0 => R1Link::Base,
            k if k < arms => R1Link::Torso(k - 1),
            k => {
                let (side, k) = (
                    (k - arms) / (R1_ARM_JOINTS + 1),
                    (k - arms) % (R1_ARM_JOINTS + 1),
                );
                let side = if side == 0 { Side::Left } else { Side::Right };
                if k == R1_ARM_JOINTS {
                    R1Link::Gripper(side)
                } else {
                    R1Link::Arm(side, k)
                }
            }
        }
    }

    /// Its world object's name.
    pub fn name(self) -> String {
        let side = |side: Side| match side {
            Side::Left => "left",
            Side::Right => "right",
        };
        match self {
            R1Link::Base => "r1_base".to_string(),
            R1Link::Torso(k) => format!("r1_torso_{}", k + 1),
            R1Link::Arm(s, k) => format!("r1_{}_arm_{}", side(s), k + 1),
            R1Link::Gripper(s) => format!("r1_{}_gripper", side(s)),
        }
    }
}

/// A box from `min` to `max` in a link's frame.
fn cuboid(min: [f32; 3], max: [f32; 3]) -> Part {
    let (min, max) = (Vector::from(min), Vector::from(max));
    Part::at(
        Primitive::Box {
            half_extents: (max - min) * 0.5,
        },
        min.midpoint(max),
    )
}

/// A box of `size` centred on `centre` in a link's frame.
fn sized(size: [f32; 3], centre: [f32; 3]) -> Part {
    Part::at(
        Primitive::Box {
            half_extents: Vector::from(size) * 0.5,
        },
        Vector::from(centre),
    )
}

/// The palm, in the end effector's frame: the gripper link's box (x ±0.03, y ±0.054, z
/// 0..0.077 in its own frame) turned into the end effector's, which sits 0.06 below its origin.
fn palm() -> Part {
    cuboid([-0.137, -0.054, -0.03], [-0.06, 0.054, 0.03])
}

/// A finger's half size: 8.8 cm along the fingers (from the palm to 1.8 cm beyond the end
/// effector), 1.4 cm thick, 3.2 cm wide (the meshes' 0.092 × 0.038 m, a pad's thickness).
const FINGER_HALF: Vector = Vector::new(0.044, 0.007, 0.016);
/// How far along x from the end effector the finger's box is centred, m.
const FINGER_CENTRE_X: f32 = -0.026;

/// A link's parts in its own frame (see the module docs).
pub(crate) fn link_parts(link: R1Link) -> Vec<Part> {
    match link {
        R1Link::Base => vec![Part::at(
            Primitive::Cylinder {
                radius: R1_BASE_RADIUS,
                half_height: 0.14,
            },
            Vector::new(0.0, 0.0, 0.16),
        )],
        R1Link::Torso(0) => vec![cuboid(
            [-0.0625, -0.0885, -0.0625],
            [0.0625, 0.0885, 0.4624],
        )],
        R1Link::Torso(1) => vec![cuboid(
            [-0.0625, -0.0915, -0.0625],
            [0.0625, 0.0915, 0.3625],
        )],
        R1Link::Torso(2) => vec![sized([0.126, 0.134, 0.187], [0.0, 0.0, 0.05])],
        R1Link::Torso(_) => vec![
            cuboid([-0.096, -0.174, -0.031], [0.119, 0.174, 0.415]),
            // The head camera (zed_link, 0.201 × 0.171 × 0.176) at its mount.
            sized([0.201, 0.171, 0.176], [0.0655, 0.0, 0.476]),
        ],
        R1Link::Arm(side, k) => {
            let y = match side {
                Side::Left => 1.0,
                Side::Right => -1.0,
            };
            let part = match k {
                0 => sized([0.049, 0.132, 0.101], [0.0, 0.074 * y, 0.0]),
                1 => sized([0.109, 0.115, 0.148], [-0.027, -0.004 * y, -0.032]),
                2 => cuboid([-0.0475, -0.046, -0.232], [0.0475, 0.046, 0.022]),
                3 => sized([0.085, 0.090, 0.151], [-0.001, -0.036 * y, -0.042]),
                4 => cuboid([-0.041, -0.0415, -0.187], [0.041, 0.0415, 0.03]),
                5 => sized([0.059, 0.064, 0.059], [0.0018, 0.0275 * y, 0.0]),
                _ => sized([0.069, 0.060, 0.115], [-0.023, 0.0, -0.0565]),
            };
            vec![part]
        }
        R1Link::Gripper(_) => vec![palm()],
    }
}

/// Link masses, kg (facts sheet §2): the base with its wheels and steering motors; the top
/// torso link with the head camera and both arm mounts; the gripper with its wrist camera.
fn link_mass(link: R1Link) -> f32 {
    const ARM: [f32; R1_ARM_JOINTS] = [1.135, 0.92, 1.245, 0.827, 0.939, 0.527, 0.185];
    match link {
        R1Link::Base => 47.63 + 6.0 * 1.5,
        R1Link::Torso(k) => [5.72, 3.5, 3.4, 5.0 + 2.05 + 2.0 * 1.48][k.min(3)],
        R1Link::Arm(Side::Right, 4) => 0.63,
        R1Link::Arm(_, k) => ARM[k.min(R1_ARM_JOINTS - 1)],
        R1Link::Gripper(_) => 0.24625 + 0.175,
    }
}

/// A finger's mass, kg (the left gripper's finger links; the right's weigh 0.027).
const FINGER_MASS: f32 = 0.0202;

/// A link's centre of mass in its own frame: the centroid of its parts, by volume.
pub(crate) fn link_centre(link: R1Link) -> Vector {
    parts_centre(&link_parts(link))
}

/// The shapes that must not move into fixed bodies, in a link's frame: its parts, and for a
/// gripper also the box its fingers sweep over their whole travel (the fingers are dynamic
/// links, which the kinematic palm would otherwise drive into a table).
pub(crate) fn blocking_parts(link: R1Link) -> Vec<Part> {
    let mut parts = link_parts(link);
    if let R1Link::Gripper(_) = link {
        parts.push(finger_sweep());
    }
    parts
}

/// The box the fingers sweep over their travel, in the end effector's frame.
pub(crate) fn finger_sweep() -> Part {
    let (x, z) = (FINGER_HALF.x, FINGER_HALF.z);
    let y = R1_FINGER_OPEN + 2.0 * FINGER_HALF.y;
    cuboid([FINGER_CENTRE_X - x, -y, -z], [FINGER_CENTRE_X + x, y, z])
}

/// How far the fingertips reach beyond the end effector along its x, m.
pub(crate) const R1_TIP: f32 = FINGER_CENTRE_X + FINGER_HALF.x;

/// A finger's link: its box against the gripper's middle at the closed position (joint 0), on a
/// prismatic joint that opens it outward: finger 0 toward +y, finger 1 toward −y.
fn finger_link(k: usize) -> LinkSpec {
    let sign = if k == 0 { 1.0 } else { -1.0 };
    let part = Part::at(
        Primitive::Box {
            half_extents: FINGER_HALF,
        },
        Vector::new(FINGER_CENTRE_X, sign * FINGER_HALF.y, 0.0),
    );
    LinkSpec {
        name: format!("finger_{}", k + 1),
        parts: vec![part],
        parent: None,
        joint: JointSpec {
            kind: JointKind::Prismatic,
            model: JointModel::Impulse,
            anchor: Vector::ZERO,
            axis: Vector::new(0.0, sign, 0.0),
            limits: Some([0.0, R1_FINGER_OPEN]),
            damping: 0.0,
        },
        density: FINGER_MASS / (8.0 * FINGER_HALF.x * FINGER_HALF.y * FINGER_HALF.z),
    }
}

/// Friction of the palm and fingers: firm, as Fetch's (the assisted grasp holds).
const GRIPPER_FRICTION: f32 = 1.5;

/// An R1 gripper's facts (the URDF's finger joints: 0–0.05 m each, 0.25 m/s, 100 N).
pub(crate) fn gripper_spec() -> GripperSpec {
    GripperSpec {
        fingers: [0, 1],
        open: R1_FINGER_OPEN,
        max_velocity: 0.25,
        // Stiff enough to close on a 0.2 kg apple within 3 cm at full force, damped for the
        // fingers' 20 g.
        stiffness: 2000.0,
        damping: 12.0,
        effort: 100.0,
        centre: Vector::ZERO,
        // Each finger's inner face is its link's origin: at the end effector, on the middle
        // line when closed.
        pads: [Vector::ZERO; 2],
    }
}

/// The spec of link `link` standing at `pose`: a velocity-driven kinematic body of the link's
/// mass; a gripper carries its two fingers as dynamic links.
pub(crate) fn link_spec(link: R1Link, pose: Pose) -> ObjectSpec {
    let parts = link_parts(link);
    let total: f32 = parts.iter().map(part_volume).sum();
    let colour = match link {
        R1Link::Base | R1Link::Torso(_) => [225, 225, 222],
        _ => [45, 45, 50],
    };
    let mut spec = ObjectSpec::new(&link.name(), AGENT_SYNSET, parts)
        .body(BodyKind::KinematicVelocity)
        .looks(colour, Material::Plastic);
    spec.pose = pose;
    spec.density = link_mass(link) / total;
    if let R1Link::Gripper(_) = link {
        spec.friction = GRIPPER_FRICTION;
        spec = spec.link(finger_link(0)).link(finger_link(1));
    }
    spec
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_are_numbered_both_ways() {
        for k in 0..R1_LINKS {
            assert_eq!(R1Link::of(k).index(), k);
        }
        assert_eq!(R1Link::Gripper(Side::Right).index(), R1_LINKS - 1);
        assert_eq!(R1Joints::default().link_poses().len(), R1_LINKS);
    }

    #[test]
    fn the_links_weigh_what_the_urdf_says() {
        let links: f32 = (0..R1_LINKS).map(|k| link_mass(R1Link::of(k))).sum();
        // The URDF's 91.44 kg (its right fingers weigh 7 g more than ours).
        let total = links + 4.0 * FINGER_MASS;
        assert!((total - 91.44).abs() < 0.5, "{total}");
    }

    #[test]
    fn each_gripper_sits_at_its_arms_end_effector() {
        let joints = R1Joints::default();
        let poses = joints.link_poses();
        for side in Side::BOTH {
            let at = poses[R1Link::Gripper(side).index()];
            assert_eq!(at, joints.eef(side));
        }
        // At the reset the hands hang in front of the robot, over the floor, apart.
        let (left, right) = (joints.eef(Side::Left), joints.eef(Side::Right));
        assert!(
            left.translation.y > right.translation.y + 0.2,
            "{left:?} {right:?}"
        );
        assert!(left.translation.z > 0.3, "{left:?}");
    }
}
