//! The object library against the official activities: coverage, buildability, openings and
//! containers that really contain.

use behavior_assets::CATALOG;
use behavior_assets::{Library, Shape};
use behavior_core::Ability;
use behavior_core::Predicate;
use behavior_data::DataDir;
use behavior_sim::{ObjectSpec, Part, Primitive, Relation, World};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;
use rapier3d::math::Vector;
use std::collections::BTreeSet;

fn taxonomy() -> behavior_bddl::Taxonomy {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap()
}

/// Every category declared by the 100 official activities.
fn official_synsets() -> BTreeSet<String> {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let mut synsets = BTreeSet::new();
    for name in data.activities().unwrap() {
        let (activity, _) = knowledge
            .load(&behavior_bddl::load::read_source(&data.problem_path(&name).unwrap()).unwrap())
            .unwrap();
        synsets.extend(activity.categories.iter().map(|c| c.name.clone()));
    }
    synsets
}

#[test]
fn every_synset_of_the_100_activities_resolves_to_an_archetype() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let synsets = official_synsets();
    assert_eq!(synsets.len(), 194);
    let missing: Vec<&String> = synsets
        .iter()
        .filter(|s| library.resolve(s).is_err())
        .collect();
    assert!(missing.is_empty(), "no archetype for {missing:?}");
    // A synset without its own archetype resolves through a descendant.
    assert_eq!(library.resolve("fruit.n.01").unwrap().shape, Shape::Ball);
    assert!(library.resolve("nonsense.n.01").is_err());
}

#[test]
fn the_catalog_has_one_sorted_entry_per_synset_with_sane_sizes() {
    assert!(
        CATALOG.windows(2).all(|w| w[0].synset < w[1].synset),
        "sorted and unique"
    );
    for a in CATALOG {
        assert!(
            (0..3).all(|k| a.min[k] > 0.0 && a.min[k] <= a.max[k]),
            "{}",
            a.synset
        );
        assert!(a.density > 0.0, "{}", a.synset);
        assert!(
            a.max.iter().all(|&x| x <= 5.0),
            "{} is larger than a room",
            a.synset
        );
    }
}

fn spawn_all(seed: u64) -> Vec<(ObjectSpec, &'static behavior_assets::Archetype)> {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    CATALOG
        .iter()
        .map(|a| {
            (
                library
                    .spawn(a.synset, &format!("{}_1", a.synset), &mut rng)
                    .unwrap(),
                a,
            )
        })
        .collect()
}

#[test]
fn every_archetype_builds_in_every_variant_and_openables_open() {
    let taxonomy = taxonomy();
    let mut opened = 0;
    for a in CATALOG {
        for variant in 0..a.shape.variants() {
            let mid = Vector::from_array(std::array::from_fn(|k| (a.min[k] + a.max[k]) / 2.0));
            let (mut spec, _) = a.build(&format!("{}_1", a.synset), mid, variant);
            spec.abilities = taxonomy.abilities(a.synset).cloned().unwrap_or_default();
            let openable = spec.abilities.contains_key(&Ability::Openable);
            let mut world = World::default();
            let id = world
                .add(spec)
                .unwrap_or_else(|e| panic!("{}: {e}", a.synset));
            if openable && !world.bodies().object(id).links.is_empty() {
                world.set_state(id, Predicate::Open, true).unwrap();
                assert!(world.state(id, Predicate::Open), "{}", a.synset);
                world.set_state(id, Predicate::Open, false).unwrap();
                assert!(!world.state(id, Predicate::Open), "{}", a.synset);
                opened += 1;
            }
            for _ in 0..5 {
                world.step();
            }
        }
    }
    assert!(opened >= 15, "only {opened} openable archetypes opened");
}

#[test]
fn openable_synsets_get_doors_drawers_or_lids() {
    let taxonomy = taxonomy();
    let openable: Vec<&str> = CATALOG
        .iter()
        .filter(|a| {
            let id = taxonomy.get(a.synset);
            id.is_some_and(|id| taxonomy.has_ability(id, Ability::Openable))
        })
        .map(|a| a.synset)
        .collect();
    let spawned = spawn_all(1);
    let without: Vec<&str> = openable
        .iter()
        .copied()
        .filter(|s| {
            spawned
                .iter()
                .any(|(spec, a)| a.synset == *s && spec.links.is_empty())
        })
        .collect();
    // A stove is openable in the taxonomy (its oven); ours is a cooktop block for now.
    assert_eq!(
        without,
        ["stove.n.01"],
        "openable synsets without a moving part"
    );
}

#[test]
fn containers_used_with_inside_hold_an_object_inside() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    // The synsets the activities put things inside.
    let containers = [
        "ashcan.n.01",
        "backpack.n.01",
        "basket.n.01",
        "bathtub.n.01",
        "bin.n.01",
        "bucket.n.01",
        "cabinet.n.01",
        "carton.n.02",
        "dish.n.01",
        "dishwasher.n.01",
        "electric_refrigerator.n.01",
        "jar.n.01",
        "sack.n.01",
        "shelf.n.01",
        "sink.n.01",
        "stocking.n.01",
        "teapot.n.01",
    ];
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for synset in containers {
        let mut world = World::default();
        let _floor = world
            .add(
                ObjectSpec::new(
                    "floor",
                    "floor.n.01",
                    vec![Part::at(
                        Primitive::Box {
                            half_extents: Vector::new(5.0, 5.0, 0.05),
                        },
                        Vector::new(0.0, 0.0, -0.05),
                    )],
                )
                .fixed(),
            )
            .unwrap();
        let mut spec = library.spawn(synset, "container", &mut rng).unwrap();
        spec.body = behavior_sim::BodyKind::Fixed;
        let container = world.add(spec).unwrap();
        let size = world.bodies().aabb(container).maxs - world.bodies().aabb(container).mins;
        let radius = (size.x.min(size.y).min(size.z) / 8.0).clamp(0.005, 0.04);
        let ball = world
            .add(
                ObjectSpec::new(
                    "ball",
                    "ball.n.01",
                    vec![Part::new(Primitive::Sphere { radius })],
                )
                .at(Vector::new(3.0, 3.0, 0.5)),
            )
            .unwrap();
        world
            .place(ball, Relation::Inside, container, &mut rng)
            .unwrap_or_else(|e| panic!("{synset}: {e}"));
        world.settle(200);
        assert!(
            world.relations().inside(ball, container),
            "{synset}: the ball fell out"
        );
    }
}

#[test]
fn spawning_is_deterministic_per_seed_and_varies_across_seeds() {
    let sizes = |seed| -> Vec<u32> {
        spawn_all(seed)
            .iter()
            .flat_map(|(spec, _)| spec.parts.iter().map(|p| p.offset.translation.z.to_bits()))
            .collect()
    };
    assert_eq!(sizes(3), sizes(3));
    assert_ne!(sizes(3), sizes(4));
}

#[test]
fn tools_and_appliances_get_the_points_their_abilities_use() {
    use behavior_sim::PointKind;
    let spawned = spawn_all(2);
    let point = |synset: &str, kind: PointKind| {
        spawned
            .iter()
            .any(|(spec, a)| a.synset == synset && spec.points.iter().any(|(k, _)| *k == kind))
    };
    assert!(point("stove.n.01", PointKind::HeatingElement));
    assert!(point("sink.n.01", PointKind::WaterOutlet));
    assert!(point("sink.n.01", PointKind::ToggleButton));
    assert!(point("carving_knife.n.01", PointKind::SlicingEdge));
    let stove = spawned
        .iter()
        .find(|(_, a)| a.synset == "stove.n.01")
        .unwrap();
    assert_eq!(
        stove
            .0
            .points
            .iter()
            .filter(|(k, _)| *k == PointKind::HeatingElement)
            .count(),
        4
    );
}

#[test]
fn sliceables_split_into_their_archetype_halves() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut sliced = 0;
    for a in CATALOG {
        let Some(id) = taxonomy.get(a.synset) else {
            continue;
        };
        if !taxonomy.has_ability(id, Ability::Sliceable) {
            continue;
        }
        for variant in 0..a.shape.variants() {
            let mid = Vector::from_array(std::array::from_fn(|k| (a.min[k] + a.max[k]) / 2.0));
            let spec = library.instance(a.synset, "whole", mid, variant).unwrap();
            assert!(spec.halves.is_some(), "{}", a.synset);
            let mut world = World::default();
            let whole = world.add(spec).unwrap();
            let mass = world.bodies().mass(whole);
            world.set_state(whole, Predicate::Sliced, true).unwrap();
            let [h1, h2] = world.bodies().object(whole).replaced_by.unwrap();
            let halves = world.bodies().mass(h1) + world.bodies().mass(h2);
            assert!(
                (halves - mass).abs() <= 0.1 * mass,
                "{} v{variant}: {mass} kg into {halves} kg",
                a.synset
            );
            // Each half lies on its own side of the cut.
            assert!(
                world.bodies().aabb(h1).center().x < world.bodies().aabb(h2).center().x,
                "{}",
                a.synset
            );
            sliced += 1;
        }
    }
    assert!(sliced >= 10, "only {sliced} sliceable archetypes");
}

#[test]
fn resting_orientations_are_stable_on_a_floor() {
    use rapier3d::math::Pose;
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut checked = 0;
    for a in CATALOG
        .iter()
        .filter(|a| !a.shape.is_fixed() && a.max.iter().all(|&x| x < 1.0))
    {
        for rotation in a.shape.resting_orientations() {
            let mut world = World::default();
            let slab = Primitive::Box {
                half_extents: Vector::new(3.0, 3.0, 0.05),
            };
            world
                .add(
                    ObjectSpec::new(
                        "floor",
                        "floor.n.01",
                        vec![Part::at(slab, Vector::new(0.0, 0.0, -0.05))],
                    )
                    .fixed(),
                )
                .unwrap();
            let mid = Vector::from_array(std::array::from_fn(|k| (a.min[k] + a.max[k]) / 2.0));
            let mut spec = library.instance(a.synset, "thing", mid, 0).unwrap();
            spec.pose = Pose::from_parts(Vector::new(0.0, 0.0, 1.5), rotation);
            let id = world.add(spec).unwrap();
            // Lower it onto the floor, 5 mm up.
            let bottom = world.bodies().aabb(id).mins.z;
            world
                .bodies_mut()
                .set_pose(
                    id,
                    Pose::from_parts(Vector::new(0.0, 0.0, 1.5 - bottom + 0.005), rotation),
                )
                .unwrap();
            world.settle(300);
            // The world's up, seen in the object's frame, must still point up.
            let up_in_object = rotation.inverse() * Vector::Z;
            let now = world.bodies().pose(id).rotation * up_in_object;
            assert!(
                now.z > 0.98,
                "{} does not rest in orientation {rotation:?}: up is now {now:?}",
                a.synset
            );
            checked += 1;
        }
    }
    assert!(checked > 150, "{checked}");
}

#[test]
fn a_general_synset_comes_as_any_of_its_kinds() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let drawn: BTreeSet<&str> = (0..40)
        .map(|_| library.choose("food.n.02", &mut rng).unwrap().synset)
        .collect();
    assert!(drawn.len() >= 5, "{drawn:?}");
    // Never a fixed piece of furniture for a movable kind (a vessel is not a bathtub).
    for _ in 0..40 {
        assert!(
            !library
                .choose("vessel.n.03", &mut rng)
                .unwrap()
                .shape
                .is_fixed()
        );
    }
    // A synset without kinds below it is always itself.
    assert!(
        (0..10).all(|_| library.choose("apple.n.01", &mut rng).unwrap().synset == "apple.n.01")
    );
}

#[test]
fn slicers_weigh_what_a_kitchen_knife_weighs() {
    // A knife must cut by being pushed, not by its own weight (slicing needs 10 N): a real one
    // weighs 0.05–0.3 kg, at every size and variant its archetype can come in.
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let slicers: Vec<_> = CATALOG
        .iter()
        .filter(|a| {
            taxonomy
                .abilities(a.synset)
                .is_some_and(|abilities| abilities.contains_key(&Ability::Slicer))
        })
        .collect();
    assert!(slicers.len() >= 2, "{} slicer archetypes", slicers.len());
    for a in slicers {
        for size in [a.min, a.max] {
            for variant in 0..a.shape.variants() {
                let mut world = World::default();
                let spec =
                    library.instance_of(a, a.synset, "knife", Vector::from_array(size), variant);
                let id = world.add(spec).unwrap();
                let mass = world.bodies().mass(id);
                assert!(
                    (0.05..=0.3).contains(&mass),
                    "{} of size {size:?}, variant {variant}: {mass} kg",
                    a.synset
                );
            }
        }
    }
}

/// Movable things nobody in the activities lifts: vehicles, a pool or hot tub, a barbecue grill
/// (rolled on its legs), the robot's stand-in.
const NOT_LIFTED: [&str; 5] = [
    "agent.n.01",
    "car.n.01",
    "grill.n.02",
    "pool.n.01",
    "vehicle.n.01",
];

#[test]
fn what_people_carry_is_light_enough_for_the_assisted_grasp() {
    // Issue 42: a floor lamp (76 kg as a solid cylinder) and boxes with thick cardboard walls
    // (21 kg) were refused by the BehaviorRobot's assisted grasp, whose limit (the original's)
    // is 10 kg, though people carry them. Hollow or airy things have effective densities; every
    // movable archetype but those nobody lifts weighs at most 10 kg at every size and variant.
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    // The assisted grasp's limit, kg (`behavior_robots::GraspRules::max_mass`, the original's).
    let limit = 10.0;
    let mut checked = 0;
    for a in CATALOG
        .iter()
        .filter(|a| !a.shape.is_fixed() && !NOT_LIFTED.contains(&a.synset))
    {
        for size in [a.min, a.max] {
            for variant in 0..a.shape.variants() {
                let mut world = World::default();
                let spec = library.instance_of(a, a.synset, "x", Vector::from_array(size), variant);
                let id = world.add(spec).unwrap();
                let mass = world.bodies().total_mass(id);
                assert!(
                    mass <= limit,
                    "{} of size {size:?}, variant {variant}: {mass:.1} kg, over the grasp's {limit} kg",
                    a.synset
                );
                checked += 1;
            }
        }
    }
    assert!(
        checked > 300,
        "only {checked} movable archetype builds checked"
    );
}
