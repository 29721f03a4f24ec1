//! The primitive action space for Python: the original's `Discrete(n × K)` (object `a mod n`,
//! primitive `a div n`, `behavior-planning`'s [`PrimitiveSpace`]), each action one primitive
//! run to its end in the episode (symbolic or physical), with the mask of feasible actions.

use behavior_env::{Env, Step};
use behavior_planning::{Mode, PrimitiveSet, PrimitiveSpace, RunError, run};

/// Which primitives, run how, over which objects (the episode's, found again at each reset).
pub struct Primitives {
    set: PrimitiveSet,
    mode: Mode,
    space: Option<PrimitiveSpace>,
}

/// What one primitive did, and the step it ended with.
pub struct Done {
    /// The last step the primitive took.
    pub step: Step,
    /// The change of Q over the whole primitive.
    pub reward: f64,
    /// The primitive's name, the object's and the hand.
    pub primitive: &'static str,
    pub object: String,
    pub hand: usize,
    /// Why it failed, if it did.
    pub failure: Option<String>,
}

/// Why an action was not run.
#[derive(Debug, thiserror::Error)]
pub enum PrimitiveError {
    /// Out of the space.
    #[error("primitive action {action} is out of range: the space has {len} actions")]
    OutOfRange { action: usize, len: usize },
    /// The episode refused (not reset, over).
    #[error(transparent)]
    Run(#[from] RunError),
}

impl Primitives {
    /// The set (`paper`, `two_hands`, `all`) and mode (`symbolic`, `physical`) of these names.
    pub fn new(set: &str, mode: &str) -> Result<Primitives, String> {
        let set = PrimitiveSet::from_name(set).ok_or_else(|| {
            format!("primitive_set must be one of paper, two_hands, all, not `{set}`")
        })?;
        let mode = Mode::from_name(mode)
            .ok_or_else(|| format!("primitive_mode must be symbolic or physical, not `{mode}`"))?;
        Ok(Primitives {
            set,
            mode,
            space: None,
        })
    }

    /// Finds the new episode's objects.
    pub fn reset(&mut self, env: &Env) {
        self.space = PrimitiveSpace::of(env, self.set);
    }

    /// How many actions (n × K).
    pub fn len(&self) -> usize {
        self.space.as_ref().map_or(0, PrimitiveSpace::len)
    }

    /// What each action does: its primitive's name and its object's, in action order.
    pub fn meanings(&self, env: &Env) -> Vec<(&'static str, String)> {
        let (Some(space), Some(world)) = (self.space.as_ref(), env.world()) else {
            return Vec::new();
        };
        (0..space.len())
            .filter_map(|a| space.decode(a))
            .map(|call| {
                let object = world.bodies().object(call.object).name.clone();
                (call.primitive.name(), object)
            })
            .collect()
    }

    /// Whether each action's preconditions hold now.
    pub fn mask(&self, env: &Env) -> Vec<bool> {
        self.space.as_ref().map_or_else(Vec::new, |s| s.mask(env))
    }

    /// Runs action `a` to its end (the episode records it if it is recording).
    pub fn step(&self, env: &mut Env, a: usize) -> Result<Done, PrimitiveError> {
        let call =
            self.space
                .as_ref()
                .and_then(|s| s.decode(a))
                .ok_or(PrimitiveError::OutOfRange {
                    action: a,
                    len: self.len(),
                })?;
        let before = env.score().map_or(0.0, |s| s.q);
        let object = env
            .world()
            .map(|w| w.bodies().object(call.object).name.clone())
            .unwrap_or_default();
        let outcome = run(env, call, self.mode, None)?;
        Ok(Done {
            reward: outcome.step.info.score.q - before,
            step: outcome.step,
            primitive: call.primitive.name(),
            object,
            hand: call.hand,
            failure: outcome.result.err().map(|f| f.to_string()),
        })
    }
}
