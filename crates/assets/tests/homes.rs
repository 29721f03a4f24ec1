//! The named homes: they generate, build, round-trip through JSON exactly, span the plan
//! families, and each official activity is covered by at least five of them.

use behavior_assets::{Library, NAMED_HOMES, Scene, generate};
use behavior_assets::{missing, requirements};
use behavior_core::RoomType;
use behavior_data::DataDir;
use behavior_sim::FloorRect;

#[test]
fn named_homes_generate_build_and_round_trip_exactly() {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let mut families = std::collections::BTreeSet::new();
    for (name, seed) in NAMED_HOMES {
        let scene = generate(name, seed, &library).unwrap();
        let kinds: Vec<&str> = scene.rooms.iter().map(|r| r.kind.name()).collect();
        for core in ["kitchen", "living_room", "bathroom"] {
            assert!(kinds.contains(&core), "{name} lacks a {core}");
        }
        families.insert(scene.family.expect("a named home has a family"));
        let text = scene.to_json();
        let back = Scene::from_json(&text).unwrap();
        assert_eq!(back, scene, "{name}");
        assert_eq!(back.to_json(), text, "{name}");
        let built = scene.build(&library).unwrap();
        assert_eq!(built.objects.len(), scene.objects.len());
        // Every object stands in the room it is filed under.
        for (plan, &id) in scene.objects.iter().zip(&built.objects) {
            let c = built.world.bodies().aabb(id).center();
            assert_eq!(
                scene.room_at(c.x, c.y),
                Some(plan.room),
                "{name}: {} is not in its room",
                plan.name
            );
        }
        assert_eq!(
            generate(name, seed, &library).unwrap(),
            scene,
            "{name}: same seed, same home"
        );
    }
    assert_eq!(
        families.len(),
        behavior_assets::Family::ALL.len(),
        "the named homes span the families: {families:?}"
    );
    assert_ne!(
        generate("x", 1, &library).unwrap().rooms,
        generate("x", 2, &library).unwrap().rooms
    );
}

#[test]
fn furniture_does_not_overlap_and_settles_in_place() {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let (name, seed) = NAMED_HOMES[0];
    let scene = generate(name, seed, &library).unwrap();
    let mut built = scene.build(&library).unwrap();
    let boxes: Vec<_> = built
        .objects
        .iter()
        .map(|&id| built.world.bodies().aabb(id))
        .collect();
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            let (a, b) = (&boxes[i], &boxes[j]);
            let overlap = (a.maxs.min(b.maxs) - a.mins.max(b.mins)).min_element();
            let stacked = scene.objects[i].synset == "microwave.n.02"
                || scene.objects[j].synset == "microwave.n.02";
            assert!(
                overlap <= 0.01 || stacked,
                "{} and {} overlap",
                scene.objects[i].name,
                scene.objects[j].name
            );
        }
    }
    let before: Vec<_> = built
        .objects
        .iter()
        .map(|&id| built.world.bodies().pose(id))
        .collect();
    assert!(built.world.settle(300), "the home comes to rest");
    for (k, &id) in built.objects.iter().enumerate() {
        let moved = (built.world.bodies().pose(id).translation - before[k].translation).length();
        assert!(
            moved < 0.05,
            "{} moved {moved} m while settling",
            scene.objects[k].name
        );
    }
}

#[test]
fn every_official_activity_is_covered_by_at_least_five_named_homes() {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let library = Library::new(&knowledge.taxonomy);
    let homes: Vec<Scene> = NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, &library).unwrap())
        .collect();
    let mut short = Vec::new();
    for name in data.activities().unwrap() {
        let (activity, _) = knowledge
            .load(&behavior_bddl::load::read_source(&data.problem_path(&name).unwrap()).unwrap())
            .unwrap();
        let needs = requirements(&activity);
        let covering = homes
            .iter()
            .filter(|h| missing(h, &needs, &knowledge.taxonomy).is_empty())
            .count();
        if covering < 5 {
            let why: Vec<String> = homes
                .iter()
                .map(|h| missing(h, &needs, &knowledge.taxonomy).join("; "))
                .collect();
            short.push(format!("{name}: {covering} homes; e.g. {:?}", &why[..2]));
        }
    }
    assert!(short.is_empty(), "{}", short.join("\n"));
}

/// The stretch of wall rectangles `a` and `b` share: whether it is vertical, its coordinate and
/// its span along it.
fn shared_edge(a: &FloorRect, b: &FloorRect) -> Option<(bool, f32, [f32; 2])> {
    for (vertical, across, along) in [(true, 0, 1), (false, 1, 0)] {
        let at = if a.max[across] == b.min[across] {
            a.max[across]
        } else if a.min[across] == b.max[across] {
            a.min[across]
        } else {
            continue;
        };
        let span = [
            a.min[along].max(b.min[along]),
            a.max[along].min(b.max[along]),
        ];
        // As long as the generator opens up between public rooms.
        if span[1] - span[0] >= 2.0 {
            return Some((vertical, at, span));
        }
    }
    None
}

#[test]
fn a_dining_room_opens_onto_the_living_room_with_a_table_across() {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let mut open = 0;
    // The named homes, and homes of free seeds of every family.
    let free = (1..=80).map(|seed| ("free", seed));
    for (name, seed) in NAMED_HOMES.into_iter().chain(free) {
        let scene = generate(name, seed, &library).unwrap();
        let living = scene
            .rooms
            .iter()
            .position(|r| r.kind == RoomType::LivingRoom)
            .unwrap();
        let l = &scene.rooms[living];
        // A rectangle of a dining room sharing a long wall with one of the living room's.
        let beside = scene
            .rooms
            .iter()
            .filter(|d| d.kind == RoomType::DiningRoom)
            .flat_map(|d| d.rects())
            .find_map(|d| Some((d, l.rects().find_map(|p| shared_edge(&p, &d))?)));
        let Some((d, (vertical, at, span))) = beside else {
            continue;
        };
        // Walk along the shared edge: no wall stands on it.
        for k in 1..20 {
            let t = span[0] + (span[1] - span[0]) * k as f32 / 20.0;
            let (x, y) = if vertical { (at, t) } else { (t, at) };
            assert!(
                !scene
                    .walls
                    .iter()
                    .any(|w| { w.min[0] <= x && x <= w.max[0] && w.min[1] <= y && y <= w.max[1] }),
                "{name} {seed}: a wall stands between the living and dining rooms at ({x}, {y})"
            );
        }
        // A living-room table reaches at least 30 cm over the dining room's floor.
        let built = scene.build(&library).unwrap();
        let across = usize::from(!vertical);
        let across_opening = scene.objects.iter().zip(&built.objects).any(|(o, &id)| {
            let b = built.world.bodies().aabb(id);
            let (lo, hi) = (b.mins.to_array(), b.maxs.to_array());
            let over = (hi[across].min(d.max[across]) - lo[across].max(d.min[across])).max(0.0);
            o.room == living && o.synset == "table.n.02" && over >= 0.3
        });
        assert!(
            across_opening,
            "{name} {seed}: no living-room table stands across the opening"
        );
        open += 1;
    }
    assert!(open >= 40, "only {open} homes have an open dining room");
}

#[test]
fn scene_errors_say_their_cause_once() {
    use std::error::Error;
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let json = Scene::from_json("{").unwrap_err();
    assert!(
        json.to_string()
            .starts_with("the scene file is not valid: ")
    );
    assert!(json.source().is_none(), "the cause is in the message only");
    let mut scene = generate("alder", 101, &library).unwrap();
    scene.objects[0].synset = "nonsense.n.01".into();
    let Err(asset) = scene.build(&library) else {
        panic!("an unknown synset builds");
    };
    let text = asset.to_string();
    assert!(text.contains("unknown synset `nonsense.n.01`"), "{text}");
    assert!(asset.source().is_none(), "{text}");
}

/// A cluttered home saved to bytes while a dropped object bounces among the clutter loads into a
/// world that continues bit-identically; prints the checkpoint's size and the save and load times.
#[test]
fn a_cluttered_home_saved_to_bytes_mid_motion_continues_bit_identically() {
    use std::time::Instant;
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
    let library = Library::new(&taxonomy);
    let (name, seed) = NAMED_HOMES[0];
    let scene =
        behavior_assets::clutter(&generate(name, seed, &library).unwrap(), &library, seed).unwrap();
    let mut built = scene.build(&library).unwrap();
    built.world.step();
    // Lift a piece of clutter: it falls back onto its support, into the others' contacts.
    let dropped = *built.clutter.first().expect("the home has clutter");
    let mut pose = built.world.bodies().pose(dropped);
    pose.translation.z += 0.2;
    built.world.bodies_mut().set_pose(dropped, pose).unwrap();
    for _ in 0..5 {
        built.world.step();
    }
    let mut original = built.world;
    let start = Instant::now();
    let bytes = original.to_bytes();
    let saved = start.elapsed();
    let start = Instant::now();
    let mut loaded = behavior_sim::World::from_bytes(&bytes).unwrap();
    let read = start.elapsed();
    eprintln!(
        "{name}: {} objects, {} bytes; to_bytes {saved:?}, from_bytes {read:?}",
        original.bodies().objects().len(),
        bytes.len()
    );
    for _ in 0..60 {
        original.step();
        loaded.step();
    }
    assert_eq!(
        loaded.bodies().motion_bits(),
        original.bodies().motion_bits()
    );
    assert_eq!(loaded.to_bytes(), original.to_bytes());
    assert_ne!(
        original.bodies().pose(dropped),
        pose,
        "the dropped object fell"
    );
}
