//! A step in which nothing changes does no heap allocation: the world is at rest, with every kind
//! of state system present (a heat source, a water source that is off, a cleaning tool, dirt).

mod common;

use behavior_core::Predicate;
use behavior_sim::World;
use common::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Counts the allocations made on this process's heap.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: forwarded unchanged to the system allocator.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded unchanged to the system allocator.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: forwarded unchanged to the system allocator.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

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
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    for _ in 0..30 {
        world.step();
    }
    let during = ALLOCATIONS.load(Ordering::Relaxed) - before;
    assert_eq!(during, 0, "{during} allocations in 30 steps at rest");
    // The rules still ran: the apple on the lit stove kept heating.
    assert!(
        world.temperature(apple) > 30.0,
        "{}",
        world.temperature(apple)
    );
}
