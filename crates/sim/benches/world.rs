//! Criterion benchmarks of the world: a step of the 201-object resting scene (asleep), and the
//! 15 BDDL predicates over every pair of 20 of its objects, memo cold and warm.
//! `cargo bench -p behavior-sim`. Awake physics and the PyBullet comparison:
//! `bench/physics_side_by_side.sh`.

use behavior_core::Predicate;
mod common;

use behavior_sim::{ObjectId, Primitive, QueryFilter, Substeps, World};
use common::resting_home;
use criterion::{Criterion, criterion_group, criterion_main};
use rapier3d::math::{Pose, Vector};
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
            true_count += usize::from(world.relations().ontop(a, b))
                + usize::from(world.relations().inside(a, b))
                + usize::from(world.relations().under(a, b))
                + usize::from(world.relations().nextto(a, b))
                + usize::from(world.relations().touching(a, b))
                + usize::from(world.relations().onfloor(a, b));
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

    // What a planner pays to branch: a snapshot, and a restore into a world it has stepped.
    let snapshot = world.snapshot();
    c.bench_function("snapshot_201_objects", |b| {
        b.iter(|| black_box(world.snapshot()))
    });
    let mut scratch = world.clone();
    c.bench_function("restore_201_objects", |b| {
        b.iter(|| scratch.restore(black_box(&snapshot)))
    });

    // Queries on the settled scene: one ray across the room, a 360-ray lidar sweep at 0.3 m
    // height, and a 0.3 m sphere overlap test (a planner's collision check), the query index
    // already built.
    let none = QueryFilter::default();
    let origin = Vector::new(-9.0, 0.0, 0.3);
    let sweep: Vec<(Vector, Vector)> = (0..360)
        .map(|k| {
            let a = (k as f32).to_radians();
            (origin, Vector::new(a.cos(), a.sin(), 0.0))
        })
        .collect();
    c.bench_function("ray_first_hit", |b| {
        b.iter(|| black_box(world.query().cast_ray(origin, Vector::X, 30.0, &none)))
    });
    c.bench_function("lidar_360_rays", |b| {
        b.iter(|| black_box(world.query().cast_rays(&sweep, 30.0, &none)))
    });
    let probe = Primitive::Sphere { radius: 0.3 };
    let at = Pose::from_translation(Vector::new(-8.0, -4.0, 1.0));
    c.bench_function("sphere_overlap_query", |b| {
        b.iter(|| black_box(world.query().overlaps(&probe, at, &none)))
    });
    // After a teleport the index is rebuilt on the next query: the cost a planner pays per
    // configuration it moves an object to.
    let mut moving = world.clone();
    let thing = ObjectId(200);
    let home = moving.bodies().pose(thing);
    c.bench_function("teleport_then_ray", |b| {
        b.iter(|| {
            moving.bodies_mut().set_pose(thing, home).unwrap();
            black_box(moving.query().cast_ray(origin, Vector::X, 30.0, &none))
        })
    });
}

criterion_group! {
    name = world;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = benches
}
criterion_main!(world);
