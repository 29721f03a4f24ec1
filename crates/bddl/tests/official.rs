//! Tests on the 100 official BEHAVIOR-100 definitions (fetched from PyPI on first use, see
//! `behavior_data`), compared with the reference implementation's recorded outputs in
//! `tests/fixtures/bddl-1.0.1-conformance.json` (made by `tests/fixtures/conformance.py` from bddl
//! 1.0.1 on PyPI).

mod common;

use behavior_bddl::load::{Knowledge, read_source};
use behavior_bddl::options::options_with;
use behavior_bddl::{Activity, Counting, FactSet, GroundGoal, Optimizer, Ratio, Source};
use behavior_data::DataDir;
use serde_json::Value;
use std::path::PathBuf;

fn data() -> DataDir {
    DataDir::locate(None, |m| eprintln!("{m}")).expect("official data")
}

fn all_activities() -> (DataDir, Knowledge, Vec<(String, Source, Activity)>) {
    let data = data();
    let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let activities = data
        .activities()
        .unwrap()
        .into_iter()
        .map(|name| {
            let source = read_source(&data.problem_path(&name).unwrap()).unwrap();
            let (activity, _) = knowledge.load(&source).unwrap_or_else(|e| panic!("{e}"));
            (name, source, activity)
        })
        .collect();
    (data, knowledge, activities)
}

fn conformance() -> Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/bddl-1.0.1-conformance.json");
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("the conformance file {} is needed: {e}", path.display()));
    serde_json::from_str(&text).unwrap()
}

#[test]
fn all_100_official_definitions_parse_and_check_without_errors_or_warnings() {
    let data = data();
    let knowledge = Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let names = data.activities().unwrap();
    assert_eq!(names.len(), 100);
    for name in names {
        let source = read_source(&data.problem_path(&name).unwrap()).unwrap();
        let (_, warnings) = knowledge.load(&source).unwrap_or_else(|e| panic!("{e}"));
        // A warning here would be a finding about the official data; there are none.
        assert!(warnings.0.is_empty(), "{}", warnings.render(&source));
    }
}

/// Under the reference's counting (a repeated literal counts each time) our volume and Q equal
/// the recorded ones; set counting differs on two activities (see the tests below).
#[test]
fn volume_q_and_success_at_init_match_the_reference_on_all_100() {
    let reference = conformance();
    let (_, _, activities) = all_activities();
    for (name, _, activity) in &activities {
        let expected = &reference["activities"][name];
        let goal = GroundGoal::new(activity);
        let optimizer = Optimizer::with_counting(&goal, Counting::Reference);
        let state: FactSet = activity.initial_facts().into_iter().collect();
        assert_eq!(
            optimizer.volume(),
            expected["volume"].as_u64(),
            "{name}: volume"
        );
        let q = optimizer.q(&state).unwrap().to_f64();
        assert!(
            (q - expected["q_at_init"].as_f64().unwrap()).abs() < 1e-12,
            "{name}: Q {q}"
        );
        assert_eq!(
            goal.holds(&state),
            expected["success_at_init"].as_bool().unwrap(),
            "{name}"
        );
        let satisfied: Vec<bool> = goal.conjuncts_hold(&state).collect();
        let listed: Vec<bool> = (0..satisfied.len())
            .map(|i| {
                expected["goal_status_at_init"]["satisfied"]
                    .as_array()
                    .unwrap()
                    .contains(&Value::from(i))
            })
            .collect();
        assert_eq!(
            satisfied, listed,
            "{name}: top-level conditions satisfied at init"
        );
    }
}

/// Volume, and Q at init, of one official activity under a counting.
fn at_init(name: &str, counting: Counting) -> (Option<u64>, Option<Ratio>) {
    let (_, _, activities) = all_activities();
    let (_, _, activity) = activities.iter().find(|(n, ..)| n == name).unwrap();
    let goal = GroundGoal::new(activity);
    let optimizer = Optimizer::with_counting(&goal, counting);
    let state: FactSet = activity.initial_facts().into_iter().collect();
    (optimizer.volume(), optimizer.q(&state))
}

/// `(not (inside cup.n.01_1 ?cabinet))` is written once per bowl inside `forall bowl`, and
/// `(not (inside bowl.n.01_1 ?cabinet))` once per cup: as sets an option has 2 + 3 + 3 literals.
/// Both options (bowls in one cabinet, cups in the other) have 3 true at init — e.g. bowls in
/// cabinet 1, cups in cabinet 2: cup 1 is not in cabinet 1, cup 1 is in cabinet 2, bowl 1 is not
/// in cabinet 2. The reference counts each repeated negation twice: 5 of 10.
#[test]
fn cleaning_kitchen_cupboard_counts_a_literal_written_per_bowl_once() {
    let (volume, q) = at_init("cleaning_kitchen_cupboard", Counting::Set);
    assert_eq!(volume, Some(8));
    assert_eq!(q, Some(Ratio::new(3, 8)));
    assert_eq!(q.unwrap().to_f64(), 0.375);
    let (volume, q) = at_init("cleaning_kitchen_cupboard", Counting::Reference);
    assert_eq!(volume, Some(10));
    assert_eq!(q, Some(Ratio::new(1, 2)));
}

/// `(not (stained ?floor.n.01_1))` is written twice among the top-level conjuncts.
#[test]
fn cleaning_up_after_a_meal_counts_a_conjunct_written_twice_once() {
    let (volume, q) = at_init("cleaning_up_after_a_meal", Counting::Set);
    assert_eq!(volume, Some(14));
    assert_eq!(q, Some(Ratio::new(1, 14)));
    let (volume, q) = at_init("cleaning_up_after_a_meal", Counting::Reference);
    assert_eq!(volume, Some(15));
    assert_eq!(q, Some(Ratio::new(2, 15)));
}

/// Volume and Q of the fast path against the naive enumeration, both countings, on the initial
/// state and 20 random states, for every activity small enough to enumerate.
#[test]
fn every_official_goal_agrees_with_enumeration_at_init_and_on_random_states() {
    let (_, _, activities) = all_activities();
    let mut compared = 0;
    for (name, _, activity) in &activities {
        let formula = activity.goal_formula();
        let Some(all) = common::dnf(activity, &formula, &mut Vec::new(), true) else {
            continue; // more options than the naive enumeration can hold
        };
        compared += 1;
        let goal = GroundGoal::new(activity);
        let init: FactSet = activity.initial_facts().into_iter().collect();
        let at_init = move |atom| behavior_bddl::PredicateOracle::holds(&init, atom);
        let mut states: Vec<Box<dyn Fn(behavior_bddl::Atom) -> bool>> = vec![Box::new(at_init)];
        states.extend((0..20).map(|seed| Box::new(common::random_truth(seed)) as Box<_>));
        for counting in [Counting::Set, Counting::Reference] {
            let optimizer = Optimizer::with_counting(&goal, counting);
            for (k, truth) in states.iter().enumerate() {
                let (volume, q) = common::volume_and_q(&all, truth, counting);
                let context = format!("{name}, {counting:?}, state {k}");
                assert_eq!(optimizer.volume().map(|v| v as usize), volume, "{context}");
                let ours = optimizer.q(truth).map(|r| (r.num, r.den));
                let expected = q.map(|(s, n)| {
                    let r = Ratio::new(s, n);
                    (r.num, r.den)
                });
                assert_eq!(ours, expected, "{context}");
                let direct = common::holds(activity, &formula, &mut Vec::new(), truth);
                assert_eq!(goal.holds(truth), direct, "{context}");
            }
        }
    }
    assert!(
        compared >= 90,
        "only {compared} activities were small enough to enumerate"
    );
}

#[test]
fn options_are_listed_smallest_first_and_start_at_the_volume() {
    let (_, _, activities) = all_activities();
    for (name, _, activity) in &activities {
        let goal = GroundGoal::new(activity);
        for counting in [Counting::Set, Counting::Reference] {
            let volume = Optimizer::with_counting(&goal, counting).volume().unwrap() as usize;
            let first: Vec<_> = options_with(&goal, counting).take(50).collect();
            assert_eq!(first[0].len(), volume, "{name}, {counting:?}");
            assert!(
                first.windows(2).all(|w| w[0].len() <= w[1].len()),
                "{name}, {counting:?}"
            );
        }
    }
}

/// Every truncation (at a stride) and many seeded byte mutations of every official file are
/// checked without a panic; each either loads or yields located errors.
#[test]
fn no_truncation_or_mutation_of_an_official_file_panics() {
    let (_, knowledge, activities) = all_activities();
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    let alphabet = b"()?-;_ \n0123456789abcdefnotandorforallexistsforn:\xff\xc3";
    let mut rejected = 0;
    for (name, source, _) in &activities {
        let bytes = source.text.as_bytes();
        let mut variants: Vec<Vec<u8>> = (0..bytes.len())
            .step_by(13)
            .map(|cut| bytes[..cut].to_vec())
            .collect();
        for _ in 0..60 {
            let mut m = bytes.to_vec();
            for _ in 0..1 + next() % 4 {
                let at = next() as usize % m.len();
                match next() % 3 {
                    0 => m[at] = alphabet[next() as usize % alphabet.len()],
                    1 => {
                        m.remove(at);
                    }
                    _ => m.insert(at, alphabet[next() as usize % alphabet.len()]),
                }
            }
            variants.push(m);
        }
        for variant in variants {
            match behavior_bddl::load::source_from_bytes(name.clone(), variant) {
                Ok(source) => {
                    if let Err(e) = knowledge.load(&source) {
                        rejected += 1;
                        assert!(e.diagnostics.has_errors());
                        let shown = e.to_string();
                        assert!(
                            shown.starts_with(name.as_str()) && shown.contains("error"),
                            "{shown}"
                        );
                    }
                }
                Err(e) => {
                    rejected += 1;
                    assert!(e.to_string().contains("not valid UTF-8"));
                }
            }
        }
    }
    assert!(
        rejected > 10_000,
        "mutations should mostly be rejected, {rejected} were"
    );
}

/// The official taxonomy, on the facts the reference's own taxonomy tests check.
#[test]
fn the_official_taxonomy_folds_into_a_dag_with_abilities() {
    use behavior_bddl::taxonomy::Ability;
    let taxonomy = behavior_bddl::load::read_taxonomy(&data().taxonomy_path()).unwrap();
    let id = |name: &str| taxonomy.get(name).unwrap_or_else(|| panic!("{name}"));
    assert_eq!(taxonomy.len(), 757); // 756 synsets in the file, plus agent.n.01
    let stove = id("stove.n.01");
    assert!(taxonomy.has_ability(stove, Ability::HeatSource));
    assert!(!taxonomy.has_ability(stove, Ability::Burnable));
    let parents: Vec<&str> = taxonomy
        .synset(stove)
        .parents
        .iter()
        .map(|&p| taxonomy.name(p))
        .collect();
    assert_eq!(parents, ["kitchen_appliance.n.01"]);
    let home = id("home_appliance.n.01");
    let below = taxonomy.descendants(home);
    assert!(below.contains(&id("kitchen_appliance.n.01")) && below.contains(&stove));
    assert!(
        taxonomy
            .ancestors(id("kitchen_appliance.n.01"))
            .contains(&id("entity.n.01"))
    );
    assert!(taxonomy.is_a(id("apple.n.01"), id("fruit.n.01")));
    assert!(!taxonomy.is_leaf(id("kitchen_appliance.n.01")));
    let apple = taxonomy
        .ability(id("apple.n.01"), Ability::Cookable)
        .unwrap();
    assert!(apple["cook_temperature"].as_f64().unwrap() > 0.0);
    assert!(taxonomy.synset(id("agent.n.01")).parents == [taxonomy.root()]);
    // Some synsets sit under several parents.
    assert!(taxonomy.ids().any(|s| taxonomy.synset(s).parents.len() > 1));
}
