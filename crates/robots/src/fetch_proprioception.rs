//! What Fetch feels of itself: 49 numbers, as iGibson 2.0's `FetchGripper` (iGibson 2.0.3's
//! `robots/fetch_gripper_robot.py`).
//!
//! | index | value |
//! |---|---|
//! | 0–2 | end-effector position in the base frame, m |
//! | 3–5 | end-effector roll, pitch, yaw in the base frame (fixed axes x, y, z), rad |
//! | 6 | holding something (1) or not (0) |
//! | 7 + 3k, 8 + 3k, 9 + 3k | joint k's position, velocity and effort |
//!
//! with the 14 joints k in [`FetchJoint::ALL`] order: right wheel, left wheel, torso lift, head
//! pan, head tilt, shoulder pan, shoulder lift, upper-arm roll, elbow flex, forearm roll, wrist
//! flex, wrist roll, right finger, left finger (iGibson's `ordered_joints`).
//!
//! Positions are the joints' own (a wheel's angle accumulates; roll joints are not wrapped).
//! Velocities of the wheels, torso, head and arm are those of the step just taken. Efforts:
//! the fingers' are their drives' (see `behavior_sim::JointState`); the torso's and arm's are
//! the static loads they carry (gravity on the links beyond them and on what the gripper holds),
//! since those joints are moved kinematically and no motor reports a torque; the wheels' and the
//! head's are 0.

use crate::fetch_body::{FETCH_JOINTS, FetchJoint};
use crate::proprioception::LocalPose;
use behavior_sim::JointState;

/// Fetch's proprioception (see the module docs for the layout).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FetchProprioception {
    /// The end effector in the base frame.
    pub eef: LocalPose,
    /// Whether the gripper holds something.
    pub grasping: bool,
    /// Every joint's state, in [`FetchJoint::ALL`] order.
    pub joints: [JointState; FETCH_JOINTS],
}

impl FetchProprioception {
    /// How many numbers [`FetchProprioception::to_array`] gives.
    pub const DIM: usize = 7 + 3 * FETCH_JOINTS;

    /// A joint's state.
    pub fn joint(&self, joint: FetchJoint) -> JointState {
        self.joints[joint.index()]
    }

    /// The 49 numbers, in the order of the module docs.
    pub fn to_array(&self) -> [f32; FetchProprioception::DIM] {
        let mut out = [0.0; FetchProprioception::DIM];
        out[0..3].copy_from_slice(&self.eef.position);
        out[3..6].copy_from_slice(&self.eef.euler);
        out[6] = f32::from(u8::from(self.grasping));
        for (k, s) in self.joints.iter().enumerate() {
            out[7 + 3 * k..10 + 3 * k].copy_from_slice(&[s.position, s.velocity, s.effort]);
        }
        out
    }
}
