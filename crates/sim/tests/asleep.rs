//! Objects added asleep (`ObjectSpec::asleep`): a stack resting where it was put stays asleep and
//! exactly in place through its first steps, although rapier wakes every body whose contact
//! begins; and it wakes, moves and falls asleep again like any body once something hits it.

use behavior_sim::{BodyKind, ObjectId, ObjectSpec, Part, Primitive, Velocity, World};
use rapier3d::math::Vector;

/// A fixed slab whose top is at z = 0.05, and two 10 cm boxes stacked on it, added asleep.
fn stack() -> (World, [ObjectId; 2]) {
    let mut world = World::default();
    let slab = Primitive::Box {
        half_extents: Vector::new(2.0, 2.0, 0.05),
    };
    world
        .add(ObjectSpec::new("table", "table.n.02", vec![Part::new(slab)]).fixed())
        .unwrap();
    let cube = Primitive::Box {
        half_extents: Vector::splat(0.05),
    };
    let mut add = |name: &str, z: f32| {
        let spec = ObjectSpec::new(name, "box.n.01", vec![Part::new(cube.clone())]);
        world
            .add(spec.at(Vector::new(0.0, 0.0, z)).asleep())
            .unwrap()
    };
    let ids = [add("low", 0.1), add("high", 0.2)];
    (world, ids)
}

#[test]
fn objects_added_asleep_at_rest_stay_asleep_and_exactly_in_place() {
    let (mut world, ids) = stack();
    let before = world.bodies().motion_bits();
    assert!(ids.iter().all(|&id| world.bodies().is_sleeping(id)));
    for _ in 0..30 {
        world.step();
        assert!(ids.iter().all(|&id| world.bodies().is_sleeping(id)));
    }
    assert_eq!(world.bodies().motion_bits(), before, "nothing moved a bit");
    assert_eq!(world.bodies().motion(ids[0]), 0, "never marked as moved");
}

#[test]
fn an_object_added_asleep_wakes_when_hit_and_sleeps_again_once_at_rest() {
    let (mut world, [low, high]) = stack();
    world.step();
    let ball = ObjectSpec::new(
        "ball",
        "ball.n.01",
        vec![Part::new(Primitive::Sphere { radius: 0.03 })],
    );
    world
        .add(ball.at(Vector::new(0.03, 0.0, 0.5)).body(BodyKind::Dynamic))
        .unwrap();
    let mut woke = false;
    for _ in 0..60 {
        world.step();
        woke |= !world.bodies().is_sleeping(high);
    }
    assert!(woke, "the falling ball woke the box it landed on");
    assert!(world.bodies().is_sleeping(high), "and it slept again");
    // Pushed hard, the upper box slides off and falls to the table like any box.
    let push = Velocity {
        linear: Vector::new(2.0, 0.0, 0.0),
        angular: Vector::ZERO,
    };
    world.bodies_mut().set_velocity(high.into(), push).unwrap();
    for _ in 0..60 {
        world.step();
    }
    let z = world.bodies().pose(high).translation.z;
    assert!((z - 0.1).abs() < 0.01, "it fell one box lower, to {z}");
    assert!(world.bodies().pose(high).translation.x > 0.2);
    assert!(world.bodies().is_sleeping(low));
}
