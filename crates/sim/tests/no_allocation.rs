//! A step in which nothing changes does no heap allocation: the world is at rest, with every kind
//! of state system present (a heat source, a water source that is off, a cleaning tool, dirt).

mod common;

use behavior_core::Predicate;
use behavior_sim::World;
use common::*;

#[path = "common/counting.rs"]
mod counting;

#[test]
fn a_step_at_rest_allocates_nothing() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let stove = stove(&mut world, -1.0, 0.0);
    sink(&mut world, -2.5, 0.0);
    table(&mut world, 1.0, 0.0);
    let plate = dirty_plate(&mut world, v(1.0, 0.0, 0.8));
    rag(&mut world, v(1.3, 0.2, 0.8));
    let apple = sliceable_apple(&mut world, "apple_1", v(-1.0, 0.0, 1.0));
    world.set_state(plate, Predicate::Dusty, true).unwrap();
    world.set_state(stove, Predicate::ToggledOn, true).unwrap();
    assert!(world.settle(600), "the scene comes to rest");
    let before = counting::allocations();
    for _ in 0..30 {
        world.step();
    }
    let during = counting::allocations() - before;
    assert_eq!(during, 0, "{during} allocations in 30 steps at rest");
    // The rules still ran: the apple on the lit stove kept heating.
    assert!(
        world.temperature(apple) > 30.0,
        "{}",
        world.temperature(apple)
    );
}
