//! Sampling in cluttered homes: the homes of the original's three benchmark activities hold at
//! least as many objects as its scenes once the activity is in them; no instance is ever bound to
//! clutter; the clutter around the activity's furniture is put away; cluttered instances save
//! and load.

use behavior_assets::{ClutterPlan, Library, NAMED_HOMES, Scene, clutter, generate};
use behavior_assets::{missing, requirements};
use behavior_bddl::{Activity, Knowledge};
use behavior_data::DataDir;
use behavior_sampling::{Instance, SampleError, SavedInstance, instantiate};
use std::collections::BTreeSet;
use std::sync::OnceLock;

fn data() -> &'static DataDir {
    static DATA: OnceLock<DataDir> = OnceLock::new();
    DATA.get_or_init(|| DataDir::locate(None, |m| eprintln!("{m}")).unwrap())
}

fn knowledge() -> &'static Knowledge {
    static KNOWLEDGE: OnceLock<Knowledge> = OnceLock::new();
    KNOWLEDGE.get_or_init(|| {
        let data = data();
        Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap()
    })
}

fn library() -> Library<'static> {
    Library::new(&knowledge().taxonomy)
}

fn activity(name: &str) -> Activity {
    let source = behavior_bddl::load::read_source(&data().problem_path(name).unwrap()).unwrap();
    knowledge().load(&source).unwrap().0
}

/// The home `behavior sample` uses by default: the first named home that covers the activity,
/// with the clutter of its own seed. Each named home is cluttered once.
fn default_home(activity: &Activity) -> Scene {
    static HOMES: OnceLock<std::sync::Mutex<Vec<Scene>>> = OnceLock::new();
    let library = library();
    let needs = requirements(activity);
    let (name, seed) = NAMED_HOMES
        .into_iter()
        .find(|(n, s)| {
            missing(
                &generate(n, *s, &library).unwrap(),
                &needs,
                &knowledge().taxonomy,
            )
            .is_empty()
        })
        .expect("a covering home");
    let mut homes = HOMES.get_or_init(Default::default).lock().unwrap();
    if let Some(home) = homes.iter().find(|h| h.name == name) {
        return home.clone();
    }
    let home = clutter(&generate(name, seed, &library).unwrap(), &library, seed).unwrap();
    homes.push(home.clone());
    home
}

fn sample(name: &str, home: &Scene) -> Result<Instance, SampleError> {
    instantiate(&activity(name), home, 0, &library(), &knowledge().taxonomy)
}

/// Every object of the world but walls: furniture, doors, windows, floors, clutter and the
/// activity's own objects (the agent's stand-in among them).
fn objects(instance: &Instance) -> usize {
    instance
        .world
        .bodies()
        .objects()
        .filter(|(_, o)| o.category != "wall.n.01")
        .count()
}

#[test]
fn cluttered_homes_hold_as_many_objects_as_the_originals_scenes_after_sampling() {
    // The objects of the original's scenes for its speed benchmark (iGibson 2.0).
    for (name, original) in [
        ("bringing_in_wood", 134),
        ("re-shelving_library_books", 144),
        ("laying_tile_floors", 216),
    ] {
        let home = default_home(&activity(name));
        let instance = sample(name, &home).unwrap();
        let count = objects(&instance);
        eprintln!("{name} in {}: {count} objects", home.name);
        assert!(
            count >= original,
            "{name}: {count} objects, the original has {original}"
        );
        assert!(instance.check_init(&activity(name)).all_hold());
    }
}

/// The names of the instance's objects bound to the activity.
fn bound_names(instance: &Instance) -> BTreeSet<String> {
    let bodies = instance.world.bodies();
    instance
        .bindings
        .iter()
        .map(|&b| bodies.object(b).name.clone())
        .collect()
}

#[test]
fn no_instance_is_bound_to_clutter_and_clutter_around_its_furniture_is_put_away() {
    let name = "re-shelving_library_books";
    let home = default_home(&activity(name));
    let instance = sample(name, &home).unwrap();
    let clutter: BTreeSet<&str> = home.clutter.iter().map(|c| c.name.as_str()).collect();
    assert!(
        bound_names(&instance)
            .iter()
            .all(|b| !clutter.contains(b.as_str()))
    );
    // The shelf and the table the books go on are cleared; the rest of the clutter stays.
    let kept = &instance.scene.clutter;
    assert!(kept.len() < home.clutter.len() && kept.len() > home.clutter.len() / 2);
    assert!(kept.iter().all(|c| home.clutter.contains(c)));
    let world = &instance.world;
    let shelf = activity(name)
        .instances
        .iter()
        .position(|i| i.name == "shelf.n.01_1")
        .map(|i| instance.bindings[i])
        .unwrap();
    assert_eq!(world.bodies().object(shelf).category, "shelf.n.01");
    for c in kept {
        let id = world.bodies().object_named(&c.name).unwrap();
        assert!(
            !world.relations().ontop(id, shelf) && !world.relations().touching(id, shelf),
            "{}",
            c.name
        );
    }
}

#[test]
fn furniture_that_is_clutter_is_never_bound() {
    // The living room's only shelf is a piece of clutter (hovering, asleep, over the room):
    // re-shelving the books must find no shelf rather than bind it.
    let name = "re-shelving_library_books";
    let mut home = default_home(&activity(name));
    let living = home
        .rooms
        .iter()
        .position(|r| r.kind.name() == "living_room")
        .unwrap();
    home.objects
        .retain(|o| !(o.room == living && o.synset == "shelf.n.01"));
    let room = &home.rooms[living];
    home.clutter.push(ClutterPlan {
        name: "clutter_shelf_0".into(),
        synset: "shelf.n.01".into(),
        archetype: "shelf.n.01".into(),
        position: [
            (room.min[0] + room.max[0]) / 2.0,
            (room.min[1] + room.max[1]) / 2.0,
            3.0,
        ],
        rotation: [0.0, 0.0, 0.0, 1.0],
        size: [1.0, 0.3, 1.2],
        variant: 0,
    });
    match sample(name, &home) {
        Err(SampleError::NoFurniture { synset, .. }) => assert_eq!(synset, "shelf.n.01"),
        Err(other) => panic!("unexpected error: {other}"),
        Ok(instance) => panic!("bound {:?}", bound_names(&instance)),
    }
}

#[test]
fn a_cluttered_instance_saves_and_loads_with_its_clutter() {
    let name = "bringing_in_wood";
    let home = default_home(&activity(name));
    let instance = sample(name, &home).unwrap();
    let saved = instance.save();
    assert!(!saved.scene.clutter.is_empty());
    let text = saved.to_json();
    let loaded = SavedInstance::from_json(&text)
        .unwrap()
        .load(&activity(name), &library())
        .unwrap();
    assert_eq!(loaded.scene, instance.scene);
    assert_eq!(objects(&loaded), objects(&instance));
    for c in &loaded.scene.clutter {
        let (a, b) = (&loaded.world, &instance.world);
        let pose = |w: &behavior_sim::World| {
            w.bodies()
                .pose(w.bodies().object_named(&c.name).unwrap())
                .translation
        };
        assert!(
            pose(a).distance(pose(b)) < 1e-6,
            "{} is where it was",
            c.name
        );
    }
}
