//! Placement helpers: each relation holds where the object is put, and still holds once the
//! world has settled; impossible placements fail with a clear error and leave the object be.

mod common;

use behavior_core::Predicate;
use behavior_core::rng::seeded;
use behavior_sim::{PLACEMENT_ATTEMPTS, Relation, World};
use common::*;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

#[test]
fn ontop_inside_under_and_onfloor_placements_hold_after_settling() {
    let mut world = World::default();
    let (kitchen, living) = two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let bin = open_box(&mut world, 1.5, 1.5);
    let on = apple(&mut world, "apple_1", v(0.0, 4.0, 0.1));
    let inside = apple(&mut world, "apple_2", v(0.3, 4.0, 0.1));
    let under = apple(&mut world, "apple_3", v(0.6, 4.0, 0.1));
    let floor = apple(&mut world, "apple_4", v(0.9, 4.0, 0.1));
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    world.place(on, Relation::OnTop, table, &mut rng).unwrap();
    world
        .place(inside, Relation::Inside, bin, &mut rng)
        .unwrap();
    world
        .place(under, Relation::Under, table, &mut rng)
        .unwrap();
    world
        .place(floor, Relation::OnFloor, living, &mut rng)
        .unwrap();
    assert!(
        world.relations().ontop(on, table)
            && world.relations().inside(inside, bin)
            && world.relations().under(under, table)
    );
    assert!(world.relations().onfloor(floor, living) && !world.relations().onfloor(floor, kitchen));
    assert!(world.settle(300), "the world comes to rest");
    assert!(world.relations().ontop(on, table));
    assert!(world.relations().inside(inside, bin));
    assert!(world.relations().under(under, table));
    assert!(world.relations().onfloor(floor, living));
}

#[test]
fn placement_is_deterministic_per_seed_and_varies_across_seeds() {
    let place = |seed| {
        let mut world = World::default();
        two_room_floor(&mut world);
        let table = table(&mut world, -1.0, 0.0);
        let a = apple(&mut world, "apple_1", v(0.0, 4.0, 0.1));
        let pose = world
            .place(
                a,
                Relation::OnTop,
                table,
                &mut ChaCha8Rng::seed_from_u64(seed),
            )
            .unwrap();
        pose.translation.to_array().map(f32::to_bits)
    };
    assert_eq!(place(1), place(1));
    assert_ne!(place(1), place(2));
}

#[test]
fn an_impossible_placement_is_a_clear_error_and_the_object_stays() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let bin = open_box(&mut world, 1.5, 1.5);
    let table = table(&mut world, -1.0, 0.0);
    let before = world.bodies().pose(table);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    // A table cannot go inside a 0.5 m bin.
    let err = world
        .place(table, Relation::Inside, bin, &mut rng)
        .unwrap_err();
    let expected = format!("could not place table_1 inside bin_1 in {PLACEMENT_ATTEMPTS} attempts");
    assert!(err.to_string().starts_with(&expected), "{err}");
    assert_eq!(world.bodies().pose(table), before);
}

#[test]
fn a_joint_placement_satisfies_every_relation_or_fails_naming_them_all() {
    let mut world = World::default();
    let (kitchen, living) = two_room_floor(&mut world);
    // Rooms meet at x = 0 with no wall; this table (1.2 m long) stands in the kitchen and reaches
    // 0.35 m into the living room.
    let table = table(&mut world, -0.25, 0.0);
    let shoe = apple(&mut world, "apple_1", v(0.0, 4.0, 0.1));
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    world
        .place_jointly(
            shoe,
            &[(Relation::Under, table), (Relation::OnFloor, living)],
            &mut rng,
        )
        .unwrap();
    assert!(world.relations().under(shoe, table) && world.relations().onfloor(shoe, living));
    assert!(world.settle(300));
    assert!(world.relations().under(shoe, table) && world.relations().onfloor(shoe, living));
    assert!(!world.relations().onfloor(shoe, kitchen));

    // Under a table wholly in the kitchen and on the living room's floor cannot both hold.
    let far = common::table(&mut world, -2.0, 2.0);
    let before = world.bodies().pose(shoe);
    let err = world
        .place_jointly(
            shoe,
            &[(Relation::Under, far), (Relation::OnFloor, living)],
            &mut rng,
        )
        .unwrap_err();
    assert!(
        err.to_string()
            .starts_with("could not place apple_1 under table_1 and onfloor floor_living"),
        "{err}"
    );
    assert_eq!(world.bodies().pose(shoe), before);
}

#[test]
fn nextto_places_beside_the_target_on_the_same_surface() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, 1.0, 0.0);
    let a = apple(&mut world, "apple_1", v(0.0, 4.0, 0.1));
    let b = apple(&mut world, "apple_2", v(0.5, 4.0, 0.1));
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    world.place(a, Relation::OnTop, table, &mut rng).unwrap();
    world
        .place_jointly(
            b,
            &[(Relation::OnTop, table), (Relation::NextTo, a)],
            &mut rng,
        )
        .unwrap();
    assert!(world.relations().nextto(b, a) && world.relations().ontop(b, table));
    // Beside the table, on the floor.
    let c = apple(&mut world, "apple_3", v(1.0, 4.0, 0.1));
    world.place(c, Relation::NextTo, table, &mut rng).unwrap();
    assert!(world.relations().nextto(c, table) && !world.relations().ontop(c, table));
    assert!(world.settle(300));
    assert!(world.relations().nextto(b, a) && world.relations().nextto(c, table));
}

#[test]
fn a_sliced_apple_is_placed_inside_a_bin_as_one_piece() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let bin = open_box(&mut world, 1.0, 1.0);
    let apple = sliceable_apple(&mut world, "apple_1", v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    world.set_state(apple, Predicate::Sliced, true).unwrap();
    settle(&mut world, 1.0);
    let [a, b] = world.bodies().object(apple).replaced_by.unwrap();
    let apart = world.bodies().pose(a).translation - world.bodies().pose(b).translation;
    world
        .place(apple, Relation::Inside, bin, &mut seeded(3))
        .unwrap();
    assert!(
        world.relations().inside(a, bin) && world.relations().inside(b, bin),
        "both halves moved"
    );
    assert!(world.relations().inside(apple, bin));
    let moved = world.bodies().pose(a).translation - world.bodies().pose(b).translation;
    assert!(
        (moved.length() - apart.length()).abs() < 1e-4,
        "the halves keep their distance"
    );
    assert!(!world.relations().ontop(a, table) && !world.relations().ontop(b, table));
}

/// The heading of an object's x axis about the vertical, rad.
fn heading(world: &World, id: behavior_sim::ObjectId) -> f32 {
    let x = world.bodies().pose(id).rotation * rapier3d::math::Vector::X;
    x.y.atan2(x.x)
}

/// A box `length` m long, 0.4 m wide and 0.3 m high, parked off the floor.
fn long_box(world: &mut World, name: &str, length: f32) -> behavior_sim::ObjectId {
    let spec = behavior_sim::ObjectSpec::new(
        name,
        "carton.n.02",
        vec![behavior_sim::Part::new(cuboid(0.5 * length, 0.2, 0.15))],
    )
    .at(v(0.0, 0.0, 5.0));
    world.add(spec).unwrap()
}

#[test]
fn what_is_as_long_as_a_way_is_wide_is_set_on_a_floor_square_to_the_walls() {
    let quarter = std::f32::consts::FRAC_PI_2;
    let off_square = |a: f32| {
        let r = a.rem_euclid(quarter);
        r.min(quarter - r)
    };
    let mut turned = 0;
    for seed in 0..8 {
        let mut world = World::default();
        let (_, living) = two_room_floor(&mut world);
        let car = long_box(&mut world, "car_1", 1.8);
        let shoe = long_box(&mut world, "shoe_1", 0.6);
        let mut rng = seeded(seed);
        let on = [(Relation::OnFloor, living)];
        world.place_turning(car, &on, &mut rng).unwrap();
        world.place_turning(shoe, &on, &mut rng).unwrap();
        assert!(
            off_square(heading(&world, car)) < 1e-3,
            "seed {seed}: the long box heads {} rad",
            heading(&world, car)
        );
        if off_square(heading(&world, shoe)) > 0.05 {
            turned += 1;
        }
    }
    // What is shorter than a way is wide still turns at random.
    assert!(
        turned >= 4,
        "the short box stood square in {} of 8 homes",
        8 - turned
    );
}
