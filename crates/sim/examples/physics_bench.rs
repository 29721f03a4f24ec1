//! Physics timing on a resting home-like scene, and the scene written out for PyBullet.
//!
//! `cargo run --release -p behavior-sim --example physics_bench -- [--scene OUT.json] [--json] [--quick]`
//!
//! The scene: a 20 × 20 m floor, 10 tables (a top on four legs) and 190 small boxes, cylinders
//! and balls resting on the tables and the floor — 201 objects. Times are per action step
//! (1/30 s): 10 substeps of 1/300 s, or 4 of 1/120 s. "idle": after 300 steps of settling, with
//! sleeping on; "awake": the same with sleeping disabled. `bench/physics_side_by_side.sh` runs
//! this and the PyBullet script on the same scene file.

#[path = "../benches/common/mod.rs"]
mod common;

use behavior_sim::{ObjectSpec, Primitive, Substeps, World};
use common::resting_home as scene;
use std::time::Instant;

fn build(substeps: Substeps, sleeping: bool) -> World {
    let mut world = World::new(substeps);
    for spec in scene() {
        world.add(spec).expect("the benchmark scene is valid");
    }
    world.bodies_mut().set_sleeping_allowed(sleeping);
    world
}

/// Median nanoseconds per action step over `repeats` blocks of `steps` steps, after settling.
fn time(substeps: Substeps, sleeping: bool, steps: usize, repeats: usize) -> (f64, usize) {
    let mut world = build(substeps, sleeping);
    for _ in 0..300 {
        world.step();
    }
    let asleep = world
        .bodies()
        .objects()
        .filter(|(id, o)| !o.is_fixed() && world.bodies().is_sleeping(*id))
        .count();
    let mut samples: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..steps {
                world.step();
            }
            start.elapsed().as_nanos() as f64 / steps as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    (samples[samples.len() / 2], asleep)
}

fn scene_json(specs: &[ObjectSpec]) -> serde_json::Value {
    let objects: Vec<serde_json::Value> = specs
        .iter()
        .map(|s| {
            let parts: Vec<serde_json::Value> = s
                .parts
                .iter()
                .map(|p| {
                    let o = p.offset.translation;
                    let offset = [o.x, o.y, o.z];
                    match p.primitive.clone() {
                        Primitive::Box { half_extents: h } => serde_json::json!({"type": "box", "half_extents": [h.x, h.y, h.z], "offset": offset}),
                        Primitive::Cylinder { radius, half_height } => serde_json::json!({"type": "cylinder", "radius": radius, "half_height": half_height, "offset": offset}),
                        Primitive::Sphere { radius } => serde_json::json!({"type": "sphere", "radius": radius, "offset": offset}),
                        Primitive::Capsule { .. } | Primitive::ConvexHull { .. } => {
                            unreachable!("the benchmark scene has only boxes, cylinders and balls")
                        }
                    }
                })
                .collect();
            let t = s.pose.translation;
            let r = s.pose.rotation;
            serde_json::json!({
                "name": s.name, "fixed": s.body == behavior_sim::BodyKind::Fixed, "position": [t.x, t.y, t.z],
                "orientation_xyzw": [r.x, r.y, r.z, r.w], "density": s.density, "friction": s.friction,
                "parts": parts,
            })
        })
        .collect();
    serde_json::json!({"gravity": [0.0, 0.0, -9.81], "dt": 1.0 / 300.0, "substeps_per_step": 10, "objects": objects})
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let json = args.iter().any(|a| a == "--json");
    let quick = args.iter().any(|a| a == "--quick");
    if let Some(i) = args.iter().position(|a| a == "--scene") {
        let Some(path) = args.get(i + 1) else {
            eprintln!("--scene needs a file name");
            std::process::exit(2);
        };
        let text = serde_json::to_string_pretty(&scene_json(&scene())).expect("serializable");
        if let Err(e) = std::fs::write(path, text) {
            eprintln!("cannot write {path}: {e}");
            std::process::exit(1);
        }
    }
    let (steps, repeats) = if quick { (20, 1) } else { (100, 5) };
    let specs = scene();
    let dynamic = specs
        .iter()
        .filter(|s| s.body != behavior_sim::BodyKind::Fixed)
        .count();
    let (idle, asleep) = time(Substeps::Hz300, true, steps, repeats);
    let (awake, _) = time(Substeps::Hz300, false, steps, repeats);
    let (idle_120, _) = time(Substeps::Hz120, true, steps, repeats);
    let (awake_120, _) = time(Substeps::Hz120, false, steps, repeats);
    if json {
        println!(
            "{}",
            serde_json::json!({
                "engine": "behavior-sim (rapier3d 0.36)", "objects": specs.len(), "dynamic": dynamic,
                "idle_ns": idle, "awake_ns": awake, "idle_120_ns": idle_120, "awake_120_ns": awake_120,
                "sleeping_after_settle": asleep,
            })
        );
    } else {
        println!(
            "{} objects ({dynamic} dynamic), {asleep} asleep after settling",
            specs.len()
        );
        println!("per action step (1/30 s):");
        println!(
            "  1/300 substeps: idle {:>10.0} ns   awake {:>10.0} ns",
            idle, awake
        );
        println!(
            "  1/120 substeps: idle {:>10.0} ns   awake {:>10.0} ns",
            idle_120, awake_120
        );
    }
}
