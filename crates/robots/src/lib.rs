//! Embodiments for the BEHAVIOR world: robots made of world objects, moved by actions inside the
//! world's step ([`behavior_sim::StepHooks`]).
//!
//! It owns the robots' bodies (built from our own simple shapes, with the original robots' real
//! dimensions and masses), their action spaces, how an action becomes motion, assisted grasping,
//! proprioception and the robot-relative predicates (in hand, in reach, in the same room, in the
//! field of view). Today that is the [`BehaviorRobot`], the bimanual humanoid of the VR
//! demonstrations; Fetch comes next, and a shared trait with it.
//!
//! It knows nothing of BDDL, activities, episodes, rewards, metrics or rendering: an environment
//! builds on it, and reads the world through [`behavior_sim`] as any other crate does.
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
//! Inside: `action.rs` (the action and the reduced spaces), `body.rs` and `hand.rs` (the parts
//! and their constants), `motion.rs` (from an action to the step's targets), `follow.rs` (how a
//! palm follows its target), `grasp.rs` (assisted grasping), `proprioception.rs`, `relative.rs`
//! (robot-relative predicates) and `robot.rs` (the robot as a step hook).

#![warn(missing_docs)]

mod action;
mod body;
mod embodiment;
mod fetch;
mod fetch_action;
mod fetch_body;
mod fetch_proprioception;
mod follow;
mod grasp;
mod hand;
mod ik;
mod motion;
mod proprioception;
mod relative;
mod robot;

pub use action::{ACTION_DIM, ACTION_SCALE, Action, ActionError, ActionSpace};
pub use body::{BODY_HEIGHT, BODY_LENGTH, BODY_MASS, BODY_RADIUS, EYE_REACH, HAND_REACH};
pub use embodiment::{Robot, RobotKind, TrackedPart};
pub use fetch::{
    ARM_GAIN, Fetch, FetchParts, WORKSPACE_CENTRE, WORKSPACE_HEIGHT, WORKSPACE_RADIUS,
};
pub use fetch_action::{
    EEF_STEP, EEF_TURN, FETCH_ACTION_DIM, FetchAction, HEAD_SPEED, MAX_ANGULAR_SPEED,
    MAX_LINEAR_SPEED,
};
pub use fetch_body::{
    BASE_RADIUS, CAMERA_OFFSET, DIAGONAL30, FETCH_FINGER_MASS, FETCH_JOINTS, FETCH_LINKS,
    FETCH_MASS, FINGER_OPEN, FetchJoint, FetchJoints, FetchLink, GRIPPER_CENTRE, GRIPPER_FRICTION,
    GRIPPER_OFFSET, JointInfo, START_TILT, START_TORSO, WHEEL_RADIUS, WHEEL_SEPARATION, link_mass,
};
pub use fetch_proprioception::FetchProprioception;
pub use grasp::GraspRules;
pub use hand::{
    FINGER_CLOSED, FINGER_MASS, FINGER_TORQUE, FINGERS, HAND_FRICTION, PALM_MASS, Side,
    THUMB_CLOSED,
};
pub use ik::{IK_JOINTS, IkError, IkSolver};
pub use proprioception::{LocalPose, Proprioception};
pub use relative::{EYE_FOV, REACH_DISTANCE};
pub use robot::{BehaviorRobot, RobotError, RobotParts};
