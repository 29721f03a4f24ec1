//! Physical primitives (the paper's fully simulated ones): a plan made with the motion
//! planner, then executed as the robot's own actions, one step of physics each, so that what
//! the robot meets on its way stops it. Here: NAVIGATE_TO for both robots, and the [`Stepper`]
//! that every physical primitive takes its steps through; GRASP and PLACE_* are the robot's
//! manipulator's (`manipulation.rs`). OPEN, CLOSE and the toggles are kinematic in the original's motion-planning
//! mode too, and are done as in symbolic mode.

use crate::edits::RecordedCall;
use crate::execute::RunError;
use crate::execute::Watcher;
use crate::manipulation::manipulator;
use crate::primitive::{Call, Failure};
use crate::symbolic::{call_seed, limited_links, open_all_the_way, stand_for};
use crate::tuning::Tuning;
use behavior_bddl::GroundGoal;
use behavior_core::rng::{SimRng, seeded};
use behavior_core::wrap_angle;
use behavior_core::{DOOR_SYNSET, Predicate};
use behavior_env::Env;
use behavior_motion::PlanError;
use behavior_motion::Standing;
use behavior_motion::{BaseConfig, BaseSpace, home_extent};
use behavior_motion::{PlanParams, Space, plan, steps_along};
use behavior_motion::{Reachable, lattice_plan, reachable_from};
use behavior_robots::{BaseDrive, BaseMove, Robot};
use behavior_sim::{BodyRef, ObjectId, World};
use std::f32::consts::PI;

/// A robot's base path as planned and as executed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BasePath {
    /// The configurations the plan passes through, densified at the space's resolution.
    pub planned: Vec<BaseConfig>,
    /// Where the base was after each step of the execution.
    pub executed: Vec<BaseConfig>,
}

/// NAVIGATE_TO with physics: a place to stand (the symbolic search), a base path there
/// (RRT-Connect in [`BaseSpace`]), then the path driven step by step, each shown to the
/// watcher if one is given. The outer error ends the run (the episode refused a step, or the
/// watcher failed: a recording not written); the inner one is the primitive's.
pub fn drive_to(
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Result<Result<BasePath, Failure>, RunError> {
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    open_doors(&mut steps)?;
    // Best effort: a hand that cannot get there is planned around where it is.
    if let Some(hands) = steps.env.robot().map(manipulator) {
        let _ = hands.tuck(&mut steps)?;
    }
    let planned = match plan_base(steps.env, call, tuning) {
        Ok(path) => path,
        Err(failure) => return Ok(Err(failure)),
    };
    let mut path = BasePath {
        planned,
        executed: Vec::new(),
    };
    for target in path.planned.clone() {
        let mut reached = false;
        for _ in 0..tuning.steps_per_waypoint {
            let Some(action) = drive_toward(steps.env, &target, tuning) else {
                reached = true;
                break;
            };
            if let Err(ended) = steps.act(&action)? {
                return Ok(Err(ended));
            }
            path.executed.push(base_config(steps.env));
        }
        if !reached && drive_toward(steps.env, &target, tuning).is_some() {
            return Ok(Err(Failure::Blocked {
                at: base_config(steps.env),
                toward: target,
            }));
        }
    }
    Ok(Ok(path))
}

/// The edit that opens the home's doors before a drive (`open_doors`), for replays to do
/// again.
pub const DOORS_OPENED: &str = "open_doors";

/// Opens every closed door of the home that the activity does not name all the way, between
/// two steps, recorded as the edit [`DOORS_OPENED`]. The original's motion-primitive example
/// does the same before it navigates ("until we can open doors": every door's Open set fully),
/// and iGibson offers it as `should_open_all_interior_doors`. Base plans go through doors
/// (their leaves are pushed aside, see [`plan_base`]), but what a robot carries beside or
/// ahead of its base met a leaf as the base pushed it: a sheet of plywood's grasp broke on
/// one. A door the activity names keeps its state: its openness may be the goal.
fn open_doors(steps: &mut Stepper<'_, '_>) -> Result<(), RunError> {
    // None closed is no failure: there is nothing to open.
    let _ = steps.env.apply(&RecordedCall::own(DOORS_OPENED, 0))?;
    Ok(())
}

/// `open_doors` in a world whose activity objects are `bindings`: whether any door was
/// closed.
pub(crate) fn open_doors_in(world: &mut World, bindings: &[Option<ObjectId>]) -> bool {
    let closed: Vec<ObjectId> = world
        .bodies()
        .objects()
        .filter(|(id, o)| o.category == DOOR_SYNSET && !bindings.contains(&Some(*id)))
        .map(|(id, _)| id)
        .filter(|&id| !world.state(id, Predicate::Open))
        .collect();
    for &door in &closed {
        let links = limited_links(world, door, None);
        open_all_the_way(world, door, &links);
    }
    !closed.is_empty()
}

/// A physical primitive's outcome: the run's error outside, the primitive's failure inside.
pub(crate) type Attempt<T> = Result<Result<T, Failure>, RunError>;

/// A primitive's failure found before any step (a check, no goal to go to) as its outcome, for
/// [`attempt!`].
pub(crate) fn at_once<T>(result: Result<T, Failure>) -> Attempt<T> {
    Ok(result)
}

/// Unwraps a step's outcome: a failed primitive returns its failure, a failed run its error.
macro_rules! attempt {
    ($e:expr) => {
        match $e? {
            Ok(v) => v,
            Err(failure) => return Ok(Err(failure)),
        }
    };
}
pub(crate) use attempt;

/// The call's own random numbers (the same episode, step and call draw the same).
pub(crate) fn call_rng(env: &Env, call: &Call) -> SimRng {
    seeded(call_seed(
        env.start().map_or(0, |s| s.seed),
        env.steps(),
        call,
    ))
}

/// Forces the assisted grasp of `call.object` by `call.hand` where the hand touches it, as
/// the original does after closing, recorded as the edit [`crate::FORCED_GRASP`] for replays to do
/// again; nothing where it does not touch it.
pub(crate) fn force_grasp(steps: &mut Stepper<'_, '_>, call: &Call) -> Result<(), RunError> {
    // Not touching it is no failure here: the grasp is then not held, which the caller sees.
    let forced = RecordedCall::own_of(steps.env, crate::FORCED_GRASP, call);
    let _ = steps.env.apply(&forced)?;
    Ok(())
}

/// The steps a physical primitive takes, each shown to the watcher if one is given.
pub(crate) struct Stepper<'a, 'w> {
    pub(crate) env: &'a mut Env,
    pub(crate) tuning: &'a Tuning,
    pub(crate) watcher: Option<&'w mut dyn Watcher>,
}

impl Stepper<'_, '_> {
    /// One step with `action`. The outer error ends the run (the episode refused the step, or
    /// the recording failed); the inner one fails the primitive: the episode ended.
    pub(crate) fn act(&mut self, action: &[f32]) -> Result<Result<(), Failure>, RunError> {
        self.env.step(action)?;
        if let Some(r) = crate::execute::again(&mut self.watcher) {
            r.stepped(self.env, action)?;
        }
        if self.env.is_over() {
            return Ok(Err(Failure::Unavailable("the episode ended on the way")));
        }
        Ok(Ok(()))
    }

    /// `n` steps of a still action, or fewer if `done` holds first.
    pub(crate) fn wait_until(
        &mut self,
        n: u32,
        mut done: impl FnMut(&Env) -> bool,
    ) -> Result<Result<(), Failure>, RunError> {
        let still = self
            .env
            .robot()
            .map_or(Vec::new(), |r| r.still_action(r.space()));
        for _ in 0..n {
            if done(self.env) {
                break;
            }
            if let Err(ended) = self.act(&still)? {
                return Ok(Err(ended));
            }
        }
        Ok(Ok(()))
    }
}

/// The densified base path to where the robot will stand for `call.object`.
fn plan_base(env: &Env, call: &Call, tuning: &Tuning) -> Result<Vec<BaseConfig>, Failure> {
    let carrying = env
        .robot()
        .is_some_and(|r| (0..r.hands()).any(|h| r.held(h).is_some()));
    match plan_base_with(env, call, tuning, Leaves::AsObstacles) {
        Err(failure @ Failure::NoPath(_)) if !carrying => {
            plan_base_with(env, call, tuning, Leaves::Pushed).map_err(|_| failure)
        }
        other => other,
    }
}

/// What a base plan makes of the leaves of the home's open doors (see [`hinged_parts`]).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Leaves {
    /// Obstacles: a leaf open against the wall stands beside the way.
    AsObstacles,
    /// Pushed aside like a closed one's: what an empty-handed robot with no other way does (a
    /// bathroom's door opened against a shower closed the corner behind it).
    Pushed,
}

/// [`plan_base`] with the open doors' `leaves` taken as said.
fn plan_base_with(
    env: &Env,
    call: &Call,
    tuning: &Tuning,
    leaves: Leaves,
) -> Result<Vec<BaseConfig>, Failure> {
    let (world, robot) = match (env.world(), env.robot()) {
        (Some(w), Some(r)) => (w, r),
        _ => return Err(Failure::Unavailable("no episode")),
    };
    if robot.space() != robot.spec().primitive_space {
        return Err(Failure::Unavailable(
            "physical primitives drive a robot through its primitive space \
             (the BehaviorRobot's full action space, Fetch's `joints`)",
        ));
    }
    let seed = call_seed(env.start().map_or(0, |s| s.seed), env.steps(), call);
    let mut standing = Standing::of(world, robot);
    // What the robot already overlaps and will push aside — a door opened against it, a box
    // at its feet — is no obstacle to its plan; fixed things still are.
    let pushed = standing.overlapping(world, &standing.config);
    let movable = |b: &BodyRef| b.link.is_some() || !world.bodies().object(b.object).is_fixed();
    standing
        .filter
        .exclude_bodies
        .extend(pushed.into_iter().filter(movable));
    // Hinged and sliding parts — room doors, a cabinet's door left open — are pushed aside on
    // the way: the body is kinematic, a leaf yields on its hinge.
    standing
        .filter
        .exclude_bodies
        .extend(hinged_parts(world, leaves, &opened_by_goal(env)));
    let reach = robot.spec().arm_reach;
    let start = standing.config;
    // The robot stands first where a hand reaches the object from.
    let test = manipulator(robot).reach_test(env, call.object, tuning);
    let arm = test.as_deref();
    // A robot put or pushed into something fixed first backs out of it, by the shortest free
    // move nearby, then plans from there.
    let mut dense = Vec::new();
    let mut from = start;
    let mut last = Failure::NoPlaceToStand;
    let params = PlanParams {
        seed,
        ..tuning.budget
    };
    // A clear place to stand may lie in a pocket no way leads into (between a cabinet and a
    // corner), which the lattice tells at once: then another one, among the places the base
    // reaches from where it starts (flooded once the lattice has said so; a bedroom's stands
    // by a present on the floor lay in three pockets between the bed, the present and a wall).
    let mut reachable: Option<Reachable> = None;
    let mut pocket_tried = false;
    for k in 0..tuning.stand_plans {
        let mut rng = seeded(seed.wrapping_add(k));
        let only = |c: &BaseConfig| reachable.as_ref().is_none_or(|r| r.contains(c));
        let found = stand_for(world, &standing, call.object, reach, arm, &only, &mut rng);
        let Some(goal) = found else {
            break;
        };
        let space = home_space(world, &standing, &start, &goal);
        if k == 0 && !space.free(&start) {
            let out = escape(&space, robot, &start).ok_or(PlanError::StartInCollision)?;
            dense.extend(straight(&start, &out, space.resolution()));
            from = out;
        }
        // Where RRT-Connect's samples miss the way (a door between rooms), the lattice finds it.
        let planned = match plan(&space, &from, &goal, &params) {
            Ok(planned) => Ok(planned.path),
            Err(PlanError::NoPath { .. }) => match lattice_plan(&space, &from, &goal, &params) {
                Err(e @ PlanError::NoLatticePath { .. }) if !pocket_tried => {
                    pocket_tried = true;
                    let region = reachable.get_or_insert_with(|| reachable_from(&space, &from));
                    out_of_pocket(&space, region, &from, &goal, &params).ok_or(e)
                }
                other => other,
            },
            Err(other) => Err(other),
        };
        match planned {
            Ok(path) => {
                dense.extend(steps_along(&space, &path));
                return Ok(dense);
            }
            Err(e) if ends_navigation(&e, &params) => return Err(e.into()),
            Err(other) => {
                if reachable.is_none() && matches!(other, PlanError::NoLatticePath { .. }) {
                    reachable = Some(reachable_from(&space, &from));
                }
                last = other.into();
            }
        }
    }
    Err(last)
}

/// How many times the usual iterations of a base plan's runs a robot in a pocket gets to find
/// its way out.
const POCKET_BUDGET: u32 = 4;

/// A way from `from` to `goal` for a robot standing in a pocket of the lattice (`region`, the
/// cells the lattice reaches from it, holds no cell near the goal), by RRT-Connect with
/// [`POCKET_BUDGET`] times the iterations (a narrow way takes more growing, not more fresh
/// trees: four times the runs found none where four times the iterations did); `None` where
/// the goal lies in the start's region (the lattice's failure stands) or none is found.
/// RRT-Connect's paths turn at any heading, the lattice's at eight: the robot drove into the
/// pocket along such a path (a stand by a window, 20° off the grid), and only such a path
/// leads out.
fn out_of_pocket(
    space: &BaseSpace<'_>,
    region: &Reachable,
    from: &BaseConfig,
    goal: &BaseConfig,
    params: &PlanParams,
) -> Option<Vec<BaseConfig>> {
    if region.contains(goal) {
        return None;
    }
    let wider = PlanParams {
        iterations: params.iterations * POCKET_BUDGET,
        ..*params
    };
    plan(space, from, goal, &wider).ok().map(|p| p.path)
}

/// Whether a base plan's failure ends NAVIGATE_TO rather than sending it to the next stand: a
/// start in collision (no stand helps), or a lattice search that ran out of nodes (seconds
/// spent; where one stand by a wall cannot be turned into, the next one by it is no better).
fn ends_navigation(e: &PlanError, params: &PlanParams) -> bool {
    match e {
        PlanError::StartInCollision => true,
        PlanError::NoLatticePath { expansions, .. } => *expansions >= params.expansions,
        _ => false,
    }
}

/// The base's space from `start` to `goal` for `standing`, sampled anywhere in the home as the
/// July 2021 version did: the way round a table may leave the box around the ends.
fn home_space<'w>(
    world: &'w World,
    standing: &Standing,
    start: &BaseConfig,
    goal: &BaseConfig,
) -> BaseSpace<'w> {
    let space = BaseSpace::new(
        world,
        standing.footprint.clone(),
        standing.filter.clone(),
        start,
        goal,
    );
    match home_extent(world) {
        Some((min, max)) => space.with_bounds(min, max),
        None => space,
    }
}

/// How far a robot overlapping something at its start looks for a way out, m.
const ESCAPE_DISTANCE: f32 = 0.4;
/// The steps of that search, m.
const ESCAPE_STEP: f32 = 0.05;
/// The directions tried at each distance.
const ESCAPE_DIRECTIONS: usize = 16;

/// The nearest free configuration within [`ESCAPE_DISTANCE`] of `start`, heading kept, straight
/// back tried first at each distance: where a robot that overlaps a fixed thing (its body
/// carried into a carcass by a door it opened) gets out without turning (the robot's own
/// motion allows leaving an overlap, never entering one). A holonomic base moves any way, a
/// differential one back or forward only.
fn escape(space: &BaseSpace<'_>, robot: &Robot, start: &BaseConfig) -> Option<BaseConfig> {
    let steps = (ESCAPE_DISTANCE / ESCAPE_STEP).round() as usize;
    let directions: Vec<usize> = match robot.spec().drive {
        BaseDrive::Holonomic => (0..ESCAPE_DIRECTIONS).collect(),
        BaseDrive::Differential => vec![0, ESCAPE_DIRECTIONS / 2],
    };
    (1..=steps).find_map(|k| {
        let d = ESCAPE_STEP * k as f32;
        directions.iter().find_map(|&i| {
            let a = start.yaw + PI + 2.0 * PI * i as f32 / ESCAPE_DIRECTIONS as f32;
            let c = BaseConfig::new(start.x + d * a.cos(), start.y + d * a.sin(), start.yaw);
            space.free(&c).then_some(c)
        })
    })
}

/// The configurations from `a` to `b` on a straight line, heading kept, at most `resolution`
/// apart, without `a`.
fn straight(a: &BaseConfig, b: &BaseConfig, resolution: f32) -> Vec<BaseConfig> {
    let n = ((b.x - a.x).hypot(b.y - a.y) / resolution).ceil().max(1.0) as usize;
    (1..=n)
        .map(|k| {
            let t = k as f32 / n as f32;
            BaseConfig::new(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.yaw)
        })
        .collect()
}

/// Every object's links — the leaves of doors, the doors, lids and drawers of furniture — but,
/// with [`Leaves::AsObstacles`], those of the home's open doors (`open_doors`): a leaf open
/// against the wall stands beside the way, and what the robot carries must pass it; and never
/// those of an open one of `goal_opens`, whose openness is part of the goal (a present's lid
/// opened, then shut by the robot driving past it to the next present). A closed one is
/// pushed as any: a door to be locked stands in the way to the next.
fn hinged_parts(world: &World, leaves: Leaves, goal_opens: &[ObjectId]) -> Vec<BodyRef> {
    let obstacle = |id: ObjectId, category: &str| {
        let open = world.state(id, Predicate::Open);
        let open_door = category == DOOR_SYNSET && open;
        (leaves == Leaves::AsObstacles && open_door) || (open && goal_opens.contains(&id))
    };
    world
        .bodies()
        .objects()
        .filter(|(id, o)| !obstacle(*id, &o.category))
        .flat_map(|(id, o)| (0..o.links.len()).map(move |l| BodyRef::link(id, l)))
        .collect()
}

/// The objects whose openness the activity's goal speaks of (bound to the episode's world).
fn opened_by_goal(env: &Env) -> Vec<ObjectId> {
    let Some(bindings) = env.bindings() else {
        return Vec::new();
    };
    let goal = GroundGoal::new(&env.config().activity);
    goal.atoms
        .iter()
        .filter(|a| a.predicate == Predicate::Open)
        .filter_map(|a| bindings.get(a.subject.0 as usize).copied().flatten())
        .collect()
}

/// The base's configuration on the floor now.
pub fn base_config(env: &Env) -> BaseConfig {
    let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
        return BaseConfig::new(0.0, 0.0, 0.0);
    };
    let pose = robot.base_pose(world);
    let forward = pose.rotation * rapier3d::math::Vector::X;
    BaseConfig::new(
        pose.translation.x,
        pose.translation.y,
        forward.y.atan2(forward.x),
    )
}

/// The action that takes the base one step toward `target`, or `None` when it is there.
fn drive_toward(env: &Env, target: &BaseConfig, tuning: &Tuning) -> Option<Vec<f32>> {
    let robot = env.robot()?;
    let now = base_config(env);
    let (dx, dy) = (target.x - now.x, target.y - now.y);
    let dyaw = wrap_angle(target.yaw - now.yaw);
    if dx.hypot(dy) <= tuning.position_tolerance && dyaw.abs() <= tuning.yaw_tolerance {
        return None;
    }
    let (c, s) = (now.yaw.cos(), now.yaw.sin());
    // The offset in the base's own frame: forward and to the left.
    let step = BaseMove {
        forward: c * dx + s * dy,
        left: -s * dx + c * dy,
        turn: dyaw,
        within: tuning.position_tolerance,
    };
    robot.base_action(step)
}
