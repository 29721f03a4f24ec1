//! Determinism: the same scene and steps give bit-identical states, and a run resumed from a
//! snapshot continues bit-identically.

mod common;

use behavior_sim::World;
use common::*;

/// 48 boxes, balls and cylinders dropped in a column onto an open bin, so they collide, stack,
/// roll off and go to sleep.
fn falling_pile() -> World {
    let mut world = World::default();
    two_room_floor(&mut world);
    open_box(&mut world, 0.5, 0.5);
    for i in 0..48 {
        world.add(column_thing(i, 0.6, 0.09)).unwrap();
    }
    world
}

fn run(world: &mut World, steps: usize) {
    for _ in 0..steps {
        world.step();
    }
}

#[test]
fn snapshot_determinism_two_runs_and_a_resumed_run_are_bit_identical() {
    let mut first = falling_pile();
    let mut second = falling_pile();
    run(&mut first, 500);
    run(&mut second, 500);
    assert_eq!(
        first.bodies().motion_bits(),
        second.bodies().motion_bits(),
        "same steps, same state"
    );
    let midway = first.snapshot();

    run(&mut first, 500);
    run(&mut second, 500);
    assert_eq!(first.bodies().motion_bits(), second.bodies().motion_bits());

    // Resume from the midway snapshot in a fresh world, and by rewinding the first one.
    let mut resumed = falling_pile();
    resumed.restore(&midway);
    run(&mut resumed, 500);
    assert_eq!(
        resumed.bodies().motion_bits(),
        first.bodies().motion_bits(),
        "resumed from a snapshot"
    );
    let end = first.bodies().motion_bits();
    first.restore(&midway);
    assert_eq!(first.bodies().steps(), 500);
    run(&mut first, 500);
    assert_eq!(first.bodies().motion_bits(), end, "rewound and replayed");

    // The pile really moved and came to rest.
    let moved = (0..first.bodies().objects().len())
        .filter(|&i| {
            first
                .bodies()
                .pose(behavior_sim::ObjectId(i as u32))
                .translation
                .z
                < 0.5
        })
        .count();
    assert!(moved > 40, "only {moved} objects fell");
    let asleep = first
        .bodies()
        .objects()
        .filter(|(id, o)| !o.is_fixed() && first.bodies().is_sleeping(*id))
        .count();
    assert!(
        asleep > 40,
        "only {asleep} objects are asleep after 1000 steps"
    );
}

/// A stove heating an apple and a running tap soaking a rag: states, drops and particles continue
/// bit-identically from a snapshot too.
#[test]
fn snapshot_determinism_covers_temperatures_water_and_particles() {
    use behavior_core::Predicate;
    let scene = || {
        let mut world = World::default();
        two_room_floor(&mut world);
        let stove = stove(&mut world, -1.0, 0.0);
        let apple = sliceable_apple(&mut world, "apple_1", v(-1.0, 0.0, 1.0));
        let sink = sink(&mut world, 1.0, 0.0);
        let rag = rag(&mut world, v(1.0, 0.15, 0.7));
        let plate = dirty_plate(&mut world, v(-3.0, 0.0, 0.05));
        world.set_state(stove, Predicate::ToggledOn, true).unwrap();
        world.set_state(sink, Predicate::ToggledOn, true).unwrap();
        world.set_state(plate, Predicate::Dusty, true).unwrap();
        (world, apple, rag)
    };
    let digest = |world: &World, apple, rag| {
        let drops: Vec<u32> = world
            .drops()
            .iter()
            .flat_map(|d| [d.x.to_bits(), d.y.to_bits(), d.z.to_bits()])
            .collect();
        (
            world.bodies().motion_bits(),
            world.temperature(apple).to_bits(),
            world.state(rag, Predicate::Soaked),
            drops,
        )
    };
    let (mut first, apple, rag) = scene();
    run(&mut first, 20);
    let midway = first.snapshot();
    run(&mut first, 40);
    let (mut second, _, _) = scene();
    second.restore(&midway);
    run(&mut second, 40);
    assert_eq!(digest(&first, apple, rag), digest(&second, apple, rag));
    assert!(!first.drops().is_empty());
    assert!(first.temperature(apple) > 30.0);
}
