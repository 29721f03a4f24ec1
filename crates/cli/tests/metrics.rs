//! `behavior metrics` as a user runs it: episodes recorded by `behavior run`, measured again
//! from their recordings, and compared with a reference episode or a folder of the planner's
//! demonstrations.

mod support;

use serde_json::Value;
use support::{behavior, behavior_ok, scratch};

fn json_of(args: &[&str]) -> Value {
    serde_json::from_slice(&behavior_ok(args).stdout).expect("JSON on stdout")
}

/// Records 30 steps of `agent` on bringing_in_wood's seed-`seed` instance; returns the file
/// and what `behavior run` reported.
fn record(agent: &str, seed: &str) -> (String, Value) {
    let file = scratch(&format!("{agent}-{seed}.mcap"));
    let file = file.to_str().unwrap().to_string();
    let args = [
        "run", "--agent", agent, "--seed", seed, "--steps", "30", "--record", &file, "--json",
    ];
    (file.clone(), json_of(&args))
}

#[test]
fn metrics_are_measured_from_recordings_and_normalized_by_the_reference() {
    let (idle, _) = record("idle", "0");
    let (random, live) = record("random", "0");
    let (elsewhere, _) = record("random", "4");
    let out = json_of(&[
        "metrics",
        &random,
        &elsewhere,
        "--reference",
        &idle,
        "--json",
    ]);

    // The reference is shown for what it is: an agent's episode, not a person's.
    let reference = &out["references"][0];
    assert_eq!(reference["teleoperated"], serde_json::json!({}));
    assert_eq!(reference["metrics"]["distance_navigated"], 0.0);

    // Measured again from the recording: the metrics the live episode reported, exactly.
    let same = &out["episodes"][0];
    assert_eq!(same["metrics"], live["metrics"]);
    assert_eq!(same["reference"], "instance");
    let n = &same["normalized"];
    assert_eq!(n["simulated_time"], 1.0, "30 steps against 30");
    assert!(
        n["distance_navigated"].is_null(),
        "the idle reference did not move: no ratio"
    );
    assert_eq!(same["humans"]["demonstrations"], 1);
    assert_eq!(
        same["humans"]["step_limit"], 60,
        "twice the reference's 30 steps"
    );

    // Another instance of the activity is compared with the activity's best.
    assert_eq!(out["episodes"][1]["reference"], "activity");
}

#[test]
fn a_damaged_recording_is_refused_with_where_and_why() {
    let (idle, _) = record("idle", "1");
    let bytes = std::fs::read(&idle).unwrap();
    let cut = scratch("cut.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let output = behavior(&["metrics", cut.to_str().unwrap(), "--reference", &idle]);
    assert!(!output.status.success());
    let error = String::from_utf8_lossy(&output.stderr);
    assert!(
        error.contains("cut.mcap") && error.contains("damaged or cut after step"),
        "{error}"
    );
}

#[test]
fn a_folder_of_the_planners_demonstrations_is_a_reference_shown_as_the_planners() {
    let dir = scratch("metrics-demos");
    let _ = std::fs::remove_dir_all(&dir);
    let dir_s = dir.to_str().unwrap();
    behavior_ok(&[
        "demos",
        "generate",
        "--out",
        dir_s,
        "--activities",
        "installing_a_fax_machine",
        "--per-activity",
        "1",
        "--tries",
        "3",
    ]);
    let manifest: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("demos.json")).unwrap()).unwrap();
    let demo = dir.join(manifest["demos"][0]["file"].as_str().unwrap());
    let demo_s = demo.to_str().unwrap();
    let out = json_of(&["metrics", demo_s, "--reference", dir_s, "--json"]);
    let reference = &out["references"][0];
    assert_eq!(reference["provenance"]["kind"], "planner");
    assert_eq!(reference["provenance"]["mode"], "physical");
    let episode = &out["episodes"][0];
    assert_eq!(episode["reference"], "instance");
    assert_eq!(episode["normalized"]["simulated_time"], 1.0, "itself");
    let text = behavior_ok(&["metrics", demo_s, "--reference", dir_s]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("1 the planner's") && text.contains("NOT a person's"),
        "{text}"
    );
}
