//! Running primitives in an environment: each is done between two steps ([`Env::apply`], a
//! recorded edit; a physical one by steps of its own) and followed by one step of a still
//! action, as the original's primitive environment does, so that reward, done and observation
//! come from that step.

use crate::edits::{EditError, RecordedCall};
use crate::primitive::{Call, Failure, Primitive, WAIT_STEPS};
use crate::tuning::Tuning;
use crate::{manipulation, physical};
use behavior_env::{Env, EnvError, Info, Step};
use behavior_robots::{ActionSpace, RobotKind};
use serde::{Deserialize, Serialize};

/// How far across the floor from the base an object's box may be for the task planner to
/// try a physical primitive on it before it stands again, m: what a BehaviorRobot's hand (1.2 m
/// from a shoulder 1 m above the floor) and Fetch's arm reach of a table's far side. Where the
/// base stands for an object is planned with each robot's own
/// [`behavior_robots::EmbodimentSpec::arm_reach`].
pub const ARM_REACH: f32 = 1.0;

/// How primitives act: setting outcomes, or moving the robot through its controllers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Check, then set the outcome (the paper's partially simulated primitives).
    Symbolic,
    /// Plan and execute with physics (the fully simulated ones).
    Physical,
}

impl Mode {
    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Symbolic => "symbolic",
            Mode::Physical => "physical",
        }
    }

    /// How near an object the planner stands before acting on it: the primitives' 2 m
    /// ([`behavior_robots::REACH_DISTANCE`]) when outcomes are set, [`ARM_REACH`] when a hand
    /// or an arm must get there.
    pub fn reach(self) -> f32 {
        match self {
            Mode::Symbolic => behavior_robots::REACH_DISTANCE,
            Mode::Physical => ARM_REACH,
        }
    }

    /// The action space an environment's robot of `kind` is driven through for primitives of
    /// this mode: its [`behavior_robots::EmbodimentSpec::primitive_space`] when physical (Fetch's
    /// [`ActionSpace::Joints`], so that its arm's plans are executed as planned); its full space
    /// otherwise.
    pub fn action_space(self, kind: RobotKind) -> ActionSpace {
        match self {
            Mode::Physical => kind.spec().primitive_space,
            Mode::Symbolic => ActionSpace::Full,
        }
    }

    /// The mode of a name.
    pub fn from_name(name: &str) -> Option<Mode> {
        [Mode::Symbolic, Mode::Physical]
            .into_iter()
            .find(|m| m.name() == name)
    }
}

/// Why running a primitive stopped the episode's run (as opposed to the primitive failing,
/// which is an outcome).
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The environment refused (no episode, or it is over).
    #[error(transparent)]
    Env(#[from] EnvError),
    /// The recording could not be written.
    #[error(transparent)]
    Record(#[from] behavior_env::record::RecordError),
    /// Another [`Watcher`] failed (a video could not be written): why.
    #[error("{0}")]
    Watcher(String),
}

/// What sees each step a primitive takes: a video, a viewer (the episode records itself:
/// [`Env::record_to`]). Its error ends the run.
pub trait Watcher {
    /// After a step taken with `action`.
    fn stepped(&mut self, env: &Env, action: &[f32]) -> Result<(), RunError>;
}

/// The watcher once more, for one call (an `Option<&mut dyn Watcher>` does not reborrow as
/// another by itself).
pub(crate) fn again<'b>(watcher: &'b mut Option<&mut dyn Watcher>) -> Option<&'b mut dyn Watcher> {
    match watcher {
        Some(w) => Some(&mut **w),
        None => None,
    }
}

/// What one primitive did.
#[derive(Debug)]
pub struct Outcome {
    /// Done, or why not.
    pub result: Result<(), Failure>,
    /// How long the primitive itself took, s: its check and outcome (in physical mode its plan
    /// and the steps that execute it), not the still step after it.
    pub seconds: f64,
    /// The last step it took (a wait takes [`WAIT_STEPS`], any other one).
    pub step: Step,
    /// Whether a physical OPEN, CLOSE or toggle fell back to the kinematic setter (the hand
    /// could not do it; recorded as an edit).
    pub set: bool,
}

/// Runs one primitive in `mode` and the steps after it, each shown to `watcher` if given, with
/// the physical primitives' default [`Tuning`].
pub fn run(
    env: &mut Env,
    call: Call,
    mode: Mode,
    watcher: Option<&mut dyn Watcher>,
) -> Result<Outcome, RunError> {
    run_with(env, call, mode, &Tuning::default(), watcher)
}

/// [`run`] with the physical primitives' settings `tuning`.
pub fn run_with(
    env: &mut Env,
    call: Call,
    mode: Mode,
    tuning: &Tuning,
    mut watcher: Option<&mut dyn Watcher>,
) -> Result<Outcome, RunError> {
    let began = std::time::Instant::now();
    let mut set = false;
    let result = match (mode, call.primitive) {
        (_, Primitive::Wait) => Ok(()),
        (Mode::Physical, Primitive::NavigateTo) => {
            physical::drive_to(env, &call, tuning, again(&mut watcher))?.map(|_| ())
        }
        (Mode::Symbolic, _) => apply(env, &call)?,
        // A door, lid or drawer is taken by hand and swung (`doors.rs`); a switch is pressed by
        // hand (`tools.rs`). Where the hand cannot — no pose before the leaf or no way to the
        // button (a tap's button between the tap and the wall), a full hand, a movable box's
        // lid, a leaf that jams on its neighbour, a press without effect — the state is set as
        // the original's motion-planning mode sets every door and switch, recorded as an edit.
        (Mode::Physical, Primitive::Open | Primitive::Close) => {
            let swung = manipulation::swing(env, &call, tuning, again(&mut watcher))?;
            or_set(env, &call, swung, |_| true, &mut set)?
        }
        (Mode::Physical, Primitive::ToggleOn | Primitive::ToggleOff) => {
            let pressed = manipulation::press(env, &call, tuning, again(&mut watcher))?;
            let unpressable = |f: &Failure| {
                matches!(
                    f,
                    Failure::NoHandPose
                        | Failure::NoPath(_)
                        | Failure::HandBlocked
                        | Failure::NoEffect(_)
                )
            };
            or_set(env, &call, pressed, unpressable, &mut set)?
        }
        (Mode::Physical, Primitive::Grasp) => {
            manipulation::grasp(env, &call, tuning, again(&mut watcher))?
        }
        (Mode::Physical, Primitive::Soak | Primitive::Wipe | Primitive::Slice) => {
            manipulation::use_tool(env, &call, tuning, again(&mut watcher))?
        }
        (Mode::Physical, p) => match p.relation() {
            Some(r) => manipulation::place(env, &call, r, tuning, again(&mut watcher))?,
            None => Err(Failure::Unavailable("no physical form of this primitive")),
        },
    };
    let seconds = began.elapsed().as_secs_f64();
    let steps = if call.primitive == Primitive::Wait {
        WAIT_STEPS
    } else {
        1
    };
    // A physical primitive that ended the episode on its way (the goal reached, or the step
    // limit) leaves no step to take: its last one stands.
    if env.is_over() {
        return Ok(Outcome {
            result,
            seconds,
            step: ended(env)?,
            set,
        });
    }
    let still = env
        .robot()
        .map_or(Vec::new(), |r| r.still_action(r.space()));
    let mut last = None;
    for _ in 0..steps {
        let step = env.step(&still)?;
        if let Some(r) = again(&mut watcher) {
            r.stepped(env, &still)?;
        }
        let over = step.terminated || step.truncated;
        last = Some(step);
        if over {
            break;
        }
    }
    let step = last.ok_or(EnvError::NotReset)?;
    Ok(Outcome {
        result,
        seconds,
        step,
        set,
    })
}

/// What the hand did (`by_hand`), or, where it failed in a way `falls_back` accepts and the
/// episode goes on, the setter's outcome instead, with `set` raised.
fn or_set(
    env: &mut Env,
    call: &Call,
    by_hand: Result<(), Failure>,
    falls_back: impl Fn(&Failure) -> bool,
    set: &mut bool,
) -> Result<Result<(), Failure>, RunError> {
    match by_hand {
        Err(f) if falls_back(&f) && !env.is_over() => {
            *set = true;
            Ok(apply(env, call)?)
        }
        done => Ok(done),
    }
}

/// The step that ended the episode, as it stands after it: terminated if the goal holds,
/// else truncated; its reward is not given again (0).
fn ended(env: &mut Env) -> Result<Step, EnvError> {
    let score = env.score().cloned().ok_or(EnvError::NotReset)?;
    Ok(Step {
        obs: env.observe()?,
        reward: 0.0,
        terminated: score.success,
        truncated: !score.success,
        info: Info {
            steps: env.steps(),
            score,
        },
    })
}

/// A primitive's outcome set at once, between steps: an edit the episode records.
fn apply(env: &mut Env, call: &Call) -> Result<Result<(), Failure>, EnvError> {
    let done = env.apply(&RecordedCall::of(env, call))?;
    Ok(done.map_err(|e| match e {
        EditError::Failed { failure, .. } => failure,
        EditError::Robot(e) => Failure::Robot(e),
        // A live call names its object by id and its primitive by value.
        EditError::UnknownPrimitive(_) | EditError::NoObject(_) | EditError::NoDoorClosed => {
            Failure::Unavailable("the primitive could not be described")
        }
    }))
}
