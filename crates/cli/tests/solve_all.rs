//! `behavior solve-all` as a user runs it: several seeds per activity, each activity stopping at
//! its first success.

mod support;

use serde_json::Value;
use support::{behavior, behavior_ok};

#[test]
fn solve_all_tries_the_next_seed_only_where_the_last_did_not_solve_it() {
    // Alarms are solved on seed 0, and no other seed is tried. Sorting mail is solved on none of
    // the three: the fourth envelope, to touch the first, finds no place on it beside the third
    // (every seed's stack is as crowded), so each seed is tried in turn.
    let output = behavior_ok(&[
        "solve-all",
        "--activity",
        "installing_alarms",
        "--activity",
        "sorting_mail",
        "--seeds",
        "3",
        "--json",
    ]);
    let report: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(report["seeds"], 3);
    assert_eq!(report["solved"], 1, "{report:#}");
    let runs: Vec<(String, u64, bool)> = report["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            (
                r["activity"].as_str().unwrap().to_string(),
                r["seed"].as_u64().unwrap(),
                r["success"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        runs,
        [
            ("installing_alarms_0".to_string(), 0, true),
            ("sorting_mail_0".to_string(), 0, false),
            ("sorting_mail_0".to_string(), 1, false),
            ("sorting_mail_0".to_string(), 2, false),
        ]
    );
}

#[test]
fn solve_all_refuses_zero_seeds() {
    let output = behavior(&["solve-all", "--seeds", "0"]);
    assert!(!output.status.success());
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(err.contains("--seeds"), "{err}");
}
