//! The world as a BDDL predicate oracle: an activity's goal evaluated on a physical scene. It
//! lives here, where the language and the world meet; the scene helpers are the world's own.

#[path = "../../sim/tests/common/mod.rs"]
mod common;

use behavior_bddl::activity::CheckContext;
use behavior_bddl::{Activity, GroundGoal, Optimizer, Predicate, Source};
use behavior_sim::{BoundWorld, World};
use common::*;

const ACTIVITY: &str = "(define (problem serving_0) (:domain igibson)
  (:objects apple.n.01_1 apple.n.01_2 - apple.n.01 plate.n.04_1 - plate.n.04 table.n.02_1 - table.n.02
            floor.n.01_1 - floor.n.01)
  (:init (ontop plate.n.04_1 table.n.02_1) (inroom table.n.02_1 kitchen) (inroom floor.n.01_1 kitchen))
  (:goal (and (forall (?apple.n.01 - apple.n.01) (ontop ?apple.n.01 ?plate.n.04_1))
              (not (onfloor ?plate.n.04_1 ?floor.n.01_1))
              (sliced ?apple.n.01_2))))";

#[test]
fn a_goal_is_evaluated_on_the_physical_scene() {
    let (activity, _) = Activity::load(
        &Source::new("serving.bddl", ACTIVITY),
        CheckContext::default(),
    )
    .unwrap();
    let mut world = World::default();
    let (kitchen_floor, _) = two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let plate = plate(&mut world, v(-1.0, 0.0, 0.80));
    let first = apple(&mut world, "apple_1", v(-1.03, 0.0, 1.0));
    let second = sliceable_apple(&mut world, "apple_2", v(-2.0, -2.0, 0.3));
    settle(&mut world, 2.0);
    // Instances in :objects order: apple 1, apple 2, plate, table, floor.
    let bindings = [
        Some(first),
        Some(second),
        Some(plate),
        Some(table),
        Some(kitchen_floor),
    ];
    let goal = GroundGoal::new(&activity);
    let optimizer = Optimizer::new(&goal);
    let status = |world: &World| {
        let bound = BoundWorld {
            world,
            bindings: &bindings,
        };
        (
            goal.holds(&bound),
            goal.conjuncts_hold(&bound).collect::<Vec<_>>(),
            optimizer.q(&bound).unwrap().to_string(),
        )
    };
    // The one option: apple 1 and apple 2 on the plate, the plate off the floor, apple 2 sliced;
    // the first and third hold.
    assert_eq!(
        status(&world),
        (false, vec![false, true, false], "1/2".to_string())
    );

    // Put the second apple on the plate and slice it.
    world
        .bodies_mut()
        .set_pose(
            second,
            rapier3d::math::Pose::from_translation(v(-0.93, 0.0, 0.85)),
        )
        .unwrap();
    settle(&mut world, 2.0);
    world.set_state(second, Predicate::Sliced, true).unwrap();
    assert_eq!(
        status(&world),
        (true, vec![true, true, true], "1/1".to_string())
    );
}
