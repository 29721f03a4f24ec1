//! One small physical scene per kinematic predicate. Objects are dropped and left to settle, then
//! the predicate is read from geometry.

mod common;

use behavior_sim::{ObjectId, ObjectSpec, Part, World};
use common::*;

/// A table with a plate dropped on it and an apple dropped on the plate, settled.
fn apple_on_plate_on_table() -> (World, ObjectId, ObjectId, ObjectId) {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let plate = plate(&mut world, v(-1.0, 0.0, 0.80));
    let apple = apple(&mut world, "apple_1", v(-1.0, 0.0, 1.0));
    settle(&mut world, 2.0);
    (world, table, plate, apple)
}

#[test]
fn ontop_an_apple_dropped_on_a_plate_on_a_table() {
    let (world, table, plate, apple) = apple_on_plate_on_table();
    assert!(world.relations().ontop(apple, plate));
    assert!(
        !world.relations().ontop(apple, table),
        "the apple rests on the plate, not the table"
    );
    assert!(world.relations().ontop(plate, table));
    assert!(!world.relations().ontop(plate, apple) && !world.relations().ontop(table, plate));
    assert!(world.bodies().is_sleeping(apple), "a settled scene sleeps");
}

#[test]
fn touching_only_what_is_in_contact() {
    let (world, table, plate, apple) = apple_on_plate_on_table();
    assert!(world.relations().touching(apple, plate) && world.relations().touching(plate, apple));
    assert!(world.relations().touching(plate, table));
    assert!(!world.relations().touching(apple, table));
    assert!(!world.relations().touching(apple, apple));
}

#[test]
fn inside_an_apple_dropped_into_a_bin_and_not_one_beside_it() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let bin = open_box(&mut world, 1.0, 1.0);
    let inner = apple(&mut world, "apple_1", v(1.0, 1.0, 0.6));
    let outer = apple(&mut world, "apple_2", v(1.6, 1.0, 0.3));
    settle(&mut world, 2.0);
    assert!(world.relations().inside(inner, bin));
    assert!(!world.relations().inside(outer, bin));
    assert!(!world.relations().inside(bin, inner));
    assert!(
        world.relations().ontop(inner, bin),
        "it rests on the bin's bottom"
    );
}

#[test]
fn under_a_ball_below_a_table_top() {
    let mut world = World::default();
    let (kitchen_floor, _) = two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let below = apple(&mut world, "apple_1", v(-1.0, 0.1, 0.1));
    let beside = apple(&mut world, "apple_2", v(-3.0, 0.0, 0.1));
    settle(&mut world, 1.0);
    assert!(world.relations().under(below, table));
    assert!(!world.relations().under(beside, table));
    assert!(!world.relations().under(table, below));
    assert!(
        !world.relations().under(below, kitchen_floor),
        "the floor is below, not above"
    );
}

#[test]
fn nextto_two_apples_close_together_and_not_far_apart() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let a = apple(&mut world, "apple_1", v(-1.0, 2.0, 0.05));
    let b = apple(&mut world, "apple_2", v(-1.0, 2.1, 0.05));
    let far = apple(&mut world, "apple_3", v(-1.0, 3.5, 0.05));
    settle(&mut world, 1.0);
    assert!(world.relations().nextto(a, b) && world.relations().nextto(b, a));
    assert!(!world.relations().nextto(a, far));
}

#[test]
fn onfloor_in_the_room_where_the_object_lies() {
    let mut world = World::default();
    let (kitchen, living) = two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let dropped = apple(&mut world, "apple_1", v(-2.0, -2.0, 0.3));
    let on_table = apple(&mut world, "apple_2", v(-1.0, 0.0, 1.0));
    settle(&mut world, 2.0);
    assert!(world.relations().onfloor(dropped, kitchen));
    assert!(!world.relations().onfloor(dropped, living));
    assert!(
        !world.relations().onfloor(on_table, kitchen),
        "resting on the table, not the floor"
    );
    assert_eq!(
        world.relations().room_of(dropped),
        Some(behavior_core::RoomType::Kitchen)
    );
    assert_eq!(
        world.relations().room_of(table),
        Some(behavior_core::RoomType::Kitchen)
    );
}

#[test]
fn bad_object_specs_are_errors_not_panics() {
    use behavior_sim::{ObjectSpec, Part, Primitive};
    let mut world = World::default();
    let nan = ObjectSpec::new(
        "x",
        "apple.n.01",
        vec![Part::new(Primitive::Sphere { radius: f32::NAN })],
    );
    assert!(world.add(nan).is_err());
    assert!(
        world
            .add(ObjectSpec::new("y", "apple.n.01", vec![]))
            .is_err()
    );
    let far = ObjectSpec::new(
        "z",
        "apple.n.01",
        vec![Part::new(Primitive::Sphere { radius: 0.1 })],
    )
    .at(v(f32::INFINITY, 0.0, 0.0));
    assert!(world.add(far).is_err());
    assert_eq!(world.bodies().objects().len(), 0);
}

#[test]
fn ontop_memo_survives_sleep_and_is_invalidated_by_motion() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let apple = apple(&mut world, "apple_1", v(-1.0, 0.0, 0.9));
    settle(&mut world, 3.0);
    assert!(world.relations().ontop(apple, table));
    let count = world.bodies().motion(apple);
    settle(&mut world, 1.0);
    assert_eq!(
        world.bodies().motion(apple),
        count,
        "a sleeping apple does not count as moving"
    );
    assert!(world.relations().ontop(apple, table));
    world
        .bodies_mut()
        .set_pose(
            apple,
            rapier3d::math::Pose::from_translation(v(-3.0, 0.0, 0.04)),
        )
        .unwrap();
    assert!(
        !world.relations().ontop(apple, table),
        "a teleport invalidates the memo"
    );
    assert!(
        world
            .relations()
            .touching(apple, world.bodies().object_named("floor_kitchen").unwrap())
    );
}

#[test]
fn onfloor_includes_lying_on_a_mat_but_not_sitting_in_a_low_bin() {
    let mut world = World::default();
    let (kitchen, _) = two_room_floor(&mut world);
    let mat = world
        .add(
            behavior_sim::ObjectSpec::new(
                "mat_1",
                "rug.n.01",
                vec![behavior_sim::Part::new(cuboid(0.4, 0.3, 0.01))],
            )
            .at(v(-2.0, 2.0, 0.02)),
        )
        .unwrap();
    let on_mat = apple(&mut world, "apple_1", v(-2.0, 2.0, 0.2));
    let bin = open_box(&mut world, -1.0, -2.0);
    let in_bin = apple(&mut world, "apple_2", v(-1.0, -2.0, 0.3));
    settle(&mut world, 2.0);
    assert!(world.relations().ontop(on_mat, mat) && !world.relations().touching(on_mat, kitchen));
    assert!(
        world.relations().onfloor(on_mat, kitchen),
        "lying on a mat on the floor"
    );
    assert!(world.relations().inside(in_bin, bin));
    assert!(
        !world.relations().onfloor(in_bin, kitchen),
        "in a bin on the floor is not on the floor"
    );
}

#[test]
fn onfloor_not_for_an_apple_in_a_basket_standing_on_the_floor() {
    let mut world = World::default();
    let (kitchen, _) = two_room_floor(&mut world);
    // A light wicker basket, free to move: 30 cm wide, 15 cm tall, 1 cm walls.
    let (w, h, t) = (0.15, 0.075, 0.005);
    let parts = vec![
        Part::at(cuboid(w, w, t), v(0.0, 0.0, t)),
        Part::at(cuboid(t, w, h), v(-w + t, 0.0, h)),
        Part::at(cuboid(t, w, h), v(w - t, 0.0, h)),
        Part::at(cuboid(w, t, h), v(0.0, -w + t, h)),
        Part::at(cuboid(w, t, h), v(0.0, w - t, h)),
    ];
    let mut spec = ObjectSpec::new("basket_1", "basket.n.01", parts).at(v(-2.0, 1.0, 0.0));
    spec.density = 300.0;
    let basket = world.add(spec).unwrap();
    let in_basket = apple(&mut world, "apple_1", v(-2.0, 1.0, 0.1));
    // A towel lying on the floor, a bar of soap on it (washing_floor asks for both onfloor).
    let towel = world
        .add(
            ObjectSpec::new(
                "towel_1",
                "towel.n.01",
                vec![Part::new(cuboid(0.3, 0.2, 0.004))],
            )
            .at(v(-2.0, -1.0, 0.01)),
        )
        .unwrap();
    let soap = world
        .add(
            ObjectSpec::new(
                "soap_1",
                "soap.n.01",
                vec![Part::new(cuboid(0.04, 0.03, 0.015))],
            )
            .at(v(-2.0, -1.0, 0.05)),
        )
        .unwrap();
    settle(&mut world, 2.0);
    assert!(
        world.relations().onfloor(basket, kitchen),
        "the basket stands on the floor"
    );
    assert!(world.relations().inside(in_basket, basket));
    let bottom = world.bodies().aabb(in_basket).mins.z;
    assert!(
        bottom < 0.1,
        "the apple is low ({bottom} m) but in the basket"
    );
    assert!(
        !world.relations().onfloor(in_basket, kitchen),
        "in a basket is not on the floor"
    );
    assert!(world.relations().ontop(soap, towel) && !world.relations().touching(soap, kitchen));
    assert!(
        world.relations().onfloor(soap, kitchen),
        "on a towel lying on the floor"
    );
}

#[test]
fn ontop_not_for_an_apple_on_the_shelf_of_a_closed_fridge() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let fridge = fridge(&mut world, -2.0, 0.0);
    let shelved = apple(&mut world, "apple_1", v(-2.0, 0.0, 0.2));
    let on_top = apple(&mut world, "apple_2", v(-2.0, 0.0, 1.4));
    settle(&mut world, 2.0);
    assert!(!world.state(fridge, behavior_core::Predicate::Open));
    assert!(world.relations().inside(shelved, fridge));
    assert!(
        world.relations().touching(shelved, fridge),
        "it rests on the fridge's floor"
    );
    assert!(
        !world.relations().ontop(shelved, fridge),
        "inside the fridge, not on top of it: the fridge is above it"
    );
    assert!(world.relations().ontop(on_top, fridge) && !world.relations().inside(on_top, fridge));
}

#[test]
fn touching_a_pad_half_a_millimetre_above_a_slightly_turned_slab() {
    // Two flat boxes, one turned 0.05 rad about z, faces 0.5 mm apart: touching, however the
    // distance query would have it (parry's cuboid distance reported 7 mm here).
    use rapier3d::math::{Pose, Rotation};
    let mut world = World::default();
    let slab = ObjectSpec::new(
        "slab_1",
        "board.n.01",
        vec![Part::new(cuboid(0.15, 0.1, 0.02))],
    )
    .fixed();
    let mut slab = slab;
    slab.pose = Pose::from_parts(v(0.0, 0.0, 0.0), Rotation::from_rotation_z(0.05));
    let slab = world.add(slab).unwrap();
    let pad = world
        .add(
            ObjectSpec::new(
                "pad_1",
                "rag.n.01",
                vec![Part::new(cuboid(0.2, 0.12, 0.005))],
            )
            .at(v(-0.2, 0.0, 0.02 + 0.0005 + 0.005))
            .fixed(),
        )
        .unwrap();
    assert!(world.relations().touching(pad, slab) && world.relations().touching(slab, pad));
    // 6 mm apart is not touching.
    world
        .bodies_mut()
        .set_pose(
            pad,
            Pose::from_translation(v(-0.2, 0.0, 0.02 + 0.006 + 0.005)),
        )
        .unwrap();
    assert!(!world.relations().touching(pad, slab));
}
