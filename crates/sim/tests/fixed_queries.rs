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
    let all = world
        .query()
        .overlaps(&probe, Pose::IDENTITY, &QueryFilter::default())
        .unwrap();
    assert_eq!(
        all.iter().map(|b| b.object).collect::<Vec<_>>(),
        vec![wall, ball]
    );
    let only = world
        .query()
        .overlaps(&probe, Pose::IDENTITY, &fixed)
        .unwrap();
    assert_eq!(
        only.iter().map(|b| b.object).collect::<Vec<_>>(),
        vec![wall]
    );
    // Steps move the ball, not the answer; a teleported wall and a new table are seen at once.
    for _ in 0..10 {
        world.step();
    }
    world
        .bodies_mut()
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
        let found = world.query().overlaps(&cube(0.2), pose, &fixed).unwrap();
        found.into_iter().map(|b| b.object).collect()
    };
    assert_eq!(hits(&world, at(0.0, 0.0)), vec![]);
    assert_eq!(hits(&world, at(5.0, 0.0)), vec![wall]);
    assert_eq!(hits(&world, at(0.0, 3.0)), vec![table]);
}

#[test]
fn solids_test_shapes_against_each_other_where_the_world_does_not_have_them() {
    use behavior_sim::Solid;
    // A 0.2 m cube offset 0.5 m along x in its frame, and a long thin box.
    let cube = Solid::new(
        &cube(0.1),
        Pose::from_translation(Vector::new(0.5, 0.0, 0.0)),
    )
    .unwrap();
    let rod = Solid::new(
        &Primitive::Box {
            half_extents: Vector::new(1.0, 0.02, 0.02),
        },
        Pose::IDENTITY,
    )
    .unwrap();
    let at = |x: f32, y: f32| Pose::from_translation(Vector::new(x, y, 0.0));
    assert!(cube.intersects(at(0.0, 0.0), &rod, at(0.0, 0.0)));
    assert!(cube.intersects(at(0.0, 0.0), &rod, at(1.5, 0.1)));
    assert!(!cube.intersects(at(0.0, 0.0), &rod, at(0.0, 0.2)));
    assert!(!cube.intersects(at(0.0, 0.3), &rod, at(0.0, 0.0)));
    let (lo, hi) = cube.aabb(at(1.0, 0.0));
    assert!(
        (lo - Vector::new(1.4, -0.1, -0.1)).length() < 1e-5,
        "{lo:?}"
    );
    assert!((hi - Vector::new(1.6, 0.1, 0.1)).length() < 1e-5, "{hi:?}");
    // A shape that cannot be built is an error, not a panic.
    let bad = Primitive::Sphere { radius: f32::NAN };
    assert!(Solid::new(&bad, Pose::IDENTITY).is_err());
}
