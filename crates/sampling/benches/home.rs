//! A home's step: the world step (physics, then the state rules), then every goal atom evaluated,
//! on sampled instances of the seed's runtime activities and of a state-heavy one, in their
//! first covering named home with its clutter (as `behavior sample` uses), with every object at
//! rest and with the activity's objects moving. Also counts the heap allocations of a
//! step at rest. `cargo bench -p behavior-sampling --bench home`.

use behavior_assets::{Library, NAMED_HOMES, clutter, covering, generate};
use behavior_bddl::{Activity, GroundGoal, Knowledge, PredicateOracle};
use behavior_data::DataDir;
use behavior_sampling::{Instance, instantiate};
use behavior_sim::{BoundWorld, ObjectId, World};
use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use rapier3d::math::{Pose, Vector};
use std::time::Duration;

/// The runtime activities of the paper's speed table, and one heavy on object states.
const ACTIVITIES: [&str; 4] = [
    "bringing_in_wood",
    "re-shelving_library_books",
    "laying_tile_floors",
    "cleaning_up_after_a_meal",
];

#[path = "../../sim/tests/common/counting.rs"]
mod counting;

/// A sampled instance in the activity's first covering named home, with its ground goal.
struct Home {
    activity: Activity,
    instance: Instance,
    goal: GroundGoal,
}

fn homes() -> Vec<Home> {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let library = Library::new(&knowledge.taxonomy);
    let named: Vec<_> = NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, &library).unwrap())
        .collect();
    ACTIVITIES
        .iter()
        .map(|name| {
            let source =
                behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap();
            let (activity, _) = knowledge.load(&source).unwrap();
            let furnished = covering(&named, &activity, &knowledge.taxonomy)[0];
            let home = clutter(furnished, &library, furnished.seed).unwrap();
            let instance = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy).unwrap();
            let goal = GroundGoal::new(&activity);
            Home {
                activity,
                instance,
                goal,
            }
        })
        .collect()
}

/// One step of the home, then the truth of every goal atom into `truth`.
fn step_and_check(
    world: &mut World,
    home: &Home,
    bindings: &[Option<ObjectId>],
    truth: &mut [bool],
) {
    world.step();
    let oracle = BoundWorld { world, bindings };
    for (t, &atom) in truth.iter_mut().zip(&home.goal.atoms) {
        *t = oracle.holds(atom);
    }
}

/// The world with every created object of the activity lifted 2 cm and woken: a step of it
/// simulates them falling back.
fn lifted(home: &Home) -> World {
    let mut world = home.instance.world.clone();
    for created in &home.instance.created {
        let id = world.bodies().object_named(&created.instance).unwrap();
        let pose = world.bodies().pose(id);
        let up = Pose::from_parts(
            pose.translation + Vector::new(0.0, 0.0, 0.02),
            pose.rotation,
        );
        world.bodies_mut().set_pose(id, up).unwrap();
    }
    world
}

fn bench_homes(c: &mut Criterion) {
    let homes = homes();
    let mut group = c.benchmark_group("home");
    group.measurement_time(Duration::from_secs(4));
    for home in &homes {
        let name = home.activity.name.trim_end_matches("_0").to_string();
        let bindings = home.instance.bound();
        let mut truth = vec![false; home.goal.atoms.len()];
        let mut world = home.instance.world.clone();
        for _ in 0..60 {
            step_and_check(&mut world, home, &bindings, &mut truth);
        }
        let before = counting::allocations();
        for _ in 0..100 {
            step_and_check(&mut world, home, &bindings, &mut truth);
        }
        let allocations = counting::allocations() - before;
        eprintln!(
            "{name}: {} objects ({} created), {} goal atoms; {allocations} heap allocations in 100 steps at rest",
            world.bodies().objects().len(),
            home.instance.created.len(),
            home.goal.atoms.len(),
        );
        group.bench_function(format!("{name}/asleep"), |b| {
            b.iter(|| step_and_check(&mut world, home, &bindings, &mut truth))
        });
        let falling = lifted(home);
        group.bench_function(format!("{name}/moving"), |b| {
            b.iter_batched_ref(
                || falling.clone(),
                |w| step_and_check(w, home, &bindings, &mut truth),
                BatchSize::SmallInput,
            )
        });
    }
    group.finish();
}

criterion_group!(benches, bench_homes);
criterion_main!(benches);
