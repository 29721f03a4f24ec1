//! Each of the R1's arms as an [`Arm`]: the torso's four joints and the arm's seven, read
//! through one [`Chain`] from the base to the end effector (forward kinematics, damped
//! least-squares IK) and the 23-d action's absolute joint positions. The torso is part of each
//! arm, as Fetch's torso lift is part of its: bent forward, it takes a hand over a table the
//! arm alone does not reach from where the base can stand.

use crate::arm::{Arm, ArmConfig};
use crate::chain::{Chain, ChainIk};
use crate::hand::Side;
use crate::r1::GRIPPER;
use crate::r1_action::{R1Action, step_toward};
use crate::r1_body::{R1_LINKS, R1_TIP, R1Joints, R1Link, finger_sweep};
use crate::r1_kinematics::{R1_ARM_JOINTS, R1_FINGER_OPEN, R1_TORSO_JOINTS, torso_arm_chain};
use behavior_sim::{BodyRef, ObjectId, Primitive, STEP_SECONDS, World};
use rapier3d::math::Pose;
use std::ops::Range;

/// The joints of an arm's configuration: the torso's, then the arm's.
const JOINTS: usize = R1_TORSO_JOINTS + R1_ARM_JOINTS;

/// How many seeds beyond the start [`Arm::ik`] tries.
const IK_SEEDS: usize = 8;

/// One arm of an R1 as it stands: its side, the robot's objects, where every joint is, and the
/// chain of its torso and arm.
#[derive(Clone, Debug)]
pub(crate) struct R1Arm {
    side: Side,
    links: Vec<ObjectId>,
    joints: R1Joints,
    chain: Chain,
    limits: [Option<[f32; 2]>; JOINTS],
}

impl R1Arm {
    pub(crate) fn new(side: Side, links: Vec<ObjectId>, joints: R1Joints) -> R1Arm {
        let chain = torso_arm_chain(side);
        let limits = std::array::from_fn(|k| chain.joints[k].limits);
        R1Arm {
            side,
            links,
            joints,
            chain,
            limits,
        }
    }

    /// The robot's joints with the torso and this arm at `c`, the other arm where it is.
    fn joints_at(&self, c: &ArmConfig) -> R1Joints {
        let mut joints = self.joints;
        let at = |k: usize, now: f32| c.values().get(k).copied().unwrap_or(now);
        for (k, q) in joints.torso.iter_mut().enumerate() {
            *q = at(k, *q);
        }
        for (k, q) in joints.arms[self.side.index()].iter_mut().enumerate() {
            *q = at(R1_TORSO_JOINTS + k, *q);
        }
        joints
    }

    fn config_of(&self, joints: &R1Joints) -> ArmConfig {
        let arm = &joints.arms[self.side.index()];
        ArmConfig::from_fn(JOINTS, |k| match k {
            k if k < R1_TORSO_JOINTS => joints.torso[k],
            k => arm[k - R1_TORSO_JOINTS],
        })
    }

    /// The `n`th IK seed: the torso where `start` has it and each arm joint at a point of the
    /// Halton sequence over its range (its own prime base), the same for every arm and call.
    fn seed(&self, start: &ArmConfig, n: usize) -> Vec<f32> {
        const PRIMES: [usize; R1_ARM_JOINTS] = [2, 3, 5, 7, 11, 13, 17];
        let halton = |mut i: usize, base: usize| {
            let (mut f, mut r) = (1.0, 0.0);
            i += 1;
            while i > 0 {
                f /= base as f32;
                r += f * (i % base) as f32;
                i /= base;
            }
            r
        };
        let arm = &self.chain.joints[R1_TORSO_JOINTS..];
        let arm = arm.iter().zip(PRIMES).map(|(joint, base)| {
            let [lo, hi] = joint
                .limits
                .unwrap_or([-std::f32::consts::PI, std::f32::consts::PI]);
            lo + (hi - lo) * halton(n, base)
        });
        start.values()[..R1_TORSO_JOINTS]
            .iter()
            .copied()
            .chain(arm)
            .collect()
    }

    fn palm(&self) -> ObjectId {
        self.links[R1Link::Gripper(self.side).index()]
    }
}

impl Arm for R1Arm {
    fn hand(&self) -> usize {
        self.side.index()
    }

    fn now(&self) -> ArmConfig {
        self.config_of(&self.joints)
    }

    fn limits(&self) -> &[Option<[f32; 2]>] {
        &self.limits
    }

    fn links(&self) -> &[ObjectId] {
        &self.links
    }

    /// Every link above the base: the torso carries both arms.
    fn moving(&self) -> Range<usize> {
        1..R1_LINKS
    }

    fn gripper(&self) -> usize {
        R1Link::Gripper(self.side).index()
    }

    fn link_poses(&self, c: &ArmConfig) -> Vec<Pose> {
        self.joints_at(c).link_poses()
    }

    fn eef(&self, c: &ArmConfig) -> Pose {
        self.chain.tip(c.values())
    }

    /// From `start`, then from [`IK_SEEDS`] arm postures spread over the joints' ranges (the
    /// torso where `start` has it): damped least squares from one start stops at a joint's
    /// limit short of many poses the arm can take.
    fn ik(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig> {
        let ik = ChainIk {
            max_iterations: 120,
            ..ChainIk::default()
        };
        let seeds = (0..IK_SEEDS).map(|n| self.seed(start, n));
        let solved = std::iter::once(start.values().to_vec())
            .chain(seeds)
            .find_map(|seed| self.chain.solve(&seed, goal, &ik))?;
        Some(ArmConfig::new(&solved))
    }

    fn ik_near(&self, start: &ArmConfig, goal: &Pose) -> Option<ArmConfig> {
        let solved = self
            .chain
            .solve(start.values(), goal, &ChainIk::default())?;
        Some(ArmConfig::new(&solved))
    }

    /// Its torso bends rather than lifts: no joint raises it straight up.
    fn lift_joint(&self) -> Option<usize> {
        None
    }

    /// The arm hanging straight down (OmniGibson's tucked R1 Pro: every arm joint 0), the
    /// torso where it is.
    fn tucked(&self, from: &ArmConfig) -> ArmConfig {
        ArmConfig::from_fn(
            from.len(),
            |k| if k < R1_TORSO_JOINTS { from[k] } else { 0.0 },
        )
    }

    fn finger_sweep(&self) -> (Primitive, Pose) {
        let part = finger_sweep();
        (part.primitive, part.offset)
    }

    fn tip(&self) -> f32 {
        R1_TIP
    }

    fn gripper_bodies(&self) -> Vec<BodyRef> {
        crate::gripper::bodies(self.palm(), &GRIPPER).to_vec()
    }

    fn fingers_open(&self, world: &World) -> bool {
        let [a, b] = crate::gripper::fingers(world, self.palm(), &GRIPPER);
        a.min(b) >= 0.9 * R1_FINGER_OPEN
    }

    /// The 23-d action with the torso and this arm at `from` + `delta`, the other arm held
    /// where it is, the base still, the other gripper left as it is.
    fn joint_action(&self, from: &ArmConfig, delta: &ArmConfig, gripper: f32) -> Option<Vec<f32>> {
        let target = ArmConfig::from_fn(from.len(), |k| from[k] + delta[k]);
        if !target.is_finite() || !gripper.is_finite() {
            return None;
        }
        let mut values = *R1Action::holding(&self.joints_at(&target)).values();
        values[R1Action::gripper_index(self.side)] = gripper;
        let action = R1Action::new(&values).ok()?;
        Some(action.values().to_vec())
    }

    fn after(&self, c: &ArmConfig, action: &[f32]) -> ArmConfig {
        let Ok(action) = R1Action::new(action) else {
            return *c;
        };
        let now = self.joints_at(c);
        let target = action.joints();
        self.config_of(&step_toward(&now, &target, STEP_SECONDS))
    }
}
