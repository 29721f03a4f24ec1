//! A serial chain of joints as a URDF states it — each joint where it sits in its parent link's
//! frame, how it moves, its limits — with its forward kinematics and a damped-least-squares
//! inverse kinematics over any number of joints: what a jointed robot is described by, so that
//! a new robot is a table of numbers rather than new kinematics code.
//!
//! The inverse kinematics is the method Fetch's controller uses (`ik.rs`, pybullet's
//! `calculateInverseKinematics` as iGibson calls it): the geometric Jacobian of the joints
//! that move the tip, `(J Jᵀ + λ² I)⁻¹` steps, each joint clamped to its limits every
//! iteration, the step per joint bounded; here without the pull toward a rest pose, from the
//! start given (a planner restarts it from elsewhere).

use crate::ik::{CONVERGED, rotation_error, solve6};
use behavior_sim::JointKind;
use rapier3d::math::{Pose, Rotation, Vector};

/// One joint of a chain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainJoint {
    /// The URDF name.
    pub name: &'static str,
    /// Revolute (turns about `axis`, rad) or prismatic (slides along it, m); a fixed one
    /// (a mount) is folded into the next joint's origin instead.
    pub kind: JointKind,
    /// Where the joint sits in its parent link's frame (URDF `origin`: xyz, then the fixed
    /// rotation of its rpy).
    pub origin: Pose,
    /// The axis in the joint's frame.
    pub axis: Vector,
    /// Lower and upper position, or `None` for a continuous joint.
    pub limits: Option<[f32; 2]>,
    /// Its fastest motion, rad/s or m/s.
    pub max_velocity: f32,
}

/// A URDF `origin`: the translation `xyz` and the rotation of `rpy` (fixed axes: roll about x,
/// then pitch about y, then yaw about z).
pub fn urdf_origin(xyz: [f32; 3], [roll, pitch, yaw]: [f32; 3]) -> Pose {
    let rotation = Rotation::from_rotation_z(yaw)
        * Rotation::from_rotation_y(pitch)
        * Rotation::from_rotation_x(roll);
    Pose::from_parts(Vector::from_array(xyz), rotation)
}

impl ChainJoint {
    /// The transform across the joint at position `q`: to its origin, then along or about its
    /// axis.
    pub fn transform(&self, q: f32) -> Pose {
        let motion = match self.kind {
            JointKind::Revolute => Pose::from_rotation(Rotation::from_axis_angle(self.axis, q)),
            JointKind::Prismatic => Pose::from_translation(self.axis * q),
            JointKind::Fixed => Pose::IDENTITY,
        };
        self.origin * motion
    }

    /// `q` within the joint's limits.
    pub fn clamp(&self, q: f32) -> f32 {
        self.limits.map_or(q, |[lo, hi]| q.clamp(lo, hi))
    }
}

/// The inverse kinematics' settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainIk {
    /// Iterations at most.
    pub max_iterations: u32,
    /// A solution puts the tip within this distance of the target, m.
    pub position_tolerance: f32,
    /// ... and within this angle of its rotation, rad.
    pub rotation_tolerance: f32,
    /// The damping of the least-squares step, m: keeps steps small near singularities.
    pub damping: f64,
    /// The largest change of one joint in one iteration (rad or m).
    pub max_step: f64,
}

impl Default for ChainIk {
    /// Fetch's controller's numbers (`ik.rs`).
    fn default() -> Self {
        ChainIk {
            max_iterations: 100,
            position_tolerance: 0.005,
            rotation_tolerance: 0.02,
            damping: 0.05,
            max_step: 0.3,
        }
    }
}

/// A serial chain from a root frame (in the robot's base frame) through its joints to a tip
/// (the end effector, fixed to the last joint's link).
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// Where the chain starts, in the base frame.
    pub root: Pose,
    /// The joints, root first.
    pub joints: Vec<ChainJoint>,
    /// The tip in the last joint's link frame.
    pub tip: Pose,
}

impl Chain {
    /// Each joint's child link frame at `q` (one position per joint), in the base frame; a
    /// missing position counts as 0.
    pub fn link_poses(&self, q: &[f32]) -> Vec<Pose> {
        let mut frame = self.root;
        self.joints
            .iter()
            .enumerate()
            .map(|(k, joint)| {
                frame *= joint.transform(q.get(k).copied().unwrap_or(0.0));
                frame
            })
            .collect()
    }

    /// The tip's pose at `q`, in the base frame.
    pub fn tip(&self, q: &[f32]) -> Pose {
        let last = self.link_poses(q).last().copied().unwrap_or(self.root);
        last * self.tip
    }

    /// The tip's pose and the geometric Jacobian (rows: linear x y z, angular x y z; one column
    /// per joint) at `q`.
    fn jacobian(&self, q: &[f32]) -> (Pose, Vec<[f64; 6]>) {
        let mut frame = self.root;
        let mut axes = Vec::with_capacity(self.joints.len());
        for (k, joint) in self.joints.iter().enumerate() {
            let at = frame * joint.origin;
            axes.push((at.translation, at.rotation * joint.axis, joint.kind));
            frame *= joint.transform(q.get(k).copied().unwrap_or(0.0));
        }
        let tip = frame * self.tip;
        let columns = axes
            .into_iter()
            .map(|(point, axis, kind)| {
                let (linear, angular) = match kind {
                    JointKind::Revolute => (axis.cross(tip.translation - point), axis),
                    JointKind::Prismatic => (axis, Vector::ZERO),
                    JointKind::Fixed => (Vector::ZERO, Vector::ZERO),
                };
                let [a, b, c] = linear.to_array();
                let [d, e, f] = angular.to_array();
                [a, b, c, d, e, f].map(f64::from)
            })
            .collect();
        (tip, columns)
    }

    /// Joint positions within the limits that put the tip at `target` (base frame), searched
    /// from `start` by damped least squares; `None` where the search ends farther than the
    /// tolerances (or a number is not finite).
    pub fn solve(&self, start: &[f32], target: &Pose, ik: &ChainIk) -> Option<Vec<f32>> {
        let finite = start.iter().all(|x| x.is_finite()) && target.is_finite();
        if !finite || start.len() != self.joints.len() || target.rotation.length() < 0.5 {
            return None;
        }
        let target = Pose::from_parts(target.translation, target.rotation.normalize());
        let mut q: Vec<f32> = self
            .joints
            .iter()
            .zip(start)
            .map(|(j, &x)| j.clamp(x))
            .collect();
        for _ in 0..ik.max_iterations {
            let (tip, j) = self.jacobian(&q);
            let dp = target.translation - tip.translation;
            let dr = rotation_error(tip.rotation, target.rotation);
            if dp.length() < CONVERGED.0 && dr.length() < CONVERGED.1 {
                break;
            }
            let e = [dp.x, dp.y, dp.z, dr.x, dr.y, dr.z].map(f64::from);
            let mut a = [[0.0; 6]; 6];
            for (r, row) in a.iter_mut().enumerate() {
                for (c, cell) in row.iter_mut().enumerate() {
                    *cell = j.iter().map(|col| col[r] * col[c]).sum();
                }
                row[r] += ik.damping * ik.damping;
            }
            let y = solve6(&a, &e);
            for ((x, col), joint) in q.iter_mut().zip(&j).zip(&self.joints) {
                let step: f64 = (0..6).map(|r| col[r] * y[r]).sum();
                let step = step.clamp(-ik.max_step, ik.max_step) as f32;
                *x = joint.clamp(*x + step);
            }
        }
        let tip = self.tip(&q);
        let near = (tip.translation - target.translation).length() <= ik.position_tolerance;
        let turned =
            rotation_error(tip.rotation, target.rotation).length() <= ik.rotation_tolerance;
        (near && turned).then_some(q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::FRAC_PI_2;

    /// A planar two-link arm in the x–z plane: shoulder and elbow about y, links 0.4 and 0.3.
    fn planar() -> Chain {
        let hinge = |name, z| ChainJoint {
            name,
            kind: JointKind::Revolute,
            origin: Pose::from_translation(Vector::new(0.0, 0.0, z)),
            axis: Vector::Y,
            limits: Some([-3.0, 3.0]),
            max_velocity: 1.0,
        };
        Chain {
            root: Pose::IDENTITY,
            joints: vec![hinge("shoulder", 0.0), hinge("elbow", 0.4)],
            tip: Pose::from_translation(Vector::new(0.0, 0.0, 0.3)),
        }
    }

    #[test]
    fn forward_kinematics_follows_the_joints() {
        let arm = planar();
        assert!((arm.tip(&[0.0, 0.0]).translation - Vector::new(0.0, 0.0, 0.7)).length() < 1e-6);
        // The elbow bent a right angle about +y swings the forearm toward +x.
        let bent = arm.tip(&[0.0, FRAC_PI_2]).translation;
        assert!(
            (bent - Vector::new(0.3, 0.0, 0.4)).length() < 1e-6,
            "{bent:?}"
        );
        assert_eq!(arm.link_poses(&[0.0, 0.0]).len(), 2);
    }

    #[test]
    fn inverse_kinematics_finds_a_reachable_pose_and_refuses_an_unreachable_one() {
        let arm = planar();
        let goal = arm.tip(&[0.4, 0.9]);
        let q = arm.solve(&[0.0, 0.2], &goal, &ChainIk::default()).unwrap();
        let reached = arm.tip(&q);
        assert!((reached.translation - goal.translation).length() < 0.005);
        assert!(reached.rotation.angle_between(goal.rotation) < 0.02);
        let far = Pose::from_translation(Vector::new(2.0, 0.0, 0.0));
        assert!(arm.solve(&[0.0, 0.2], &far, &ChainIk::default()).is_none());
        let bad = Pose::from_translation(Vector::new(f32::NAN, 0.0, 0.0));
        assert!(arm.solve(&[0.0, 0.2], &bad, &ChainIk::default()).is_none());
        // Limits hold: a goal past them is not reached by leaving them.
        let mut tight = planar();
        tight.joints[1].limits = Some([-0.1, 0.1]);
        assert!(
            tight
                .solve(&[0.0, 0.0], &goal, &ChainIk::default())
                .is_none()
        );
    }

    #[test]
    fn a_urdf_origin_turns_roll_then_pitch_then_yaw_about_fixed_axes() {
        let pose = urdf_origin([1.0, 2.0, 3.0], [FRAC_PI_2, 0.0, FRAC_PI_2]);
        assert_eq!(pose.translation, Vector::new(1.0, 2.0, 3.0));
        // Roll takes y to z; yaw then leaves z alone.
        assert!((pose.rotation * Vector::Y - Vector::Z).length() < 1e-6);
        // x is untouched by roll and turned to y by yaw.
        assert!((pose.rotation * Vector::X - Vector::Y).length() < 1e-6);
    }
}
