//! SOAK, WIPE and SLICE with physics, and the switches pressed by hand, the same for every
//! manipulator: the world's own rules do the work, the primitive only brings the tool (or the
//! hand) where they act. A soakable thing becomes soaked
//! when a drop of a running source touches it, so SOAK holds the tool under the outlet until one
//! has; a cleaning tool touching a dirty object takes the particles within its box (stains only
//! when soaked), so WIPE presses the tool onto the surface where the particles lie and rubs it
//! about, spot after spot, until the object is clean; a slicer pressing a sliceable object with
//! more than 10 N near its cutting edge cuts it in two, so SLICE brings the knife's edge over the
//! object's top and pushes it down through it; a hand held within 0.1 m of a switch's button
//! for 5 steps flips it, so TOGGLE_ON and TOGGLE_OFF bring the hand there and hold it. Each
//! reports what it did not manage ([`Failure::NoEffect`]) rather than setting the state.

use crate::execute::Watcher;
use crate::manipulation::{Grip, Manipulator, manipulator};
use crate::physical::{Attempt, Stepper, at_once, attempt, call_rng};
use crate::primitive::{Call, Failure, Primitive};
use crate::symbolic::check;
use crate::tuning::Tuning;
use behavior_core::rng::SimRng;
use behavior_core::{Ability, Predicate};
use behavior_env::Env;
use behavior_robots::Robot;
use behavior_sim::{OUTLET_OFFSET, ObjectId, PointKind, World};
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::FRAC_PI_2;

/// Gaps tried between the tool's top and where the drops start, m.
const UNDER_TAP: [f32; 3] = [0.03, 0.06, 0.1];
/// Still steps the tool is held under the tap before it is moved under the drops: five drops'
/// worth.
const SOAK_STEPS: u32 = 20;
/// Moves under the drops at most.
const SOAK_CORRECTIONS: usize = 4;
/// How high above a dirty spot the tool is brought before it is pressed down, m.
const HOVER: f32 = 0.02;
/// How far the tool is raised off what it touched before the hand comes back, m.
const LIFT: f32 = 0.05;
/// How far down the tool is pressed at most, m.
const PRESS: f32 = 0.06;
/// The rub about a spot: offsets of the tool's centre, m, gone through in order.
const RUB: [(f32, f32); 5] = [
    (0.06, 0.0),
    (-0.06, 0.06),
    (-0.06, -0.06),
    (0.06, -0.06),
    (0.0, 0.03),
];
/// How far past a tool's side the drops fall, m: within a drop's radius and the world's
/// touching distance of it.
const GRAZE: f32 = 0.006;
/// How far in from a tool's side the point put under a tap or over a spot lies, m.
const TAP_INSET: f32 = 0.02;
/// How high above the object's top the knife's edge is brought before it is pushed down, m.
const OVER_CUT: f32 = 0.03;
/// How far below the object's bottom the push aims, m: the knife stops on what the object
/// lies on, pressing, unless the object is cut first.
const THROUGH: f32 = 0.03;
/// Still steps the knife keeps pressing where the push stopped, until the object is cut.
const CUT_STEPS: u32 = 30;
/// Where the hand's pressing point is put for a button: out from it toward the robot and up,
/// m — over a button on top, then before one on the front of furniture (the fingers, ahead
/// of that point, come within the world's 0.1 m of it).
const PRESS_FROM: [(f32, f32); 5] = [
    (0.0, 0.05),
    (0.1, 0.04),
    (0.08, 0.0),
    (0.12, 0.0),
    (0.03, 0.03),
];
/// Still steps the hand is held at the button at most: three times the world's five.
const PRESS_STEPS: u32 = 15;
/// Dirty spots nearest the hand that a wipe tries to bring the tool over, each time: the five
/// nearest left a shelf's dust undone where its nearest lay behind the shelf's boards.
const SPOT_CHOICES: usize = 20;
/// Dirty spots a reach test looks at, spread over the object's dirt: where a hand can wipe.
const SPOTS_TESTED: usize = 16;
/// Spots wiped at most per WIPE.
const SPOTS: usize = 8;

/// SOAK with physics: what hand `call.hand` holds brought under `call.object`'s outlet and held
/// there until a drop soaks it, then brought back.
pub(crate) fn soak_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    let hand = attempt!(at_once(checked(hands, env, call)));
    let (goals, drops_from) = attempt!(at_once(under_tap(env, call)));
    let mut rng = call_rng(env, call);
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let tool = held(steps.env, call);
    let soaked = move |env: &Env| {
        tool.zip(env.world())
            .is_some_and(|(t, w)| w.state(t, Predicate::Soaked))
    };
    let mut reached = attempt!(hands.reach(&mut steps, hand, &goals, Grip::Closed, &mut rng));
    // The hand stops a few centimetres off its goal: where the drops miss, the tool is moved
    // under them by what they missed it by, and held again.
    for _ in 0..SOAK_CORRECTIONS {
        attempt!(hands.hold_still(&mut steps, hand, SOAK_STEPS, &soaked));
        let miss = tool
            .zip(steps.env.world())
            .map(|(t, w)| missed_by(w, t, drops_from));
        match miss {
            Some(by) if !soaked(steps.env) && by.length() > 1e-3 => {
                attempt!(hands.slide(&mut steps, hand, by, &mut reached, &soaked));
            }
            _ => break,
        }
    }
    // Up off the basin's rim or the tap it may have been moved against, then back.
    attempt!(hands.slide(&mut steps, hand, Vector::Z * LIFT, &mut reached, &|_| false));
    attempt!(hands.come_back(&mut steps, hand, Grip::Closed, &mut reached));
    if soaked(steps.env) {
        Ok(Ok(()))
    } else {
        Ok(Err(Failure::NoEffect(
            "no drop reached what the hand holds",
        )))
    }
}

/// WIPE with physics: the tool hand `call.hand` holds pressed onto `call.object` where its
/// dirt lies and rubbed about, spot after spot (the nearest left first), until the object is
/// clean of what the tool takes, or [`SPOTS`] have been wiped.
pub(crate) fn wipe_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    mut watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    let hand = attempt!(at_once(checked(hands, env, call)));
    let mut rng = call_rng(env, call);
    let object = call.object;
    let Some(tool) = held(env, call) else {
        return Ok(Err(Failure::HandEmpty));
    };
    let clean = move |env: &Env| env.world().is_none_or(|w| !dirty(w, tool, object));
    let mut last = Failure::NoEffect("the dirt stayed where the tool went");
    for _ in 0..SPOTS {
        if clean(env) {
            return Ok(Ok(()));
        }
        let goals = match spot_goals(env, call, tool) {
            Some(goals) => goals,
            None => break,
        };
        let mut steps = Stepper {
            env,
            tuning,
            watcher: crate::execute::again(&mut watcher),
        };
        let mut reached = match hands.reach(&mut steps, hand, &goals, Grip::Closed, &mut rng)? {
            Ok(reached) => reached,
            Err(failure) => {
                last = failure;
                break;
            }
        };
        let touching = move |env: &Env| {
            env.world()
                .is_some_and(|w| w.relations().touching(tool, object))
        };
        attempt!(hands.slide(
            &mut steps,
            hand,
            -Vector::Z * PRESS,
            &mut reached,
            &touching
        ));
        for (dx, dy) in RUB {
            let by = Vector::new(dx, dy, -0.005);
            attempt!(hands.slide(&mut steps, hand, by, &mut reached, &clean));
        }
        attempt!(hands.slide(&mut steps, hand, Vector::Z * LIFT, &mut reached, &|_| false));
        attempt!(hands.come_back(&mut steps, hand, Grip::Closed, &mut reached));
    }
    if clean(env) {
        Ok(Ok(()))
    } else {
        Ok(Err(last))
    }
}

/// SLICE with physics: the knife hand `call.hand` holds brought with its cutting edge
/// [`OVER_CUT`] above the middle of `call.object`'s top, pushed down through it to
/// [`THROUGH`] below its bottom, kept pressing for up to [`CUT_STEPS`] where it stopped, then
/// lifted and brought back. The world's slicing rule decides whether the object is cut.
pub(crate) fn slice_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    let hand = attempt!(at_once(checked(hands, env, call)));
    let (goals, depth) = attempt!(at_once(edge_goals(env, call)));
    let object = call.object;
    let sliced = move |env: &Env| {
        env.world()
            .is_some_and(|w| w.state(object, Predicate::Sliced))
    };
    let mut rng = call_rng(env, call);
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let cut = cut_through(hands, &mut steps, hand, &goals, depth, &sliced, &mut rng)?;
    // A knife that cut on the way and then found no way on (making_tea's lemon, cut as the
    // hand went down into the refrigerator, then "no free hand pose") has done it.
    Ok(judged(
        sliced(steps.env),
        cut,
        "the knife did not cut through it",
    ))
}

/// A primitive's outcome by the state it is for: done where the state was reached, whatever
/// stopped the moves after; else the moves' failure, or `no_effect` where they all ran.
pub(crate) fn judged(
    reached: bool,
    moves: Result<(), Failure>,
    no_effect: &'static str,
) -> Result<(), Failure> {
    match (reached, moves) {
        (true, _) => Ok(()),
        (false, Err(failure)) => Err(failure),
        (false, Ok(())) => Err(Failure::NoEffect(no_effect)),
    }
}

/// SLICE's moves: the knife to one of `goals`, pushed `depth` down, held there while it has
/// not cut, lifted and brought back.
fn cut_through<M: Manipulator>(
    hands: &M,
    steps: &mut Stepper<'_, '_>,
    hand: M::Hand,
    goals: &[Pose],
    depth: f32,
    sliced: &dyn Fn(&Env) -> bool,
    rng: &mut SimRng,
) -> Attempt<()> {
    let mut reached = attempt!(hands.reach(steps, hand, goals, Grip::Closed, rng));
    attempt!(hands.slide(steps, hand, -Vector::Z * depth, &mut reached, sliced));
    attempt!(hands.hold_still(steps, hand, CUT_STEPS, sliced));
    attempt!(hands.slide(steps, hand, Vector::Z * depth, &mut reached, &|_| false));
    attempt!(hands.come_back(steps, hand, Grip::Closed, &mut reached));
    Ok(Ok(()))
}

/// Poses of the hand that put the cutting edge of the knife it holds (its slicing point, else
/// the middle of its box's bottom) [`OVER_CUT`] above the middle of `call.object`'s top, the
/// knife held as the hand can set it down and turned by quarter turns about the edge; with the
/// push down from there that ends [`THROUGH`] below the object's bottom.
fn edge_goals(env: &Env, call: &Call) -> Result<(Vec<Pose>, f32), Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    let knife = robot.held(call.hand).ok_or(Failure::HandEmpty)?;
    let held = Held::of(world, robot, call)?;
    let (lo, hi) = held.local;
    let edge = world
        .bodies()
        .object(knife)
        .point(PointKind::SlicingEdge)
        .unwrap_or((0.5 * (lo + hi)).with_z(lo.z));
    let b = world.bodies().aabb(call.object);
    let over = b.center().with_z(b.maxs.z + OVER_CUT);
    let depth = over.z - (b.mins.z - THROUGH);
    let mut goals = Vec::new();
    for (pose, turn) in held.turned() {
        let at = pose.transform_point(edge);
        let turned = about(at, turn, over) * pose;
        goals.push(held.holder_at(&turned));
    }
    Ok((goals, depth))
}

/// TOGGLE_ON or TOGGLE_OFF with physics: hand `call.hand` brought to `call.object`'s button
/// (its toggle point; else the middle of its top) from one of [`PRESS_FROM`], held there until
/// the switch flips or [`PRESS_STEPS`] have passed, and brought back. The world's toggle rule
/// decides.
pub(crate) fn toggle_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    let hand = attempt!(at_once(checked(hands, env, call)));
    let Some(goals) = press_goals(hands, env, hand, call) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let (object, on) = (call.object, call.primitive == Primitive::ToggleOn);
    let switched = move |env: &Env| {
        env.world()
            .is_some_and(|w| w.state(object, Predicate::ToggledOn) == on)
    };
    let grip = Grip::holding(held(env, call).is_some());
    let mut rng = call_rng(env, call);
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let mut reached = attempt!(hands.reach(&mut steps, hand, &goals, grip, &mut rng));
    attempt!(hands.hold_still(&mut steps, hand, PRESS_STEPS, &switched));
    // A hand that switched it and then found no free way back has done it (four sinks in
    // solve-all were switched on so, then reported failed, and the setter's fallback refused:
    // "already on"); the next motion plans from where the hand is.
    let back = hands.come_back(&mut steps, hand, grip, &mut reached)?;
    Ok(judged(
        switched(steps.env),
        back,
        "the hand at the button did not switch it",
    ))
}

/// The hand's goals for pressing `call.object`'s button: from each of [`PRESS_FROM`], out
/// being the way across the floor from the button to the robot's base.
fn press_goals<M: Manipulator>(
    hands: &M,
    env: &Env,
    hand: M::Hand,
    call: &Call,
) -> Option<Vec<Pose>> {
    let (world, robot) = (env.world()?, env.robot()?);
    let object = world.bodies().object(call.object);
    let b = world.bodies().aabb(call.object);
    let button = object
        .point(PointKind::ToggleButton)
        .map(|p| world.bodies().pose(call.object).transform_point(p))
        .unwrap_or(b.center().with_z(b.maxs.z));
    let base = robot.base_pose(world).translation;
    let out = (base - button).with_z(0.0).normalize_or_zero();
    // The press faces the way into the button.
    let facing = (-out.y).atan2(-out.x);
    let mut goals = Vec::new();
    for (away, up) in PRESS_FROM {
        let at = button + out * away + Vector::Z * up;
        goals.extend(hands.press_goals(env, hand, at, facing));
    }
    Some(goals)
}

/// The hand a call uses, after the primitive's own checks (but reach: the hand goes there).
pub(crate) fn checked<M: Manipulator>(
    hands: &M,
    env: &Env,
    call: &Call,
) -> Result<M::Hand, Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    match check(world, robot, call) {
        Ok(()) | Err(Failure::Unreachable) => hands.hand(env, call),
        Err(failure) => Err(failure),
    }
}

/// What hand `call.hand` holds.
fn held(env: &Env, call: &Call) -> Option<ObjectId> {
    env.robot().and_then(|r| r.held(call.hand))
}

/// Where the particles of dirt that `tool` takes from `object` lie: its dust, and its stains
/// if the tool is soaked.
fn dirt_spots(world: &World, tool: ObjectId, object: ObjectId) -> Vec<Vector> {
    let kinds: &[Predicate] = if world.state(tool, Predicate::Soaked) {
        &[Predicate::Dusty, Predicate::Stained]
    } else {
        &[Predicate::Dusty]
    };
    kinds
        .iter()
        .filter(|&&k| world.state(object, k))
        .flat_map(|&k| world.particle_positions(object, k))
        .collect()
}

/// Points [`HOVER`] over up to [`SPOTS_TESTED`] of the particles of dirt that `tool` takes from
/// `object`, spread over them: where a hand that holds the tool must reach to wipe. A place
/// to stand that reaches the nearest corner of a bathtub's box leaves the stains on its
/// bottom, a metre on, out of reach; empty where there is no such dirt (the tool is carried
/// there to be put down, say).
pub(crate) fn wiping_points(world: &World, tool: ObjectId, object: ObjectId) -> Vec<Vector> {
    let spots = dirt_spots(world, tool, object);
    let every = spots.len().div_ceil(SPOTS_TESTED).max(1);
    spots
        .into_iter()
        .step_by(every)
        .map(|p| p + Vector::Z * HOVER)
        .collect()
}

/// Where hand `hand` must be to slice `object` with the knife it holds ([`edge_goals`]): none
/// where it holds no slicer or `object` is not there to be sliced.
pub(crate) fn slicing_points(env: &Env, object: ObjectId, hand: usize) -> Vec<Pose> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Vec::new();
    };
    let slices = robot.held(hand).is_some_and(|knife| {
        world.bodies().object(knife).has(Ability::Slicer)
            && world.bodies().object(object).has(Ability::Sliceable)
            && !world.state(object, Predicate::Sliced)
    });
    let call = Call {
        primitive: Primitive::Slice,
        object,
        hand,
    };
    match slices.then(|| edge_goals(env, &call)) {
        Some(Ok((goals, _))) => goals,
        _ => Vec::new(),
    }
}

/// Whether `object` still has dirt that `tool` takes: dust, and stains if it is soaked.
fn dirty(world: &World, tool: ObjectId, object: ObjectId) -> bool {
    world.state(object, Predicate::Dusty)
        || (world.state(tool, Predicate::Soaked) && world.state(object, Predicate::Stained))
}

/// Poses of the hand that put what it holds [`UNDER_TAP`] below where `call.object`'s drops
/// start, on its side away from the palm (a palm holding a sponge from above catches the drops
/// itself): first with the drops falling [`GRAZE`] past its far side, which they touch on the
/// way down, then onto its top [`TAP_INSET`] in from that side; the tool held as the hand can
/// set it down ([`Held::poses`]) and turned about the vertical by quarter turns (one of them
/// keeps it off the tap). With where the drops start.
fn under_tap(env: &Env, call: &Call) -> Result<(Vec<Pose>, Vector), Failure> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Err(Failure::Unavailable("no episode"));
    };
    let source = world.bodies().object(call.object);
    let outlet = source
        .point(PointKind::WaterOutlet)
        .ok_or(Failure::Unable {
            what: "has no outlet",
        })?;
    let drops_from =
        world.bodies().pose(call.object).transform_point(outlet) - Vector::Z * OUTLET_OFFSET;
    let held = Held::of(world, robot, call)?;
    let mut goals = Vec::new();
    for (pose, turn) in held.turned() {
        let (lo, hi) = held.boxed(&pose);
        let top = (0.5 * (lo + hi)).with_z(hi.z);
        // Turned about the vertical through the middle of its top, which stays put.
        let turned = about(top, turn, top) * pose;
        let (lo, hi) = held.boxed(&turned);
        let half = 0.5 * (hi - lo);
        let away = (top - held.palm(&turned)).with_z(0.0);
        let way = if away.length() > 1e-3 {
            away.normalize()
        } else {
            Vector::X
        };
        let side = way.x.abs() * half.x + way.y.abs() * half.y;
        for far in [side + GRAZE, (side - TAP_INSET).max(0.0)].map(|d| top + way * d) {
            for gap in UNDER_TAP {
                let by = Pose::from_translation(drops_from - Vector::Z * gap - far);
                goals.push(held.holder_at(&(by * turned)));
            }
        }
    }
    Ok((goals, drops_from))
}

/// How far across the floor `tool`'s top, [`TAP_INSET`] in from its sides, lies from the
/// column the drops fall down from `drops_from`: the move that puts it under them. Taken in
/// the tool's own frame: a rag turned 45° leaves the corners of its box in the world empty,
/// and drops aimed there fall past it.
fn missed_by(world: &World, tool: ObjectId, drops_from: Vector) -> Vector {
    let b = world.bodies().local_aabb(tool);
    let pose = world.bodies().pose(tool);
    let local = pose.inverse_transform_point(drops_from);
    let within = |v: f32, lo: f32, hi: f32| {
        let (lo, hi) = (lo + TAP_INSET, hi - TAP_INSET);
        if lo > hi {
            0.5 * (lo + hi)
        } else {
            v.clamp(lo, hi)
        }
    };
    let nearest = Vector::new(
        within(local.x, b.mins.x, b.maxs.x),
        within(local.y, b.mins.y, b.maxs.y),
        b.maxs.z,
    );
    (drops_from - pose.transform_point(nearest)).with_z(0.0)
}

/// Poses of the hand that put `tool` [`HOVER`] above one of the dirty spots of `call.object`
/// nearest the hand ([`SPOT_CHOICES`] of them), the spot under the middle of the tool's bottom
/// or under one of its sides (a spot by a tub's wall is wiped by the tool's edge), the tool
/// held as the hand can set it down and turned by quarter turns; `None` where no dirt is left
/// that the tool takes.
fn spot_goals(env: &Env, call: &Call, tool: ObjectId) -> Option<Vec<Pose>> {
    let (world, robot) = (env.world()?, env.robot()?);
    let held = Held::of(world, robot, call).ok()?;
    let hand_at = held.palm(&world.bodies().pose(tool));
    let mut spots = dirt_spots(world, tool, call.object);
    if spots.is_empty() {
        return None;
    }
    spots.sort_by(|a, b| (*a - hand_at).length().total_cmp(&(*b - hand_at).length()));
    let mut goals = Vec::new();
    for spot in spots.into_iter().take(SPOT_CHOICES) {
        for (pose, turn) in held.turned() {
            let (lo, hi) = held.boxed(&pose);
            let bottom = (0.5 * (lo + hi)).with_z(lo.z);
            let turned = about(bottom, turn, bottom) * pose;
            let (lo, hi) = held.boxed(&turned);
            let half = 0.5 * (hi - lo);
            let (sx, sy) = ((half.x - TAP_INSET).max(0.0), (half.y - TAP_INSET).max(0.0));
            for (dx, dy) in [(0.0, 0.0), (sx, 0.0), (-sx, 0.0), (0.0, sy), (0.0, -sy)] {
                let to = spot + Vector::new(dx, dy, HOVER);
                let by = Pose::from_translation(to - bottom);
                goals.push(held.holder_at(&(by * turned)));
            }
        }
    }
    Some(goals)
}

/// The motion that turns a thing by `turn` about the vertical through its point `point` and
/// brings that point to `to`.
fn about(point: Vector, turn: Rotation, to: Vector) -> Pose {
    Pose::from_translation(to) * Pose::from_rotation(turn) * Pose::from_translation(-point)
}

/// What a hand holds, for putting it somewhere: its shape's box, how the hand grips it, and
/// the poses it can be brought to as held (the manipulator's `set_down_turns`: a palm keeps
/// it as it is, a gripper holds it hanging below, pointing down).
struct Held {
    /// Its box in its own frame.
    local: (Vector, Vector),
    /// Its pose in the holding part's frame.
    grip: Pose,
    /// The poses it may be held at, before any turn about the vertical.
    poses: Vec<Pose>,
}

impl Held {
    fn of(world: &World, robot: &Robot, call: &Call) -> Result<Held, Failure> {
        let tool = robot.held(call.hand).ok_or(Failure::HandEmpty)?;
        let holder = robot
            .hand_object(call.hand)
            .ok_or(Failure::NoHand(call.hand))?;
        let now = world.bodies().pose(tool);
        let grip = world.bodies().pose(holder).inverse() * now;
        let b = world.bodies().local_aabb(tool);
        let poses = manipulator(robot)
            .set_down_turns(world, robot, call, &grip)
            .into_iter()
            .map(|turned| turned.unwrap_or(now))
            .collect();
        Ok(Held {
            local: (b.mins, b.maxs),
            grip,
            poses,
        })
    }

    /// Each pose it may be held at with each quarter turn about the vertical.
    fn turned(&self) -> impl Iterator<Item = (Pose, Rotation)> + '_ {
        self.poses.iter().flat_map(|&pose| {
            (0..4).map(move |k| (pose, Rotation::from_rotation_z(FRAC_PI_2 * k as f32)))
        })
    }

    /// Its box in the world at `pose`: lowest and highest corners.
    fn boxed(&self, pose: &Pose) -> (Vector, Vector) {
        let (a, b) = self.local;
        let corners = (0..8).map(|k| {
            let pick = |bit: usize, lo: f32, hi: f32| if k & bit == 0 { lo } else { hi };
            pose.transform_point(Vector::new(
                pick(1, a.x, b.x),
                pick(2, a.y, b.y),
                pick(4, a.z, b.z),
            ))
        });
        corners.fold(
            (Vector::splat(f32::MAX), Vector::splat(f32::MIN)),
            |(lo, hi), c| (lo.min(c), hi.max(c)),
        )
    }

    /// The holding part's pose that holds it at `pose`.
    fn holder_at(&self, pose: &Pose) -> Pose {
        *pose * self.grip.inverse()
    }

    /// Where the holding part is when it is held at `pose`.
    fn palm(&self, pose: &Pose) -> Vector {
        self.holder_at(pose).translation
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{ObjectSpec, Part, Primitive};

    #[test]
    fn a_turned_rag_is_moved_under_the_drops_by_its_own_box() {
        // A rag 10 cm square turned 45°: the corners of its box in the world hold no rag.
        let mut world = World::default();
        let cloth = Part::new(Primitive::Box {
            half_extents: Vector::new(0.05, 0.05, 0.0075),
        });
        let mut spec = ObjectSpec::new("rag_1", "rag.n.01", vec![cloth]);
        spec.pose = Pose::from_parts(
            Vector::new(0.0, 0.0, 1.0),
            Rotation::from_rotation_z(FRAC_PI_2 / 2.0),
        );
        let rag = world.add(spec).unwrap();
        // Over a corner of the world box, 2 cm in from its sides: 6.4 cm from the rag's middle
        // along its diagonal, beyond its 5 cm half side.
        let drops_from = Vector::new(0.045, 0.045, 1.2);
        let miss = missed_by(&world, rag, drops_from);
        assert!(
            miss.length() > 0.02,
            "the drops would fall past the rag: moved by only {miss:?}"
        );
        // Moved by the miss, the column of drops falls on the rag, TAP_INSET in from its sides.
        let pose = world.bodies().pose(rag);
        let under = pose.inverse_transform_point(drops_from - miss);
        let on = |v: f32| v.abs() <= 0.05 - TAP_INSET + 1e-4;
        assert!(
            on(under.x) && on(under.y),
            "the drops fall at {under:?} in the rag's frame"
        );
        // A column over the rag already needs no move.
        let over = Vector::new(0.0, 0.01, 1.2);
        assert!(missed_by(&world, rag, over).length() < 1e-6);
    }
}
