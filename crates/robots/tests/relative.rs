//! Robot-relative predicates: in reach, in the same room, in the field of view.

mod common;

use behavior_robots::{Action, Embodiment, REACH_DISTANCE};
use behavior_sim::World;
use common::*;

#[test]
fn objects_within_two_metres_of_the_body_are_in_reach() {
    let mut world = World::default();
    floor(&mut world);
    let robot = robot_at(&mut world, 0.0, 0.0);
    // Apples resting on the floor: their centres are 0.66 m below the body's origin.
    let drop = 0.7f32 - 0.04;
    let horizontal = |d: f32| (d * d - drop * drop).sqrt();
    let near = apple(&mut world, v(horizontal(REACH_DISTANCE - 0.05), 0.0, 0.04));
    let far = apple(&mut world, v(0.0, -horizontal(REACH_DISTANCE + 0.05), 0.04));
    assert!(robot.in_reach(&world, near));
    assert!(!robot.in_reach(&world, far));
}

#[test]
fn the_same_room_is_where_the_body_stands() {
    let mut world = World::default();
    floor(&mut world); // kitchen for x < 0, living room for x ≥ 0
    let mut robot = robot_at(&mut world, 0.5, 0.0);
    let living = apple(&mut world, v(3.0, 1.0, 0.04));
    let kitchen = apple(&mut world, v(-0.3, 0.0, 0.04));
    assert!(robot.in_same_room(&world, living));
    assert!(
        !robot.in_same_room(&world, kitchen),
        "0.8 m away, but in the kitchen"
    );
    // Backing 1 m into the kitchen.
    for _ in 0..20 {
        step(&mut world, &mut robot, action(&[(0, -1.0)]));
    }
    assert!(robot.in_same_room(&world, kitchen));
    assert!(!robot.in_same_room(&world, living));
}

#[test]
fn the_field_of_view_holds_what_is_ahead_and_unhidden() {
    let mut world = World::default();
    floor(&mut world);
    let mut robot = robot_at(&mut world, 0.0, 0.0);
    // The eye is at (0.05, 0, 1.1), looking along +x; 120° wide and high.
    let ahead = apple(&mut world, v(2.0, 0.5, 0.04));
    let behind = apple(&mut world, v(-2.0, 0.0, 0.04));
    let wide = apple(&mut world, v(1.0, 2.0, 0.04)); // 63° to the left
    let hidden = apple(&mut world, v(4.0, 0.0, 0.04));
    wall(&mut world, 3.0);
    assert!(robot.in_field_of_view(&world, ahead));
    assert!(!robot.in_field_of_view(&world, behind));
    assert!(!robot.in_field_of_view(&world, wide));
    assert!(!robot.in_field_of_view(&world, hidden), "behind the wall");
    // Turning the body left by 0.5 rad brings the wide one in.
    for _ in 0..10 {
        step(&mut world, &mut robot, action(&[(5, 1.0)]));
    }
    assert!(robot.in_field_of_view(&world, wide));
    // Looking 1.5 rad up (pitch about y, negative lifts the view): the floor leaves the view.
    let eye = Action::EYE.start + 4;
    for _ in 0..30 {
        step(&mut world, &mut robot, action(&[(eye, -1.0)]));
    }
    assert!(!robot.in_field_of_view(&world, wide));
    let up = robot.eye_pose(&world).rotation * v(1.0, 0.0, 0.0);
    assert!(up.z > 0.99, "the eye looks up: {up}");
}
