//! Small real scenes for the physics tests: a floor, a table, a plate, an apple, an open box.

#![allow(dead_code)]

use behavior_core::RoomType;
use behavior_sim::{
    JointKind, JointModel, JointSpec, LinkSpec, ObjectId, ObjectSpec, Part, Primitive, Room, World,
};
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
        kind: RoomType::Kitchen,
        instance: 0,
        min: [-5.0, -5.0],
        max: [0.0, 5.0],
        annexes: Vec::new(),
        floor: Some(kitchen),
    });
    world.add_room(Room {
        kind: RoomType::LivingRoom,
        instance: 0,
        min: [0.0, -5.0],
        max: [5.0, 5.0],
        annexes: Vec::new(),
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
    use behavior_core::{Ability, ParamValue};
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

use behavior_core::{Ability, ParamValue};
use behavior_sim::PointKind;

pub fn num(x: f32) -> ParamValue {
    ParamValue::Number(f64::from(x))
}

pub fn yes(b: bool) -> ParamValue {
    ParamValue::Bool(b)
}

/// A stove: a 0.6 m cube with a burner at the centre of its top, heating as the taxonomy's
/// `stove.n.01` (500 °C, rate 0.02 /s, 0.2 m reach, needs to be toggled on), with a knob button.
pub fn stove(world: &mut World, x: f32, y: f32) -> ObjectId {
    let spec = ObjectSpec::new(
        "stove_1",
        "stove.n.01",
        vec![Part::at(cuboid(0.3, 0.3, 0.45), v(0.0, 0.0, 0.45))],
    )
    .at(v(x, y, 0.0))
    .fixed()
    .ability(
        Ability::HeatSource,
        &[
            ("temperature", num(500.0)),
            ("heating_rate", num(0.02)),
            ("distance_threshold", num(0.2)),
            ("requires_toggled_on", yes(true)),
            ("requires_closed", yes(false)),
            ("requires_inside", yes(false)),
        ],
    )
    .ability(Ability::Toggleable, &[])
    .point(PointKind::HeatingElement, v(0.0, 0.0, 0.9))
    .point(PointKind::ToggleButton, v(0.3, 0.0, 0.8));
    world.add(spec).unwrap()
}

/// A fridge: an insulated box 0.7 × 0.7 × 1.2 m with a door on a hinge along its front-left
/// edge, cooling as `electric_refrigerator.n.01` (−18 °C, rate 0.02 /s, closed and inside).
pub fn fridge(world: &mut World, x: f32, y: f32) -> ObjectId {
    let (w, d, h, t) = (0.35, 0.35, 1.2, 0.02);
    let parts = vec![
        Part::at(cuboid(w, d, t), v(0.0, 0.0, t)),
        Part::at(cuboid(w, d, t), v(0.0, 0.0, h - t)),
        Part::at(cuboid(t, d, h / 2.0), v(-w + t, 0.0, h / 2.0)),
        Part::at(cuboid(t, d, h / 2.0), v(w - t, 0.0, h / 2.0)),
        Part::at(cuboid(w, t, h / 2.0), v(0.0, d - t, h / 2.0)),
    ];
    let door = LinkSpec {
        name: "door".into(),
        parts: vec![Part::at(cuboid(w, t, h / 2.0), v(0.0, -d - t, h / 2.0))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(-w, -d - t, 0.0),
            v(0.0, 0.0, -1.0),
            2.0,
            5.0,
        ),
        density: 300.0,
    };
    let spec = ObjectSpec::new("fridge_1", "electric_refrigerator.n.01", parts)
        .at(v(x, y, 0.0))
        .fixed()
        .link(door)
        .ability(Ability::Openable, &[])
        .ability(
            Ability::ColdSource,
            &[
                ("temperature", num(-18.0)),
                ("heating_rate", num(0.02)),
                ("requires_toggled_on", yes(false)),
                ("requires_closed", yes(true)),
                ("requires_inside", yes(true)),
            ],
        );
    world.add(spec).unwrap()
}

/// A sink basin with a faucet outlet 0.35 m above its bottom, toggled by a button.
pub fn sink(world: &mut World, x: f32, y: f32) -> ObjectId {
    let (w, h, t) = (0.3, 0.25, 0.02);
    let parts = vec![
        Part::at(cuboid(w, w, t), v(0.0, 0.0, 0.6 + t)),
        Part::at(cuboid(t, w, h / 2.0), v(-w + t, 0.0, 0.6 + h / 2.0)),
        Part::at(cuboid(t, w, h / 2.0), v(w - t, 0.0, 0.6 + h / 2.0)),
        Part::at(cuboid(w, t, h / 2.0), v(0.0, -w + t, 0.6 + h / 2.0)),
        Part::at(cuboid(w, t, h / 2.0), v(0.0, w - t, 0.6 + h / 2.0)),
        Part::at(cuboid(0.05, 0.05, 0.3), v(0.0, 0.0, 0.3)),
    ];
    let spec = ObjectSpec::new("sink_1", "sink.n.01", parts)
        .at(v(x, y, 0.0))
        .fixed()
        .ability(Ability::WaterSource, &[])
        .ability(Ability::Toggleable, &[])
        .point(PointKind::WaterOutlet, v(0.0, 0.0, 1.0))
        .point(PointKind::ToggleButton, v(0.0, w, 0.9));
    world.add(spec).unwrap()
}

/// A 30 × 30 cm rag, 1 cm thick: soakable, a cleaning tool.
pub fn rag(world: &mut World, at: Vector) -> ObjectId {
    let spec = ObjectSpec::new(
        "rag_1",
        "rag.n.01",
        vec![Part::new(cuboid(0.15, 0.15, 0.005))],
    )
    .at(at)
    .ability(Ability::Soakable, &[])
    .ability(Ability::CleaningTool, &[]);
    world.add(spec).unwrap()
}

/// A stainable, dustyable plate.
pub fn dirty_plate(world: &mut World, at: Vector) -> ObjectId {
    let disc = Primitive::Cylinder {
        radius: 0.12,
        half_height: 0.01,
    };
    let mut spec = ObjectSpec::new("plate_1", "plate.n.04", vec![Part::new(disc)])
        .at(at)
        .ability(Ability::Stainable, &[])
        .ability(Ability::Dustyable, &[]);
    spec.density = 2000.0;
    world.add(spec).unwrap()
}

/// Of a kitchen knife (kg): a real one weighs 0.05–0.3 kg.
pub const KNIFE_MASS: f32 = 0.192;

/// A kitchen knife lying flat, blade down: a slicer of [`KNIFE_MASS`] (a 24 × 2 × 4 cm box).
pub fn knife(world: &mut World, at: Vector) -> ObjectId {
    let mut spec = ObjectSpec::new(
        "knife_1",
        "carving_knife.n.01",
        vec![Part::new(cuboid(0.12, 0.01, 0.02))],
    )
    .at(at)
    .ability(Ability::Slicer, &[]);
    spec.density = KNIFE_MASS / (0.24 * 0.02 * 0.04);
    world.add(spec).unwrap()
}

/// A microwave: a 0.5 × 0.4 × 0.3 m box on a counter-height stand, with a door, heating as
/// `microwave.n.02` (1000 °C, rate 0.04 /s, needs to be on, closed, and the food inside).
pub fn microwave(world: &mut World, x: f32, y: f32) -> ObjectId {
    let (w, d, h, t, z0) = (0.25, 0.2, 0.3, 0.01, 0.9);
    let parts = vec![
        Part::at(cuboid(0.25, 0.2, z0 / 2.0), v(0.0, 0.0, z0 / 2.0)),
        Part::at(cuboid(w, d, t), v(0.0, 0.0, z0 + h - t)),
        Part::at(cuboid(t, d, h / 2.0), v(-w + t, 0.0, z0 + h / 2.0)),
        Part::at(cuboid(t, d, h / 2.0), v(w - t, 0.0, z0 + h / 2.0)),
        Part::at(cuboid(w, t, h / 2.0), v(0.0, d - t, z0 + h / 2.0)),
    ];
    let door = LinkSpec {
        name: "door".into(),
        parts: vec![Part::at(
            cuboid(w, t, h / 2.0),
            v(0.0, -d - t, z0 + h / 2.0),
        )],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(-w, -d - t, 0.0),
            v(0.0, 0.0, -1.0),
            1.8,
            5.0,
        ),
        density: 300.0,
    };
    let spec = ObjectSpec::new("microwave_1", "microwave.n.02", parts)
        .at(v(x, y, 0.0))
        .fixed()
        .link(door)
        .ability(Ability::Openable, &[])
        .ability(Ability::Toggleable, &[])
        .ability(
            Ability::HeatSource,
            &[
                ("temperature", num(1000.0)),
                ("heating_rate", num(0.04)),
                ("requires_toggled_on", yes(true)),
                ("requires_closed", yes(true)),
                ("requires_inside", yes(true)),
            ],
        );
    world.add(spec).unwrap()
}

/// A post at (x, y) with a three-link arm whose revolute joints turn about y (so gravity loads
/// them), each link a 0.3 m bar along x, on multibody joints.
pub fn multibody_arm(world: &mut World, x: f32, y: f32) -> ObjectId {
    let mut spec = ObjectSpec::new(
        "arm",
        "robot.n.01",
        vec![Part::at(cuboid(0.05, 0.05, 0.5), v(0.0, 0.0, 0.5))],
    )
    .at(v(x, y, 0.0))
    .fixed();
    for k in 0..3 {
        let x0 = 0.3 * k as f32;
        spec = spec.link(LinkSpec {
            name: format!("link_{k}"),
            parts: vec![Part::at(cuboid(0.15, 0.02, 0.02), v(x0 + 0.15, 0.0, 1.0))],
            parent: if k == 0 { None } else { Some(k - 1) },
            joint: JointSpec {
                kind: JointKind::Revolute,
                model: JointModel::Multibody,
                anchor: v(x0, 0.0, 1.0),
                axis: v(0.0, 1.0, 0.0),
                limits: Some([-2.5, 2.5]),
                damping: 0.0,
            },
            density: 500.0,
        });
    }
    world.add(spec).unwrap()
}

/// The `i`-th of a column of boxes, balls and cylinders over (0.5, 0.5) — the open box's place —
/// at `base + gap · i` high, a little off the column's axis so that they collide and tumble.
pub fn column_thing(i: usize, base: f32, gap: f32) -> ObjectSpec {
    let primitive = match i % 3 {
        0 => cuboid(0.04, 0.03, 0.02),
        1 => Primitive::Sphere { radius: 0.035 },
        _ => Primitive::Cylinder {
            radius: 0.03,
            half_height: 0.04,
        },
    };
    let (dx, dy) = (
        (i % 4) as f32 * 0.03 - 0.045,
        ((i / 4) % 3) as f32 * 0.03 - 0.03,
    );
    ObjectSpec::new(
        &format!("thing_{i}"),
        "thing.n.01",
        vec![Part::new(primitive)],
    )
    .at(v(0.5 + dx, 0.5 + dy, base + gap * i as f32))
}
