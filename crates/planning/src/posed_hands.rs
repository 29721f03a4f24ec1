//! Physical GRASP and PLACE_* for hands posed directly ([`behavior_robots::HandMotion::Posed`]:
//! the BehaviorRobot's) (the paper's fully simulated primitives,
//! iGibson 2.0.3's `envs/behavior_mp_env.py`): the hand's motion planned in [`HandSpace`] and
//! executed as the robot's own hand actions, one step of physics each; the grasp made by the
//! assisted grasp as the trigger closes, the placement by letting go above a pose the world's
//! sampler found, then settling.
//!
//! - GRASP: palm down over the top of the object's box ([`APPROACH_HEIGHT`] above it, ±
//!   [`GRASP_JITTER`], a random heading), down in steps of [`DESCENT_STEP`] until the hand
//!   touches it (at most [`DESCENT_STEPS`]), the trigger pressed until it holds (at most
//!   [`CLOSE_STEPS`]), then back to where the hand was — raised if what it now carries would
//!   not fit there.
//! - PLACE_*: poses for the held object by the world's sampler ([`PLACE_TRIES`], in a copy of
//!   the world, so that the episode itself only ever moves by actions), the hand planned with
//!   the object to [`PLACE_HEIGHT`] above one, the trigger let go, [`SETTLE_STEPS`] steps for it
//!   to fall and settle, then the hand back.
//! - Where the hand cannot reach its goal from the shoulder, the body goes down (at most
//!   [`CROUCH`]) or up ([`RISE`]) first, and back after.
//!
//! - The hand is planned to a little above its goal, or in front of it, and comes straight in;
//!   it backs out the same way after ([`plan_with_approach`], [`back_out`]).
//!
//! Where we differ: the original retracts along the reversed approach, we back out of the
//! last straight stretch and then plan the way back with what the hand now carries (a carton lifted
//! off a table, retraced, drags through the table's edge); it forces the assisted grasp after
//! closing if the hand touches the object, we report the miss; after placing, the original leaves
//! the hand where it let go, ours comes back, so that the next NAVIGATE_TO finds the robot as
//! compact as it started.

use crate::execute::Watcher;
use crate::execute::{RecordedCall, RunError};
use crate::manipulation::{
    CLOSE_STEPS, GRASP_JITTER, Manipulator, RELEASE_STEPS, SETTLE_STEPS, StandTest, grasp_point,
    on_or_in_goals, on_top, placement_goals, rng_seed,
};
use crate::physical::{
    Attempt, PHYSICAL_BUDGET, STEPS_PER_WAYPOINT, Stepper, attempt, base_config, call_rng,
    force_grasp,
};
use crate::primitive::{Call, Failure};
use crate::symbolic::check;
use behavior_core::rng::{SimRng, uniform};
use behavior_env::Env;
use behavior_motion::BaseConfig;
use behavior_motion::shapes_in;
use behavior_motion::{HandBody, HandConfig, HandSpace};
use behavior_motion::{PlanParams, plan, steps_along};
use behavior_robots::{ACTION_SCALE, Action, ActionSpace, BehaviorRobot, HAND_REACH, Robot, Side};
use behavior_sim::{BodyRef, ObjectId, QueryFilter, Relation, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::PI;

/// How a recording names a hand put back at its target (see `free_stranded`).
pub const HAND_RESET: &str = "reset_hand";
/// A palm this far from its target is pinned, not trailing, m (it trails by about a step,
/// ≤ 0.05 m).
const STRANDED: f32 = 0.1;
/// How far above the top of the object's box the grasp's approach ends, m (the original's).
pub const APPROACH_HEIGHT: f32 = 0.05;
/// How much higher the approach is tried where fingers at [`APPROACH_HEIGHT`] would touch
/// something, m, in turn: a tilted tile's edge is cleared by the second; the higher ones are
/// for an object low among others or in an open box, where a column the hand can come down
/// clear of all but the object leads to it ([`clear_column`]). The descent grows by the raise.
const APPROACH_RAISES: [f32; 5] = [0.0, 0.05, 0.15, 0.25, 0.35];
/// How far apart the poses checked down a raised approach's column are, m.
const COLUMN_STEP: f32 = 0.025;
/// How far the body may go down to reach low things, m: its capsule's bottom is 0.2 m above
/// the floor at the original's standing height ([`behavior_robots::BODY_HEIGHT`]).
pub const CROUCH: f32 = 0.19;
/// Room left within a hand's reach for the grasp's jitter and the hand's own size, m.
const REACH_MARGIN: f32 = 0.05;
/// Room left within a hand's reach for a goal, m: the path to it may bend outward.
const REACH_SLACK: f32 = 0.02;
/// How far the body may go up to reach high things, m (the BehaviorRobot's body floats; a
/// person in VR stands up or stretches).
pub const RISE: f32 = 0.4;
/// Headings tried for the approach until one is free and within reach.
pub const GRASP_HEADINGS: usize = 8;
/// Free goals (at the body height of the first) that the hand is planned to in turn, until a
/// plan is found: a free goal may have no way to it (the last folder into a file cabinet had
/// none on four seeds).
const GOALS_PLANNED: usize = 3;
/// How far above a grasp's approach or a placement the hand is planned to, m, best first,
/// before it comes straight down (see [`plan_with_approach`]).
const PRE_ABOVE: [f32; 2] = [0.1, 0.05];
/// How far toward the shoulder (across the floor) from a grasp's approach or a placement the
/// hand is planned to, m, best first, where it cannot come from above, before it goes straight
/// in (see [`plan_with_approach`]).
const PRE_FRONT: [f32; 3] = [0.3, 0.2, 0.1];
/// One step of the descent onto the object, m.
pub const DESCENT_STEP: f32 = 0.005;
/// The most steps of descent from [`APPROACH_HEIGHT`] (the original's 25), more from a raised
/// approach (see `APPROACH_RAISES`).
pub const DESCENT_STEPS: u32 = 25;
/// Raises of the way-back pose tried when what the hand carries would not fit where it
/// started, m each.
const RAISE: f32 = 0.1;
const RAISES: usize = 7;
/// The point of the hand put over the object: under the fingers' roots on the palm's inner
/// face, where closing fingers wrap (see `behavior-robots`' hand frame).
const GRASP_POINT: Vector = Vector::new(0.04, 0.0, -0.015);
/// A hand target this close to a configuration counts as there, m or rad.
const TARGET_TOLERANCE: f32 = 1e-4;
/// A palm this close to its target has arrived, m.
const ARRIVED: f32 = 0.005;
/// Still steps the palm gets to arrive at the end of a motion.
const ARRIVAL_STEPS: u32 = 30;

/// A hand's motion: the configurations planned (to over the object, or to above the
/// placement) and the palm's poses as that plan was executed, step by step; then its poses
/// in contact and on the way back (the descent, the lift, the return).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HandPath {
    /// The configurations planned.
    pub planned: Vec<HandConfig>,
    /// The palm's poses as they were executed, a step each.
    pub executed: Vec<Pose>,
    /// The palm's poses after: in contact and on the way back.
    pub after: Vec<Pose>,
}

/// GRASP with physics (see the module docs). The paths it planned and executed come back.
pub fn grasp(env: &mut Env, call: &Call, watcher: Option<&mut dyn Watcher>) -> Attempt<HandPath> {
    let side = match hand_side(env, call) {
        Ok(side) => side,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut rng = call_rng(env, call);
    let goals = match behavior_robot(env) {
        Some((world, robot)) => approach_goals(world, robot, call, side, &mut rng),
        None => Vec::new(),
    };
    let mut steps = Stepper { env, watcher };
    let mut reached = attempt!(reach(&mut steps, side, &goals, &mut rng));
    attempt!(descend(
        &mut steps,
        side,
        call.object,
        &mut reached.path.after
    ));
    close(&mut steps, call)?;
    let held = holds(steps.env, side, call.object);
    if !held {
        attempt!(open(&mut steps, side));
    }
    // Straight back up as high as the approach ended, turned as the palm now is (what it
    // holds keeps its pose), lifting it off its support.
    let mut up = palm(steps.env, side);
    let top = reached.path.planned.last().map(|c| c.position.z);
    up.translation.z = top.unwrap_or(up.translation.z);
    let up = HandConfig::of(&up);
    attempt!(follow(&mut steps, side, &[up, up], &mut reached.path.after));
    attempt!(retreat(&mut steps, side, &mut reached));
    if !held {
        return Ok(Err(Failure::Missed));
    }
    Ok(Ok(reached.path))
}

/// PLACE_* with physics (see the module docs).
pub fn place(
    env: &mut Env,
    call: &Call,
    relation: Relation,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<HandPath> {
    let side = match hand_side(env, call) {
        Ok(side) => side,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut rng = call_rng(env, call);
    let goals = match (env.world(), env.robot()) {
        (Some(world), Some(robot)) => placement_goals(world, robot, call, relation, &mut rng),
        _ => Err(Failure::Unavailable("no episode")),
    };
    let goals = match goals {
        Ok(goals) => goals,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut steps = Stepper { env, watcher };
    let mut reached = attempt!(reach(&mut steps, side, &goals, &mut rng));
    attempt!(open(&mut steps, side));
    attempt!(steps.wait_until(SETTLE_STEPS, |_| false));
    attempt!(retreat(&mut steps, side, &mut reached));
    Ok(Ok(reached.path))
}

/// The hand's plan to over `call.object` for a GRASP from where the robot stands, as the
/// physical primitive makes it (without moving the body: a goal out of reach at the body's
/// height counts as none). For measuring the planner (`behavior bench plan --hands`).
pub fn approach_plan(env: &Env, call: &Call) -> Result<Vec<HandConfig>, Failure> {
    let side = hand_side(env, call)?;
    let (world, robot) = behavior_robot(env).ok_or(Failure::Unavailable("no episode"))?;
    let mut rng = call_rng(env, call);
    let goals = approach_goals(world, robot, call, side, &mut rng);
    plan_hand(world, robot, side, goals, rng_seed(&mut rng))
}

/// Whether a hand holding something reaches, its body down or up if need be, above one of the
/// places the world's sampler finds for it by `call` (a PLACE_*), drawing the numbers the
/// placement itself will; true where the call is no physical BehaviorRobot placement or the
/// hand is empty (the primitive then says why it cannot).
pub(crate) fn placement_in_reach(env: &Env, call: &Call) -> bool {
    let (Some((world, robot)), Some(relation), Some(&side)) = (
        behavior_robot(env),
        call.primitive.relation(),
        Side::BOTH.get(call.hand),
    ) else {
        return true;
    };
    if robot.holding(side).is_none() {
        return true;
    }
    let shoulder = robot.shoulder(world, side);
    let (Some(embodied), mut rng) = (env.robot(), call_rng(env, call)) else {
        return true;
    };
    placement_goals(world, embodied, call, relation, &mut rng)
        .is_ok_and(|goals| places_from(world, robot, &goals, shoulder))
}

/// Where a BehaviorRobot's hands go before it drives, in the body frame: drawn in so that
/// palm and fingers lie within the body's capsule (at rest the fingertips stick out 2 cm, and a
/// door leaf the body pushes open caught them and left both palms behind at a doorway).
fn tucked(side: Side) -> Pose {
    let y = match side {
        Side::Left => 0.1,
        Side::Right => -0.1,
    };
    Pose::from_translation(Vector::new(-0.02, y, 0.05))
}

/// Draws a BehaviorRobot's hands in to [`tucked`] poses, with what they hold (nothing for Fetch,
/// or for hands already there), each along a straight line. Tucking only empty hands did worse:
/// summed Q over the 12 Table 1 activities and seeds 0–2, 6.7 against 8.9.
pub(crate) fn tuck(steps: &mut Stepper<'_, '_>) -> Attempt<()> {
    for side in Side::BOTH {
        let Some((world, robot)) = behavior_robot(steps.env) else {
            return Ok(Ok(()));
        };
        let tuck = robot.body_pose(world) * tucked(side);
        let (goal, here) = (HandConfig::of(&tuck), target_in_world(steps.env, side));
        if HandConfig::of(&here) == goal {
            continue;
        }
        // Straight in where that is free, else planned (a hand left over a high shelf board
        // would be carried into it).
        let body = planning_body(world, robot, side);
        let line = straight(&HandConfig::of(&here), &goal);
        let direct = vec![HandConfig::of(&here), goal];
        let path = if line.iter().all(|c| body.clear(world, c)) {
            direct
        } else {
            let seed = u64::from(steps.env.steps());
            plan_hand(world, robot, side, [tuck], seed).unwrap_or(direct)
        };
        let mut poses = Vec::new();
        attempt!(follow(steps, side, &path, &mut poses));
    }
    free_stranded(steps)?;
    Ok(Ok(()))
}

/// Puts back at its target, at once, each palm its servo left more than [`STRANDED`] behind
/// (pinned behind furniture the body moved past: 300 N cannot pull it through), as the
/// original robot's reset entry does; recorded as an edit, [`HAND_RESET`], for replays.
fn free_stranded(steps: &mut Stepper<'_, '_>) -> Result<(), RunError> {
    for side in Side::BOTH {
        let behind = behavior_robot(steps.env).map_or(0.0, |(world, robot)| {
            let target = robot.body_pose(world) * robot.hand_target(side);
            (robot.hand_pose(world, side).translation - target.translation).length()
        });
        if behind <= STRANDED {
            continue;
        }
        let hand = side.index();
        let reset = steps
            .env
            .edit(|edit| edit.robot.reset_hand(edit.world, hand).is_ok())?;
        if reset {
            steps.record_edit(&RecordedCall {
                primitive: HAND_RESET.to_string(),
                object: String::new(),
                hand,
            })?;
        }
    }
    Ok(())
}

/// Where a physical primitive's hand got to: how far the body went down for it (up, if
/// negative), where the hand was told to be before, and the path.
struct Reached {
    depth: f32,
    start: Pose,
    path: HandPath,
    /// The way the hand came straight in at the end, reversed (see [`plan_with_approach`]).
    exit: Option<Vector>,
}

/// The hand taken along a plan to the first of `goals` it can reach (the body down or up
/// first if need be, [`choose_goals`]), the next tried where no plan is found. On failure the
/// hand and the body are brought back.
fn reach(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    goals: &[Pose],
    rng: &mut SimRng,
) -> Attempt<Reached> {
    free_stranded(steps)?;
    let Some((world, robot)) = behavior_robot(steps.env) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let Some((chosen, depth)) = choose_goals(world, robot, side, goals) else {
        return Ok(Err(Failure::NoHandPose));
    };
    attempt!(crouch(steps, depth));
    let start = target_in_world(steps.env, side);
    let mut planned = Err(Failure::NoHandPose);
    for goal in chosen {
        planned = match behavior_robot(steps.env) {
            Some((world, robot)) => plan_with_approach(world, robot, side, goal, rng_seed(rng)),
            None => Err(Failure::Unavailable("no episode")),
        };
        if planned.is_ok() {
            break;
        }
    }
    let (planned, exit) = match planned {
        Ok(planned) => planned,
        Err(failure) => {
            attempt!(crouch(steps, -depth));
            return Ok(Err(failure));
        }
    };
    let mut reached = Reached {
        depth,
        start,
        path: HandPath {
            planned: planned.clone(),
            executed: Vec::new(),
            after: Vec::new(),
        },
        exit,
    };
    if let Err(failure) = follow(steps, side, &planned, &mut reached.path.executed)? {
        let _ = retreat(steps, side, &mut reached)?;
        return Ok(Err(failure));
    }
    Ok(Ok(reached))
}

/// The hand back where it was told to be before the primitive, the body at its height (even
/// where the hand could not come back).
fn retreat(steps: &mut Stepper<'_, '_>, side: Side, reached: &mut Reached) -> Attempt<()> {
    if let Some(exit) = reached.exit {
        back_out(steps, side, exit, &mut reached.path.after)?;
    }
    let back = come_back(steps, side, reached.start, &mut reached.path.after)?;
    let up = crouch(steps, -reached.depth)?;
    Ok(back.and(up))
}

/// The hand a call uses, checked with the primitive's preconditions.
fn hand_side(env: &Env, call: &Call) -> Result<Side, Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    if robot.space() != ActionSpace::Full {
        return Err(Failure::Unavailable(
            "physical primitives drive the full action space",
        ));
    }
    check(world, robot, call)?;
    Side::BOTH
        .get(call.hand)
        .copied()
        .ok_or(Failure::NoHand(call.hand))
}

/// The episode's world and BehaviorRobot, if it drives one through the full action space (the
/// hand actions here are that space's).
fn behavior_robot(env: &Env) -> Option<(&World, &BehaviorRobot)> {
    match (env.world(), env.robot()) {
        (Some(world), Some(Robot::Behavior(robot, ActionSpace::Full))) => Some((world, robot)),
        _ => None,
    }
}

/// Where the hand is told to be, in the world.
fn target_in_world(env: &Env, side: Side) -> Pose {
    behavior_robot(env).map_or(Pose::IDENTITY, |(world, robot)| {
        robot.body_pose(world) * robot.hand_target(side)
    })
}

/// The hand and what it holds as the planner moves them, ignoring the robot and what it holds.
pub fn hand_body(world: &World, robot: &BehaviorRobot, side: Side) -> HandBody {
    let hand = robot.parts().hand(side);
    let held = robot.holding(side).map(|b| b.object);
    let frame = world.pose(hand).inverse();
    let mut ignored = robot.parts().all().to_vec();
    ignored.extend(
        Side::BOTH
            .iter()
            .filter_map(|&s| robot.holding(s).map(|b| b.object)),
    );
    HandBody {
        shapes: shapes_in(world, std::iter::once(hand).chain(held), frame),
        filter: QueryFilter::excluding(&ignored),
        shoulder: robot.shoulder(world, side),
        reach: HAND_REACH,
    }
}

/// The hand as planned: [`hand_body`] with the palm's straight-fingered box, which the robot
/// keeps out of fixed bodies by refusing the hand's target there (a plan clear of it only
/// would stop the hand on its way, at a countertop's edge).
fn planning_body(world: &World, robot: &BehaviorRobot, side: Side) -> HandBody {
    let mut body = hand_body(world, robot, side);
    body.shapes.push(behavior_robots::sweep_shape());
    body
}

/// Whether a hand of the robot, its body down or up if need be, reaches the nearest point of the
/// object's box within its reach less `REACH_MARGIN` (for a small object, over it; for a
/// shelf, its near side), and the top of the box there lies `open_to` the shoulder (a
/// necklace in a cabinet is not in reach from beside the cabinet).
pub fn hand_reaches(world: &World, robot: &Robot, object: ObjectId) -> bool {
    let Robot::Behavior(robot, _) = robot else {
        return true;
    };
    Side::BOTH
        .iter()
        .any(|&side| reaches_from(world, robot, object, robot.shoulder(world, side)))
}

/// [`hand_reaches`] for one shoulder, wherever it is.
fn reaches_from(world: &World, robot: &BehaviorRobot, object: ObjectId, shoulder: Vector) -> bool {
    let b = world.aabb(object);
    let top = on_top(world, object, shoulder, 0.0);
    let nearest = top.with_z(shoulder.z.clamp(b.mins.z, b.maxs.z));
    shift_for(shoulder, nearest, HAND_REACH - REACH_MARGIN).is_some()
        && open_to(world, robot, top, shoulder, &[object])
}

/// Whether a shoulder at `shoulder` reaches above one of the placement `goals` as
/// [`placement_in_reach`] asks.
fn places_from(world: &World, robot: &BehaviorRobot, goals: &[Pose], shoulder: Vector) -> bool {
    goals.iter().any(|g| {
        shift_for(shoulder, g.translation, HAND_REACH - REACH_SLACK).is_some()
            && open_to(world, robot, g.translation, shoulder, &[])
    })
}

/// A test of places to stand for NAVIGATE_TO `object`, for a BehaviorRobot: whether, its body
/// standing there, a hand reaches the object as [`hand_reaches`] asks (a necklace in a cabinet
/// from before its open front, not from beside it) or, holding something, above a place for it
/// on or in the object as [`placement_in_reach`] asks — the checks the solver makes once the
/// robot has arrived, made before it drives, so that it drives to a stand the solver accepts
/// rather than to one within reach of the object's box from which no hand reaches it (then
/// it drove again, up to ten times). `None` for no BehaviorRobot driven by its full action
/// space.
pub(crate) fn reach_test<'e>(
    env: &'e Env,
    object: ObjectId,
) -> Option<impl Fn(&BaseConfig) -> bool + 'e> {
    let (world, robot) = behavior_robot(env)?;
    let to_base = base_config(env).pose().inverse();
    let shoulder_of = |side: Side| to_base.transform_point(robot.shoulder(world, side));
    let holding = Side::BOTH
        .iter()
        .rposition(|&side| robot.holding(side).is_some());
    let goals = holding.map_or_else(Vec::new, |hand| on_or_in_goals(env, object, hand));
    // Holding something with no place for it there, the object's box in reach is what counts.
    let shoulders: Vec<Vector> = match holding {
        Some(hand) if !goals.is_empty() => vec![shoulder_of(Side::BOTH[hand])],
        _ => Side::BOTH.into_iter().map(shoulder_of).collect(),
    };
    Some(move |stand: &BaseConfig| {
        let pose = stand.pose();
        shoulders.iter().any(|&s| {
            let shoulder = pose.transform_point(s);
            if goals.is_empty() {
                reaches_from(world, robot, object, shoulder)
            } else {
                places_from(world, robot, &goals, shoulder)
            }
        })
    })
}

/// How far up a point must be clear to count as open from above, m.
const OPEN_ABOVE: f32 = 0.3;

/// Whether a hand can come to `point` from the shoulder's side or from above: nothing fixed
/// (furniture, walls) lies across the floor from it toward the shoulder, or above it. The
/// robot's parts and `besides` aside; what moves would be pushed. (The hand flies free, with
/// no arm: what matters is whether the point is walled in on the robot's side.)
fn open_to(
    world: &World,
    robot: &BehaviorRobot,
    point: Vector,
    shoulder: Vector,
    besides: &[ObjectId],
) -> bool {
    let mut ignored = robot.parts().all().to_vec();
    ignored.extend_from_slice(besides);
    let filter = QueryFilter {
        fixed_only: true,
        ..QueryFilter::excluding(&ignored)
    };
    let clear = |direction: Vector, length: f32| {
        length <= 0.0
            || matches!(
                world.core().cast_ray(point, direction, length, &filter),
                Ok(None)
            )
    };
    let across = (shoulder - point).with_z(0.0);
    let level = across.length();
    (level > 0.0 && clear(across / level, level)) || clear(Vector::Z, OPEN_ABOVE)
}

/// How far the body must go down (up, if negative) for a shoulder at `shoulder` to reach
/// `point` within `reach`: 0 if it does, `None` if no height within [`CROUCH`] down and
/// [`RISE`] up does.
fn shift_for(shoulder: Vector, point: Vector, reach: f32) -> Option<f32> {
    let across = (point - shoulder).truncate().length();
    if across > reach {
        return None;
    }
    let half = (reach * reach - across * across).sqrt();
    let height = shoulder.z.clamp(point.z - half, point.z + half);
    let shift = shoulder.z - height;
    (-RISE..=CROUCH).contains(&shift).then_some(shift)
}

/// Up to [`GOALS_PLANNED`] of `goals` (hand poses, best first) that are clear of everything and
/// that the hand reaches once the body has gone down or up by the shift the first needs (see
/// [`shift_for`]); with that shift.
fn choose_goals(
    world: &World,
    robot: &BehaviorRobot,
    side: Side,
    goals: &[Pose],
) -> Option<(Vec<Pose>, f32)> {
    let body = planning_body(world, robot, side);
    let reach = HAND_REACH - REACH_SLACK;
    let mut free = goals.iter().filter_map(|g| {
        let shift = shift_for(body.shoulder, g.translation, reach)?;
        body.clear(world, &HandConfig::of(g)).then_some((*g, shift))
    });
    let (first, depth) = free.next()?;
    let same = free.filter(|&(_, shift)| shift == depth).map(|(g, _)| g);
    let chosen = std::iter::once(first).chain(same).take(GOALS_PLANNED);
    Some((chosen.collect(), depth))
}

/// Lowers (or raises, for a negative `depth`) the body by `depth`, m, with body actions.
fn crouch(steps: &mut Stepper<'_, '_>, depth: f32) -> Attempt<()> {
    let Some((world, robot)) = behavior_robot(steps.env) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let goal = robot.body_pose(world).translation.z - depth;
    for _ in 0..STEPS_PER_WAYPOINT {
        let Some((world, robot)) = behavior_robot(steps.env) else {
            break;
        };
        let dz = goal - robot.body_pose(world).translation.z;
        if dz.abs() <= TARGET_TOLERANCE {
            break;
        }
        let mut action = vec![0.0; robot_dim(steps.env)];
        action[Action::BODY.start + 2] = (dz / ACTION_SCALE).clamp(-1.0, 1.0);
        attempt!(steps.act(&action));
    }
    Ok(Ok(()))
}

/// A planned hand path from where the hand is told to be to `goals`' first free one.
fn plan_hand(
    world: &World,
    robot: &BehaviorRobot,
    side: Side,
    goals: impl IntoIterator<Item = Pose>,
    seed: u64,
) -> Result<Vec<HandConfig>, Failure> {
    let start = HandConfig::of(&(robot.body_pose(world) * robot.hand_target(side)));
    let body = planning_body(world, robot, side);
    let goal = goals
        .into_iter()
        .map(|g| HandConfig::of(&g))
        .find(|g| body.reaches(g) && body.clear(world, g))
        .ok_or(Failure::NoHandPose)?;
    let space = HandSpace::new(world, body, &start, &goal);
    let params = PlanParams {
        seed,
        ..PHYSICAL_BUDGET
    };
    let planned = plan(&space, &start, &goal, &params)?;
    let mut dense = vec![start];
    dense.extend(steps_along(&space, &planned.path));
    Ok(dense)
}

/// A planned hand path to `goal` that ends with a straight move onto it: down from above
/// ([`PRE_ABOVE`]), else in from the robot's side ([`PRE_FRONT`], into a cabinet or under a
/// shelf), where that last stretch is free; else planned to the goal itself. With the path,
/// the way out: from the goal back to where the straight move began. Planned to hover
/// just over a tin, a hand found no way in sideways, its fingers a few millimetres above the
/// lid; planned into a cabinet's compartment, none through the narrow opening.
fn plan_with_approach(
    world: &World,
    robot: &BehaviorRobot,
    side: Side,
    goal: Pose,
    seed: u64,
) -> Result<(Vec<HandConfig>, Option<Vector>), Failure> {
    let body = planning_body(world, robot, side);
    let end = HandConfig::of(&goal);
    let outward = (body.shoulder - goal.translation)
        .with_z(0.0)
        .normalize_or_zero();
    let above = PRE_ABOVE.iter().map(|&h| Vector::Z * h);
    let front = PRE_FRONT.iter().map(|&d| outward * d);
    for offset in above.chain(front) {
        let mut pre = end;
        pre.position += offset;
        let last = straight(&pre, &end);
        let free = body.reaches(&pre) && last.iter().all(|c| body.clear(world, c));
        if !free {
            continue;
        }
        if let Ok(mut path) = plan_hand(world, robot, side, [pre.pose()], seed) {
            path.extend(last);
            return Ok((path, Some(offset)));
        }
    }
    Ok((plan_hand(world, robot, side, [goal], seed)?, None))
}

/// The hand's configurations from `from` straight to `to`, at the hand planner's resolution,
/// without `from`.
fn straight(from: &HandConfig, to: &HandConfig) -> Vec<HandConfig> {
    let n = ((from.position - to.position).length() / behavior_motion::HAND_RESOLUTION)
        .ceil()
        .max(1.0) as usize;
    (1..=n)
        .map(|k| HandConfig {
            position: from.position.lerp(to.position, k as f32 / n as f32),
            angles: to.angles,
        })
        .collect()
}

/// Hand poses over the object, palm down, best first: over the top of its box near the
/// shoulder, jittered, at headings around the one from the body to the object; then the same
/// higher up, by each of `APPROACH_RAISES` (fingers that would touch a tilted tile at
/// [`APPROACH_HEIGHT`] clear it higher, and the descent still reaches it), those raised more
/// than the first only above a column the hand can come down clear of everything but the
/// object.
fn approach_goals(
    world: &World,
    robot: &BehaviorRobot,
    call: &Call,
    side: Side,
    rng: &mut SimRng,
) -> Vec<Pose> {
    let shoulder = robot.shoulder(world, side);
    let at = grasp_point(world, call.object, shoulder);
    let body = robot.body_pose(world).translation;
    let facing = (at.y - body.y).atan2(at.x - body.x);
    let low: Vec<Pose> = (0..GRASP_HEADINGS)
        .map(|k| {
            let top = Vector::new(
                at.x + uniform(rng, -GRASP_JITTER, GRASP_JITTER),
                at.y + uniform(rng, -GRASP_JITTER, GRASP_JITTER),
                at.z + APPROACH_HEIGHT,
            );
            let spread = if k == 0 { 0.0 } else { PI / 2.0 };
            let heading = facing + uniform(rng, -spread, spread);
            let rotation = Rotation::from_rotation_z(heading);
            Pose::from_parts(top - rotation * GRASP_POINT, rotation)
        })
        .collect();
    // The hand coming down to the object touches only it.
    let mut coming_down = planning_body(world, robot, side);
    coming_down.filter.exclude_objects.push(call.object);
    let mut goals = Vec::new();
    for (k, raise) in APPROACH_RAISES.into_iter().enumerate() {
        for g in &low {
            let raised = Pose::from_parts(g.translation + Vector::Z * raise, g.rotation);
            if k < 2 || clear_column(world, &coming_down, &raised, g) {
                goals.push(raised);
            }
        }
    }
    goals
}

/// Whether `body` comes straight down from `from` to `to` clear (checked every
/// [`COLUMN_STEP`]).
fn clear_column(world: &World, body: &HandBody, from: &Pose, to: &Pose) -> bool {
    let drop = from.translation.z - to.translation.z;
    let n = (drop / COLUMN_STEP).ceil().max(1.0) as usize;
    (0..=n).all(|i| {
        let t = i as f32 / n as f32;
        let mut pose = *from;
        pose.translation.z -= t * drop;
        body.clear(world, &HandConfig::of(&pose))
    })
}

/// How far the hand's target is from `goal` (in the world), as the hand's action counts it:
/// position and roll, pitch, yaw in the body frame; `None` when it is there.
fn hand_offset(env: &Env, side: Side, goal: &Pose) -> Option<[f32; 6]> {
    let (world, robot) = behavior_robot(env)?;
    let local = robot.body_pose(world).inverse() * *goal;
    let target = robot.hand_target(side);
    let d = local.translation - target.translation;
    let turn = (local.rotation * target.rotation.inverse()).normalize();
    let (yaw, pitch, roll) = turn.to_euler(EulerRot::ZYX);
    let values = [d.x, d.y, d.z, roll, pitch, yaw];
    (!values.iter().all(|v| v.abs() <= TARGET_TOLERANCE)).then_some(values)
}

/// The steps a hand's target needs to get to `goal` at full speed.
fn steps_to(env: &Env, side: Side, goal: &Pose) -> u32 {
    hand_offset(env, side, goal).map_or(0, |values| {
        let longest = values.iter().fold(0.0f32, |m, v| m.max(v.abs()));
        (longest / ACTION_SCALE).ceil() as u32
    })
}

/// The action that takes the hand's target one step toward `goal` (in the world), or `None`
/// when it is there.
fn hand_action(env: &Env, side: Side, goal: &Pose) -> Option<Vec<f32>> {
    let values = hand_offset(env, side, goal)?;
    let mut action = vec![0.0; robot_dim(env)];
    for (k, v) in values.iter().enumerate() {
        action[Action::hand_range(side).start + k] = (v / ACTION_SCALE).clamp(-1.0, 1.0);
    }
    Some(action)
}

fn robot_dim(env: &Env) -> usize {
    env.robot().map_or(0, |r| r.action_dim())
}

/// Executes a hand path, one step per configuration (more where a turn needs them), then lets
/// the palm arrive. The palm's poses go to `executed`.
fn follow(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    path: &[HandConfig],
    executed: &mut Vec<Pose>,
) -> Attempt<()> {
    for c in path.iter().skip(1) {
        let goal = c.pose();
        // Waypoints a resolution apart take a step each; a straight move (tucking the hands)
        // takes as many as it needs.
        for _ in 0..STEPS_PER_WAYPOINT + steps_to(steps.env, side, &goal) {
            let Some(action) = hand_action(steps.env, side, &goal) else {
                break;
            };
            attempt!(steps.act(&action));
            executed.push(palm(steps.env, side));
        }
        if hand_action(steps.env, side, &goal).is_some() {
            return Ok(Err(Failure::HandBlocked));
        }
    }
    attempt!(steps.wait_until(ARRIVAL_STEPS, |env| arrived(env, side)));
    Ok(Ok(()))
}

/// Down onto the object until the hand touches it: at most [`DESCENT_STEPS`], more from an
/// approach raised above [`APPROACH_HEIGHT`] (by as many steps as the raise).
fn descend(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    object: ObjectId,
    executed: &mut Vec<Pose>,
) -> Attempt<()> {
    let above = behavior_robot(steps.env).map_or(0.0, |(world, _)| {
        let fingers = palm(steps.env, side).transform_point(GRASP_POINT).z;
        fingers - world.aabb(object).maxs.z - APPROACH_HEIGHT
    });
    let raised = (above.max(0.0) / DESCENT_STEP).ceil() as u32;
    for _ in 0..DESCENT_STEPS + raised {
        if touches(steps.env, side, object) {
            break;
        }
        let mut goal = target_in_world(steps.env, side);
        goal.translation.z -= DESCENT_STEP;
        let Some(action) = hand_action(steps.env, side, &goal) else {
            break;
        };
        attempt!(steps.act(&action));
        executed.push(palm(steps.env, side));
    }
    Ok(Ok(()))
}

/// Presses the trigger until the hand holds the object; if the assisted grasp has not taken
/// it once the trigger is past its threshold and the hand touches it, forces the grasp as the
/// original does after closing (recorded as an
/// edit, [`FORCED_GRASP`], for replays to do again).
fn close(steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
    let side = Side::BOTH[call.hand];
    let mut action = vec![0.0; robot_dim(steps.env)];
    action[Action::trigger_index(side)] = 1.0;
    for _ in 0..CLOSE_STEPS {
        if steps.act(&action)?.is_err() || holds(steps.env, side, call.object) {
            return Ok(());
        }
        // Past the grasp's threshold, touching and still not holding: force it.
        let closed =
            behavior_robot(steps.env).is_some_and(|(_, r)| r.trigger(side) > r.rules().threshold);
        if closed && touches(steps.env, side, call.object) {
            break;
        }
    }
    force_grasp(steps, call)
}

/// Lets the trigger go until the hand is open and holds nothing.
fn open(steps: &mut Stepper<'_, '_>, side: Side) -> Attempt<()> {
    let mut action = vec![0.0; robot_dim(steps.env)];
    action[Action::trigger_index(side)] = -1.0;
    for _ in 0..RELEASE_STEPS {
        let done = behavior_robot(steps.env)
            .is_none_or(|(_, r)| r.trigger(side) == 0.0 && r.holding(side).is_none());
        if done {
            break;
        }
        attempt!(steps.act(&action));
    }
    Ok(Ok(()))
}

/// The hand moved straight by `exit` (the way it came in, reversed), with what it now
/// carries, as far as that is free: out of the cabinet or up from the table before the way
/// back is planned (from where it let go, the placed object under its fingers, no plan starts).
fn back_out(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    exit: Vector,
    executed: &mut Vec<Pose>,
) -> Result<(), RunError> {
    let Some((world, robot)) = behavior_robot(steps.env) else {
        return Ok(());
    };
    let body = planning_body(world, robot, side);
    let here = HandConfig::of(&target_in_world(steps.env, side));
    let mut out = here;
    out.position += exit;
    let line = straight(&here, &out);
    // The first step may still touch what was let go or taken; the rest must be clear.
    let clear = line
        .iter()
        .skip(1)
        .take_while(|c| body.clear(world, c))
        .count();
    let path: Vec<HandConfig> = std::iter::once(here)
        .chain(line.into_iter().take(clear + 1))
        .collect();
    if path.len() > 1 {
        follow(steps, side, &path, executed)?.ok();
    }
    Ok(())
}

/// The hand planned back to `start` with what it now carries, raised where that would not
/// fit.
fn come_back(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    start: Pose,
    executed: &mut Vec<Pose>,
) -> Attempt<()> {
    let Some((world, robot)) = behavior_robot(steps.env) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    // Holding something, the hand keeps the turn it has (so does what it holds); empty, it
    // turns back as it was.
    let turn = if robot.holding(side).is_some() {
        robot.hand_pose(world, side).rotation
    } else {
        start.rotation
    };
    let goals = (0..RAISES)
        .map(|k| Pose::from_parts(start.translation + Vector::Z * (RAISE * k as f32), turn));
    let seed = u64::from(steps.env.steps());
    let path = match plan_hand(world, robot, side, goals, seed) {
        Ok(path) => path,
        Err(failure) => return Ok(Err(failure)),
    };
    follow(steps, side, &path, executed)
}

/// The palm's pose now.
fn palm(env: &Env, side: Side) -> Pose {
    behavior_robot(env).map_or(Pose::IDENTITY, |(world, robot)| {
        robot.hand_pose(world, side)
    })
}

/// Whether the palm is within [`ARRIVED`] of its target.
fn arrived(env: &Env, side: Side) -> bool {
    let target = target_in_world(env, side);
    (palm(env, side).translation - target.translation).length() <= ARRIVED
}

/// Whether the hand (palm or finger) touches the object (its body or a link).
fn touches(env: &Env, side: Side, object: ObjectId) -> bool {
    behavior_robot(env).is_some_and(|(world, robot)| {
        let hand = BodyRef::from(robot.parts().hand(side));
        world
            .core()
            .contacts(hand)
            .unwrap_or_default()
            .iter()
            .any(|c| c.other.is_some_and(|b| b.object == object))
    })
}

/// Whether the hand holds the object.
fn holds(env: &Env, side: Side, object: ObjectId) -> bool {
    behavior_robot(env)
        .is_some_and(|(_, robot)| robot.holding(side).is_some_and(|b| b.object == object))
}

/// The manipulator of hands posed directly by the actions: the BehaviorRobot's.
pub(crate) struct PosedHands;

impl Manipulator for PosedHands {
    fn grasp(&self, env: &mut Env, call: &Call, watcher: Option<&mut dyn Watcher>) -> Attempt<()> {
        Ok(grasp(env, call, watcher)?.map(|_| ()))
    }

    fn place(
        &self,
        env: &mut Env,
        call: &Call,
        relation: Relation,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        Ok(place(env, call, relation, watcher)?.map(|_| ()))
    }

    fn reaches(&self, env: &Env, object: ObjectId, placement: Option<&Call>) -> bool {
        match (placement, env.world(), env.robot()) {
            (Some(call), ..) => placement_in_reach(env, call),
            (None, Some(world), Some(robot)) => hand_reaches(world, robot, object),
            _ => true,
        }
    }

    fn reach_test<'e>(&self, env: &'e Env, object: ObjectId) -> Option<StandTest<'e>> {
        reach_test(env, object).map(|test| Box::new(test) as StandTest<'e>)
    }

    fn tuck(&self, steps: &mut Stepper<'_, '_>) -> Attempt<()> {
        tuck(steps)
    }

    /// A palm sets down what it holds as it holds it.
    fn set_down_turns(&self, _: &World, _: &Robot, _: ObjectId, _: &Pose) -> Vec<Option<Pose>> {
        vec![None]
    }
}
