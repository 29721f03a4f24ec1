//! Planning the base through a small world of walls.

use behavior_core::RoomType;
use behavior_core::rng::seeded;
use behavior_motion::{
    BaseConfig, BaseSpace, Footprint, PlanError, PlanParams, Space, Standing, lattice_plan, plan,
};
use behavior_sim::{Material, ObjectSpec, Part, Primitive, QueryFilter, Room, World};
use rapier3d::math::{Pose, Vector};

/// A fixed wall: a box of `half` extents centred at (x, y), 2 m tall.
fn wall(world: &mut World, name: &str, (x, y): (f32, f32), (hx, hy): (f32, f32)) {
    let part = Part::new(Primitive::Box {
        half_extents: Vector::new(hx, hy, 1.0),
    });
    let spec = ObjectSpec::new(name, "wall.n.01", vec![part])
        .looks([200, 200, 200], Material::Stone)
        .at(Vector::new(x, y, 1.0))
        .fixed();
    world.add(spec).unwrap();
}

/// The BehaviorRobot's body: an upright capsule of radius 0.25 spanning 0.2–1.2 m.
fn body() -> Footprint {
    Footprint {
        shapes: vec![(
            Primitive::Capsule {
                radius: 0.25,
                half_height: 0.25,
            },
            Pose::from_translation(Vector::new(0.0, 0.0, 0.7)),
        )],
    }
}

fn space<'w>(world: &'w World, start: &BaseConfig, goal: &BaseConfig) -> BaseSpace<'w> {
    BaseSpace::new(world, body(), QueryFilter::default(), start, goal)
}

/// A wall across x = 1 with a 0.8 m doorway at y ∈ [0.2, 1.0].
fn doorway() -> World {
    let mut world = World::default();
    wall(&mut world, "wall_south", (1.0, -1.9), (0.05, 2.1));
    wall(&mut world, "wall_north", (1.0, 2.5), (0.05, 1.5));
    world
}

/// Every configuration of `path` free, and every move between two of them free when checked
/// ten times more finely than the planner did.
fn assert_collision_free(space: &BaseSpace, path: &[BaseConfig]) {
    for w in path.windows(2) {
        for c in space.steps(&w[0], &w[1], 0.005) {
            assert!(
                space.free(&c),
                "{c:?} collides (between {:?} and {:?})",
                w[0],
                w[1]
            );
        }
    }
}

#[test]
fn an_open_floor_takes_the_direct_path() {
    let world = World::default();
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.0),
        BaseConfig::new(2.0, 1.0, 1.5),
    );
    let planned = plan(
        &space(&world, &start, &goal),
        &start,
        &goal,
        &PlanParams::default(),
    )
    .unwrap();
    assert_eq!(planned.run, 0);
    assert_eq!(planned.path.first(), Some(&start));
    assert_eq!(planned.path.last(), Some(&goal));
}

#[test]
fn a_wall_is_passed_through_its_doorway() {
    let world = doorway();
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.0),
        BaseConfig::new(2.0, 0.0, 0.0),
    );
    let space = space(&world, &start, &goal);
    assert!(
        !space.free(&BaseConfig::new(1.0, 0.0, 0.0)),
        "the wall is not in the way"
    );
    let planned = plan(&space, &start, &goal, &PlanParams::default()).unwrap();
    assert!(planned.run >= 1, "the direct path went through the wall");
    assert_eq!(planned.path.first(), Some(&start));
    assert_eq!(planned.path.last(), Some(&goal));
    assert_collision_free(&space, &planned.path);
    let crossing = planned
        .path
        .windows(2)
        .find(|w| w[0].x < 1.0 && w[1].x >= 1.0)
        .expect("the path never crosses x = 1");
    assert!(
        (0.2..=1.0).contains(&crossing[1].y),
        "crossed the wall at y = {}",
        crossing[1].y
    );
}

#[test]
fn the_same_seed_gives_the_same_path_and_another_seed_may_not() {
    let world = doorway();
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.0),
        BaseConfig::new(2.0, 0.0, 0.0),
    );
    let space = space(&world, &start, &goal);
    let run = |seed| {
        plan(
            &space,
            &start,
            &goal,
            &PlanParams {
                seed,
                ..PlanParams::default()
            },
        )
        .unwrap()
        .path
    };
    assert_eq!(run(3), run(3));
    let paths: Vec<_> = (0..4).map(run).collect();
    assert!(
        paths.windows(2).any(|w| w[0] != w[1]),
        "four seeds gave one path"
    );
}

#[test]
fn a_goal_inside_a_wall_or_walled_in_is_refused_with_the_reason() {
    let world = doorway();
    let start = BaseConfig::new(0.0, 0.0, 0.0);
    let inside = BaseConfig::new(1.0, -1.0, 0.0);
    let err = plan(
        &space(&world, &start, &inside),
        &start,
        &inside,
        &PlanParams::default(),
    );
    assert_eq!(err, Err(PlanError::GoalInCollision));
    let err = plan(
        &space(&world, &inside, &start),
        &inside,
        &start,
        &PlanParams::default(),
    );
    assert_eq!(err, Err(PlanError::StartInCollision));

    let mut world = World::default();
    wall(&mut world, "w", (2.0, 0.0), (0.05, 1.0));
    wall(&mut world, "e", (4.0, 0.0), (0.05, 1.0));
    wall(&mut world, "s", (3.0, -1.0), (1.0, 0.05));
    wall(&mut world, "n", (3.0, 1.0), (1.0, 0.05));
    let goal = BaseConfig::new(3.0, 0.0, 0.0);
    let err = plan(
        &space(&world, &start, &goal),
        &start,
        &goal,
        &PlanParams::default(),
    );
    assert_eq!(
        err,
        Err(PlanError::NoPath {
            restarts: 2,
            iterations: 20
        })
    );
}

/// A wall across x = 1 from y = −6 to 6 with a 0.65 m gap at y ∈ [3.0, 3.65]: far off the line
/// between the ends, and narrow for a body 0.5 m across.
fn narrow_gap() -> World {
    let mut world = World::default();
    wall(&mut world, "wall_south", (1.0, -1.5), (0.05, 4.5));
    wall(&mut world, "wall_north", (1.0, 4.825), (0.05, 1.175));
    world
}

#[test]
fn the_lattice_finds_the_narrow_way_that_a_short_rrt_search_misses() {
    let world = narrow_gap();
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.3),
        BaseConfig::new(2.0, 0.0, -1.0),
    );
    let space = space(&world, &start, &goal).with_bounds([-2.0, -6.0], [4.0, 6.0]);
    let short = PlanParams {
        iterations: 5,
        restarts: 0,
        ..PlanParams::default()
    };
    assert_eq!(
        plan(&space, &start, &goal, &short),
        Err(PlanError::NoPath {
            restarts: 0,
            iterations: 5
        })
    );
    let path = lattice_plan(&space, &start, &goal, &short).unwrap();
    assert_eq!(path.first(), Some(&start));
    assert_eq!(path.last(), Some(&goal));
    assert_collision_free(&space, &path);
    let crossing = path
        .windows(2)
        .find(|w| w[0].x < 1.0 && w[1].x >= 1.0)
        .expect("the path never crosses x = 1");
    let y = crossing[0].y
        + (crossing[1].y - crossing[0].y) * (1.0 - crossing[0].x) / (crossing[1].x - crossing[0].x);
    assert!((3.0..=3.65).contains(&y), "crossed the wall at y = {y}");
    // The same ends and seed give the same path.
    assert_eq!(lattice_plan(&space, &start, &goal, &short), Ok(path));
}

#[test]
fn the_lattice_says_when_no_way_leads_to_a_walled_in_goal() {
    let mut world = World::default();
    wall(&mut world, "w", (2.0, 0.0), (0.05, 1.0));
    wall(&mut world, "e", (4.0, 0.0), (0.05, 1.0));
    wall(&mut world, "s", (3.0, -1.0), (1.0, 0.05));
    wall(&mut world, "n", (3.0, 1.0), (1.0, 0.05));
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.0),
        BaseConfig::new(3.0, 0.0, 0.0),
    );
    let space = space(&world, &start, &goal);
    let err = lattice_plan(&space, &start, &goal, &PlanParams::default());
    assert!(
        matches!(err, Err(PlanError::NoLatticePath { .. })),
        "{err:?}"
    );
}

#[test]
fn a_base_that_cannot_turn_backs_out_of_a_dead_end() {
    let mut world = World::default();
    wall(&mut world, "south", (-1.0, -0.35), (3.0, 0.05));
    wall(&mut world, "north", (-1.0, 0.35), (3.0, 0.05));
    wall(&mut world, "end", (1.0, 0.0), (0.05, 0.4));
    // Long and narrow, as a base carrying a board ahead: no turn fits between the walls.
    let long = Footprint {
        shapes: vec![(
            Primitive::Box {
                half_extents: Vector::new(0.5, 0.2, 0.3),
            },
            Pose::from_translation(Vector::new(0.0, 0.0, 0.4)),
        )],
    };
    let (start, goal) = (
        BaseConfig::new(0.0, 0.0, 0.0),
        BaseConfig::new(-3.0, 0.0, 0.0),
    );
    let space = BaseSpace::new(&world, long, QueryFilter::default(), &start, &goal)
        .with_bounds([-4.5, -1.0], [1.5, 1.0]);
    assert!(space.free(&start) && space.free(&goal));
    assert!(
        !space.free(&BaseConfig::new(-1.5, 0.0, 0.5)),
        "a turn collides"
    );
    let params = PlanParams::default();
    let rrt = plan(&space, &start, &goal, &params).map(|p| p.path);
    for path in [rrt, lattice_plan(&space, &start, &goal, &params)] {
        let path = path.unwrap();
        assert_eq!(path.last(), Some(&goal));
        assert_collision_free(&space, &path);
        assert!(path.iter().all(|c| c.yaw.abs() < 0.2), "{path:?}");
    }
}

/// Where the robot stands to reach a box by the west wall of a 3 × 3 m room, with and
/// without the room, over twenty seeds.
fn stands_by_the_wall(with_room: bool) -> Vec<BaseConfig> {
    let mut world = World::default();
    let part = Part::new(Primitive::Box {
        half_extents: Vector::new(0.1, 0.1, 0.1),
    });
    let spec = ObjectSpec::new("box_0", "carton.n.02", vec![part])
        .looks([150, 100, 50], Material::Wood)
        .at(Vector::new(0.15, 1.5, 0.1))
        .fixed();
    let object = world.add(spec).unwrap();
    if with_room {
        world.add_room(Room {
            kind: RoomType::Kitchen,
            instance: 0,
            min: [0.0, 0.0],
            max: [3.0, 3.0],
            annexes: Vec::new(),
            floor: None,
        });
    }
    let standing = Standing {
        config: BaseConfig::new(1.5, 1.5, 0.0),
        footprint: body(),
        eye: Pose::from_translation(Vector::new(0.0, 0.0, 1.2)),
        filter: QueryFilter::default(),
    };
    (0..20)
        .filter_map(|seed| standing.near(&world, object, &mut seeded(seed)))
        .collect()
}

#[test]
fn a_place_to_stand_lies_in_the_home_not_beyond_its_outer_wall() {
    let indoors = stands_by_the_wall(true);
    assert_eq!(indoors.len(), 20, "no place to stand for some seed");
    for c in &indoors {
        assert!(
            (0.0..=3.0).contains(&c.x) && (0.0..=3.0).contains(&c.y),
            "{c:?}"
        );
    }
    // Without the room, nothing keeps the search off the far side of the box.
    let anywhere = stands_by_the_wall(false);
    assert!(anywhere.iter().any(|c| c.x < 0.0), "{anywhere:?}");
}
