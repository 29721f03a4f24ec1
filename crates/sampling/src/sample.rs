//! Sampling one instance of an activity in a home, and checking that its goal can be reached.

use crate::instance::{Created, Instance};
use behavior_assets::{AssetError, BuiltScene, Library, Scene, SceneError};
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
                match goal_feasible(activity, &instance, &mut rng) {
                    Ok(()) => return Ok(instance),
                    Err(e) => last = Some(e),
                }
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
    let n = activity.instances.len();
    let mut bindings: Vec<Option<ObjectId>> = vec![None; n];
    let kinematic: Vec<Literal> = activity
        .init
        .iter()
        .filter_map(|l| match l {
            InitLiteral::Atom(l) if placement(l).is_some() => Some(*l),
            _ => None,
        })
        .collect();
    bind_furniture(
        activity,
        scene,
        &built,
        &kinematic,
        library,
        taxonomy,
        rng,
        &mut bindings,
    )?;
    let mut world = built.world;
    // Bound furniture and floors already stand; the rest is placed below.
    let mut placed: Vec<bool> = bindings.iter().map(Option::is_some).collect();
    let show = |l: Literal| activity.show_literal(l);

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
            let b = world.core().aabb(target);
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
        spec.body = behavior_sim::BodyKind::Dynamic;
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

    // Placement in dependency order: an object is placed once everything it is to stand on, in or
    // under stands, by all its placement literals at once (a soap on a towel on the floor; a shoe
    // under a table and on the floor of the room that end of the table is in). `nextto` and
    // `touching` are symmetric: one towards an object not yet placed is handed on to that object,
    // reversed, so two objects that touch each other do not wait for each other. An object rests on
    // what its first `ontop`, `inside` or `under` names, else beside what `nextto` names, else on
    // its floor.
    let target_of = |l: &Literal| l.atom.object.expect("binary").0 as usize;
    // (handed to, the literal as it is placed, the literal as the definition writes it)
    let mut handed_on: Vec<(usize, Literal, Literal)> = Vec::new();
    loop {
        let own = |i: usize| {
            kinematic
                .iter()
                .filter(move |l| l.atom.subject.0 as usize == i)
        };
        let ready = (0..n).find(|&i| {
            !placed[i]
                && own(i).all(|l| is_symmetric(l) || placed[target_of(l)])
                && (own(i).any(|l| placed[target_of(l)]) || handed_on.iter().any(|h| h.0 == i))
        });
        let Some(i) = ready else { break };
        let mut literals: Vec<(Literal, Literal)> = Vec::new();
        for l in own(i) {
            if placed[target_of(l)] {
                literals.push((*l, *l));
            } else {
                handed_on.push((target_of(l), reversed(l), *l));
            }
        }
        literals.extend(
            handed_on
                .iter()
                .filter(|h| h.0 == i)
                .map(|&(_, placed_as, written)| (placed_as, written)),
        );
        place_by(&mut world, activity, &bindings, i, &literals, rng)
            .map_err(|(literal, reason)| SampleError::Literal { literal, reason })?;
        placed[i] = true;
    }
    if let Some(i) = placed.iter().position(|p| !p) {
        return Err(SampleError::Literal {
            literal: activity.instances[i].name.clone(),
            reason: "no `ontop`, `inside`, `under`, `nextto`, `touching` or `onfloor` literal \
                     places it relative to placed objects"
                .into(),
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
                let here = world.core().room_of(object);
                if (here == Some(*room)) != *positive {
                    let name = &activity.instance(*instance).name;
                    return Some((
                        format!("(inroom {name} {room})"),
                        format!("it stands in {}", here.map_or("no room", |r| r.name())),
                    ));
                }
            }
        }
    }
    None
}

/// Binds every instance with an `inroom` literal to a scene object (or room floor) of its synset
/// or a descendant, in a room of the right type, by maximum matching per room type; ties are
/// broken at random so seeds vary the choice. Only candidates that can host their own init
/// literals take part (see [`hosts`]).
#[allow(clippy::too_many_arguments)]
fn bind_furniture(
    activity: &Activity,
    scene: &Scene,
    built: &BuiltScene,
    kinematic: &[Literal],
    library: &Library,
    taxonomy: &Taxonomy,
    rng: &mut ChaCha8Rng,
    bindings: &mut [Option<ObjectId>],
) -> Result<(), SampleError> {
    let mut wanted: Vec<(InstanceId, behavior_bddl::RoomType)> = activity
        .init
        .iter()
        .filter_map(|l| match l {
            InitLiteral::InRoom {
                instance,
                room,
                positive: true,
            } => Some((*instance, *room)),
            _ => None,
        })
        .collect();
    wanted.sort();
    let fits = |i: InstanceId, synset: &str| {
        let want = &activity.category(activity.instance(i).category).name;
        match (taxonomy.get(synset), taxonomy.get(want)) {
            (Some(have), Some(want)) => taxonomy.is_a(have, want),
            _ => synset == want,
        }
    };
    // Candidates of each instance: the room type's floors, or the objects of its kind standing in
    // rooms of that type.
    let mut candidates: Vec<Vec<ObjectId>> = vec![Vec::new(); activity.instances.len()];
    for (i, room) in &wanted {
        let list = &mut candidates[i.0 as usize];
        for (k, r) in scene.rooms.iter().enumerate() {
            if r.kind == *room && fits(*i, FLOOR_SYNSET) {
                list.push(built.floors[k]);
            }
        }
        for (k, o) in scene.objects.iter().enumerate() {
            if scene.rooms[o.room].kind == *room && fits(*i, &o.synset) {
                list.push(built.objects[k]);
            }
        }
    }
    let unmatched = |i: InstanceId, room: &behavior_bddl::RoomType| SampleError::NoFurniture {
        scene: scene.name.clone(),
        instance: activity.instance(i).name.clone(),
        synset: activity
            .category(activity.instance(i).category)
            .name
            .clone(),
        room: room.to_string(),
    };
    for (i, room) in &wanted {
        if candidates[i.0 as usize].is_empty() {
            return Err(unmatched(*i, room));
        }
    }
    let hosting = hosts(activity, scene, kinematic, &candidates, library, rng)?;
    let candidates_before: Vec<usize> = candidates.iter().map(Vec::len).collect();
    // When too few candidates can host, the error says which literal ruled them out. Probes are
    // random, so another attempt may keep more.
    let ruled_out = |i: InstanceId, room: &behavior_bddl::RoomType| {
        let (kept, why) = &hosting[i.0 as usize];
        if kept.len() == candidates_before[i.0 as usize] {
            return unmatched(i, room);
        }
        SampleError::Literal {
            literal: why.0.clone(),
            reason: format!(
                "{} of the {} {} in {}'s {room}s can take it: {}",
                kept.len(),
                candidates_before[i.0 as usize],
                activity.category(activity.instance(i).category).name,
                scene.name,
                why.1
            ),
        }
    };
    for (i, room) in &wanted {
        if hosting[i.0 as usize].0.is_empty() {
            return Err(ruled_out(*i, room));
        }
        candidates[i.0 as usize] = hosting[i.0 as usize].0.clone();
    }

    let mut rooms: Vec<behavior_bddl::RoomType> = wanted.iter().map(|(_, r)| *r).collect();
    rooms.sort();
    rooms.dedup();
    for room in rooms {
        let instances: Vec<InstanceId> = wanted
            .iter()
            .filter(|(_, r)| *r == room)
            .map(|(i, _)| *i)
            .collect();
        let mut columns: Vec<ObjectId> = instances
            .iter()
            .flat_map(|i| candidates[i.0 as usize].iter().copied())
            .collect();
        columns.sort();
        columns.dedup();
        // Which instance to blame when no full matching exists: one that lost candidates to
        // the hosting test, if any.
        let blame = |fallback: InstanceId| {
            let i = instances
                .iter()
                .copied()
                .find(|i| hosting[i.0 as usize].0.len() < candidates_before[i.0 as usize])
                .unwrap_or(fallback);
            ruled_out(i, &room)
        };
        if columns.len() < instances.len() {
            return Err(blame(instances[columns.len()]));
        }
        // Hosting pairs weigh 1000 plus a random tie-breaker; a full matching of such pairs
        // exists exactly when the best assignment scores at least 1000 per instance.
        let weights = Matrix::from_fn(instances.len(), columns.len(), |(r, c)| {
            if candidates[instances[r].0 as usize].contains(&columns[c]) {
                1000 + i64::from(rng.next_u32() % 100)
            } else {
                0
            }
        });
        let (_, assignment) = kuhn_munkres(&weights);
        for (r, &c) in assignment.iter().enumerate() {
            if weights[(r, c)] < 1000 {
                return Err(blame(instances[r]));
            }
            bindings[instances[r].0 as usize] = Some(columns[c]);
        }
    }
    Ok(())
}

/// A candidate kept, or the literal that rules candidates out and why (the last failure seen).
type Hosting = (Vec<ObjectId>, (String, String));

/// Which candidates can host their instance's init literals, as iGibson filters them before
/// matching: for every object to be placed on, in, under or next to the instance, a probe of that object's
/// smallest size is placed there in a scratch copy of the home, together with its placements
/// relative to other furniture (trying their candidates too). A candidate is kept if every probe
/// finds a place. Instances without candidates keep their list empty with the reason.
fn hosts(
    activity: &Activity,
    scene: &Scene,
    kinematic: &[Literal],
    candidates: &[Vec<ObjectId>],
    library: &Library,
    rng: &mut ChaCha8Rng,
) -> Result<Vec<Hosting>, SampleError> {
    let furniture = |i: InstanceId| !candidates[i.0 as usize].is_empty();
    let mut scratch: Option<World> = None;
    let mut probes: Vec<Option<(ObjectId, Pose)>> = vec![None; activity.instances.len()];
    let mut out = Vec::with_capacity(candidates.len());
    for (i, list) in candidates.iter().enumerate() {
        if list.is_empty() {
            out.push((Vec::new(), (String::new(), String::new())));
            continue; // not furniture: nothing to choose
        }
        let mut hosted: Vec<InstanceId> = kinematic
            .iter()
            .filter(|l| {
                l.atom.object.is_some_and(|o| o.0 as usize == i) && !furniture(l.atom.subject)
            })
            .map(|l| l.atom.subject)
            .collect();
        hosted.sort();
        hosted.dedup();
        if hosted.is_empty() {
            out.push((list.clone(), (String::new(), String::new())));
            continue;
        }
        let world = match &mut scratch {
            Some(w) => w,
            None => scratch.insert(scene.build(library)?.world),
        };
        let mut kept = Vec::new();
        let mut why = (String::new(), String::new());
        for &candidate in list {
            let mut ok = true;
            for &subject in &hosted {
                let probe = match probes[subject.0 as usize] {
                    Some(p) => p,
                    None => {
                        let p = add_probe(world, activity, subject, library)?;
                        *probes[subject.0 as usize].insert(p)
                    }
                };
                // Its placements relative to furniture: this candidate for `i`, every candidate
                // (up to a few combinations) for the others.
                let literals: Vec<&Literal> = kinematic
                    .iter()
                    .filter(|l| {
                        l.atom.subject == subject && furniture(l.atom.object.expect("binary"))
                    })
                    .collect();
                let mut options: Vec<Vec<(Relation, ObjectId)>> = vec![Vec::new()];
                for l in &literals {
                    let o = l.atom.object.expect("binary").0 as usize;
                    let targets = if o == i {
                        &[candidate][..]
                    } else {
                        &candidates[o][..]
                    };
                    options = options
                        .iter()
                        .flat_map(|prefix| {
                            targets.iter().map(move |&t| {
                                let mut v = prefix.clone();
                                v.push((relation_of(l), t));
                                v
                            })
                        })
                        .take(MAX_HOST_COMBINATIONS)
                        .collect();
                }
                options.iter_mut().for_each(|o| order_relations(world, o));
                let mut last_error = None;
                let placed = options.iter().any(|relations| {
                    match world.place_jointly(probe.0, relations, rng) {
                        Ok(_) => true,
                        Err(e) => {
                            last_error = Some(e.to_string());
                            false
                        }
                    }
                });
                // Back to its parking spot, out of the next probe's way.
                let _ = world.set_pose(probe.0, probe.1);
                if !placed {
                    why = (
                        show_all(activity, literals.iter().copied()),
                        last_error.unwrap_or_default(),
                    );
                    ok = false;
                    break;
                }
            }
            if ok {
                kept.push(candidate);
            }
        }
        out.push((kept, why));
    }
    Ok(out)
}

/// Joint placements tried per probe when its other furniture has several candidates.
const MAX_HOST_COMBINATIONS: usize = 16;

/// A probe for `subject`: its synset's archetype at the smallest size, parked far away.
fn add_probe(
    world: &mut World,
    activity: &Activity,
    subject: InstanceId,
    library: &Library,
) -> Result<(ObjectId, Pose), SampleError> {
    let instance = activity.instance(subject);
    let synset = &activity.category(instance.category).name;
    let archetype = library.resolve(synset)?;
    let mut spec = library.instance_of(
        archetype,
        synset,
        &instance.name,
        Vector::from_array(archetype.min),
        0,
    );
    let park = Pose::from_translation(Vector::new(-1000.0 - 5.0 * subject.0 as f32, 1000.0, 0.0));
    spec.pose = park;
    spec.body = behavior_sim::BodyKind::Dynamic;
    let id = world.add(spec).map_err(|e| SampleError::Literal {
        literal: instance.name.clone(),
        reason: e.to_string(),
    })?;
    Ok((id, park))
}

/// The placement a literal asks for: a positive `ontop`, `inside`, `under`, `nextto`, `touching`
/// or `onfloor`.
fn placement(l: &Literal) -> Option<Relation> {
    let relation = match l.atom.predicate {
        Predicate::OnTop => Relation::OnTop,
        Predicate::Inside => Relation::Inside,
        Predicate::Under => Relation::Under,
        Predicate::NextTo => Relation::NextTo,
        Predicate::Touching => Relation::Touching,
        Predicate::OnFloor => Relation::OnFloor,
        _ => return None,
    };
    l.positive.then_some(relation)
}

/// The relation of a literal already known to be a placement.
fn relation_of(l: &Literal) -> Relation {
    placement(l).expect("a placement literal")
}

fn is_symmetric(l: &Literal) -> bool {
    placement(l).is_some_and(Relation::is_symmetric)
}

/// The same relation stated from its object's side (for symmetric ones).
fn reversed(l: &Literal) -> Literal {
    let mut r = *l;
    (r.atom.subject, r.atom.object) = (l.atom.object.expect("binary"), Some(l.atom.subject));
    r
}

/// Places instance `i` by all its `literals` at once, each given as placed (perhaps reversed from
/// the other side) and as the definition writes it; on failure, the written ones and why.
fn place_by(
    world: &mut World,
    activity: &Activity,
    bindings: &[ObjectId],
    i: usize,
    literals: &[(Literal, Literal)],
    rng: &mut ChaCha8Rng,
) -> Result<(), (String, String)> {
    let mut relations: Vec<(Relation, ObjectId)> = literals
        .iter()
        .map(|(l, _)| {
            (
                relation_of(l),
                bindings[l.atom.object.expect("binary").0 as usize],
            )
        })
        .collect();
    order_relations(world, &mut relations);
    world
        .place_jointly(bindings[i], &relations, rng)
        .map(|_| ())
        .map_err(|e| {
            let written = show_all(activity, literals.iter().map(|(_, w)| w));
            (written, e.to_string())
        })
}

/// Literals as an error shows them: `(a) and (b)`.
fn show_all<'a>(activity: &Activity, literals: impl IntoIterator<Item = &'a Literal>) -> String {
    literals
        .into_iter()
        .map(|l| activity.show_literal(*l))
        .collect::<Vec<_>>()
        .join(" and ")
}

/// Puts first the relation that picks where an object rests ([`World::place_jointly`]): a support
/// (`ontop`, `inside`, `under`) before a neighbour (`nextto`, `touching`) before a floor, and
/// among equals the smallest target, whose narrow surroundings are the hardest to hit by chance.
fn order_relations(world: &World, relations: &mut [(Relation, ObjectId)]) {
    let rank = |r: Relation| match r {
        Relation::OnTop | Relation::Inside | Relation::Under => 0,
        Relation::NextTo | Relation::Touching => 1,
        Relation::OnFloor => 2,
    };
    let volume = |t: ObjectId| {
        let b = world.core().aabb(t);
        let d = b.maxs - b.mins;
        d.x * d.y * d.z
    };
    relations.sort_by(|a, b| {
        rank(a.0)
            .cmp(&rank(b.0))
            .then(volume(a.1).total_cmp(&volume(b.1)))
    });
}

/// How many goal options (smallest first) [`goal_feasible`] tries before giving up.
pub const FEASIBILITY_OPTIONS: usize = 64;
/// How many of those, having passed the size test, it places physically (iGibson tries 10).
pub const PHYSICAL_OPTIONS: usize = 10;

/// Checks that some goal option can be reached in this home: every object in a positive
/// `ontop`, `inside`, `under`, `nextto`, `touching` or `onfloor` literal of the option can be placed
/// as it asks. Options are tried smallest first, leaving out those that relate an object to
/// itself. Each must first pass a shape test — nothing on, in or under two things that stay too
/// far apart for it to reach both, inside a container
/// whose box can hold its box (in some orientation), on a support whose widest side is at least
/// its narrowest, under something whose largest side is at least its smallest — and then the first
/// [`PHYSICAL_OPTIONS`] that do are placed for real in a copy of the world: the objects the option
/// moves are lifted out, then put back targets first, each by all its literals at once, among
/// the objects that stay (iGibson also places them physically). The error reports why the first
/// option failed.
pub fn goal_feasible(
    activity: &Activity,
    instance: &Instance,
    rng: &mut ChaCha8Rng,
) -> Result<(), SampleError> {
    // No object is on, in, under, next to or touching itself: options asking so are skipped.
    let goal = behavior_bddl::GroundGoal::new(activity)
        .assuming_false(|atom| atom.object == Some(atom.subject));
    let world = &instance.world;
    let dims = |i: InstanceId| {
        let b = world.core().aabb(instance.bindings[i.0 as usize]);
        let mut d = (b.maxs - b.mins).to_array();
        d.sort_by(f32::total_cmp);
        d
    };
    let mut first_failure: Option<(String, String)> = None;
    let mut physical = 0;
    for option in behavior_bddl::options::options(&goal).take(FEASIBILITY_OPTIONS) {
        // Whether something the option moves goes on, in or under `target` and `other`, which
        // both stay where they are, though they stand too far apart for it to reach both.
        let moved = |i: InstanceId| option.iter().any(|l| l.positive && l.atom.subject == i);
        let apart = |subject: InstanceId, target: InstanceId, other: InstanceId| {
            let (t, o) = (
                world.core().aabb(instance.bindings[target.0 as usize]),
                world.core().aabb(instance.bindings[other.0 as usize]),
            );
            let gap = (t.mins - o.maxs).max(o.mins - t.maxs).max(Vector::ZERO);
            !moved(target) && !moved(other) && gap.x.hypot(gap.y) > dims(subject)[2]
        };
        let too_big = option.iter().filter(|l| l.positive).find_map(|l| {
            let target = l.atom.object?;
            let (a, b) = (dims(l.atom.subject), dims(target));
            let support = |o: &Literal| {
                matches!(
                    o.atom.predicate,
                    Predicate::OnTop | Predicate::Inside | Predicate::Under
                ) && o.positive
                    && o.atom.subject == l.atom.subject
            };
            let reason = match l.atom.predicate {
                Predicate::OnTop | Predicate::Inside | Predicate::Under
                    if option.iter().any(|o| {
                        support(o)
                            && o.atom
                                .object
                                .is_some_and(|t| apart(l.atom.subject, target, t))
                    }) =>
                {
                    "it would have to be in two places at once".to_string()
                }
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
        let failure = match too_big {
            Some(f) => Some(f),
            None if physical < PHYSICAL_OPTIONS => {
                physical += 1;
                place_option(activity, instance, &option, rng).err()
            }
            None => continue,
        };
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

/// Places a goal option's positive placement literals in a copy of the instance's world; the
/// literal that could not be placed and why.
fn place_option(
    activity: &Activity,
    instance: &Instance,
    option: &[Literal],
    rng: &mut ChaCha8Rng,
) -> Result<(), (String, String)> {
    let placements: Vec<&Literal> = option.iter().filter(|l| placement(l).is_some()).collect();
    let mut subjects: Vec<InstanceId> = placements.iter().map(|l| l.atom.subject).collect();
    subjects.sort();
    subjects.dedup();
    // Targets first: an object waits while something it goes on, in or under is still to be
    // placed. `nextto` and `touching` are symmetric, so they make nothing wait: between two moved
    // objects, the later one is placed beside the earlier.
    let mut order = Vec::with_capacity(subjects.len());
    while order.len() < subjects.len() {
        let waiting = |s: InstanceId| {
            placements.iter().any(|l| {
                l.atom.subject == s
                    && !is_symmetric(l)
                    && l.atom
                        .object
                        .is_some_and(|t| t != s && subjects.contains(&t) && !order.contains(&t))
            })
        };
        // Better one with something placed to go by than one that would stay where it was.
        let anchored = |s: InstanceId| {
            placements.iter().any(|l| {
                l.atom.subject == s
                    && l.atom
                        .object
                        .is_some_and(|t| !subjects.contains(&t) || order.contains(&t))
            })
        };
        let free = |s: &InstanceId| !order.contains(s);
        let next = subjects
            .iter()
            .copied()
            .find(|&s| free(&s) && !waiting(s) && anchored(s))
            .or_else(|| subjects.iter().copied().find(|&s| free(&s) && !waiting(s)))
            // A cycle (a inside b, b inside a): place in order and let the check fail.
            .or_else(|| subjects.iter().copied().find(free));
        order.extend(next);
    }
    // What each object is placed by: its own literals, and the symmetric ones of objects placed
    // before it, handed on reversed (shown as the goal writes them).
    let mut plans: Vec<Vec<(Literal, Literal)>> = vec![Vec::new(); order.len()];
    for (k, &subject) in order.iter().enumerate() {
        for l in placements.iter().filter(|l| l.atom.subject == subject) {
            let target = l.atom.object.expect("binary");
            match order[k + 1..].iter().position(|&t| t == target) {
                Some(later) if is_symmetric(l) => plans[k + 1 + later].push((reversed(l), **l)),
                _ => plans[k].push((**l, **l)),
            }
        }
    }
    // What the goal moves is lifted out first, so it does not stand in its own way; an object
    // whose literals were all handed on stays where it is, for the others to come to it.
    let mut world = instance.world.clone();
    for (k, &subject) in order.iter().enumerate() {
        if plans[k].is_empty() {
            continue;
        }
        let id = instance.bindings[subject.0 as usize];
        let parked = Pose::from_parts(
            Vector::new(-2000.0 - 5.0 * k as f32, -2000.0, 0.0),
            world.pose(id).rotation,
        );
        world
            .set_pose(id, parked)
            .map_err(|e| (activity.instance(subject).name.clone(), e.to_string()))?;
    }
    for (k, &subject) in order.iter().enumerate() {
        if !plans[k].is_empty() {
            let i = subject.0 as usize;
            place_by(&mut world, activity, &instance.bindings, i, &plans[k], rng)?;
        }
    }
    Ok(())
}
