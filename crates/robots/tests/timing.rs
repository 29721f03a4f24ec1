//! What an action step costs with the robot in a small scene: standing still, driving, and
//! under random actions. Printed, not asserted (machines are noisy); run with
//! `cargo test -p behavior-robots --test timing -- --nocapture` (add `--release` for figures
//! comparable with the README's benchmarks).

mod common;

use behavior_core::rng::{seeded, uniform};
use behavior_robots::{ACTION_DIM, Action, BehaviorRobot};
use behavior_sim::{Substeps, World};
use common::*;
use std::time::Instant;

/// A table with 20 small objects on and around it, and the robot before it.
fn scene(substeps: Substeps) -> (World, BehaviorRobot) {
    let mut world = World::new(substeps);
    floor(&mut world);
    table(&mut world, 1.0, 0.0);
    for k in 0..10 {
        let (x, y) = (0.6 + 0.08 * k as f32, if k % 2 == 0 { 0.25 } else { -0.3 });
        crate_of(&mut world, &format!("on_{k}"), v(x, y, 0.75), 0.03, 0.3);
        crate_of(&mut world, &format!("under_{k}"), v(x, 1.0, 0.0), 0.04, 0.5);
    }
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    idle(&mut world, &mut robot, 60);
    (world, robot)
}

/// Mean microseconds per step over `actions`.
fn time(world: &mut World, robot: &mut BehaviorRobot, actions: &[Action]) -> f64 {
    let start = Instant::now();
    for &a in actions {
        step(world, robot, a);
    }
    start.elapsed().as_secs_f64() * 1e6 / actions.len() as f64
}

/// Mean microseconds per step standing still, driving, and under random actions.
fn costs(substeps: Substeps) -> (usize, [f64; 3]) {
    let (mut world, mut robot) = scene(substeps);
    let still = vec![Action::ZERO; 600];
    let idle_us = time(&mut world, &mut robot, &still);
    assert!(
        robot
            .parts()
            .all()
            .iter()
            .all(|&p| world.core().is_sleeping(p)),
        "standing still, the robot sleeps"
    );
    // Back and forth along y at 1.5 m/s, the hands carried.
    let drive: Vec<Action> = (0..600)
        .map(|k| action(&[(1, if (k / 30) % 2 == 0 { 1.0 } else { -1.0 })]))
        .collect();
    let (mut w, mut r) = scene(substeps);
    let drive_us = time(&mut w, &mut r, &drive);
    let mut rng = seeded(3);
    let random: Vec<Action> = (0..600)
        .map(|_| {
            let values: Vec<f32> = (0..ACTION_DIM)
                .map(|_| uniform(&mut rng, -1.0, 1.0))
                .collect();
            Action::new(&values).unwrap()
        })
        .collect();
    let (mut w, mut r) = scene(substeps);
    let random_us = time(&mut w, &mut r, &random);
    (world.objects().len(), [idle_us, drive_us, random_us])
}

#[test]
fn the_cost_of_an_action_step_standing_still_driving_and_acting_at_random() {
    for (substeps, name) in [
        (Substeps::Hz300, "10 × 1/300 s"),
        (Substeps::Hz120, "4 × 1/120 s"),
    ] {
        let (objects, [idle, drive, random]) = costs(substeps);
        println!(
            "{objects} objects, substeps {name}: standing still {idle:.1} µs/step, \
             driving {drive:.0} µs/step, random actions {random:.0} µs/step"
        );
    }
}

mod fetch {
    use super::*;
    use behavior_robots::{FETCH_ACTION_DIM, Fetch, FetchAction};
    use rapier3d::math::Pose;

    /// The same table and objects, with Fetch before the table.
    fn scene(substeps: Substeps) -> (World, Fetch) {
        let mut world = World::new(substeps);
        floor(&mut world);
        table(&mut world, 0.95, 0.0);
        for k in 0..10 {
            let (x, y) = (0.6 + 0.08 * k as f32, if k % 2 == 0 { 0.25 } else { -0.3 });
            crate_of(&mut world, &format!("on_{k}"), v(x, y, 0.75), 0.03, 0.3);
            crate_of(&mut world, &format!("under_{k}"), v(x, 1.0, 0.0), 0.04, 0.5);
        }
        let mut robot = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        run(&mut world, &mut robot, &vec![FetchAction::ZERO; 60]);
        (world, robot)
    }

    fn run(world: &mut World, robot: &mut Fetch, actions: &[FetchAction]) -> f64 {
        let start = Instant::now();
        for &a in actions {
            robot.set_action(a);
            world.step_with(robot);
        }
        start.elapsed().as_secs_f64() * 1e6 / actions.len() as f64
    }

    fn random(seed: u64, keep: impl Fn(usize) -> bool) -> Vec<FetchAction> {
        let mut rng = seeded(seed);
        (0..600)
            .map(|_| {
                let values: Vec<f32> = (0..FETCH_ACTION_DIM)
                    .map(|k| uniform(&mut rng, -1.0, 1.0) * f32::from(u8::from(keep(k))))
                    .collect();
                FetchAction::new(&values).unwrap()
            })
            .collect()
    }

    /// Mean microseconds per step standing still, driving, moving the arm, and at random.
    fn costs(substeps: Substeps) -> [f64; 4] {
        let (mut world, mut robot) = scene(substeps);
        let before = world.core().motion_bits();
        let idle = run(&mut world, &mut robot, &vec![FetchAction::ZERO; 600]);
        assert_eq!(
            world.core().motion_bits(),
            before,
            "standing still, nothing moves"
        );
        // Back and forth along x at 0.5 m/s (clear of the table), then turning.
        let drive: Vec<FetchAction> = (0..600)
            .map(|k| {
                let mut values = [0.0; FETCH_ACTION_DIM];
                values[0] = if (k / 30) % 2 == 0 { -0.5 } else { 0.5 };
                values[1] = 0.3;
                FetchAction::new(&values).unwrap()
            })
            .collect();
        let (mut w, mut r) = scene(substeps);
        let drive_us = run(&mut w, &mut r, &drive);
        // The arm at random (end effector and gripper), the base still.
        let (mut w, mut r) = scene(substeps);
        let arm_us = run(&mut w, &mut r, &random(5, |k| k >= 4));
        let (mut w, mut r) = scene(substeps);
        let random_us = run(&mut w, &mut r, &random(3, |_| true));
        [idle, drive_us, arm_us, random_us]
    }

    #[test]
    fn the_cost_of_a_fetch_step_standing_still_driving_moving_the_arm_and_at_random() {
        for (substeps, name) in [
            (Substeps::Hz300, "10 × 1/300 s"),
            (Substeps::Hz120, "4 × 1/120 s"),
        ] {
            let [idle, drive, arm, random] = costs(substeps);
            println!(
                "Fetch, substeps {name}: standing still {idle:.1} µs/step, driving {drive:.0} \
                 µs/step, moving the arm {arm:.0} µs/step, random actions {random:.0} µs/step"
            );
        }
    }
}
