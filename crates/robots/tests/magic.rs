//! Symbolic moves: teleporting, grasping and releasing at once.

use behavior_robots::{ActionSpace, BODY_HEIGHT, MagicError, Robot, RobotKind};
use behavior_sim::{Material, ObjectSpec, Part, Primitive, World};
use rapier3d::math::{Pose, Rotation, Vector};

/// A floor, a robot of `kind` at the origin and a carton-sized box 1 m in front of it.
fn scene(kind: RobotKind) -> (World, Robot, behavior_sim::ObjectId) {
    let mut world = World::default();
    let slab = Part::new(Primitive::Box {
        half_extents: Vector::new(10.0, 10.0, 0.05),
    });
    let floor = ObjectSpec::new("floor_0", "floor.n.01", vec![slab])
        .looks([200, 200, 200], Material::Stone)
        .at(Vector::new(0.0, 0.0, -0.05))
        .fixed();
    world.add(floor).unwrap();
    let carton = Part::new(Primitive::Box {
        half_extents: Vector::new(0.25, 0.2, 0.15),
    });
    let mut spec =
        ObjectSpec::new("carton_1", "carton.n.02", vec![carton]).at(Vector::new(1.0, 0.0, 0.15));
    spec.density = 100.0; // 6 kg: cardboard and what it holds

    let carton = world.add(spec).unwrap();
    let pose = Robot::standing_pose(kind, Vector::ZERO, 0.0);
    let robot = Robot::add(kind, ActionSpace::Full, &mut world, pose).unwrap();
    (world, robot, carton)
}

fn steps(world: &mut World, robot: &mut Robot, n: usize) {
    let still = robot.still_action(robot.space());
    for _ in 0..n {
        robot.set_action(&still).unwrap();
        world.step_with(robot);
    }
}

#[test]
fn a_grasp_made_at_once_holds_through_steps_and_a_teleport() {
    for kind in RobotKind::ALL {
        let (mut world, mut robot, carton) = scene(kind);
        let hand = robot.hands() - 1;
        robot.grasp_now(&mut world, hand, carton).unwrap();
        steps(&mut world, &mut robot, 30);
        assert_eq!(
            robot.held(hand),
            Some(carton),
            "{kind:?} dropped it while standing"
        );
        let to = Robot::standing_pose(kind, Vector::new(3.0, 2.0, 0.0), 1.0);
        robot.teleport(&mut world, to).unwrap();
        steps(&mut world, &mut robot, 30);
        assert_eq!(
            robot.held(hand),
            Some(carton),
            "{kind:?} dropped it after the teleport"
        );
        let base = robot.base_pose(&world).translation;
        assert!(
            (base.truncate() - Vector::new(3.0, 2.0, 0.0).truncate()).length() < 1e-3,
            "{kind:?} at {base:?}"
        );
        let near = (world.bodies().aabb(carton).center() - base).length();
        assert!(near < 1.5, "{kind:?}: the carton is {near} m from the base");
        let held_at = world.bodies().aabb(carton).mins.z;
        assert_eq!(robot.release_now(&mut world, hand), Some(carton));
        steps(&mut world, &mut robot, 60);
        assert_eq!(robot.held(hand), None);
        // To the floor, or onto the R1's base, over which its hands hang.
        let fell = held_at - world.bodies().aabb(carton).mins.z;
        assert!(fell > 0.1, "{kind:?}: the released carton fell {fell} m");
    }
}

#[test]
fn a_full_hand_and_a_fixed_object_are_refused() {
    let (mut world, mut robot, carton) = scene(RobotKind::Behavior);
    robot.grasp_now(&mut world, 1, carton).unwrap();
    assert_eq!(
        robot.grasp_now(&mut world, 1, carton),
        Err(MagicError::HandFull(carton))
    );
    assert_eq!(
        robot.grasp_now(&mut world, 2, carton),
        Err(MagicError::NoHand(2))
    );
    let floor = world.bodies().object_named("floor_0").unwrap();
    assert_eq!(
        robot.grasp_now(&mut world, 0, floor),
        Err(MagicError::NotHoldable(floor))
    );
    let bad = Pose::from_parts(Vector::new(f32::NAN, 0.0, BODY_HEIGHT), Rotation::IDENTITY);
    assert_eq!(robot.teleport(&mut world, bad), Err(MagicError::BadPose));
}

#[test]
fn a_hand_reset_puts_a_pinned_palm_back_at_its_target_with_what_it_holds() {
    let (mut world, mut robot, carton) = scene(RobotKind::Behavior);
    robot.grasp_now(&mut world, 1, carton).unwrap();
    steps(&mut world, &mut robot, 10);
    let Robot::Behavior(bot, _) = &robot else {
        unreachable!()
    };
    let side = behavior_robots::Side::Right;
    let (palm, target) = (
        bot.parts().hand(side),
        bot.body_pose(&world) * bot.hand_target(side),
    );
    let grip = world
        .bodies()
        .pose(palm)
        .inv_mul(&world.bodies().pose(carton));
    // Left 2 m behind with what it holds, as a doorway can leave it.
    let behind = Pose::from_translation(Vector::new(-2.0, 0.0, 1.0));
    world.bodies_mut().set_pose(palm, behind).unwrap();
    world.bodies_mut().set_pose(carton, behind * grip).unwrap();
    robot.reset_hand(&mut world, 1).unwrap();
    let now = world.bodies().pose(palm);
    assert!(
        (now.translation - target.translation).length() < 1e-4,
        "{now:?}"
    );
    let carried = world
        .bodies()
        .pose(palm)
        .inv_mul(&world.bodies().pose(carton));
    assert!((carried.translation - grip.translation).length() < 1e-4);
    steps(&mut world, &mut robot, 30);
    assert_eq!(robot.held(1), Some(carton), "still held after the reset");
    assert_eq!(robot.reset_hand(&mut world, 2), Err(MagicError::NoHand(2)));
}
