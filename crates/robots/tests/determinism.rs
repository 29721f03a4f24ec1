//! The same actions give the same world, bit for bit, and a saved world with its robot goes on
//! as the original does.

mod common;

use behavior_core::rng::{seeded, uniform};
use behavior_robots::{ACTION_DIM, Action, BehaviorRobot};
use behavior_sim::World;
use common::*;

/// A table with an apple and two boxes on it, and a robot before it.
fn scene() -> (World, BehaviorRobot) {
    let mut world = World::default();
    floor(&mut world);
    table(&mut world, 1.0, 0.0);
    apple(&mut world, v(0.7, -0.12, 0.791));
    crate_of(&mut world, "box_a", v(0.8, 0.2, 0.75), 0.05, 0.5);
    crate_of(&mut world, "box_b", v(1.2, -0.2, 0.75), 0.08, 2.0);
    let robot = robot_at(&mut world, 0.0, 0.0);
    (world, robot)
}

fn random_actions(seed: u64, n: usize) -> Vec<Action> {
    let mut rng = seeded(seed);
    (0..n)
        .map(|_| {
            let values: Vec<f32> = (0..ACTION_DIM)
                .map(|_| uniform(&mut rng, -1.0, 1.0))
                .collect();
            Action::new(&values).unwrap()
        })
        .collect()
}

/// Every body's motion state and the robot's proprioception, as raw bits.
fn fingerprint(world: &World, robot: &BehaviorRobot) -> Vec<u32> {
    let mut bits = world.bodies().motion_bits();
    bits.extend(robot.proprioception(world).to_array().map(f32::to_bits));
    bits
}

fn run(world: &mut World, robot: &mut BehaviorRobot, actions: &[Action]) {
    for &a in actions {
        step(world, robot, a);
    }
}

#[test]
fn the_same_hundred_random_actions_give_bit_identical_worlds() {
    let actions = random_actions(7, 100);
    let (mut a, mut robot_a) = scene();
    let (mut b, mut robot_b) = scene();
    run(&mut a, &mut robot_a, &actions);
    run(&mut b, &mut robot_b, &actions);
    let start = scene();
    assert_ne!(
        fingerprint(&a, &robot_a),
        fingerprint(&start.0, &start.1),
        "the actions moved something"
    );
    assert_eq!(fingerprint(&a, &robot_a), fingerprint(&b, &robot_b));
    // Other actions, another world.
    let (mut c, mut robot_c) = scene();
    run(&mut c, &mut robot_c, &random_actions(8, 100));
    assert_ne!(fingerprint(&a, &robot_a), fingerprint(&c, &robot_c));
}

#[test]
fn a_snapshot_taken_mid_run_with_the_robot_continues_identically() {
    let actions = random_actions(11, 100);
    let (mut world, mut robot) = scene();
    run(&mut world, &mut robot, &actions[..50]);
    let (saved_world, saved_robot) = (world.snapshot(), robot.clone());
    run(&mut world, &mut robot, &actions[50..]);
    let expected = fingerprint(&world, &robot);

    world.restore(&saved_world);
    let mut robot = saved_robot.clone();
    run(&mut world, &mut robot, &actions[50..]);
    assert_eq!(
        fingerprint(&world, &robot),
        expected,
        "rewound and replayed"
    );

    let mut fresh = World::default();
    fresh.restore(&saved_world);
    let mut robot = saved_robot;
    run(&mut fresh, &mut robot, &actions[50..]);
    assert_eq!(
        fingerprint(&fresh, &robot),
        expected,
        "restored into another world"
    );
}

mod fetch {
    use super::*;
    use behavior_robots::{FETCH_ACTION_DIM, Fetch, FetchAction};
    use rapier3d::math::Pose;

    /// The same table, with Fetch before it: its arm reaches the apple and the boxes.
    fn scene() -> (World, Fetch) {
        let mut world = World::default();
        floor(&mut world);
        table(&mut world, 0.95, 0.0);
        apple(&mut world, v(0.55, -0.1, 0.791));
        crate_of(&mut world, "box_a", v(0.6, 0.15, 0.75), 0.04, 0.5);
        crate_of(&mut world, "box_b", v(1.2, -0.2, 0.75), 0.08, 2.0);
        let robot = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        (world, robot)
    }

    fn random_actions(seed: u64, n: usize) -> Vec<FetchAction> {
        let mut rng = seeded(seed);
        (0..n)
            .map(|_| {
                let values: Vec<f32> = (0..FETCH_ACTION_DIM)
                    .map(|_| uniform(&mut rng, -1.0, 1.0))
                    .collect();
                FetchAction::new(&values).unwrap()
            })
            .collect()
    }

    fn fingerprint(world: &World, robot: &Fetch) -> Vec<u32> {
        let mut bits = world.bodies().motion_bits();
        bits.extend(robot.proprioception(world).to_array().map(f32::to_bits));
        bits
    }

    fn run(world: &mut World, robot: &mut Fetch, actions: &[FetchAction]) {
        for &a in actions {
            robot.set_action(a);
            world.step_with(robot);
        }
    }

    #[test]
    fn fetch_under_the_same_random_actions_gives_bit_identical_worlds() {
        let actions = random_actions(7, 100);
        let (mut a, mut robot_a) = scene();
        let (mut b, mut robot_b) = scene();
        run(&mut a, &mut robot_a, &actions);
        run(&mut b, &mut robot_b, &actions);
        let start = scene();
        assert_ne!(fingerprint(&a, &robot_a), fingerprint(&start.0, &start.1));
        assert_eq!(fingerprint(&a, &robot_a), fingerprint(&b, &robot_b));
        let (mut c, mut robot_c) = scene();
        run(&mut c, &mut robot_c, &random_actions(8, 100));
        assert_ne!(fingerprint(&a, &robot_a), fingerprint(&c, &robot_c));
    }

    #[test]
    fn a_snapshot_of_fetch_mid_run_continues_identically() {
        let actions = random_actions(11, 100);
        let (mut world, mut robot) = scene();
        run(&mut world, &mut robot, &actions[..50]);
        let (saved_world, saved_robot) = (world.snapshot(), robot.clone());
        run(&mut world, &mut robot, &actions[50..]);
        let expected = fingerprint(&world, &robot);

        world.restore(&saved_world);
        let mut robot = saved_robot.clone();
        run(&mut world, &mut robot, &actions[50..]);
        assert_eq!(fingerprint(&world, &robot), expected, "rewound");

        let mut fresh = World::default();
        fresh.restore(&saved_world);
        let mut robot = saved_robot;
        run(&mut fresh, &mut robot, &actions[50..]);
        assert_eq!(fingerprint(&fresh, &robot), expected, "another world");
    }
}
