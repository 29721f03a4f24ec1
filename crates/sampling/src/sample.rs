//! Sampling one instance of an activity in a home, and checking that its goal can be reached.

use crate::instance::{Created, Instance};
use behavior_assets::{AssetError, Library, Scene, SceneError};
use behavior_bddl::activity::{Activity, InitLiteral, InstanceId, Literal};
use behavior_bddl::taxonomy::FLOOR_SYNSET;
use behavior_bddl::{Predicate, PredicateOracle, Taxonomy};
use behavior_sim::{BoundWorld, ObjectId, Relation, World};
use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};
use rapier3d::math::{Pose, Vector};

/// Attempts per instance, each with fresh randomness, before giving up.
pub const ATTEMPTS: u32 = 5;
/// Steps the world settles for after everything is placed (5 s).
pub const SETTLE_STEPS: usize = 150;

#[derive(Debug, thiserror::Error)]
pub enum SampleError {
    #[error("{scene} has no {room} with a {synset} free for {instance}")]
    NoFurniture {
        scene: String,
        instance: String,
        synset: String,
        room: String,
    },
    #[error("{literal} could not be satisfied: {reason}")]
    Literal { literal: String, reason: String },
    #[error("no goal option can be reached in this home: {literal}: {reason}")]
    Infeasible { literal: String, reason: String },
    #[error("{0}")]
    Asset(#[from] AssetError),
    #[error("{0}")]
    Scene(#[from] SceneError),
}

impl SampleError {
    /// Whether fresh randomness might succeed.
    fn retryable(&self) -> bool {
        // Sizes and poses are drawn afresh on each attempt, so either may come out differently.
        matches!(
            self,
            SampleError::Literal { .. } | SampleError::Infeasible { .. }
        )
    }
}

/// Samples an instance of `activity` in the home `scene`, deterministically from `seed`.
pub fn instantiate(
    activity: &Activity,
    scene: &Scene,
    seed: u64,
    library: &Library,
    taxonomy: &Taxonomy,
) -> Result<Instance, SampleError> {
    let mut last = None;
    for attempt in 0..ATTEMPTS {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(u64::from(attempt));
        match attempt_once(activity, scene, library, taxonomy, &mut rng) {
            Ok((world, bindings, created)) => {
                let instance = Instance {
                    activity: activity.name.clone(),
                    scene: scene.clone(),
                    seed,
                    attempt,
                    world,
                    bindings,
                    created,
                };
                goal_feasible(activity, &instance)?;
                return Ok(instance);
            }
            Err(e) if e.retryable() => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.expect("at least one attempt ran"))
}

type Attempt = (World, Vec<ObjectId>, Vec<Created>);

fn attempt_once(
    activity: &Activity,
    scene: &Scene,
    library: &Library,
    taxonomy: &Taxonomy,
    rng: &mut ChaCha8Rng,
) -> Result<Attempt, SampleError> {
    let built = scene.build(library)?;
    let mut world = built.world;
    let n = activity.instances.len();
    let mut bindings: Vec<Option<ObjectId>> = vec![None; n];
    bind_furniture(
        activity,
        scene,
        &built.objects,
        &built.floors,
        taxonomy,
        rng,
        &mut bindings,
    )?;
    // Bound furniture and floors already stand; the rest is placed below.
    let mut placed: Vec<bool> = bindings.iter().map(Option::is_some).collect();

    let show = |l: Literal| activity.show_literal(l);
    let kinematic: Vec<Literal> = activity
        .init
        .iter()
        .filter_map(|l| match l {
            InitLiteral::Atom(l)
                if l.positive
                    && matches!(
                        l.atom.predicate,
                        Predicate::OnTop
                            | Predicate::Inside
                            | Predicate::Under
                            | Predicate::OnFloor
                    ) =>
            {
                Some(*l)
            }
            _ => None,
        })
        .collect();

    // Where the goal may want objects (every positive `inside`/`ontop` atom of the ground goal):
    // sizing takes these into account too, so that the goal stays reachable.
    let goal = behavior_bddl::GroundGoal::new(activity);
    let mut demands: Vec<Literal> = kinematic.clone();
    for node in &goal.nodes {
        if let behavior_bddl::ground::Node::Lit(lit) = node {
            let atom = goal.atom(lit.atom);
            if lit.positive && matches!(atom.predicate, Predicate::Inside | Predicate::OnTop) {
                demands.push(Literal {
                    atom,
                    positive: true,
                });
            }
        }
    }
    demands.sort();
    demands.dedup();

    // Everything else comes from the library, parked far away until placed. Supports and
    // containers are made before what they hold, so a held object can be sized to fit.
    let mut created = Vec::new();
    loop {
        let ready = (0..n).find(|&i| {
            bindings[i].is_none()
                && demands.iter().all(|l| {
                    l.atom.subject.0 as usize != i
                        || l.atom.predicate == Predicate::OnFloor
                        || bindings[l.atom.object.expect("binary").0 as usize].is_some()
                        || l.atom.object.expect("binary").0 as usize == i
                })
        });
        let Some(i) = ready.or_else(|| (0..n).find(|&i| bindings[i].is_none())) else {
            break;
        };
        let instance = &activity.instances[i];
        let synset = activity.category(instance.category).name.clone();
        let (archetype, mut size, variant) = library.sample_any(&synset, rng)?;
        // How many objects go inside or on top of this one: a container that must hold several
        // is made as large as its kind comes.
        let holds = |j: usize| {
            demands
                .iter()
                .filter(|l| {
                    matches!(l.atom.predicate, Predicate::Inside | Predicate::OnTop)
                        && l.atom.object.is_some_and(|o| o.0 as usize == j)
                })
                .count()
        };
        if holds(i) >= 3 {
            size = Vector::from_array(archetype.max);
        }
        // Objects on or in another are shrunk, if need be, so that all it holds fit side by side.
        for l in demands.iter().filter(|l| l.atom.subject.0 as usize == i) {
            let Some(o) = l.atom.object else { continue };
            let Some(target) = bindings[o.0 as usize] else {
                continue;
            };
            let b = world.aabb(target);
            let room = b.maxs - b.mins;
            let share = 1.0 / (holds(o.0 as usize) as f32).sqrt().ceil().max(1.0);
            let cap = match l.atom.predicate {
                Predicate::Inside => room * Vector::new(0.7 * share, 0.7 * share, 0.4),
                Predicate::OnTop => room * Vector::new(0.9 * share, 0.9 * share, 10.0),
                _ => continue,
            };
            size = size.min(cap);
        }
        let mut spec = library.instance_of(archetype, &synset, &instance.name, size, variant);
        spec.pose = Pose::from_translation(Vector::new(1000.0 + 5.0 * i as f32, 1000.0, 0.0));
        spec.fixed = false;
        let id = world.add(spec).map_err(|e| SampleError::Literal {
            literal: instance.name.clone(),
            reason: e.to_string(),
        })?;
        bindings[i] = Some(id);
        created.push(Created {
            instance: instance.name.clone(),
            synset,
            archetype: archetype.synset.to_string(),
            size: size.to_array(),
            variant,
        });
    }
    let bindings: Vec<ObjectId> = bindings
        .into_iter()
        .map(|b| b.expect("every instance is bound"))
        .collect();

    // Placement in dependency order: a literal is placed once its second object stands. An
    // object with several placement literals is placed by `ontop`, `inside` or `under` when it
    // can be (resting on a towel on the floor, under a table on the floor), by `onfloor` last.
    loop {
        let mut progress = false;
        for pass_onfloor in [false, true] {
            for literal in &kinematic {
                let (a, b) = (literal.atom.subject, literal.atom.object.expect("binary"));
                let onfloor = literal.atom.predicate == Predicate::OnFloor;
                if onfloor != pass_onfloor || placed[a.0 as usize] || !placed[b.0 as usize] {
                    continue;
                }
                if onfloor
                    && kinematic.iter().any(|o| {
                        o.atom.subject == a
                            && o.atom.predicate != Predicate::OnFloor
                            && !placed[o.atom.object.expect("binary").0 as usize]
                    })
                {
                    continue; // wait for its other support
                }
                let relation = match literal.atom.predicate {
                    Predicate::OnTop => Relation::OnTop,
                    Predicate::Inside => Relation::Inside,
                    Predicate::Under => Relation::Under,
                    _ => Relation::OnFloor,
                };
                let (object, target) = (bindings[a.0 as usize], bindings[b.0 as usize]);
                world
                    .place(object, relation, target, rng)
                    .map_err(|e| SampleError::Literal {
                        literal: show(*literal),
                        reason: e.to_string(),
                    })?;
                placed[a.0 as usize] = true;
                progress = true;
            }
            if progress {
                break;
            }
        }
        if !progress {
            break;
        }
    }
    if let Some(i) = placed.iter().position(|p| !p) {
        return Err(SampleError::Literal {
            literal: activity.instances[i].name.clone(),
            reason: "no `ontop`, `inside`, `under` or `onfloor` literal places it relative to placed objects".into(),
        });
    }

    // Unary states, positive and negative.
    for literal in &activity.init {
        if let InitLiteral::Atom(l) = literal
            && l.atom.object.is_none()
        {
            let object = bindings[l.atom.subject.0 as usize];
            if world.state(object, l.atom.predicate) == l.positive {
                continue; // already so: `(not (open x))` needs no joints, `(not (frozen x))` no cooling
            }
            world
                .set_state(object, l.atom.predicate, l.positive)
                .map_err(|e| SampleError::Literal {
                    literal: show(*l),
                    reason: e.to_string(),
                })?;
        }
    }

    world.settle(SETTLE_STEPS);
    if let Some((literal, reason)) = first_unmet(activity, &world, &bindings) {
        return Err(SampleError::Literal { literal, reason });
    }
    Ok((world, bindings, created))
}

/// The first init literal that does not hold in the world, with why.
pub fn first_unmet(
    activity: &Activity,
    world: &World,
    bindings: &[ObjectId],
) -> Option<(String, String)> {
    let bound: Vec<Option<ObjectId>> = bindings.iter().copied().map(Some).collect();
    let oracle = BoundWorld {
        world,
        bindings: &bound,
    };
    for literal in &activity.init {
        match literal {
            InitLiteral::Atom(l) => {
                if oracle.holds(l.atom) != l.positive {
                    return Some((
                        activity.show_literal(*l),
                        "it does not hold in the settled world".into(),
                    ));
                }
            }
            InitLiteral::InRoom {
                instance,
                room,
                positive,
            } => {
                let object = bindings[instance.0 as usize];
                let here = world.room_of(object).unwrap_or("no room");
                if (here == room) != *positive {
                    let name = &activity.instance(*instance).name;
                    return Some((
                        format!("(inroom {name} {room})"),
                        format!("it stands in {here}"),
                    ));
                }
            }
        }
    }
    None
}

/// Binds every instance with an `inroom` literal to a scene object (or room floor) of its synset
/// or a descendant, in a room of the right type, by maximum matching per room type; ties are
/// broken at random so seeds vary the choice.
fn bind_furniture(
    activity: &Activity,
    scene: &Scene,
    scene_objects: &[ObjectId],
    floors: &[ObjectId],
    taxonomy: &Taxonomy,
    rng: &mut ChaCha8Rng,
    bindings: &mut [Option<ObjectId>],
) -> Result<(), SampleError> {
    let mut wanted: Vec<(InstanceId, String)> = activity
        .init
        .iter()
        .filter_map(|l| match l {
            InitLiteral::InRoom {
                instance,
                room,
                positive: true,
            } => Some((*instance, room.clone())),
            _ => None,
        })
        .collect();
    wanted.sort();
    let mut rooms: Vec<String> = wanted.iter().map(|(_, r)| r.clone()).collect();
    rooms.sort();
    rooms.dedup();
    for room in rooms {
        let instances: Vec<InstanceId> = wanted
            .iter()
            .filter(|(_, r)| *r == room)
            .map(|(i, _)| *i)
            .collect();
        // Candidates: the room type's floors and the objects standing in rooms of that type.
        let mut candidates: Vec<(ObjectId, String)> = Vec::new();
        for (k, r) in scene.rooms.iter().enumerate() {
            if r.kind == room {
                candidates.push((floors[k], FLOOR_SYNSET.to_string()));
            }
        }
        for (k, o) in scene.objects.iter().enumerate() {
            if scene.rooms[o.room].kind == room {
                candidates.push((scene_objects[k], o.synset.clone()));
            }
        }
        let fits = |i: InstanceId, synset: &str| {
            let want = &activity.category(activity.instance(i).category).name;
            match (taxonomy.get(synset), taxonomy.get(want)) {
                (Some(have), Some(want)) => taxonomy.is_a(have, want),
                _ => synset == want,
            }
        };
        let unmatched = |i: InstanceId| SampleError::NoFurniture {
            scene: scene.name.clone(),
            instance: activity.instance(i).name.clone(),
            synset: activity
                .category(activity.instance(i).category)
                .name
                .clone(),
            room: room.clone(),
        };
        if candidates.len() < instances.len() {
            return Err(unmatched(instances[candidates.len()]));
        }
        // Fitting pairs weigh 1000 plus a random tie-breaker; a full matching of fitting pairs
        // exists exactly when the best assignment scores at least 1000 per instance.
        let weights = Matrix::from_fn(instances.len(), candidates.len(), |(r, c)| {
            if fits(instances[r], &candidates[c].1) {
                1000 + i64::from(rng.next_u32() % 100)
            } else {
                0
            }
        });
        let (_, assignment) = kuhn_munkres(&weights);
        for (r, &c) in assignment.iter().enumerate() {
            if weights[(r, c)] < 1000 {
                return Err(unmatched(instances[r]));
            }
            bindings[instances[r].0 as usize] = Some(candidates[c].0);
        }
    }
    Ok(())
}

/// How many goal options (smallest first) [`goal_feasible`] tries before giving up.
pub const FEASIBILITY_OPTIONS: usize = 64;

/// Checks that some goal option can be reached in this home: every object in a positive
/// `ontop`, `inside` or `under` literal of the option fits where it is asked to go — inside a
/// container whose box can hold its box (in some orientation), on a support whose widest side is at
/// least its narrowest, under something whose largest side is at least its smallest. Other objects in the way do not count (the
/// agent can move them). Options are tried smallest first; the error reports why the first fails.
pub fn goal_feasible(activity: &Activity, instance: &Instance) -> Result<(), SampleError> {
    let goal = behavior_bddl::GroundGoal::new(activity);
    let world = &instance.world;
    let dims = |i: InstanceId| {
        let b = world.aabb(instance.bindings[i.0 as usize]);
        let mut d = (b.maxs - b.mins).to_array();
        d.sort_by(f32::total_cmp);
        d
    };
    let mut first_failure: Option<(String, String)> = None;
    for option in behavior_bddl::options::options(&goal).take(FEASIBILITY_OPTIONS) {
        let failure = option.iter().filter(|l| l.positive).find_map(|l| {
            let target = l.atom.object?;
            let (a, b) = (dims(l.atom.subject), dims(target));
            let reason = match l.atom.predicate {
                Predicate::Inside if (0..3).any(|k| a[k] > 0.95 * b[k]) => {
                    format!("its box {a:.2?} does not fit in {:.2?}", b)
                }
                Predicate::OnTop if a[0] > b[2] => format!(
                    "its narrower side {:.2} exceeds the support's widest {:.2}",
                    a[0], b[2]
                ),
                Predicate::Under if a[0] > b[2] => {
                    "it is larger than what it should go under".to_string()
                }
                _ => return None,
            };
            Some((activity.show_literal(*l), reason))
        });
        match failure {
            None => return Ok(()),
            Some(f) => {
                first_failure.get_or_insert(f);
            }
        }
    }
    let (literal, reason) =
        first_failure.unwrap_or_else(|| ("the goal".into(), "it has no consistent option".into()));
    Err(SampleError::Infeasible { literal, reason })
}
