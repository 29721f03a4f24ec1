//! Criterion benchmarks of the BDDL crate on the 100 official definitions:
//! parse + check of all 100, and goal evaluation and exact Q on each activity's initial state
//! (the positive `:init` literals without `inroom`). Run: `cargo bench -p behavior-bddl`.
//! Per-activity medians and the side-by-side with the reference Python implementation come from
//! `behavior bddl bench` and `bench/side_by_side.sh`.

use behavior_bddl::load::{Knowledge, read_source};
use behavior_bddl::{FactSet, GroundGoal, Optimizer};
use behavior_data::DataDir;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).expect("official data");
    let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let sources: Vec<_> = data
        .activities()
        .unwrap()
        .iter()
        .map(|a| read_source(&data.problem_path(a).unwrap()).unwrap())
        .collect();

    c.bench_function("parse_and_check_all_100", |b| {
        b.iter(|| {
            for source in &sources {
                black_box(knowledge.load(source).unwrap());
            }
        })
    });

    let activities: Vec<_> = sources
        .iter()
        .map(|s| knowledge.load(s).unwrap().0)
        .collect();
    let goals: Vec<GroundGoal> = activities.iter().map(GroundGoal::new).collect();
    let states: Vec<FactSet> = activities
        .iter()
        .map(|a| a.initial_facts().into_iter().collect())
        .collect();

    c.bench_function("ground_all_100_goals", |b| {
        b.iter(|| {
            for a in &activities {
                black_box(GroundGoal::new(a));
            }
        })
    });
    c.bench_function("goal_eval_all_100", |b| {
        b.iter(|| {
            for (goal, state) in goals.iter().zip(&states) {
                black_box(goal.holds(state));
            }
        })
    });
    c.bench_function("q_all_100", |b| {
        b.iter(|| {
            for (goal, state) in goals.iter().zip(&states) {
                black_box(Optimizer::new(goal).q(state));
            }
        })
    });
    c.bench_function("volume_all_100", |b| {
        b.iter(|| {
            for goal in &goals {
                black_box(Optimizer::new(goal).volume());
            }
        })
    });
}

criterion_group! {
    name = bddl;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = benches
}
criterion_main!(bddl);
