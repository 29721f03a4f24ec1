//! `behavior scene export --gltf` run as a user would: a sampled instance written as binary glTF
//! (the Khronos validator checks the file itself in `crates/web/ui/tests/gltf.mjs`).

mod support;

use std::process::Output;
use support::{behavior, behavior_ok, scratch};

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn an_instance_is_written_as_a_glb_holding_its_objects() {
    let out = scratch("home.glb");
    let output = behavior_ok(&[
        "scene",
        "export",
        "storing_food",
        "--seed",
        "3",
        "--no-robot",
        "--gltf",
        out.to_str().unwrap(),
    ]);
    assert!(stderr(&output).contains("objects"), "{}", stderr(&output));
    let file = std::fs::read(&out).unwrap();
    assert_eq!(&file[..4], b"glTF", "not a binary glTF");
    let total = u32::from_le_bytes(file[8..12].try_into().unwrap()) as usize;
    assert_eq!(total, file.len(), "the header's length is not the file's");
    let json_len = u32::from_le_bytes(file[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&file[20..20 + json_len]).unwrap();
    let names: Vec<&str> = doc["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|n| n["name"].as_str())
        .collect();
    assert!(
        names.iter().any(|n| n.starts_with("floor")),
        "no floor among {names:?}"
    );
    assert!(
        names.iter().filter(|n| n.contains(".n.0")).count() > 5,
        "too few of the activity's objects among {names:?}"
    );
    assert!(
        !names.iter().any(|n| n.starts_with("robot")),
        "--no-robot kept {names:?}"
    );
}

#[test]
fn export_refuses_a_file_that_is_not_glb() {
    let bad = behavior(&["scene", "export", "storing_food", "--gltf", "home.gltf"]);
    assert!(!bad.status.success());
    assert!(
        stderr(&bad).contains("must end in .glb"),
        "{}",
        stderr(&bad)
    );
}
