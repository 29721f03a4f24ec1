//! Clutter: the same home and seed give the same clutter bit for bit; it rests asleep and still
//! in the built home, on, in or beside furniture; scene files with clutter round-trip and
//! rebuild exactly; the furniture-only home is unchanged; bad clutter entries are errors naming
//! the object.

use behavior_assets::{ClutterPlan, Library, NAMED_HOMES, Scene, SceneError, clutter, generate};
use behavior_data::DataDir;
use std::sync::OnceLock;

fn taxonomy() -> &'static behavior_bddl::Taxonomy {
    static TAXONOMY: OnceLock<behavior_bddl::Taxonomy> = OnceLock::new();
    TAXONOMY.get_or_init(|| {
        let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
        behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap()
    })
}

fn library() -> Library<'static> {
    Library::new(taxonomy())
}

/// The first named home, furniture only and with the clutter of its own seed (made once).
fn alder() -> &'static (Scene, Scene) {
    static ALDER: OnceLock<(Scene, Scene)> = OnceLock::new();
    ALDER.get_or_init(|| {
        let library = library();
        let (name, seed) = NAMED_HOMES[0];
        let bare = generate(name, seed, &library).unwrap();
        let full = clutter(&bare, &library, seed).unwrap();
        (bare, full)
    })
}

#[test]
fn the_same_seed_gives_the_same_clutter_bit_for_bit_and_another_seed_other_clutter() {
    let library = library();
    let (bare, full) = alder();
    let again = clutter(bare, &library, bare.seed).unwrap();
    assert_eq!(again.to_json(), full.to_json());
    let other = clutter(bare, &library, bare.seed + 1).unwrap();
    assert_ne!(other.clutter, full.clutter);
    // Cluttering a cluttered home starts again from its furniture.
    assert_eq!(clutter(full, &library, bare.seed).unwrap(), *full);
}

#[test]
fn a_home_holds_over_a_hundred_things_of_clutter_from_many_synsets() {
    let (bare, full) = alder();
    assert!(full.clutter.len() > 100, "{} things", full.clutter.len());
    let mut synsets: Vec<&str> = full.clutter.iter().map(|c| c.synset.as_str()).collect();
    synsets.sort();
    synsets.dedup();
    assert!(synsets.len() >= 30, "{synsets:?}");
    let mut names: Vec<&str> = full.clutter.iter().map(|c| c.name.as_str()).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), full.clutter.len(), "names are unique");
    assert!(names.iter().all(|n| n.starts_with("clutter_")));
    assert_eq!(full.objects, bare.objects, "the furniture is untouched");
}

#[test]
fn clutter_rests_asleep_and_still_on_in_or_beside_furniture_once_built() {
    let library = library();
    let (_, full) = alder();
    let mut built = full.build(&library).unwrap();
    assert_eq!(built.clutter.len(), full.clutter.len());
    assert!(built.clutter.iter().all(|&id| built.is_clutter(id)));
    assert!(!built.objects.iter().any(|&id| built.is_clutter(id)));
    let world = &built.world;
    let fixed: Vec<_> = built.objects.iter().chain(&built.floors).copied().collect();
    for (plan, &id) in full.clutter.iter().zip(&built.clutter) {
        assert!(
            world.bodies().is_sleeping(id),
            "{} starts asleep",
            plan.name
        );
        let held = fixed
            .iter()
            .any(|&f| world.relations().ontop(id, f) || world.relations().inside(id, f));
        let on_a_floor = built
            .floors
            .iter()
            .any(|&f| world.relations().onfloor(id, f));
        assert!(
            held || on_a_floor,
            "{} rests on, in or beside furniture",
            plan.name
        );
    }
    let before = world.bodies().motion_bits();
    for _ in 0..30 {
        built.world.step();
    }
    let world = &built.world;
    assert_eq!(
        world.bodies().motion_bits(),
        before,
        "nothing moved a bit in 30 steps"
    );
    assert!(
        built
            .clutter
            .iter()
            .all(|&id| world.bodies().is_sleeping(id))
    );
}

#[test]
fn a_scene_file_with_clutter_round_trips_and_rebuilds_exactly() {
    let library = library();
    let (_, full) = alder();
    let text = full.to_json();
    assert!(text.contains("\"clutter\""));
    let back = Scene::from_json(&text).unwrap();
    assert_eq!(back, *full);
    assert_eq!(back.to_json(), text);
    let (a, b) = (full.build(&library).unwrap(), back.build(&library).unwrap());
    assert_eq!(
        a.world.bodies().motion_bits(),
        b.world.bodies().motion_bits()
    );
}

#[test]
fn the_furniture_only_home_is_unchanged_and_its_file_has_no_clutter() {
    let (bare, full) = alder();
    assert!(bare.clutter.is_empty());
    assert_eq!(full.without_clutter(), *bare);
    assert!(!bare.to_json().contains("clutter"));
    // A file written before clutter existed still reads.
    assert_eq!(Scene::from_json(&bare.to_json()).unwrap(), *bare);
}

/// A change to a thing of clutter.
type Edit = fn(&mut ClutterPlan);

/// The home with its first thing of clutter changed by `edit`.
fn with_bad_first(edit: impl FnOnce(&mut ClutterPlan)) -> (String, Result<(), SceneError>) {
    let (_, full) = alder();
    let mut scene = full.clone();
    edit(&mut scene.clutter[0]);
    let name = scene.clutter[0].name.clone();
    (name, scene.build(&library()).map(|_| ()))
}

#[test]
fn bad_clutter_entries_are_errors_naming_the_thing() {
    let cases: [(&str, Edit); 6] = [
        ("unknown synset", |c| c.synset = "unicorn.n.01".into()),
        ("unknown archetype", |c| c.archetype = "unicorn.n.01".into()),
        ("zero size", |c| c.size = [0.1, 0.0, 0.1]),
        ("NaN size", |c| c.size[2] = f32::NAN),
        ("zero rotation", |c| c.rotation = [0.0; 4]),
        ("infinite position", |c| c.position[0] = f32::INFINITY),
    ];
    for (what, edit) in cases {
        let (name, result) = with_bad_first(edit);
        let message = result.expect_err(what).to_string();
        assert!(message.contains(&name), "{what}: {message}");
    }
    let bad = r#"{"name": "x", "seed": 1, "rooms": [], "walls": [], "objects": [],
        "clutter": [{"name": "clutter_book_0", "synset": "book.n.02"}]}"#;
    let message = Scene::from_json(bad).unwrap_err().to_string();
    assert!(message.contains("archetype"), "{message}");
}
