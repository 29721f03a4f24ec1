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

/// A robot of `kind` standing at the origin, driven through its primitive space.
fn standing(kind: RobotKind, world: &mut World) -> Robot {
    let start = Robot::standing_pose(kind, Vector::ZERO, 0.0);
    Robot::add(kind, kind.spec().primitive_space, world, start).unwrap()
}

#[test]
fn every_hand_is_lent_through_exactly_one_of_the_two_hand_interfaces() {
    for kind in RobotKind::ALL {
        let mut world = World::default();
        let robot = standing(kind, &mut world);
        for hand in 0..robot.hands() {
            let (arm, posed) = (robot.arm(hand).is_some(), robot.posed_hand(hand).is_some());
            assert!(
                arm != posed,
                "{}: hand {hand}: arm {arm}, posed {posed}",
                kind.name()
            );
            if let Some(arm) = robot.arm(hand) {
                assert_eq!(arm.hand(), hand);
            }
            if let Some(posed) = robot.posed_hand(hand) {
                assert_eq!(posed.hand(), hand);
            }
        }
        let beyond = robot.hands();
        assert!(robot.arm(beyond).is_none() && robot.posed_hand(beyond).is_none());
    }
}

#[test]
fn an_arm_reads_its_own_pose_back_through_ik_and_predicts_its_joint_action() {
    for kind in RobotKind::ALL {
        let mut world = World::default();
        let mut robot = standing(kind, &mut world);
        for hand in 0..robot.hands() {
            let Some(arm) = robot.arm(hand) else {
                continue;
            };
            let name = format!("{} hand {hand}", kind.name());
            let now = arm.now();
            assert_eq!(now.len(), arm.limits().len());
            assert_eq!(arm.link_poses(&now).len(), arm.links().len());
            // The end effector where the gripper's object is.
            let gripper = world.bodies().pose(arm.links()[arm.gripper()]);
            let eef = robot.base_pose(&world) * arm.eef(&now);
            assert!(
                (gripper.translation - eef.translation).length() < 1e-4,
                "{name}"
            );
            // Its own pose is solved where it is; 5 cm higher, a solution near it (the search
            // a straight line of the end effector makes, a step at a time) puts it there.
            let here = arm.ik(&now, &arm.eef(&now)).expect("its own pose");
            assert!((arm.eef(&here).translation - arm.eef(&now).translation).length() < 0.01);
            let mut goal = arm.eef(&now);
            goal.translation.z += 0.05;
            let solved = arm.ik_near(&now, &goal).expect("5 cm up is within reach");
            let reached = arm.eef(&solved);
            assert!(
                (reached.translation - goal.translation).length() < 0.01,
                "{name}"
            );
            // A joint action's predicted step is the step the robot takes.
            let mut delta = now;
            delta.values_mut().fill(0.0);
            delta[1] = 0.02;
            let action = arm
                .joint_action(&now, &delta, 1.0)
                .expect("a finite action");
            let predicted = arm.after(&now, &action);
            assert!(
                (predicted[1] - now[1] - 0.02).abs() < 1e-5,
                "{name}: {predicted:?}"
            );
            robot.set_action(&action).unwrap();
            world.step_with(&mut robot);
            let stepped = robot.arm(hand).unwrap().now();
            assert_eq!(stepped, predicted, "{name}");
            assert!(robot.arm(hand).unwrap().fingers_open(&world), "{name}");
        }
    }
}

#[test]
fn a_posed_hands_actions_move_its_target_press_its_trigger_and_raise_the_body() {
    for kind in RobotKind::ALL {
        let mut world = World::default();
        let mut robot = standing(kind, &mut world);
        let Some(hand) = robot.posed_hand(1) else {
            continue;
        };
        let before = hand.target();
        let body = robot.base_pose(&world).translation.z;
        robot
            .set_action(&hand.move_action([0.01, -0.02, 0.0, 0.0, 0.0, 0.0]))
            .unwrap();
        world.step_with(&mut robot);
        let moved = robot.posed_hand(1).unwrap().target().translation - before.translation;
        assert!(
            (moved - Vector::new(0.01, -0.02, 0.0)).length() < 1e-5,
            "{moved:?}"
        );
        robot.set_action(&hand.trigger_action(1.0)).unwrap();
        world.step_with(&mut robot);
        assert!(robot.posed_hand(1).unwrap().trigger() > 0.0);
        assert_eq!(robot.posed_hand(0).unwrap().trigger(), 0.0);
        robot.set_action(&hand.lift_action(-0.03)).unwrap();
        world.step_with(&mut robot);
        let lowered = body - robot.base_pose(&world).translation.z;
        assert!((lowered - 0.03).abs() < 1e-3, "{lowered}");
        // One action moved the target by 1 and 2 cm: within a step of it.
        assert!(hand.step() >= 0.02 && hand.reach() > hand.step());
    }
}
