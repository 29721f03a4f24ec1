//! What the BehaviorRobot feels of itself: 22 numbers, as iGibson 2.0.3's
//! (`robots/behavior_robot.py`).
//!
//! | index | value |
//! |---|---|
//! | 0–2, 3–5 | left palm position and roll, pitch, yaw in the body frame |
//! | 6–8, 9–11 | right palm, the same |
//! | 12–14, 15–17 | eye, the same |
//! | 18, 19 | left and right trigger fractions |
//! | 20, 21 | left and right hand holding something (1) or not (0) |
//!
//! The hands' entries are where the palms are, not where they were sent. iGibson 2.0.3 fills
//! the eye's slot with the right hand's pose (a documented bug); ours is the eye's. The 20-d
//! vector of 2.0.0–2.0.2 and of the paper's baselines is the first 20 entries.

use rapier3d::glamx::EulerRot;
use rapier3d::math::Pose;

/// A part's pose in the body frame, as proprioception reports it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LocalPose {
    /// m.
    pub position: [f32; 3],
    /// Roll about x, pitch about y, yaw about z (fixed axes, applied in that order), rad.
    pub euler: [f32; 3],
}

impl LocalPose {
    pub(crate) fn of(pose: Pose) -> LocalPose {
        let (yaw, pitch, roll) = pose.rotation.to_euler(EulerRot::ZYX);
        LocalPose {
            position: pose.translation.to_array(),
            euler: [roll, pitch, yaw],
        }
    }
}

/// The BehaviorRobot's proprioception (see the module docs for the layout).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Proprioception {
    /// The palms (left, right).
    pub hands: [LocalPose; 2],
    /// The eye.
    pub eye: LocalPose,
    /// The trigger fractions (left, right), in [0, 1].
    pub triggers: [f32; 2],
    /// Whether each hand (left, right) holds something.
    pub grasping: [bool; 2],
}

impl Proprioception {
    /// How many numbers [`Proprioception::to_array`] gives.
    pub const DIM: usize = 22;

    /// The 22 numbers, in the order of the module docs.
    pub fn to_array(&self) -> [f32; Proprioception::DIM] {
        let mut out = [0.0; Proprioception::DIM];
        let poses = [self.hands[0], self.hands[1], self.eye];
        for (k, pose) in poses.iter().enumerate() {
            out[6 * k..6 * k + 3].copy_from_slice(&pose.position);
            out[6 * k + 3..6 * k + 6].copy_from_slice(&pose.euler);
        }
        out[18..20].copy_from_slice(&self.triggers);
        out[20] = f32::from(u8::from(self.grasping[0]));
        out[21] = f32::from(u8::from(self.grasping[1]));
        out
    }
}
