//! The Galaxea R1 Pro (the robot of the BEHAVIOR Challenge 2025): adding it to a world,
//! stepping it, and reading it, through the [`Embodiment`] interface only.
//!
//! **Proprioception** (57 numbers):
//!
//! | index | value |
//! |---|---|
//! | 0–3, 4–10, 11–17 | torso, left arm, right arm joint positions, rad |
//! | 18–35 | the same joints' velocities in the last step, rad/s |
//! | 36–37, 38–39 | left and right gripper's finger positions, m (0 closed) |
//! | 40–42 | the base's velocity in the last step: forward, left (m/s), turning (rad/s) |
//! | 43–48, 49–54 | left and right end effector: position and roll, pitch, yaw in the base frame |
//! | 55, 56 | left and right gripper holding something (1) or not (0) |

use crate::action::{ActionError, ActionSpace};
use crate::arm::Arm;
use crate::embodiment::{
    BaseDrive, BaseMove, Embodiment, EmbodimentSpec, HandMotion, LidarMount, Scan,
};
use crate::grasp::GraspRules;
use crate::gripper::{GraspContext, GripperSpec, ParallelGripper};
use crate::hand::Side;
use crate::kinematic_links::{LinkModel, LinkMotion, Posture, add_links};
use crate::magic::MagicError;
use crate::proprioception::LocalPose;
use crate::r1_action::{R1_ACTION_DIM, R1_BASE_SPEED, R1Action, step_toward};
use crate::r1_arm::R1Arm;
use crate::r1_body::{
    R1_LINKS, R1Joints, R1Link, blocking_parts, gripper_spec, link_centre, link_spec,
};
use crate::r1_kinematics::head_camera;
use crate::robot::{RobotError, RobotKind, pose_ok};
use behavior_sim::{AttachmentId, ObjectId, Primitive, STEP_SECONDS, StepHooks, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};
use std::sync::{Arc, LazyLock};

/// The R1's parallel grippers' facts (both alike), made once.
pub(crate) static GRIPPER: LazyLock<GripperSpec> = LazyLock::new(gripper_spec);

/// The chassis lidar's place in the base frame, m (Galaxea's 2025 URDF: `lidar_chassis_left`).
const LIDAR_OFFSET: Vector = Vector::new(0.15711, 0.26215, 0.29465);

/// The Galaxea R1 Pro: a holonomic base, a 4-joint torso, two 7-joint arms with parallel
/// grippers, a head camera, driven by the challenge's 23-d [`R1Action`] (a velocity for the
/// base, absolute positions for the joints) and holding things by assisted grasping
/// ([`GraspRules`]), from the published facts of its URDF (`docs/r1-pro-facts.md`).
///
/// **Body model.** As Fetch's: every link a kinematic body placed by forward kinematics
/// (`r1_body.rs`, moved as `kinematic_links.rs` moves them): the base goes exactly where its
/// velocity takes it within the step, the joints move toward their positions at most at their
/// URDF velocities, no part is sent into a fixed body, movable things are pushed. Each gripper's
/// fingers are dynamic links on prismatic joints (the shared parallel gripper, `gripper.rs`).
///
/// **State.** What it was told lives here, the rest in the world; clone it with
/// [`World::snapshot`] and the pair continues bit-identically.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub struct R1 {
    /// Its objects, in [`R1Link`] order.
    links: Vec<ObjectId>,
    motion: LinkMotion<R1Joints>,
    /// The grippers (left, right).
    grippers: [ParallelGripper; 2],
    /// The action for the next step; none holds every joint where it is.
    pending: Option<R1Action>,
    rules: GraspRules,
}

impl R1 {
    /// What the R1 is, for planners and episodes.
    pub const SPEC: EmbodimentSpec = EmbodimentSpec {
        kind: RobotKind::R1,
        hand_names: &["left_gripper", "right_gripper"],
        origin_height: 0.0,
        drive: BaseDrive::Holonomic,
        hand_motion: HandMotion::Jointed,
        spaces: &[ActionSpace::Full, ActionSpace::Navigation],
        primitive_space: ActionSpace::Full,
        // The arms hang from shoulders over the base's front; bent forward, they reach about
        // as far beyond the base as Fetch's.
        arm_reach: 0.7,
        carry_sway: 0.01,
    };

    /// Adds an R1 with its base's origin at `pose` (a point on the floor's top at the centre of
    /// its wheels; only the rotation's yaw counts), in the challenge's reset pose (torso half
    /// bent, arms hanging, grippers open), with the original's grasp rules.
    pub fn add(world: &mut World, pose: Pose) -> Result<R1, RobotError> {
        if !pose_ok(&pose) {
            return Err(RobotError::BadPose);
        }
        let posture = Posture {
            base: upright(pose),
            joints: R1Joints::default(),
        };
        let poses = posture.joints.link_poses();
        let specs = (0..R1_LINKS).map(|k| link_spec(R1Link::of(k), posture.base * poses[k]));
        let links = add_links(world, specs)?;
        let grippers = [
            ParallelGripper::open_on(world, links[R1Link::Gripper(Side::Left).index()], &GRIPPER)?,
            ParallelGripper::open_on(world, links[R1Link::Gripper(Side::Right).index()], &GRIPPER)?,
        ];
        let robot = R1 {
            links,
            motion: LinkMotion::at(posture),
            grippers,
            pending: None,
            rules: GraspRules::default(),
        };
        robot.press(world);
        Ok(robot)
    }

    /// Checks `values` as an [`R1Action`] and, if it is one, takes a step of the world with it.
    /// A bad action is an error and leaves the world and the robot untouched.
    pub fn step(&mut self, world: &mut World, values: &[f32]) -> Result<(), ActionError> {
        self.pending = Some(R1Action::new(values)?);
        world.step_with(self);
        Ok(())
    }

    /// The joint positions (where the step begun last ends).
    pub fn joints(&self) -> R1Joints {
        self.motion.now.joints
    }

    /// The object of a link.
    pub fn link(&self, link: R1Link) -> ObjectId {
        self.links[link.index()]
    }

    /// The action that holds everything where it is.
    pub fn still(&self) -> R1Action {
        R1Action::holding(&self.motion.now.joints)
    }

    fn gripper_object(&self, side: Side) -> ObjectId {
        self.link(R1Link::Gripper(side))
    }

    /// Tells the world where both grippers' centres and pads are, for buttons.
    fn press(&self, world: &mut World) {
        let points = self.grippers.each_ref().map(|g| g.points(world, &GRIPPER));
        world.set_hand_points(&points.concat());
    }

    /// Takes the pending action: the step's base motion and joint targets, checked against
    /// fixed bodies, and the grippers' commands.
    fn begin_step(&mut self, world: &mut World) {
        let action = self.pending.take().unwrap_or_else(|| self.still());
        let joints = step_toward(&self.motion.now.joints, &action.joints(), STEP_SECONDS);
        self.motion
            .begin::<R1>(world, &self.links, action.twist(), joints);
        for side in Side::BOTH {
            let command = action.gripper(side);
            if command != 0.0 {
                self.grippers[side.index()].command(world, &GRIPPER, command);
            }
        }
    }

    /// Its proprioception (see the module docs for the layout).
    fn proprioception(&self, world: &World) -> Vec<f32> {
        let (from, now) = (self.motion.from.joints, self.motion.now.joints);
        let flat = |j: &R1Joints| -> Vec<f32> {
            j.torso
                .iter()
                .chain(j.arms.iter().flatten())
                .copied()
                .collect()
        };
        let (a, b) = (flat(&from), flat(&now));
        let mut out = b.clone();
        out.extend(a.iter().zip(&b).map(|(a, b)| (b - a) / STEP_SECONDS));
        for side in Side::BOTH {
            let g = &self.grippers[side.index()];
            out.extend(g.fingers(world, &GRIPPER));
        }
        let twist = self.motion.twist();
        out.extend([twist.forward, twist.left, twist.turn]);
        for side in Side::BOTH {
            let eef = LocalPose::of(now.eef(side));
            out.extend(eef.position.iter().chain(&eef.euler));
        }
        for g in &self.grippers {
            out.push(if g.holding().is_some() { 1.0 } else { 0.0 });
        }
        out
    }

    /// The gripper of hand `hand` and what its grasp reads of the robot.
    fn gripper(
        &mut self,
        hand: usize,
    ) -> Result<(&mut ParallelGripper, GraspContext<'_>), MagicError> {
        let side = R1::side(hand)?;
        let cx = GraspContext {
            spec: &GRIPPER,
            rules: &self.rules,
            own: &self.links,
        };
        Ok((&mut self.grippers[side.index()], cx))
    }

    /// The number of hand `hand` as a side: 0 left, 1 right.
    fn side(hand: usize) -> Result<Side, MagicError> {
        match hand {
            0 => Ok(Side::Left),
            1 => Ok(Side::Right),
            _ => Err(MagicError::NoHand(hand)),
        }
    }
}

/// `pose` with its rotation reduced to the yaw: the base stays upright.
fn upright(pose: Pose) -> Pose {
    let (yaw, _, _) = pose.rotation.normalize().to_euler(EulerRot::ZYX);
    Pose::from_parts(pose.translation, Rotation::from_rotation_z(yaw))
}

/// The R1's links for their motion: [`R1Link`]s placed by [`R1Joints::link_poses`].
impl LinkModel for R1 {
    type Joints = R1Joints;

    fn link_poses(joints: &R1Joints) -> Vec<Pose> {
        joints.link_poses()
    }

    fn between(a: &R1Joints, b: &R1Joints, t: f32) -> R1Joints {
        let lerp = |a: f32, b: f32| a + (b - a) * t;
        R1Joints {
            torso: std::array::from_fn(|k| lerp(a.torso[k], b.torso[k])),
            arms: std::array::from_fn(|i| {
                std::array::from_fn(|k| lerp(a.arms[i][k], b.arms[i][k]))
            }),
        }
    }

    fn centre(link: usize) -> Vector {
        link_centre(R1Link::of(link))
    }

    fn blocking(link: usize) -> Vec<(Primitive, Pose)> {
        let parts = blocking_parts(R1Link::of(link));
        parts.into_iter().map(|p| (p.primitive, p.offset)).collect()
    }
}

impl Embodiment for R1 {
    fn spec(&self) -> &'static EmbodimentSpec {
        &R1::SPEC
    }

    fn action_dim(&self, space: ActionSpace) -> usize {
        match space {
            ActionSpace::Full => R1_ACTION_DIM,
            ActionSpace::Navigation => 3,
            _ => 0,
        }
    }

    fn set_action(&mut self, space: ActionSpace, values: &[f32]) -> Result<(), ActionError> {
        let action = match space {
            ActionSpace::Full => R1Action::new(values)?,
            ActionSpace::Navigation => {
                if values.len() != 3 {
                    return Err(ActionError::WrongLength {
                        expected: 3,
                        got: values.len(),
                    });
                }
                let mut full = *self.still().values();
                full[R1Action::BASE].copy_from_slice(values);
                R1Action::new(&full)?
            }
            _ => {
                return Err(ActionError::Unsupported {
                    robot: RobotKind::R1.name(),
                    space: space.name(),
                });
            }
        };
        self.pending = Some(action);
        Ok(())
    }

    /// Holonomic: forward, sideways and turning at once, each within its top speed.
    fn base_action(&self, space: ActionSpace, step: BaseMove) -> Option<Vec<f32>> {
        let wanted = [step.forward, step.left, step.turn];
        let base: [f32; 3] = std::array::from_fn(|k| {
            (wanted[k] / (R1_BASE_SPEED[k] * STEP_SECONDS)).clamp(-1.0, 1.0)
        });
        match space {
            ActionSpace::Navigation => Some(base.to_vec()),
            ActionSpace::Full => {
                let mut full = *self.still().values();
                full[R1Action::BASE].copy_from_slice(&base);
                Some(full.to_vec())
            }
            _ => None,
        }
    }

    /// The base and grippers in [−1, 1], each joint within its limits.
    fn action_bounds(&self, space: ActionSpace) -> Vec<[f32; 2]> {
        match space {
            ActionSpace::Full => R1Action::bounds().to_vec(),
            _ => vec![[-1.0, 1.0]; self.action_dim(space)],
        }
    }

    fn still_action(&self, space: ActionSpace) -> Vec<f32> {
        match space {
            ActionSpace::Full => self.still().values().to_vec(),
            _ => vec![0.0; self.action_dim(space)],
        }
    }

    fn proprioception_dim(&self) -> usize {
        57
    }

    fn proprioception_into(&self, world: &World, out: &mut Vec<f32>) {
        out.extend(self.proprioception(world));
    }

    fn base_pose(&self, world: &World) -> Pose {
        world.bodies().pose(self.links[0])
    }

    fn base(&self) -> ObjectId {
        self.links[0]
    }

    fn objects(&self) -> Vec<ObjectId> {
        self.links.clone()
    }

    fn hand_object(&self, hand: usize) -> Option<ObjectId> {
        R1::side(hand).ok().map(|s| self.gripper_object(s))
    }

    fn held(&self, hand: usize) -> Option<ObjectId> {
        let side = R1::side(hand).ok()?;
        self.grippers[side.index()].holding().map(|b| b.object)
    }

    fn grasp_attachment(&self, hand: usize) -> Option<AttachmentId> {
        let side = R1::side(hand).ok()?;
        self.grippers[side.index()].attachment()
    }

    fn grasp_rules(&self) -> &GraspRules {
        &self.rules
    }

    /// The head's stereo camera (`zed_link`), 20° down.
    fn camera_pose(&self, world: &World) -> Pose {
        self.base_pose(world) * head_camera(&self.motion.now.joints.torso)
    }

    /// The chassis lidar. Its scan is not published: one horizontal fan of 360 beams all round,
    /// 0.05–25 m (what a planar chassis lidar of its kind gives).
    fn lidar(&self, world: &World) -> LidarMount {
        LidarMount {
            pose: self.base_pose(world) * Pose::from_translation(LIDAR_OFFSET),
            scan: Scan::Fan {
                beams: 360,
                fov: std::f32::consts::TAU,
            },
            min_range: 0.05,
            max_range: 25.0,
        }
    }

    fn arm(&self, hand: usize) -> Option<Arc<dyn Arm>> {
        let side = R1::side(hand).ok()?;
        let arm = R1Arm::new(side, self.links.clone(), self.motion.now.joints);
        Some(Arc::new(arm))
    }

    fn teleport(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError> {
        if !pose_ok(&pose) {
            return Err(MagicError::BadPose);
        }
        let before = self.grippers.each_ref().map(|g| g.palm_pose(world));
        self.motion.place::<R1>(world, &self.links, upright(pose))?;
        for (gripper, before) in self.grippers.iter().zip(before) {
            gripper.carry_held(world, before)?;
        }
        self.press(world);
        Ok(())
    }

    fn grasp_now(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        let (gripper, cx) = self.gripper(hand)?;
        gripper.grasp_now(world, cx, object)
    }

    fn grasp_touching(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        let (gripper, cx) = self.gripper(hand)?;
        gripper.grasp_touching(world, cx, object)
    }

    /// Its arms are kinematic and never left behind: nothing to do.
    fn reset_hand(&mut self, _world: &mut World, hand: usize) -> Result<(), MagicError> {
        R1::side(hand).map(|_| ())
    }

    fn release_now(&mut self, world: &mut World, hand: usize) -> Option<ObjectId> {
        let (gripper, cx) = self.gripper(hand).ok()?;
        gripper.release(world, cx)
    }
}

impl StepHooks for R1 {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        if substep == 0 {
            self.begin_step(world);
        }
        self.motion.move_links::<R1>(world, &self.links, substep);
    }

    fn after_step(&mut self, world: &mut World) {
        for gripper in &mut self.grippers {
            let cx = GraspContext {
                spec: &GRIPPER,
                rules: &self.rules,
                own: &self.links,
            };
            gripper.after_step(world, cx);
        }
        if self.motion.moves() {
            self.press(world);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_drives_sideways_and_moves_its_joints_toward_their_positions() {
        let mut world = World::default();
        let mut r1 = R1::add(&mut world, Pose::IDENTITY).unwrap();
        let mut values = *r1.still().values();
        values[1] = 1.0;
        values[R1Action::LEFT_ARM.start + 3] = -1.0;
        // The elbow at most 8.4 rad/s: 1 rad in four steps.
        for _ in 0..4 {
            r1.step(&mut world, &values).unwrap();
        }
        let base = r1.base_pose(&world).translation;
        assert!((base.y - 4.0 * 0.75 / 30.0).abs() < 1e-4, "{base:?}");
        assert!(base.x.abs() < 1e-5, "{base:?}");
        assert!((r1.joints().arms[0][3] + 1.0).abs() < 1e-6);
        let proprioception = {
            let mut out = Vec::new();
            r1.proprioception_into(&world, &mut out);
            out
        };
        assert_eq!(proprioception.len(), r1.proprioception_dim());
        // Still afterwards: nothing moves.
        let before = r1.joints();
        r1.step(&mut world, r1.still().values()).unwrap();
        assert_eq!(r1.joints(), before);
        assert!((r1.base_pose(&world).translation - base).length() < 1e-6);
    }
}
