//! Sampling one instance of an activity in a home: one attempt runs the stages in order, and a
//! failed attempt is retried with fresh randomness.

use crate::error::{Literals, SampleError, Unsatisfied};
use crate::goal::goal_feasible;
use crate::instance::{Created, Instance};
use crate::place::placement;
use crate::verify::check_init;
use behavior_assets::{Library, Scene};
use behavior_bddl::Taxonomy;
use behavior_bddl::activity::{Activity, InitLiteral, Literal};
use behavior_sim::{ObjectId, World};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};

/// Attempts per instance, each with fresh randomness, before giving up: iGibson's sampler also
/// retries, and most failures are a crowded support or an unlucky size.
pub const ATTEMPTS: u32 = 5;
/// Steps the world settles for after everything is placed (5 s), so that the init check sees
/// objects at rest rather than where they were dropped.
pub const SETTLE_STEPS: usize = 150;

/// Samples an instance of `activity` in the home `scene`, deterministically from `seed`.
///
/// Binds the activity's furniture and floors to the home's objects, creates the other objects
/// from `library`, places them, sets their states, lets the world settle and checks every init
/// literal, then checks that some goal option is reachable ([`goal_feasible`]). A failed attempt
/// is retried with fresh randomness, up to [`ATTEMPTS`]; the error is the last attempt's, or the
/// first that no retry can mend (a home without the rooms the activity needs). The same
/// (activity, home, seed) always gives a bit-identical instance.
///
/// ```
/// use behavior_assets::covering;
/// use behavior_assets::{Library, NAMED_HOMES, Scene, generate};
/// use behavior_data::DataDir;
/// use behavior_sampling::instantiate;
///
/// let data = DataDir::locate(None, |_| {}).unwrap();
/// let knowledge = behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
/// let library = Library::new(&knowledge.taxonomy);
/// let source = behavior_bddl::load::read_source(&data.problem_path("packing_lunches").unwrap()).unwrap();
/// let (activity, _) = knowledge.load(&source).unwrap();
/// // The first named home with the kitchen and furniture the activity's `inroom` literals need.
/// let (name, seed) = NAMED_HOMES[0];
/// let homes: Vec<Scene> = vec![generate(name, seed, &library).unwrap()];
/// let home = covering(&homes, &activity, &knowledge.taxonomy)[0];
///
/// let instance = instantiate(&activity, home, 7, &library, &knowledge.taxonomy).unwrap();
/// assert_eq!(instance.bindings.len(), activity.instances.len());
/// // Every `:init` literal holds in the settled world...
/// assert!(instance.check_init(&activity).all_hold());
/// // ...and the same seed gives the same instance.
/// let again = instantiate(&activity, home, 7, &library, &knowledge.taxonomy).unwrap();
/// assert_eq!(instance.world.bodies().motion_bits(), again.world.bodies().motion_bits());
/// ```
pub fn instantiate(
    activity: &Activity,
    scene: &Scene,
    seed: u64,
    library: &Library,
    taxonomy: &Taxonomy,
) -> Result<Instance, SampleError> {
    let task = Task {
        activity,
        scene,
        library,
        taxonomy,
        seed,
    };
    let mut attempt = 0;
    loop {
        match task.attempt(attempt) {
            Err(e) if e.retryable() && attempt + 1 < ATTEMPTS => attempt += 1,
            outcome => return outcome,
        }
    }
}

/// What is asked for: an instance of this activity in this home from this seed.
#[derive(Clone, Copy)]
struct Task<'a> {
    activity: &'a Activity,
    scene: &'a Scene,
    library: &'a Library<'a>,
    taxonomy: &'a Taxonomy,
    seed: u64,
}

impl Task<'_> {
    /// One attempt: the initial state, then the goal check on it.
    fn attempt(&self, attempt: u32) -> Result<Instance, SampleError> {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream(u64::from(attempt));
        let mut draft = Attempt::start(self, rng)?;
        draft.bind_furniture()?;
        draft.tidy()?;
        draft.create_objects()?;
        let bindings = draft.bound();
        draft.place_objects(&bindings)?;
        // The state setters (dust layouts, how far things open) draw from the attempt's stream.
        let states_seed = draft.rng.next_u64();
        draft.world.reseed(states_seed);
        draft.set_states(&bindings)?;
        draft.settle_and_check(&bindings)?;
        let mut rng = draft.rng;
        let instance = Instance {
            activity: self.activity.name.clone(),
            scene: draft.scene,
            seed: self.seed,
            attempt,
            world: draft.world,
            bindings,
            created: draft.created,
        };
        goal_feasible(self.activity, &instance, &mut rng)?;
        Ok(instance)
    }
}

/// The state one attempt shares between its stages: what it works from, its random numbers,
/// the world being built, which object each instance is, and the objects created so far.
pub(crate) struct Attempt<'a> {
    pub(crate) activity: &'a Activity,
    /// The home as it stands in this attempt: once tidied, without the clutter around the
    /// activity's furniture and floors.
    pub(crate) scene: Scene,
    pub(crate) library: &'a Library<'a>,
    pub(crate) taxonomy: &'a Taxonomy,
    /// This attempt's own stream: a retry draws other numbers.
    pub(crate) rng: ChaCha8Rng,
    /// The home, then with the created objects.
    pub(crate) world: World,
    /// The floor object of each room of the home, in `scene.rooms` order.
    pub(crate) floors: Vec<ObjectId>,
    /// The object built for each of `scene.objects`.
    pub(crate) furniture: Vec<ObjectId>,
    /// The object built for each of `scene.clutter`: never bound to an instance.
    pub(crate) clutter: Vec<ObjectId>,
    /// The object of each activity instance once bound or created, in `:objects` order.
    pub(crate) bindings: Vec<Option<ObjectId>>,
    /// Which instances are bound to the home's own objects (furniture and floors): they stand
    /// before anything is placed.
    pub(crate) home_bound: Vec<bool>,
    /// The objects created from the library, in creation order.
    pub(crate) created: Vec<Created>,
    /// The init's placement literals (positive `ontop`, `inside`, `under`, `nextto`,
    /// `touching`, `onfloor`), in the definition's order.
    pub(crate) kinematic: Vec<Literal>,
}

impl<'a> Attempt<'a> {
    /// Builds the home afresh for an attempt.
    fn start(task: &Task<'a>, rng: ChaCha8Rng) -> Result<Attempt<'a>, SampleError> {
        let built = task.scene.build(task.library)?;
        let kinematic = task
            .activity
            .init
            .iter()
            .filter_map(|l| match l {
                InitLiteral::Atom(l) if placement(l).is_some() => Some(*l),
                _ => None,
            })
            .collect();
        Ok(Attempt {
            activity: task.activity,
            scene: task.scene.clone(),
            library: task.library,
            taxonomy: task.taxonomy,
            rng,
            world: built.world,
            floors: built.floors,
            furniture: built.objects,
            clutter: built.clutter,
            bindings: vec![None; task.activity.instances.len()],
            home_bound: vec![false; task.activity.instances.len()],
            created: Vec::new(),
            kinematic,
        })
    }

    /// The object of every instance, once all are bound or created.
    fn bound(&self) -> Vec<ObjectId> {
        self.bindings
            .iter()
            .map(|b| b.expect("every instance is bound or created before placing"))
            .collect()
    }

    /// Lets the world come to rest, then requires every init literal to hold.
    fn settle_and_check(&mut self, bindings: &[ObjectId]) -> Result<(), SampleError> {
        self.world.settle(SETTLE_STEPS);
        let check = check_init(self.activity, &self.world, bindings);
        match check
            .literals
            .into_iter()
            .find_map(|l| Some((l.literal, l.unmet?)))
        {
            None => Ok(()),
            Some((literal, unmet)) => Err(SampleError::Literal {
                literals: Literals(vec![literal]),
                why: Unsatisfied::Unmet(unmet),
            }),
        }
    }
}
