//! The robot and the rest of the world: opening a lid by its edge, pressing a button, standing
//! under running water, falling asleep when idle.

mod common;

use behavior_core::{Ability, Predicate};
use behavior_robots::{Action, Embodiment, Side};
use behavior_sim::{
    AttachmentKind, BodyRef, JointKind, JointSpec, LinkSpec, ObjectId, ObjectSpec, Part, PointKind,
    World,
};
use common::*;

/// A chest 0.4 m deep, its top at 0.4 m, under a lid 2 cm thick hinged along its near edge
/// (x = 0.4) so that it opens by lifting its far edge (x = 0.8).
fn chest(world: &mut World) -> ObjectId {
    let lid = LinkSpec {
        name: "lid".into(),
        parts: vec![Part::at(cuboid(0.2, 0.25, 0.01), v(0.6, 0.0, 0.41))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.4, 0.0, 0.41),
            v(0.0, -1.0, 0.0),
            1.5,
            0.5,
        ),
        density: 400.0,
    };
    let body = Part::at(cuboid(0.2, 0.25, 0.2), v(0.6, 0.0, 0.2));
    let spec = ObjectSpec::new("chest", "chest.n.02", vec![body])
        .fixed()
        .ability(Ability::Openable, &[])
        .link(lid);
    world.add(spec).unwrap()
}

#[test]
fn a_hand_holds_a_lid_by_its_edge_on_a_point_and_opens_it() {
    let mut world = World::default();
    floor(&mut world);
    let chest = chest(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    // The palm on the lid (top at 0.42 m), the knuckles past its far edge.
    hand_to(&mut world, &mut robot, Side::Right, v(0.78, -0.12, -0.1));
    hand_to(&mut world, &mut robot, Side::Right, v(0.78, -0.12, -0.265));
    press(&mut world, &mut robot, Side::Right, 1.0, 14);
    assert_eq!(robot.holding(Side::Right), Some(BodyRef::link(chest, 0)));
    assert!(robot.is_holding(chest));
    // Up and back along the lid's arc (about its hinge, 0.38 m away): it opens.
    for _ in 0..4 {
        let up_and_back = [
            (Action::RIGHT_HAND.start, -0.6),
            (Action::RIGHT_HAND.start + 2, 1.0),
        ];
        step(&mut world, &mut robot, action(&up_and_back));
    }
    idle(&mut world, &mut robot, 10);
    let opened = world.joints().position(chest, 0);
    assert!(opened > 0.5, "the lid opened {opened} rad");
    assert!(world.state(chest, Predicate::Open));
    assert!(
        robot.is_holding(chest),
        "a point grasp lets the lid turn in the hand"
    );
    // Let go, and take the hand from under the lid sideways: it falls shut.
    press(&mut world, &mut robot, Side::Right, -1.0, 12);
    assert!(!robot.is_holding(chest));
    for _ in 0..10 {
        step(
            &mut world,
            &mut robot,
            action(&[(Action::RIGHT_HAND.start + 1, -1.0)]),
        );
    }
    idle(&mut world, &mut robot, 60);
    assert!(
        !world.state(chest, Predicate::Open),
        "{}",
        world.joints().position(chest, 0)
    );
}

#[test]
fn the_point_kind_is_for_hinged_parts_of_fixed_furniture() {
    let mut world = World::default();
    floor(&mut world);
    let chest = chest(&mut world);
    let apple = apple(&mut world, v(0.0, 2.0, 0.04));
    let robot = robot_at(&mut world, 0.0, 0.0);
    let rules = robot.rules();
    assert_eq!(
        rules.holdable(&world, BodyRef::link(chest, 0)),
        Some(AttachmentKind::Point)
    );
    assert_eq!(
        rules.holdable(&world, chest.into()),
        None,
        "not the chest itself"
    );
    assert_eq!(
        rules.holdable(&world, apple.into()),
        Some(AttachmentKind::Fixed)
    );
    let body = robot.parts().body;
    assert_eq!(rules.holdable(&world, body.into()), None, "not a robot");
}

#[test]
fn a_hand_held_at_a_button_for_five_steps_turns_the_lamp_on() {
    let mut world = World::default();
    floor(&mut world);
    table(&mut world, 1.0, 0.0);
    let lamp = ObjectSpec::new(
        "lamp",
        "lamp.n.02",
        vec![Part::at(cuboid(0.08, 0.08, 0.15), v(0.0, 0.0, 0.15))],
    )
    .at(v(0.75, -0.12, 0.751))
    .fixed()
    .ability(Ability::Toggleable, &[])
    .point(PointKind::ToggleButton, v(-0.08, 0.0, 0.05));
    let lamp = world.add(lamp).unwrap();
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    // The fingertips 3 cm short of the button at (0.67, -0.12, 0.80).
    hand_to(&mut world, &mut robot, Side::Right, v(0.4, -0.12, 0.11));
    assert!(
        !world.state(lamp, Predicate::ToggledOn),
        "not yet: the hand is 0.2 m away"
    );
    hand_to(&mut world, &mut robot, Side::Right, v(0.51, -0.12, 0.1));
    idle(&mut world, &mut robot, 5);
    assert!(world.state(lamp, Predicate::ToggledOn));
}

#[test]
fn water_runs_through_the_robot_and_does_not_stop_on_it() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    // A tap 0.3 m above the top of the body (a capsule of radius 0.25 up to 1.2 m).
    let top = v(0.0, 0.0, 1.2);
    let tap = ObjectSpec::new(
        "tap",
        "faucet.n.01",
        vec![Part::at(cuboid(0.03, 0.03, 0.03), top + v(0.0, 0.0, 0.35))],
    )
    .fixed()
    .ability(Ability::WaterSource, &[])
    .point(PointKind::WaterOutlet, top + v(0.0, 0.0, 0.3));
    world.add(tap).unwrap();
    idle(&mut world, &mut robot, 25);
    // Inside the body's capsule: only where water runs through it.
    let inside = |d: &&rapier3d::math::Vector| d.z < 1.0 && d.z > 0.3 && d.x.hypot(d.y) < 0.2;
    let through = world.drops().iter().filter(inside).count();
    assert!(
        through > 0,
        "drops run through the body: {:?}",
        world.drops()
    );
}

#[test]
fn an_idle_robot_falls_asleep_and_wakes_when_told_to_move() {
    let mut world = World::default();
    floor(&mut world);
    table(&mut world, 1.0, 0.0);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    hand_to(&mut world, &mut robot, Side::Left, v(0.3, 0.2, 0.3));
    press(&mut world, &mut robot, Side::Left, 1.0, 10);
    idle(&mut world, &mut robot, 40);
    let parts = robot.parts();
    for id in parts.all() {
        assert!(
            world.bodies().is_sleeping(id),
            "{} sleeps",
            world.bodies().object(id).name
        );
    }
    let hand = robot.hand_pose(&world, Side::Left);
    idle(&mut world, &mut robot, 30);
    assert_eq!(
        robot.hand_pose(&world, Side::Left),
        hand,
        "a parked hand stays put"
    );
    step(
        &mut world,
        &mut robot,
        action(&[(Action::LEFT_HAND.start + 2, 1.0)]),
    );
    assert!(!world.bodies().is_sleeping(parts.hand(Side::Left)));
    idle(&mut world, &mut robot, 5);
    let risen = robot.hand_pose(&world, Side::Left).translation.z - hand.translation.z;
    assert!((risen - 0.05).abs() < 1e-3, "the hand rose {risen} m");
}
