//! Queries over fixed bodies only: they see walls and furniture, not what moves, and follow a
//! fixed object that is teleported or added between steps.

use behavior_sim::{ObjectSpec, Part, Primitive, QueryFilter, World};
use rapier3d::math::{Pose, Vector};

fn cube(half: f32) -> Primitive {
    Primitive::Box {
        half_extents: Vector::splat(half),
    }
}

#[test]
fn fixed_only_queries_see_fixed_bodies_and_follow_their_changes() {
    let mut world = World::default();
    let wall = world
        .add(ObjectSpec::new("wall", "wall.n.01", vec![Part::new(cube(0.5))]).fixed())
        .unwrap();
    let ball = world
        .add(
            ObjectSpec::new("ball", "ball.n.01", vec![Part::new(cube(0.1))])
                .at(Vector::new(0.0, 0.0, 0.7)),
        )
        .unwrap();
    let fixed = QueryFilter {
        fixed_only: true,
        ..QueryFilter::default()
    };
    let probe = cube(1.0);
    let core = world.core();
    let all = core
        .overlaps(&probe, Pose::IDENTITY, &QueryFilter::default())
        .unwrap();
    assert_eq!(
        all.iter().map(|b| b.object).collect::<Vec<_>>(),
        vec![wall, ball]
    );
    let only = core.overlaps(&probe, Pose::IDENTITY, &fixed).unwrap();
    assert_eq!(
        only.iter().map(|b| b.object).collect::<Vec<_>>(),
        vec![wall]
    );
    // Steps move the ball, not the answer; a teleported wall and a new table are seen at once.
    for _ in 0..10 {
        world.step();
    }
    world
        .set_pose(wall, Pose::from_translation(Vector::new(5.0, 0.0, 0.0)))
        .unwrap();
    let table = world
        .add(
            ObjectSpec::new("table", "table.n.02", vec![Part::new(cube(0.3))])
                .at(Vector::new(0.0, 3.0, 0.0))
                .fixed(),
        )
        .unwrap();
    let at = |x: f32, y: f32| Pose::from_translation(Vector::new(x, y, 0.0));
    let hits = |world: &World, pose| -> Vec<_> {
        let found = world.core().overlaps(&cube(0.2), pose, &fixed).unwrap();
        found.into_iter().map(|b| b.object).collect()
    };
    assert_eq!(hits(&world, at(0.0, 0.0)), vec![]);
    assert_eq!(hits(&world, at(5.0, 0.0)), vec![wall]);
    assert_eq!(hits(&world, at(0.0, 3.0)), vec![table]);
}
