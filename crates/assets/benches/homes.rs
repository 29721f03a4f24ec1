//! Generating a home from a seed, cluttering it, building a scene into a world, and stepping a
//! freshly built home with and without clutter (which costs next to nothing once the first step
//! has found the resting contacts: everything starts asleep), and saving and loading a home's
//! full state as bytes (`World::to_bytes`, `World::from_bytes`).
//! `cargo bench -p behavior-assets`.

use behavior_assets::{Library, NAMED_HOMES, Scene, clutter, generate};
use behavior_data::DataDir;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let (name, seed) = NAMED_HOMES[0];
    c.bench_function("generate_a_home", |b| {
        b.iter(|| black_box(generate(name, seed, &library).unwrap()))
    });
    let scene = generate(name, seed, &library).unwrap();
    let json = scene.to_json();
    c.bench_function("load_a_scene_file_and_build_the_world", |b| {
        b.iter(|| {
            black_box(
                Scene::from_json(&json)
                    .unwrap()
                    .build(&library)
                    .unwrap()
                    .world
                    .bodies()
                    .objects()
                    .len(),
            )
        })
    });
    cluttered(c, &library, &scene);
}

/// Cluttering the home, loading and building the cluttered home, and stepping both homes.
fn cluttered(c: &mut Criterion, library: &Library, scene: &Scene) {
    let mut group = c.benchmark_group("cluttered");
    group.sample_size(10);
    group.bench_function("clutter_a_home", |b| {
        b.iter(|| black_box(clutter(scene, library, scene.seed).unwrap().clutter.len()))
    });
    let full = clutter(scene, library, scene.seed).unwrap();
    let json = full.to_json();
    group.bench_function("load_a_cluttered_scene_file_and_build_the_world", |b| {
        b.iter(|| {
            black_box(
                Scene::from_json(&json)
                    .unwrap()
                    .build(library)
                    .unwrap()
                    .clutter
                    .len(),
            )
        })
    });
    for (label, home) in [("home", scene), ("cluttered_home", &full)] {
        let mut built = home.build(library).unwrap();
        // The first step finds every resting contact (and puts back to sleep what that wakes).
        group.bench_function(format!("first_step_of_a_built_{label}"), |b| {
            b.iter_batched(
                || built.world.clone(),
                |mut world| {
                    world.step();
                    world
                },
                criterion::BatchSize::LargeInput,
            )
        });
        // Then the home is at rest: an idle step.
        built.world.step();
        group.bench_function(format!("idle_step_of_a_{label}"), |b| {
            b.iter(|| built.world.step())
        });
        // A full-state checkpoint of the home at rest, with its resting contacts.
        group.bench_function(format!("{label}_to_bytes"), |b| {
            b.iter(|| black_box(built.world.to_bytes().len()))
        });
        let bytes = built.world.to_bytes();
        group.bench_function(format!("{label}_from_bytes"), |b| {
            b.iter(|| {
                black_box(
                    behavior_sim::World::from_bytes(&bytes)
                        .unwrap()
                        .bodies()
                        .steps(),
                )
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = homes;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = benches
}
criterion_main!(homes);
