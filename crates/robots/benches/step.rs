//! What an action step costs with each robot in a small scene — a table with 20 small boxes on
//! and around it — standing still, driving back and forth, and under random actions, at the
//! world's two substep rates. Every robot through the one interface (`Robot`, its full action
//! space). `cargo bench -p behavior-robots --bench step`; the figures are in the guide's robots
//! chapter.

use behavior_core::rng::{seeded, uniform};
use behavior_robots::{ActionSpace, BaseMove, Robot, RobotKind};
use behavior_sim::{ObjectSpec, Part, Primitive, Substeps, World};
use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use rapier3d::math::Vector;
use std::time::Duration;

fn cuboid(hx: f32, hy: f32, hz: f32) -> Primitive {
    Primitive::Box {
        half_extents: Vector::new(hx, hy, hz),
    }
}

/// A floor, a table 1 m ahead with 10 boxes on it and 10 on the floor beside it, and a robot of
/// `kind` at the origin, after a second of standing.
fn scene(kind: RobotKind, substeps: Substeps) -> (World, Robot) {
    let mut world = World::new(substeps);
    let floor = ObjectSpec::new(
        "floor",
        "floor.n.01",
        vec![Part::new(cuboid(10.0, 5.0, 0.05))],
    );
    world
        .add(floor.at(Vector::new(0.0, 0.0, -0.05)).fixed())
        .unwrap();
    let mut legs = vec![Part::at(
        cuboid(0.6, 0.4, 0.025),
        Vector::new(0.0, 0.0, 0.725),
    )];
    for (x, y) in [(-0.55, -0.35), (0.55, -0.35), (-0.55, 0.35), (0.55, 0.35)] {
        legs.push(Part::at(
            cuboid(0.025, 0.025, 0.35),
            Vector::new(x, y, 0.35),
        ));
    }
    let table = ObjectSpec::new("table", "table.n.02", legs);
    world
        .add(table.at(Vector::new(1.0, 0.0, 0.0)).fixed())
        .unwrap();
    for k in 0..10 {
        let (x, y) = (0.6 + 0.08 * k as f32, if k % 2 == 0 { 0.25 } else { -0.3 });
        for (name, at, half, mass) in [
            (format!("on_{k}"), Vector::new(x, y, 0.75), 0.03, 0.3),
            (format!("under_{k}"), Vector::new(x, 1.0, 0.0), 0.04, 0.5),
        ] {
            let mut spec = ObjectSpec::new(
                &name,
                "carton.n.02",
                vec![Part::new(cuboid(half, half, half))],
            )
            .at(at + Vector::new(0.0, 0.0, half + 0.001));
            spec.density = mass / (8.0 * half * half * half);
            world.add(spec).unwrap();
        }
    }
    let pose = Robot::standing_pose(kind, Vector::new(-0.2, 0.0, 0.0), 0.0);
    let mut robot = Robot::add(kind, ActionSpace::Full, &mut world, pose).unwrap();
    let still = robot.still_action(robot.space());
    for _ in 0..30 {
        robot.set_action(&still).unwrap();
        world.step_with(&mut robot);
    }
    (world, robot)
}

/// 600 actions of each kind of motion: still, back and forth along x (30 steps each way, at
/// what one step allows), and random in every entry.
fn motions(robot: &Robot) -> [(&'static str, Vec<Vec<f32>>); 3] {
    let dim = robot.action_dim();
    let drive = (0..600)
        .map(|k| {
            let forward = if (k / 30) % 2 == 0 { 0.05 } else { -0.05 };
            let step = BaseMove {
                forward,
                ..BaseMove::default()
            };
            robot
                .base_action(step)
                .expect("the full space moves the base")
        })
        .collect();
    let mut rng = seeded(3);
    // Random within each number's bounds (a joint's limits where the number is its position).
    let bounds = robot.action_bounds();
    let random = (0..600)
        .map(|_| {
            (0..dim)
                .map(|k| uniform(&mut rng, bounds[k][0], bounds[k][1]))
                .collect()
        })
        .collect();
    let still = robot.still_action(robot.space());
    [
        ("still", vec![still; 600]),
        ("driving", drive),
        ("random", random),
    ]
}

fn steps(c: &mut Criterion) {
    let mut group = c.benchmark_group("robot step");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(4));
    for kind in RobotKind::ALL {
        for (substeps, rate) in [(Substeps::Hz300, "300 Hz"), (Substeps::Hz120, "120 Hz")] {
            let (world, robot) = scene(kind, substeps);
            for (motion, actions) in motions(&robot) {
                let name = format!("{} {motion} {rate} (600 steps)", kind.name());
                group.bench_function(name, |b| {
                    b.iter_batched(
                        || (world.clone(), robot.clone()),
                        |(mut world, mut robot)| {
                            for action in &actions {
                                robot.set_action(action).unwrap();
                                world.step_with(&mut robot);
                            }
                            world
                        },
                        BatchSize::PerIteration,
                    )
                });
            }
        }
    }
    group.finish();
}

criterion_group!(benches, steps);
criterion_main!(benches);
