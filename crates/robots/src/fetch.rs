//! Fetch: adding it to a world, stepping it, and reading it.

use crate::action::{ActionError, ActionSpace};
use crate::arm::Arm;
use crate::embodiment::{
    BaseDrive, BaseMove, Embodiment, EmbodimentSpec, HandMotion, LidarMount, Scan,
};
use crate::fetch_action::{FetchAction, FetchCommand, MAX_ANGULAR_SPEED, MAX_LINEAR_SPEED};
use crate::fetch_arm::FetchArm;
use crate::fetch_body::{
    FETCH_LINKS, FINGER_LINKS, FINGER_OPEN, FetchJoint, FetchJoints, FetchLink, GRIPPER_CENTRE,
    LASER_OFFSET, WHEEL_RADIUS, WHEEL_SEPARATION, blocking_parts, link_centre, link_mass,
    link_spec, pad_face,
};
use crate::fetch_proprioception::FetchProprioception;
use crate::grasp::GraspRules;
use crate::gripper::{GraspContext, GripperSpec, ParallelGripper};
use crate::ik::{IkError, IkSolver};
use crate::kinematic_links::{LinkModel, LinkMotion, Posture, Twist, add_links};
use crate::magic::MagicError;
use crate::proprioception::LocalPose;
use crate::robot::{RobotError, RobotKind, pose_ok};
use behavior_core::wrap_angle;
use behavior_sim::{
    AttachmentId, BodyRef, JointState, ObjectId, Primitive, STEP_SECONDS, StepHooks, World,
    WorldError,
};
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI};
use std::sync::{Arc, LazyLock};

/// How fast the torso and arm joints close on the IK solution, 1/s (iGibson's `kv`): each
/// moves at `ARM_GAIN · (q_ik − q)`, within its maximum velocity. A full Δ of 5 cm per step so
/// moves the end effector at about 0.1 m/s, as the original's.
const ARM_GAIN: f32 = 2.0;
/// The end effector's targets are kept within this distance of `WORKSPACE_CENTRE` (x, y in
/// the base frame), m (iGibson's radius limit).
const WORKSPACE_RADIUS: f32 = 0.5;
/// The centre of the end effector's workspace disk, base frame (x, y), m.
const WORKSPACE_CENTRE: [f32; 2] = [0.25, 0.0];
/// The end effector's targets are kept between these heights above the base's origin, m.
const WORKSPACE_HEIGHT: [f32; 2] = [0.2, 1.5];
/// Finger drive: at most the URDF's 60 N, stiff enough to close on a 0.2 kg apple at full
/// force within 3 cm of travel, damped near critically for the finger's 0.08 kg.
const FINGER_STIFFNESS: f32 = 2000.0;
const FINGER_DAMPING: f32 = 25.0;

/// Fetch's parallel gripper (its URDF's fingers, `fetch_body.rs`), made once: the step reads it.
pub(crate) static GRIPPER: LazyLock<GripperSpec> = LazyLock::new(gripper_spec);

fn gripper_spec() -> GripperSpec {
    let finger = FetchJoint::RightFinger.info();
    GripperSpec {
        fingers: FINGER_LINKS,
        open: FINGER_OPEN,
        max_velocity: finger.max_velocity,
        stiffness: FINGER_STIFFNESS,
        damping: FINGER_DAMPING,
        effort: finger.max_effort,
        centre: GRIPPER_CENTRE,
        pads: FINGER_LINKS.map(pad_face),
    }
}

/// The world objects Fetch is made of: one kinematic body per link ([`FetchLink`]); the
/// gripper's object carries the two fingers as dynamic links (0 right, 1 left).
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq, Eq)]
pub struct FetchParts {
    /// In [`FetchLink::ALL`] order.
    pub links: [ObjectId; FETCH_LINKS],
}

impl FetchParts {
    /// A link's object.
    pub fn link(&self, link: FetchLink) -> ObjectId {
        self.links[link as usize]
    }

    /// The base's object.
    pub fn base(&self) -> ObjectId {
        self.link(FetchLink::Base)
    }

    /// The gripper's object (its frame is the end effector's).
    pub fn gripper(&self) -> ObjectId {
        self.link(FetchLink::Gripper)
    }

    /// Every object, base first.
    pub fn all(&self) -> [ObjectId; FETCH_LINKS] {
        self.links
    }

    /// The bodies that touch what the gripper takes: its palm and its two fingers.
    pub fn gripper_bodies(&self) -> [BodyRef; 3] {
        let gripper = self.gripper();
        crate::gripper::bodies(gripper, &GRIPPER)
    }
}

/// The Fetch mobile manipulator (iGibson 2.0's `FetchGripper`, iGibson 2.0.3's
/// `robots/fetch_gripper_robot.py`): a differential-drive base, a torso lift, a pan/tilt head with
/// the camera, a 7-joint arm and a parallel gripper, driven by an 11-d [`FetchAction`] whose
/// end-effector part goes through inverse kinematics ([`IkSolver`]), holding things by assisted
/// grasping ([`GraspRules`]).
///
/// **Body model.** Every link is a kinematic body, moved each substep to where the joint
/// positions put it (forward kinematics from the URDF's joint table, `fetch_body.rs`):
/// - The base drives as a unicycle at the commanded (v, ω), within the wheels' 17.4 rad/s, and
///   stays upright on the floor. The original's base rolls on simulated wheels; ours goes
///   exactly where it is told (it drives 1 m when told to), costs the solver nothing, and
///   sleeps when still.
/// - The torso, head and arm joints move toward their targets at the URDF's maximum velocities:
///   the head at the commanded rates, the torso and arm toward the IK solution at
///   `ARM_GAIN`` · (q_ik − q)`, as the original's velocity controller.
/// - No part is ever sent into a fixed body (walls, furniture, the floor): a step whose base
///   motion or joint motion would make a part newly overlap one is refused — first the base's
///   motion, then the arm's, then both (see `motion.rs`). Movable things are pushed, with
///   unbounded force (the original's arm pushes with its joints' efforts).
/// - The fingers are dynamic links of the gripper on prismatic joints, position-driven at most
///   with the URDF's 60 N, so they close on what they meet and yield, and a body they both
///   touch can be grasped ([`Fetch::holding`]).
///
/// The links are velocity-driven kinematic bodies, moved as `kinematic_links.rs` moves them
/// (it says why not position-driven).
///
/// Measured (`benches/step.rs`, release, a table with 20 objects, 10 × 1/300 s): 1.7 µs per
/// step standing still, ≈ 0.12 ms driving, ≈ 0.2 ms under random actions — a simulated 9-link
/// arm costs 0.65–3 ms driving (`docs/design.md` §4).
///
/// **State.** As the BehaviorRobot's: what it was told lives here, the rest in the world;
/// clone it with [`World::snapshot`] and the pair continues bit-identically. Step the world with
/// the robot ([`World::step_with`]); an action acts for one step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub struct Fetch {
    parts: FetchParts,
    /// Where the links are and how they move in the step begun last.
    motion: LinkMotion<FetchJoints>,
    /// The wheels' angles and rates (right, left).
    wheels: [f32; 2],
    wheel_rates: [f32; 2],
    /// The parallel gripper: its command, what it holds, what it let go.
    gripper: ParallelGripper,
    pending: FetchCommand,
    /// Why the last end-effector command could not be followed exactly.
    ik_error: Option<IkError>,
    ik: IkSolver,
    rules: GraspRules,
}

impl Fetch {
    /// Adds Fetch with its base's origin at `pose` — a point on the floor's top, between the
    /// wheels; only the rotation's yaw counts (the base stays upright) — in iGibson's BEHAVIOR
    /// start pose (torso 0.385 m, head tilted 0.45 rad down, arm `diagonal30`, gripper open),
    /// with the original's grasp rules.
    pub fn add(world: &mut World, pose: Pose) -> Result<Fetch, RobotError> {
        Fetch::add_with(world, pose, GraspRules::default())
    }

    /// [`Fetch::add`] with other grasp rules.
    pub fn add_with(world: &mut World, pose: Pose, rules: GraspRules) -> Result<Fetch, RobotError> {
        if !pose_ok(&pose) {
            return Err(RobotError::BadPose);
        }
        let (yaw, _, _) = pose.rotation.normalize().to_euler(EulerRot::ZYX);
        let base = Pose::from_parts(pose.translation, Rotation::from_rotation_z(yaw));
        let posture = Posture {
            base,
            joints: FetchJoints::default(),
        };
        let parts = add_parts(world, &posture)?;
        let gripper = ParallelGripper::open_on(world, parts.gripper(), &GRIPPER)?;
        let fetch = Fetch {
            parts,
            motion: LinkMotion::at(posture),
            wheels: [0.0; 2],
            wheel_rates: [0.0; 2],
            gripper,
            pending: FetchCommand::default(),
            ik_error: None,
            ik: IkSolver::default(),
            rules,
        };
        fetch.gripper.press(world, &GRIPPER);
        Ok(fetch)
    }

    /// The action for the next step (replacing one set before): a [`FetchAction`] through
    /// the end-effector controller or a [`crate::FetchJointAction`] joint by joint.
    pub fn set_action(&mut self, action: impl Into<FetchCommand>) {
        self.pending = action.into();
    }

    /// Checks `values` as a [`FetchAction`] and, if it is one, takes a step of the world with it.
    /// A bad action is an error and leaves the world and the robot untouched.
    pub fn step(&mut self, world: &mut World, values: &[f32]) -> Result<(), ActionError> {
        self.set_action(FetchAction::new(values)?);
        world.step_with(self);
        Ok(())
    }

    /// The world objects it is made of.
    pub fn parts(&self) -> FetchParts {
        self.parts
    }

    /// The grasp rules in force.
    pub fn rules(&self) -> &GraspRules {
        &self.rules
    }

    /// The IK solver the end-effector controller uses.
    pub fn ik(&self) -> &IkSolver {
        &self.ik
    }

    /// Why the last end-effector command could not be followed exactly (an unreachable
    /// target: the arm then heads for the closest pose found), or `None`.
    pub fn ik_error(&self) -> Option<&IkError> {
        self.ik_error.as_ref()
    }

    /// The base's pose in the world: its origin on the floor between the wheels, x forward.
    pub fn base_pose(&self, world: &World) -> Pose {
        world.bodies().pose(self.parts.base())
    }

    /// The torso, head and arm positions (where the step begun last ends).
    pub fn joints(&self) -> FetchJoints {
        self.motion.now.joints
    }

    /// The end effector's pose in the world (`gripper_link`: x out of the gripper, the fingers
    /// along ±y).
    pub fn eef_pose(&self, world: &World) -> Pose {
        world.bodies().pose(self.parts.gripper())
    }

    /// The head camera's pose in the world: it looks along its +x, with no roll.
    pub fn camera_pose(&self, world: &World) -> Pose {
        self.base_pose(world) * self.motion.now.joints.camera()
    }

    /// The finger positions (right, left), m: 0 closed, 0.05 open.
    pub fn fingers(&self, world: &World) -> [f32; 2] {
        self.gripper.fingers(world, &GRIPPER)
    }

    /// The body the gripper holds.
    pub fn holding(&self) -> Option<BodyRef> {
        self.gripper.holding()
    }

    /// The robot's proprioception now.
    pub fn proprioception(&self, world: &World) -> FetchProprioception {
        let eef = self.motion.now.joints.eef();
        let rate = |a: f32, b: f32| (b - a) / STEP_SECONDS;
        let (from, now) = (self.motion.from.joints, self.motion.now.joints);
        let efforts = self.static_efforts(world);
        let joints = FetchJoint::ALL.map(|j| match j {
            FetchJoint::RightWheel | FetchJoint::LeftWheel => JointState {
                position: self.wheels[j.index()],
                velocity: self.wheel_rates[j.index()],
                effort: 0.0,
            },
            FetchJoint::RightFinger | FetchJoint::LeftFinger => {
                let link = j.index() - FetchJoint::RightFinger.index();
                let state = world.joints().state(self.parts.gripper(), link);
                state.unwrap_or(JointState {
                    position: 0.0,
                    velocity: 0.0,
                    effort: 0.0,
                })
            }
            _ => {
                let (a, b) = (from.get(j).unwrap_or(0.0), now.get(j).unwrap_or(0.0));
                JointState {
                    position: b,
                    velocity: rate(a, b),
                    effort: load_index(j).map_or(0.0, |k| efforts[k]),
                }
            }
        });
        FetchProprioception {
            eef: LocalPose::of(eef),
            grasping: self.gripper.holding().is_some(),
            joints,
        }
    }
}

/// Where a joint's static load is in `Fetch::static_efforts`: the torso first, then the arm.
fn load_index(joint: FetchJoint) -> Option<usize> {
    if joint == FetchJoint::TorsoLift {
        return Some(0);
    }
    FetchJoint::ARM
        .iter()
        .position(|&a| a == joint)
        .map(|k| k + 1)
}

/// Adds every link at its place, in the robot's collision group.
fn add_parts(world: &mut World, posture: &Posture<FetchJoints>) -> Result<FetchParts, WorldError> {
    let poses = posture.joints.link_poses();
    let specs = (FetchLink::ALL.into_iter().enumerate())
        .map(|(k, link)| link_spec(link, posture.base * poses[k]));
    let links = add_links(world, specs)?;
    let mut parts = [ObjectId(0); FETCH_LINKS];
    parts.copy_from_slice(&links);
    Ok(FetchParts { links: parts })
}

/// The wheel rates (right, left) for (v, ω), each within its maximum, and the (v, ω) they give.
fn wheel_limited((v, w): (f32, f32)) -> ([f32; 2], (f32, f32)) {
    let max = FetchJoint::RightWheel.info().max_velocity;
    let half = 0.5 * WHEEL_SEPARATION;
    let right = ((v + w * half) / WHEEL_RADIUS).clamp(-max, max);
    let left = ((v - w * half) / WHEEL_RADIUS).clamp(-max, max);
    let v = 0.5 * WHEEL_RADIUS * (right + left);
    let w = WHEEL_RADIUS * (right - left) / WHEEL_SEPARATION;
    ([right, left], (v, w))
}

/// A base-frame end-effector position kept in the workspace (iGibson's clips).
/// The head's and arm's positions after one step of `command` from `now`: the head at its
/// commanded rates; the torso and arm at theirs ([`FetchCommand::Joints`]), or toward the IK
/// solution for the end-effector target (or the closest found, with why it is not exact),
/// each within its maximum velocity and its limits.
pub(crate) fn step_joints(
    ik: &IkSolver,
    now: &FetchJoints,
    command: &FetchCommand,
) -> (FetchJoints, Option<IkError>) {
    let mut joints = *now;
    let [pan, tilt] = command.head();
    joints.head = [
        joints.head[0] + pan * STEP_SECONDS,
        joints.head[1] + tilt * STEP_SECONDS,
    ];
    let action = match command {
        FetchCommand::EndEffector(action) => action,
        FetchCommand::Joints(action) => {
            let rates = action.rates();
            joints.torso += rates[0] * STEP_SECONDS;
            for (q, rate) in joints.arm.iter_mut().zip(&rates[1..]) {
                *q += rate * STEP_SECONDS;
            }
            return (joints.clamped(), None);
        }
    };
    let mut error = None;
    if action.moves_eef() {
        let eef = now.eef();
        let (dp, dr) = action.eef();
        let target = Pose::from_parts(
            in_workspace(eef.translation + dp),
            (dr * eef.rotation).normalize(),
        );
        let goal = match ik.solve(now, &target) {
            Ok(q) => q,
            Err(e) => {
                let closest = match &e {
                    IkError::Unreachable { closest, .. } => *closest,
                    IkError::NotFinite => *now,
                };
                error = Some(e);
                closest
            }
        };
        joints.torso = approach(
            joints.torso,
            goal.torso,
            FetchJoint::TorsoLift.info().max_velocity,
        );
        for (k, joint) in FetchJoint::ARM.iter().enumerate() {
            joints.arm[k] = approach(joints.arm[k], goal.arm[k], joint.info().max_velocity);
        }
    }
    (joints.clamped(), error)
}

fn in_workspace(p: Vector) -> Vector {
    let centre = Vector::new(WORKSPACE_CENTRE[0], WORKSPACE_CENTRE[1], 0.0);
    let mut flat = Vector::new(p.x, p.y, 0.0) - centre;
    if flat.length() > WORKSPACE_RADIUS {
        flat *= WORKSPACE_RADIUS / flat.length();
    }
    let z = p.z.clamp(WORKSPACE_HEIGHT[0], WORKSPACE_HEIGHT[1]);
    centre + flat + Vector::new(0.0, 0.0, z)
}

/// `q` moved toward `goal` for one step at `ARM_GAIN · (goal − q)`, within `max_velocity`.
fn approach(q: f32, goal: f32, max_velocity: f32) -> f32 {
    let rate = (ARM_GAIN * (goal - q)).clamp(-max_velocity, max_velocity);
    q + rate * STEP_SECONDS
}

impl Fetch {
    /// What Fetch is, for planners and episodes.
    pub const SPEC: EmbodimentSpec = EmbodimentSpec {
        kind: RobotKind::Fetch,
        hand_names: &["gripper"],
        origin_height: 0.0,
        drive: BaseDrive::Differential,
        hand_motion: HandMotion::Jointed,
        spaces: &ActionSpace::ALL,
        primitive_space: ActionSpace::Joints,
        // Within it the arm reaches both over a counter and down to the floor (the end-effector
        // controller's workspace, which physical primitives do not go through, ends 0.75 m in
        // front of the base).
        arm_reach: 0.7,
        // Its arm is moved joint by joint exactly and holds still while the base drives, so what
        // it holds lags only by the grasp's give. With 3 cm, the base and a sheet of plywood
        // carried upright beside it, about 0.65 m wide, found no way through a doorway 0.75 m
        // wide on the 0.1 m lattice; 1 cm less on each side, it found one.
        carry_sway: 0.01,
    };

    /// Turning within which a differential base drives while it turns, rad: farther off its
    /// heading it only turns toward the point first.
    const DRIVE_ALIGNED: f32 = 0.05;
}

/// Fetch's one hand, its gripper, is hand 0: any other number is no hand.
fn gripper(hand: usize) -> Result<(), MagicError> {
    if hand == 0 {
        Ok(())
    } else {
        Err(MagicError::NoHand(hand))
    }
}

impl Embodiment for Fetch {
    fn spec(&self) -> &'static EmbodimentSpec {
        &Fetch::SPEC
    }

    fn action_dim(&self, space: ActionSpace) -> usize {
        space.fetch_dim()
    }

    fn set_action(&mut self, space: ActionSpace, values: &[f32]) -> Result<(), ActionError> {
        self.pending = space.fetch_action(values)?;
        Ok(())
    }

    /// A unicycle: it turns toward the point first, drives when facing it (a point behind is
    /// backed onto), and turns to the final heading once there (within `step.within`).
    fn base_action(&self, space: ActionSpace, step: BaseMove) -> Option<Vec<f32>> {
        if space == ActionSpace::TabletopManipulation {
            return None;
        }
        let distance = step.forward.hypot(step.left);
        let turn = if distance > step.within {
            let toward = wrap_angle(step.left.atan2(step.forward));
            if toward.abs() > FRAC_PI_2 {
                wrap_angle(toward + PI)
            } else {
                toward
            }
        } else {
            step.turn
        };
        let drive = if distance > step.within && turn.abs() < Fetch::DRIVE_ALIGNED {
            step.forward
        } else {
            0.0
        };
        // The base's two values lead every space that has them.
        let mut action = vec![0.0; space.fetch_dim()];
        action[FetchAction::LINEAR] = (drive / (MAX_LINEAR_SPEED * STEP_SECONDS)).clamp(-1.0, 1.0);
        action[FetchAction::ANGULAR] = (turn / (MAX_ANGULAR_SPEED * STEP_SECONDS)).clamp(-1.0, 1.0);
        Some(action)
    }

    fn proprioception_dim(&self) -> usize {
        FetchProprioception::DIM
    }

    fn proprioception_into(&self, world: &World, out: &mut Vec<f32>) {
        out.extend(self.proprioception(world).to_array());
    }

    fn base_pose(&self, world: &World) -> Pose {
        Fetch::base_pose(self, world)
    }

    fn base(&self) -> ObjectId {
        self.parts.base()
    }

    fn objects(&self) -> Vec<ObjectId> {
        self.parts.all().to_vec()
    }

    fn hand_object(&self, hand: usize) -> Option<ObjectId> {
        (hand == 0).then(|| self.parts.gripper())
    }

    fn held(&self, hand: usize) -> Option<ObjectId> {
        self.holding().filter(|_| hand == 0).map(|b| b.object)
    }

    fn grasp_attachment(&self, hand: usize) -> Option<AttachmentId> {
        self.gripper.attachment().filter(|_| hand == 0)
    }

    fn grasp_rules(&self) -> &GraspRules {
        &self.rules
    }

    fn camera_pose(&self, world: &World) -> Pose {
        Fetch::camera_pose(self, world)
    }

    /// The base laser (SICK TIM571 on the real robot): 220 beams over 220°, 0.05–25 m, iGibson's.
    fn lidar(&self, world: &World) -> LidarMount {
        LidarMount {
            pose: self.base_pose(world) * Pose::from_translation(LASER_OFFSET),
            scan: Scan::Fan {
                beams: 220,
                fov: 220f32.to_radians(),
            },
            min_range: 0.05,
            max_range: 25.0,
        }
    }

    fn arm(&self, hand: usize) -> Option<Arc<dyn Arm>> {
        gripper(hand).ok()?;
        let arm = FetchArm::new(self.parts, self.motion.now.joints, self.ik);
        Some(Arc::new(arm))
    }

    fn teleport(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError> {
        self.place_at(world, pose)
    }

    fn grasp_now(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        gripper(hand)?;
        self.grasp_now_in(world, object)
    }

    fn grasp_touching(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        gripper(hand)?;
        self.grasp_touching_in(world, object)
    }

    /// Its arm is kinematic and never left behind: nothing to do.
    fn reset_hand(&mut self, _world: &mut World, hand: usize) -> Result<(), MagicError> {
        gripper(hand)
    }

    fn release_now(&mut self, world: &mut World, hand: usize) -> Option<ObjectId> {
        gripper(hand).ok().and_then(|()| self.release_from(world))
    }
}

impl StepHooks for Fetch {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        if substep == 0 {
            self.begin_step(world);
        }
        let links = self.parts.all();
        self.motion.move_links::<Fetch>(world, &links, substep);
    }

    fn after_step(&mut self, world: &mut World) {
        let own = self.parts.all();
        let cx = GraspContext {
            spec: &GRIPPER,
            rules: &self.rules,
            own: &own,
        };
        self.gripper.after_step(world, cx);
        if self.motion.moves() {
            self.gripper.press(world, &GRIPPER);
        }
    }
}

impl Fetch {
    /// Takes the pending action: the step's base motion and joint targets, checked against
    /// fixed bodies, and the fingers' drive.
    fn begin_step(&mut self, world: &mut World) {
        let action = std::mem::take(&mut self.pending);
        let (rates, (v, w)) = wheel_limited(action.base());
        let twist = Twist {
            forward: v,
            left: 0.0,
            turn: w,
        };
        let joints = self.joint_targets(&action);
        let links = self.parts.all();
        let base_moves = self.motion.begin::<Fetch>(world, &links, twist, joints);
        self.wheel_rates = if base_moves { rates } else { [0.0; 2] };
        for k in 0..2 {
            self.wheels[k] += self.wheel_rates[k] * STEP_SECONDS;
        }
        self.gripper.command(world, &GRIPPER, action.gripper());
    }

    /// The head's and arm's positions at the end of the step the command asks for.
    fn joint_targets(&mut self, command: &FetchCommand) -> FetchJoints {
        let (joints, error) = step_joints(&self.ik, &self.motion.now.joints, command);
        match command {
            FetchCommand::EndEffector(action) if !action.moves_eef() => {}
            _ => self.ik_error = error,
        }
        joints
    }

    /// Where one step of `action` takes the torso, head and arm from `joints` if nothing fixed
    /// is in their way: what the controller does, without a world, for planners that predict
    /// an executed path.
    pub fn joints_after(&self, joints: &FetchJoints, command: &FetchCommand) -> FetchJoints {
        step_joints(&self.ik, joints, command).0
    }

    /// The static loads of the torso and the arm joints (torso first): what holds the links
    /// beyond each, and what the gripper holds, against gravity (see `fetch_proprioception.rs`).
    fn static_efforts(&self, world: &World) -> [f32; 8] {
        let gravity = self.motion.now.base.rotation.inverse() * world.bodies().gravity();
        let poses = self.motion.now.joints.link_poses();
        let held = self
            .gripper
            .holding()
            .map_or(0.0, |b| world.bodies().total_mass(b.object));
        // (mass, centre in the base frame) of each link the arm carries, gripper last.
        let mut loads: Vec<(f32, Vector)> = (4..FETCH_LINKS)
            .map(|k| {
                let link = FetchLink::ALL[k];
                (link_mass(link), poses[k].transform_point(link_centre(link)))
            })
            .collect();
        let gripper = poses[FetchLink::Gripper as usize];
        loads.push((
            held + 2.0 * crate::fetch_body::FETCH_FINGER_MASS,
            gripper.transform_point(GRIPPER_CENTRE * 0.5),
        ));
        let mut out = [0.0; 8];
        let carried: f32 = (1..4).map(|k| link_mass(FetchLink::ALL[k])).sum::<f32>()
            + loads.iter().map(|l| l.0).sum::<f32>();
        out[0] = -carried * gravity.z;
        let mut frame = poses[FetchLink::Torso as usize];
        for (k, joint) in FetchJoint::ARM.iter().enumerate() {
            let at = frame * Pose::from_translation(joint.info().origin);
            let axis = at.rotation * joint.info().axis;
            // The links from this joint's own onward: link 4 + k is the shoulder pan for k 0.
            let moment: Vector = loads[k..]
                .iter()
                .map(|&(m, c)| (c - at.translation).cross(gravity * m))
                .sum();
            out[k + 1] = -axis.dot(moment);
            frame *= joint.transform(self.motion.now.joints.arm[k]);
        }
        out
    }
}

/// Fetch's links for their motion: [`FetchLink::ALL`] placed by [`FetchJoints::link_poses`].
impl LinkModel for Fetch {
    type Joints = FetchJoints;

    fn link_poses(joints: &FetchJoints) -> Vec<Pose> {
        joints.link_poses().to_vec()
    }

    fn between(a: &FetchJoints, b: &FetchJoints, t: f32) -> FetchJoints {
        let lerp = |a: f32, b: f32| a + (b - a) * t;
        FetchJoints {
            torso: lerp(a.torso, b.torso),
            head: std::array::from_fn(|k| lerp(a.head[k], b.head[k])),
            arm: std::array::from_fn(|k| lerp(a.arm[k], b.arm[k])),
        }
    }

    fn centre(link: usize) -> Vector {
        link_centre(FetchLink::ALL[link])
    }

    fn blocking(link: usize) -> Vec<(Primitive, Pose)> {
        let parts = blocking_parts(FetchLink::ALL[link]);
        parts.into_iter().map(|p| (p.primitive, p.offset)).collect()
    }
}

/// Symbolic moves (see `magic.rs`).
impl Fetch {
    /// Puts the base at `pose` (only its yaw counts), every link where the joints put it and
    /// what the gripper holds with it, all at rest.
    fn place_at(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError> {
        if !pose_ok(&pose) {
            return Err(MagicError::BadPose);
        }
        let (yaw, _, _) = pose.rotation.normalize().to_euler(EulerRot::ZYX);
        let base = Pose::from_parts(pose.translation, Rotation::from_rotation_z(yaw));
        let before = self.gripper.palm_pose(world);
        let links = self.parts.all();
        self.motion.place::<Fetch>(world, &links, base)?;
        self.gripper.carry_held(world, before)?;
        self.wheel_rates = [0.0; 2];
        self.gripper.press(world, &GRIPPER);
        Ok(())
    }

    /// Puts `object` between the fingers, attaches it as the assisted grasp does and closes.
    fn grasp_now_in(&mut self, world: &mut World, object: ObjectId) -> Result<(), MagicError> {
        let own = self.parts.all();
        let cx = GraspContext {
            spec: &GRIPPER,
            rules: &self.rules,
            own: &own,
        };
        self.gripper.grasp_now(world, cx, object)
    }

    /// Holds `object` where it is, if the palm or a finger touches it: the forced assisted
    /// grasp after a physical GRASP closed the gripper (the BehaviorRobot's, which asks for
    /// contact too), attached at the middle of those contacts.
    fn grasp_touching_in(&mut self, world: &mut World, object: ObjectId) -> Result<(), MagicError> {
        let own = self.parts.all();
        let cx = GraspContext {
            spec: &GRIPPER,
            rules: &self.rules,
            own: &own,
        };
        self.gripper.grasp_touching(world, cx, object)
    }

    /// Detaches what the gripper holds and opens it.
    fn release_from(&mut self, world: &mut World) -> Option<ObjectId> {
        let own = self.parts.all();
        let cx = GraspContext {
            spec: &GRIPPER,
            rules: &self.rules,
            own: &own,
        };
        self.gripper.release(world, cx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_base_drives_within_its_wheels() {
        // Full speed ahead and full turn at once is more than the wheels give.
        let (rates, (v, w)) = wheel_limited((1.0, std::f32::consts::PI));
        assert_eq!(rates[0], 17.4);
        assert!(v < 1.0 && w > 0.0);
        let (_, straight) = wheel_limited((1.0, 0.0));
        assert!((straight.0 - 1.0).abs() < 1e-6);
    }

    #[test]
    fn joints_after_predicts_what_a_step_does_to_the_arm() {
        let mut world = World::default();
        let mut fetch = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        let mut values = [0.0; crate::FETCH_ACTION_DIM];
        values[FetchAction::EEF_POSITION.start] = 1.0;
        values[FetchAction::EEF_ROTATION.start + 2] = -0.5;
        values[FetchAction::HEAD.start] = 0.3;
        values[FetchAction::GRIPPER] = 1.0;
        let action = FetchAction::new(&values).unwrap();
        for _ in 0..5 {
            let predicted = fetch.joints_after(&fetch.joints(), &action.into());
            fetch.step(&mut world, &values).unwrap();
            assert_eq!(fetch.joints(), predicted);
        }
        assert_ne!(fetch.joints(), FetchJoints::default(), "the arm moved");
    }

    #[test]
    fn targets_are_kept_in_the_workspace() {
        let p = in_workspace(Vector::new(2.0, 0.0, 3.0));
        assert!((p - Vector::new(0.75, 0.0, 1.5)).length() < 1e-6);
        let inside = Vector::new(0.5, -0.1, 0.9);
        assert_eq!(in_workspace(inside), inside);
    }
}
