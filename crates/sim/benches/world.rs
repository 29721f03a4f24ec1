//! Criterion benchmarks of the world: a step of the 201-object resting scene (asleep), and the
//! 15 BDDL predicates over every pair of 20 of its objects, memo cold and warm.
//! `cargo bench -p behavior-sim`. Awake physics and the PyBullet comparison:
//! `bench/physics_side_by_side.sh`.

use behavior_core::Predicate;
mod common;

use behavior_sim::{ObjectId, Substeps, World};
use common::resting_home;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn settled(substeps: Substeps) -> World {
    let mut world = World::new(substeps);
    for spec in resting_home() {
        world.add(spec).unwrap();
    }
    for _ in 0..300 {
        world.step();
    }
    world
}

/// All 6 binary predicates over all ordered pairs and the 9 unary ones over each of 20 objects.
fn all_predicates(world: &World, objects: &[ObjectId]) -> usize {
    let mut true_count = 0;
    for &a in objects {
        for p in Predicate::UNARY_STATES {
            true_count += usize::from(world.state(a, p));
        }
        for &b in objects {
            true_count += usize::from(world.core().ontop(a, b))
                + usize::from(world.core().inside(a, b))
                + usize::from(world.core().under(a, b))
                + usize::from(world.core().nextto(a, b))
                + usize::from(world.core().touching(a, b))
                + usize::from(world.core().onfloor(a, b));
        }
    }
    true_count
}

fn benches(c: &mut Criterion) {
    let mut idle = settled(Substeps::Hz300);
    c.bench_function("step_resting_201_objects_1_300", |b| b.iter(|| idle.step()));
    let mut idle_120 = settled(Substeps::Hz120);
    c.bench_function("step_resting_201_objects_1_120", |b| {
        b.iter(|| idle_120.step())
    });

    let world = settled(Substeps::Hz300);
    // The floor, two tables and the 17 objects on or near them: an activity-sized set.
    let mut objects: Vec<ObjectId> = vec![ObjectId(0), ObjectId(1), ObjectId(2)];
    objects.extend((11..28).map(ObjectId));
    c.bench_function("all_15_predicates_over_20_objects_cold", |b| {
        b.iter(|| {
            world.forget_relations();
            black_box(all_predicates(&world, &objects))
        })
    });
    c.bench_function("all_15_predicates_over_20_objects_warm", |b| {
        b.iter(|| black_box(all_predicates(&world, &objects)))
    });
}

criterion_group! {
    name = world;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = benches
}
criterion_main!(world);
