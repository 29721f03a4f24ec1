//! Fetch's torso and arm as an [`Arm`]: the torso lift and the seven arm joints, read through
//! Fetch's own forward kinematics ([`FetchJoints::link_poses`]), inverse kinematics
//! ([`IkSolver`]) and joint-by-joint action ([`FetchJointAction`]).

use crate::arm::{Arm, ArmConfig};
use crate::fetch::{FetchParts, GRIPPER, step_joints};
use crate::fetch_action::{FETCH_JOINT_ACTION_DIM, FetchCommand, FetchJointAction};
use crate::fetch_body::{FETCH_LINKS, FINGER_OPEN, FetchJoint, FetchJoints, FetchLink};
use crate::ik::IkSolver;
use behavior_sim::{BodyRef, ObjectId, Primitive, World};
use rapier3d::math::{Pose, Vector};
use std::f32::consts::FRAC_PI_2;
use std::ops::Range;

/// The joints of Fetch's arm as an [`Arm`] orders them: the torso lift, then the seven arm
/// joints from the shoulder pan.
const ARM_JOINTS: usize = 8;

/// iGibson's tucked arm joints (iGibson 2.0.3's `robots/fetch_gripper_robot.py`).
const TUCKED: [f32; 7] = [1.1708, 1.4708, -0.4, 1.6708, 0.0, FRAC_PI_2, 0.0];

/// The joint of an arm configuration's coordinate `k`.
fn joint(k: usize) -> FetchJoint {
    match k {
        0 => FetchJoint::TorsoLift,
        _ => FetchJoint::ARM[k - 1],
    }
}

/// Fetch's arm as it stands: its parts, where its joints are (the head's kept as they are by
/// every configuration) and its IK solver.
#[derive(Clone, Debug)]
pub(crate) struct FetchArm {
    parts: FetchParts,
    links: [ObjectId; FETCH_LINKS],
    joints: FetchJoints,
    ik: IkSolver,
    limits: [Option<[f32; 2]>; ARM_JOINTS],
}

impl FetchArm {
    pub(crate) fn new(parts: FetchParts, joints: FetchJoints, ik: IkSolver) -> FetchArm {
        FetchArm {
            parts,
            links: parts.all(),
            joints,
            ik,
            limits: std::array::from_fn(|k| joint(k).info().limits),
        }
    }

    /// Fetch's joints with the torso and arm at `c`, the head where it is.
    fn joints_at(&self, c: &ArmConfig) -> FetchJoints {
        let at = |k: usize, now: f32| c.values().get(k).copied().unwrap_or(now);
        FetchJoints {
            torso: at(0, self.joints.torso),
            head: self.joints.head,
            arm: std::array::from_fn(|k| at(k + 1, self.joints.arm[k])),
        }
    }
}

/// The torso and arm positions of `joints`.
pub(crate) fn config_of(joints: &FetchJoints) -> ArmConfig {
    ArmConfig::from_fn(ARM_JOINTS, |k| match k {
        0 => joints.torso,
        _ => joints.arm[k - 1],
    })
}

impl Arm for FetchArm {
    fn hand(&self) -> usize {
        0
    }

    fn now(&self) -> ArmConfig {
        config_of(&self.joints)
    }

    fn limits(&self) -> &[Option<[f32; 2]>] {
        &self.limits
    }

    fn links(&self) -> &[ObjectId] {
        &self.links
    }

    /// From the torso on: the head rides on the torso.
    fn moving(&self) -> Range<usize> {
        1..FETCH_LINKS
    }

    fn gripper(&self) -> usize {
        FetchLink::Gripper as usize
    }

    fn link_poses(&self, c: &ArmConfig) -> Vec<Pose> {
        self.joints_at(c).link_poses().to_vec()
    }

    fn eef(&self, c: &ArmConfig) -> Pose {
        self.joints_at(c).eef()
    }

    fn ik(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig> {
        let solved = self.ik.solve(&self.joints_at(start), goal).ok()?;
        Some(config_of(&solved))
    }

    fn ik_near(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig> {
        let solved = self.ik.solve_near(&self.joints_at(start), goal).ok()?;
        Some(config_of(&solved))
    }

    fn lift_joint(&self) -> Option<usize> {
        Some(0)
    }

    fn tucked(&self, from: &ArmConfig) -> ArmConfig {
        let mut tucked = *from;
        tucked.values_mut()[1..].copy_from_slice(&TUCKED);
        tucked
    }

    /// Fetch's own blocking box: pads 6 × 1.4 × 2.6 cm, each travelling 5 cm out.
    fn finger_sweep(&self) -> (Primitive, Pose) {
        let half_extents = Vector::new(0.03, 0.0643, 0.01315);
        (
            Primitive::Box { half_extents },
            Pose::from_translation(Vector::new(0.001, 0.0, 0.0)),
        )
    }

    /// The pads' ends (Fetch's pads reach 3.1 cm beyond its finger-joint line).
    fn tip(&self) -> f32 {
        0.031
    }

    fn gripper_bodies(&self) -> Vec<BodyRef> {
        self.parts.gripper_bodies().to_vec()
    }

    fn fingers_open(&self, world: &World) -> bool {
        let [a, b] = crate::gripper::fingers(world, self.parts.gripper(), &GRIPPER);
        a.min(b) >= 0.9 * FINGER_OPEN
    }

    /// Fetch's joint action gives rates: `from` does not matter.
    fn joint_action(&self, _from: &ArmConfig, delta: &ArmConfig, gripper: f32) -> Option<Vec<f32>> {
        let mut values = [0.0; FETCH_JOINT_ACTION_DIM];
        for (k, &d) in delta.values().iter().enumerate().take(ARM_JOINTS) {
            values[FetchJointAction::JOINTS.start + k] = FetchJointAction::value_for(k, d);
        }
        values[FetchJointAction::GRIPPER] = gripper;
        let action = FetchJointAction::new(&values).ok()?;
        Some(action.values().to_vec())
    }

    fn after(&self, c: &ArmConfig, action: &[f32]) -> ArmConfig {
        let Ok(action) = FetchJointAction::new(action) else {
            return *c;
        };
        let command = FetchCommand::Joints(action);
        config_of(&step_joints(&self.ik, &self.joints_at(c), &command).0)
    }
}
