//! Every robot through the one interface: its facts agree with what it does, and the base
//! action each gives for an offset takes its base there, whatever its drive.

use behavior_robots::{ActionSpace, BaseMove, Robot, RobotKind};
use behavior_sim::World;
use rapier3d::math::{Pose, Vector};
use std::f32::consts::PI;

/// Where the base is, relative to where it should get: (forward, left, turn) in its own frame.
fn offset(world: &World, robot: &Robot, goal: (f32, f32, f32)) -> BaseMove {
    let pose = robot.base_pose(world);
    let forward = pose.rotation * Vector::X;
    let yaw = forward.y.atan2(forward.x);
    let (dx, dy) = (goal.0 - pose.translation.x, goal.1 - pose.translation.y);
    let turn = (goal.2 - yaw + PI).rem_euclid(2.0 * PI) - PI;
    let (c, s) = (yaw.cos(), yaw.sin());
    BaseMove {
        forward: c * dx + s * dy,
        left: -s * dx + c * dy,
        turn,
        within: 0.01,
    }
}

#[test]
fn each_robots_base_action_takes_its_base_to_a_point_beside_it_and_turns_it() {
    for kind in RobotKind::ALL {
        let mut world = World::default();
        let start = Robot::standing_pose(kind, Vector::ZERO, 0.0);
        let space = kind.spec().primitive_space;
        let mut robot = Robot::add(kind, space, &mut world, start).unwrap();
        // To the left and a little ahead: a differential base must turn, drive and turn again.
        let goal = (0.3, 0.6, 1.0);
        let mut steps = 0;
        loop {
            let step = offset(&world, &robot, goal);
            let there = step.forward.hypot(step.left) <= step.within && step.turn.abs() <= 0.02;
            if there || steps == 600 {
                break;
            }
            let action = robot
                .base_action(step)
                .expect("its primitive space moves the base");
            assert_eq!(action.len(), robot.action_dim(), "{kind:?}");
            robot.set_action(&action).unwrap();
            world.step_with(&mut robot);
            steps += 1;
        }
        let last = offset(&world, &robot, goal);
        assert!(
            last.forward.hypot(last.left) <= 0.011 && last.turn.abs() <= 0.021,
            "{kind:?} ended {last:?} from the goal after {steps} steps"
        );
        let height = robot.base_pose(&world).translation.z;
        assert!(
            (height - kind.spec().origin_height).abs() < 1e-4,
            "{kind:?} stands at {height}"
        );
    }
}

#[test]
fn a_space_without_the_base_has_no_base_action_and_unsupported_spaces_are_refused() {
    for kind in RobotKind::ALL {
        let spec = kind.spec();
        for space in ActionSpace::ALL {
            let mut world = World::default();
            let added = Robot::add(kind, space, &mut world, Pose::IDENTITY);
            let Ok(robot) = added else {
                assert!(!spec.drives(space), "{kind:?} refused {space:?}");
                continue;
            };
            assert!(spec.drives(space), "{kind:?} took {space:?}");
            let step = BaseMove {
                forward: 0.02,
                ..BaseMove::default()
            };
            let action = robot.base_action(step);
            match space {
                ActionSpace::TabletopManipulation => assert_eq!(action, None, "{kind:?}"),
                _ => {
                    let action = action.expect("a space with the base");
                    assert_eq!(action.len(), robot.action_dim(), "{kind:?} {space:?}");
                    assert!(action.iter().any(|&v| v > 0.0), "{kind:?} {space:?}");
                }
            }
        }
        // Each hand its spec names is one of the robot's objects; the next number is no hand.
        let mut world = World::default();
        let robot = Robot::add(kind, ActionSpace::Full, &mut world, Pose::IDENTITY).unwrap();
        for hand in 0..spec.hands() {
            let object = robot.hand_object(hand).expect("a hand the spec names");
            assert!(robot.objects().contains(&object), "{kind:?} hand {hand}");
        }
        assert_eq!(robot.hand_object(spec.hands()), None, "{kind:?}");
        assert_eq!(robot.held(spec.hands()), None, "{kind:?}");
    }
}
