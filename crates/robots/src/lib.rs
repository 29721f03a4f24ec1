//! Embodiments for the BEHAVIOR world: robots made of world objects, moved by actions inside the
//! world's step ([`behavior_sim::StepHooks`]).
//!
//! It owns the robots' bodies (built from our own simple shapes, with the original robots' real
//! dimensions and masses), their action spaces, how an action becomes motion, assisted grasping,
//! proprioception and the robot-relative predicates (in hand, in reach, in the same room, in the
//! field of view). The two embodiments of BEHAVIOR, and the BEHAVIOR Challenge's:
//! - the [`BehaviorRobot`], the bimanual humanoid of the VR demonstrations (26-d [`Action`],
//!   22-d [`Proprioception`]);
//! - [`Fetch`], the mobile manipulator (11-d [`FetchAction`] with an end-effector controller
//!   through inverse kinematics, [`IkSolver`], or 13-d [`FetchJointAction`] driving the arm
//!   joint by joint; 49-d [`FetchProprioception`]);
//! - the [`R1`], the Galaxea R1 Pro of the BEHAVIOR Challenge 2025 (23-d [`R1Action`]: a
//!   holonomic base's velocity and the torso's and both arms' joint positions; 57-d
//!   proprioception), built only through the interfaces below.
//!
//! Each implements [`Embodiment`], the one interface an environment, its sensors and metrics,
//! recordings and planners use (action space, the step, grasping, proprioception, camera and
//! lidar, the moves outside physics), with its facts in an [`EmbodimentSpec`]. Its hands are read
//! by planners through one of two more: an [`Arm`] for a hand at the end of a jointed arm
//! (joints, limits, forward and inverse kinematics, the joint action and what it does: Fetch's
//! and the R1's) or a [`PosedHand`] for a hand the actions pose directly (the BehaviorRobot's). [`Robot`] holds
//! one of them, chosen by [`RobotKind`], and derefs to its [`Embodiment`]: only `robot.rs` names
//! every kind. [`ActionSpace`] names the original's reduced action spaces, which each kind reads
//! its own way (see `fetch_action.rs` for Fetch's).
//!
//! **Body models, chosen for cost.** Every robot moves its body kinematically (exactly where
//! it is told, refusing moves into fixed bodies) and keeps dynamic bodies only where contact
//! forces matter: the BehaviorRobot's hands (each one body, its fingers shapes turned with the
//! trigger rather than jointed links: see `hand.rs`), Fetch's and the R1's fingers (one shared
//! parallel gripper, `gripper.rs`). Fetch's and the R1's links are kinematic bodies placed by
//! forward kinematics each substep (`kinematic_links.rs`, shared), not a simulated chain:
//! measured in `benches/step.rs` (release, a table with 20 objects, 10 × 1/300 s), a Fetch step
//! costs 1.7 µs standing still, ≈ 0.12 ms driving and ≈ 0.2 ms under random actions
//! (IK, the fixed-body checks and the awake fingers) — where `docs/design.md` §4 measured
//! 0.65–3 ms for a simulated 9-link arm while driving.
//!
//! **Looks.** Fetch's links name model pieces whose real meshes ([`shared_models`]) come from
//! gymnasium-robotics' MuJoCo model, fetched from PyPI at first use (`fetch_model.rs`); the
//! BehaviorRobot's body is drawn as a trunk ([`behavior_sim::Form::Torso`]), the R1 as its own
//! boxes (no mesh of it is on PyPI). Collision is our own
//! primitives either way.
//!
//! It knows nothing of BDDL, activities, episodes, rewards, metrics or how anything is drawn (it
//! hands renderers the meshes): an environment builds on it, and reads the world through
//! [`behavior_sim`] as any other crate does.
//!
//! ```
//! use behavior_robots::{Action, BehaviorRobot, BODY_HEIGHT};
//! use behavior_sim::World;
//! use rapier3d::math::{Pose, Vector};
//!
//! let mut world = World::default();
//! let start = Pose::from_translation(Vector::new(0.0, 0.0, BODY_HEIGHT));
//! let mut robot = BehaviorRobot::add(&mut world, start).unwrap();
//! let mut forward = [0.0; 26];
//! forward[Action::BODY.start] = 1.0; // +x in the body frame, scaled to 0.05 m
//! forward[Action::RIGHT_TRIGGER] = 1.0; // the right hand starts to close
//! robot.set_action(Action::new(&forward).unwrap());
//! world.step_with(&mut robot);
//! assert!((robot.body_pose(&world).translation.x - 0.05).abs() < 1e-6);
//! assert_eq!(robot.proprioception(&world).to_array()[19], 0.05);
//! // Bad input is an error, and nothing moves.
//! assert!(robot.step(&mut world, &[f32::NAN; 26]).is_err());
//! ```
//!
//! Fetch, from the floor up (its base origin is on the floor; [`Robot::standing_pose`] gives
//! each kind's pose for a point on the floor):
//!
//! ```
//! use behavior_robots::{Fetch, FetchAction, FETCH_ACTION_DIM};
//! use behavior_sim::World;
//! use rapier3d::math::Pose;
//!
//! let mut world = World::default();
//! let mut fetch = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
//! let mut forward = [0.0; FETCH_ACTION_DIM];
//! forward[FetchAction::LINEAR] = 1.0; // 1 m/s
//! forward[FetchAction::GRIPPER] = 1.0; // keep the gripper open
//! for _ in 0..30 {
//!     fetch.step(&mut world, &forward).unwrap();
//! }
//! assert!((fetch.base_pose(&world).translation.x - 1.0).abs() < 1e-3);
//! assert_eq!(fetch.proprioception(&world).to_array().len(), 49);
//! assert!(fetch.step(&mut world, &[0.0; 26]).is_err());
//! ```
//!
//! Inside: `embodiment.rs` (the interface), `arm.rs` and `posed_hand.rs` (the hands' two
//! interfaces), `chain.rs` (a serial chain of URDF joints: forward and inverse kinematics for
//! any number of joints), `r1_kinematics.rs` (the Galaxea R1 Pro's torso and arms as chains, the
//! third robot's first part), `robot.rs` (any robot by kind), `magic.rs` (why a
//! move outside physics is refused), `relative.rs` (robot-relative predicates), `grasp.rs`
//! (assisted grasping, shared), `gripper.rs` (a parallel-jaw gripper and its assisted grasp,
//! for any robot that carries one: Fetch's); for the BehaviorRobot `action.rs` (the action and the reduced
//! spaces), `body.rs` and `hand.rs` (the parts and their constants), `motion.rs` (from an action
//! to the step's targets), `follow.rs` (how a palm follows its target), `proprioception.rs` and
//! `behavior_robot.rs` (the robot as a step hook); for Fetch, `fetch_body.rs` (joints, links,
//! forward kinematics), `fetch_arm.rs` (its arm as an [`Arm`]), `fetch_model.rs` (its real
//! meshes), `ik.rs`, `fetch_action.rs`,
//! `fetch_proprioception.rs` and `fetch.rs` (the robot as a step hook).

mod action;
mod arm;
mod behavior_robot;
mod body;
mod chain;
mod embodiment;
mod fetch;
mod fetch_action;
mod fetch_arm;
mod fetch_body;
mod fetch_model;
mod fetch_proprioception;
mod follow;
mod grasp;
mod gripper;
mod hand;
mod ik;
mod kinematic_links;
mod magic;
mod motion;
mod posed_hand;
mod proprioception;
mod r1;
mod r1_action;
mod r1_arm;
mod r1_body;
mod r1_kinematics;
mod relative;
mod robot;

/// The guide's chapter on robots (`docs/guide/09-robots.md`), whose Rust snippets are compiled
/// and run with this crate's doctests, so that the guide stays true.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/guide/09-robots.md")]
struct GuideChapter;

pub use action::{ACTION_DIM, ACTION_SCALE, Action, ActionError, ActionSpace};
pub use arm::{Arm, ArmConfig, MAX_ARM_JOINTS};
pub use behavior_robot::{BehaviorRobot, RobotParts};
pub use body::{BODY_HEIGHT, BODY_LENGTH, BODY_MASS, BODY_RADIUS, EYE_REACH, HAND_REACH};
pub use chain::{Chain, ChainIk, ChainJoint, urdf_origin};
pub use embodiment::{
    BaseDrive, BaseMove, Embodiment, EmbodimentSpec, HandMotion, LidarMount, Scan, TrackedPart,
};
pub use fetch::{Fetch, FetchParts};
pub use fetch_action::{
    EEF_STEP, EEF_TURN, FETCH_ACTION_DIM, FETCH_JOINT_ACTION_DIM, FetchAction, FetchCommand,
    FetchJointAction, HEAD_SPEED, MAX_ANGULAR_SPEED, MAX_LINEAR_SPEED,
};
pub use fetch_body::{
    BASE_RADIUS, CAMERA_OFFSET, DIAGONAL30, FETCH_FINGER_MASS, FETCH_JOINTS, FETCH_LINKS,
    FETCH_MASS, FINGER_OPEN, FetchJoint, FetchJoints, FetchLink, GRIPPER_CENTRE, GRIPPER_FRICTION,
    GRIPPER_OFFSET, JointInfo, START_TILT, START_TORSO, WHEEL_RADIUS, WHEEL_SEPARATION, link_mass,
};
pub use fetch_model::{ModelError, fetch_models, fetch_piece, shared_models};
pub use fetch_proprioception::FetchProprioception;
pub use grasp::GraspRules;
pub use hand::{
    FINGER_CLOSED, FINGER_SPEED, FINGERS, HAND_FRICTION, HAND_MASS, Side, THUMB_CLOSED, sweep_shape,
};
pub use ik::{IK_JOINTS, IkError, IkSolver};
pub use magic::MagicError;
pub use posed_hand::PosedHand;
pub use proprioception::{LocalPose, Proprioception};
pub use r1::R1;
pub use r1_action::{R1_ACTION_DIM, R1_BASE_SPEED, R1Action};
pub use r1_body::{R1_BASE_RADIUS, R1_LINKS, R1Joints, R1Link};
pub use r1_kinematics::{
    EEF_DEPTH, GRIPPER_MOUNT, R1_ARM_JOINTS, R1_FINGER_OPEN, R1_START_TORSO, R1_TORSO_JOINTS,
    arm_chain, arm_joints, arm_mount, eef_in_gripper, head_camera, torso_arm_chain, torso_chain,
    torso_joints,
};
pub use relative::{EYE_FOV, REACH_DISTANCE};
pub use robot::{Robot, RobotError, RobotKind};
