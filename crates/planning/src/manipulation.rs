//! The manipulation interface: how physical primitives move a robot's hands, whichever the
//! robot. A manipulator plans a hand's motion in the space the robot's hands move in
//! ([`HandMotion`]: a free pose, `posed_hands.rs`; an arm's joints, `jointed_arm.rs`) and
//! executes it through the robot's own actions, one step of physics each; [`grasp`], [`place`]
//! and [`reaches`] take the episode's robot's. What every manipulator shares lives here: where
//! on an object a hand goes, and the poses above the places the world's sampler finds for what
//! a hand holds.

use crate::execute::{RunError, Watcher};
use crate::physical::{Attempt, Stepper, attempt, call_rng};
use crate::primitive::{Call, Failure, Primitive};
use crate::symbolic::put;
use crate::tuning::Tuning;
use crate::{jointed_arm, posed_hands};
use behavior_core::rng::{SimRng, uniform};
use behavior_env::Env;
use behavior_motion::BaseConfig;
use behavior_robots::{HandMotion, Robot};
use behavior_sim::{ObjectId, Relation, World};
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::PI;

/// A test of a place to stand: whether a hand reaches what it must from a base there.
pub(crate) type StandTest<'e> = Box<dyn Fn(&BaseConfig) -> bool + 'e>;

/// What a gripper is told as it moves: open, or closed on what it holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Grip {
    /// Open (a gripper) or let go (a trigger).
    Open,
    /// Closed on what it holds.
    Closed,
}

impl Grip {
    /// Closed if the hand holds something, else open.
    pub(crate) fn holding(held: bool) -> Grip {
        if held { Grip::Closed } else { Grip::Open }
    }
}

/// What a planner asks of a robot's hands besides grasping and placing: whether they reach,
/// where to stand for them, drawing them in, how what they hold is set down.
pub(crate) trait Hands: Sync {
    /// Whether, from where the base stands, a hand reaches `object` for a grasp — or, holding
    /// something and given a `placement` (a PLACE_* call), a place for it; true where there is
    /// nothing to test (the primitive then says why it cannot).
    fn reaches(
        &self,
        env: &Env,
        object: ObjectId,
        placement: Option<&Call>,
        tuning: &Tuning,
    ) -> bool;

    /// A test of places to stand for NAVIGATE_TO `object`: whether, the base standing there, a
    /// hand reaches it as the manipulator's `reaches` asks, or, holding something, a place for it
    /// on or in the object. `None` where there is nothing to test.
    fn reach_test<'e>(
        &self,
        env: &'e Env,
        object: ObjectId,
        tuning: &'e Tuning,
    ) -> Option<StandTest<'e>>;

    /// Draws the hands (and what they hold) in before the base drives.
    fn tuck(&self, steps: &mut Stepper<'_, '_>) -> Attempt<()>;

    /// The ways what hand `call.hand` holds (held at `grip` in the hand's frame) is turned
    /// before places by `call.object` are sampled for it: `None` as it is held, or its pose in
    /// the world.
    fn set_down_turns(
        &self,
        world: &World,
        robot: &Robot,
        call: &Call,
        grip: &Pose,
    ) -> Vec<Option<Pose>>;
}

/// How physical primitives move a robot's hands: one implementation per [`HandMotion`], for
/// every robot whose hands move that way. Each supplies the steps of a grasp and of a placement
/// (reach, descend, close, lift off, open, settle, leave, come back);
/// [`grasp_with`] and [`place_with`] put the steps together, the same for every manipulator.
pub(crate) trait Manipulator: Hands {
    /// Which of the robot's hands a call moves, as the manipulator names it.
    type Hand: Copy;
    /// What [`Manipulator::reach`] leaves for the steps after it: where the hand started and
    /// the path so far.
    type Reached;
    /// The paths a grasp or placement planned and executed, for measuring.
    type Path;

    /// The primitive's preconditions, and the hand `call` moves.
    fn hand(&self, env: &Env, call: &Call) -> Result<Self::Hand, Failure>;

    /// Poses of the hand's holding part (in the world) that put the point it presses with (a
    /// palm's grasp point, a gripper's fingertips) at `at`, pointing down or toward `facing`
    /// (a heading across the floor), best first: how a switch's button is pressed.
    fn press_goals(&self, env: &Env, hand: Self::Hand, at: Vector, facing: f32) -> Vec<Pose>;

    /// Poses of the hand (in the world) over `call.object` for a grasp, best first.
    fn grasp_goals(
        &self,
        env: &Env,
        hand: Self::Hand,
        call: &Call,
        tuning: &Tuning,
        rng: &mut SimRng,
    ) -> Vec<Pose>;

    /// The hand brought to the first of `goals` it can reach, its grip held as `grip`; on
    /// failure, brought back.
    fn reach(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        goals: &[Pose],
        grip: Grip,
        rng: &mut SimRng,
    ) -> Attempt<Self::Reached>;

    /// On from the reached pose toward `object` until the hand touches it.
    fn descend(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        object: ObjectId,
        reached: &mut Self::Reached,
    ) -> Attempt<()>;

    /// Closes the hand until it holds `call.object`, forcing the grasp where it touches it.
    fn close(&self, steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError>;

    /// The hand, holding what it took (`held`) or not, drawn up off where it closed.
    fn lift_off(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        held: bool,
        reached: &mut Self::Reached,
    ) -> Attempt<()>;

    /// Opens the hand until it holds nothing.
    fn open(&self, steps: &mut Stepper<'_, '_>, hand: Self::Hand) -> Attempt<()>;

    /// Still steps for what was let go to fall and settle ([`Tuning::settle_steps`]).
    fn settle(&self, steps: &mut Stepper<'_, '_>, hand: Self::Hand) -> Attempt<()>;

    /// The open hand drawn away from what it let go.
    fn leave(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        reached: &mut Self::Reached,
    ) -> Attempt<()>;

    /// The hand brought back where it started, with what it now carries, its grip `grip`.
    fn come_back(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        grip: Grip,
        reached: &mut Self::Reached,
    ) -> Attempt<()>;

    /// The hand, and what it holds, moved straight by `offset` (in the world, m) with its
    /// grip closed, a little at a time, until `done` holds or the offset is covered. Stopped
    /// short by what it presses on, it stays there: the press of a tool onto a surface, the
    /// rub of a wipe.
    fn slide(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        offset: Vector,
        reached: &mut Self::Reached,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()>;

    /// Still steps with the grip closed, until `done` holds or `n` have passed: what the hand
    /// holds kept under a running tap.
    fn hold_still(
        &self,
        steps: &mut Stepper<'_, '_>,
        hand: Self::Hand,
        n: u32,
        done: &dyn Fn(&Env) -> bool,
    ) -> Attempt<()>;

    /// Whether the hand can hold a door, lid or drawer on its hinge while it swings it
    /// (`doors.rs`): a hand that yields (a posed palm's force-limited servo) can; an arm whose
    /// links are moved kinematically holds the leaf with unbounded force, and the least
    /// mismatch between its path and the leaf's arc breaks the grasp's 350 N at once.
    const SWINGS_LEAVES: bool;

    /// The paths of a grasp or placement once done.
    fn path(&self, reached: Self::Reached) -> Self::Path;
}

/// GRASP with physics, the same for every manipulator: the hand brought over `call.object`,
/// on until it touches it, closed until it holds, lifted off and brought back with it. The
/// paths it planned and executed come back.
pub(crate) fn grasp_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<M::Path> {
    let hand = match hands.hand(env, call) {
        Ok(hand) => hand,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut rng = call_rng(env, call);
    let goals = hands.grasp_goals(env, hand, call, tuning, &mut rng);
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let mut reached = attempt!(hands.reach(&mut steps, hand, &goals, Grip::Open, &mut rng));
    attempt!(hands.descend(&mut steps, hand, call.object, &mut reached));
    hands.close(&mut steps, call)?;
    let held = holds(steps.env, call);
    attempt!(hands.lift_off(&mut steps, hand, held, &mut reached));
    let back = hands.come_back(&mut steps, hand, Grip::holding(held), &mut reached)?;
    let holds = holds(steps.env, call);
    match back {
        // A hand that holds it counts though it found no way back with it (a chicken taken out
        // of a refrigerator): the next drive's tuck plans its way in, or, pinned, puts it back
        // at its target. Reported as failed, the planner went on to place it all the same.
        Err(failure) if !holds => Ok(Err(failure)),
        _ if !holds => Ok(Err(Failure::Missed)),
        _ => Ok(Ok(hands.path(reached))),
    }
}

/// PLACE_* with physics, the same for every manipulator: what hand `call.hand` holds brought
/// above a place the world's sampler finds for it by `relation` to `call.object`, let go,
/// left to settle, and the hand drawn away and brought back.
pub(crate) fn place_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    relation: Relation,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<M::Path> {
    let hand = match hands.hand(env, call) {
        Ok(hand) => hand,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut rng = call_rng(env, call);
    let goals = match (env.world(), env.robot()) {
        (Some(world), Some(robot)) => {
            placement_goals(world, robot, call, relation, tuning, &mut rng)
        }
        _ => Err(Failure::Unavailable("no episode")),
    };
    let goals = match goals {
        Ok(goals) => goals,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let mut reached = attempt!(hands.reach(&mut steps, hand, &goals, Grip::Closed, &mut rng));
    attempt!(hands.open(&mut steps, hand));
    attempt!(hands.settle(&mut steps, hand));
    attempt!(hands.leave(&mut steps, hand, &mut reached));
    attempt!(hands.come_back(&mut steps, hand, Grip::Open, &mut reached));
    Ok(Ok(hands.path(reached)))
}

/// Whether hand `call.hand` of the episode's robot holds `call.object`.
pub(crate) fn holds(env: &Env, call: &Call) -> bool {
    env.robot()
        .is_some_and(|r| r.held(call.hand) == Some(call.object))
}

/// A [`Manipulator`] as the episode's robot's, whichever it is: grasp and place put together
/// by [`grasp_with`] and [`place_with`].
pub(crate) trait AnyManipulator: Hands {
    /// GRASP with physics.
    fn grasp(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()>;

    /// PLACE_* with physics.
    fn place(
        &self,
        env: &mut Env,
        call: &Call,
        relation: Relation,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()>;

    /// TOGGLE_ON or TOGGLE_OFF with physics ([`crate::tools`]): the switch pressed by hand.
    fn press(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()>;

    /// SOAK, WIPE or SLICE with physics ([`crate::tools`]), by `call.primitive`.
    fn use_tool(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()>;

    /// OPEN or CLOSE with physics ([`crate::doors`]): the leaves taken by hand and swung.
    fn swing(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()>;

    /// Whether its hands swing doors ([`Manipulator::SWINGS_LEAVES`]).
    fn swings_leaves(&self) -> bool;
}

impl<M: Manipulator> AnyManipulator for M {
    fn grasp(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        Ok(grasp_with(self, env, call, tuning, watcher)?.map(|_| ()))
    }

    fn place(
        &self,
        env: &mut Env,
        call: &Call,
        relation: Relation,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        Ok(place_with(self, env, call, relation, tuning, watcher)?.map(|_| ()))
    }

    fn press(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        crate::tools::toggle_with(self, env, call, tuning, watcher)
    }

    fn use_tool(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        match call.primitive {
            Primitive::Soak => crate::tools::soak_with(self, env, call, tuning, watcher),
            Primitive::Wipe => crate::tools::wipe_with(self, env, call, tuning, watcher),
            Primitive::Slice => crate::tools::slice_with(self, env, call, tuning, watcher),
            _ => Ok(Err(Failure::Unavailable("not a tool's primitive"))),
        }
    }

    fn swing(
        &self,
        env: &mut Env,
        call: &Call,
        tuning: &Tuning,
        watcher: Option<&mut dyn Watcher>,
    ) -> Attempt<()> {
        crate::doors::swing_with(self, env, call, tuning, watcher)
    }

    fn swings_leaves(&self) -> bool {
        M::SWINGS_LEAVES
    }
}

/// The manipulator for a robot's hands.
pub(crate) fn manipulator(robot: &Robot) -> &'static dyn AnyManipulator {
    match robot.spec().hand_motion {
        HandMotion::Posed => &posed_hands::PosedHands,
        HandMotion::Jointed => &jointed_arm::JointedArm,
    }
}

/// `act` by the episode's robot's manipulator; with no episode, a failure.
fn by_robot(
    env: &mut Env,
    act: impl FnOnce(&'static dyn AnyManipulator, &mut Env) -> Attempt<()>,
) -> Attempt<()> {
    match env.robot().map(manipulator) {
        Some(hands) => act(hands, env),
        None => Ok(Err(Failure::Unavailable("no episode"))),
    }
}

/// GRASP with physics by the episode's robot's manipulator (see `posed_hands.rs` and
/// `jointed_arm.rs` for how each moves).
pub fn grasp(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    by_robot(env, |hands, env| hands.grasp(env, call, tuning, watcher))
}

/// PLACE_* with physics by the episode's robot's manipulator.
pub fn place(
    env: &mut Env,
    call: &Call,
    relation: Relation,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    by_robot(env, |hands, env| {
        hands.place(env, call, relation, tuning, watcher)
    })
}

/// TOGGLE_ON or TOGGLE_OFF with physics by the episode's robot's manipulator: its hand brought
/// to the switch's button and held there (`tools.rs`), without the kinematic fallback that
/// [`crate::run`] has.
pub fn press(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    by_robot(env, |hands, env| hands.press(env, call, tuning, watcher))
}

/// OPEN or CLOSE with physics by the episode's robot's manipulator: its hand takes each door,
/// lid or drawer and swings it (`doors.rs`), without the kinematic fallback that [`crate::run`]
/// has.
pub fn swing(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    by_robot(env, |hands, env| hands.swing(env, call, tuning, watcher))
}

/// SOAK, WIPE or SLICE with physics by the episode's robot's manipulator (`tools.rs`).
pub fn use_tool(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    by_robot(env, |hands, env| hands.use_tool(env, call, tuning, watcher))
}

/// Whether the episode's robot opens and shuts doors by hand with physics (`doors.rs`); false
/// with no episode.
pub(crate) fn swings_leaves(env: &Env) -> bool {
    env.robot().is_some_and(|r| manipulator(r).swings_leaves())
}

/// Whether, from where the episode's robot stands, a hand reaches `object` for a grasp, or,
/// holding something and given a `placement` (a PLACE_* call), a place for it (see
/// the manipulator's `reaches`); true with no episode.
pub fn reaches(env: &Env, object: ObjectId, placement: Option<&Call>, tuning: &Tuning) -> bool {
    env.robot()
        .is_none_or(|robot| manipulator(robot).reaches(env, object, placement, tuning))
}

/// How a recording names the forced grasp of a physical GRASP (see `physical.rs`'s
/// `force_grasp`).
pub const FORCED_GRASP: &str = "grasp_touching";

/// Heights tried above a sampled pose when [`Tuning::place_height`] collides (a shelf above),
/// m.
const LOWER_PLACE_HEIGHTS: [f32; 2] = [0.05, 0.02];

/// Where on the top of the object's box the hand goes: the point nearest the shoulder, at
/// least `inset` ([`Tuning::grasp_inset`]) in from the box's sides (its centre, for a small object), so that a
/// board is taken by its near end. The box is the object's own, turned as it lies (a plank
/// turned about the vertical fills only part of its axis-aligned box: a corner of that box
/// may be floor).
pub(crate) fn grasp_point(world: &World, object: ObjectId, shoulder: Vector, inset: f32) -> Vector {
    on_top(world, object, shoulder, inset)
}

/// Which of an object's own axes (0 x, 1 y, 2 z), turned by `rotation`, lies nearest the
/// vertical: the axis of its height as it lies now.
pub(crate) fn vertical_axis(rotation: Rotation) -> usize {
    let up = rotation.inverse() * Vector::Z;
    (0..3)
        .max_by(|&a, &b| up[a].abs().total_cmp(&up[b].abs()))
        .unwrap_or(2)
}

/// The point of the object's own box nearest `toward` across the floor, at least `inset` in
/// from its sides, at the height of the top of the object.
pub(crate) fn on_top(world: &World, object: ObjectId, toward: Vector, inset: f32) -> Vector {
    let pose = world.bodies().pose(object);
    let local = world.bodies().local_aabb(object);
    let mut at = pose.inverse_transform_point(toward);
    // The object's axis nearest the vertical is its height: the point sits at its middle.
    let vertical = vertical_axis(pose.rotation);
    for axis in 0..3 {
        let middle = 0.5 * (local.mins[axis] + local.maxs[axis]);
        // How far from the middle the point may lie (never negative: a clamp whose bounds
        // cross by a rounding error panics).
        let room = (0.5 * (local.maxs[axis] - local.mins[axis]) - inset).max(0.0);
        at[axis] = if axis == vertical {
            middle
        } else {
            at[axis].clamp(middle - room, middle + room)
        };
    }
    pose.transform_point(at)
        .with_z(world.bodies().aabb(object).maxs.z)
}

/// The poses above places on or in `object` for what `hand` holds, as PLACE_ONTOP and
/// PLACE_INSIDE would sample them (drawing the numbers those placements will): what a place
/// to stand is tested against when the robot carries something there. Empty where the hand
/// holds nothing or neither finds a place.
pub(crate) fn on_or_in_goals(
    env: &Env,
    object: ObjectId,
    hand: usize,
    tuning: &Tuning,
) -> Vec<Pose> {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return Vec::new();
    };
    [Primitive::PlaceOnTop, Primitive::PlaceInside]
        .into_iter()
        .filter_map(|primitive| {
            let call = Call {
                primitive,
                object,
                hand,
            };
            let relation = primitive.relation()?;
            let mut rng = call_rng(env, &call);
            placement_goals(world, robot, &call, relation, tuning, &mut rng).ok()
        })
        .flatten()
        .collect()
}

/// Poses of the part that holds in hand `call.hand` (a palm, Fetch's gripper) that hold what
/// it holds, as it holds it now, above the places the world's sampler finds for it by `call`
/// (sampled in a copy of the world where the hand has let go: see [`poses_above_places`]).
pub(crate) fn placement_goals(
    world: &World,
    robot: &Robot,
    call: &Call,
    relation: Relation,
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Result<Vec<Pose>, Failure> {
    let held = robot.held(call.hand).ok_or(Failure::HandEmpty)?;
    let holder = robot
        .hand_object(call.hand)
        .ok_or(Failure::NoHand(call.hand))?;
    let grip = world.bodies().pose(holder).inverse() * world.bodies().pose(held);
    let mut let_go = world.clone();
    robot.clone().release_now(&mut let_go, call.hand);
    // As the hand holds it (a palm), or turned as the hand can set it down (a gripper pointing
    // down).
    let turns = manipulator(robot).set_down_turns(world, robot, call, &grip);
    let mut poses = Vec::new();
    let mut last = Failure::NoHandPose;
    for turned in turns {
        if let Some(turned) = turned {
            // A finite pose turned by a finite rotation: the teleport cannot fail.
            let _ = let_go.bodies_mut().set_pose(held, turned);
        }
        match poses_above_places(&let_go, held, call.object, relation, tuning, rng) {
            Ok(found) => poses.extend(found.into_iter().map(|p| p * grip.inverse())),
            Err(failure) => last = failure,
        }
    }
    if poses.is_empty() {
        return Err(last);
    }
    Ok(poses)
}

/// Poses of `held` above the places the world's sampler finds for it (in `let_go`, a copy of
/// the world where the hand has let go of it; [`Tuning::place_tries`] samples): each sample as
/// found and turned half round about its centre (a hand then comes from the other side), at
/// [`Tuning::place_height`] and the [`LOWER_PLACE_HEIGHTS`]. Where the sampler finds no place
/// for it tilted as it is held, it is levelled (see [`levelled`]) and sampled again, as a
/// person sets a thing down upright. Traced: a sock (one compound shape) held 12° off level found no place on a
/// table in 400 samples: the sampler sets an object down by its box, which for a turned
/// compound is its box as built, turned (parry's), deeper than the sock itself; the sock was
/// set short of touching the table and `ontop` did not hold.
fn poses_above_places(
    let_go: &World,
    held: ObjectId,
    target: ObjectId,
    relation: Relation,
    tuning: &Tuning,
    rng: &mut SimRng,
) -> Result<Vec<Pose>, Failure> {
    let mut poses = Vec::new();
    let mut last = Failure::NoHandPose;
    for level in [false, true] {
        let upright;
        let world = if level {
            upright = levelled(let_go, held);
            &upright
        } else {
            let_go
        };
        for _ in 0..tuning.place_tries {
            let mut scratch = world.clone();
            match put(&mut scratch, held, target, relation, rng) {
                Ok(()) => poses.extend(above_place(&scratch, held, tuning.place_height)),
                Err(failure) => last = failure,
            }
        }
        if !poses.is_empty() {
            return Ok(poses);
        }
    }
    Err(last)
}

/// A copy of `world` where `object` is levelled: turned the least that brings its axis
/// nearest the vertical to the vertical (a plate held tipped lies flat again; a can lying on
/// its side stays on its side).
fn levelled(world: &World, object: ObjectId) -> World {
    let mut level = world.clone();
    let pose = level.bodies().pose(object);
    let up = pose.rotation.inverse() * Vector::Z;
    let axis = vertical_axis(pose.rotation);
    let mut local = Vector::ZERO;
    local[axis] = up[axis].signum();
    let correction = Rotation::from_rotation_arc(pose.rotation * local, Vector::Z);
    let upright = Pose::from_parts(pose.translation, correction * pose.rotation);
    // A finite pose turned by a finite rotation: the teleport cannot fail.
    let _ = level.bodies_mut().set_pose(object, upright);
    level
}

/// `object`'s poses above where it lies in `world`: as it lies and turned half round about its
/// centre, at `height` and each of the [`LOWER_PLACE_HEIGHTS`].
fn above_place(world: &World, object: ObjectId, height: f32) -> impl Iterator<Item = Pose> {
    let placed = world.bodies().pose(object);
    let centre = world.bodies().aabb(object).center();
    [0.0, PI].into_iter().flat_map(move |turn| {
        let about = Rotation::from_rotation_z(turn);
        let turned = Pose::from_parts(
            centre + about * (placed.translation - centre),
            about * placed.rotation,
        );
        std::iter::once(height)
            .chain(LOWER_PLACE_HEIGHTS)
            .map(move |h| Pose::from_parts(turned.translation + Vector::Z * h, turned.rotation))
    })
}

/// A seed for the planner drawn from the call's random numbers.
pub(crate) fn rng_seed(rng: &mut SimRng) -> u64 {
    (uniform(rng, 0.0, 1.0) * u32::MAX as f32) as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grasp inset the primitives use by default.
    fn grasp_inset() -> f32 {
        Tuning::default().grasp_inset
    }
    use behavior_sim::{ObjectSpec, Part, Primitive};
    use rapier3d::glamx::EulerRot;

    /// A board 1 × 0.8 m lying flat, turned `yaw` about the vertical.
    fn board(yaw: f32) -> (World, ObjectId) {
        let mut world = World::default();
        let slab = Part::new(Primitive::Box {
            half_extents: Vector::new(0.5, 0.4, 0.01),
        });
        let mut spec = ObjectSpec::new("plywood_1", "plywood.n.01", vec![slab]);
        spec.pose = Pose::from_parts(Vector::new(2.0, 0.0, 0.01), Rotation::from_rotation_z(yaw));
        let id = world.add(spec).unwrap();
        (world, id)
    }

    #[test]
    fn a_turned_board_is_taken_on_the_board_by_its_near_end() {
        for yaw in [0.0, 0.37, 1.2, -2.5] {
            let (world, id) = board(yaw);
            // From the corner of the box around the board, where a turned board leaves floor.
            let b = world.bodies().aabb(id);
            let shoulder = Vector::new(b.mins.x - 0.3, b.mins.y - 0.3, 1.0);
            let at = grasp_point(&world, id, shoulder, grasp_inset());
            let local = world.bodies().pose(id).inverse_transform_point(at);
            let inside = |x: f32, half: f32| x.abs() <= half - grasp_inset() + 1e-4;
            assert!(
                inside(local.x, 0.5) && inside(local.y, 0.4),
                "yaw {yaw}: {local:?} off the board"
            );
            assert!((at.z - b.maxs.z).abs() < 1e-5, "on top: {at:?}");
            // The near end: no point of the board (inset) lies nearer the shoulder.
            let corners = [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)].map(|(sx, sy)| {
                let c = Vector::new(sx * (0.5 - grasp_inset()), sy * (0.4 - grasp_inset()), 0.0);
                world.bodies().pose(id).transform_point(c)
            });
            let d = |p: Vector| (p - shoulder).truncate().length();
            let nearest = corners.iter().map(|&c| d(c)).fold(f32::MAX, f32::min);
            assert!(d(at) <= nearest + 1e-4, "yaw {yaw}: {} > {nearest}", d(at));
        }
    }

    #[test]
    fn an_object_smaller_than_twice_the_inset_is_taken_at_its_middle() {
        let mut world = World::default();
        // Half as wide as the inset one way, a rounding error short of it the other.
        let eraser = Part::new(Primitive::Box {
            half_extents: Vector::new(grasp_inset() * (1.0 - 1e-7), 0.5 * grasp_inset(), 0.01),
        });
        let mut spec = ObjectSpec::new("eraser_1", "eraser.n.01", vec![eraser]);
        spec.pose = Pose::from_parts(Vector::new(1.0, 1.0, 0.5), Rotation::from_rotation_z(0.3));
        let id = world.add(spec).unwrap();
        let at = grasp_point(&world, id, Vector::new(0.0, 3.0, 1.0), grasp_inset());
        let local = world.bodies().pose(id).inverse_transform_point(at);
        assert!(local.x.abs() < 1e-4 && local.y.abs() < 1e-4, "{local:?}");
    }

    /// A table 1.4 × 0.7 m, its top at 0.77 m, and a cylinder 20 cm long, 7 cm across, held
    /// over the floor tilted `tilt` (rad) off level.
    fn table_and_sock(tilt: f32) -> (World, ObjectId, ObjectId) {
        let mut world = World::default();
        let top = Part::new(Primitive::Box {
            half_extents: Vector::new(0.7, 0.35, 0.02),
        });
        let mut spec = ObjectSpec::new("table_1", "table.n.02", vec![top]).fixed();
        spec.pose = Pose::from_parts(Vector::new(0.0, 0.0, 0.75), Rotation::IDENTITY);
        let table = world.add(spec).unwrap();
        let sock = Part::new(Primitive::Cylinder {
            radius: 0.035,
            half_height: 0.1,
        });
        let mut spec = ObjectSpec::new("sock_1", "sock.n.01", vec![sock]);
        let lying = Rotation::from_rotation_x(std::f32::consts::FRAC_PI_2);
        let held = Rotation::from_euler(EulerRot::ZYX, 0.3, tilt, 0.5 * tilt) * lying;
        spec.pose = Pose::from_parts(Vector::new(0.0, 1.5, 1.2), held);
        let sock = world.add(spec).unwrap();
        (world, table, sock)
    }

    #[test]
    fn what_is_held_tilted_is_set_down_level_where_it_finds_no_place_as_it_is() {
        let tuning = Tuning::default();
        let mut rng = behavior_core::rng::seeded(7);
        // Level, the sock is placed as it is held: every place keeps its turn (or its half
        // turn) about the vertical.
        let (world, table, sock) = table_and_sock(0.0);
        let poses =
            poses_above_places(&world, sock, table, Relation::OnTop, &tuning, &mut rng).unwrap();
        let up = |p: &Pose| (p.rotation * Vector::Y).z.abs();
        assert!(poses.iter().all(|p| up(p) > 0.999), "kept as held");
        // 12° off level, the sampler finds no place for it as it is...
        let (world, table, sock) = table_and_sock(0.21);
        let mut tilted = world.clone();
        let placed = (0..tuning.place_tries)
            .filter(|_| put(&mut tilted, sock, table, Relation::OnTop, &mut rng).is_ok())
            .count();
        assert_eq!(placed, 0, "as held, the sock was placed {placed} times");
        // ...so it is set down levelled: lying along the table, touching it.
        let poses =
            poses_above_places(&world, sock, table, Relation::OnTop, &tuning, &mut rng).unwrap();
        assert_eq!(
            poses.len(),
            tuning.place_tries * 2 * (1 + LOWER_PLACE_HEIGHTS.len())
        );
        assert!(
            poses.iter().all(|p| up(p) > 0.999),
            "levelled: {:?}",
            poses[0]
        );
    }
}
