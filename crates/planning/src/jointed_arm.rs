//! Physical GRASP and PLACE_* for hands at the end of jointed arms
//! ([`behavior_robots::HandMotion::Jointed`]: Fetch's), read only through the robot's [`Arm`]:
//! goals for the end effector turned into joint positions by the arm's own inverse kinematics
//! ([`Arm::ik`]; Fetch's [`behavior_robots::IkSolver`]), the arm planned to them in its joint
//! space ([`ArmSpace`]) and executed joint by joint through the robot's primitive action space
//! (Fetch's [`behavior_robots::ActionSpace::Joints`], iGibson 2.1+'s joint controller), one step
//! of physics each; the
//! grasp made by the assisted grasp as the gripper closes, the placement by opening it above a
//! pose the world's sampler found, then settling.
//!
//! - GRASP: the gripper pointing down at the top of the object's box, its fingers across the
//!   narrower side of its own box (other headings after; then tilted toward it from the base's
//!   side), the fingertips [`Tuning::arm_approach`] short of it; on in a straight line until
//!   the palm or a finger touches the object (at most [`Tuning::arm_descent`]), closed until it
//!   holds (at most [`Tuning::close_steps`]; touching and not held, the grasp is forced as the BehaviorRobot's is),
//!   straight back up, then the arm planned back to where it was, with what it holds (where
//!   that is not free — a tile does not fit the folded arm — it stays, and the next drive's
//!   [`tuck`] finds a way to carry it).
//! - PLACE_*: poses for the held object by the world's sampler (in a copy of the world where the
//!   gripper let go; held as the gripper points down, tilted or level, upright ways first), the
//!   arm planned with it to [`Tuning::place_height`] above one, the gripper opened,
//!   [`Tuning::settle_steps`] steps to settle, straight up and back.
//!
//! Executing joint by joint, each step's configuration is what the robot's own joint update
//! ([`Arm::after`]) makes of the action, so every configuration the arm will pass is
//! known before it moves: each is checked free (the plan re-validated a step, at most 0.04 rad
//! a joint, apart), and after each step the arm is compared with it — one that is not there
//! was stopped by something fixed. Straight lines of the end effector (the descent, the lift,
//! the leave) are IK solutions [`LINE_STEP`] apart, each from the last.
//!
//! Before, the arm went through the end-effector controller, whose IK pulls the arm toward its
//! rest pose: it did not follow joint-space plans joint for joint, got stuck between the tucked
//! arm and a grasp pose, and its workspace floor (0.2 m above the base) kept things on the
//! floor out of reach. Fetch solved none of Table 1's activities that way.

use crate::execute::RunError;
use crate::manipulation::{
    Grip, Hands, Manipulator, StandTest, grasp_point, holds, on_or_in_goals, placement_goals,
    rng_seed, vertical_axis,
};
use crate::physical::{Attempt, Stepper, attempt, call_rng, force_grasp};
use crate::primitive::{Call, Failure};
use crate::symbolic::check;
use crate::tuning::Tuning;
use behavior_core::rng::{SimRng, seeded, uniform};
use behavior_env::Env;
use behavior_motion::BaseConfig;
use behavior_motion::{ArmBody, ArmSpace, any_config, closest_turn};
use behavior_motion::{PlanParams, plan, steps_along};
use behavior_robots::{Arm, ArmConfig, Embodiment, Robot};
use behavior_sim::{BodyRef, ObjectId, World};
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

/// How far the gripper moves a step in its descent, m.
const DESCENT_STEP: f32 = 0.004;
/// How far apart the IK solutions of an end effector's straight line are, m.
const LINE_STEP: f32 = 0.01;
/// The largest change of a joint between two solutions of a straight line, rad (m for the
/// torso): a bigger one is the IK jumping to another branch, and the line is not followed.
const LINE_JUMP: f32 = 0.25;
/// Headings of the fingers tried: across the box's narrower side, its other side, and these
/// many more at random.
const MORE_HEADINGS: usize = 4;
/// How close to each configuration of a path the arm must be, rad (m for the torso): the joint
/// controller moves a joint exactly as asked, so any gap is a block.
const ON_PATH: f32 = 1e-4;
/// How high the arm may lift its torso more to carry what it took back, m each.
const LIFT: f32 = 0.1;
const LIFTS: usize = 4;
/// How far the gripper goes straight up with what it took, m.
const LIFT_OFF: f32 = 0.1;
/// How far the gripper goes straight up after letting go, m.
const LEAVE: f32 = 0.1;

/// An arm's motion: where it started and the goal configuration it was taken to, the
/// configurations it passed on the way, step by step, and those of the rest of the primitive
/// (the descent, the lift, the way back).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct ArmPath {
    /// The configurations planned, from where it started to the goal.
    pub planned: Vec<ArmConfig>,
    /// The configurations it passed on the way, a step each.
    pub executed: Vec<ArmConfig>,
    /// Those of the rest of the primitive: the descent, the lift, the way back.
    pub after: Vec<ArmConfig>,
}

/// Whether the arm of the carrying hand ([`carrying`]; of `placement`'s hand, given one), from
/// where the base stands, has a free configuration over the object for a grasp — or, holding
/// something and given a placement, above a place for it; true for what cannot be held (a
/// cabinet to open) and for a hand at the end of no arm.
pub fn reaches(env: &Env, object: ObjectId, placement: Option<&Call>, tuning: &Tuning) -> bool {
    let hand = placement.map_or_else(|| carrying(env), |call| call.hand);
    let (Some((world, robot, arm)), Some(goals)) = (
        arm_of(env, hand),
        reach_goals(env, hand, object, placement, tuning),
    ) else {
        return true;
    };
    any_solved(world, &ArmBody::of(world, robot, arm), &goals)
}

/// The hand whose arm a reach test tries when no call names one: the last, which the task
/// solver carries with (the right of two; Fetch's one).
fn carrying(env: &Env) -> usize {
    env.robot().map_or(0, |r| r.hands().saturating_sub(1))
}

/// A test of places to stand for NAVIGATE_TO `object`: whether the arm of the hand that holds
/// something (the last that does), else of the carrying hand ([`carrying`]), its base standing
/// there, reaches over the object for a grasp or, holding something, above a place for it on
/// or in the object, as OmniGibson's base-pose sampler checks IK reach for each candidate.
/// The goals are the world poses [`reaches`] tries from where the base stands now (straight
/// down they are the same from anywhere). `None` for what there is no arm to test for: no
/// arm, or nothing to take or to put there.
pub(crate) fn reach_test<'e>(
    env: &'e Env,
    object: ObjectId,
    tuning: &Tuning,
) -> Option<impl Fn(&BaseConfig) -> bool + 'e> {
    let hands = env.robot().map_or(0, |r| r.hands());
    let holding = (0..hands)
        .rev()
        .find(|&h| env.robot().is_some_and(|r| r.held(h).is_some()));
    let hand = holding.unwrap_or_else(|| carrying(env));
    let (world, robot, arm) = arm_of(env, hand)?;
    let goals = match robot.held(hand) {
        Some(_) => {
            let goals = on_or_in_goals(env, object, hand, tuning);
            (!goals.is_empty()).then_some(goals)?
        }
        None => reach_goals(env, hand, object, None, tuning)?,
    };
    let body = ArmBody::of(world, robot, arm);
    // The base's frame over the floor's at its configuration: kept as the base moves.
    let lift = crate::physical::base_config(env).pose().inverse() * body.base;
    Some(move |stand: &BaseConfig| {
        let mut moved = body.clone();
        moved.base = stand.pose() * lift;
        any_solved(world, &moved, &goals)
    })
}

/// The end-effector goals of [`reaches`]; `None` for what cannot be held and is given no
/// placement (a cabinet to open: within reach of its box is enough).
fn reach_goals(
    env: &Env,
    hand: usize,
    object: ObjectId,
    placement: Option<&Call>,
    tuning: &Tuning,
) -> Option<Vec<Pose>> {
    let (world, robot, arm) = arm_of(env, hand)?;
    match placement.and_then(|c| Some((c, c.primitive.relation()?))) {
        Some((call, relation)) if robot.held(hand).is_some() => {
            let mut rng = call_rng(env, call);
            let goals = placement_goals(world, env.robot()?, call, relation, tuning, &mut rng);
            Some(goals.unwrap_or_default())
        }
        _ if robot
            .grasp_rules()
            .holdable(world, BodyRef::from(object))
            .is_none() =>
        {
            None
        }
        _ => {
            let call = Call {
                primitive: crate::Primitive::Grasp,
                object,
                hand,
            };
            let mut rng = call_rng(env, &call);
            Some(grasp_goals(
                world,
                robot,
                arm.tip(),
                object,
                tuning,
                &mut rng,
            ))
        }
    }
}

/// Whether one of `goals` has a free IK solution for the arm `body`.
fn any_solved(world: &World, body: &ArmBody, goals: &[Pose]) -> bool {
    goals.iter().any(|g| solve(world, body, g).is_some())
}

/// The gripper's commands: open, or closed on what it holds.
const OPEN: f32 = 1.0;
const CLOSED: f32 = -1.0;

/// The primitive's preconditions, and that the robot is driven through its primitive action
/// space (joint by joint) with an arm at the hand called.
fn precondition(env: &Env, call: &Call) -> Result<(), Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    if robot.space() != robot.spec().primitive_space {
        return Err(Failure::Unavailable(
            "physical primitives drive an arm joint by joint: the robot's primitive action \
             space (Fetch's `joints`)",
        ));
    }
    if robot.arm(call.hand).is_none() {
        return Err(Failure::NoHand(call.hand));
    }
    check(world, robot, call)
}

/// The episode's world, its robot and the arm of `hand` as it stands, if the robot is driven
/// through its primitive action space and that hand is at the end of an arm.
fn arm_of(env: &Env, hand: usize) -> Option<(&World, &dyn Embodiment, Arc<dyn Arm>)> {
    let (world, robot) = (env.world()?, env.robot()?);
    if robot.space() != robot.spec().primitive_space {
        return None;
    }
    Some((world, robot.embodiment(), robot.arm(hand)?))
}

/// The manipulator of hands at the end of jointed arms, read through each robot's [`Arm`].
pub(crate) struct JointedArm;

/// Where an arm started a primitive, and its path so far.
pub(crate) struct ArmReached {
    start: ArmConfig,
    path: ArmPath,
}

/// The gripper's command for a grip.
fn command(grip: Grip) -> f32 {
    match grip {
        Grip::Open => OPEN,
        Grip::Closed => CLOSED,
    }
}

impl Manipulator for JointedArm {
    type Hand = usize;
    type Reached = ArmReached;
    type Path = ArmPath;

    fn hand(&self, env: &Env, call: &Call) -> Result<usize, Failure> {
        precondition(env, call).map(|()| call.hand)
    }

    /// The fingertips at `at`, the gripper pointing straight down, then pitched toward
    /// `facing` as for a grasp, then level toward it.
    fn press_goals(&self, env: &Env, hand: usize, at: Vector, facing: f32) -> Vec<Pose> {
        let Some((_, _, arm)) = arm_of(env, hand) else {
            return Vec::new();
        };
        let pitches = [FRAC_PI_2].into_iter().chain(PITCHES).chain([0.0]);
        pitches
            .map(|pitch| {
                let rotation = pointing(facing, pitch);
                Pose::from_parts(at - rotation * Vector::X * arm.tip(), rotation)
            })
            .collect()
    }

    fn grasp_goals(
        &self,
        env: &Env,
        hand: usize,
        call: &Call,
        tuning: &Tuning,
        rng: &mut SimRng,
    ) -> Vec<Pose> {
        arm_of(env, hand).map_or(Vec::new(), |(world, robot, arm)| {
            grasp_goals(world, robot, arm.tip(), call.object, tuning, rng)
        })
    }

    fn reach(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        goals: &[Pose],
        grip: Grip,
        rng: &mut SimRng,
    ) -> Attempt<ArmReached> {
        let start = arm_now(steps.env, hand);
        let path = attempt!(reach(steps, hand, goals, command(grip), rng));
        Ok(Ok(ArmReached { start, path }))
    }

    fn descend(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        object: ObjectId,
        reached: &mut ArmReached,
    ) -> Attempt<()> {
        descend(steps, hand, object, &mut reached.path.after)
    }

    fn close(&self, steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
        close(steps, call)
    }

    /// Straight up by [`LIFT_OFF`], the gripper closed if it holds what it took.
    fn lift_off(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        held: bool,
        reached: &mut ArmReached,
    ) -> Attempt<()> {
        let grip = command(Grip::holding(held));
        straight_up(steps, hand, LIFT_OFF, grip, &mut reached.path.after)
    }

    fn open(&self, steps: &mut Stepper<'_, '_>, hand: usize) -> Attempt<()> {
        open(steps, hand)
    }

    fn settle(&self, steps: &mut Stepper<'_, '_>, hand: usize) -> Attempt<()> {
        let n = steps.tuning.settle_steps;
        wait(steps, hand, n)
    }

    /// Straight up by [`LEAVE`], open.
    fn leave(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        reached: &mut ArmReached,
    ) -> Attempt<()> {
        straight_up(steps, hand, LEAVE, OPEN, &mut reached.path.after)
    }

    fn come_back(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        grip: Grip,
        reached: &mut ArmReached,
    ) -> Attempt<()> {
        come_back(
            steps,
            hand,
            reached.start,
            command(grip),
            &mut reached.path.after,
        )
    }

    fn slide(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        offset: Vector,
        reached: &mut ArmReached,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()> {
        slide(steps, hand, offset, &mut reached.path.after, done)
    }

    fn hold_still(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: usize,
        n: u32,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()> {
        hold(steps, hand, n, CLOSED, done)
    }

    /// The arm's links are kinematic: pulling a fridge door along its arc, Fetch's grasp broke
    /// in the first step at 1.4–23 kN (10° and 2° moves) against the grasp's 350 N.
    const SWINGS_LEAVES: bool = false;

    fn path(&self, reached: ArmReached) -> ArmPath {
        reached.path
    }
}

impl Hands for JointedArm {
    fn reaches(
        &self,
        env: &Env,
        object: ObjectId,
        placement: Option<&Call>,
        tuning: &Tuning,
    ) -> bool {
        reaches(env, object, placement, tuning)
    }

    fn reach_test<'e>(
        &self,
        env: &'e Env,
        object: ObjectId,
        tuning: &'e Tuning,
    ) -> Option<StandTest<'e>> {
        reach_test(env, object, tuning).map(|test| Box::new(test) as StandTest<'e>)
    }

    fn tuck(&self, steps: &mut Stepper<'_, '_>) -> Attempt<()> {
        let hands = steps.env.robot().map_or(0, |r| r.hands());
        for hand in 0..hands {
            attempt!(tuck(steps, hand));
        }
        Ok(Ok(()))
    }

    /// The gripper sets what it holds down pointing down: see [`held_below`].
    fn set_down_turns(
        &self,
        world: &World,
        robot: &Robot,
        call: &Call,
        grip: &Pose,
    ) -> Vec<Option<Pose>> {
        held_below(world, robot.embodiment(), call.hand, call.object, grip)
            .into_iter()
            .map(Some)
            .collect()
    }
}

/// End-effector poses in the world over the object, best first, the gripper pointing at the
/// top of its box (near its end nearest the base, for a long one), jittered, the fingertips
/// [`Tuning::arm_approach`] short of it (they reach `tip` beyond the end effector): straight down, the fingers closing across the box's narrower
/// side, then the other, then at random headings; then tilted by each of [`PITCHES`] from the
/// base's side (straight down, a hamburger 0.98 m ahead had no IK solution within 0.27 m).
fn grasp_goals(
    world: &World,
    robot: &dyn Embodiment,
    tip: f32,
    object: ObjectId,
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Vec<Pose> {
    let base = robot.base_pose(world).translation;
    let at = grasp_point(world, object, base, tuning.grasp_inset);
    let across = across_heading(world, object);
    let facing = (at.y - base.y).atan2(at.x - base.x);
    let mut rotations: Vec<Rotation> =
        [across, across + PI, across + FRAC_PI_2, across - FRAC_PI_2]
            .into_iter()
            .chain((0..MORE_HEADINGS).map(|_| uniform(rng, -PI, PI)))
            .map(|heading| pointing(heading, FRAC_PI_2))
            .collect();
    rotations.extend(PITCHES.iter().map(|&pitch| pointing(facing, pitch)));
    rotations
        .into_iter()
        .map(|rotation| {
            let target = Vector::new(
                at.x + uniform(rng, -tuning.grasp_jitter, tuning.grasp_jitter),
                at.y + uniform(rng, -tuning.grasp_jitter, tuning.grasp_jitter),
                at.z,
            );
            let back = rotation * Vector::X * (tuning.arm_approach + tip);
            Pose::from_parts(target - back, rotation)
        })
        .collect()
}

/// The heading of the gripper pointing down whose fingers close across the object's narrower
/// side: perpendicular to the longer of its own box's two axes that lie nearest the floor,
/// in [−π/2, π/2). The fingers close along the end effector's y, so heading `h` closes them
/// along `h + π/2`. Taken from the world's box instead, a candle lying diagonally (13.6 cm
/// long, 4 cm thick, a 12 × 15 cm box) had the fingers close along its length, wider than
/// they open, and a finger came down on it.
fn across_heading(world: &World, object: ObjectId) -> f32 {
    let pose = world.bodies().pose(object);
    let size = {
        let local = world.bodies().local_aabb(object);
        local.maxs - local.mins
    };
    let vertical = vertical_axis(pose.rotation);
    let long = (0..3)
        .filter(|&a| a != vertical)
        .max_by(|&a, &b| size[a].total_cmp(&size[b]))
        .unwrap_or(0);
    let mut axis = Vector::ZERO;
    axis[long] = 1.0;
    let along = pose.rotation * axis;
    let heading = along.y.atan2(along.x);
    if heading >= FRAC_PI_2 {
        heading - PI
    } else if heading < -FRAC_PI_2 {
        heading + PI
    } else {
        heading
    }
}

/// Where what the gripper holds (`grip`: its pose in the gripper's frame) is with the gripper
/// pointing down toward `target` from the base, straight down, at each of [`PITCHES`] and
/// level: the ways a placement sets it down, those that set it down upright (its own vertical
/// axis within [`UPRIGHT`] of the world's) first. The sampler keeps an object's turn, and the
/// gripper as it comes back from a grasp (tucked, or turned on the way back) points anywhere;
/// a placement as it is held asks the wrist for a turn the arm has not got (traced: every goal
/// for a pad over an ash can was 0.7–1 m out of reach of Fetch's IK). A candle taken lying
/// from a carton, set down as it was held, rolled off the table; held level, the gripper
/// sets it down standing.
pub(crate) fn held_below(
    world: &World,
    robot: &dyn Embodiment,
    hand: usize,
    target: ObjectId,
    grip: &Pose,
) -> Vec<Pose> {
    let base = robot.base_pose(world).translation;
    let at = world.bodies().aabb(target).center();
    let facing = (at.y - base.y).atan2(at.x - base.x);
    let Some(gripper) = robot.hand_object(hand) else {
        return Vec::new();
    };
    let eef = world.bodies().pose(gripper).translation;
    let mut held: Vec<Pose> = std::iter::once(FRAC_PI_2)
        .chain(PITCHES)
        .chain([0.0])
        .map(|pitch| Pose::from_parts(eef, pointing(facing, pitch)) * *grip)
        .collect();
    // Stable: among the upright and among the others, straight down first.
    held.sort_by_key(|pose| (pose.rotation * Vector::Z).z.abs() < UPRIGHT.cos());
    held
}

/// How far from the vertical an object's own vertical axis may lean for it to be set down
/// upright, rad.
const UPRIGHT: f32 = PI / 12.0;

/// Pitches below the floor of the tilted approaches, rad, steepest first.
const PITCHES: [f32; 3] = [PI / 3.0, PI / 4.0, PI / 6.0];

/// The end effector's rotation pointing `pitch` below the floor (its x) toward the floor's
/// direction `heading`, its fingers closing level.
fn pointing(heading: f32, pitch: f32) -> Rotation {
    Rotation::from_rotation_z(heading) * Rotation::from_rotation_y(pitch)
}

/// The arm's free configuration that puts the end effector at `goal` (in the world), by IK
/// from where the arm is.
fn solve(world: &World, body: &ArmBody, goal: &Pose) -> Option<ArmConfig> {
    let local = body.base.inverse() * *goal;
    let mut rng = seeded(goal_seed(&local));
    free_ik(body.arm.as_ref(), &local, &mut rng, |c| {
        body.clear(world, c)
    })
}

/// The first IK solution for `goal` (base frame) that `fits`: from where the arm is, then from
/// [`IK_RESTARTS`] configurations drawn at random — the redundant arm reaches most goals in
/// several ways, and the one nearest where it is may pass through the table (or, carrying a
/// sheet of plywood upright, through the torso) where another does not.
fn free_ik(
    arm: &dyn Arm,
    goal: &Pose,
    rng: &mut SimRng,
    fits: impl Fn(&ArmConfig) -> bool,
) -> Option<ArmConfig> {
    let here = arm.now();
    let starts = std::iter::once(here).chain((0..IK_RESTARTS).map(|_| any_config(arm, &here, rng)));
    starts
        .filter_map(|start| arm.ik(&start, goal))
        .map(|c| closest_turn(arm, &c, &here))
        .find(|c| fits(c))
}

/// IK searches from random configurations after the one from where the arm is.
const IK_RESTARTS: usize = 4;

/// A seed from a goal's pose, so that the same goal draws the same restarts.
fn goal_seed(goal: &Pose) -> u64 {
    let t = goal.translation;
    let r = goal.rotation;
    [t.x, t.y, t.z, r.x, r.y, r.z, r.w]
        .iter()
        .fold(0u64, |h, v| h.rotate_left(9) ^ u64::from(v.to_bits()))
}

/// An arm folded over its base before the robot drives ([`Arm::tucked`]: Fetch's as the real
/// robot's `tuck_arm` folds it, reference: robots §1.6, iGibson's tucked joints), the torso
/// where it is or higher:
/// unfolded, the BEHAVIOR start pose holds the gripper 0.55 m ahead at a counter's height, and
/// every stand found with it left a hamburger on a counter 0.9 m from the base. Holding
/// something that does not fit the folded arm (a tile, a pad), it is carried over the front of
/// the base ([`CARRY`]) the way that keeps the footprint smallest: left where it took the
/// thing, low and ahead, the arm made the base's footprint too big for most ways through the
/// home. Planned with what the gripper holds; where no plan gets to any of these, the arm
/// stays. Nothing to do for a hand at the end of no arm.
pub(crate) fn tuck(steps: &mut Stepper<'_, '_>, hand: usize) -> Attempt<()> {
    let Some((_, robot, arm)) = arm_of(steps.env, hand) else {
        return Ok(Ok(()));
    };
    let now = arm.now();
    let tucked = arm.tucked(&now);
    if close_to(&now, &tucked) {
        return Ok(Ok(()));
    }
    let gripper = if robot.held(hand).is_some() {
        CLOSED
    } else {
        OPEN
    };
    attempt!(unstick(steps, hand, gripper));
    let Some((world, robot, arm)) = arm_of(steps.env, hand) else {
        return Ok(Ok(()));
    };
    let body = ArmBody::of(world, robot, arm);
    let mut rng = seeded(u64::from(steps.env.steps()));
    let goals = carry_goals(world, &body, tucked, &mut rng);
    let planned = goals
        .into_iter()
        .take(CARRY_TRIES)
        .find_map(|goal| plan_arm_to(world, body.clone(), goal, steps.tuning, &mut rng).ok());
    let Some(planned) = planned else {
        return Ok(Ok(()));
    };
    follow(steps, hand, &planned, gripper, Check::Free, &mut Vec::new())
}

/// Whether every joint of `a` is within [`ON_PATH`] of `b`'s.
fn close_to(a: &ArmConfig, b: &ArmConfig) -> bool {
    a.values()
        .iter()
        .zip(b.values())
        .all(|(a, b)| (a - b).abs() <= ON_PATH)
}

/// Where [`tuck`] may take the arm, each free, the smallest footprint first
/// ([`ArmBody::spread`]): the folded arm with the torso where it is, then higher by [`LIFT`]
/// steps; the gripper pointing down or ahead at each of [`CARRY`], or to one side with what it
/// holds upright beside the base at each of [`CARRY_BESIDE`] (base frame), by IK
/// ([`free_ik`]).
fn carry_goals(
    world: &World,
    body: &ArmBody,
    tucked: ArmConfig,
    rng: &mut SimRng,
) -> Vec<ArmConfig> {
    let arm = body.arm.as_ref();
    let folded = (0..LIFTS).map(|k| lifted(arm, &tucked, LIFT * k as f32, true));
    let rolled = |heading: f32, pitch: f32, rolls: &[f32]| -> Vec<Rotation> {
        rolls
            .iter()
            .map(|&roll| pointing(heading, pitch) * Rotation::from_rotation_x(roll))
            .collect()
    };
    let down_or_ahead = [FRAC_PI_2, 0.0].map(|pitch| rolled(0.0, pitch, &[0.0, FRAC_PI_2]));
    // Pointing to one side, what it holds turned four ways about that axis: a sheet of
    // plywood taken by its edge is carried upright along the way, not flat across a door.
    let quarters = [0.0, FRAC_PI_2, PI, -FRAC_PI_2];
    let sideways = [FRAC_PI_2, -FRAC_PI_2].map(|heading| rolled(heading, 0.0, &quarters));
    let ahead = down_or_ahead
        .concat()
        .into_iter()
        .flat_map(|way| CARRY.iter().map(move |&at| (at, way)))
        .map(|([x, z], way)| {
            // What it holds is carried centred on the base's axis: held by its edge, a tile
            // held with the gripper there stuck 0.37 m out to one side, and no door let it
            // through.
            let centre = body.held_centre().map_or(0.0, |c| (way * c).y);
            Pose::from_parts(Vector::new(x, -centre, z), way)
        });
    let beside = sideways
        .concat()
        .into_iter()
        .flat_map(|way| [-1.0, 1.0].map(|side| (way, side)))
        .flat_map(|(way, side)| CARRY_BESIDE.iter().map(move |&at| (at, way, side)))
        .filter_map(|(at, way, side)| beside_base(body, at, way, side));
    let fits = |c: &ArmConfig| body.clear(world, c);
    let carried: Vec<ArmConfig> = ahead
        .chain(beside)
        .filter_map(|goal| free_ik(arm, &goal, rng, fits))
        .collect();
    let mut goals: Vec<(f32, ArmConfig)> = Vec::new();
    for c in folded.filter(|c| fits(c)).chain(carried) {
        if !goals.iter().any(|(_, g)| *g == c) {
            goals.push((body.spread(&c), c));
        }
    }
    // Ties (a torso lifted) keep their order.
    goals.sort_by(|a, b| a.0.total_cmp(&b.0));
    goals.into_iter().map(|(_, c)| c).collect()
}

/// Where the gripper carries what does not fit the folded arm, pointing down or ahead (each
/// turned about its axis both ways: a tile held flat or on its edge, across or along the way):
/// (ahead of the base's centre, height), m, in the base's frame.
const CARRY: [[f32; 2]; 8] = [
    [0.2, 1.1],
    [0.25, 1.0],
    [0.3, 1.2],
    [0.35, 1.1],
    [0.45, 1.1],
    [0.35, 0.9],
    [0.45, 0.9],
    [0.55, 1.0],
];
/// Where what the gripper holds is carried upright beside the base, pointing to one side: its
/// centre's (ahead of the base's centre, height), m, in the base's frame. Carried upright
/// ahead of the base (the gripper 0.55–0.75 m out, the sheet 0.9 m beyond), a sheet of
/// plywood found no base path through the corridor; beside it, the base passed.
const CARRY_BESIDE: [[f32; 2]; 8] = [
    [-0.2, 0.8],
    [-0.1, 0.9],
    [-0.2, 1.0],
    [0.0, 0.8],
    [0.0, 1.0],
    [0.1, 0.9],
    [0.2, 0.8],
    [0.2, 1.0],
];
/// How far from the base's axis what is carried beside it starts, m: 1.5 cm clear of the
/// base's 0.28 m radius (a doorway 0.75 m wide between an open leaf and the frame leaves the
/// base and a sheet of plywood beside it a few centimetres).
const BESIDE: f32 = behavior_robots::BASE_RADIUS + 0.015;

/// The gripper's pose (base frame) pointing `way` that carries what it holds with its box's
/// centre at `at` (ahead, height), on `side` (−1 right, 1 left) of the base, its near face
/// [`BESIDE`] from the base's axis; `None` if it holds nothing.
fn beside_base(body: &ArmBody, [x, z]: [f32; 2], way: Rotation, side: f32) -> Option<Pose> {
    let (lo, hi) = body.held_box(Pose::from_rotation(way))?;
    let centre = (lo + hi) / 2.0;
    let y = if side < 0.0 {
        -BESIDE - hi.y
    } else {
        BESIDE - lo.y
    };
    Some(Pose::from_parts(
        Vector::new(x - centre.x, y, z - centre.z),
        way,
    ))
}

/// Carrying goals planned to before the arm stays as it is.
const CARRY_TRIES: usize = 3;

/// `c` with the torso lifted by `by`, m ([`Arm::lift_joint`]), within its upper limit if
/// `within`; `c` for an arm without a lift.
fn lifted(arm: &dyn Arm, c: &ArmConfig, by: f32, within: bool) -> ArmConfig {
    let mut out = *c;
    if let Some(j) = arm.lift_joint() {
        let top = arm.limits()[j].map_or(c[j], |l| l[1]);
        out[j] = if within {
            (c[j] + by).min(top)
        } else {
            c[j] + by
        };
    }
    out
}

/// The arm taken to the first of `goals` (in the world) with a free IK solution that a plan in
/// its joint space gets to, the gripper held at `gripper`, every step of the way checked free
/// ([`follow`]). Stopped on the way, the arm is brought back.
fn reach(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    goals: &[Pose],
    gripper: f32,
    rng: &mut SimRng,
) -> Attempt<ArmPath> {
    attempt!(unstick(steps, hand, gripper));
    let start = arm_now(steps.env, hand);
    let mut last = Failure::NoHandPose;
    let mut tried = 0;
    for goal in goals {
        let Some((world, robot, arm)) = arm_of(steps.env, hand) else {
            return Ok(Err(Failure::Unavailable("no episode")));
        };
        let body = ArmBody::of(world, robot, arm);
        let Some(config) = solve(world, &body, goal) else {
            continue;
        };
        if tried == GOAL_TRIES {
            break;
        }
        tried += 1;
        let planned = match plan_arm_to(world, body, config, steps.tuning, rng) {
            Ok(planned) => planned,
            Err(failure) => {
                last = failure;
                continue;
            }
        };
        let mut path = ArmPath {
            planned: vec![start, config],
            ..ArmPath::default()
        };
        match follow(
            steps,
            hand,
            &planned,
            gripper,
            Check::Free,
            &mut path.executed,
        )? {
            Ok(()) => return Ok(Ok(path)),
            // Refused before a step: another goal.
            Err(Failure::HandBlocked) if path.executed.is_empty() => {
                last = Failure::HandBlocked;
            }
            Err(failure) => {
                // Best effort: an arm left out would be in the base's way.
                let _ = come_back(steps, hand, start, gripper, &mut path.after)?;
                return Ok(Err(failure));
            }
        }
    }
    Ok(Err(last))
}

/// Ways the gripper is drawn straight out of what it touches, in the base's frame, m: up, back
/// toward the base, both, and higher up.
const UNSTICK: [[f32; 3]; 4] = [
    [0.0, 0.0, 0.1],
    [-0.15, 0.0, 0.0],
    [-0.1, 0.0, 0.1],
    [0.0, 0.0, 0.25],
];

/// An arm whose configuration touches something — the gripper left against a window by a
/// motion that was stopped — drawn straight out of it, unchecked, along the first of
/// [`UNSTICK`] that ends clear: the planner starts only from a free configuration, and every
/// later grasp of a can by a window failed there. Where none ends clear, the arm stays and
/// the planner says why.
fn unstick(steps: &mut Stepper<'_, '_>, hand: usize, gripper: f32) -> Attempt<()> {
    let Some((world, robot, arm)) = arm_of(steps.env, hand) else {
        return Ok(Ok(()));
    };
    let body = ArmBody::of(world, robot, arm);
    if body.clear(world, &body.arm.now()) {
        return Ok(Ok(()));
    }
    let out = UNSTICK.into_iter().find_map(|offset| {
        let path = line(body.arm.as_ref(), Vector::from_array(offset), LINE_STEP)?;
        path.last()
            .is_some_and(|c| body.clear(world, c))
            .then_some(path)
    });
    match out {
        Some(path) => follow(
            steps,
            hand,
            &path,
            gripper,
            Check::Touching,
            &mut Vec::new(),
        ),
        None => Ok(Ok(())),
    }
}

/// Goals with a free IK solution tried before the arm gives up.
const GOAL_TRIES: usize = 4;

/// A planned arm path, densified, from where the arm is to `goal`.
fn plan_arm_to(
    world: &World,
    body: ArmBody,
    goal: ArmConfig,
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Result<Vec<ArmConfig>, Failure> {
    let start = body.arm.now();
    let goal = closest_turn(body.arm.as_ref(), &goal, &start);
    let space = ArmSpace::new(world, body, &start);
    let params = PlanParams {
        seed: rng_seed(rng),
        ..tuning.budget
    };
    let planned = plan(&space, &start, &goal, &params)?;
    let mut dense = vec![start];
    dense.extend(steps_along(&space, &planned.path));
    Ok(dense)
}

/// The configuration of hand `hand`'s arm now (none without one).
fn arm_now(env: &Env, hand: usize) -> ArmConfig {
    arm_of(env, hand).map_or(ArmConfig::default(), |(_, _, a)| a.now())
}

/// The joint action that moves the arm from `now` toward `target` as far as one step allows,
/// the gripper at `gripper`; `None` once within [`ON_PATH`] of it.
fn joint_action(
    arm: &dyn Arm,
    now: &ArmConfig,
    target: &ArmConfig,
    gripper: f32,
) -> Option<Vec<f32>> {
    if close_to(target, now) {
        return None;
    }
    let delta = ArmConfig::from_fn(now.len(), |k| target[k] - now[k]);
    arm.joint_action(now, &delta, gripper)
}

/// The most steps taken toward one configuration of a path: a gap within a joint's range of a
/// step closes in one, a longer one at full speed.
const STEPS_PER_CONFIG: usize = 64;

/// The actions that take the arm through `path` from where it is, and the joints after each, as
/// the robot's joint update ([`Arm::after`]) will move them; `None` where it does not get
/// there (a target beyond a joint's limit).
fn predict(arm: &dyn Arm, path: &[ArmConfig], gripper: f32) -> Option<Vec<(Vec<f32>, ArmConfig)>> {
    let mut joints = arm.now();
    let mut out = Vec::new();
    for target in path {
        let mut there = false;
        for _ in 0..STEPS_PER_CONFIG {
            let Some(action) = joint_action(arm, &joints, target, gripper) else {
                there = true;
                break;
            };
            joints = arm.after(&joints, &action);
            out.push((action, joints));
        }
        if !there && joint_action(arm, &joints, target, gripper).is_some() {
            return None;
        }
    }
    Some(out)
}

/// Which configurations of a motion [`follow`] checks before it moves.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Check {
    /// Every one, free of everything but the robot and what it holds.
    Free,
    /// None: a descent onto the object, a lift off the table it stood on.
    Touching,
}

/// The arm taken through `path` joint by joint with the gripper at `gripper`, every step's
/// configuration predicted ([`predict`]) and, with [`Check::Free`], checked free first; each
/// configuration reached goes to `executed`. A step that leaves the arm short of its
/// prediction was stopped by something fixed: [`Failure::HandBlocked`].
fn follow(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    path: &[ArmConfig],
    gripper: f32,
    check: Check,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let motion = Motion {
        hand,
        gripper,
        check,
    };
    follow_until(steps, motion, path, executed, |_| false)
}

/// How [`follow_until`] moves an arm: which hand's, the gripper held at what, each step
/// checked how.
#[derive(Clone, Copy)]
struct Motion {
    hand: usize,
    gripper: f32,
    check: Check,
}

/// [`follow`], stopping before a step once `done` holds.
fn follow_until(
    steps: &mut Stepper<'_, '_>,
    motion: Motion,
    path: &[ArmConfig],
    executed: &mut Vec<ArmConfig>,
    done: impl Fn(&Env) -> bool,
) -> Attempt<()> {
    let Some((world, robot, arm)) = arm_of(steps.env, motion.hand) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let Some(predicted) = predict(arm.as_ref(), path, motion.gripper) else {
        return Ok(Err(Failure::NoHandPose));
    };
    let body = ArmBody::of(world, robot, arm.clone());
    if motion.check == Check::Free && !predicted.iter().all(|(_, c)| body.clear(world, c)) {
        return Ok(Err(Failure::HandBlocked));
    }
    for (action, expected) in &predicted {
        if done(steps.env) {
            break;
        }
        attempt!(steps.act(action));
        let now = arm_now(steps.env, motion.hand);
        executed.push(now);
        if joint_action(arm.as_ref(), &now, expected, motion.gripper).is_some() {
            return Ok(Err(Failure::HandBlocked));
        }
    }
    Ok(Ok(()))
}

/// The arm's configurations that take the end effector from where it is along `offset` (base
/// frame, m) in a straight line, `step` apart, each an IK solution from the last, as far as
/// the arm gets (a torso at the bottom of its travel stops a descent to the floor); `None`
/// where not one step is reached.
fn line(arm: &dyn Arm, offset: Vector, step: f32) -> Option<Vec<ArmConfig>> {
    let mut a = arm.now();
    let from = arm.eef(&a);
    let n = (offset.length() / step).ceil().max(1.0) as usize;
    let mut out = Vec::with_capacity(n);
    for i in 1..=n {
        let mut target = from;
        target.translation += offset * (i as f32 / n as f32);
        let Some(next) = arm.ik_near(&a, &target) else {
            break;
        };
        let b = closest_turn(arm, &next, &a);
        let jumps = a.values().iter().zip(b.values());
        if jumps.into_iter().any(|(x, y)| (x - y).abs() > LINE_JUMP) {
            break;
        }
        out.push(b);
        a = b;
    }
    (!out.is_empty()).then_some(out)
}

/// The gripper straight up by `height`, m, not checked: what it takes still touches the table.
fn straight_up(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    height: f32,
    gripper: f32,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let path = arm_of(steps.env, hand)
        .and_then(|(_, _, a)| line(a.as_ref(), Vector::Z * height, LINE_STEP));
    let Some(path) = path else {
        return Ok(Err(Failure::NoHandPose));
    };
    follow(steps, hand, &path, gripper, Check::Touching, executed)
}

/// Still steps with the gripper at `gripper` (the arm's joint action moving no joint).
fn hold(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    n: u32,
    gripper: f32,
    mut done: impl FnMut(&Env) -> bool,
) -> Attempt<()> {
    let still = arm_of(steps.env, hand).and_then(|(_, _, a)| {
        let none = ArmConfig::from_fn(a.now().len(), |_| 0.0);
        a.joint_action(&a.now(), &none, gripper)
    });
    let Some(action) = still else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    for _ in 0..n {
        if done(steps.env) {
            break;
        }
        attempt!(steps.act(&action));
    }
    Ok(Ok(()))
}

fn wait(steps: &mut Stepper<'_, '_>, hand: usize, n: u32) -> Attempt<()> {
    hold(steps, hand, n, OPEN, |_| false)
}

/// On toward the object, the way the gripper points, until the palm or a finger touches it.
fn descend(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    object: ObjectId,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let path = arm_of(steps.env, hand).and_then(|(_, _, a)| {
        let ahead = a.eef(&a.now()).rotation * Vector::X;
        line(a.as_ref(), ahead * steps.tuning.arm_descent, DESCENT_STEP)
    });
    // Not a step further: the gripper closes where it is.
    let Some(path) = path else {
        return Ok(Ok(()));
    };
    let touching = |env: &Env| touches(env, hand, object);
    let motion = Motion {
        hand,
        gripper: OPEN,
        check: Check::Touching,
    };
    match follow_until(steps, motion, &path, executed, touching)? {
        // Stopped by what it is to take, or by what that lies on: the gripper closes there.
        Err(Failure::HandBlocked) => Ok(Ok(())),
        other => Ok(other),
    }
}

/// The gripper, closed, moved straight by `offset` (in the world) along [`line`], unchecked
/// (it presses on what it touches), until `done` holds; stopped by what it presses on, it
/// stays there.
fn slide(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    offset: Vector,
    executed: &mut Vec<ArmConfig>,
    done: &dyn Fn(&Env) -> bool,
) -> Attempt<()> {
    let path = steps
        .env
        .world()
        .zip(steps.env.robot())
        .and_then(|(world, robot)| {
            let (_, _, arm) = arm_of(steps.env, hand)?;
            let in_base = robot.base_pose(world).rotation.inverse() * offset;
            line(arm.as_ref(), in_base, LINE_STEP)
        });
    let Some(path) = path else {
        return Ok(Ok(()));
    };
    let motion = Motion {
        hand,
        gripper: CLOSED,
        check: Check::Touching,
    };
    match follow_until(steps, motion, &path, executed, done)? {
        Err(Failure::HandBlocked) => Ok(Ok(())),
        other => Ok(other),
    }
}

/// Closes the gripper until it holds the object; touching it and not holding it once closed,
/// forces the grasp ([`force_grasp`]).
fn close(steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
    let holds = |env: &Env| holds(env, call);
    let n = steps.tuning.close_steps;
    if hold(steps, call.hand, n, CLOSED, holds)?.is_err() || holds(steps.env) {
        return Ok(());
    }
    force_grasp(steps, call)
}

/// Opens the gripper until it holds nothing and the fingers are apart.
fn open(steps: &mut Stepper<'_, '_>, hand: usize) -> Attempt<()> {
    let n = steps.tuning.release_steps;
    hold(steps, hand, n, OPEN, |env| {
        arm_of(env, hand)
            .is_none_or(|(world, robot, a)| robot.held(hand).is_none() && a.fingers_open(world))
    })
}

/// The arm planned back to `start`, with what it now holds; where that is not free, with the
/// torso higher.
fn come_back(
    steps: &mut Stepper<'_, '_>,
    hand: usize,
    start: ArmConfig,
    gripper: f32,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    attempt!(unstick(steps, hand, gripper));
    let planned = match arm_of(steps.env, hand) {
        Some((world, robot, arm)) => {
            let body = ArmBody::of(world, robot, arm);
            let mut rng = seeded(u64::from(steps.env.steps()));
            let goal = (0..LIFTS)
                .map(|k| lifted(body.arm.as_ref(), &start, LIFT * k as f32, false))
                .find(|c| body.clear(world, c));
            match goal {
                Some(goal) => plan_arm_to(world, body, goal, steps.tuning, &mut rng),
                None => Err(Failure::NoHandPose),
            }
        }
        None => Err(Failure::Unavailable("no episode")),
    };
    match planned {
        Ok(planned) => follow(steps, hand, &planned, gripper, Check::Free, executed),
        Err(failure) => Ok(Err(failure)),
    }
}

/// Whether the gripper's palm or a finger touches the object.
fn touches(env: &Env, hand: usize, object: ObjectId) -> bool {
    arm_of(env, hand).is_some_and(|(world, _, arm)| {
        arm.gripper_bodies().into_iter().any(|part| {
            world
                .contacts()
                .of(part)
                .unwrap_or_default()
                .iter()
                .any(|c| c.other.is_some_and(|b| b.object == object))
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_robots::Fetch;
    use behavior_sim::{ObjectSpec, Part, Primitive};

    /// A candle 13.6 cm long and 4 cm across lying on its side, its axis turned `yaw` about
    /// the vertical.
    fn lying_candle(yaw: f32) -> (World, ObjectId) {
        let mut world = World::default();
        let wax = Part::new(Primitive::Cylinder {
            radius: 0.02,
            half_height: 0.068,
        });
        let mut spec = ObjectSpec::new("candle_1", "candle.n.01", vec![wax]);
        // Its own z (the cylinder's axis) laid along the floor's x, then turned by `yaw`.
        let lying = Rotation::from_rotation_z(yaw) * Rotation::from_rotation_y(FRAC_PI_2);
        spec.pose = Pose::from_parts(Vector::new(1.0, 1.0, 0.02), lying);
        let id = world.add(spec).unwrap();
        (world, id)
    }

    #[test]
    fn the_fingers_close_across_a_lying_candle_whichever_way_it_lies() {
        for yaw in [0.0, 0.7, -0.7, FRAC_PI_2, 2.4, -3.0] {
            let (world, candle) = lying_candle(yaw);
            let heading = across_heading(&world, candle);
            assert!(
                (-FRAC_PI_2..FRAC_PI_2).contains(&heading),
                "yaw {yaw}: {heading}"
            );
            // The fingers close along heading + π/2: across the candle's axis, not along it.
            let closing = heading + FRAC_PI_2;
            let along = (closing - yaw).cos().abs();
            assert!(
                along < 1e-4,
                "yaw {yaw}: the fingers close {along} along the axis"
            );
        }
    }

    #[test]
    fn a_candle_held_lying_is_set_down_standing_first() {
        let (mut world, candle) = lying_candle(0.4);
        let fetch = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        // Held as a grasp from above takes it: its axis across the fingers, along the
        // gripper's z, the gripper pointing down.
        let down = Pose::from_rotation(pointing(0.4, FRAC_PI_2));
        let grip = down.inverse() * world.bodies().pose(candle);
        let poses = held_below(&world, &fetch, 0, candle, &grip);
        let upright = |pose: &Pose| (pose.rotation * Vector::Z).z.abs() >= UPRIGHT.cos();
        // Straight down, three tilts and level: only level stands it up, and it comes first.
        assert_eq!(poses.len(), 5);
        assert!(upright(&poses[0]), "{:?}", poses[0].rotation);
        assert!(poses[1..].iter().all(|p| !upright(p)));
        // Held upright (a can taken from above), straight down stays first.
        let standing = down.inverse() * Pose::from_translation(Vector::new(1.0, 1.0, 0.1));
        let poses = held_below(&world, &fetch, 0, candle, &standing);
        // The candle's box centre lies at (1, 1) from the base: the gripper faces π/4.
        let facing = std::f32::consts::FRAC_PI_4;
        let eef = fetch.eef_pose(&world).translation;
        let straight_down = Pose::from_parts(eef, pointing(facing, FRAC_PI_2)) * standing;
        assert!(poses[0].rotation.angle_between(straight_down.rotation) < 1e-3);
        assert!(upright(&poses[0]));
    }
}
