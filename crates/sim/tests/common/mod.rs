//! Small real scenes for the physics tests: a floor, a table, a plate, an apple, an open box.

#![allow(dead_code)]

use behavior_sim::{ObjectId, ObjectSpec, Part, Primitive, Room, World};
use rapier3d::math::Vector;

pub fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

pub fn cuboid(hx: f32, hy: f32, hz: f32) -> Primitive {
    Primitive::Box {
        half_extents: v(hx, hy, hz),
    }
}

/// A 10 m × 10 m floor slab whose top is at z = 0, standing for the floor of a kitchen that
/// covers x < 0 and a living room that covers x ≥ 0 (two floor objects).
pub fn two_room_floor(world: &mut World) -> (ObjectId, ObjectId) {
    let kitchen = world
        .add(
            ObjectSpec::new(
                "floor_kitchen",
                "floor.n.01",
                vec![Part::new(cuboid(2.5, 5.0, 0.05))],
            )
            .at(v(-2.5, 0.0, -0.05))
            .fixed(),
        )
        .unwrap();
    let living = world
        .add(
            ObjectSpec::new(
                "floor_living",
                "floor.n.01",
                vec![Part::new(cuboid(2.5, 5.0, 0.05))],
            )
            .at(v(2.5, 0.0, -0.05))
            .fixed(),
        )
        .unwrap();
    world.add_room(Room {
        kind: "kitchen".into(),
        instance: 0,
        min: [-5.0, -5.0],
        max: [0.0, 5.0],
        floor: Some(kitchen),
    });
    world.add_room(Room {
        kind: "living_room".into(),
        instance: 0,
        min: [0.0, -5.0],
        max: [5.0, 5.0],
        floor: Some(living),
    });
    (kitchen, living)
}

/// A table 0.75 m high: a 1.2 × 0.8 m top on four legs, centred at (x, y) on the floor.
pub fn table(world: &mut World, x: f32, y: f32) -> ObjectId {
    let mut parts = vec![Part::at(cuboid(0.6, 0.4, 0.025), v(0.0, 0.0, 0.725))];
    for (lx, ly) in [(-0.55, -0.35), (0.55, -0.35), (-0.55, 0.35), (0.55, 0.35)] {
        parts.push(Part::at(cuboid(0.025, 0.025, 0.35), v(lx, ly, 0.35)));
    }
    world
        .add(
            ObjectSpec::new("table_1", "table.n.02", parts)
                .at(v(x, y, 0.0))
                .fixed(),
        )
        .unwrap()
}

pub fn plate(world: &mut World, at: Vector) -> ObjectId {
    let disc = Primitive::Cylinder {
        radius: 0.12,
        half_height: 0.01,
    };
    let mut spec = ObjectSpec::new("plate_1", "plate.n.04", vec![Part::new(disc)]).at(at);
    spec.density = 2000.0;
    world.add(spec).unwrap()
}

pub fn apple(world: &mut World, name: &str, at: Vector) -> ObjectId {
    let mut spec = ObjectSpec::new(
        name,
        "apple.n.01",
        vec![Part::new(Primitive::Sphere { radius: 0.04 })],
    )
    .at(at);
    spec.density = 800.0;
    world.add(spec).unwrap()
}

pub fn sliceable_apple(world: &mut World, name: &str, at: Vector) -> ObjectId {
    use behavior_bddl::taxonomy::{Ability, ParamValue};
    let mut spec = ObjectSpec::new(
        name,
        "apple.n.01",
        vec![Part::new(Primitive::Sphere { radius: 0.04 })],
    )
    .at(at)
    .ability(Ability::Sliceable, &[])
    .ability(
        Ability::Cookable,
        &[("cook_temperature", ParamValue::Number(70.0))],
    )
    .ability(
        Ability::Burnable,
        &[("burn_temperature", ParamValue::Number(200.0))],
    )
    .ability(Ability::Freezable, &[]);
    spec.density = 800.0;
    world.add(spec).unwrap()
}

/// An open-top box (a bin): 0.5 m wide, 0.4 m tall, 2 cm walls, standing on the floor at (x, y).
pub fn open_box(world: &mut World, x: f32, y: f32) -> ObjectId {
    let (h, t) = (0.2, 0.01);
    let parts = vec![
        Part::at(cuboid(0.25, 0.25, t), v(0.0, 0.0, t)),
        Part::at(cuboid(t, 0.25, h), v(-0.25 + t, 0.0, h)),
        Part::at(cuboid(t, 0.25, h), v(0.25 - t, 0.0, h)),
        Part::at(cuboid(0.25, t, h), v(0.0, -0.25 + t, h)),
        Part::at(cuboid(0.25, t, h), v(0.0, 0.25 - t, h)),
    ];
    world
        .add(
            ObjectSpec::new("bin_1", "bin.n.01", parts)
                .at(v(x, y, 0.0))
                .fixed(),
        )
        .unwrap()
}

pub fn settle(world: &mut World, seconds: f32) {
    for _ in 0..(seconds * 30.0) as usize {
        world.step();
    }
}
