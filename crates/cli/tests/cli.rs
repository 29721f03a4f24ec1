//! End-to-end tests of the `behavior bddl` commands, run as a user would run them.

#[path = "../../bddl/tests/common/mod.rs"]
mod common;
mod support;

use behavior_bddl::activity::InitLiteral;
use behavior_bddl::{Activity, Atom, Counting};
use behavior_data::DataDir;
use serde_json::Value;
use std::path::{Path, PathBuf};
use support::{behavior, behavior_ok, scratch, stdout};

fn conformance() -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../bddl/tests/fixtures/bddl-1.0.1-conformance.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("conformance file")).unwrap()
}

/// With the reference's counting, every volume equals the reference's recorded one.
#[test]
fn stats_json_lists_the_100_activities_with_exact_volumes() {
    let output = behavior_ok(&["bddl", "stats", "--json", "--reference-counting"]);
    let rows: Vec<Value> = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(rows.len(), 100);
    let reference = conformance();
    for row in &rows {
        let keys: Vec<&str> = row
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        assert_eq!(
            keys,
            [
                "activity",
                "init_literals",
                "objects",
                "q_at_init",
                "success_at_init",
                "volume"
            ]
        );
        let name = row["activity"].as_str().unwrap();
        assert_eq!(
            row["volume"], reference["activities"][name]["volume"],
            "{name}"
        );
    }
    let lunches = rows
        .iter()
        .find(|r| r["activity"] == "packing_lunches")
        .unwrap();
    assert_eq!(lunches["objects"], 19);
    assert_eq!(lunches["init_literals"], 19);
    assert_eq!(lunches["volume"], 12);
}

fn write_state(activity: &Activity, atoms: &[Atom], path: &Path) {
    let facts: Vec<Vec<String>> = atoms
        .iter()
        .map(|a| {
            let mut fact = vec![
                a.predicate.name().to_string(),
                activity.instance(a.subject).name.clone(),
            ];
            fact.extend(a.object.map(|o| activity.instance(o).name.clone()));
            fact
        })
        .collect();
    std::fs::write(path, serde_json::json!({ "facts": facts }).to_string()).unwrap();
}

/// Random states over each activity's goal atoms; the binary's success, Q and volume must equal
/// a naive enumeration of the options, counted as sets (the default).
#[test]
fn eval_agrees_with_an_independent_exact_evaluation_on_random_states() {
    let data = DataDir::locate(None, |_| ()).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let activities = [
        "packing_lunches",
        "setting_up_candles",
        "cleaning_sneakers",
        "sorting_groceries",
        "serving_hors_d_oeuvres",
        "putting_away_toys",
        "polishing_silver",
        "cleaning_up_the_kitchen_only",
    ];
    let mut checked = 0;
    for name in activities {
        let (activity, _) = knowledge
            .load(&behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap())
            .unwrap();
        let formula = activity.goal_formula();
        let options =
            common::dnf(&activity, &formula, &mut Vec::new(), true).expect("small enough");
        let mut atoms: Vec<Atom> = options.iter().flatten().map(|l| l.atom).collect();
        atoms.sort();
        atoms.dedup();
        for seed in 0..6u64 {
            let truth = common::random_truth(seed * 7919 + 1);
            let state: Vec<Atom> = atoms.iter().copied().filter(|&a| truth(a)).collect();
            let is_true = |a: Atom| state.contains(&a);
            let path = scratch(&format!("{name}-{seed}.json"));
            write_state(&activity, &state, &path);
            let output = behavior_ok(&[
                "bddl",
                "eval",
                name,
                "--state",
                path.to_str().unwrap(),
                "--json",
            ]);
            let report: Value = serde_json::from_slice(&output.stdout).unwrap();
            let (volume, q) = common::volume_and_q(&options, &is_true, Counting::Set);
            let success = common::holds(&activity, &formula, &mut Vec::new(), &is_true);
            assert_eq!(report["success"], success, "{name} {seed}");
            assert_eq!(
                report["volume"].as_u64(),
                volume.map(|v| v as u64),
                "{name}"
            );
            let (s, n) = q.unwrap();
            let q_reported = report["q"].as_f64().unwrap();
            assert!(
                (q_reported - s as f64 / n as f64).abs() < 1e-12,
                "{name} {seed}: {q_reported} vs {s}/{n}"
            );
            assert_eq!(
                report["conjuncts"].as_array().unwrap().len(),
                activity.goal.len()
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 48);
}

/// The official activity whose goal writes a literal once per bowl (and one once per cup):
/// `stats`, `eval` and `options` count it once by default and twice with `--reference-counting`.
#[test]
fn reference_counting_flag_counts_repeated_literals_as_the_reference_does() {
    let name = "cleaning_kitchen_cupboard";
    let stats = |extra: &[&str]| -> Vec<Value> {
        let output = behavior_ok(&[&["bddl", "stats", "--json"], extra].concat());
        serde_json::from_slice(&output.stdout).unwrap()
    };
    let (sets, lists) = (stats(&[]), stats(&["--reference-counting"]));
    let row = |rows: &[Value]| rows.iter().find(|r| r["activity"] == name).unwrap().clone();
    assert_eq!(
        (
            row(&sets)["volume"].clone(),
            row(&sets)["q_at_init"].clone()
        ),
        (8.into(), 0.375.into())
    );
    assert_eq!(
        (
            row(&lists)["volume"].clone(),
            row(&lists)["q_at_init"].clone()
        ),
        (10.into(), 0.5.into())
    );
    // Only the two goals that repeat a literal count differently.
    let differing: Vec<&Value> = sets
        .iter()
        .zip(&lists)
        .filter(|(s, l)| s != l)
        .map(|(s, _)| &s["activity"])
        .collect();
    assert_eq!(
        differing,
        ["cleaning_kitchen_cupboard", "cleaning_up_after_a_meal"]
    );

    let data = DataDir::locate(None, |_| ()).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let source = behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap();
    let (activity, _) = knowledge.load(&source).unwrap();
    let state = scratch("cupboard-init.json");
    write_state(&activity, &activity.initial_facts(), &state);
    let eval = |extra: &[&str]| -> Value {
        let args = [
            &[
                "bddl",
                "eval",
                name,
                "--state",
                state.to_str().unwrap(),
                "--json",
            ],
            extra,
        ];
        serde_json::from_slice(&behavior_ok(&args.concat()).stdout).unwrap()
    };
    let (set, list) = (eval(&[]), eval(&["--reference-counting"]));
    assert_eq!(
        (&set["q_exact"], &set["volume"]),
        (&"3/8".into(), &8.into())
    );
    assert_eq!(
        (&list["q_exact"], &list["volume"]),
        (&"1/2".into(), &10.into())
    );

    let first = |extra: &[&str]| {
        let output = behavior_ok(&[&["bddl", "options", name, "--limit", "1"], extra].concat());
        stdout(&output)
            .lines()
            .take(2)
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(
        first(&[]),
        "cleaning_kitchen_cupboard_0: volume 8\noption 1 (8 literals)"
    );
    assert_eq!(
        first(&["--reference-counting"]),
        "cleaning_kitchen_cupboard_0: volume 10\noption 1 (10 literals)"
    );
}

#[test]
fn eval_reports_each_conjunct_and_rejects_a_bad_state() {
    let state = scratch("lunches.json");
    std::fs::write(
        &state,
        r#"{"facts": [["inside", "apple.n.01_1", "carton.n.02_1"], ["inside", "banana.n.02_1", "carton.n.02_2"]]}"#,
    )
    .unwrap();
    let output = behavior_ok(&[
        "bddl",
        "eval",
        "packing_lunches",
        "--state",
        state.to_str().unwrap(),
        "--json",
    ]);
    let report: Value = serde_json::from_slice(&output.stdout).unwrap();
    let holds: Vec<bool> = report["conjuncts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["holds"].as_bool().unwrap())
        .collect();
    assert_eq!(holds, [false, false, false, false, true, true]);
    assert_eq!(report["success"], false);
    // Two positive literals and two true negations ("not inside" holds) of a 12-literal option.
    assert_eq!(report["q_exact"], "1/3");

    std::fs::write(&state, r#"{"facts": [["ontop", "apple.n.01_1"]]}"#).unwrap();
    let output = behavior(&[
        "bddl",
        "eval",
        "packing_lunches",
        "--state",
        state.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(
        err.contains("fact 0") && err.contains("`ontop` takes 2 argument(s), 1 given"),
        "{err}"
    );
}

#[test]
fn check_reports_located_errors_and_exits_1() {
    let bad = scratch("bad.bddl");
    std::fs::write(
        &bad,
        "(define (problem bad_0) (:domain igibson)\n  (:objects apple.n.01_1 - apple.n.01 table.n.02_1 - table.n.02)\n  (:init (ontop apple.n.01_1 table.n.02_1))\n  (:goal (and (ontopp ?apple.n.01_1 ?table.n.02_1) (cooked ?pear.n.01_1))))\n",
    )
    .unwrap();
    let unbalanced = scratch("unbalanced.bddl");
    std::fs::write(
        &unbalanced,
        "(define (problem x_0)\n  (:domain igibson)\n  (:objects a.n.01_1 - a.n.01\n",
    )
    .unwrap();
    let binary = scratch("binary.bddl");
    std::fs::write(&binary, b"(define \xff\xfe)").unwrap();
    let output = behavior(&[
        "bddl",
        "check",
        bad.to_str().unwrap(),
        unbalanced.to_str().unwrap(),
        binary.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    let out = stdout(&output);
    let bad_name = bad.display().to_string();
    assert!(
        out.contains(&format!(
            "{bad_name}:4:16: error: unknown predicate `ontopp`"
        )),
        "{out}"
    );
    assert!(
        out.contains(&format!(
            "{bad_name}:4:60: error: undeclared instance `?pear.n.01_1`"
        )),
        "{out}"
    );
    assert!(out.contains("^^^^^^"), "{out}");
    assert!(
        out.contains(&format!(
            "{}:3:3: error: unclosed `(`",
            unbalanced.display()
        )),
        "{out}"
    );
    assert!(
        out.contains(&format!(
            "{}:1:9: error: the file is not valid UTF-8",
            binary.display()
        )),
        "{out}"
    );
    assert!(out.contains("checked 3 file(s): 3 with errors"), "{out}");
}

#[test]
fn check_accepts_an_unfamiliar_valid_file_and_warns_about_abilities() {
    let file = scratch("custom.bddl");
    std::fs::write(
        &file,
        "; a definition written by a user\n(define (problem toasting_bread_0) (:domain igibson)\n (:objects bread.n.01_1 - bread.n.01 table.n.02_1 - table.n.02 floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)\n (:init (ontop bread.n.01_1 table.n.02_1) (inroom table.n.02_1 kitchen) (inroom floor.n.01_1 kitchen) (onfloor agent.n.01_1 floor.n.01_1))\n (:goal (and (cooked ?bread.n.01_1) (sliced ?table.n.02_1))))\n",
    )
    .unwrap();
    let output = behavior(&["bddl", "check", file.to_str().unwrap()]);
    let out = stdout(&output);
    assert!(output.status.success(), "{out}");
    assert!(
        out.contains(
            "warning: `sliced` applied to `table.n.02_1`, but synset `table.n.02` is not sliceable"
        ),
        "{out}"
    );
    assert!(
        out.contains("checked 1 file(s): 0 with errors, 0 error(s), 1 warning(s)"),
        "{out}"
    );
}

#[test]
fn check_without_paths_checks_the_100_official_definitions_and_the_domain() {
    let output = behavior_ok(&["bddl", "check"]);
    assert!(
        stdout(&output).contains("checked 101 file(s): 0 with errors, 0 error(s), 0 warning(s)")
    );
}

#[test]
fn options_lists_the_smallest_first() {
    let output = behavior_ok(&["bddl", "options", "setting_up_candles", "--limit", "3"]);
    let out = stdout(&output);
    assert!(
        out.starts_with("setting_up_candles_0: volume 6\noption 1 (6 literals)\n"),
        "{out}"
    );
    assert_eq!(out.matches("option ").count(), 3);
    assert!(out.contains("(first 3 shown"));
}

#[test]
fn a_bad_data_directory_is_a_clear_error() {
    let empty = scratch("empty-data");
    std::fs::create_dir_all(&empty).unwrap();
    let output = behavior(&["--data-dir", empty.to_str().unwrap(), "bddl", "stats"]);
    assert_eq!(output.status.code(), Some(1));
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(
        err.contains("is not a bddl data directory: hierarchy_owned.json is missing"),
        "{err}"
    );
}

#[test]
fn check_recognizes_a_domain_file() {
    let domain = scratch("domain_custom.bddl");
    std::fs::write(
        &domain,
        "(define (domain custom)\n  (:requirements :strips)\n  (:predicates (inside ?a ?b) (ontop ?a)))\n",
    )
    .unwrap();
    let output = behavior(&["bddl", "check", domain.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    let out = stdout(&output);
    assert!(
        out.contains(&format!(
            "{}:3:31: error: `ontop` takes 2 parameter(s), declared with 1",
            domain.display()
        )),
        "{out}"
    );
}

#[test]
fn scene_list_names_fifteen_homes() {
    let output = behavior_ok(&["scene", "list"]);
    let out = stdout(&output);
    assert_eq!(out.lines().count(), 16, "{out}");
    assert!(out.contains("alder") && out.contains("willow") && out.contains("kitchen_0"));
    for family in behavior_assets::Family::ALL {
        assert!(
            out.contains(family.name()),
            "no {family} home listed: {out}"
        );
    }
}

#[test]
fn scene_generate_takes_a_family_and_scene_sheet_draws_two_of_each() {
    let path = scratch("seed_5_studio.json");
    let file = path.to_str().unwrap();
    let generate = |family: &str| {
        let args = ["scene", "generate", "--seed", "5", "--no-clutter"];
        behavior(&[&args[..], &["--family", family, "--out", file]].concat())
    };
    assert!(generate("studio").status.success());
    let scene =
        behavior_assets::Scene::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(scene.family, Some(behavior_assets::Family::Studio));
    let wrong = generate("castle");
    assert_eq!(wrong.status.code(), Some(2));
    let said = String::from_utf8_lossy(&wrong.stderr);
    assert!(said.contains("unknown plan family `castle`"), "{said}");
    let png = scratch("families.png");
    behavior_ok(&[
        "scene",
        "sheet",
        "--families-from",
        "1",
        "--png",
        png.to_str().unwrap(),
    ]);
    let sheet = image::open(&png).unwrap();
    assert_eq!(
        (sheet.width(), sheet.height()),
        (4 * 640, 3 * 520),
        "12 maps, 4 a row"
    );
}

#[test]
fn scene_generate_writes_a_scene_file_that_round_trips() {
    let path = scratch("seed_42.json");
    behavior_ok(&[
        "scene",
        "generate",
        "--seed",
        "42",
        "--out",
        path.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&path).unwrap();
    let scene = behavior_assets::Scene::from_json(&text).unwrap();
    assert_eq!(scene.seed, 42);
    assert_eq!(scene.to_json(), text);
    // The file draws as well as a named home does.
    let png = scratch("seed_42.png");
    behavior_ok(&[
        "scene",
        "show",
        path.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    let image = image::open(&png).unwrap();
    assert!(image.width() > 500 && image.height() > 300);
    // A broken file is a clear error.
    std::fs::write(&path, "{\"name\": 3}").unwrap();
    let output = behavior(&[
        "scene",
        "show",
        path.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("the scene file is not valid"));
}

#[test]
fn scene_generate_no_clutter_writes_the_furniture_only_home() {
    let (bare, full) = (scratch("seed_7_bare.json"), scratch("seed_7.json"));
    for (path, flags) in [(&bare, &["--no-clutter"][..]), (&full, &[][..])] {
        let mut args = vec!["scene", "generate", "--seed", "7", "--out"];
        args.push(path.to_str().unwrap());
        args.extend(flags);
        behavior_ok(&args);
    }
    let read =
        |p: &PathBuf| behavior_assets::Scene::from_json(&std::fs::read_to_string(p).unwrap());
    let (bare_text, bare) = (
        std::fs::read_to_string(&bare).unwrap(),
        read(&bare).unwrap(),
    );
    let full = read(&full).unwrap();
    assert!(
        !bare_text.contains("clutter"),
        "no clutter in the file at all"
    );
    assert!(
        full.clutter.len() > 100,
        "{} things of clutter",
        full.clutter.len()
    );
    assert_eq!(
        full.without_clutter(),
        bare,
        "the same home under the clutter"
    );
}

#[test]
fn sample_uses_a_cluttered_home_unless_told_not_to() {
    let run = |flags: &[&str]| -> Value {
        let mut args = vec!["sample", "bringing_in_wood", "--json"];
        args.extend(flags);
        serde_json::from_slice(&behavior_ok(&args).stdout).unwrap()
    };
    let (full, bare) = (run(&[]), run(&["--no-clutter"]));
    let count = |r: &Value, key: &str| r["objects"][key].as_u64().unwrap();
    assert!(count(&full, "clutter") > 100, "{full}");
    // The original's home for this activity holds 134 objects.
    assert!(count(&full, "total") >= 134, "{full}");
    assert_eq!(count(&bare, "clutter"), 0, "{bare}");
    assert_eq!(
        count(&full, "total") - count(&full, "clutter"),
        count(&bare, "total"),
        "the same furniture, floors and activity objects"
    );
    for r in [&full, &bare] {
        assert_eq!(r["init_check"]["failing"], serde_json::json!([]));
    }
}

#[test]
fn scene_coverage_json_lists_at_least_three_homes_per_activity() {
    let output = behavior_ok(&["scene", "coverage", "--json"]);
    let rows: Vec<Value> = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(rows.len(), 100);
    for row in &rows {
        let scenes = row["scenes"].as_array().unwrap();
        assert!(scenes.len() >= 3, "{row}");
    }
}

/// How many `:init` literals an official activity has: all, relations (binary atoms), unary
/// states, `inroom` — counted from the parsed definition, independently of the sampler.
fn init_counts(name: &str) -> [usize; 4] {
    let data = DataDir::locate(None, |_| ()).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let (activity, _) = knowledge
        .load(&behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap())
        .unwrap();
    let count = |f: &dyn Fn(&InitLiteral) -> bool| activity.init.iter().filter(|l| f(l)).count();
    [
        activity.init.len(),
        count(&|l| matches!(l, InitLiteral::Atom(a) if a.atom.object.is_some())),
        count(&|l| matches!(l, InitLiteral::Atom(a) if a.atom.object.is_none())),
        count(&|l| matches!(l, InitLiteral::InRoom { .. })),
    ]
}

#[test]
fn sample_prints_bindings_and_saves_an_instance() {
    let out = scratch("lunches_instance.json");
    let output = behavior_ok(&[
        "sample",
        "packing_lunches",
        "--seed",
        "1",
        "--json",
        "--out",
        out.to_str().unwrap(),
    ]);
    let report: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(report["activity"], "packing_lunches");
    // The init check ran on every literal of the definition, and every one holds.
    let [literals, relations, unary, inroom] = init_counts("packing_lunches");
    let check = &report["init_check"];
    assert_eq!(check["literals"], literals);
    assert_eq!(check["holding"], literals);
    assert_eq!(check["relations"], relations);
    assert_eq!(check["unary_states"], unary);
    assert_eq!(check["inroom"], inroom);
    assert_eq!(check["failing"], serde_json::json!([]));
    assert_eq!(report["bindings"].as_array().unwrap().len(), 19);
    let saved =
        behavior_sampling::SavedInstance::from_json(&std::fs::read_to_string(&out).unwrap())
            .unwrap();
    assert_eq!(saved.activity, "packing_lunches_0");
    assert_eq!(saved.bindings.len(), 19);
}

#[test]
fn sample_prints_the_init_check_it_ran() {
    // Dusty and stained surfaces: unary states as well as relations and rooms.
    let output = behavior_ok(&["sample", "cleaning_stove"]);
    let out = stdout(&output);
    let [literals, relations, unary, inroom] = init_counts("cleaning_stove");
    assert!(unary > 0);
    let line = format!(
        "init check: {literals} of {literals} init literals hold ({relations} relations, \
         {unary} unary states, {inroom} inroom)\n"
    );
    assert!(out.contains(&line), "{out}");
    assert!(!out.contains("fails:"), "{out}");
}

#[test]
fn sample_reports_an_activity_that_cannot_be_instantiated() {
    // A definition of one's own that wants the apple on the kitchen table and in the fridge.
    let file = scratch("apple_in_two_places.bddl");
    std::fs::write(
        &file,
        "(define (problem apple_in_two_places_0) (:domain igibson)
          (:objects apple.n.01_1 - apple.n.01 table.n.02_1 - table.n.02
                    electric_refrigerator.n.01_1 - electric_refrigerator.n.01
                    floor.n.01_1 - floor.n.01 agent.n.01_1 - agent.n.01)
          (:init (ontop apple.n.01_1 table.n.02_1) (inside apple.n.01_1 electric_refrigerator.n.01_1)
                 (inroom table.n.02_1 kitchen) (inroom electric_refrigerator.n.01_1 kitchen)
                 (inroom floor.n.01_1 kitchen) (onfloor agent.n.01_1 floor.n.01_1))
          (:goal (not (ontop ?apple.n.01_1 ?table.n.02_1))))",
    )
    .unwrap();
    let output = behavior(&["sample", file.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(
        err.contains(
            "(ontop apple.n.01_1 table.n.02_1) and (inside apple.n.01_1 \
             electric_refrigerator.n.01_1) could not be satisfied"
        ),
        "{err}"
    );
}

/// The facts of a `{"facts": [...]}` document, as lists of strings.
fn facts_of(json: &Value) -> Vec<Vec<String>> {
    json["facts"]
        .as_array()
        .expect("a facts list")
        .iter()
        .map(|f| {
            f.as_array()
                .unwrap()
                .iter()
                .map(|s| s.as_str().unwrap().to_string())
                .collect()
        })
        .collect()
}

#[test]
fn facts_of_every_activity_match_between_sample_and_the_saved_instance_and_imply_the_init() {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    for name in data.activities().unwrap() {
        let file = scratch(&format!("facts-{name}.json"));
        let file = file.to_str().unwrap();
        let sampled = behavior(&["sample", &name, "--seed", "0", "--out", file, "--json"]);
        if !sampled.status.success() {
            // An activity the first covering home cannot host; sample-all reports those.
            eprintln!("{name}: {}", String::from_utf8_lossy(&sampled.stderr));
            continue;
        }
        let sampled: Value = serde_json::from_str(&stdout(&sampled)).unwrap();
        let printed = stdout(&behavior_ok(&["facts", file, "--json"]));
        let loaded: Value = serde_json::from_str(&printed).unwrap();
        let facts = facts_of(&sampled);
        assert_eq!(
            facts,
            facts_of(&loaded),
            "{name}: sample --json and facts differ"
        );
        assert_eq!(
            sampled["poses"].as_object().unwrap().len(),
            sampled["bindings"].as_array().unwrap().len(),
            "{name}: a pose per instance"
        );
        // Every init literal, read off the printed facts alone.
        let source = behavior_bddl::load::read_source(&data.problem_path(&name).unwrap()).unwrap();
        let (activity, _) = knowledge.load(&source).unwrap();
        let listed: std::collections::BTreeSet<Vec<String>> = facts.into_iter().collect();
        for (fact, positive) in common::init_as_facts(&activity) {
            assert_eq!(listed.contains(&fact), positive, "{name}: {fact:?}");
        }
        // `bddl eval` reads the facts back, inroom included.
        let state = scratch(&format!("state-{name}.json"));
        std::fs::write(&state, printed).unwrap();
        behavior_ok(&["bddl", "eval", &name, "--state", state.to_str().unwrap()]);
    }
}

#[test]
fn stats_json_agrees_with_a_naive_set_evaluation_at_init_on_every_enumerable_activity() {
    // The default counting is the paper's: an option is a set of literals.
    let data = DataDir::locate(None, |_| ()).unwrap();
    let knowledge =
        behavior_bddl::Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap();
    let rows: Vec<Value> =
        serde_json::from_slice(&behavior_ok(&["bddl", "stats", "--json"]).stdout).unwrap();
    let mut checked = 0;
    for row in &rows {
        let name = row["activity"].as_str().unwrap();
        let source = behavior_bddl::load::read_source(&data.problem_path(name).unwrap()).unwrap();
        let (activity, _) = knowledge.load(&source).unwrap();
        let formula = activity.goal_formula();
        let Some(options) = common::dnf(&activity, &formula, &mut Vec::new(), true) else {
            continue; // too many options to enumerate naively
        };
        let init = activity.initial_facts();
        let is_true = |a: Atom| init.contains(&a);
        let (volume, q) = common::volume_and_q(&options, &is_true, Counting::Set);
        assert_eq!(row["volume"].as_u64(), volume.map(|v| v as u64), "{name}");
        match q {
            Some((s, n)) => {
                let reported = row["q_at_init"].as_f64().unwrap();
                assert!(
                    (reported - s as f64 / n as f64).abs() < 1e-12,
                    "{name}: {reported} vs {s}/{n}"
                );
            }
            None => assert!(row["q_at_init"].is_null(), "{name}"),
        }
        checked += 1;
    }
    assert!(
        checked >= 90,
        "only {checked} activities could be enumerated"
    );
}
