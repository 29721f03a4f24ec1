//! The Galaxea R1 Pro's kinematics (the robot of the BEHAVIOR Challenge 2025, OmniGibson's
//! `R1Pro`), from the published facts of its URDF (Galaxea's R1 Pro description as used beside
//! OmniGibson; the joint ranges of OmniGibson's own evaluation utilities where the two differ):
//! a 4-joint torso on a holonomic base, two 7-joint arms mounted on the torso's top link, a
//! parallel gripper at each, a stereo head camera on the torso. Frames as in the URDF: x
//! forward, y left, z up; the base's origin is on the floor at the centre of its three wheels.
//!
//! At all joints zero the torso stands straight and the arms hang down; the shoulders (the arm
//! mounts) are 1.445 m above the floor, 0.097 m either side, the head camera 1.618 m up.
//!
//! This file is the robot as numbers and forward kinematics ([`Chain`]s): the torso, each arm
//! from its mount to its gripper, the head camera's mount. The robot's body, action and step are
//! built on it.

// The URDF's numbers as published (its 1.5708 and 3.1416 are its own roundings).
#![allow(clippy::approx_constant)]

use crate::chain::{Chain, ChainJoint, urdf_origin};
use crate::hand::Side;
use behavior_sim::JointKind;
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::FRAC_PI_2;

/// Joints in the torso.
pub const R1_TORSO_JOINTS: usize = 4;
/// Joints in each arm.
pub const R1_ARM_JOINTS: usize = 7;
/// How far each finger opens from the gripper's middle, m (each finger 0–0.05).
pub const R1_FINGER_OPEN: f32 = 0.05;

/// One revolute joint of the URDF's table: name, origin xyz (no rotation), axis, limits,
/// velocity.
struct Row(&'static str, [f32; 3], [f32; 3], [f32; 2], f32);

impl Row {
    fn joint(&self) -> ChainJoint {
        let Row(name, xyz, axis, limits, max_velocity) = *self;
        ChainJoint {
            name,
            kind: JointKind::Revolute,
            origin: Pose::from_translation(Vector::from_array(xyz)),
            axis: Vector::from_array(axis),
            limits: Some(limits),
            max_velocity,
        }
    }
}

/// The torso, base link first: a pitch at the base (leaning the whole torso forward), a pitch
/// at the "knee", a pitch at the "waist" (about −y) and a yaw of the top.
const TORSO: [Row; R1_TORSO_JOINTS] = [
    Row(
        "torso_joint1",
        [-0.079032, 0.0, 0.34265],
        [0.0, 1.0, 0.0],
        [-1.1345, 1.8326],
        2.5,
    ),
    Row(
        "torso_joint2",
        [0.0, 0.0, 0.4],
        [0.0, 1.0, 0.0],
        [-2.7925, 2.5307],
        2.5,
    ),
    Row(
        "torso_joint3",
        [0.0, 0.0001005, 0.3],
        [0.0, -1.0, 0.0],
        [-1.8326, 1.5708],
        2.5,
    ),
    Row(
        "torso_joint4",
        [0.0, -0.00010015, 0.09962],
        [0.0, 0.0, 1.0],
        [-3.0543, 3.0543],
        2.5,
    ),
];

/// Each arm's joint velocities, rad/s, shoulder first.
const ARM_VELOCITY: [f32; R1_ARM_JOINTS] = [7.1209, 7.1209, 8.3776, 8.3776, 10.472, 10.472, 10.472];

const LEFT_ARM: [Row; R1_ARM_JOINTS] = [
    Row(
        "left_arm_joint1",
        [0.0, 0.0735, 0.0],
        [0.0, 1.0, 0.0],
        [-4.4506, 1.3090],
        ARM_VELOCITY[0],
    ),
    Row(
        "left_arm_joint2",
        [0.025012, 0.081265, 0.0],
        [1.0, 0.0, 0.0],
        [-0.1745, 3.1416],
        ARM_VELOCITY[1],
    ),
    Row(
        "left_arm_joint3",
        [-0.025012, 0.0, -0.1155],
        [0.0, 0.0, 1.0],
        [-2.356196, 2.356196],
        ARM_VELOCITY[2],
    ),
    Row(
        "left_arm_joint4",
        [0.0, 0.035065, -0.1945],
        [0.0, 1.0, 0.0],
        [-2.0944, 0.3491],
        ARM_VELOCITY[3],
    ),
    Row(
        "left_arm_joint5",
        [0.0, -0.035065, -0.095],
        [0.0, 0.0, 1.0],
        [-2.356196, 2.356196],
        ARM_VELOCITY[4],
    ),
    Row(
        "left_arm_joint6",
        [0.0, -0.028, -0.16305],
        [0.0, 1.0, 0.0],
        [-1.047198, 1.047198],
        ARM_VELOCITY[5],
    ),
    Row(
        "left_arm_joint7",
        [0.0295, 0.028, 0.0],
        [1.0, 0.0, 0.0],
        [-1.5708, 1.5708],
        ARM_VELOCITY[6],
    ),
];

/// The right arm, the left's mirror image (its shoulder roll's range mirrored too).
const RIGHT_ARM: [Row; R1_ARM_JOINTS] = [
    Row(
        "right_arm_joint1",
        [0.0, -0.0735, 0.0],
        [0.0, 1.0, 0.0],
        [-4.4506, 1.3090],
        ARM_VELOCITY[0],
    ),
    Row(
        "right_arm_joint2",
        [0.023988, -0.081265, 0.0],
        [1.0, 0.0, 0.0],
        [-3.1416, 0.1745],
        ARM_VELOCITY[1],
    ),
    Row(
        "right_arm_joint3",
        [-0.023988, 0.0, -0.1155],
        [0.0, 0.0, 1.0],
        [-2.356196, 2.356196],
        ARM_VELOCITY[2],
    ),
    Row(
        "right_arm_joint4",
        [0.0, 0.035058, -0.1945],
        [0.0, 1.0, 0.0],
        [-2.0944, 0.3491],
        ARM_VELOCITY[3],
    ),
    Row(
        "right_arm_joint5",
        [0.0, -0.035058, -0.095],
        [0.0, 0.0, 1.0],
        [-2.356196, 2.356196],
        ARM_VELOCITY[4],
    ),
    Row(
        "right_arm_joint6",
        [0.0, 0.028001, -0.16305],
        [0.0, 1.0, 0.0],
        [-1.047198, 1.047198],
        ARM_VELOCITY[5],
    ),
    Row(
        "right_arm_joint7",
        [0.0295, -0.028001, 0.0],
        [1.0, 0.0, 0.0],
        [-1.5708, 1.5708],
        ARM_VELOCITY[6],
    ),
];

/// The torso's joints, base link first.
pub fn torso_joints() -> [ChainJoint; R1_TORSO_JOINTS] {
    TORSO.each_ref().map(Row::joint)
}

/// Where an arm is mounted on the torso's top link (`torso_link4`).
pub fn arm_mount(side: Side) -> Pose {
    match side {
        Side::Left => Pose::from_translation(Vector::new(-0.00048618, 0.097234, 0.30302)),
        Side::Right => Pose::from_translation(Vector::new(-0.00048706, -0.097236, 0.30302)),
    }
}

/// The gripper's link in the last arm link's frame (`*_gripper_joint`, fixed).
pub const GRIPPER_MOUNT: Vector = Vector::new(-0.0295, 0.0, -0.16065);

/// How far from the gripper link's origin the end effector sits, along the fingers, m: the
/// middle of the finger pads (they reach about 0.078 m out: their joints 0.037 m out, the pads
/// 0.042 m beyond).
pub const EEF_DEPTH: f32 = 0.06;

/// The end effector in the gripper link's frame: x out along the fingers (the link's −z), the
/// fingers closing along y, as Fetch's end effector (and OmniGibson's gripper frame turned so).
pub fn eef_in_gripper() -> Pose {
    Pose::from_parts(
        Vector::new(0.0, 0.0, -EEF_DEPTH),
        Rotation::from_rotation_y(FRAC_PI_2),
    )
}

/// The arm of `side`, from its mount on the torso's top link: shoulder pitch (y), shoulder
/// roll (x), upper-arm yaw (z), elbow (y), forearm yaw (z), wrist pitch (y), wrist roll (x).
/// The elbow's lower limit is OmniGibson's (−2.0944; the URDF says −1.7453).
pub fn arm_joints(side: Side) -> [ChainJoint; R1_ARM_JOINTS] {
    let rows = match side {
        Side::Left => &LEFT_ARM,
        Side::Right => &RIGHT_ARM,
    };
    rows.each_ref().map(Row::joint)
}

/// The torso as a chain from the base's origin to its top link (the tip: no offset).
pub fn torso_chain() -> Chain {
    Chain {
        root: Pose::IDENTITY,
        joints: torso_joints().to_vec(),
        tip: Pose::IDENTITY,
    }
}

/// The arm of `side` as a chain from its mount to the end effector, the torso at `torso`: the
/// chain an arm planner moves with the torso still.
pub fn arm_chain(side: Side, torso: &[f32; R1_TORSO_JOINTS]) -> Chain {
    Chain {
        root: torso_chain().tip(torso) * arm_mount(side),
        joints: arm_joints(side).to_vec(),
        tip: Pose::from_translation(GRIPPER_MOUNT) * eef_in_gripper(),
    }
}

/// The torso and the arm of `side` as one chain from the base to the end effector (4 + 7
/// joints, the arm's mount folded into its first joint's origin): the chain an arm planner
/// moves when the torso helps the arm reach.
pub fn torso_arm_chain(side: Side) -> Chain {
    let mut joints = torso_joints().to_vec();
    let mut arm = arm_joints(side);
    arm[0].origin = arm_mount(side) * arm[0].origin;
    joints.extend(arm);
    Chain {
        root: Pose::IDENTITY,
        joints,
        tip: Pose::from_translation(GRIPPER_MOUNT) * eef_in_gripper(),
    }
}

/// The head camera in the base frame, the torso at `torso`: at the stereo camera's mount
/// (`zed_link`), looking along its +x with +z up, pitched 20° down as the mount is (its URDF
/// roll of −1.9199 rad, less the quarter turn of an optical frame).
pub fn head_camera(torso: &[f32; R1_TORSO_JOINTS]) -> Pose {
    let mount = urdf_origin([0.065511, 0.060003, 0.47598], [0.0, 0.0, 0.0]);
    let pitch = 1.9199 - FRAC_PI_2;
    torso_chain().tip(torso) * mount * Pose::from_rotation(Rotation::from_rotation_y(pitch))
}

/// The joint positions of the BEHAVIOR Challenge's reset: the torso bent halfway between
/// upright and reaching down (OmniGibson's teleoperation config: trunk translate 0.5 between
/// (0.45, −0.4, 0, 0) and (1.6, −2.5, −0.94, 0)), the arms hanging, the grippers open.
pub const R1_START_TORSO: [f32; R1_TORSO_JOINTS] = [1.025, -1.45, -0.47, 0.0];

#[cfg(test)]
mod tests {
    use super::*;

    const UPRIGHT: [f32; R1_TORSO_JOINTS] = [0.0; R1_TORSO_JOINTS];

    #[test]
    fn standing_straight_the_shoulders_and_the_head_are_where_the_urdf_puts_them() {
        for (side, y) in [(Side::Left, 0.097234), (Side::Right, -0.097236)] {
            let shoulder = arm_chain(side, &UPRIGHT).root.translation;
            assert!((shoulder.z - 1.44529).abs() < 1e-4, "{shoulder:?}");
            assert!((shoulder.y - y).abs() < 1e-3, "{shoulder:?}");
        }
        let head = head_camera(&UPRIGHT);
        assert!((head.translation.z - 1.61825).abs() < 1e-4, "{head:?}");
        // It looks forward and 20° down.
        let ahead = head.rotation * Vector::X;
        assert!(ahead.x > 0.9 && (ahead.z + 0.342).abs() < 0.01, "{ahead:?}");
    }

    #[test]
    fn a_hanging_arm_reaches_0_73_m_below_its_shoulder_pitch_and_points_its_fingers_down() {
        for side in [Side::Left, Side::Right] {
            let arm = arm_chain(side, &UPRIGHT);
            let zero = [0.0; R1_ARM_JOINTS];
            let poses = arm.link_poses(&zero);
            // From the shoulder pitch (joint 2's link) to the gripper link: 0.7287 m straight
            // down at zero.
            let gripper = poses[6] * Pose::from_translation(GRIPPER_MOUNT);
            let drop = poses[1].translation.z - gripper.translation.z;
            assert!((drop - 0.7287).abs() < 1e-3, "{drop}");
            let eef = arm.tip(&zero);
            assert!((eef.rotation * Vector::X - Vector::NEG_Z).length() < 1e-5);
            assert!((gripper.translation.z - eef.translation.z - EEF_DEPTH).abs() < 1e-5);
        }
    }

    #[test]
    fn each_arm_finds_by_ik_a_pose_it_was_at_from_hanging_down() {
        use crate::chain::ChainIk;
        for side in [Side::Left, Side::Right] {
            let arm = arm_chain(side, &R1_START_TORSO);
            // Somewhere the arm puts its gripper with its joints half bent.
            let bent = [0.3, 0.4, 0.2, -1.0, 0.3, 0.4, 0.2].map(|q| match side {
                Side::Left => q,
                Side::Right => -q,
            });
            let bent: Vec<f32> = arm
                .joints
                .iter()
                .zip(bent)
                .map(|(j, q)| j.clamp(q))
                .collect();
            let goal = arm.tip(&bent);
            let solved = arm
                .solve(&[0.0; R1_ARM_JOINTS], &goal, &ChainIk::default())
                .expect("a pose the arm was at");
            assert!((arm.tip(&solved).translation - goal.translation).length() < 0.005);
        }
    }
}
