//! The task planner agent: from the goal's options and the facts as they are, it picks the
//! option nearest to holding, the next literal of it to make true, and the primitives that
//! make it so (a symbolic model of what each primitive needs and does); runs them, looks at
//! the facts again, and re-plans. A literal that fails [`Limits::tries`] times is given up,
//! with the reason, and options needing it are passed over.
//!
//! Which literal goes next: first those that change an object by a process it must be taken to
//! (cooked, frozen, soaked, cleaned), then placements — an object before what goes on, in,
//! under or next to it, since moving a container leaves its contents behind — and last slicing
//! (the halves stay where the whole was put) and the doors and switches (`open`,
//! `toggled_on`), so that a fridge closes after it is filled.
//! The BehaviorRobot carries objects in its right hand and tools (slicer, cleaning tool) in its
//! left; Fetch, with one gripper, puts one down to take the other.

use crate::execute::Watcher;
use crate::execute::{Mode, RunError, run_with};
use crate::manipulation::{reaches, swings_leaves};
use crate::primitive::{Call, Failure, Primitive};
use crate::symbolic::{container_where, wide_open, within};
use crate::tuning::Tuning;
use behavior_bddl::{GroundGoal, Literal, Predicate, PredicateOracle};
use behavior_core::{Ability, FLOOR_SYNSET};
use behavior_env::Env;
use behavior_motion::floor_gap;
use behavior_sim::{BoundWorld, ObjectId, World};
use serde::Serialize;
use std::collections::BTreeMap;

/// How far the planner goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Primitives run at most (waits included).
    pub primitives: usize,
    /// Goal options considered (smallest first, leaving out those that put an object in two
    /// places at once).
    pub options: usize,
    /// Attempts at one literal before it is given up.
    pub tries: u32,
    /// Waits for one process (cooking, freezing) at most.
    pub waits: u32,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            primitives: 400,
            options: 64,
            tries: 3,
            waits: 120,
        }
    }
}

/// One primitive as it ran.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Executed {
    /// [`Primitive::name`].
    pub name: &'static str,
    /// The object's name.
    pub object: String,
    /// The hand.
    pub hand: usize,
    /// Whether it succeeded.
    pub ok: bool,
    /// Why not.
    pub reason: Option<String>,
    /// How long the primitive itself took, ms (its check and outcome, not the step after).
    pub ms: f64,
    /// The episode's steps it took (one for a symbolic primitive: the still step after it).
    pub steps: u32,
    /// Whether a physical OPEN, CLOSE or toggle was done by the kinematic setter because the
    /// hand could not ([`crate::Outcome::set`]).
    pub set: bool,
}

/// A literal the planner gave up on, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GivenUp {
    /// The literal, as BDDL writes it.
    pub literal: String,
    /// The last failure.
    pub reason: String,
}

/// How a solve went.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Solution {
    /// The goal held at the end.
    pub success: bool,
    /// Q at the end.
    pub q_final: f64,
    /// What ran, in order.
    pub primitives: Vec<Executed>,
    /// Literals given up.
    pub given_up: Vec<GivenUp>,
    /// Why it stopped.
    pub stopped: String,
}

/// Navigations to one object before it is given up as out of reach (the 2.0.x primitives').
const NAVIGATE_ATTEMPTS: usize = 10;
/// Places a physical WIPE is done from at most, while each takes some of the dirt.
const WIPE_STANDS: usize = 4;
/// Physical navigations in a row that may fail, nothing else run between them, before the
/// robot counts as stuck where it stands and the next ones are not tried (a robot holding a
/// book found no way to the shelf or the floor 60 times in a row).
const STUCK_AFTER: usize = 6;

/// Physical navigations to one object that may fail (no place to stand, no way there) before
/// it is given up: each has tried several places to stand already, and a robot carrying a book
/// spent 9 minutes in 60 failing ones, 30 each to the shelf and to the floor.
const NAVIGATE_FAILURES: usize = 3;

/// The right hand carries, the left holds tools (Fetch: its one gripper for both).
const CARRY: usize = 1;
const TOOL: usize = 0;

/// The planner at work on one episode.
pub struct Solver<'a> {
    env: &'a mut Env,
    mode: Mode,
    limits: Limits,
    /// The physical primitives' settings.
    tuning: Tuning,
    watcher: Option<&'a mut dyn Watcher>,
    observer: &'a mut dyn FnMut(&Executed),
    log: Vec<Executed>,
    /// How often each literal was tried and still did not hold.
    tries: BTreeMap<Literal, u32>,
    given_up: Vec<(Literal, String)>,
    /// How often each literal was made true.
    made: BTreeMap<Literal, u32>,
    /// The option (index) followed.
    following: Option<usize>,
    /// An error that ends the solve (the recording could not be written).
    fatal: Option<RunError>,
    /// Whether the next approach stands somewhere new even if in reach: a physical grasp or
    /// placement failed from where the robot stands, and would fail there again.
    stand_again: bool,
}

/// Why a step of a recipe failed: a primitive's failure, or something the planner lacks.
type Reason = String;

impl<'a> Solver<'a> {
    /// A planner for the episode `env` has just reset; `observer` sees every primitive as it
    /// ends, and `watcher`, if given, every step and edit (a recording, a video).
    pub fn new(
        env: &'a mut Env,
        mode: Mode,
        limits: Limits,
        watcher: Option<&'a mut dyn Watcher>,
        observer: &'a mut dyn FnMut(&Executed),
    ) -> Solver<'a> {
        Solver {
            env,
            mode,
            limits,
            tuning: Tuning::default(),
            watcher,
            observer,
            log: Vec::new(),
            tries: BTreeMap::new(),
            given_up: Vec::new(),
            made: BTreeMap::new(),
            following: None,
            fatal: None,
            stand_again: false,
        }
    }

    /// The solver with the physical primitives' settings `tuning` instead of the defaults.
    pub fn with_tuning(mut self, tuning: Tuning) -> Solver<'a> {
        self.tuning = tuning;
        self
    }

    /// Plans and runs until the goal holds, the episode ends, the budget is spent or no
    /// option is left.
    pub fn solve(mut self) -> Result<Solution, RunError> {
        if self.env.world().is_none() {
            return Err(RunError::Env(behavior_env::EnvError::NotReset));
        }
        let activity = self.env.config().activity.clone();
        let goal = GroundGoal::new(&activity).assuming_false(|a| a.object == Some(a.subject));
        let options: Vec<Vec<Literal>> = behavior_bddl::options::options(&goal)
            .take(OPTIONS_SCANNED)
            .filter(|o| !in_two_places(o))
            .take(self.limits.options)
            .collect();
        let stopped = loop {
            if self.env.score().is_some_and(|s| s.success) {
                break "the goal holds".to_string();
            }
            if self.env.is_over() {
                break "the episode is over (step limit)".to_string();
            }
            if self.log.len() >= self.limits.primitives {
                break format!("{} primitives run", self.log.len());
            }
            let Some(literal) = self.next_literal(&options) else {
                break "every option needs a literal given up".to_string();
            };
            let result = self.achieve(literal);
            if let Some(fatal) = self.fatal.take() {
                return Err(fatal);
            }
            if !self.holds(&literal) {
                let reason = result
                    .err()
                    .unwrap_or_else(|| "done, but it does not hold".into());
                self.failed(literal, reason);
            } else if bump(&mut self.made, literal) > self.limits.tries {
                let reason = "made true again and again, undone by what came after".to_string();
                self.given_up.push((literal, reason));
            }
        };
        Ok(Solution {
            success: self.env.score().is_some_and(|s| s.success),
            q_final: self.env.score().map_or(0.0, |s| s.q),
            primitives: self.log,
            given_up: self
                .given_up
                .iter()
                .map(|(l, reason)| GivenUp {
                    literal: activity.show_literal(*l),
                    reason: reason.clone(),
                })
                .collect(),
            stopped,
        })
    }

    fn failed(&mut self, literal: Literal, reason: Reason) {
        if bump(&mut self.tries, literal) >= self.limits.tries {
            self.given_up.push((literal, reason));
        }
    }

    /// The episode's world: [`Solver::solve`] runs only once the environment is reset.
    fn world(&self) -> &World {
        self.env
            .world()
            .expect("solve checked that an episode runs")
    }

    fn holds(&self, literal: &Literal) -> bool {
        let (Some(world), Some(bindings)) = (self.env.world(), self.env.bindings()) else {
            return false;
        };
        BoundWorld { world, bindings }.holds(literal.atom) == literal.positive
    }

    /// The next literal to make true: of the option with fewest unmet literals and none given
    /// up — the one followed so far while no other has fewer, so that two options that undo
    /// each other's literals are not taken in turn — the first by the order in the module docs.
    fn next_literal(&mut self, options: &[Vec<Literal>]) -> Option<Literal> {
        let given_up = |l: &Literal| self.given_up.iter().any(|(g, _)| g == l);
        let unmet: Vec<Option<Vec<Literal>>> = options
            .iter()
            .map(|o| {
                (!o.iter().any(given_up))
                    .then(|| o.iter().filter(|l| !self.holds(l)).copied().collect())
            })
            .collect();
        let best = (0..options.len())
            .filter(|&k| unmet[k].is_some())
            .min_by_key(|&k| unmet[k].as_ref().map_or(usize::MAX, Vec::len))?;
        let fewest = unmet[best].as_ref().map_or(0, Vec::len);
        let chosen = match self.following {
            Some(k) if unmet[k].as_ref().is_some_and(|u| u.len() <= fewest) => k,
            _ => best,
        };
        self.following = Some(chosen);
        let unmet = unmet[chosen].as_deref().unwrap_or_default();
        let placed_first = |l: &Literal| {
            l.atom.object.is_some_and(|target| {
                unmet
                    .iter()
                    .any(|o| o.positive && o.atom.object.is_some() && o.atom.subject == target)
            })
        };
        unmet
            .iter()
            .min_by_key(|l| (phase(l), placed_first(l)))
            .copied()
    }

    fn object(&self, instance: behavior_bddl::InstanceId) -> Result<ObjectId, Reason> {
        self.env
            .bindings()
            .and_then(|b| b.get(instance.0 as usize).copied().flatten())
            .ok_or_else(|| format!("instance {} is bound to no object", instance.0))
    }

    /// Runs the primitives that should make `literal` hold.
    fn achieve(&mut self, literal: Literal) -> Result<(), Reason> {
        let x = self.object(literal.atom.subject)?;
        let target = literal.atom.object.map(|t| self.object(t)).transpose()?;
        let p = literal.atom.predicate;
        match (p, target, literal.positive) {
            (_, Some(y), true) => self.place(x, p, y),
            (_, Some(_), false) => {
                self.hold(x, CARRY)?;
                self.put_down(CARRY)
            }
            (Predicate::Cooked | Predicate::Burnt, None, true) => {
                self.process(x, Ability::HeatSource, literal)
            }
            (Predicate::Frozen, None, true) => self.process(x, Ability::ColdSource, literal),
            (Predicate::Frozen, None, false) => self.thaw(x, literal),
            (Predicate::Soaked, None, true) => {
                self.hold(x, CARRY)?;
                self.soak(CARRY)
            }
            (Predicate::Dusty | Predicate::Stained, None, false) => self.clean(x, p),
            (Predicate::Sliced, None, true) => {
                let knife = self
                    .find(Ability::Slicer, x)
                    .ok_or("no slicer in the home")?;
                self.hold(knife, self.tool_hand())?;
                // A knife does not reach through a shut door (making_tea's lemon lay in the
                // refrigerator); the symbolic check asks only for reach, as the original's.
                if self.mode == Mode::Physical {
                    self.open_around(x, CARRY)?;
                }
                self.approach(x)?;
                self.call(Primitive::Slice, x, self.tool_hand())
            }
            (Predicate::Open, None, v) => {
                self.approach(x)?;
                self.call(if v { Primitive::Open } else { Primitive::Close }, x, CARRY)
            }
            (Predicate::ToggledOn, None, v) => {
                self.approach(x)?;
                self.call(
                    if v {
                        Primitive::ToggleOn
                    } else {
                        Primitive::ToggleOff
                    },
                    x,
                    CARRY,
                )
            }
            _ => Err(format!(
                "no primitive makes {}{} true",
                if literal.positive { "" } else { "not " },
                p.name()
            )),
        }
    }

    fn tool_hand(&self) -> usize {
        if self.env.robot().map_or(1, |r| r.hands()) > 1 {
            TOOL
        } else {
            0
        }
    }

    fn carry_hand(&self) -> usize {
        if self.env.robot().map_or(1, |r| r.hands()) > 1 {
            CARRY
        } else {
            0
        }
    }

    /// The hand that presses a switch or swings a door for a recipe that asked for `asked`:
    /// that one if it is empty, else an empty one (a hand holding a towel to soak pressed the
    /// tap with it, and the towel met the tap; a hand holding a plate cannot take a door's
    /// edge), else that one.
    fn empty_hand_for(&self, asked: usize) -> usize {
        let asked = if asked == CARRY {
            self.carry_hand()
        } else {
            asked
        };
        let Some(robot) = self.env.robot() else {
            return asked;
        };
        if robot.held(asked).is_none() {
            return asked;
        }
        (0..robot.hands())
            .find(|&h| robot.held(h).is_none())
            .unwrap_or(asked)
    }

    /// Runs one primitive; its failure is the recipe's.
    fn call(&mut self, primitive: Primitive, object: ObjectId, hand: usize) -> Result<(), Reason> {
        let by_hand = [
            Primitive::ToggleOn,
            Primitive::ToggleOff,
            Primitive::Open,
            Primitive::Close,
        ];
        let hand = if by_hand.contains(&primitive) {
            self.empty_hand_for(hand)
        } else if primitive.uses_hand() && hand == CARRY {
            self.carry_hand()
        } else {
            hand
        };
        let call = Call {
            primitive,
            object,
            hand,
        };
        let drive = self.mode == Mode::Physical && primitive == Primitive::NavigateTo;
        if drive && self.failed_drives() >= STUCK_AFTER {
            return Err(format!(
                "stuck: the last {STUCK_AFTER} navigations found no way, nothing else tried since"
            ));
        }
        let before = self.env.steps();
        let outcome = match run_with(
            self.env,
            call,
            self.mode,
            &self.tuning,
            crate::execute::again(&mut self.watcher),
        ) {
            Ok(outcome) => outcome,
            Err(e) => {
                let reason = e.to_string();
                // A recording that cannot be written ends the solve; an episode that ended
                // just ends this recipe.
                if matches!(e, RunError::Record(_)) {
                    self.fatal = Some(e);
                }
                return Err(reason);
            }
        };
        let executed = Executed {
            name: primitive.name(),
            object: self.world().bodies().object(object).name.clone(),
            hand,
            ok: outcome.result.is_ok(),
            reason: outcome.result.as_ref().err().map(Failure::to_string),
            ms: outcome.seconds * 1000.0,
            steps: self.env.steps() - before,
            set: outcome.set,
        };
        let manipulates = matches!(
            primitive,
            Primitive::Grasp | Primitive::Soak | Primitive::Wipe
        ) || primitive.relation().is_some();
        if self.mode == Mode::Physical && manipulates && !executed.ok {
            self.stand_again = true;
        }
        (self.observer)(&executed);
        self.log.push(executed);
        outcome.result.map_err(|e| {
            format!(
                "{} {}: {e}",
                primitive.name(),
                self.world().bodies().object(object).name
            )
        })
    }

    /// The navigations that failed last, in a row, nothing else run between them.
    fn failed_drives(&self) -> usize {
        let navigate = Primitive::NavigateTo.name();
        self.log
            .iter()
            .rev()
            .take_while(|e| e.name == navigate && !e.ok)
            .count()
    }

    /// Stands where `x` is in reach, if it is not: next to it, or next to what holds it, up to
    /// [`NAVIGATE_ATTEMPTS`] times (the 2.0.x primitives' `navigate_if_needed`).
    fn approach(&mut self, x: ObjectId) -> Result<(), Reason> {
        self.approach_for(x, None)
    }

    /// As [`Self::approach`]; for a physical `placement` (a PLACE_* call on `x`), in reach
    /// means within a hand's reach of a place the world's sampler finds, not of the nearest
    /// corner of `x`'s box (which left an ashcan's inside 1.2 m away).
    fn approach_for(&mut self, x: ObjectId, placement: Option<Call>) -> Result<(), Reason> {
        let mut last = String::new();
        let mut failed = 0;
        let may_fail = match self.mode {
            Mode::Physical => NAVIGATE_FAILURES,
            Mode::Symbolic => NAVIGATE_ATTEMPTS,
        };
        let mut tried = 0;
        for _ in 0..NAVIGATE_ATTEMPTS {
            if failed == may_fail {
                break;
            }
            tried += 1;
            let robot = self.env.robot().ok_or("no robot")?;
            let near = !std::mem::take(&mut self.stand_again)
                && within(self.world(), robot, x, self.mode.reach())
                && (self.mode == Mode::Symbolic
                    || reaches(self.env, x, placement.as_ref(), &self.tuning));
            if near {
                return Ok(());
            }
            let result = match self.call(Primitive::NavigateTo, x, CARRY) {
                Err(first) => match self.holder(x) {
                    Some(c) => self.call(Primitive::NavigateTo, c, CARRY),
                    None => Err(first),
                },
                ok => ok,
            };
            if let Err(why) = result {
                last = why;
                failed += 1;
            }
        }
        Err(if last.is_empty() {
            let name = &self.world().bodies().object(x).name;
            format!(
                "{name} not in reach after {NAVIGATE_ATTEMPTS} navigations, each of which arrived"
            )
        } else {
            format!("{last} (not in reach after {tried} navigations, {failed} of which failed)")
        })
    }

    /// What `x` is in or on, if anything.
    fn holder(&self, x: ObjectId) -> Option<ObjectId> {
        let world = self.world();
        world.bodies().objects().map(|(id, _)| id).find(|&c| {
            c != x
                && world.bodies().object(c).is_present()
                && (world.relations().inside(x, c) || world.relations().ontop(x, c))
        })
    }

    /// Gets `x` into `hand`: puts down what the hand holds, goes to it, opens its container.
    fn hold(&mut self, x: ObjectId, hand: usize) -> Result<(), Reason> {
        let hand = if hand == CARRY {
            self.carry_hand()
        } else {
            hand
        };
        let robot = self.env.robot().ok_or("no robot")?;
        if robot.held(hand) == Some(x) {
            return Ok(());
        }
        if let Some(other) = (0..robot.hands()).find(|&h| robot.held(h) == Some(x)) {
            self.put_down(other)?;
        }
        if self.env.robot().and_then(|r| r.held(hand)).is_some() {
            self.put_down(hand)?;
        }
        self.open_around(x, hand)?;
        self.approach(x)?;
        self.call(Primitive::Grasp, x, hand)
    }

    /// Opens, with `hand`, the container `x` lies in where it must be opened before a hand
    /// reaches in ([`Self::to_open`]).
    fn open_around(&mut self, x: ObjectId, hand: usize) -> Result<(), Reason> {
        if let Some(c) = container_where(self.world(), x, |c| self.to_open(c)) {
            self.approach(c)?;
            self.call(Primitive::Open, c, hand)?;
        }
        Ok(())
    }

    /// Whether the openable `c` must be opened before a hand takes from it or puts into it:
    /// shut, or in physical mode not open all the way ([`wide_open`]: a door ajar stops the
    /// hand).
    fn to_open(&self, c: ObjectId) -> bool {
        match self.mode {
            Mode::Physical => !wide_open(self.world(), c),
            Mode::Symbolic => !self.world().state(c, Predicate::Open),
        }
    }

    /// Puts what `hand` holds on the floor of the room the robot is in (or is nearest).
    fn put_down(&mut self, hand: usize) -> Result<(), Reason> {
        let world = self.world();
        let at = self
            .env
            .robot()
            .ok_or("no robot")?
            .base_pose(world)
            .translation;
        let gap = |r: &&behavior_sim::Room| {
            r.rects()
                .map(|p| floor_gap(p.min, p.max, at.x, at.y))
                .fold(f32::MAX, f32::min)
        };
        let floor = world
            .rooms()
            .iter()
            .filter(|r| r.floor.is_some())
            .min_by(|a, b| gap(a).total_cmp(&gap(b)))
            .and_then(|r| r.floor)
            .ok_or("the home has no floors")?;
        self.call(Primitive::PlaceOnFloor, floor, hand)
    }

    /// A placement: `x` carried to `y` and put on, in, under or next to it.
    fn place(&mut self, x: ObjectId, p: Predicate, y: ObjectId) -> Result<(), Reason> {
        // A sliced object relates as its halves do, both of them: each that does not is placed.
        if let Some(halves) = self.world().bodies().object(x).replaced_by {
            for half in halves {
                if !self.world().relations().relation(p, half, y) {
                    self.place(half, p, y)?;
                }
            }
            return Ok(());
        }
        let primitive = match p {
            Predicate::OnTop | Predicate::Touching => Primitive::PlaceOnTop,
            Predicate::Inside => Primitive::PlaceInside,
            Predicate::NextTo => Primitive::PlaceNextTo,
            Predicate::Under => Primitive::PlaceUnder,
            Predicate::OnFloor => Primitive::PlaceOnFloor,
            other => return Err(format!("{} is not a placement", other.name())),
        };
        // A robot that swings doors by hand opens the furniture `x` goes into (or into whose
        // shelves) before it takes `x`: a hand holding a plate while the other swung a cabinet's
        // door open had the door strike the plate from its grasp. A door that is set (a movable
        // box's lid, any door of a robot whose arm cannot swing it) is opened as before, once
        // `x` is held: opened first, Fetch drove ten times to a file cabinet whose drawer the
        // setter had opened before it took the document, and found no stand to put it in from.
        let carried = self.env.robot().and_then(|r| r.held(self.carry_hand())) == Some(x);
        let fixed = |o: ObjectId| self.world().bodies().object(o).is_fixed();
        let swung = fixed(y) || container_where(self.world(), y, fixed).is_some();
        let by_hand = self.mode == Mode::Physical && swings_leaves(self.env);
        if by_hand && swung && !carried {
            self.open_for(primitive, y)?;
        }
        self.hold(x, CARRY)?;
        self.open_for(primitive, y)?;
        if primitive == Primitive::PlaceOnFloor {
            self.call(Primitive::NavigateTo, y, CARRY)?;
        } else {
            let call = Call {
                primitive,
                object: y,
                hand: self.carry_hand(),
            };
            self.approach_for(y, Some(call))?;
        }
        self.call(primitive, y, CARRY)
    }

    /// Opens what a placement by `primitive` into or onto `y` needs open: `y` itself for
    /// PLACE_INSIDE, and with physics the container `y` lies in (a hand reaches a dish in a
    /// cabinet only through the cabinet's open door; the symbolic primitives, as the
    /// original's, ask only of `y` itself).
    fn open_for(&mut self, primitive: Primitive, y: ObjectId) -> Result<(), Reason> {
        if primitive == Primitive::PlaceInside
            && self.world().bodies().object(y).has(Ability::Openable)
            && self.to_open(y)
        {
            self.approach(y)?;
            self.call(Primitive::Open, y, CARRY)?;
        }
        if self.mode == Mode::Physical
            && primitive != Primitive::PlaceOnFloor
            && let Some(c) = container_where(self.world(), y, |c| self.to_open(c))
        {
            self.approach(c)?;
            self.call(Primitive::Open, c, CARRY)?;
        }
        Ok(())
    }

    /// Cooking or freezing: `x` taken to a source of `ability`, put on or in it as the source
    /// needs, the source closed and switched on as it needs, then time let pass.
    fn process(&mut self, x: ObjectId, ability: Ability, literal: Literal) -> Result<(), Reason> {
        let source = self
            .find(ability, x)
            .ok_or_else(|| format!("no {} in the home", ability.name()))?;
        let (inside, on, closed) = {
            let s = self.world().bodies().object(source);
            (
                s.flag(ability, "requires_inside", false),
                s.flag(ability, "requires_toggled_on", false),
                s.flag(ability, "requires_closed", false),
            )
        };
        if inside {
            self.place(x, Predicate::Inside, source)?;
        } else {
            self.place(x, Predicate::OnTop, source)?;
        }
        if closed && self.world().state(source, Predicate::Open) {
            self.call(Primitive::Close, source, CARRY)?;
        }
        if on && !self.world().state(source, Predicate::ToggledOn) {
            self.call(Primitive::ToggleOn, source, CARRY)?;
        }
        self.wait_until(literal)
    }

    /// Thawing: `x` taken out of the cold it lies in or on (a refrigerator, where waiting
    /// never thaws it) and put down in the room, then time let pass.
    fn thaw(&mut self, x: ObjectId, literal: Literal) -> Result<(), Reason> {
        let world = self.world();
        let cold = world.bodies().objects().any(|(c, o)| {
            c != x
                && o.is_present()
                && o.has(Ability::ColdSource)
                && (world.relations().inside(x, c) || world.relations().ontop(x, c))
        });
        if cold {
            self.hold(x, CARRY)?;
            self.put_down(CARRY)?;
        }
        self.wait_until(literal)
    }

    fn wait_until(&mut self, literal: Literal) -> Result<(), Reason> {
        for _ in 0..self.limits.waits {
            if self.holds(&literal) || self.env.is_over() {
                return Ok(());
            }
            let anything = self
                .env
                .bindings()
                .and_then(|b| b.iter().flatten().next().copied());
            self.call(Primitive::Wait, anything.ok_or("no objects")?, CARRY)?;
        }
        Err(format!("still not so after {} waits", self.limits.waits))
    }

    /// Soaks what `hand` holds at a water source, switched on first.
    fn soak(&mut self, hand: usize) -> Result<(), Reason> {
        let hand = if hand == CARRY {
            self.carry_hand()
        } else {
            hand
        };
        let held = self
            .env
            .robot()
            .and_then(|r| r.held(hand))
            .ok_or("the hand is empty")?;
        let water = self
            .find(Ability::WaterSource, held)
            .ok_or("no water source in the home")?;
        self.approach(water)?;
        if self.world().bodies().object(water).has(Ability::Toggleable)
            && !self.world().state(water, Predicate::ToggledOn)
        {
            self.call(Primitive::ToggleOn, water, hand)?;
        }
        self.call(Primitive::Soak, water, hand)
    }

    /// Dust or stains off `y` with a cleaning tool, soaked first for stains.
    fn clean(&mut self, y: ObjectId, dirt: Predicate) -> Result<(), Reason> {
        let soaks = dirt == Predicate::Stained;
        let tool = self
            .find_with(Ability::CleaningTool, y, |o| {
                !soaks || o.has(Ability::Soakable)
            })
            .ok_or("no cleaning tool in the home that does this")?;
        let hand = self.tool_hand();
        self.hold(tool, hand)?;
        if dirt == Predicate::Stained && !self.world().state(tool, Predicate::Soaked) {
            self.soak(hand)?;
        }
        // A physical wipe takes the dirt its hand reaches from where the robot stands; what
        // is big (a car's roof) is wiped from one stand after another while each takes some.
        let mut stands = 0;
        loop {
            self.approach(y)?;
            let before = self.dirt_left(y);
            let wiped = self.call(Primitive::Wipe, y, hand);
            stands += 1;
            let progress = self.dirt_left(y) < before;
            match wiped {
                Err(_) if self.mode == Mode::Physical && progress && stands < WIPE_STANDS => {
                    self.stand_again = true;
                }
                done => return done,
            }
        }
    }

    /// The dust and stain particles left on `y`.
    fn dirt_left(&self, y: ObjectId) -> usize {
        [Predicate::Dusty, Predicate::Stained]
            .iter()
            .map(|&k| self.world().particle_positions(y, k).len())
            .sum()
    }
}

impl Solver<'_> {
    /// An object with `ability` to use on `near`: one of the activity's if any, else the
    /// home's nearest.
    fn find(&self, ability: Ability, near: ObjectId) -> Option<ObjectId> {
        self.find_with(ability, near, |_| true)
    }

    /// [`Solver::find`] among the objects `also` accepts.
    fn find_with(
        &self,
        ability: Ability,
        near: ObjectId,
        also: impl Fn(&behavior_sim::Object) -> bool,
    ) -> Option<ObjectId> {
        let world = self.world();
        let bound = self.env.bindings().unwrap_or_default();
        let robot: Vec<ObjectId> = self.env.robot().map(|r| r.objects()).unwrap_or_default();
        let at = world.bodies().aabb(near).center();
        world
            .bodies()
            .objects()
            .filter(|(id, o)| {
                *id != near
                    && o.is_present()
                    && o.has(ability)
                    && also(o)
                    && !robot.contains(id)
                    && o.category != FLOOR_SYNSET
            })
            .map(|(id, _)| {
                let distance = (world.bodies().aabb(id).center() - at).length();
                (!bound.contains(&Some(id)), distance, id)
            })
            .min_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)).then(a.2.cmp(&b.2)))
            .map(|(_, _, id)| id)
    }
}

/// Options looked at, at most, for [`Limits::options`] that are not in two places at once
/// (a goal of `forn` over many objects has millions).
const OPTIONS_SCANNED: usize = 10_000;

/// Whether an option asks an object to be on two things, or in two things, at once: no
/// placement makes both hold (three candles on each of two tables, where an option may ask for
/// one candle on both).
fn in_two_places(option: &[Literal]) -> bool {
    option.iter().enumerate().any(|(k, a)| {
        a.positive
            && matches!(a.atom.predicate, Predicate::OnTop | Predicate::Inside)
            && option[k + 1..].iter().any(|b| {
                b.positive
                    && b.atom.predicate == a.atom.predicate
                    && b.atom.subject == a.atom.subject
                    && b.atom.object != a.atom.object
            })
    })
}

/// Counts one more for `literal`; the count now.
fn bump(counts: &mut BTreeMap<Literal, u32>, literal: Literal) -> u32 {
    let n = counts.entry(literal).or_insert(0);
    *n += 1;
    *n
}

/// Processes first, placements next, then slicing (the halves stay where the whole was put)
/// and doors and switches last.
fn phase(l: &Literal) -> u8 {
    match l.atom.predicate {
        _ if l.atom.object.is_some() => 1,
        Predicate::Open | Predicate::ToggledOn | Predicate::Sliced => 2,
        _ => 0,
    }
}
