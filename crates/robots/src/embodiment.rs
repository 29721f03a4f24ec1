//! What every robot is: the [`Embodiment`] trait and the plain facts of [`EmbodimentSpec`].
//!
//! An environment, its metrics, sensors and recordings, and the planners reach a robot only
//! through this interface, so that a new robot is one new implementation, not a new branch in
//! every caller. Hands are numbered (0 left, 1 right for two; 0 for one), actions and
//! proprioception are plain numbers whose layout each robot documents, and the moves outside
//! physics that symbolic primitives make (teleport, grasp now, release now) are part of it.

use crate::action::{ActionError, ActionSpace};
use crate::arm::Arm;
use crate::grasp::GraspRules;
use crate::magic::MagicError;
use crate::posed_hand::PosedHand;
use crate::relative;
use crate::robot::RobotKind;
use behavior_sim::{AttachmentId, ObjectId, Primitive, StepHooks, World};
use rapier3d::math::Pose;
use std::sync::Arc;

/// How a robot's base moves on the floor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BaseDrive {
    /// Any way at once: forward, sideways and turning (the BehaviorRobot's floating body).
    Holonomic,
    /// Forward or back along its heading, and turning on the spot (Fetch's two wheels).
    Differential,
}

/// How a robot's hands are moved: what a planner of its hands' motion works in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HandMotion {
    /// Each hand a free body whose pose the actions set directly, within reach of a shoulder
    /// (the BehaviorRobot's palms): planned as a pose.
    Posed,
    /// Each hand at the end of a jointed arm whose joints the actions move (Fetch's arm):
    /// planned in the arm's joint space.
    Jointed,
}

/// A move of the base asked of [`Embodiment::base_action`], in the base's own frame at the
/// step's start: forward (+x), to the left (+y), m, and turning left, rad.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BaseMove {
    /// Forward, m.
    pub forward: f32,
    /// To the left, m.
    pub left: f32,
    /// Turning left (counter-clockwise seen from above), rad.
    pub turn: f32,
    /// How near the point counts as there, m: a base that cannot move sideways turns to
    /// `turn` only within it.
    pub within: f32,
}

/// How a lidar sweeps its beams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scan {
    /// One horizontal fan of `beams` over `fov` rad, centred ahead.
    Fan {
        /// Beams in the fan.
        beams: u32,
        /// Its opening, rad.
        fov: f32,
    },
    /// `rows` fans of `columns` beams all round, at elevations spread over `vertical_fov` rad
    /// centred on the horizon.
    AllRound {
        /// Fans, top first.
        rows: u32,
        /// Beams per fan, starting straight ahead and turning left.
        columns: u32,
        /// The spread of the fans' elevations, rad.
        vertical_fov: f32,
    },
}

/// A lidar on a robot: where it is now, how it scans, and its range, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LidarMount {
    /// Its pose in the world: beams go out along its +x, fans about its z.
    pub pose: Pose,
    /// How it scans.
    pub scan: Scan,
    /// Returns nearer than this are dropped, m.
    pub min_range: f32,
    /// Returns farther than this are dropped, m.
    pub max_range: f32,
}

/// The plain facts about a kind of robot that callers plan with, before and after it exists.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EmbodimentSpec {
    /// Which kind.
    pub kind: RobotKind,
    /// The names the episode's metrics give its hands or grippers, in hand order.
    pub hand_names: &'static [&'static str],
    /// How high above the floor its own origin is when it stands: what
    /// [`crate::Robot::standing_pose`] adds to a floor point, m.
    pub origin_height: f32,
    /// How its base moves.
    pub drive: BaseDrive,
    /// How its hands move.
    pub hand_motion: HandMotion,
    /// The action spaces it can be driven through.
    pub spaces: &'static [ActionSpace],
    /// The space physical primitives drive it through: the one that moves each part exactly as
    /// a plan says (a hand's pose, an arm's joints).
    pub primitive_space: ActionSpace,
    /// How far across the floor from the base an object's box may be for its hands to be tried
    /// on it, m.
    pub arm_reach: f32,
    /// How far what a hand carries may trail where the hand is told to be while the base
    /// drives, m: the margin base plans keep round it.
    pub carry_sway: f32,
}

impl EmbodimentSpec {
    /// How many hands (or grippers) it has.
    pub fn hands(&self) -> usize {
        self.hand_names.len()
    }

    /// Whether it can be driven through `space`.
    pub fn drives(&self, space: ActionSpace) -> bool {
        self.spaces.contains(&space)
    }
}

/// A part of a robot whose motion the episode's metrics follow (the original's body and hands,
/// or body and gripper).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackedPart {
    /// `body`, then a hand's name ([`EmbodimentSpec::hand_names`]).
    pub name: &'static str,
    /// The world object it is.
    pub object: ObjectId,
    /// Whether it holds something now.
    pub holding: bool,
}

/// A robot, whichever: what an episode, its sensors and metrics, a recording and a planner need
/// of a body. It acts inside the world's step ([`StepHooks`]): an action set with
/// [`Embodiment::set_action`] acts for the next step, after which it holds still.
///
/// Hands are numbered from 0 ([`EmbodimentSpec::hand_names`] names them); a number beyond them
/// is no hand: it holds nothing and a move with it is [`MagicError::NoHand`].
pub trait Embodiment: StepHooks {
    /// Its facts.
    fn spec(&self) -> &'static EmbodimentSpec;

    /// How many numbers an action of `space` has (0 for a space it cannot be driven through).
    fn action_dim(&self, space: ActionSpace) -> usize;

    /// Checks `values` as an action of `space` and sets it for the next step. A bad one is an
    /// error and changes nothing.
    fn set_action(&mut self, space: ActionSpace, values: &[f32]) -> Result<(), ActionError>;

    /// The action of `space` that moves the base by `step` within one step as nearly as it can
    /// (clipped to what one step allows), everything else held still; `None` for a space
    /// without the base.
    fn base_action(&self, space: ActionSpace, step: BaseMove) -> Option<Vec<f32>>;

    /// Each number's lower and upper bound in an action of `space` (values beyond are clipped
    /// to them): [−1, 1] for a robot whose actions are normalised motions, a joint's limits
    /// for a number that is its position (the R1's).
    fn action_bounds(&self, space: ActionSpace) -> Vec<[f32; 2]> {
        vec![[-1.0, 1.0]; self.action_dim(space)]
    }

    /// The action of `space` that holds everything where it is for a step: zeros for a robot
    /// whose actions are motions, the joints' present positions for one whose actions are
    /// positions (the R1's).
    fn still_action(&self, space: ActionSpace) -> Vec<f32> {
        vec![0.0; self.action_dim(space)]
    }

    /// How many numbers [`Embodiment::proprioception_into`] gives.
    fn proprioception_dim(&self) -> usize;

    /// Appends its proprioception to `out` ([`Embodiment::proprioception_dim`] numbers).
    fn proprioception_into(&self, world: &World, out: &mut Vec<f32>);

    /// The base's pose in the world (its own origin: see [`EmbodimentSpec::origin_height`]).
    fn base_pose(&self, world: &World) -> Pose;

    /// The base's object.
    fn base(&self) -> ObjectId;

    /// The world objects it is made of, base first.
    fn objects(&self) -> Vec<ObjectId>;

    /// The object of hand `hand`: the palm or the gripper whose pose is the hand's.
    fn hand_object(&self, hand: usize) -> Option<ObjectId>;

    /// The object hand `hand` holds.
    fn held(&self, hand: usize) -> Option<ObjectId>;

    /// The attachment by which hand `hand` holds what it holds (see
    /// [`behavior_sim::Attachments::anchors`]: where a hand holding a door pulls it).
    fn grasp_attachment(&self, hand: usize) -> Option<AttachmentId>;

    /// What its assisted grasp may take, and how.
    fn grasp_rules(&self) -> &GraspRules;

    /// The on-board camera's pose in the world. It looks along its +x, with +z up.
    fn camera_pose(&self, world: &World) -> Pose;

    /// Its lidar now.
    fn lidar(&self, world: &World) -> LidarMount;

    /// The jointed arm that moves hand `hand`, as it stands now, for arm planners; `None` for a
    /// hand that is not at the end of one (the BehaviorRobot's posed palms) or no hand.
    fn arm(&self, _hand: usize) -> Option<Arc<dyn Arm>> {
        None
    }

    /// Hand `hand` as a hand posed directly by actions, as it stands now, for hand planners;
    /// `None` for a hand at the end of an arm (Fetch's gripper) or no hand.
    fn posed_hand(&self, _hand: usize) -> Option<Arc<dyn PosedHand>> {
        None
    }

    /// Shapes beyond its objects that move with the base and that a base plan must keep clear
    /// of fixed things, with their poses in the world: what stops the base where its objects
    /// alone would not.
    fn base_sweep(&self, _world: &World) -> Vec<(Primitive, Pose)> {
        Vec::new()
    }

    /// Puts the base at `pose` (as [`Embodiment::base_pose`] gives it) at once, the hands or
    /// arms with it and what they hold with them; nothing else moves, and nothing is checked
    /// for collisions (a caller checks where it sends the robot).
    fn teleport(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError>;

    /// Puts `object` in hand `hand` and holds it there with the assisted grasp's attachment,
    /// closing the hand.
    fn grasp_now(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError>;

    /// Holds `object` in hand `hand` where it is, if the hand touches it: the original's
    /// forced assisted grasp after a physical grasp closed the hand (it asks for contact, not
    /// for the assisted grasp's rays).
    fn grasp_touching(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError>;

    /// Puts hand `hand` at its target at once, with what it holds, for a hand pinned behind
    /// furniture; nothing to do for one that cannot be left behind.
    fn reset_hand(&mut self, world: &mut World, hand: usize) -> Result<(), MagicError>;

    /// Lets go of what hand `hand` holds at once and opens it; the object it held, if any.
    /// The object stays where it is, its contacts with the hand back once they are apart.
    fn release_now(&mut self, world: &mut World, hand: usize) -> Option<ObjectId>;

    /// The base, then each hand, as the original's metrics follow them.
    fn tracked_parts(&self) -> Vec<TrackedPart> {
        let body = TrackedPart {
            name: "body",
            object: self.base(),
            holding: false,
        };
        let names = self.spec().hand_names.iter().enumerate();
        let hands = names.filter_map(|(hand, &name)| {
            Some(TrackedPart {
                name,
                object: self.hand_object(hand)?,
                holding: self.held(hand).is_some(),
            })
        });
        std::iter::once(body).chain(hands).collect()
    }

    /// `in hand`: whether a hand holds the object.
    fn is_holding(&self, object: ObjectId) -> bool {
        (0..self.spec().hands()).any(|hand| self.held(hand) == Some(object))
    }

    /// `in reach`: the object's centre is within 2 m of the base's origin (see `relative.rs`).
    fn in_reach(&self, world: &World, object: ObjectId) -> bool {
        relative::in_reach(world, self.base_pose(world).translation, object)
    }

    /// `in the same room`: the object is in the room the base is in.
    fn in_same_room(&self, world: &World, object: ObjectId) -> bool {
        relative::in_same_room(world, self.base_pose(world).translation, object)
    }

    /// `in the field of view` of the camera, approximated geometrically: the object's centre is
    /// in its 120° view and nothing hides it (see `relative.rs`).
    fn in_field_of_view(&self, world: &World, object: ObjectId) -> bool {
        let camera = self.camera_pose(world);
        relative::in_view(world, camera, object, &self.objects())
    }
}
