//! The BehaviorRobot in small real scenes: driving, reaching, closing the fingers, grasping,
//! lifting and letting go, bad actions, and walls.

mod common;

use behavior_robots::{
    Action, ActionError, BehaviorRobot, Embodiment, FINGER_CLOSED, HAND_REACH, Proprioception,
    RobotError, Side, THUMB_CLOSED,
};
use behavior_sim::{ObjectId, Substeps, World};
use common::*;
use rapier3d::math::{Pose, Vector};

#[test]
fn the_robot_drives_one_metre_and_its_body_moves_one_metre() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    let start = robot.body_pose(&world);
    let hand_start = robot.hand_pose(&world, Side::Right).translation;
    for _ in 0..20 {
        step(&mut world, &mut robot, action(&[(0, 1.0)]));
    }
    let moved = robot.body_pose(&world).translation - start.translation;
    assert!(
        (moved - v(1.0, 0.0, 0.0)).length() < 1e-5,
        "the body moved {moved}"
    );
    idle(&mut world, &mut robot, 10);
    let hand_moved = robot.hand_pose(&world, Side::Right).translation - hand_start;
    assert!(
        (hand_moved - v(1.0, 0.0, 0.0)).length() < 1e-4,
        "the hand came along: {hand_moved}"
    );
    // Turning by 0.05 rad a step for 10 steps, then forward: it goes along its new heading.
    for _ in 0..10 {
        step(&mut world, &mut robot, action(&[(5, 1.0)]));
    }
    let (axis, angle) = robot.body_pose(&world).rotation.to_axis_angle();
    assert!(
        (angle - 0.5).abs() < 1e-4 && axis.z > 0.999,
        "turned {angle} about {axis}"
    );
    let before = robot.body_pose(&world).translation;
    for _ in 0..20 {
        step(&mut world, &mut robot, action(&[(0, 1.0)]));
    }
    let heading = robot.body_pose(&world).translation - before;
    let expected = v(0.5f32.cos(), 0.5f32.sin(), 0.0);
    assert!((heading - expected).length() < 1e-4, "went {heading}");
}

#[test]
fn a_turned_robot_comes_to_rest_and_sleeps() {
    let mut world = World::default();
    floor(&mut world);
    let at = Pose::from_parts(
        v(1.3, 2.7, behavior_robots::BODY_HEIGHT),
        rapier3d::math::Rotation::from_rotation_z(0.7),
    );
    let mut robot = BehaviorRobot::add(&mut world, at).unwrap();
    for _ in 0..5 {
        step(&mut world, &mut robot, action(&[(0, 1.0), (5, 1.0)]));
    }
    // Every part falls asleep, so an idle robot costs an idle world nothing.
    idle(&mut world, &mut robot, 90);
    for id in robot.parts().all() {
        assert!(
            world.bodies().is_sleeping(id),
            "{} is awake",
            world.bodies().object(id).name
        );
    }
}

#[test]
fn a_wall_stops_the_body_and_a_table_stops_the_hand() {
    let mut world = World::default();
    floor(&mut world);
    wall(&mut world, 1.0);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    for _ in 0..40 {
        step(&mut world, &mut robot, action(&[(0, 1.0)]));
    }
    let x = robot.body_pose(&world).translation.x;
    assert!(
        x > 0.6 && x <= 0.75,
        "the body stopped before the wall, at x = {x}"
    );
    // It can still back away and turn.
    step(&mut world, &mut robot, action(&[(0, -1.0)]));
    assert!(robot.body_pose(&world).translation.x < x);

    let mut world = World::default();
    floor(&mut world);
    table(&mut world, 1.0, 0.0);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    // Reach forward over the table, then push down into it.
    hand_to(&mut world, &mut robot, Side::Right, v(0.6, -0.12, 0.2));
    for _ in 0..20 {
        step(
            &mut world,
            &mut robot,
            action(&[(Action::RIGHT_HAND.start + 2, -1.0)]),
        );
    }
    idle(&mut world, &mut robot, 10);
    let palm = robot.hand_pose(&world, Side::Right).translation;
    assert!(
        palm.z > 0.75,
        "the palm stopped on the table top (0.75 m): z = {}",
        palm.z
    );
}

#[test]
fn a_hand_stays_within_reach_of_its_shoulder() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    for _ in 0..60 {
        step(
            &mut world,
            &mut robot,
            action(&[
                (Action::LEFT_HAND.start, 1.0),
                (Action::LEFT_HAND.start + 1, 1.0),
            ]),
        );
    }
    idle(&mut world, &mut robot, 30);
    let hand = Vector::from(robot.proprioception(&world).hands[0].position);
    let shoulder = v(-0.15, 0.15, 0.3);
    let reach = (hand - shoulder).length();
    assert!(
        (reach - HAND_REACH).abs() < 1e-3,
        "the hand is {reach} m from its shoulder"
    );
}

/// The hand's finger shapes (parts 1–5 of its body) as they are in the world now.
fn finger_shapes(world: &World, hand: ObjectId) -> Vec<Pose> {
    world.bodies().object(hand).parts[1..]
        .iter()
        .map(|p| p.offset)
        .collect()
}

/// How far each finger has turned from `rest`, rad, read from the hand's shapes in the world.
fn finger_turns(world: &World, hand: ObjectId, rest: &[Pose]) -> Vec<f32> {
    let now = finger_shapes(world, hand);
    let turn = |(a, b): (&Pose, &Pose)| (a.rotation * b.rotation.inverse()).to_scaled_axis();
    now.iter().zip(rest).map(|p| turn(p).length()).collect()
}

#[test]
fn triggers_close_the_fingers() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    let hand = robot.parts().hand(Side::Left);
    let right = robot.parts().hand(Side::Right);
    let (rest, right_rest) = (finger_shapes(&world, hand), finger_shapes(&world, right));
    assert_eq!(rest.len(), 5);
    press(&mut world, &mut robot, Side::Left, 1.0, 25);
    idle(&mut world, &mut robot, 15);
    assert_eq!(robot.trigger(Side::Left), 1.0);
    assert_eq!(robot.trigger(Side::Right), 0.0);
    for (finger, q) in finger_turns(&world, hand, &rest).into_iter().enumerate() {
        let closed = if finger == 4 {
            THUMB_CLOSED
        } else {
            FINGER_CLOSED
        };
        assert!(
            (q - closed).abs() < 1e-4,
            "finger {finger} at {q} rad, closed is {closed}"
        );
    }
    assert!(
        finger_turns(&world, right, &right_rest)
            .iter()
            .all(|&q| q == 0.0)
    );
    // The closed fingers curl under the palm: their shapes' centres are below its middle plane.
    assert!(
        finger_shapes(&world, hand)
            .iter()
            .all(|p| p.translation.z < -0.01)
    );
    // Half open again.
    press(&mut world, &mut robot, Side::Left, -1.0, 10);
    idle(&mut world, &mut robot, 15);
    let q = finger_turns(&world, hand, &rest)[1];
    assert!((q - 0.5 * FINGER_CLOSED).abs() < 1e-4, "{q}");
}

/// A table with an apple on it, and a robot whose right hand has just closed on the apple.
fn holding_an_apple(substeps: Substeps) -> (World, BehaviorRobot, ObjectId, ObjectId) {
    let mut world = World::new(substeps);
    floor(&mut world);
    let table = table(&mut world, 1.0, 0.0);
    let apple = apple(&mut world, v(0.7, -0.12, 0.791));
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    for _ in 0..30 {
        world.step();
    }
    assert!(world.relations().ontop(apple, table));
    // Over the apple, then down until the palm rests on it (apple top 0.83 m; palm 1.5 cm thick).
    hand_to(&mut world, &mut robot, Side::Right, v(0.66, -0.12, 0.2));
    hand_to(&mut world, &mut robot, Side::Right, v(0.66, -0.12, 0.1455));
    assert!(!robot.is_holding(apple));
    press(&mut world, &mut robot, Side::Right, 1.0, 14);
    (world, robot, apple, table)
}

#[test]
fn a_hand_grasps_an_apple_on_a_table_lifts_it_and_lets_it_fall() {
    for substeps in [Substeps::Hz300, Substeps::Hz120] {
        grasp_lift_and_drop(substeps);
    }
}

fn grasp_lift_and_drop(substeps: Substeps) {
    let (mut world, mut robot, apple, table) = holding_an_apple(substeps);
    assert!(
        robot.is_holding(apple),
        "the hand closed on the apple and holds it"
    );
    assert_eq!(robot.holding(Side::Right), Some(apple.into()));
    assert!(robot.proprioception(&world).grasping[1]);

    let z0 = world.bodies().pose(apple).translation.z;
    hand_to(&mut world, &mut robot, Side::Right, v(0.66, -0.12, 0.45));
    let lifted = world.bodies().pose(apple).translation.z - z0;
    assert!(
        (lifted - 0.3).abs() < 0.02,
        "the apple rose {lifted} m with the hand"
    );
    assert!(!world.relations().ontop(apple, table));
    assert!(robot.is_holding(apple));

    // Let go: the trigger falls to 0.4, at or below the 0.5 threshold.
    press(&mut world, &mut robot, Side::Right, -1.0, 6);
    assert!(!robot.is_holding(apple));
    assert!(!robot.proprioception(&world).grasping[1]);
    idle(&mut world, &mut robot, 40);
    let z = world.bodies().pose(apple).translation.z;
    assert!(
        (z - z0).abs() < 0.01,
        "the apple fell back onto the table: z = {z}"
    );
    assert!(world.relations().ontop(apple, table));
}

#[test]
fn a_grasp_ends_when_its_attachment_breaks_or_what_it_holds_is_taken_away() {
    // Pulled down with 1,000 N for a step: more than the grasp's 500 N.
    let (mut world, mut robot, apple, table) = holding_an_apple(Substeps::default());
    assert!(robot.is_holding(apple));
    world
        .bodies_mut()
        .apply_force(apple.into(), v(0.0, 0.0, -1000.0))
        .unwrap();
    step(&mut world, &mut robot, Action::ZERO);
    assert!(
        !robot.is_holding(apple),
        "the grasp broke and the hand let go"
    );
    assert!(
        robot.trigger(Side::Right) > 0.5,
        "though the trigger is still pressed"
    );
    idle(&mut world, &mut robot, 30);
    assert!(world.relations().ontop(apple, table));
    assert!(
        !robot.is_holding(apple),
        "nor does it grasp again while touching it"
    );

    // Taken away (teleported 0.5 m): its anchor drifted past 0.1 m.
    let (mut world, mut robot, apple, _) = holding_an_apple(Substeps::default());
    let away = Pose::from_translation(world.bodies().pose(apple).translation + v(0.0, 0.5, 0.0));
    world.bodies_mut().set_pose(apple, away).unwrap();
    step(&mut world, &mut robot, Action::ZERO);
    assert!(!robot.is_holding(apple));
}

#[test]
fn a_heavy_box_is_not_grasped_unless_its_category_is_allowed() {
    let grasped = |allow: bool| {
        let mut world = World::default();
        floor(&mut world);
        let heavy = crate_of(&mut world, "heavy", v(0.55, -0.12, 0.0), 0.12, 30.0);
        let mut rules = behavior_robots::GraspRules::default();
        if allow {
            rules.allowed.insert("carton.n.02".into());
        }
        let start = Pose::from_translation(v(0.0, 0.0, behavior_robots::BODY_HEIGHT));
        let mut robot = BehaviorRobot::add_with(&mut world, start, rules).unwrap();
        // The box's top is at 0.241 m and its far side at x = 0.67: the palm goes on its top,
        // the knuckles just past that side, so the fingers close over its edge.
        hand_to(&mut world, &mut robot, Side::Right, v(0.63, -0.12, 0.0));
        hand_to(&mut world, &mut robot, Side::Right, v(0.63, -0.12, -0.444));
        press(&mut world, &mut robot, Side::Right, 1.0, 14);
        robot.is_holding(heavy)
    };
    assert!(!grasped(false), "a 30 kg box is too heavy to hold");
    assert!(
        grasped(true),
        "an allow-listed category is held whatever its mass"
    );
}

#[test]
fn bad_actions_are_refused_and_leave_the_world_untouched() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    for _ in 0..5 {
        step(
            &mut world,
            &mut robot,
            action(&[(0, 0.5), (Action::LEFT_TRIGGER, 1.0)]),
        );
    }
    let bits = world.bodies().motion_bits();
    let steps = world.bodies().steps();
    let felt: Proprioception = robot.proprioception(&world);
    let mut nan = [0.0; 26];
    nan[7] = f32::NAN;
    let mut inf = [0.0; 26];
    inf[25] = f32::NEG_INFINITY;
    assert!(matches!(
        robot.step(&mut world, &nan),
        Err(ActionError::NotFinite { index: 7, .. })
    ));
    assert!(matches!(
        robot.step(&mut world, &inf),
        Err(ActionError::NotFinite { index: 25, .. })
    ));
    assert_eq!(
        robot.step(&mut world, &[0.0; 25]),
        Err(ActionError::WrongLength {
            expected: 26,
            got: 25
        })
    );
    assert_eq!(
        robot.step(&mut world, &[]).unwrap_err().to_string(),
        "an action of this space has 26 values, got 0"
    );
    assert_eq!(world.bodies().steps(), steps, "no step was taken");
    assert_eq!(world.bodies().motion_bits(), bits, "nothing moved");
    assert_eq!(robot.proprioception(&world), felt);
}

#[test]
fn a_bad_starting_pose_is_refused_and_adds_nothing() {
    let mut world = World::default();
    floor(&mut world);
    let bad = Pose::from_translation(v(f32::NAN, 0.0, 0.0));
    assert_eq!(
        BehaviorRobot::add(&mut world, bad).unwrap_err(),
        RobotError::BadPose
    );
    let skewed = Pose::from_parts(
        v(0.0, 0.0, 0.7),
        rapier3d::math::Rotation::from_xyzw(0.0, 0.0, 0.0, 2.0),
    );
    assert_eq!(
        BehaviorRobot::add(&mut world, skewed).unwrap_err(),
        RobotError::BadPose
    );
    assert_eq!(world.bodies().objects().len(), 1, "no part of it was added");
}

#[test]
fn proprioception_reports_where_the_parts_are_in_the_body_frame() {
    let mut world = World::default();
    floor(&mut world);
    // A robot turned to face +y: the body frame is not the world's.
    let turned = Pose::from_parts(
        v(2.0, 1.0, behavior_robots::BODY_HEIGHT),
        rapier3d::math::Rotation::from_rotation_z(std::f32::consts::FRAC_PI_2),
    );
    let mut robot = BehaviorRobot::add(&mut world, turned).unwrap();
    let start = robot.proprioception(&world).to_array();
    assert_eq!(start.len(), Proprioception::DIM);
    assert!(
        (start[0] - 0.1).abs() < 1e-5 && (start[1] - 0.12).abs() < 1e-5,
        "{start:?}"
    );
    assert!(
        (start[12] - 0.05).abs() < 1e-6 && (start[14] - 0.4).abs() < 1e-6,
        "the eye's own pose: {start:?}"
    );
    // Raise the right hand 0.2 m, turn the eye down 0.2 rad (pitch), press the left trigger.
    for _ in 0..4 {
        let entries = [
            (Action::RIGHT_HAND.start + 2, 1.0),
            (Action::EYE.start + 4, 1.0),
            (Action::LEFT_TRIGGER, 1.0),
        ];
        step(&mut world, &mut robot, action(&entries));
    }
    idle(&mut world, &mut robot, 20);
    let now = robot.proprioception(&world).to_array();
    assert!(
        (now[8] - (0.05 + 0.2)).abs() < 1e-4,
        "right hand z {}",
        now[8]
    );
    assert!((now[6] - 0.1).abs() < 1e-4 && (now[7] + 0.12).abs() < 1e-4);
    assert!((now[16] - 0.2).abs() < 1e-4, "eye pitch {}", now[16]);
    assert_eq!((now[18], now[19]), (0.2, 0.0));
    assert_eq!((now[20], now[21]), (0.0, 0.0));
    // In the world, "up in the body frame" is up, and the hand stands where the body's +x (world +y) says.
    let hand = robot.hand_pose(&world, Side::Right).translation;
    assert!((hand - v(2.0 + 0.12, 1.1, 0.95)).length() < 1e-4, "{hand}");
}

#[test]
fn what_a_hand_holds_passes_through_the_other_hand_until_let_go_and_clear() {
    let (mut world, mut robot, apple, _) = holding_an_apple(Substeps::default());
    assert!(robot.is_holding(apple));
    let ignored = |world: &World, robot: &BehaviorRobot, side: Side| {
        let part = robot.parts().hand(side);
        world.contacts().ignored(part.into(), apple.into())
    };
    // The whole robot lets it through while held: the hand, the body and the other hand.
    assert!(ignored(&world, &robot, Side::Right));
    assert!(ignored(&world, &robot, Side::Left));
    let body = robot.parts().body;
    assert!(world.contacts().ignored(body.into(), apple.into()));
    // Let go, it falls onto the table clear of every part: contacts are back with each.
    press(&mut world, &mut robot, Side::Right, -1.0, 6);
    assert!(!robot.is_holding(apple));
    hand_to(&mut world, &mut robot, Side::Right, v(0.66, -0.12, 0.45));
    idle(&mut world, &mut robot, 20);
    assert!(!ignored(&world, &robot, Side::Right));
    assert!(!ignored(&world, &robot, Side::Left));
    assert!(!world.contacts().ignored(body.into(), apple.into()));
}

#[test]
fn the_head_is_drawn_round_the_eye_and_follows_it_without_entering_the_physics() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot =
        BehaviorRobot::add(&mut world, Pose::from_translation(v(0.0, 0.0, 0.7))).unwrap();
    // The floor, the body and two hands: the head is no object of its own.
    assert_eq!(world.bodies().objects().len(), 4);
    let head = |world: &World, robot: &BehaviorRobot| {
        let parts = world.visuals().parts(robot.parts().body);
        let last = parts.last().copied().expect("the body is drawn");
        match last.shape {
            behavior_sim::VisualShape::Formed { form, half_extents } => {
                assert_eq!(form, behavior_sim::Form::Head, "the body's last drawn part");
                (last.pose, half_extents)
            }
            other => panic!("the body's last drawn part is {other:?}, not its head"),
        }
    };
    let inside = |world: &World, robot: &BehaviorRobot| {
        let (pose, half) = head(world, robot);
        let eye = pose.inverse() * robot.eye_pose(world).translation;
        eye.abs().cmplt(half).all()
    };
    assert!(inside(&world, &robot), "the eye starts inside its head");
    let before = head(&world, &robot).0;
    // Turn the eye down and move it forward: the head goes with it.
    for _ in 0..4 {
        let entries = [(Action::EYE.start, 1.0), (Action::EYE.start + 4, 1.0)];
        step(&mut world, &mut robot, action(&entries));
    }
    let after = head(&world, &robot).0;
    assert!(
        (after.translation - before.translation).length() > 0.1,
        "the head moved from {} to {}",
        before.translation,
        after.translation
    );
    assert!(inside(&world, &robot), "the eye is still inside its head");
    assert_eq!(
        world.bodies().objects().len(),
        4,
        "the head added no object to the world"
    );
}
