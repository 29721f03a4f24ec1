//! Sampling official activities in the named homes.

use behavior_assets::{Library, NAMED_HOMES, Scene, generate};
use behavior_assets::{missing, requirements};
use behavior_bddl::Knowledge;
use behavior_bddl::activity::InitLiteral;
use behavior_bddl::{Activity, PredicateOracle};
use behavior_data::DataDir;
use behavior_sampling::{
    LiteralKind, LoadError, SampleError, SavedInstance, Unmet, Unreachable, Unsatisfied,
    instantiate,
};

#[path = "../../bddl/tests/common/mod.rs"]
mod naive;

fn setup() -> (DataDir, Knowledge) {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    (data, knowledge)
}

fn activity(data: &DataDir, knowledge: &Knowledge, name: &str) -> Activity {
    knowledge
        .load(&behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap())
        .unwrap()
        .0
}

fn covering_home(activity: &Activity, library: &Library, knowledge: &Knowledge) -> Scene {
    let needs = requirements(activity);
    NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, library).unwrap())
        .find(|h| missing(h, &needs, &knowledge.taxonomy).is_empty())
        .expect("a covering home")
}

/// The first init literal that the facts contradict (a positive one missing, a negative one
/// present), read off the facts alone.
fn init_unmet_in_facts(activity: &Activity, facts: &[behavior_sampling::Fact]) -> Option<String> {
    let listed: std::collections::BTreeSet<Vec<String>> = facts
        .iter()
        .map(|f| {
            let mut v = vec![f.predicate.name().to_string()];
            v.extend(f.args.iter().cloned());
            v
        })
        .collect();
    naive::init_as_facts(activity)
        .into_iter()
        .find(|(fact, positive)| listed.contains(fact) != *positive)
        .map(|(fact, positive)| format!("{fact:?} (positive: {positive})"))
}

/// Re-checks every positive and negative init literal through the BDDL oracle, independently of
/// the sampler's own check.
fn all_init_literals_hold(activity: &Activity, instance: &behavior_sampling::Instance) -> bool {
    let bound = instance.bound();
    let oracle = instance.oracle(&bound);
    activity.init.iter().all(|l| match l {
        InitLiteral::Atom(l) => oracle.holds(l.atom) == l.positive,
        InitLiteral::InRoom {
            instance: i,
            room,
            positive,
        } => {
            (instance
                .world
                .relations()
                .room_of(instance.bindings[i.0 as usize])
                == Some(*room))
                == *positive
        }
    })
}

#[test]
fn packing_lunches_is_sampled_with_every_init_literal_true_and_saves_and_loads() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "packing_lunches");
    let home = covering_home(&activity, &library, &knowledge);
    let instance = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(all_init_literals_hold(&activity, &instance));
    // Saved and loaded, the instance still satisfies its initial condition.
    let saved = instance.save();
    let text = saved.to_json();
    let back = SavedInstance::from_json(&text).unwrap();
    assert_eq!(back, saved);
    let loaded = back
        .load(&activity, &library)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(all_init_literals_hold(&activity, &loaded));
    for (&a, &b) in instance.bindings.iter().zip(&loaded.bindings) {
        let (pa, pb) = (
            instance.world.bodies().pose(a),
            loaded.world.bodies().pose(b),
        );
        assert!((pa.translation - pb.translation).length() < 1e-5);
    }
}

#[test]
fn the_same_seed_gives_the_same_instance_and_another_seed_another() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "putting_away_toys");
    let home = covering_home(&activity, &library, &knowledge);
    let sample = |seed| instantiate(&activity, &home, seed, &library, &knowledge.taxonomy).unwrap();
    let (a, b, c) = (sample(7), sample(7), sample(8));
    assert_eq!(
        a.world.bodies().motion_bits(),
        b.world.bodies().motion_bits()
    );
    assert_eq!(a.created, b.created);
    // Another seed puts the created objects elsewhere...
    let position = |s: &behavior_sampling::Instance, name: &str| {
        let i = activity
            .instances
            .iter()
            .position(|i| i.name == name)
            .unwrap();
        s.world.bodies().pose(s.bindings[i]).translation
    };
    let moved = a
        .created
        .iter()
        .filter(|o| (position(&a, &o.instance) - position(&c, &o.instance)).length() > 0.01)
        .count();
    assert!(moved * 2 > a.created.len(), "only {moved} objects moved");
    // ...and, over a few seeds, makes them from other archetypes and variants.
    let looks = |s: &behavior_sampling::Instance| {
        s.created
            .iter()
            .map(|o| (o.archetype.clone(), o.variant))
            .collect::<Vec<_>>()
    };
    let mut seen: Vec<_> = (0..6).map(|seed| looks(&sample(seed))).collect();
    seen.sort();
    seen.dedup();
    assert!(
        seen.len() >= 5,
        "{} distinct looks over 6 seeds",
        seen.len()
    );
    let variants = |k: usize| {
        let mut v: Vec<u32> = seen.iter().map(|look| look[k].1).collect();
        v.sort();
        v.dedup();
        v.len()
    };
    assert!(
        (0..a.created.len()).any(|k| variants(k) > 1),
        "no object ever changes variant"
    );
}

#[test]
fn a_home_without_the_rooms_an_activity_needs_is_a_clear_error() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "cleaning_garage");
    let needs = requirements(&activity);
    let home = NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, &library).unwrap())
        .find(|h| !missing(h, &needs, &knowledge.taxonomy).is_empty())
        .expect("a home without a garage");
    match instantiate(&activity, &home, 0, &library, &knowledge.taxonomy) {
        Err(e @ SampleError::NoFurniture { .. }) => {
            assert!(e.to_string().contains("has no garage"), "{e}")
        }
        Err(e) => panic!("unexpected error: {e}"),
        Ok(_) => panic!("sampled without a garage"),
    }
}

#[test]
fn every_activity_samples_in_its_first_covering_home_and_reloads_with_its_init_true() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let homes: Vec<Scene> = NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, &library).unwrap())
        .collect();
    let mut failures = Vec::new();
    let names = data.activities().unwrap();
    for name in &names {
        let activity = activity(&data, &knowledge, name);
        let needs = requirements(&activity);
        let home = homes
            .iter()
            .find(|h| missing(h, &needs, &knowledge.taxonomy).is_empty())
            .unwrap();
        match instantiate(&activity, home, 0, &library, &knowledge.taxonomy) {
            Ok(instance) => {
                assert!(all_init_literals_hold(&activity, &instance), "{name}");
                // Saved to JSON and loaded into a fresh world, every literal is re-evaluated.
                let loaded = SavedInstance::from_json(&instance.save().to_json())
                    .unwrap()
                    .load(&activity, &library)
                    .unwrap_or_else(|e| panic!("{name}: {e}"));
                assert!(
                    all_init_literals_hold(&activity, &loaded),
                    "{name} reloaded"
                );
                // The logical state is the same before saving and after loading, and every
                // init literal can be read off it.
                let facts = instance.facts(&activity);
                assert_eq!(
                    facts,
                    loaded.facts(&activity),
                    "{name}: facts after loading"
                );
                if let Some(literal) = init_unmet_in_facts(&activity, &facts) {
                    panic!("{name}: {literal} does not follow from the facts");
                }
            }
            Err(e) => failures.push(format!("{name} in {}: {e}", home.name)),
        }
    }
    eprintln!(
        "{} of {} failed:\n{}",
        failures.len(),
        names.len(),
        failures.join("\n")
    );
    assert!(failures.len() <= 3, "{}", failures.join("\n"));
}

#[test]
fn an_unreachable_goal_is_reported_as_infeasible() {
    let (_, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    // The goal wants a kitchen table inside a small bin.
    let text = "(define (problem tidy_0) (:domain igibson)
      (:objects bin.n.01_1 - bin.n.01 table.n.02_1 - table.n.02 floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
      (:init (onfloor bin.n.01_1 floor.n.01_1) (inroom table.n.02_1 kitchen) (inroom floor.n.01_1 kitchen) (onfloor agent.n.01_1 floor.n.01_1))
      (:goal (inside ?table.n.02_1 ?bin.n.01_1)))";
    let (activity, _) = knowledge
        .load(&behavior_bddl::Source::new("tidy.bddl", text))
        .unwrap();
    let home = generate(NAMED_HOMES[0].0, NAMED_HOMES[0].1, &library).unwrap();
    match instantiate(&activity, &home, 0, &library, &knowledge.taxonomy) {
        Err(
            ref e @ SampleError::Infeasible {
                ref literals,
                why: Unreachable::DoesNotFit { object, container },
            },
        ) => {
            assert!(e.to_string().starts_with("no goal option can be reached in this home: (inside table.n.02_1 bin.n.01_1): its box"), "{e}");
            assert_eq!(literals.to_string(), "(inside table.n.02_1 bin.n.01_1)");
            assert!(object[2] > container[2]);
        }
        Err(e) => panic!("unexpected error: {e}"),
        Ok(_) => panic!("an impossible goal was accepted"),
    }
}

#[test]
fn a_dusty_floor_survives_saving_and_loading() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "cleaning_floors");
    let home = covering_home(&activity, &library, &knowledge);
    let instance = instantiate(&activity, &home, 2, &library, &knowledge.taxonomy)
        .unwrap_or_else(|e| panic!("{e}"));
    let saved = instance.save();
    assert!(
        saved
            .objects
            .iter()
            .any(|o| o.name.starts_with("floor_") && !o.states.is_empty())
    );
    let loaded = SavedInstance::from_json(&saved.to_json())
        .unwrap()
        .load(&activity, &library)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(all_init_literals_hold(&activity, &loaded));
}

#[test]
fn a_saved_instance_holds_the_whole_state_of_every_object() {
    // Temperatures, soaked, switches, particles and joints come back as they were sampled, not
    // re-set from the unary predicates.
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    for name in ["cleaning_stove", "thawing_frozen_food"] {
        let activity = activity(&data, &knowledge, name);
        let home = covering_home(&activity, &library, &knowledge);
        let mut instance = instantiate(&activity, &home, 1, &library, &knowledge.taxonomy)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        // A second on, frozen food has warmed: a temperature no setter would give.
        for _ in 0..30 {
            instance.world.step();
        }
        let loaded = SavedInstance::from_json(&instance.save().to_json())
            .unwrap()
            .load(&activity, &library)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let (a, b) = (&instance.world, &loaded.world);
        assert_eq!(a.bodies().objects().len(), b.bodies().objects().len());
        let mut particles = 0;
        for (id, object) in a.bodies().objects() {
            let other = b.bodies().object_named(&object.name).unwrap();
            assert_eq!(
                a.object_state(id),
                b.object_state(other),
                "{name}: {}",
                object.name
            );
            let bits = |w: &behavior_sim::World, id| {
                let p = w.bodies().pose(id);
                (
                    p.translation.to_array().map(f32::to_bits),
                    p.rotation.to_array().map(f32::to_bits),
                )
            };
            if object.is_present() {
                assert_eq!(bits(a, id), bits(b, other), "{name}: {} pose", object.name);
            }
            for k in 0..object.links.len() {
                let (qa, qb) = (a.joints().position(id, k), b.joints().position(other, k));
                assert!(
                    (qa - qb).abs() < 1e-4,
                    "{name}: {} joint {k}: {qa} vs {qb}",
                    object.name
                );
            }
            particles +=
                a.object_state(id).dust.particles.len() + a.object_state(id).stain.particles.len();
        }
        let warmed = a
            .bodies()
            .objects()
            .filter(|(id, _)| {
                let t = a.object_state(*id).temperature;
                t != 23.0 && t != behavior_sim::DEFAULT_FREEZE_TEMPERATURE - 30.0
            })
            .count();
        assert!(
            particles + warmed > 0,
            "{name}: a state beyond the pose was saved"
        );
    }
}

#[test]
fn a_saved_instance_that_contradicts_itself_is_refused() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "cleaning_stove");
    let home = covering_home(&activity, &library, &knowledge);
    let instance = instantiate(&activity, &home, 1, &library, &knowledge.taxonomy).unwrap();
    let mut saved = instance.save();
    let stove = saved
        .objects
        .iter_mut()
        .find(|o| o.states.iter().any(|s| s == "dusty" || s == "stained"))
        .unwrap();
    // Listed dirty, but with every particle gone.
    stove.state.dust.particles.clear();
    stove.state.stain.particles.clear();
    let name = stove.name.clone();
    let err = SavedInstance::from_json(&saved.to_json())
        .unwrap()
        .load(&activity, &library)
        .err()
        .expect("a contradiction is refused");
    let message = err.to_string();
    assert!(
        message.contains(&name) && message.contains("saved state"),
        "{message}"
    );
}

/// The table a living room shares with its open dining room (see `behavior_assets::generate`).
fn table_across_the_opening(home: &Scene) -> String {
    let dining = home
        .rooms
        .iter()
        .find(|r| r.kind == behavior_core::RoomType::DiningRoom)
        .expect("a dining room");
    home.objects
        .iter()
        .find(|o| {
            let reach = o.size[0] / 2.0;
            home.rooms[o.room].kind == behavior_core::RoomType::LivingRoom
                && o.synset == "table.n.02"
                && o.position[0] + reach > dining.min[0]
                && o.position[0] - reach < dining.max[0]
        })
        .expect("a table across the opening")
        .name
        .clone()
}

#[test]
fn collect_misplaced_items_puts_the_shoe_under_the_living_room_table_on_the_dining_floor() {
    // Its `:init` asks for the shoe under a living-room table and on the dining room's floor:
    // only the table standing across the open plan's opening can host that, and candidate
    // filtering binds it on every seed, at the first attempt.
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "collect_misplaced_items");
    let needs = requirements(&activity);
    let homes: Vec<Scene> = NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, &library).unwrap())
        .filter(|h| missing(h, &needs, &knowledge.taxonomy).is_empty())
        .take(3)
        .collect();
    assert_eq!(homes.len(), 3);
    let table = activity
        .instances
        .iter()
        .position(|i| i.name == "table.n.02_1")
        .unwrap();
    for home in &homes {
        let across = table_across_the_opening(home);
        for seed in 0..4 {
            let instance = instantiate(&activity, home, seed, &library, &knowledge.taxonomy)
                .unwrap_or_else(|e| panic!("{} seed {seed}: {e}", home.name));
            assert_eq!(instance.attempt, 0, "{} seed {seed}", home.name);
            assert_eq!(
                instance
                    .world
                    .bodies()
                    .object(instance.bindings[table])
                    .name,
                across,
                "{} seed {seed}",
                home.name
            );
            assert!(all_init_literals_hold(&activity, &instance));
            let loaded = SavedInstance::from_json(&instance.save().to_json())
                .unwrap()
                .load(&activity, &library)
                .unwrap_or_else(|e| panic!("{e}"));
            assert!(all_init_literals_hold(&activity, &loaded));
        }
    }
}

#[test]
fn furniture_that_cannot_host_its_init_literals_is_not_bound() {
    // Without the table across the opening, no living-room table can have the shoe under it and
    // on the dining room's floor: the error names both literals and why.
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "collect_misplaced_items");
    let mut home = covering_home(&activity, &library, &knowledge);
    let across = table_across_the_opening(&home);
    home.objects.retain(|o| o.name != across);
    match instantiate(&activity, &home, 0, &library, &knowledge.taxonomy) {
        Err(
            ref e @ SampleError::Literal {
                ref literals,
                why: Unsatisfied::NotHosted(ref ruled_out),
            },
        ) => {
            assert!(
                e.to_string().starts_with(
                    "(under gym_shoe.n.01_1 table.n.02_1) and (onfloor gym_shoe.n.01_1 floor.n.01_2) \
                     could not be satisfied: 0 of the 1 table.n.02 in"
                ) && e.to_string().contains("the relations' areas do not overlap"),
                "{e}"
            );
            // The same, as values: the literals as the definition holds them, the world's error.
            let under = activity.instance_named("gym_shoe.n.01_1").unwrap();
            assert_eq!(literals.0.len(), 2);
            assert!(matches!(
                literals.0[0].literal,
                InitLiteral::Atom(l) if l.atom.subject == under
                    && l.atom.predicate == behavior_bddl::Predicate::Under
            ));
            assert_eq!((ruled_out.kept, ruled_out.candidates), (0, 1));
            assert_eq!(ruled_out.cause.object, "gym_shoe.n.01_1");
        }
        Err(e) => panic!("unexpected error: {e}"),
        Ok(_) => panic!("sampled without a table that can host the shoe"),
    }
}

#[test]
fn nextto_and_touching_in_an_init_are_sampled_too() {
    // No official definition uses `nextto` or `touching` in its `:init`; a researcher's own may,
    // both ways round (the books touch each other).
    let (_, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let text = "(define (problem side_by_side_0) (:domain igibson)
      (:objects apple.n.01_1 - apple.n.01 bowl.n.01_1 - bowl.n.01 bucket.n.01_1 - bucket.n.01
                book.n.02_1 book.n.02_2 - book.n.02
                table.n.02_1 - table.n.02 floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
      (:init (ontop bowl.n.01_1 table.n.02_1) (ontop apple.n.01_1 table.n.02_1)
             (nextto apple.n.01_1 bowl.n.01_1) (nextto bucket.n.01_1 table.n.02_1)
             (ontop book.n.02_1 table.n.02_1) (ontop book.n.02_2 table.n.02_1)
             (touching book.n.02_1 book.n.02_2) (touching book.n.02_2 book.n.02_1)
             (inroom table.n.02_1 kitchen) (inroom floor.n.01_1 kitchen)
             (onfloor agent.n.01_1 floor.n.01_1))
      (:goal (inside ?apple.n.01_1 ?bowl.n.01_1)))";
    let (activity, _) = knowledge
        .load(&behavior_bddl::Source::new("side_by_side.bddl", text))
        .unwrap();
    let home = generate(NAMED_HOMES[0].0, NAMED_HOMES[0].1, &library).unwrap();
    for seed in 0..3 {
        let instance = instantiate(&activity, &home, seed, &library, &knowledge.taxonomy)
            .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        assert!(all_init_literals_hold(&activity, &instance), "seed {seed}");
    }
}

#[test]
fn a_goal_that_fits_by_size_but_cannot_be_placed_is_infeasible() {
    // The apple is to be in the bowl, which stays in the fridge, and next to the kitchen table:
    // every size fits, but no pose satisfies both.
    let (_, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let text = "(define (problem fridge_and_table_0) (:domain igibson)
      (:objects apple.n.01_1 - apple.n.01 bowl.n.01_1 - bowl.n.01
                electric_refrigerator.n.01_1 - electric_refrigerator.n.01 table.n.02_1 - table.n.02
                floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
      (:init (inside bowl.n.01_1 electric_refrigerator.n.01_1) (ontop apple.n.01_1 table.n.02_1)
             (inroom electric_refrigerator.n.01_1 kitchen) (inroom table.n.02_1 kitchen)
             (inroom floor.n.01_1 kitchen) (onfloor agent.n.01_1 floor.n.01_1))
      (:goal (and (inside ?apple.n.01_1 ?bowl.n.01_1) (nextto ?apple.n.01_1 ?table.n.02_1))))";
    let (activity, _) = knowledge
        .load(&behavior_bddl::Source::new("fridge_and_table.bddl", text))
        .unwrap();
    let home = generate(NAMED_HOMES[0].0, NAMED_HOMES[0].1, &library).unwrap();
    match instantiate(&activity, &home, 0, &library, &knowledge.taxonomy) {
        Err(
            ref e @ SampleError::Infeasible {
                why: Unreachable::Placement(ref placement),
                ..
            },
        ) => {
            assert!(
                e.to_string().starts_with(
                    "no goal option can be reached in this home: (inside apple.n.01_1 bowl.n.01_1) \
                     and (nextto apple.n.01_1 table.n.02_1): could not place apple.n.01_1"
                ),
                "{e}"
            );
            assert_eq!(placement.object, "apple.n.01_1");
        }
        Err(e) => panic!("unexpected error: {e}"),
        Ok(_) => panic!("an unreachable goal was accepted"),
    }
}

#[test]
fn goals_relating_objects_of_one_kind_are_feasible() {
    // `sorting_mail` asks every envelope to touch one of the first four: its smallest options
    // have an envelope touch itself, which no world allows; `thawing_frozen_food` puts a date
    // next to a fish that is itself next to the sink.
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    for name in ["sorting_mail", "thawing_frozen_food", "laying_wood_floors"] {
        let activity = activity(&data, &knowledge, name);
        let home = covering_home(&activity, &library, &knowledge);
        let instance = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(all_init_literals_hold(&activity, &instance), "{name}");
    }
}

#[test]
fn the_init_check_reports_each_literal_and_which_fail() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let activity = activity(&data, &knowledge, "packing_lunches");
    let home = covering_home(&activity, &library, &knowledge);
    let mut instance = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy)
        .unwrap_or_else(|e| panic!("{e}"));
    let check = instance.check_init(&activity);
    assert_eq!(check.literals.len(), activity.init.len());
    assert!(check.all_hold());
    let rooms = activity
        .init
        .iter()
        .filter(|l| matches!(l, InitLiteral::InRoom { .. }))
        .count();
    assert_eq!(check.count(LiteralKind::InRoom), rooms);
    assert_eq!(
        check.count(LiteralKind::Relation) + check.count(LiteralKind::UnaryState) + rooms,
        activity.init.len()
    );
    // Take the apple off the counter: its one literal fails, and the independent check agrees.
    let apple = activity.instance_named("apple.n.01_1").unwrap();
    let id = instance.bindings[apple.0 as usize];
    let far =
        rapier3d::math::Pose::from_translation(rapier3d::math::Vector::new(500.0, 500.0, 3.0));
    instance.world.bodies_mut().set_pose(id, far).unwrap();
    let check = instance.check_init(&activity);
    let failing: Vec<String> = check.failing().map(|l| l.literal.to_string()).collect();
    assert_eq!(failing, ["(ontop apple.n.01_1 countertop.n.01_1)"]);
    assert_eq!(check.holding(), activity.init.len() - 1);
    assert_eq!(check.failing().next().unwrap().unmet, Some(Unmet::False));
    assert!(!all_init_literals_hold(&activity, &instance));
}

#[test]
fn loading_a_wrong_or_broken_file_says_what_is_wrong() {
    let (data, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let other = activity(&data, &knowledge, "putting_away_toys");
    let activity = activity(&data, &knowledge, "packing_lunches");
    let home = covering_home(&activity, &library, &knowledge);
    let saved = instantiate(&activity, &home, 0, &library, &knowledge.taxonomy)
        .unwrap()
        .save();
    let load = |s: &SavedInstance, a: &Activity| s.load(a, &library).err().map(|e| e.to_string());

    assert!(matches!(
        SavedInstance::from_json("{\"activity\": 3}"),
        Err(LoadError::Json(_))
    ));
    assert_eq!(
        load(&saved, &other).unwrap(),
        format!(
            "the file is an instance of packing_lunches_0, not of {}",
            other.name
        )
    );
    let mut renamed = saved.clone();
    renamed.objects[0].name = "no_such_object".into();
    assert!(matches!(
        renamed.load(&activity, &library),
        Err(LoadError::UnknownObject { ref name }) if name == "no_such_object"
    ));
    let mut rebound = saved.clone();
    rebound.bindings[0] = "no_such_object".into();
    assert_eq!(
        load(&rebound, &activity).unwrap(),
        format!(
            "{} is bound to `no_such_object`, which is not in the rebuilt world",
            activity.instances[0].name
        )
    );
    let mut short = saved.clone();
    short.bindings.pop();
    assert!(matches!(
        short.load(&activity, &library),
        Err(LoadError::BindingCount {
            bindings: 18,
            instances: 19,
            ..
        })
    ));
    // An apple saved away from the counter breaks the initial condition.
    let mut moved = saved.clone();
    let apple = moved
        .objects
        .iter_mut()
        .find(|o| o.name == "apple.n.01_1")
        .unwrap();
    apple.position = [500.0, 500.0, 3.0];
    match moved.load(&activity, &library) {
        Err(LoadError::InitBroken { literal, why }) => {
            assert_eq!(
                literal.to_string(),
                "(ontop apple.n.01_1 countertop.n.01_1)"
            );
            assert_eq!(why, Unmet::False);
        }
        Err(e) => panic!("unexpected error: {e}"),
        Ok(_) => panic!("a broken instance loaded"),
    }
}

#[test]
fn orientations_and_openings_differ_over_seeds() {
    // The paper's diversity experiment assumes instances differ in orientation, not just in
    // position; an `open` init opens a random amount.
    let (_, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let text = "(define (problem turned_0) (:domain igibson)
      (:objects book.n.02_1 book.n.02_2 - book.n.02 bottle.n.01_1 - bottle.n.01
                cabinet.n.01_1 - cabinet.n.01 countertop.n.01_1 - countertop.n.01
                floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
      (:init (ontop book.n.02_1 countertop.n.01_1) (ontop book.n.02_2 countertop.n.01_1)
             (ontop bottle.n.01_1 countertop.n.01_1) (open cabinet.n.01_1)
             (inroom cabinet.n.01_1 kitchen) (inroom countertop.n.01_1 kitchen)
             (inroom floor.n.01_1 kitchen) (onfloor agent.n.01_1 floor.n.01_1))
      (:goal (not (open ?cabinet.n.01_1))))";
    let (activity, _) = knowledge
        .load(&behavior_bddl::Source::new("turned.bddl", text))
        .unwrap();
    let home = covering_home(&activity, &library, &knowledge);
    let samples: Vec<_> = (0..4)
        .map(|seed| instantiate(&activity, &home, seed, &library, &knowledge.taxonomy).unwrap())
        .collect();
    let rotation =
        |s: &behavior_sampling::Instance, k: usize| s.world.bodies().pose(s.bindings[k]).rotation;
    for k in 0..3 {
        let name = &activity.instances[k].name;
        let angles: Vec<f32> = samples
            .iter()
            .map(|s| rotation(s, k).angle_between(rotation(&samples[0], k)))
            .collect();
        assert!(
            angles[1..].iter().all(|&a| a > 0.01),
            "{name} turns the same way for two seeds: {angles:?}"
        );
    }
    let cabinet = 3;
    let openings: Vec<Vec<f32>> = samples
        .iter()
        .map(|s| {
            let id = s.bindings[cabinet];
            (0..s.world.bodies().object(id).links.len())
                .map(|l| s.world.joints().position(id, l))
                .collect()
        })
        .collect();
    for (s, joints) in samples.iter().zip(&openings) {
        assert!(
            s.world
                .state(s.bindings[cabinet], behavior_bddl::Predicate::Open)
        );
        assert!(!joints.is_empty());
    }
    let mut distinct = openings.clone();
    distinct.sort_by(|a, b| a.partial_cmp(b).unwrap());
    distinct.dedup();
    assert!(distinct.len() >= 3, "openings over 4 seeds: {openings:?}");
}

#[test]
fn a_sliced_tomato_can_be_asked_for_in_a_bowl() {
    // Starting sliced, the tomato's halves are placed as one piece, by the sampler and by the goal
    // check alike.
    let (_, knowledge) = setup();
    let library = Library::new(&knowledge.taxonomy);
    let text = "(define (problem sliced_0) (:domain igibson)
      (:objects tomato.n.01_1 - tomato.n.01 bowl.n.01_1 - bowl.n.01
                countertop.n.01_1 - countertop.n.01 floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
      (:init (ontop tomato.n.01_1 countertop.n.01_1) (sliced tomato.n.01_1)
             (ontop bowl.n.01_1 countertop.n.01_1)
             (inroom countertop.n.01_1 kitchen) (inroom floor.n.01_1 kitchen)
             (onfloor agent.n.01_1 floor.n.01_1))
      (:goal (inside ?tomato.n.01_1 ?bowl.n.01_1)))";
    let (activity, _) = knowledge
        .load(&behavior_bddl::Source::new("sliced.bddl", text))
        .unwrap();
    let home = covering_home(&activity, &library, &knowledge);
    for seed in 0..3 {
        let instance = instantiate(&activity, &home, seed, &library, &knowledge.taxonomy)
            .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let tomato = instance.bindings[0];
        assert!(
            instance
                .world
                .state(tomato, behavior_bddl::Predicate::Sliced)
        );
        assert!(all_init_literals_hold(&activity, &instance));
    }
}
