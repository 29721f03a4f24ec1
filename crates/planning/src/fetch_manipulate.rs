//! Physical GRASP and PLACE_* for Fetch: goals for the end effector turned into joint
//! positions by Fetch's own inverse kinematics ([`behavior_robots::IkSolver`]), the arm planned
//! to them in its joint space ([`ArmSpace`]) and executed as Fetch's own end-effector actions,
//! one step of physics each; the grasp made by the assisted grasp as the gripper closes, the
//! placement by opening it above a pose the world's sampler found, then settling.
//!
//! - GRASP: the gripper pointing down at the top of the object's box, its fingers across the
//!   box's narrower side (other headings after; then tilted toward it from the base's side),
//!   the fingertips [`FETCH_APPROACH`] short of it; on until the palm or a finger touches the
//!   object (at most [`FETCH_DESCENT_STEPS`]),
//!   closed until it holds (at most [`CLOSE_STEPS`]; touching and not held, the grasp is
//!   forced as the BehaviorRobot's is), straight back up, then the arm planned back to where
//!   it was, with what it holds.
//! - PLACE_*: poses for the held object by the world's sampler (in a copy of the world where the
//!   gripper let go), the arm planned with it to [`crate::PLACE_HEIGHT`] above one, the gripper
//!   opened, [`SETTLE_STEPS`] steps to settle, straight up and back.
//!
//! Executing through an end-effector controller: each way's end-effector poses are the
//! targets, and the action asks for what the controller's gain ([`ARM_GAIN`]) turns into that
//! move in one step, within the action's range. The controller's IK pulls the arm toward its
//! rest pose in the null space, so it does not follow a joint-space plan joint for joint: every
//! way is first predicted step by step with the robot's own joint update
//! ([`Fetch::joints_after`]) and each predicted configuration checked free; only a way that
//! arrives free is executed, and the execution then is exactly the prediction.

use crate::arm::{ArmBody, ArmConfig, ArmSpace, in_workspace};
use crate::execute::RunError;
use crate::manipulate::{
    CLOSE_STEPS, GRASP_JITTER, RELEASE_STEPS, SETTLE_STEPS, grasp_point, placement_goals, rng_seed,
};
use crate::physical::{Attempt, PHYSICAL_BUDGET, Stepper, attempt, call_rng, force_grasp};
use crate::primitive::{Call, Failure};
use crate::rrt::{PlanParams, plan, steps_along};
use crate::symbolic::check;
use behavior_core::rng::{SimRng, seeded, uniform};
use behavior_env::Env;
use behavior_env::record::Recorder;
use behavior_robots::{ARM_GAIN, ActionSpace, EEF_STEP, EEF_TURN, Fetch, FetchAction, Robot};
use behavior_sim::{BodyRef, ObjectId, Relation, STEP_SECONDS, World};
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI};

/// How far above the top of the object's box the fingertips stop before the descent, m.
pub const FETCH_APPROACH: f32 = 0.05;
/// How far the fingertips reach beyond the end effector's frame along its x, m (the pads'
/// ends).
const TIP: f32 = 0.031;
/// The most steps of descent onto the object, at the controller's full speed (≈ 3 mm each).
pub const FETCH_DESCENT_STEPS: u32 = 40;
/// Headings of the fingers tried: across the box's narrower side, its other side, and these
/// many more at random.
const MORE_HEADINGS: usize = 4;
/// Steps the arm has to reach each configuration's end-effector pose before the execution is
/// given up as blocked.
const ARM_STEPS_PER_WAYPOINT: u32 = 40;
/// How close to a configuration's end-effector pose counts as passing it, m and rad; the last
/// one must be reached within [`ARRIVED`].
const PASSING: (f32, f32) = (0.01, 0.05);
const ARRIVED: (f32, f32) = (0.003, 0.02);
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
pub struct ArmPath {
    pub planned: Vec<ArmConfig>,
    pub executed: Vec<ArmConfig>,
    pub after: Vec<ArmConfig>,
}

/// GRASP with Fetch's arm and physics (see the module docs).
pub fn grasp(env: &mut Env, call: &Call, recorder: Option<&mut Recorder>) -> Attempt<ArmPath> {
    if let Err(failure) = precondition(env, call) {
        return Ok(Err(failure));
    }
    let mut rng = call_rng(env, call);
    let goals = fetch(env).map_or(Vec::new(), |(world, fetch)| {
        grasp_goals(world, fetch, call.object, &mut rng)
    });
    let mut steps = Stepper { env, recorder };
    let start = arm_now(steps.env);
    let mut path = attempt!(reach(&mut steps, &goals, OPEN, &mut rng));
    attempt!(descend(&mut steps, call.object, &mut path.after));
    close(&mut steps, call)?;
    let held = fetch(steps.env).is_some_and(|(_, f)| f.is_holding(call.object));
    let hold = if held { CLOSED } else { OPEN };
    let mut up = eef_now(steps.env);
    up.translation.z += LIFT_OFF;
    attempt!(move_to(&mut steps, &[up], hold, false, &mut path.after));
    attempt!(come_back(&mut steps, start, hold, &mut path.after));
    if !held {
        return Ok(Err(Failure::Missed));
    }
    Ok(Ok(path))
}

/// PLACE_* with Fetch's arm and physics (see the module docs).
pub fn place(
    env: &mut Env,
    call: &Call,
    relation: Relation,
    recorder: Option<&mut Recorder>,
) -> Attempt<ArmPath> {
    if let Err(failure) = precondition(env, call) {
        return Ok(Err(failure));
    }
    let mut rng = call_rng(env, call);
    let goals = match (env.world(), env.robot()) {
        (Some(world), Some(robot)) => placement_goals(world, robot, call, relation, &mut rng),
        _ => Err(Failure::Unavailable("no episode")),
    };
    let goals = match goals {
        Ok(goals) => goals,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut steps = Stepper { env, recorder };
    let start = arm_now(steps.env);
    let mut path = attempt!(reach(&mut steps, &goals, CLOSED, &mut rng));
    attempt!(open(&mut steps));
    attempt!(wait(&mut steps, SETTLE_STEPS));
    let mut up = eef_now(steps.env);
    up.translation.z += LEAVE;
    attempt!(move_to(&mut steps, &[up], OPEN, false, &mut path.after));
    attempt!(come_back(&mut steps, start, OPEN, &mut path.after));
    Ok(Ok(path))
}

/// Whether Fetch's arm, from where the base stands, has a free configuration over the object
/// for a grasp — or, holding something and given a placement, above a place for it; true for
/// what cannot be held (a cabinet to open) and for a robot that is no Fetch.
pub(crate) fn reaches(env: &Env, object: ObjectId, placement: Option<&Call>) -> bool {
    let (Some((world, fetch)), Some(robot)) = (fetch(env), env.robot()) else {
        return true;
    };
    let goals = match placement.and_then(|c| Some((c, c.primitive.relation()?))) {
        Some((call, relation)) if fetch.holding().is_some() => {
            let mut rng = call_rng(env, call);
            placement_goals(world, robot, call, relation, &mut rng).unwrap_or_default()
        }
        // Nothing to take (a cabinet to open): within reach of its box is enough.
        _ if fetch
            .rules()
            .holdable(world, BodyRef::from(object))
            .is_none() =>
        {
            return true;
        }
        _ => {
            let call = Call {
                primitive: crate::Primitive::Grasp,
                object,
                hand: 0,
            };
            grasp_goals(world, fetch, object, &mut call_rng(env, &call))
        }
    };
    let body = ArmBody::of(world, fetch);
    goals
        .iter()
        .any(|g| solve(world, fetch, &body, g).is_some())
}

/// The gripper's commands: open, or closed on what it holds.
const OPEN: f32 = 1.0;
const CLOSED: f32 = -1.0;

/// The primitive's preconditions, and that the robot is a Fetch driven through its full
/// action space with its one hand.
fn precondition(env: &Env, call: &Call) -> Result<(), Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    if robot.space() != ActionSpace::Full {
        return Err(Failure::Unavailable(
            "physical primitives drive the full action space",
        ));
    }
    if call.hand != 0 {
        return Err(Failure::NoHand(call.hand));
    }
    check(world, robot, call)
}

/// The episode's world and Fetch.
fn fetch(env: &Env) -> Option<(&World, &Fetch)> {
    match (env.world(), env.robot()) {
        (Some(world), Some(Robot::Fetch(fetch, ActionSpace::Full))) => Some((world, fetch)),
        _ => None,
    }
}

/// End-effector poses in the world over the object, best first, the gripper pointing at the
/// top of its box (near its end nearest the base, for a long one), jittered, the fingertips
/// [`FETCH_APPROACH`] short of it: straight down, the fingers closing across the box's narrower
/// side, then the other, then at random headings; then tilted by each of [`PITCHES`] from the
/// base's side (straight down, a hamburger 0.98 m ahead had no IK solution within 0.27 m).
fn grasp_goals(world: &World, fetch: &Fetch, object: ObjectId, rng: &mut SimRng) -> Vec<Pose> {
    let base = fetch.base_pose(world).translation;
    let at = grasp_point(world, object, base);
    let b = world.aabb(object);
    let size = b.maxs - b.mins;
    // The fingers close along the end effector's y: heading −π/2 closes them along x.
    let across = if size.x <= size.y { -FRAC_PI_2 } else { 0.0 };
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
                at.x + uniform(rng, -GRASP_JITTER, GRASP_JITTER),
                at.y + uniform(rng, -GRASP_JITTER, GRASP_JITTER),
                at.z,
            );
            let back = rotation * Vector::X * (FETCH_APPROACH + TIP);
            Pose::from_parts(target - back, rotation)
        })
        .collect()
}

/// Pitches below the floor of the tilted approaches, rad, steepest first.
const PITCHES: [f32; 3] = [PI / 3.0, PI / 4.0, PI / 6.0];

/// The end effector's rotation pointing `pitch` below the floor (its x) toward the floor's
/// direction `heading`, its fingers closing level.
fn pointing(heading: f32, pitch: f32) -> Rotation {
    Rotation::from_rotation_z(heading) * Rotation::from_rotation_y(pitch)
}

/// The arm's free configuration that puts the end effector at `goal` (in the world), by IK
/// from where the arm is.
fn solve(world: &World, fetch: &Fetch, body: &ArmBody, goal: &Pose) -> Option<ArmConfig> {
    let local = body.base.inverse() * *goal;
    if !in_workspace(local.translation) {
        return None;
    }
    let joints = fetch.ik().solve(&fetch.joints(), &local).ok()?;
    let c = ArmConfig::of(&joints);
    body.clear(world, &c).then_some(c)
}

/// Fetch's arm folded over its base before it drives, as the real robot's `tuck_arm` folds
/// it (reference: robots §1.6, iGibson's tucked joints), the torso where it is: unfolded, the
/// BEHAVIOR start pose holds the gripper 0.55 m ahead at a counter's height, and every stand
/// found with it left a hamburger on a counter 0.9 m from the base. Planned with what the gripper holds; where no plan
/// gets there, the arm stays.
pub(crate) fn tuck(steps: &mut Stepper<'_>) -> Attempt<()> {
    let Some((world, fetch)) = fetch(steps.env) else {
        return Ok(Ok(()));
    };
    let mut tucked = ArmConfig::of(&fetch.joints());
    tucked.0[1..].copy_from_slice(&TUCKED);
    // The controller gets the gripper there, not every joint.
    let there = tucked.joints(fetch.joints().head).eef().translation;
    if (fetch.joints().eef().translation - there).length() <= TUCK_TOLERANCE {
        return Ok(Ok(()));
    }
    let body = ArmBody::of(world, fetch);
    let mut rng = seeded(u64::from(steps.env.steps()));
    let gripper = if fetch.holding().is_some() {
        CLOSED
    } else {
        OPEN
    };
    let Ok(planned) = plan_arm_to(world, fetch, body, tucked, &mut rng) else {
        return Ok(Ok(()));
    };
    let targets = eef_targets(steps.env, &planned);
    move_to(steps, &targets, gripper, true, &mut Vec::new())
}

/// How near its tucked place the gripper counts as tucked, m.
const TUCK_TOLERANCE: f32 = 0.05;
/// iGibson's tucked arm joints (robots reference §1.6).
const TUCKED: [f32; 7] = [1.1708, 1.4708, -0.4, 1.6708, 0.0, FRAC_PI_2, 0.0];

/// The arm taken to the first of `goals` (in the world) with a free IK solution that one of
/// its ways gets to, the gripper held at `gripper`: straight (as the controller moves), by a
/// point [`OVER`] above the goal, or along a plan in the arm's joint space — each predicted as
/// the controller will execute it and checked free ([`prepare`]). Stopped on the way, the arm
/// is brought back.
fn reach(
    steps: &mut Stepper<'_>,
    goals: &[Pose],
    gripper: f32,
    rng: &mut SimRng,
) -> Attempt<ArmPath> {
    let start = arm_now(steps.env);
    let mut last = Failure::NoHandPose;
    let mut tried = 0;
    for goal in goals {
        let Some((world, fetch)) = fetch(steps.env) else {
            return Ok(Err(Failure::Unavailable("no episode")));
        };
        let body = ArmBody::of(world, fetch);
        let Some(config) = solve(world, fetch, &body, goal) else {
            continue;
        };
        if tried == GOAL_TRIES {
            break;
        }
        tried += 1;
        let local = body.base.inverse() * *goal;
        let mut over = local;
        over.translation.z += OVER;
        let mut ways = vec![vec![local], vec![over, local]];
        let planned = plan_arm_to(world, fetch, body, config, rng);
        if let Ok(planned) = &planned {
            ways.push(eef_targets(steps.env, planned));
        }
        let Some((targets, actions)) = ways.into_iter().find_map(|targets| {
            let actions = prepare(steps.env, &targets, gripper, true)?;
            Some((targets, actions))
        }) else {
            // No way is followed free: the plan's failure if there was none, else the block.
            last = planned.err().unwrap_or(Failure::HandBlocked);
            continue;
        };
        let mut path = ArmPath {
            planned: vec![start, config],
            ..ArmPath::default()
        };
        let end = targets.last().copied().unwrap_or(local);
        if let Err(failure) = execute(steps, &actions, &end, &mut path.executed)? {
            // Best effort: an arm left out would be in the base's way.
            let _ = come_back(steps, start, gripper, &mut path.after)?;
            return Ok(Err(failure));
        }
        return Ok(Ok(path));
    }
    Ok(Err(last))
}

/// Goals with a free IK solution tried before the arm gives up.
const GOAL_TRIES: usize = 4;
/// How far above its goal the end effector's second way passes, m.
const OVER: f32 = 0.15;

/// A planned arm path, densified, from where the arm is to `goal`.
fn plan_arm_to(
    world: &World,
    fetch: &Fetch,
    body: ArmBody,
    goal: ArmConfig,
    rng: &mut SimRng,
) -> Result<Vec<ArmConfig>, Failure> {
    let start = ArmConfig::of(&fetch.joints());
    let space = ArmSpace::new(world, body, &start);
    let params = PlanParams {
        seed: rng_seed(rng),
        ..PHYSICAL_BUDGET
    };
    let planned = plan(&space, &start, &goal, &params)?;
    let mut dense = vec![start];
    dense.extend(steps_along(&space, &planned.path));
    Ok(dense)
}

/// The end effector's poses in the base frame along a planned path, after its start: the
/// targets the controller is given.
fn eef_targets(env: &Env, planned: &[ArmConfig]) -> Vec<Pose> {
    let head = fetch(env).map_or([0.0; 2], |(_, f)| f.joints().head);
    planned
        .iter()
        .skip(1)
        .map(|c| c.joints(head).eef())
        .collect()
}

/// The end effector's pose in the base frame now.
fn eef_now(env: &Env) -> Pose {
    fetch(env).map_or(Pose::IDENTITY, |(_, f)| f.joints().eef())
}

/// The arm's configuration now.
fn arm_now(env: &Env) -> ArmConfig {
    fetch(env).map_or(ArmConfig([0.0; 8]), |(_, f)| ArmConfig::of(&f.joints()))
}

/// The action that moves the end effector from `now` toward `target` (both in the base frame)
/// as far as one step allows, the gripper at `gripper`; `None` within `tolerance`.
fn arm_action(now: &Pose, target: &Pose, gripper: f32, tolerance: (f32, f32)) -> Option<Vec<f32>> {
    let dp = target.translation - now.translation;
    let mut turn = target.rotation * now.rotation.inverse();
    if turn.w < 0.0 {
        turn = -turn;
    }
    let dr = turn.to_scaled_axis();
    if dp.length() <= tolerance.0 && dr.length() <= tolerance.1 {
        return None;
    }
    // The joints close a fraction ARM_GAIN · dt of the way to the IK solution each step: ask
    // for the move divided by it.
    let boost = 1.0 / (ARM_GAIN * STEP_SECONDS);
    let mut action = vec![0.0; behavior_robots::FETCH_ACTION_DIM];
    for k in 0..3 {
        action[FetchAction::EEF_POSITION.start + k] = (dp[k] * boost / EEF_STEP).clamp(-1.0, 1.0);
        action[FetchAction::EEF_ROTATION.start + k] = (dr[k] * boost / EEF_TURN).clamp(-1.0, 1.0);
    }
    action[FetchAction::GRIPPER] = gripper;
    Some(action)
}

/// The steps the controller needs at full speed to take the end effector from `now` to
/// `target`: it moves a fraction [`ARM_GAIN`]` · dt` of the action's range a step.
fn steps_to(now: &Pose, target: &Pose) -> u32 {
    let rate = ARM_GAIN * STEP_SECONDS;
    let far = (target.translation - now.translation).length() / (EEF_STEP * rate);
    let turn = target.rotation.angle_between(now.rotation) / (EEF_TURN * rate);
    far.max(turn).ceil() as u32
}

/// The actions that take the end effector through `targets` (base frame), the last one
/// closely, and the arm's configuration after each, as Fetch's controller will move it
/// ([`Fetch::joints_after`]); `None` where the controller does not get there.
fn predict(
    fetch: &Fetch,
    targets: &[Pose],
    gripper: f32,
) -> Option<(Vec<Vec<f32>>, Vec<ArmConfig>)> {
    let mut joints = fetch.joints();
    let (mut actions, mut configs) = (Vec::new(), Vec::new());
    for (k, target) in targets.iter().enumerate() {
        let tolerance = if k + 1 == targets.len() {
            ARRIVED
        } else {
            PASSING
        };
        let mut there = false;
        for _ in 0..ARM_STEPS_PER_WAYPOINT + steps_to(&joints.eef(), target) {
            let Some(action) = arm_action(&joints.eef(), target, gripper, tolerance) else {
                there = true;
                break;
            };
            joints = fetch.joints_after(&joints, &FetchAction::new(&action).ok()?);
            actions.push(action);
            configs.push(ArmConfig::of(&joints));
        }
        if !there && arm_action(&joints.eef(), target, gripper, tolerance).is_some() {
            return None;
        }
    }
    Some((actions, configs))
}

/// The actions that take the end effector through `targets` (base frame), the controller's
/// motion predicted ([`predict`]) and, if `checked`, every configuration of it free with what
/// the gripper holds: the arm's plan re-validated as it will be executed, a step (at most
/// 0.04 rad a joint) apart. `None` where the controller does not get there or hits something.
fn prepare(env: &Env, targets: &[Pose], gripper: f32, checked: bool) -> Option<Vec<Vec<f32>>> {
    let (world, fetch) = fetch(env)?;
    let (actions, configs) = predict(fetch, targets, gripper)?;
    let body = ArmBody::of(world, fetch);
    let free = !checked || configs.iter().all(|c| body.clear(world, c));
    free.then_some(actions)
}

/// Takes `actions`; the arm's configuration after each goes to `executed`. Stopped short of
/// `last` (base frame), the hand was blocked.
fn execute(
    steps: &mut Stepper<'_>,
    actions: &[Vec<f32>],
    last: &Pose,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let gripper = actions.first().map_or(OPEN, |a| a[FetchAction::GRIPPER]);
    for action in actions {
        attempt!(steps.act(action));
        executed.push(arm_now(steps.env));
    }
    if arm_action(&eef_now(steps.env), last, gripper, ARRIVED).is_some() {
        return Ok(Err(Failure::HandBlocked));
    }
    Ok(Ok(()))
}

/// The end effector taken through `targets` (base frame), [`prepare`]d and executed. A lift
/// off a table is not `checked`: what the gripper takes still touches it.
fn move_to(
    steps: &mut Stepper<'_>,
    targets: &[Pose],
    gripper: f32,
    checked: bool,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let (Some(actions), Some(last)) = (
        prepare(steps.env, targets, gripper, checked),
        targets.last(),
    ) else {
        return Ok(Err(Failure::HandBlocked));
    };
    execute(steps, &actions, last, executed)
}

/// Still steps with the gripper at `gripper` (a still Fetch action closes it).
fn hold(
    steps: &mut Stepper<'_>,
    n: u32,
    gripper: f32,
    mut done: impl FnMut(&Env) -> bool,
) -> Attempt<()> {
    let mut action = vec![0.0; behavior_robots::FETCH_ACTION_DIM];
    action[FetchAction::GRIPPER] = gripper;
    for _ in 0..n {
        if done(steps.env) {
            break;
        }
        attempt!(steps.act(&action));
    }
    Ok(Ok(()))
}

fn wait(steps: &mut Stepper<'_>, n: u32) -> Attempt<()> {
    hold(steps, n, OPEN, |_| false)
}

/// On toward the object, the way the gripper points, until the palm or a finger touches it.
fn descend(
    steps: &mut Stepper<'_>,
    object: ObjectId,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    for _ in 0..FETCH_DESCENT_STEPS {
        if touches(steps.env, object) {
            break;
        }
        let ahead = eef_now(steps.env).rotation * Vector::X;
        let mut action = vec![0.0; behavior_robots::FETCH_ACTION_DIM];
        for k in 0..3 {
            action[FetchAction::EEF_POSITION.start + k] = ahead[k];
        }
        action[FetchAction::GRIPPER] = OPEN;
        attempt!(steps.act(&action));
        executed.push(arm_now(steps.env));
    }
    Ok(Ok(()))
}

/// Closes the gripper until it holds the object; touching it and not holding it once closed,
/// forces the grasp ([`force_grasp`]).
fn close(steps: &mut Stepper<'_>, call: &Call) -> Result<(), RunError> {
    let holds = |env: &Env| fetch(env).is_some_and(|(_, f)| f.is_holding(call.object));
    if hold(steps, CLOSE_STEPS, CLOSED, holds)?.is_err() || holds(steps.env) {
        return Ok(());
    }
    force_grasp(steps, call)
}

/// Opens the gripper until it holds nothing and the fingers are apart.
fn open(steps: &mut Stepper<'_>) -> Attempt<()> {
    hold(steps, RELEASE_STEPS, OPEN, |env| {
        fetch(env).is_none_or(|(world, f)| {
            let [a, b] = f.fingers(world);
            f.holding().is_none() && a.min(b) >= 0.9 * behavior_robots::FINGER_OPEN
        })
    })
}

/// The arm planned back to `start`, with what it now holds; where that is not free, with the
/// torso higher.
fn come_back(
    steps: &mut Stepper<'_>,
    start: ArmConfig,
    gripper: f32,
    executed: &mut Vec<ArmConfig>,
) -> Attempt<()> {
    let planned = match fetch(steps.env) {
        Some((world, fetch)) => {
            let body = ArmBody::of(world, fetch);
            let mut rng = seeded(u64::from(steps.env.steps()));
            let goal = (0..LIFTS)
                .map(|k| {
                    let mut c = start;
                    c.0[0] += LIFT * k as f32;
                    c
                })
                .find(|c| body.clear(world, c));
            match goal {
                Some(goal) => plan_arm_to(world, fetch, body, goal, &mut rng),
                None => Err(Failure::NoHandPose),
            }
        }
        None => Err(Failure::Unavailable("no episode")),
    };
    let planned = match planned {
        Ok(planned) => planned,
        Err(failure) => return Ok(Err(failure)),
    };
    let targets = eef_targets(steps.env, &planned);
    move_to(steps, &targets, gripper, true, executed)
}

/// Whether the gripper's palm or a finger touches the object.
fn touches(env: &Env, object: ObjectId) -> bool {
    fetch(env).is_some_and(|(world, fetch)| {
        fetch.parts().gripper_bodies().into_iter().any(|part| {
            world
                .core()
                .contacts(part)
                .unwrap_or_default()
                .iter()
                .any(|c| c.other.is_some_and(|b| b.object == object))
        })
    })
}
