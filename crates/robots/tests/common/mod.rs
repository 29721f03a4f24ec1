//! Small real scenes for the robot's tests: a floor with two rooms, a table, an apple, a wall,
//! and helpers that drive a hand to a place as a person with a controller would.

#![allow(dead_code)]

use behavior_core::RoomType;
use behavior_robots::{ACTION_DIM, ACTION_SCALE, Action, BODY_HEIGHT, BehaviorRobot, Side};
use behavior_sim::{ObjectId, ObjectSpec, Part, Primitive, Room, World};
use rapier3d::math::{Pose, Vector};

pub fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

pub fn cuboid(hx: f32, hy: f32, hz: f32) -> Primitive {
    Primitive::Box {
        half_extents: v(hx, hy, hz),
    }
}

/// A 20 × 10 m floor whose top is at z = 0: a kitchen for x < 0 and a living room for x ≥ 0.
pub fn floor(world: &mut World) -> ObjectId {
    let floor = world
        .add(
            ObjectSpec::new(
                "floor",
                "floor.n.01",
                vec![Part::new(cuboid(10.0, 5.0, 0.05))],
            )
            .at(v(0.0, 0.0, -0.05))
            .fixed(),
        )
        .unwrap();
    for (kind, min, max) in [
        (RoomType::Kitchen, [-10.0, -5.0], [-0.001, 5.0]),
        (RoomType::LivingRoom, [0.0, -5.0], [10.0, 5.0]),
    ] {
        world.add_room(Room {
            kind,
            instance: 0,
            min,
            max,
            annexes: Vec::new(),
            floor: Some(floor),
        });
    }
    floor
}

/// A table 0.75 m high with a 1.2 × 0.8 m top, centred at (x, y).
pub fn table(world: &mut World, x: f32, y: f32) -> ObjectId {
    let mut parts = vec![Part::at(cuboid(0.6, 0.4, 0.025), v(0.0, 0.0, 0.725))];
    for (lx, ly) in [(-0.55, -0.35), (0.55, -0.35), (-0.55, 0.35), (0.55, 0.35)] {
        parts.push(Part::at(cuboid(0.025, 0.025, 0.35), v(lx, ly, 0.35)));
    }
    world
        .add(
            ObjectSpec::new("table", "table.n.02", parts)
                .at(v(x, y, 0.0))
                .fixed(),
        )
        .unwrap()
}

/// An apple (a ball of radius 4 cm, 0.2 kg) at `at`.
pub fn apple(world: &mut World, at: Vector) -> ObjectId {
    let radius = 0.04f32;
    let mut spec = ObjectSpec::new(
        "apple",
        "apple.n.01",
        vec![Part::new(Primitive::Sphere { radius })],
    )
    .at(at);
    spec.density = 0.2 / (4.0 / 3.0 * std::f32::consts::PI * radius.powi(3));
    world.add(spec).unwrap()
}

/// A box of `mass` kg and half size `half`, resting on the floor at (x, y), or on a surface at
/// height `z`.
pub fn crate_of(world: &mut World, name: &str, at: Vector, half: f32, mass: f32) -> ObjectId {
    let mut spec = ObjectSpec::new(
        name,
        "carton.n.02",
        vec![Part::new(cuboid(half, half, half))],
    )
    .at(at + v(0.0, 0.0, half + 0.001));
    spec.density = mass / (8.0 * half * half * half);
    world.add(spec).unwrap()
}

/// A wall across x = `x`, 2 m high and 4 m wide.
pub fn wall(world: &mut World, x: f32) -> ObjectId {
    world
        .add(
            ObjectSpec::new("wall", "wall.n.01", vec![Part::new(cuboid(0.05, 2.0, 1.0))])
                .at(v(x + 0.05, 0.0, 1.0))
                .fixed(),
        )
        .unwrap()
}

/// A robot standing at (x, y) at its usual height, facing +x.
pub fn robot_at(world: &mut World, x: f32, y: f32) -> BehaviorRobot {
    BehaviorRobot::add(world, Pose::from_translation(v(x, y, BODY_HEIGHT))).unwrap()
}

/// An action from (index, value) pairs.
pub fn action(entries: &[(usize, f32)]) -> Action {
    let mut values = [0.0; ACTION_DIM];
    for &(i, x) in entries {
        values[i] = x;
    }
    Action::new(&values).unwrap()
}

pub fn step(world: &mut World, robot: &mut BehaviorRobot, action: Action) {
    robot.set_action(action);
    world.step_with(robot);
}

pub fn idle(world: &mut World, robot: &mut BehaviorRobot, steps: usize) {
    for _ in 0..steps {
        step(world, robot, Action::ZERO);
    }
}

/// Moves a hand to `goal` in the body frame (without turning it), as a person would: full speed
/// toward where proprioception says it is, slowing to half the remaining distance per step at the
/// end; then lets it come to rest.
pub fn hand_to(world: &mut World, robot: &mut BehaviorRobot, side: Side, goal: Vector) {
    let first = Action::hand_range(side).start;
    for _ in 0..200 {
        let at = Vector::from(robot.proprioception(world).hands[side.index()].position);
        let error = goal - at;
        if error.length() < 2e-4 {
            break;
        }
        // Half the error per step near the goal: the palm trails its target by a step.
        let d = error * (0.5 / ACTION_SCALE);
        let entries = [(first, d.x), (first + 1, d.y), (first + 2, d.z)];
        step(world, robot, action(&entries));
    }
    idle(world, robot, 5);
}

/// Presses or releases a trigger by `delta` per step for `steps` steps.
pub fn press(world: &mut World, robot: &mut BehaviorRobot, side: Side, delta: f32, steps: usize) {
    for _ in 0..steps {
        step(
            world,
            robot,
            action(&[(Action::trigger_index(side), delta)]),
        );
    }
}
