//! Fetch's real meshes (gymnasium-robotics, fetched from PyPI at first use): read into one piece
//! per link, each lying where the link's collision shapes are, so that what is drawn is what is
//! simulated; a broken model is a clear error, never a panic.

use behavior_data::{DataError, RobotAssets};
use behavior_robots::{Fetch, FetchLink, ModelError, fetch_models, fetch_piece};
use behavior_sim::{Model, World};
use rapier3d::math::{Pose, Vector};
use std::path::Path;

fn assets() -> RobotAssets {
    RobotAssets::locate(|line| eprintln!("{line}"))
        .expect("gymnasium-robotics from PyPI (or BEHAVIOR_ROBOT_ASSETS)")
        .expect("BEHAVIOR_ROBOT_ASSETS=none leaves nothing to test")
}

/// How far a link's mesh may reach beyond the box around its colliders, m. The largest is the
/// forearm's cable cover, 3.5 cm beyond the arm's capsule on one side; every other link is
/// within 1.6 cm.
const SLACK: f32 = 0.04;

#[test]
fn every_link_has_its_meshes_within_its_colliders_box() {
    let models = fetch_models(&assets()).unwrap();
    let mut world = World::default();
    let fetch = Fetch::add(&mut world, Pose::IDENTITY).unwrap();
    let mut colours = std::collections::BTreeSet::new();
    let mut total = 0;
    for link in FetchLink::ALL {
        let id = fetch.parts().link(link);
        let piece = world.bodies().object(id).model;
        assert_eq!(piece, Some(fetch_piece(link)), "{link:?} names its piece");
        assert_eq!(fetch_piece(link).model, Model::Fetch);
        let meshes = models.get(fetch_piece(link)).unwrap();
        assert!(!meshes.is_empty(), "{link:?} has no mesh");
        let b = world.bodies().local_aabb(id);
        let (mut lo, mut hi) = (Vector::splat(f32::MAX), Vector::splat(f32::MIN));
        for m in meshes.iter().map(|h| &h.mesh) {
            assert!(
                m.triangles.len() >= 20,
                "{link:?}: {} triangles",
                m.triangles.len()
            );
            for v in &m.vertices {
                lo = lo.min(*v);
                hi = hi.max(*v);
            }
            total += m.triangles.len();
            colours.insert(m.visual.color);
        }
        let beyond = (b.mins - lo).max(hi - b.maxs).max_element();
        assert!(
            beyond < SLACK,
            "{link:?}: mesh {lo:?}..{hi:?} reaches {beyond} m beyond colliders {:?}..{:?}",
            b.mins,
            b.maxs
        );
        // And it fills its box: no link is drawn as a sliver of where it collides.
        let short = (lo - b.mins).max(b.maxs - hi).max_element();
        assert!(
            short < SLACK,
            "{link:?}: mesh {lo:?}..{hi:?} falls {short} m short"
        );
    }
    // Grey, blue and white links, a red emergency stop and the laser's light grey.
    assert!(colours.len() >= 4, "{colours:?}");
    assert!(
        colours.contains(&[204, 0, 0]),
        "the red stop button: {colours:?}"
    );
    assert!(total > 20_000, "{total} triangles in all");
}

#[test]
fn a_missing_or_broken_model_is_an_error_naming_the_file() {
    let dir = std::env::temp_dir().join(format!("behavior-fetch-model-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let err = RobotAssets::open(&dir).unwrap_err();
    assert!(
        matches!(&err, DataError::NotRobotAssets { missing, .. } if missing == "fetch/robot.xml"),
        "{err}"
    );
    // A copy of the real assets whose model has a body with a bad position.
    let real = assets();
    for sub in ["fetch", "stls/fetch"] {
        std::fs::create_dir_all(dir.join(sub)).unwrap();
        for entry in std::fs::read_dir(real.root().join(sub)).unwrap() {
            let path = entry.unwrap().path();
            std::fs::copy(&path, dir.join(sub).join(path.file_name().unwrap())).unwrap();
        }
    }
    let model = dir.join("fetch/robot.xml");
    let text = std::fs::read_to_string(&model).unwrap();
    let broken = text.replacen("pos=\"-0.0869 0 0.3774\"", "pos=\"-0.0869 zero 0.3774\"", 1);
    assert_ne!(
        broken, text,
        "the model's torso position moved: update the test"
    );
    std::fs::write(&model, broken).unwrap();
    let err = fetch_models(&RobotAssets::open(&dir).unwrap()).unwrap_err();
    let shown = err.to_string();
    assert!(matches!(err, ModelError::Bad { .. }), "{shown}");
    assert!(
        shown.contains("robot.xml") && shown.contains("torso_lift_link") && shown.contains("zero"),
        "{shown}"
    );
    // A mesh file gone.
    std::fs::write(&model, text).unwrap();
    std::fs::remove_file(dir.join("stls/fetch/gripper_link.stl")).unwrap();
    let err = fetch_models(&RobotAssets::open(&dir).unwrap()).unwrap_err();
    assert!(err.to_string().contains("gripper_link.stl"), "{err}");
    assert!(Path::new(&dir).is_dir());
    std::fs::remove_dir_all(&dir).unwrap();
}
