//! Fetch as a user meets it: inverse kinematics, driving and turning, the head, grasping an
//! apple from a table, bad actions, and the robot through the `Robot` enum.

mod common;

use behavior_robots::{
    ActionSpace, EEF_STEP, Embodiment, FETCH_ACTION_DIM, FETCH_JOINT_ACTION_DIM, Fetch,
    FetchAction, FetchJoint, FetchJointAction, FetchJoints, FetchProprioception, IkError, IkSolver,
    Robot, RobotKind, WHEEL_RADIUS,
};
use behavior_sim::World;
use common::*;
use rapier3d::math::{Pose, Rotation, Vector};
use std::f32::consts::{FRAC_PI_2, PI};

fn fetch_at(world: &mut World, x: f32, y: f32) -> Fetch {
    Fetch::add(world, Pose::from_translation(v(x, y, 0.0))).unwrap()
}

/// An action from (index, value) pairs; the gripper stays open unless told otherwise.
fn act(entries: &[(usize, f32)]) -> FetchAction {
    let mut values = [0.0; FETCH_ACTION_DIM];
    values[FetchAction::GRIPPER] = 1.0;
    for &(i, x) in entries {
        values[i] = x;
    }
    FetchAction::new(&values).unwrap()
}

fn go(world: &mut World, robot: &mut Fetch, action: FetchAction, steps: usize) {
    for _ in 0..steps {
        robot.set_action(action);
        world.step_with(robot);
    }
}

fn yaw(pose: Pose) -> f32 {
    let x = pose.rotation * Vector::X;
    x.y.atan2(x.x)
}

#[test]
fn fetch_ik_reaches_a_reachable_target_within_a_centimetre_and_reports_an_unreachable_one() {
    let solver = IkSolver::default();
    let start = FetchJoints::default();
    // Targets the arm can reach: where other joint positions put the end effector.
    let offsets = [
        (0.05, [0.3, -0.2, 0.0, 0.2, 0.1, -0.3, 0.4]),
        (-0.1, [0.6, 0.3, -0.4, -0.3, 0.5, 0.2, -0.6]),
        (0.2, [-0.4, -0.5, 0.3, 0.4, -0.2, 0.5, 1.0]),
    ];
    for (dt, da) in offsets {
        let goal = FetchJoints {
            torso: start.torso + dt,
            arm: std::array::from_fn(|k| start.arm[k] + da[k]),
            ..start
        }
        .clamped();
        let target = goal.eef();
        let q = solver.solve(&start, &target).unwrap();
        let reached = q.eef();
        let off = (reached.translation - target.translation).length();
        assert!(off < 0.01, "{off} m from {target:?}");
        let turn = reached.rotation.angle_between(target.rotation);
        assert!(turn < 0.02, "{turn} rad off");
        assert_eq!(q.clamped(), q, "within the joint limits");
    }
    // Two metres ahead is out of reach: an error saying how far the closest pose stays.
    let far = Pose::from_translation(v(2.0, 0.0, 1.0));
    match solver.solve(&start, &far) {
        Err(IkError::Unreachable {
            position_error,
            closest,
            ..
        }) => {
            assert!(position_error > 0.5, "{position_error}");
            assert!((closest.eef().translation - far.translation).length() > 0.5);
        }
        other => panic!("expected unreachable, got {other:?}"),
    }
    let bad = Pose::from_translation(v(f32::NAN, 0.0, 1.0));
    assert_eq!(solver.solve(&start, &bad), Err(IkError::NotFinite));
}

#[test]
fn fetch_drives_one_metre_forward_in_one_second_at_full_speed() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    let eef_before = robot.eef_pose(&world).translation;
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::LINEAR, 1.0)]),
        30,
    );
    let base = robot.base_pose(&world);
    assert!(
        (base.translation - v(1.0, 0.0, 0.0)).length() < 1e-3,
        "{base:?}"
    );
    assert!(yaw(base).abs() < 1e-5);
    // The arm came along.
    let eef = robot.eef_pose(&world).translation;
    assert!((eef - eef_before - v(1.0, 0.0, 0.0)).length() < 1e-3);
    // The wheels turned 1 m / r.
    let p = robot.proprioception(&world);
    let wheel = p.joint(FetchJoint::RightWheel);
    assert!(
        (wheel.position - 1.0 / WHEEL_RADIUS).abs() < 0.01,
        "{wheel:?}"
    );
    assert!((wheel.velocity - 1.0 / WHEEL_RADIUS).abs() < 0.01);
    // Without an action it stops.
    go(&mut world, &mut robot, act(&[]), 5);
    assert!((robot.base_pose(&world).translation.x - 1.0).abs() < 1e-3);
}

#[test]
fn fetch_turns_in_place_counter_clockwise_for_a_positive_command() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    // Half speed for one second: a quarter turn.
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::ANGULAR, 0.5)]),
        30,
    );
    let base = robot.base_pose(&world);
    assert!((yaw(base) - FRAC_PI_2).abs() < 1e-3, "{}", yaw(base));
    assert!(base.translation.length() < 1e-4, "{base:?}");
    // The wheels turned opposite ways.
    let p = robot.proprioception(&world);
    let (r, l) = (
        p.joint(FetchJoint::RightWheel),
        p.joint(FetchJoint::LeftWheel),
    );
    assert!(r.position > 0.0 && l.position < 0.0, "{r:?} {l:?}");
    // Forward now goes along +y.
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::LINEAR, 0.5)]),
        30,
    );
    let base = robot.base_pose(&world).translation;
    assert!((base - v(0.0, 0.5, 0.0)).length() < 2e-3, "{base:?}");
}

#[test]
fn a_wall_stops_fetch_and_it_can_back_away() {
    let mut world = World::default();
    floor(&mut world);
    wall(&mut world, 1.0);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::LINEAR, 1.0)]),
        60,
    );
    let x = robot.base_pose(&world).translation.x;
    // The base (r 0.28) or the arm before it stops short of the wall at x = 1.
    assert!(x < 1.0 - 0.28 && x > 0.1, "stopped at {x}");
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::LINEAR, -1.0)]),
        10,
    );
    assert!(robot.base_pose(&world).translation.x < x - 0.3);
}

#[test]
fn the_head_pans_and_tilts_within_its_limits_and_sees_what_it_faces() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    let ahead = apple(&mut world, v(1.5, 0.0, 0.5));
    let left = apple(&mut world, v(0.0, 2.0, 0.5));
    world.settle(60);
    assert!(robot.in_field_of_view(&world, ahead));
    assert!(!robot.in_field_of_view(&world, left));
    // Pan left for one second: 1.57 rad, the limit.
    go(&mut world, &mut robot, act(&[(2, 1.0)]), 30);
    let head = robot.joints().head;
    assert!((head[0] - 1.57).abs() < 1e-5, "{head:?}");
    assert!(robot.in_field_of_view(&world, left));
    assert!(!robot.in_field_of_view(&world, ahead));
    // Tilting past its limit stops at it.
    go(&mut world, &mut robot, act(&[(3, 1.0)]), 60);
    assert!((robot.joints().head[1] - 1.45).abs() < 1e-5);
    let p = robot.proprioception(&world);
    assert_eq!(p.joint(FetchJoint::HeadTilt).position, 1.45);
}

/// Moves the end effector to `goal` (base frame) as a user with proprioception would: toward
/// where it is by at most a full step, until within `tolerance`; `gripper` held meanwhile.
fn eef_to(world: &mut World, robot: &mut Fetch, goal: Vector, gripper: f32, tolerance: f32) {
    for _ in 0..300 {
        let at = Vector::from(robot.proprioception(world).eef.position);
        let error = goal - at;
        if error.length() < tolerance {
            return;
        }
        let d = (error / EEF_STEP).clamp_length_max(1.0);
        let action = act(&[
            (4, d.x),
            (5, d.y),
            (6, d.z),
            (FetchAction::GRIPPER, gripper),
        ]);
        go(world, robot, action, 1);
    }
    let at = Vector::from(robot.proprioception(world).eef.position);
    panic!("the end effector did not reach {goal:?}: it is at {at:?}");
}

#[test]
fn the_gripper_grasps_an_apple_on_a_table_lifts_it_and_releases_it() {
    let mut world = World::default();
    floor(&mut world);
    // The table's near edge at x = 0.35, 7 cm before the base's front.
    table(&mut world, 0.95, 0.0);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    let fruit = apple(&mut world, v(0.55, -0.1, 0.791));
    world.settle(60);
    let at = world.bodies().pose(fruit).translation;
    assert!(robot.in_reach(&world, fruit) && robot.in_field_of_view(&world, fruit));

    // Above it, then around it, the gripper open.
    eef_to(&mut world, &mut robot, at + v(0.0, 0.0, 0.12), 1.0, 0.01);
    eef_to(&mut world, &mut robot, at, 1.0, 0.005);
    assert!(!robot.is_holding(fruit));
    // Close: the fingers meet the apple from both sides and the grasp takes it.
    for _ in 0..45 {
        if robot.is_holding(fruit) {
            break;
        }
        go(
            &mut world,
            &mut robot,
            act(&[(FetchAction::GRIPPER, -1.0)]),
            1,
        );
    }
    assert!(
        robot.is_holding(fruit),
        "fingers at {:?}",
        robot.fingers(&world)
    );
    let [r, l] = robot.fingers(&world);
    assert!(
        r > 0.02 && l > 0.02,
        "the fingers stopped on the apple: {r}, {l}"
    );
    assert_eq!(robot.proprioception(&world).to_array()[6], 1.0);

    // Lift it 20 cm, still closing (holding on).
    eef_to(&mut world, &mut robot, at + v(0.0, 0.0, 0.2), -1.0, 0.01);
    let lifted = world.bodies().pose(fruit).translation;
    assert!(lifted.z > at.z + 0.15, "{lifted:?}");
    assert!(robot.is_holding(fruit));

    // Open: it is let go and falls back to the table.
    go(
        &mut world,
        &mut robot,
        act(&[(FetchAction::GRIPPER, 1.0)]),
        1,
    );
    assert!(!robot.is_holding(fruit));
    go(&mut world, &mut robot, act(&[]), 45);
    let dropped = world.bodies().pose(fruit).translation;
    assert!(dropped.z < lifted.z - 0.1, "{dropped:?}");
}

#[test]
fn bad_actions_are_errors_that_change_nothing() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    world.settle(30);
    let (before, steps) = (world.bodies().motion_bits(), world.bodies().steps());
    let mut nan = [0.0; FETCH_ACTION_DIM];
    nan[5] = f32::NAN;
    let mut inf = [0.0; FETCH_ACTION_DIM];
    inf[0] = f32::INFINITY;
    for bad in [&nan[..], &inf[..], &[0.0; 10][..], &[0.0; 12][..], &[][..]] {
        assert!(robot.step(&mut world, bad).is_err(), "{bad:?}");
    }
    let mut any = Robot::add(
        RobotKind::Fetch,
        ActionSpace::Navigation,
        &mut world,
        Pose::from_translation(v(3.0, 0.0, 0.0)),
    )
    .unwrap();
    let bits = world.bodies().motion_bits();
    assert!(any.set_action(&[f32::NEG_INFINITY, 0.0]).is_err());
    assert!(any.set_action(&[0.0; 11]).is_err());
    world.step_with(&mut any);
    assert_eq!(world.bodies().motion_bits()[..before.len()], before[..]);
    assert_eq!(world.bodies().steps(), steps + 1);
    // The second robot stood still too (its pending action is still the zero one).
    assert_eq!(
        any.base_pose(&world).translation,
        v(3.0, 0.0, 0.0),
        "{bits:?}"
    );
}

#[test]
fn fetch_through_the_robot_enum() {
    assert_eq!(RobotKind::from_name("fetch"), Some(RobotKind::Fetch));
    assert!(RobotKind::ALL.contains(&RobotKind::Fetch));
    let mut world = World::default();
    floor(&mut world);
    let fruit = apple(&mut world, v(1.0, 0.3, 0.04));
    let far = apple(&mut world, v(-4.0, 0.0, 0.04));
    let pose = Robot::standing_pose(RobotKind::Fetch, v(0.0, 0.0, 0.0), 0.0);
    assert_eq!(pose.translation, Vector::ZERO);
    let mut robot = Robot::add(RobotKind::Fetch, ActionSpace::Full, &mut world, pose).unwrap();
    assert_eq!(robot.kind(), RobotKind::Fetch);
    assert_eq!(robot.action_dim(), 11);
    assert_eq!(robot.proprioception_dim(), FetchProprioception::DIM);
    assert_eq!(robot.proprioception_dim(), 49);
    assert_eq!(robot.hands(), 1);
    let names: Vec<&str> = robot.tracked_parts().iter().map(|p| p.name).collect();
    assert_eq!(names, ["body", "gripper"]);
    assert_eq!(robot.objects().len(), 11);
    let mut out = Vec::new();
    robot.proprioception_into(&world, &mut out);
    assert_eq!(out.len(), 49);
    assert!(robot.in_reach(&world, fruit) && !robot.in_reach(&world, far));
    assert!(robot.in_same_room(&world, fruit) && !robot.in_same_room(&world, far));
    assert!(!robot.in_field_of_view(&world, far));
    assert_eq!(robot.held(0), None);
    // Reduced spaces: navigation is the base's two values.
    for (space, dim) in [
        (ActionSpace::Navigation, 2),
        (ActionSpace::MobileManipulation, 9),
        (ActionSpace::TabletopManipulation, 7),
    ] {
        let p = Robot::standing_pose(RobotKind::Fetch, v(0.0, 3.0, 0.0), PI);
        let r = Robot::add(RobotKind::Fetch, space, &mut world, p).unwrap();
        assert_eq!(r.action_dim(), dim);
    }
    robot.set_action(&[0.0; 11]).unwrap();
    world.step_with(&mut robot);
    // A BehaviorRobot stands with its body's centre at its height.
    let b = Robot::standing_pose(RobotKind::Behavior, v(1.0, 2.0, 0.0), 0.0);
    assert_eq!(b.translation, v(1.0, 2.0, behavior_robots::BODY_HEIGHT));
    let turned = Robot::standing_pose(RobotKind::Fetch, Vector::ZERO, FRAC_PI_2);
    assert!(((turned.rotation * Vector::X) - Vector::Y).length() < 1e-6);
    let _ = Rotation::IDENTITY;
}

#[test]
fn proprioception_reports_the_start_pose_and_the_arm_loads() {
    let mut world = World::default();
    floor(&mut world);
    let robot = fetch_at(&mut world, 0.0, 0.0);
    world.settle(30);
    let p = robot.proprioception(&world);
    let eef = FetchJoints::default().eef();
    assert!((Vector::from(p.eef.position) - eef.translation).length() < 1e-6);
    assert_eq!(p.joint(FetchJoint::TorsoLift).position, 0.385);
    assert_eq!(p.joint(FetchJoint::HeadTilt).position, 0.45);
    let fingers = p.joint(FetchJoint::RightFinger).position;
    assert!((fingers - 0.05).abs() < 2e-3, "{fingers}");
    // The torso lifts everything above it: ≈ 33 kg × 9.81.
    let torso = p.joint(FetchJoint::TorsoLift).effort;
    assert!((torso - 28.0 * 9.81).abs() < 40.0, "{torso}");
    // The shoulder lift holds the arm out in front (positive lift pitches down, so it pulls up).
    let lift = p.joint(FetchJoint::ShoulderLift).effort;
    assert!(lift < -5.0, "{lift}");
    assert!(p.to_array().iter().all(|x| x.is_finite()));
}

#[test]
fn the_table_stops_the_gripper_pressed_down_into_it() {
    let mut world = World::default();
    floor(&mut world);
    table(&mut world, 0.95, 0.0);
    let mut robot = fetch_at(&mut world, 0.0, 0.0);
    // Straight down at full speed for three seconds: the eef starts 23 cm above the table top.
    go(&mut world, &mut robot, act(&[(6, -1.0)]), 90);
    let eef = robot.eef_pose(&world).translation;
    // The fingers' pads reach 3 cm beyond the eef along its x, which points down here.
    assert!(eef.z > 0.75 && eef.z < 0.85, "{eef:?}");
    let gripper = robot.parts().gripper();
    let table_top = 0.75;
    assert!(world.bodies().aabb(gripper).mins.z > table_top - 0.01);
}

#[test]
fn the_joint_space_moves_each_joint_at_its_commanded_rate_and_only_fetch_has_it() {
    let mut world = World::default();
    floor(&mut world);
    let pose = Robot::standing_pose(RobotKind::Fetch, Vector::ZERO, 0.0);
    let mut robot = Robot::add(RobotKind::Fetch, ActionSpace::Joints, &mut world, pose).unwrap();
    assert_eq!(robot.action_dim(), FETCH_JOINT_ACTION_DIM);
    let Robot::Fetch(fetch, _) = &robot else {
        panic!("a Fetch was added");
    };
    let before = fetch.joints();
    // Shoulder pan at half its maximum, the torso down at a quarter, the rest still.
    let mut values = [0.0; FETCH_JOINT_ACTION_DIM];
    values[FetchJointAction::TORSO] = -0.25;
    values[FetchJointAction::JOINTS.start + 1] = 0.5;
    values[FetchJointAction::GRIPPER] = 1.0;
    robot.set_action(&values).unwrap();
    world.step_with(&mut robot);
    let Robot::Fetch(fetch, _) = &robot else {
        panic!("a Fetch was added");
    };
    let after = fetch.joints();
    let dt = behavior_sim::STEP_SECONDS;
    let pan = FetchJoint::ShoulderPan.info().max_velocity;
    let lift = FetchJoint::TorsoLift.info().max_velocity;
    assert!((after.arm[0] - before.arm[0] - 0.5 * pan * dt).abs() < 1e-6);
    assert!((after.torso - before.torso + 0.25 * lift * dt).abs() < 1e-6);
    assert_eq!(after.arm[1..], before.arm[1..]);
    assert_eq!(after.head, before.head);
    // Asking for 0.01 rad at the elbow moves it by 0.01 rad.
    let mut values = [0.0; FETCH_JOINT_ACTION_DIM];
    values[FetchJointAction::JOINTS.start + 4] = FetchJointAction::value_for(4, 0.01);
    robot.set_action(&values).unwrap();
    world.step_with(&mut robot);
    let Robot::Fetch(fetch, _) = &robot else {
        panic!("a Fetch was added");
    };
    assert!((fetch.joints().arm[3] - after.arm[3] - 0.01).abs() < 1e-6);
    // Wrong lengths and NaN are refused.
    assert!(robot.set_action(&[0.0; FETCH_ACTION_DIM]).is_err());
    let mut nan = [0.0; FETCH_JOINT_ACTION_DIM];
    nan[7] = f32::NAN;
    assert!(matches!(
        robot.set_action(&nan),
        Err(behavior_robots::ActionError::NotFinite { index: 7, .. })
    ));
    // The BehaviorRobot has no arm joints.
    let b = Robot::standing_pose(RobotKind::Behavior, v(3.0, 0.0, 0.0), 0.0);
    let refused = Robot::add(RobotKind::Behavior, ActionSpace::Joints, &mut world, b);
    assert!(
        matches!(&refused, Err(behavior_robots::RobotError::Space(_))),
        "{refused:?}"
    );
    assert_eq!(ActionSpace::from_name("joints"), Some(ActionSpace::Joints));
}
