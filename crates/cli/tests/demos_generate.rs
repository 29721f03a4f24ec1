//! `behavior demos generate` as a user runs it, on two activities: demonstrations from several
//! homes, each a recording that says the planner made it and that replays bit for bit to
//! success; a manifest and a card; a rerun that resumes rather than redoes; a folder of another
//! robot refused.

mod support;

use behavior_env::record::{Provenance, read, replay_with};
use behavior_planning::RecordedCall;
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;
use support::{behavior, behavior_ok, scratch};

const ACTIVITIES: &str = "installing_a_fax_machine,opening_presents";

fn generate(dir: &Path, per_activity: &str) -> Value {
    behavior_ok(&[
        "demos",
        "generate",
        "--out",
        dir.to_str().unwrap(),
        "--activities",
        ACTIVITIES,
        "--per-activity",
        per_activity,
        "--tries",
        "6",
        "--json",
    ]);
    let text = std::fs::read_to_string(dir.join("demos.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn demonstrations_are_generated_checked_and_resumed() {
    let dir = scratch("demos-generated");
    let _ = std::fs::remove_dir_all(&dir);
    let manifest = generate(&dir, "2");
    let demos = manifest["demos"].as_array().unwrap();
    assert_eq!(demos.len(), 4, "two per activity: {manifest:#}");
    let catalog = behavior_catalog::Catalog::load(None, |_| {}).unwrap();
    for activity in ["installing_a_fax_machine_0", "opening_presents_0"] {
        let mine: Vec<&Value> = demos.iter().filter(|d| d["activity"] == activity).collect();
        assert_eq!(mine.len(), 2, "{activity}");
        let homes: BTreeSet<&str> = mine.iter().map(|d| d["scene"].as_str().unwrap()).collect();
        assert_eq!(homes.len(), 2, "{activity}: two homes, not one: {homes:?}");
        for demo in mine {
            assert!(demo["sim_time_s"].as_f64().unwrap() > 0.0);
            assert!(!demo["rooms_visited"].as_array().unwrap().is_empty());
            // The recording: the planner's, and a replay reaches the goal bit for bit.
            let file = dir.join(demo["file"].as_str().unwrap());
            let recording = read(&file).unwrap();
            assert!(matches!(
                &recording.header.provenance,
                Provenance::Planner { mode, .. } if mode == "physical"
            ));
            let config = recording.config_from(catalog.knowledge()).unwrap();
            let report = replay_with::<RecordedCall>(&recording, config).unwrap();
            assert!(
                report.identical && report.checkpoints > 0,
                "{}",
                file.display()
            );
            assert_eq!(report.q_final, 1.0, "{}", file.display());
        }
    }
    let card = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(card.contains("none is a person's demonstration"), "{card}");
    assert!(
        card.contains("| installing_a_fax_machine_0 | 2 | 2 |"),
        "{card}"
    );
    for plot in [
        "duration",
        "distance_navigated",
        "hand_displacement",
        "rooms_visited",
    ] {
        let png = image::open(dir.join(format!("plots/{plot}.png"))).unwrap();
        assert!(png.width() > 100, "{plot}");
    }
    let leftovers: Vec<_> = std::fs::read_dir(dir.join("episodes"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .filter(|n| n.to_string_lossy().starts_with(".partial"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");

    // Run again with the same goal: nothing is tried again.
    let tries = manifest["tries"].as_array().unwrap().len();
    let again = generate(&dir, "2");
    assert_eq!(again["tries"].as_array().unwrap().len(), tries);
    // One more each: the tries go on from where they stopped.
    let more = generate(&dir, "3");
    assert_eq!(more["demos"].as_array().unwrap().len(), 6, "{more:#}");
    assert_eq!(
        more["demos"][0], manifest["demos"][0],
        "kept demos stay as they were"
    );

    #[cfg(feature = "lerobot")]
    {
        // The folder exports as a dataset, its demonstrations in the manifest's order.
        let dataset = scratch("demos-generated-v3");
        let _ = std::fs::remove_dir_all(&dataset);
        let out = behavior_ok(&[
            "demos",
            "export",
            "--lerobot",
            dataset.to_str().unwrap(),
            dir.to_str().unwrap(),
            "--no-images",
            "--json",
        ]);
        let summary: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(summary["episodes"], 6);
        assert_eq!(summary["planned"], 6);
    }
}

#[test]
fn a_folder_of_another_robots_demonstrations_is_refused() {
    let dir = scratch("demos-of-fetch");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let manifest = r#"{"robot": "fetch", "provenance": "", "made_by": "", "demos": [], "tries": [], "wall_s": 0}"#;
    std::fs::write(dir.join("demos.json"), manifest).unwrap();
    let out = behavior(&[
        "demos",
        "generate",
        "--out",
        dir.to_str().unwrap(),
        "--activities",
        "opening_presents",
    ]);
    assert!(!out.status.success());
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(error.contains("holds the fetch robot's"), "{error}");
    assert_eq!(
        std::fs::read_to_string(dir.join("demos.json")).unwrap(),
        manifest,
        "the manifest is left as it was"
    );
}
