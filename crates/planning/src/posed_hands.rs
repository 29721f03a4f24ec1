//! Physical GRASP and PLACE_* for hands posed directly ([`behavior_robots::HandMotion::Posed`]:
//! the BehaviorRobot's) (the paper's fully simulated primitives,
//! iGibson 2.0.3's `envs/behavior_mp_env.py`): the hand's motion planned in [`HandSpace`] and
//! executed as the robot's own hand actions, one step of physics each; the grasp made by the
//! assisted grasp as the trigger closes, the placement by letting go above a pose the world's
//! sampler found, then settling.
//!
//! - GRASP: palm down over the top of the object's box ([`Tuning::approach_height`] above it,
//!   ± [`Tuning::grasp_jitter`], a random heading), down in steps of [`Tuning::descent_step`]
//!   until the hand touches it (at most [`Tuning::descent_steps`]), the trigger pressed until it
//!   holds (at most [`Tuning::close_steps`]), then back to where the hand was — raised if what it now carries would
//!   not fit there.
//! - PLACE_*: poses for the held object by the world's sampler ([`Tuning::place_tries`], in a
//!   copy of the world, so that the episode itself only ever moves by actions), the hand
//!   planned with the object to [`Tuning::place_height`] above one, the trigger let go,
//!   [`Tuning::settle_steps`] steps for it to fall and settle, then the hand back.
//! - Where the hand cannot reach its goal from the shoulder, the body goes down (at most
//!   [`Tuning::crouch`]) or up ([`Tuning::rise`]) first, and back after.
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

use crate::edits::RecordedCall;
use crate::execute::RunError;
use crate::execute::Watcher;
use crate::manipulation::{
    Grip, Hands, Manipulator, StandTest, grasp_point, grasp_with, holds, on_or_in_goals, on_top,
    place_with, placement_goals, rng_seed, vertical_axis,
};
use crate::physical::{Attempt, Stepper, attempt, base_config, call_rng, force_grasp};
use crate::primitive::{Call, Failure};
use crate::symbolic::check;
use crate::tools::{slicing_points, wiping_points};
use crate::tuning::Tuning;
use behavior_core::rng::{SimRng, uniform};
use behavior_core::wrap_angle;
use behavior_env::Env;
use behavior_motion::BaseConfig;
use behavior_motion::shapes_in;
use behavior_motion::{HandBody, HandConfig, HandSpace};
use behavior_motion::{PlanParams, plan, steps_along};
use behavior_robots::{Embodiment, PosedHand, Robot, Side};
use behavior_sim::{BodyRef, ObjectId, QueryFilter, Relation, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::{FRAC_1_SQRT_2, PI};
use std::sync::Arc;

/// How a recording names a hand put back at its target (see `free_stranded`).
pub const HAND_RESET: &str = "reset_hand";
/// A palm this far from its target is pinned, not trailing, m (it trails by about a step,
/// ≤ 0.05 m).
const STRANDED: f32 = 0.1;
/// How much higher the approach is tried where fingers at [`Tuning::approach_height`] would touch
/// something, m, in turn: a tilted tile's edge is cleared by the second; the higher ones are
/// for an object low among others or in an open box, where a column the hand can come down
/// clear of all but the object leads to it ([`clear_column`]). The descent grows by the raise.
const APPROACH_RAISES: [f32; 5] = [0.0, 0.05, 0.15, 0.25, 0.35];
/// How far apart the poses checked down a raised approach's column are, m.
const COLUMN_STEP: f32 = 0.025;
/// Room left within a hand's reach for the grasp's jitter and the hand's own size, m.
const REACH_MARGIN: f32 = 0.05;
/// Room left within a hand's reach for a goal, m: the path to it may bend outward.
const REACH_SLACK: f32 = 0.02;
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
/// Raises of the way-back pose tried when what the hand carries would not fit where it
/// started, m each.
const RAISE: f32 = 0.1;
const RAISES: usize = 7;
/// The point of the hand put over the object: under the fingers' roots on the palm's inner
/// face, where closing fingers wrap (see `behavior-robots`' hand frame).
const GRASP_POINT: Vector = Vector::new(0.04, 0.0, -0.015);
/// The fingers' headings tried for a press, from the way the press faces, rad.
const PRESS_TURNS: [f32; 5] = [0.0, PI / 4.0, -PI / 4.0, PI / 2.0, -PI / 2.0];
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
pub fn grasp(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<HandPath> {
    grasp_with(&PosedHands, env, call, tuning, watcher)
}

/// PLACE_* with physics (see the module docs).
pub fn place(
    env: &mut Env,
    call: &Call,
    relation: Relation,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<HandPath> {
    place_with(&PosedHands, env, call, relation, tuning, watcher)
}

/// The hand's plan to over `call.object` for a GRASP from where the robot stands, as the
/// physical primitive makes it (without moving the body: a goal out of reach at the body's
/// height counts as none). For measuring the planner (`behavior bench plan --hands`).
pub fn approach_plan(env: &Env, call: &Call, tuning: &Tuning) -> Result<Vec<HandConfig>, Failure> {
    let side = hand_side(env, call)?;
    let (world, robot) = posed(env).ok_or(Failure::Unavailable("no episode"))?;
    let mut rng = call_rng(env, call);
    let goals = approach_goals(world, &robot, call, side, tuning, &mut rng);
    plan_hand(world, &robot, side, goals, tuning, rng_seed(&mut rng))
}

/// Whether a hand holding something reaches, its body down or up if need be, above one of the
/// places the world's sampler finds for it by `call` (a PLACE_*), drawing the numbers the
/// placement itself will; true where the call is no physical BehaviorRobot placement or the
/// hand is empty (the primitive then says why it cannot).
pub(crate) fn placement_in_reach(env: &Env, call: &Call, tuning: &Tuning) -> bool {
    let (Some((world, robot)), Some(relation), Some(&side)) = (
        posed(env),
        call.primitive.relation(),
        sides(env).get(call.hand),
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
    placement_goals(world, embodied, call, relation, tuning, &mut rng)
        .is_ok_and(|goals| places_from(world, &robot, side, &goals, shoulder, tuning))
}

/// Draws the hands in to where they are tucked ([`PosedHand::tucked`]), with what they hold
/// (nothing for hands already there), each along a straight line. Tucking only empty hands did worse:
/// summed Q over the 12 Table 1 activities and seeds 0–2, 6.7 against 8.9.
pub(crate) fn tuck(steps: &mut Stepper<'_, '_>) -> Attempt<()> {
    for &side in sides(steps.env) {
        let Some((world, robot)) = posed(steps.env) else {
            return Ok(Ok(()));
        };
        let tuck = match robot.holding(side) {
            Some(held) => carry_pose(world, &robot, side, held),
            None => robot.body_pose(world) * robot.hand(side).tucked(),
        };
        let (goal, here) = (HandConfig::of(&tuck), target_in_world(steps.env, side));
        if HandConfig::of(&here) == goal {
            continue;
        }
        // Straight in where that is free, else planned (a hand left over a high shelf board
        // would be carried into it).
        let body = planning_body(world, &robot, side);
        let line = straight(&HandConfig::of(&here), &goal);
        let direct = vec![HandConfig::of(&here), goal];
        let path = if line.iter().all(|c| body.clear(world, c)) {
            direct
        } else {
            let seed = u64::from(steps.env.steps());
            plan_hand(world, &robot, side, [tuck], steps.tuning, seed).unwrap_or(direct)
        };
        let mut poses = Vec::new();
        attempt!(follow(steps, side, &path, &mut poses));
    }
    free_stranded(steps)?;
    Ok(Ok(()))
}

/// How high above the floor what a hand carries is held for a drive, m: its bottom above beds,
/// tables and counters (0.6–0.9 m), so that only what stands taller — walls, wardrobes — is in
/// its way. Carried at the tucked hand's height, a backpack hanging to 0.4 m met the bed the
/// robot had come past empty-handed, and no way out of the bedroom was left for it.
const CARRY_HEIGHT: f32 = 0.95;
/// The most a tucked hand is raised to carry something high, m (a hand 0.6 m over its tuck is
/// still within reach of the shoulder).
const MAX_CARRY_RAISE: f32 = 0.6;
/// How far to either side of the body's axis what a hand carries may reach before the hand
/// turns it edge-on for a drive, m: the body's half width and a little.
const CARRY_HALF_WIDTH: f32 = 0.3;

/// Where the hand on `side`, holding `held`, is put for a drive: at its tucked place, raised so
/// that what it holds, hanging below the palm as far as it does now, has its bottom at
/// [`CARRY_HEIGHT`] (at most [`MAX_CARRY_RAISE`]); turned, where what it holds would reach more
/// than [`CARRY_HALF_WIDTH`] to either side of the body, by the quarter turn (about the body's
/// forward axis or about the vertical) that keeps it narrowest, as a person carries a board
/// edge-on through a door. Held flat, a 0.9 m board was wider than the doorways, and no way
/// out of the room was found.
fn carry_pose(world: &World, robot: &PosedRobot<'_>, side: Side, held: ObjectId) -> Pose {
    let body = robot.body_pose(world);
    let tucked = robot.hand(side).tucked();
    // What the hand holds, in the palm's frame: it turns and rises with the palm.
    let grip = robot.hand_pose(world, side).inverse() * world.bodies().pose(held);
    let b = world.bodies().local_aabb(held);
    let corners: Vec<Vector> = (0..8)
        .map(|k| {
            Vector::new(
                if k & 1 == 0 { b.mins.x } else { b.maxs.x },
                if k & 2 == 0 { b.mins.y } else { b.maxs.y },
                if k & 4 == 0 { b.mins.z } else { b.maxs.z },
            )
        })
        .collect();
    // The held object's corners in the body's frame, the palm at its tucked place turned so.
    let placed = |turn: Rotation| -> Vec<Vector> {
        let palm = Pose::from_parts(tucked.translation, turn * tucked.rotation);
        corners
            .iter()
            .map(|&c| (palm * grip).transform_point(c))
            .collect()
    };
    let width = |turn: Rotation| placed(turn).iter().fold(0.0f32, |m, c| m.max(c.y.abs()));
    let quarter = PI / 2.0;
    let turns = [
        Rotation::IDENTITY,
        Rotation::from_rotation_x(quarter),
        Rotation::from_rotation_x(-quarter),
        Rotation::from_rotation_z(quarter),
        Rotation::from_rotation_z(-quarter),
    ];
    let turn = if width(turns[0]) <= CARRY_HALF_WIDTH {
        turns[0]
    } else {
        // The narrowest; among equals (to the centimetre), the one that hangs highest.
        let bottom = |turn: Rotation| placed(turn).iter().fold(f32::MAX, |m, c| m.min(c.z));
        let key = |turn: Rotation| ((width(turn) * 100.0).round() as i32, -bottom(turn));
        turns
            .into_iter()
            .min_by(|a, b| {
                let (ka, kb) = (key(*a), key(*b));
                ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
            })
            .unwrap_or(Rotation::IDENTITY)
    };
    // Raised by how far it hangs below the palm now. (Reckoned from its corners at the turned
    // palm instead, the raise was higher for things held askew, and 5 of 14 activities measured
    // side by side were lost.)
    let hangs = robot.hand_pose(world, side).translation.z - world.bodies().aabb(held).mins.z;
    let bottom = body.translation.z + tucked.translation.z - hangs;
    let raise = (CARRY_HEIGHT - bottom).clamp(0.0, MAX_CARRY_RAISE);
    let palm = Pose::from_parts(
        tucked.translation + Vector::Z * raise,
        turn * tucked.rotation,
    );
    body * palm
}

/// Puts back at its target, at once, each palm its servo left more than [`STRANDED`] behind
/// (pinned behind furniture the body moved past: 300 N cannot pull it through), as the
/// original robot's reset entry does; recorded as an edit, [`HAND_RESET`], for replays.
fn free_stranded(steps: &mut Stepper<'_, '_>) -> Result<(), RunError> {
    for &side in sides(steps.env) {
        let behind = posed(steps.env).map_or(0.0, |(world, robot)| {
            let target = robot.body_pose(world) * robot.hand_target(side);
            (robot.hand_pose(world, side).translation - target.translation).length()
        });
        if behind <= STRANDED {
            continue;
        }
        let hand = side.index();
        // A hand that cannot be put back stays where it is: the next motion says so.
        let _ = steps.env.apply(&RecordedCall::own(HAND_RESET, hand))?;
    }
    Ok(())
}

/// Where a physical primitive's hand got to: how far the body went down for it (up, if
/// negative), where the hand was told to be before, and the path.
pub(crate) struct Reached {
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
    let Some((world, robot)) = posed(steps.env) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let Some((chosen, depth)) = choose_goals(world, &robot, side, goals, steps.tuning) else {
        return Ok(Err(Failure::NoHandPose));
    };
    attempt!(crouch(steps, depth));
    let mut start = target_in_world(steps.env, side);
    let mut planned = plan_to_any(steps.env, side, &chosen, steps.tuning, rng);
    // A hand left far out by the last primitive (a drawer's handle it pulled, where it found
    // no way back) plans from where it is, hemmed in by what it let go of: drawn in first, as
    // before a drive, it plans again from beside the body.
    if planned.is_err() && !tucked(steps.env, side) {
        let _ = tuck(steps)?;
        start = target_in_world(steps.env, side);
        planned = plan_to_any(steps.env, side, &chosen, steps.tuning, rng);
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

/// A plan ([`plan_with_approach`]) to the first of `goals` one is found for.
fn plan_to_any(
    env: &Env,
    side: Side,
    goals: &[Pose],
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Result<(Vec<HandConfig>, Option<Vector>), Failure> {
    let Some((world, robot)) = posed(env) else {
        return Err(Failure::Unavailable("no episode"));
    };
    let mut planned = Err(Failure::NoHandPose);
    for goal in goals {
        planned = plan_with_approach(world, &robot, side, *goal, tuning, rng_seed(rng));
        if planned.is_ok() {
            break;
        }
    }
    planned
}

/// How far from its tucked place a hand's target may be and count as tucked, m.
const TUCKED_WITHIN: f32 = 0.1;

/// Whether the hand on `side` is told to be where [`tuck`] puts it (within [`TUCKED_WITHIN`]).
fn tucked(env: &Env, side: Side) -> bool {
    posed(env).is_none_or(|(world, robot)| {
        let tuck = robot.body_pose(world) * robot.hand(side).tucked();
        let here = target_in_world(env, side);
        (here.translation - tuck.translation).length() <= TUCKED_WITHIN
    })
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
    if robot.space() != robot.spec().primitive_space {
        return Err(Failure::Unavailable(
            "physical primitives drive the robot's primitive action space (the BehaviorRobot's \
             `full`)",
        ));
    }
    if PosedRobot::of(robot.embodiment()).is_none() {
        return Err(Failure::Unavailable(
            "these physical primitives move hands the robot's actions pose (the \
             BehaviorRobot's palms)",
        ));
    }
    check(world, robot, call)?;
    sides(env)
        .get(call.hand)
        .copied()
        .ok_or(Failure::NoHand(call.hand))
}

/// The episode's world and the robot's posed hands, if it is driven through its primitive
/// action space (the hand actions here are that space's) and every hand is posed.
fn posed(env: &Env) -> Option<(&World, PosedRobot<'_>)> {
    let (world, robot) = (env.world()?, env.robot()?);
    if robot.space() != robot.spec().primitive_space {
        return None;
    }
    Some((world, PosedRobot::of(robot.embodiment())?))
}

/// The hands of the episode's robot by side, as far as it has posed hands.
fn sides(env: &Env) -> &'static [Side] {
    let n = posed(env).map_or(0, |(_, hands)| hands.posed.len());
    &Side::BOTH[..n.min(Side::BOTH.len())]
}

/// A robot whose hands its actions pose, as the primitives read it: the robot, and each hand
/// as it stands ([`PosedHand`]), by side (0 left, 1 right).
struct PosedRobot<'e> {
    robot: &'e dyn Embodiment,
    posed: Vec<Arc<dyn PosedHand>>,
}

impl<'e> PosedRobot<'e> {
    /// `robot`'s hands, if every one is posed.
    fn of(robot: &'e dyn Embodiment) -> Option<PosedRobot<'e>> {
        let hands = robot.spec().hands().min(Side::BOTH.len());
        let posed = (0..hands)
            .map(|h| robot.posed_hand(h))
            .collect::<Option<Vec<_>>>()?;
        (!posed.is_empty()).then_some(PosedRobot { robot, posed })
    }

    /// The hand on `side` (the caller asks only for the sides [`sides`] gives).
    fn hand(&self, side: Side) -> &dyn PosedHand {
        self.posed[side.index()].as_ref()
    }

    /// The body's pose in the world: the base's.
    fn body_pose(&self, world: &World) -> Pose {
        self.robot.base_pose(world)
    }

    /// The palm's pose in the world.
    fn hand_pose(&self, world: &World, side: Side) -> Pose {
        self.robot
            .hand_object(side.index())
            .map_or(Pose::IDENTITY, |palm| world.bodies().pose(palm))
    }

    /// Where the hand is told to be, in the body's frame.
    fn hand_target(&self, side: Side) -> Pose {
        self.hand(side).target()
    }

    /// The centre of the hand's reach, in the world.
    fn shoulder(&self, world: &World, side: Side) -> Vector {
        self.hand(side).shoulder(world)
    }

    /// How far the hand's trigger is pressed.
    fn trigger(&self, side: Side) -> f32 {
        self.hand(side).trigger()
    }

    /// What the hand holds.
    fn holding(&self, side: Side) -> Option<ObjectId> {
        self.robot.held(side.index())
    }

    /// The robot's objects.
    fn objects(&self) -> Vec<ObjectId> {
        self.robot.objects()
    }

    /// The palm's object.
    fn hand_object(&self, side: Side) -> ObjectId {
        self.robot
            .hand_object(side.index())
            .unwrap_or_else(|| self.robot.base())
    }
}

/// Where the hand is told to be, in the world.
fn target_in_world(env: &Env, side: Side) -> Pose {
    posed(env).map_or(Pose::IDENTITY, |(world, robot)| {
        robot.body_pose(world) * robot.hand_target(side)
    })
}

/// The hand and what it holds as the planner moves them, ignoring the robot and what it holds.
fn body_of(world: &World, robot: &PosedRobot<'_>, side: Side) -> HandBody {
    let hand = robot.hand_object(side);
    let held = robot.holding(side);
    let frame = world.bodies().pose(hand).inverse();
    let mut ignored = robot.objects();
    ignored.extend((0..robot.posed.len()).filter_map(|h| robot.robot.held(h)));
    HandBody {
        shapes: shapes_in(world, std::iter::once(hand).chain(held), frame),
        filter: QueryFilter::excluding(&ignored),
        shoulder: robot.shoulder(world, side),
        reach: robot.hand(side).reach(),
    }
}

/// The hand `hand` of `robot` and what it holds as the planner moves them, ignoring the robot
/// and what it holds; `None` unless the robot's hands are posed.
pub fn hand_body(world: &World, robot: &dyn Embodiment, hand: usize) -> Option<HandBody> {
    let hands = PosedRobot::of(robot)?;
    let side = *Side::BOTH.get(hand).filter(|_| hand < hands.posed.len())?;
    Some(body_of(world, &hands, side))
}

/// The hand as planned: [`hand_body`] with the palm's straight-fingered box, which the robot
/// keeps out of fixed bodies by refusing the hand's target there (a plan clear of it only
/// would stop the hand on its way, at a countertop's edge).
fn planning_body(world: &World, robot: &PosedRobot<'_>, side: Side) -> HandBody {
    let mut body = body_of(world, robot, side);
    body.shapes.push(robot.hand(side).sweep());
    body
}

/// Whether a hand of the robot, its body down or up if need be, reaches the nearest point of the
/// object's box within its reach less `REACH_MARGIN` (for a small object, over it; for a
/// shelf, its near side), and the top of the box there lies `open_to` the shoulder (a
/// necklace in a cabinet is not in reach from beside the cabinet).
pub fn hand_reaches(world: &World, robot: &Robot, object: ObjectId, tuning: &Tuning) -> bool {
    let Some(hands) = PosedRobot::of(robot.embodiment()) else {
        return true;
    };
    let sides = &Side::BOTH[..hands.posed.len()];
    sides.iter().any(|&side| {
        let shoulder = hands.shoulder(world, side);
        reaches_from(world, &hands, side, object, shoulder, tuning)
    })
}

/// [`hand_reaches`] for one shoulder, wherever it is.
fn reaches_from(
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    object: ObjectId,
    shoulder: Vector,
    tuning: &Tuning,
) -> bool {
    let b = world.bodies().aabb(object);
    let top = on_top(world, object, shoulder, 0.0);
    let nearest = top.with_z(shoulder.z.clamp(b.mins.z, b.maxs.z));
    let reach = robot.hand(side).reach();
    shift_for(shoulder, nearest, reach - REACH_MARGIN, tuning).is_some()
        && open_to(world, robot, top, shoulder, &[object])
}

/// Whether a shoulder at `shoulder` reaches above one of the placement `goals` as
/// [`placement_in_reach`] asks.
fn places_from(
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    goals: &[Pose],
    shoulder: Vector,
    tuning: &Tuning,
) -> bool {
    let reach = robot.hand(side).reach();
    goals.iter().any(|g| {
        shift_for(shoulder, g.translation, reach - REACH_SLACK, tuning).is_some()
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
    tuning: &'e Tuning,
) -> Option<impl Fn(&BaseConfig) -> bool + 'e> {
    let (world, robot) = posed(env)?;
    let to_base = base_config(env).pose().inverse();
    let shoulder_of = |side: Side| (side, to_base.transform_point(robot.shoulder(world, side)));
    let all = sides(env);
    let holding = all.iter().rposition(|&side| robot.holding(side).is_some());
    let goals = holding.map_or_else(Vec::new, |hand| {
        let tool = tool_goals(env, world, &robot, all[hand], object);
        if tool.is_empty() {
            on_or_in_goals(env, object, hand, tuning)
        } else {
            tool
        }
    });
    // Holding something with no place for it there, the object's box in reach is what counts.
    let shoulders: Vec<(Side, Vector)> = match holding {
        Some(hand) if !goals.is_empty() => vec![shoulder_of(all[hand])],
        _ => all.iter().map(|&side| shoulder_of(side)).collect(),
    };
    Some(move |stand: &BaseConfig| {
        let pose = stand.pose();
        shoulders.iter().any(|&(side, s)| {
            let shoulder = pose.transform_point(s);
            if goals.is_empty() {
                reaches_from(world, &robot, side, object, shoulder, tuning)
            } else {
                places_from(world, &robot, side, &goals, shoulder, tuning)
            }
        })
    })
}

/// Where the hand on `side` must reach to use what it holds on `object`: over its dirt to wipe
/// it ([`wiping_points`]), over its top to slice it ([`slicing_points`]); none where it holds
/// nothing that acts on `object` (then it carries it there to put it down, say).
fn tool_goals(
    env: &Env,
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    object: ObjectId,
) -> Vec<Pose> {
    let Some(tool) = robot.holding(side) else {
        return Vec::new();
    };
    let wiping = wiping_points(world, tool, object);
    if wiping.is_empty() {
        slicing_points(env, object, side.index())
    } else {
        wiping.into_iter().map(Pose::from_translation).collect()
    }
}

/// For a robot whose hand holds a tool that acts on `object` ([`tool_goals`]), whether that
/// hand reaches where it must from where the robot stands; `None` where no hand holds such a
/// tool.
fn tool_in_reach(env: &Env, object: ObjectId, tuning: &Tuning) -> Option<bool> {
    let (world, robot) = posed(env)?;
    let mut acting = sides(env).iter().filter_map(|&side| {
        let goals = tool_goals(env, world, &robot, side, object);
        (!goals.is_empty()).then_some((side, goals))
    });
    let (side, goals) = acting.next()?;
    let shoulder = robot.shoulder(world, side);
    Some(places_from(world, &robot, side, &goals, shoulder, tuning))
}

/// How far up a point must be clear to count as open from above, m.
const OPEN_ABOVE: f32 = 0.3;

/// Whether a hand can come to `point` from the shoulder's side or from above: nothing fixed
/// (furniture, walls) lies across the floor from it toward the shoulder, or above it and
/// between it and the shoulder at the shoulder's height. The
/// robot's parts and `besides` aside; what moves would be pushed. (The hand flies free, with
/// no arm: what matters is whether the point is walled in on the robot's side.)
fn open_to(
    world: &World,
    robot: &PosedRobot<'_>,
    point: Vector,
    shoulder: Vector,
    besides: &[ObjectId],
) -> bool {
    // What the hands hold moves with them (carried high for a drive, at the shoulder's height).
    let mut ignored = robot.objects();
    ignored.extend(Side::BOTH.iter().filter_map(|&side| robot.holding(side)));
    ignored.extend_from_slice(besides);
    let filter = QueryFilter {
        fixed_only: true,
        ..QueryFilter::excluding(&ignored)
    };
    let clear = |from: Vector, direction: Vector, length: f32| {
        length <= 0.0
            || matches!(
                world.query().cast_ray(from, direction, length, &filter),
                Ok(None)
            )
    };
    let across = (shoulder - point).with_z(0.0);
    let level = across.length();
    // From above only where nothing stands between, at the shoulder's height, the shoulder
    // and the point: a modem on a table beyond a wall is open above, and a robot stood behind
    // the wall and planned its hand through it. (Aimed at the point above instead, the ray met
    // the rim of the ashcan a hand was to put something in.)
    (level > 0.0 && clear(point, across / level, level))
        || (clear(point, Vector::Z, OPEN_ABOVE)
            && (level == 0.0 || clear(shoulder, -across / level, level)))
}

/// How far the body must go down (up, if negative) for a shoulder at `shoulder` to reach
/// `point` within `reach`: 0 if it does, `None` if no height within [`Tuning::crouch`] down and
/// [`Tuning::rise`] up does.
fn shift_for(shoulder: Vector, point: Vector, reach: f32, tuning: &Tuning) -> Option<f32> {
    let across = (point - shoulder).truncate().length();
    if across > reach {
        return None;
    }
    let half = (reach * reach - across * across).sqrt();
    let height = shoulder.z.clamp(point.z - half, point.z + half);
    let shift = shoulder.z - height;
    (-tuning.rise..=tuning.crouch)
        .contains(&shift)
        .then_some(shift)
}

/// Up to [`GOALS_PLANNED`] of `goals` (hand poses, best first) that are clear of everything and
/// that the hand reaches once the body has gone down or up by the shift the first needs (see
/// [`shift_for`]); with that shift.
fn choose_goals(
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    goals: &[Pose],
    tuning: &Tuning,
) -> Option<(Vec<Pose>, f32)> {
    let body = planning_body(world, robot, side);
    let reach = robot.hand(side).reach() - REACH_SLACK;
    let mut free = goals.iter().filter_map(|g| {
        let shift = shift_for(body.shoulder, g.translation, reach, tuning)?;
        body.clear(world, &HandConfig::of(g)).then_some((*g, shift))
    });
    let (first, depth) = free.next()?;
    let same = free.filter(|&(_, shift)| shift == depth).map(|(g, _)| g);
    let chosen = std::iter::once(first).chain(same).take(GOALS_PLANNED);
    Some((chosen.collect(), depth))
}

/// Lowers (or raises, for a negative `depth`) the body by `depth`, m, with body actions.
fn crouch(steps: &mut Stepper<'_, '_>, depth: f32) -> Attempt<()> {
    let Some((world, robot)) = posed(steps.env) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let goal = robot.body_pose(world).translation.z - depth;
    for _ in 0..steps.tuning.steps_per_waypoint {
        let Some((world, robot)) = posed(steps.env) else {
            break;
        };
        let dz = goal - robot.body_pose(world).translation.z;
        if dz.abs() <= TARGET_TOLERANCE {
            break;
        }
        let Some(hand) = robot.posed.first() else {
            break;
        };
        attempt!(steps.act(&hand.lift_action(dz)));
    }
    Ok(Ok(()))
}

/// A planned hand path from where the hand is told to be to `goals`' first free one.
fn plan_hand(
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    goals: impl IntoIterator<Item = Pose>,
    tuning: &Tuning,
    seed: u64,
) -> Result<Vec<HandConfig>, Failure> {
    let start = HandConfig::of(&(robot.body_pose(world) * robot.hand_target(side)));
    let body = planning_body(world, robot, side);
    let goal = goals
        .into_iter()
        .map(|g| HandConfig::of(&g))
        .find(|g| body.reaches(g) && body.clear(world, g))
        .ok_or(Failure::NoHandPose)?;
    // A hand that starts touching something (resting on a towel; against a refrigerator's side
    // where the robot stood close) first moves straight to the nearest free pose, then plans
    // from there: the planner refuses a start in collision.
    let mut dense = vec![start];
    let from = match hand_way_out(world, &body, &start) {
        Some(out) if out != start => {
            dense.extend(straight(&start, &out));
            out
        }
        _ => start,
    };
    let space = HandSpace::new(world, body, &from, &goal);
    let params = PlanParams {
        seed,
        ..tuning.budget
    };
    let planned = plan(&space, &from, &goal, &params)?;
    dense.extend(steps_along(&space, &planned.path));
    Ok(dense)
}

/// How far a hand that starts in contact looks for a free place, m, by [`WAY_OUT_STEP`]s.
const HAND_WAY_OUT: f32 = 0.15;
/// The step of that search, m.
const WAY_OUT_STEP: f32 = 0.01;

/// `start` if it is free; else the nearest free configuration within [`HAND_WAY_OUT`] of it
/// along one of the 26 directions of a cube's faces, edges and corners (up first: a hand
/// resting on a towel is free a centimetre up), its turn kept; `None` where none is (the
/// planner then says the start collides).
fn hand_way_out(world: &World, body: &HandBody, start: &HandConfig) -> Option<HandConfig> {
    let free = |c: &HandConfig| body.reaches(c) && body.clear(world, c);
    if free(start) {
        return Some(*start);
    }
    let steps = (HAND_WAY_OUT / WAY_OUT_STEP).round() as usize;
    (1..=steps).find_map(|k| {
        way_out_directions().find_map(|way| {
            let mut c = *start;
            c.position += way * (WAY_OUT_STEP * k as f32);
            free(&c).then_some(c)
        })
    })
}

/// The 26 unit directions to a cube's faces, edges and corners from its centre, those that
/// rise first, in a fixed order.
fn way_out_directions() -> impl Iterator<Item = Vector> {
    let unit = [0.0, 1.0, -1.0];
    [1.0, 0.0, -1.0].into_iter().flat_map(move |z| {
        unit.into_iter().flat_map(move |x| {
            unit.into_iter()
                .map(move |y| Vector::new(x, y, z))
                .filter(|v| *v != Vector::ZERO)
                .map(|v| v.normalize())
        })
    })
}

/// A planned hand path to `goal` that ends with a straight move onto it: down from above
/// ([`PRE_ABOVE`]), else in from the robot's side ([`PRE_FRONT`], into a cabinet or under a
/// shelf), where that last stretch is free; else planned to the goal itself. With the path,
/// the way out: from the goal back to where the straight move began. Planned to hover
/// just over a tin, a hand found no way in sideways, its fingers a few millimetres above the
/// lid; planned into a cabinet's compartment, none through the narrow opening.
fn plan_with_approach(
    world: &World,
    robot: &PosedRobot<'_>,
    side: Side,
    goal: Pose,
    tuning: &Tuning,
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
        if let Ok(mut path) = plan_hand(world, robot, side, [pre.pose()], tuning, seed) {
            path.extend(last);
            return Ok((path, Some(offset)));
        }
    }
    Ok((plan_hand(world, robot, side, [goal], tuning, seed)?, None))
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
/// [`Tuning::approach_height`] clear it higher, and the descent still reaches it), those raised more
/// than the first only above a column the hand can come down clear of everything but the
/// object.
fn approach_goals(
    world: &World,
    robot: &PosedRobot<'_>,
    call: &Call,
    side: Side,
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Vec<Pose> {
    let shoulder = robot.shoulder(world, side);
    let at = grasp_point(world, call.object, shoulder, tuning.grasp_inset);
    let body = robot.body_pose(world).translation;
    let facing = (at.y - body.y).atan2(at.x - body.x);
    let jitter = tuning.grasp_jitter;
    let low: Vec<Pose> = (0..tuning.grasp_headings)
        .map(|k| {
            let top = Vector::new(
                at.x + uniform(rng, -jitter, jitter),
                at.y + uniform(rng, -jitter, jitter),
                at.z + tuning.approach_height,
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
    goals.extend(cornered_goals(world, call.object, facing, tuning));
    goals
}

/// Headings the fingers may point, all round, for an object in a corner.
const CORNER_HEADINGS: usize = 12;
/// How far off the middle of an object's top a hand may be put over it where the middle's
/// poses meet something beside it, m.
const NUDGES: [f32; 2] = [0.025, 0.045];
/// The eight ways across the top (along its two horizontal axes and between them) a hand is
/// moved off the middle by each of [`NUDGES`].
const NUDGE_WAYS: [(f32, f32); 8] = [
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, 1.0),
    (0.0, -1.0),
    (FRAC_1_SQRT_2, FRAC_1_SQRT_2),
    (FRAC_1_SQRT_2, -FRAC_1_SQRT_2),
    (-FRAC_1_SQRT_2, FRAC_1_SQRT_2),
    (-FRAC_1_SQRT_2, -FRAC_1_SQRT_2),
];

/// Poses over the object for when none of the usual ones is free — a rag pushed into the
/// corner of a shelf, where fingers pointing away from the body meet the shelf's side: palm
/// down at [`Tuning::approach_height`] over the middle of the top of its box and over a point
/// [`Tuning::grasp_inset`] in from each side, then over points [`NUDGES`] off the middle, the
/// fingers pointing every [`CORNER_HEADINGS`]th of a turn (those nearest the body's heading
/// first). Drawing no random numbers, they leave the usual goals as they were.
fn cornered_goals(world: &World, object: ObjectId, facing: f32, tuning: &Tuning) -> Vec<Pose> {
    let pose = world.bodies().pose(object);
    let local = world.bodies().local_aabb(object);
    let middle = local.center();
    let vertical = vertical_axis(pose.rotation);
    let top = world.bodies().aabb(object).maxs.z + tuning.approach_height;
    let mut points = vec![middle];
    let across: Vec<usize> = (0..3).filter(|&a| a != vertical).collect();
    for &axis in &across {
        let room = (0.5 * (local.maxs[axis] - local.mins[axis]) - tuning.grasp_inset).max(0.0);
        for way in [-1.0, 1.0] {
            let mut p = middle;
            p[axis] += way * room;
            points.push(p);
        }
    }
    // Off the middle by a few centimetres, whatever the object's size: a hand centred over a
    // bag of chips against a cabinet's side, or a towel against a counter's front, met the
    // side; moved away from it, its fingers still come down on the object.
    for nudge in NUDGES {
        for (a, b) in NUDGE_WAYS {
            let mut p = middle;
            p[across[0]] += a * nudge;
            p[across[1]] += b * nudge;
            points.push(p);
        }
    }
    let mut turns: Vec<f32> = (0..CORNER_HEADINGS)
        .map(|k| 2.0 * PI * k as f32 / CORNER_HEADINGS as f32)
        .collect();
    turns.sort_by(|a, b| wrap_angle(*a).abs().total_cmp(&wrap_angle(*b).abs()));
    let mut goals = Vec::new();
    for turn in turns {
        let rotation = Rotation::from_rotation_z(facing + turn);
        for p in &points {
            let at = pose.transform_point(*p).with_z(top);
            goals.push(Pose::from_parts(at - rotation * GRASP_POINT, rotation));
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
    let (world, robot) = posed(env)?;
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
    let Some((_, robot)) = posed(env) else {
        return 0;
    };
    hand_offset(env, side, goal).map_or(0, |values| {
        let longest = values.iter().fold(0.0f32, |m, v| m.max(v.abs()));
        (longest / robot.hand(side).step()).ceil() as u32
    })
}

/// The action that takes the hand's target one step toward `goal` (in the world), or `None`
/// when it is there.
fn hand_action(env: &Env, side: Side, goal: &Pose) -> Option<Vec<f32>> {
    let values = hand_offset(env, side, goal)?;
    let (_, robot) = posed(env)?;
    Some(robot.hand(side).move_action(values))
}

/// The action that presses (1) or lets go (−1) the trigger of the hand on `side`.
fn trigger_action(env: &Env, side: Side, press: f32) -> Vec<f32> {
    posed(env).map_or(Vec::new(), |(_, robot)| {
        robot.hand(side).trigger_action(press)
    })
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
        for _ in 0..steps.tuning.steps_per_waypoint + steps_to(steps.env, side, &goal) {
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

/// Down onto the object until the hand touches it: at most [`Tuning::descent_steps`], more from
/// an approach raised above [`Tuning::approach_height`] (by as many steps as the raise).
fn descend(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    object: ObjectId,
    executed: &mut Vec<Pose>,
) -> Attempt<()> {
    let above = posed(steps.env).map_or(0.0, |(world, _)| {
        let fingers = palm(steps.env, side).transform_point(GRASP_POINT).z;
        fingers - world.bodies().aabb(object).maxs.z - steps.tuning.approach_height
    });
    let step = steps.tuning.descent_step;
    let raised = (above.max(0.0) / step).ceil() as u32;
    for _ in 0..steps.tuning.descent_steps + raised {
        if touches(steps.env, side, object) {
            break;
        }
        let mut goal = target_in_world(steps.env, side);
        goal.translation.z -= step;
        let Some(action) = hand_action(steps.env, side, &goal) else {
            break;
        };
        attempt!(steps.act(&action));
        executed.push(palm(steps.env, side));
    }
    Ok(Ok(()))
}

/// How far the hand's target moves between checks of a slide, m.
const SLIDE_STEP: f32 = 0.01;

/// The hand's target moved straight by `offset` in the world, [`SLIDE_STEP`] at a time, each
/// taken in at most [`Tuning::steps_per_waypoint`] steps, until `done` holds. Where the palm
/// is held back (a tool pressed on a table), the target runs on ahead of it and the palm
/// presses after it: what a wipe wants.
fn slide(
    steps: &mut Stepper<'_, '_>,
    side: Side,
    offset: Vector,
    executed: &mut Vec<Pose>,
    done: &dyn Fn(&Env) -> bool,
) -> Attempt<()> {
    let start = target_in_world(steps.env, side);
    let n = (offset.length() / SLIDE_STEP).ceil().max(1.0) as u32;
    for k in 1..=n {
        let mut goal = start;
        goal.translation += offset * (k as f32 / n as f32);
        for _ in 0..steps.tuning.steps_per_waypoint {
            if done(steps.env) {
                return Ok(Ok(()));
            }
            let Some(action) = hand_action(steps.env, side, &goal) else {
                break;
            };
            attempt!(steps.act(&action));
            executed.push(palm(steps.env, side));
        }
    }
    Ok(Ok(()))
}

/// Presses the trigger until the hand holds the object; if the assisted grasp has not taken
/// it once the trigger is past its threshold and the hand touches it, forces the grasp as the
/// original does after closing (recorded as an
/// edit, [`FORCED_GRASP`], for replays to do again).
fn close(steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
    let side = Side::BOTH[call.hand];
    let action = trigger_action(steps.env, side, 1.0);
    for _ in 0..steps.tuning.close_steps {
        if steps.act(&action)?.is_err() || holds(steps.env, call) {
            return Ok(());
        }
        // Past the grasp's threshold, touching and still not holding: force it.
        let closed = posed(steps.env)
            .is_some_and(|(_, r)| r.trigger(side) > r.robot.grasp_rules().threshold);
        if closed && touches(steps.env, side, call.object) {
            break;
        }
    }
    force_grasp(steps, call)
}

/// Lets the trigger go until the hand is open and holds nothing.
fn open(steps: &mut Stepper<'_, '_>, side: Side) -> Attempt<()> {
    let action = trigger_action(steps.env, side, -1.0);
    for _ in 0..steps.tuning.release_steps {
        let done = posed(steps.env)
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
    let Some((world, robot)) = posed(steps.env) else {
        return Ok(());
    };
    let body = planning_body(world, &robot, side);
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
    let Some((world, robot)) = posed(steps.env) else {
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
    let path = match plan_hand(world, &robot, side, goals, steps.tuning, seed) {
        Ok(path) => path,
        Err(failure) => return Ok(Err(failure)),
    };
    follow(steps, side, &path, executed)
}

/// The palm's pose now.
fn palm(env: &Env, side: Side) -> Pose {
    posed(env).map_or(Pose::IDENTITY, |(world, robot)| {
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
    posed(env).is_some_and(|(world, robot)| {
        let hand = BodyRef::from(robot.hand_object(side));
        world
            .contacts()
            .of(hand)
            .unwrap_or_default()
            .iter()
            .any(|c| c.other.is_some_and(|b| b.object == object))
    })
}

/// The manipulator of hands posed directly by the actions: the BehaviorRobot's.
pub(crate) struct PosedHands;

impl Manipulator for PosedHands {
    type Hand = Side;
    type Reached = Reached;
    type Path = HandPath;

    fn hand(&self, env: &Env, call: &Call) -> Result<Side, Failure> {
        hand_side(env, call)
    }

    /// Palm down, its grasp point at `at`, the fingers toward `facing` and at eighth turns
    /// either side of it.
    fn press_goals(&self, _: &Env, _: Side, at: Vector, facing: f32) -> Vec<Pose> {
        PRESS_TURNS
            .iter()
            .map(|&turn| {
                let rotation = Rotation::from_rotation_z(facing + turn);
                Pose::from_parts(at - rotation * GRASP_POINT, rotation)
            })
            .collect()
    }

    fn grasp_goals(
        &self,
        env: &Env,
        side: Side,
        call: &Call,
        tuning: &Tuning,
        rng: &mut SimRng,
    ) -> Vec<Pose> {
        match posed(env) {
            Some((world, robot)) => approach_goals(world, &robot, call, side, tuning, rng),
            None => Vec::new(),
        }
    }

    /// The trigger is left as it is: the palm holds by the assisted grasp.
    fn reach(
        &self,
        steps: &mut Stepper<'_, '_>,
        side: Side,
        goals: &[Pose],
        _: Grip,
        rng: &mut SimRng,
    ) -> Attempt<Reached> {
        reach(steps, side, goals, rng)
    }

    fn descend(
        &self,
        steps: &mut Stepper<'_, '_>,
        side: Side,
        object: ObjectId,
        reached: &mut Reached,
    ) -> Attempt<()> {
        descend(steps, side, object, &mut reached.path.after)
    }

    fn close(&self, steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
        close(steps, call)
    }

    /// Opened first if it holds nothing; then straight back up as high as the approach
    /// ended, turned as the palm now is (what it holds keeps its pose), lifting it off its
    /// support.
    fn lift_off(
        &self,
        steps: &mut Stepper<'_, '_>,
        side: Side,
        held: bool,
        reached: &mut Reached,
    ) -> Attempt<()> {
        if !held {
            attempt!(open(steps, side));
        }
        let mut up = palm(steps.env, side);
        let top = reached.path.planned.last().map(|c| c.position.z);
        up.translation.z = top.unwrap_or(up.translation.z);
        let up = HandConfig::of(&up);
        follow(steps, side, &[up, up], &mut reached.path.after)
    }

    fn open(&self, steps: &mut Stepper<'_, '_>, side: Side) -> Attempt<()> {
        open(steps, side)
    }

    fn settle(&self, steps: &mut Stepper<'_, '_>, _: Side) -> Attempt<()> {
        let n = steps.tuning.settle_steps;
        steps.wait_until(n, |_| false)
    }

    /// Nothing here: coming back backs out the way the hand came in first.
    fn leave(&self, _: &mut Stepper<'_, '_>, _: Side, _: &mut Reached) -> Attempt<()> {
        Ok(Ok(()))
    }

    /// Backed out the way it came in, planned back, the body back at its height.
    fn come_back(
        &self,
        steps: &mut Stepper<'_, '_>,
        side: Side,
        _: Grip,
        reached: &mut Reached,
    ) -> Attempt<()> {
        retreat(steps, side, reached)
    }

    fn slide(
        &self,
        steps: &mut Stepper<'_, '_>,
        side: Side,
        offset: Vector,
        reached: &mut Reached,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()> {
        slide(steps, side, offset, &mut reached.path.after, done)
    }

    /// The still action keeps each hand's target where it is, and the palm holds by the
    /// assisted grasp.
    fn hold_still(
        &self,
        steps: &mut Stepper<'_, '_>,
        _: Side,
        n: u32,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()> {
        steps.wait_until(n, done)
    }

    /// A palm's servo yields: the door turns about it as it is pulled along the door's arc.
    const SWINGS_LEAVES: bool = true;

    fn path(&self, reached: Reached) -> HandPath {
        reached.path
    }
}

impl Hands for PosedHands {
    fn reaches(
        &self,
        env: &Env,
        object: ObjectId,
        placement: Option<&Call>,
        tuning: &Tuning,
    ) -> bool {
        match (placement, env.world(), env.robot()) {
            (Some(call), ..) => placement_in_reach(env, call, tuning),
            (None, Some(world), Some(robot)) => tool_in_reach(env, object, tuning)
                .unwrap_or_else(|| hand_reaches(world, robot, object, tuning)),
            _ => true,
        }
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
        tuck(steps)
    }

    /// A palm sets down what it holds as it holds it.
    fn set_down_turns(&self, _: &World, _: &Robot, _: &Call, _: &Pose) -> Vec<Option<Pose>> {
        vec![None]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{ObjectSpec, Part, Primitive};

    /// A fixed table top 1 m square whose top lies at 0.76 m, and a hand: a 10 cm cube.
    fn table_and_hand() -> (World, HandBody) {
        let mut world = World::default();
        let top = Part::new(Primitive::Box {
            half_extents: Vector::new(0.5, 0.5, 0.01),
        });
        let mut spec = ObjectSpec::new("table_1", "table.n.02", vec![top]).fixed();
        spec.pose = Pose::from_translation(Vector::new(0.0, 0.0, 0.75));
        world.add(spec).unwrap();
        let palm = Primitive::Box {
            half_extents: Vector::splat(0.05),
        };
        let hand = HandBody {
            shapes: vec![(palm, Pose::IDENTITY)],
            filter: QueryFilter::default(),
            shoulder: Vector::new(-0.4, 0.0, 1.0),
            reach: 1.2,
        };
        (world, hand)
    }

    #[test]
    fn a_hand_pressed_into_a_table_is_moved_straight_up_out_of_it() {
        let (world, hand) = table_and_hand();
        let start = HandConfig::of(&Pose::from_translation(Vector::new(0.1, 0.2, 0.78)));
        assert!(
            !hand.clear(&world, &start),
            "the start must collide for the test to mean anything"
        );
        let out = hand_way_out(&world, &hand, &start).expect("a free pose within 15 cm");
        assert!(
            hand.clear(&world, &out),
            "the way out is not free: {:?}",
            out.position
        );
        let moved = out.position - start.position;
        // The palm's bottom must rise above 0.76 m: 3 cm at least, the nearest being 4 cm up.
        assert!(
            moved.x.abs() < 1e-6 && moved.y.abs() < 1e-6 && (0.03..0.045).contains(&moved.z),
            "moved by {moved:?}, not straight up by the least that frees it"
        );
        assert_eq!(out.angles, start.angles, "the hand's turn is kept");
    }

    #[test]
    fn a_free_hand_stays_and_a_buried_one_finds_no_way_out() {
        let (world, hand) = table_and_hand();
        let free = HandConfig::of(&Pose::from_translation(Vector::new(0.1, 0.2, 0.9)));
        assert_eq!(hand_way_out(&world, &hand, &free), Some(free));
        // Deep in a 1 m block, every direction meets the block for more than 15 cm.
        let mut world = World::default();
        let block = Part::new(Primitive::Box {
            half_extents: Vector::splat(0.5),
        });
        let mut spec = ObjectSpec::new("cabinet_1", "cabinet.n.01", vec![block]).fixed();
        spec.pose = Pose::from_translation(Vector::new(0.2, 0.0, 0.8));
        world.add(spec).unwrap();
        let buried = HandConfig::of(&Pose::from_translation(Vector::new(0.2, 0.0, 0.8)));
        assert_eq!(hand_way_out(&world, &hand, &buried), None);
    }

    #[test]
    fn the_ways_out_are_26_distinct_unit_directions_straight_up_first() {
        let ways: Vec<Vector> = way_out_directions().collect();
        assert_eq!(ways.len(), 26);
        assert_eq!(ways[0], Vector::Z);
        for (k, a) in ways.iter().enumerate() {
            assert!(
                (a.length() - 1.0).abs() < 1e-6,
                "{a:?} is not a unit vector"
            );
            assert!(
                ways[k + 1..].iter().all(|b| (*a - *b).length() > 0.1),
                "{a:?} appears twice"
            );
        }
    }
}
