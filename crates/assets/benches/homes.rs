//! Generating a home from a seed, and building a scene into a world.
//! `cargo bench -p behavior-assets`.

use behavior_assets::{Library, NAMED_HOMES, Scene, generate};
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
                    .objects()
                    .len(),
            )
        })
    });
}

criterion_group! {
    name = homes;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = benches
}
criterion_main!(homes);
