//! Inverse kinematics for Fetch's arm: which torso and arm positions put the end effector at a
//! pose in the base frame.
//!
//! Numeric, as pybullet's `calculateInverseKinematics` that iGibson uses (iGibson 2.0.3's Fetch IK
//! controller): damped least squares on the geometric Jacobian of the 8 joints that move the end
//! effector (torso lift and the 7 arm joints), each iterate clamped to the joint limits, with a
//! pull toward a rest pose (iGibson: the untucked default) projected into the Jacobian's null space
//! so that it never fights the target. It starts from the given positions (the robot's current
//! ones: small
//! steps converge in a few iterations) and, failing that, once more from the rest pose.
//!
//! A target it cannot reach within [`IkSolver::position_tolerance`] and
//! [`IkSolver::rotation_tolerance`] is an error, [`IkError::Unreachable`], which carries the
//! closest positions found: the controller moves there, as the original moves toward pybullet's
//! best answer. Without the trunk ([`IkSolver::with_trunk`] false) the torso stays where it is.

use crate::fetch_body::{FetchJoint, FetchJoints, GRIPPER_OFFSET};
use rapier3d::math::{Pose, Rotation, Vector};

/// The joints the solver moves: torso lift, then the 7 arm joints.
pub const IK_JOINTS: usize = 8;

/// Why there is no solution.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug, PartialEq, thiserror::Error)]
pub enum IkError {
    /// The target or the starting positions are not finite numbers.
    #[error("an IK target and start must be finite, with a unit quaternion for the rotation")]
    NotFinite,
    /// No positions within the joint limits put the end effector there (or the solver did not
    /// find them); `closest` is the best it found.
    #[error(
        "the target is out of reach: the closest pose found is {position_error:.3} m and \
         {rotation_error:.3} rad away"
    )]
    Unreachable {
        /// How far the closest end-effector position is from the target's, m.
        position_error: f32,
        /// How far the closest end-effector rotation is from the target's, rad.
        rotation_error: f32,
        /// The closest positions found.
        closest: FetchJoints,
    },
}

/// The solver's settings; [`Default`] gives those of the robot's controller.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub struct IkSolver {
    /// Whether the torso lift moves too (iGibson's `ik_with_trunk`, on by default).
    pub with_trunk: bool,
    /// The pose the null-space pull prefers.
    pub rest: FetchJoints,
    /// Iterations per attempt.
    pub max_iterations: u32,
    /// A solution puts the end effector within this distance of the target, m.
    pub position_tolerance: f32,
    /// ... and within this angle of its rotation, rad.
    pub rotation_tolerance: f32,
}

impl Default for IkSolver {
    fn default() -> Self {
        IkSolver {
            with_trunk: true,
            rest: FetchJoints::default(),
            max_iterations: 100,
            position_tolerance: 0.005,
            rotation_tolerance: 0.02,
        }
    }
}

/// Iterating stops once the error is this small (m, rad): far below what is asked.
pub(crate) const CONVERGED: (f32, f32) = (1e-4, 1e-3);
/// The damping of the least-squares step (m): keeps steps small near singularities.
const DAMPING: f64 = 0.05;
/// The largest change of one joint in one iteration (rad or m).
const MAX_STEP: f64 = 0.3;
/// The fraction of the way to the rest pose the null-space pull asks per iteration.
const REST_PULL: f64 = 0.05;

type Jacobian = [[f64; IK_JOINTS]; 6];

/// The end effector's pose and Jacobian at `q` (torso, then arm).
fn jacobian(q: &FetchJoints) -> (Pose, Jacobian) {
    let mut points = [Vector::ZERO; IK_JOINTS];
    let mut axes = [Vector::ZERO; IK_JOINTS];
    let torso = FetchJoint::TorsoLift.info();
    points[0] = torso.origin;
    axes[0] = torso.axis;
    let mut frame = FetchJoint::TorsoLift.transform(q.torso);
    for (k, joint) in FetchJoint::ARM.iter().enumerate() {
        let at = frame * Pose::from_translation(joint.info().origin);
        points[k + 1] = at.translation;
        axes[k + 1] = at.rotation * joint.info().axis;
        frame *= joint.transform(q.arm[k]);
    }
    let eef = frame * Pose::from_translation(GRIPPER_OFFSET);
    let mut j = [[0.0; IK_JOINTS]; 6];
    for k in 0..IK_JOINTS {
        let (linear, angular) = if k == 0 {
            (axes[0], Vector::ZERO)
        } else {
            (axes[k].cross(eef.translation - points[k]), axes[k])
        };
        for (row, value) in linear
            .to_array()
            .into_iter()
            .chain(angular.to_array())
            .enumerate()
        {
            j[row][k] = f64::from(value);
        }
    }
    (eef, j)
}

/// The rotation vector (axis × angle, the short way) taking `from` to `to`.
pub(crate) fn rotation_error(from: Rotation, to: Rotation) -> Vector {
    let mut q = to * from.inverse();
    if q.w < 0.0 {
        q = -q;
    }
    q.to_scaled_axis()
}

/// Solves `a x = b` for a symmetric positive definite 6 × 6 `a` (Cholesky).
pub(crate) fn solve6(a: &[[f64; 6]; 6], b: &[f64; 6]) -> [f64; 6] {
    let mut l = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..=i {
            let s: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
            l[i][j] = if i == j {
                (a[i][i] - s).max(1e-12).sqrt()
            } else {
                (a[i][j] - s) / l[j][j]
            };
        }
    }
    let mut y = [0.0; 6];
    for i in 0..6 {
        let s: f64 = (0..i).map(|k| l[i][k] * y[k]).sum();
        y[i] = (b[i] - s) / l[i][i];
    }
    let mut x = [0.0; 6];
    for i in (0..6).rev() {
        let s: f64 = (i + 1..6).map(|k| l[k][i] * x[k]).sum();
        x[i] = (y[i] - s) / l[i][i];
    }
    x
}

/// `(J Jᵀ + λ² I)⁻¹ e`.
fn damped_solve(j: &Jacobian, e: &[f64; 6]) -> [f64; 6] {
    let mut a = [[0.0; 6]; 6];
    for (r, row) in a.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            *cell = (0..IK_JOINTS).map(|k| j[r][k] * j[c][k]).sum();
        }
        row[r] += DAMPING * DAMPING;
    }
    solve6(&a, e)
}

fn jt_times(j: &Jacobian, y: &[f64; 6]) -> [f64; IK_JOINTS] {
    std::array::from_fn(|k| (0..6).map(|r| j[r][k] * y[r]).sum())
}

fn to_vec(q: &FetchJoints) -> [f64; IK_JOINTS] {
    std::array::from_fn(|k| f64::from(if k == 0 { q.torso } else { q.arm[k - 1] }))
}

/// A finished attempt: where it ended and how far from the target.
struct Attempt {
    q: FetchJoints,
    position_error: f32,
    rotation_error: f32,
}

impl Attempt {
    /// The error of a solver whose best attempt this was.
    fn unreachable(self) -> IkError {
        IkError::Unreachable {
            position_error: self.position_error,
            rotation_error: self.rotation_error,
            closest: self.q,
        }
    }
}

/// The target with its rotation normalized, if it and the start are finite and its rotation
/// a unit quaternion.
fn checked(start: &FetchJoints, target: &Pose) -> Result<Pose, IkError> {
    let unit = (target.rotation.length() - 1.0).abs() < 1e-3;
    if !(start.is_finite() && target.is_finite() && unit) {
        return Err(IkError::NotFinite);
    }
    Ok(Pose::from_parts(
        target.translation,
        target.rotation.normalize(),
    ))
}

impl IkSolver {
    /// The torso and arm positions that put the end effector at `target` (in the base frame),
    /// starting from `start`; the head keeps `start`'s positions. See the module docs.
    pub fn solve(&self, start: &FetchJoints, target: &Pose) -> Result<FetchJoints, IkError> {
        let target = checked(start, target)?;
        let first = self.attempt(start.clamped(), &target, REST_PULL);
        if self.reached(&first) {
            return Ok(first.q);
        }
        let rest = FetchJoints {
            torso: if self.with_trunk {
                self.rest.torso
            } else {
                start.torso
            },
            head: start.head,
            arm: self.rest.arm,
        };
        let second = self.attempt(rest.clamped(), &target, REST_PULL);
        if self.reached(&second) {
            return Ok(second.q);
        }
        let best = if second.position_error < first.position_error {
            second
        } else {
            first
        };
        Err(best.unreachable())
    }

    /// The torso and arm positions nearest `start` that put the end effector at `target` (in
    /// the base frame): one attempt from `start`, with no pull toward the rest pose. For small
    /// moves along a path (a straight line a centimetre at a time), where [`IkSolver::solve`]'s
    /// pull, iterated, carries a redundant arm to another branch (traced: a 4 mm descent asked
    /// the elbow and wrist to turn by 0.5–1.4 rad).
    pub fn solve_near(&self, start: &FetchJoints, target: &Pose) -> Result<FetchJoints, IkError> {
        let target = checked(start, target)?;
        let only = self.attempt(start.clamped(), &target, 0.0);
        if self.reached(&only) {
            return Ok(only.q);
        }
        Err(only.unreachable())
    }

    fn reached(&self, a: &Attempt) -> bool {
        a.position_error <= self.position_tolerance && a.rotation_error <= self.rotation_tolerance
    }

    /// Damped least squares from `q`, pulled toward the rest pose by `rest_pull` of the way per
    /// iteration (see the module docs).
    fn attempt(&self, mut q: FetchJoints, target: &Pose, rest_pull: f64) -> Attempt {
        let rest = to_vec(&self.rest);
        for _ in 0..self.max_iterations {
            let (eef, mut j) = jacobian(&q);
            let dp = target.translation - eef.translation;
            let dr = rotation_error(eef.rotation, target.rotation);
            if dp.length() < CONVERGED.0 && dr.length() < CONVERGED.1 {
                break;
            }
            if !self.with_trunk {
                j.iter_mut().for_each(|row| row[0] = 0.0);
            }
            let e: [f64; 6] =
                std::array::from_fn(|r| f64::from(if r < 3 { dp[r] } else { dr[r - 3] }));
            let mut dq = jt_times(&j, &damped_solve(&j, &e));
            // The pull toward rest, less what would move the end effector.
            let now = to_vec(&q);
            let mut pull: [f64; IK_JOINTS] =
                std::array::from_fn(|k| rest_pull * (rest[k] - now[k]));
            if !self.with_trunk {
                pull[0] = 0.0;
            }
            let jz: [f64; 6] =
                std::array::from_fn(|r| (0..IK_JOINTS).map(|k| j[r][k] * pull[k]).sum());
            let back = jt_times(&j, &damped_solve(&j, &jz));
            for k in 0..IK_JOINTS {
                dq[k] += pull[k] - back[k];
            }
            let largest = dq.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let scale = if largest > MAX_STEP {
                MAX_STEP / largest
            } else {
                1.0
            };
            q.torso += (dq[0] * scale) as f32;
            for k in 0..7 {
                q.arm[k] += (dq[k + 1] * scale) as f32;
            }
            q = q.clamped();
        }
        let eef = q.eef();
        Attempt {
            q,
            position_error: (target.translation - eef.translation).length(),
            rotation_error: rotation_error(eef.rotation, target.rotation).length(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_analytic_jacobian_matches_finite_differences() {
        let q = FetchJoints::default();
        let (eef, j) = jacobian(&q);
        let h = 1e-3;
        for k in 0..IK_JOINTS {
            let mut moved = q;
            if k == 0 {
                moved.torso += h;
            } else {
                moved.arm[k - 1] += h;
            }
            let after = moved.eef();
            let dp = (after.translation - eef.translation) / h;
            let dr = rotation_error(eef.rotation, after.rotation) / h;
            let numeric: Vec<f32> = dp.to_array().into_iter().chain(dr.to_array()).collect();
            for (r, (&x, row)) in numeric.iter().zip(&j).enumerate() {
                assert!((f64::from(x) - row[k]).abs() < 2e-3, "joint {k} row {r}");
            }
        }
    }

    #[test]
    fn a_small_move_solved_near_the_start_stays_near_it() {
        // An arm reaching down to the floor (traced in a grasp of a tile): 4 mm further down.
        let c = [
            0.0712, -0.165, 0.4038, -0.0251, 1.1981, -0.6542, -0.0384, 1.7148,
        ];
        let start = FetchJoints {
            torso: c[0],
            head: [0.0, 0.0],
            arm: std::array::from_fn(|k| c[k + 1]),
        };
        let mut target = start.eef();
        target.translation.z -= 0.004;
        let solver = IkSolver::default();
        let near = solver.solve_near(&start, &target).unwrap();
        let moved = |q: &FetchJoints| {
            (0..7)
                .map(|k| (q.arm[k] - start.arm[k]).abs())
                .fold((q.torso - start.torso).abs(), f32::max)
        };
        assert!(moved(&near) < 0.05, "moved {} rad", moved(&near));
        assert!((near.eef().translation - target.translation).length() <= 0.005);
        // The solver with the pull toward rest ends on another branch of the redundant arm.
        let pulled = solver.solve(&start, &target).unwrap();
        assert!(moved(&pulled) > 0.25, "moved {} rad", moved(&pulled));
        // Out of reach, it says how close it came.
        target.translation.z -= 2.0;
        assert!(matches!(
            solver.solve_near(&start, &target),
            Err(IkError::Unreachable { .. })
        ));
    }

    #[test]
    fn a_linear_system_is_solved() {
        let mut a = [[0.0; 6]; 6];
        for (i, row) in a.iter_mut().enumerate() {
            row[i] = 2.0 + i as f64;
            if i > 0 {
                row[i - 1] = 0.5;
            }
            if i < 5 {
                row[i + 1] = 0.5;
            }
        }
        let b = [1.0, -2.0, 3.0, 0.5, 0.0, 4.0];
        let x = solve6(&a, &b);
        for i in 0..6 {
            let ax: f64 = (0..6).map(|k| a[i][k] * x[k]).sum();
            assert!((ax - b[i]).abs() < 1e-9);
        }
    }
}
