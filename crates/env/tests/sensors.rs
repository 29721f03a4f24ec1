//! The robot's camera and lidar in an episode: the arrays asked for, labelled consistently.

mod common;

use behavior_env::{CameraConfig, Env, Obs, Reading, categories};
use behavior_render::{Modality, Pixels};
use common::*;

fn camera_env(name: &str, robot: &str) -> Env {
    let mut config = config(name);
    config.robot = behavior_robots::RobotKind::from_name(robot).unwrap();
    config.observations.camera = Some(CameraConfig {
        modalities: vec![
            Modality::Rgb,
            Modality::Depth,
            Modality::Seg,
            Modality::InsSeg,
            Modality::Highlight,
            Modality::Flow,
        ],
        ..CameraConfig::default()
    });
    config.observations.lidar = true;
    Env::new(config)
}

fn get<'a>(obs: &'a Obs, key: &str) -> &'a Reading {
    obs.get(key)
        .unwrap_or_else(|| panic!("no `{key}` in the observation"))
}

#[test]
fn the_eye_sees_labelled_objects_and_highlights_the_activity_s_own() {
    let mut env = camera_env("re-shelving_library_books", "behavior");
    let (obs, _) = env.reset(0).unwrap();
    let rgb = get(&obs, "rgb");
    assert_eq!(rgb.shape, vec![128, 128, 3]);
    assert!(matches!(rgb.data, Pixels::U8(ref p) if p.len() == 128 * 128 * 3));
    let Pixels::F32(depth) = &get(&obs, "depth").data else {
        panic!("depth is f32")
    };
    let Pixels::U32(ins) = &get(&obs, "ins_seg").data else {
        panic!("ins_seg is u32")
    };
    let Pixels::U16(seg) = &get(&obs, "seg").data else {
        panic!("seg is u16")
    };
    let Pixels::U8(highlight) = &get(&obs, "highlight").data else {
        panic!("highlight is u8")
    };
    let world = env.world().unwrap();
    let table = categories(&common::taxonomy());
    let seen: std::collections::BTreeSet<u32> = ins.iter().copied().filter(|&i| i > 0).collect();
    assert!(seen.len() >= 3, "the eye sees {} objects", seen.len());
    for k in 0..ins.len() {
        if ins[k] == 0 {
            assert_eq!((seg[k], highlight[k]), (0, 0));
            continue;
        }
        // Every object pixel: its category's id, at a positive depth within the home.
        let object = world.object(behavior_sim::ObjectId(ins[k] - 1));
        assert_eq!(
            table.name(seg[k]),
            Some(object.category.as_str()),
            "pixel {k}"
        );
        assert!(depth[k] > 0.0 && depth[k] < 30.0, "depth {}", depth[k]);
        let bound = env
            .bindings()
            .unwrap()
            .contains(&Some(behavior_sim::ObjectId(ins[k] - 1)));
        assert_eq!(highlight[k] == 1, bound, "pixel {k} of {}", object.name);
    }
    // The first frame has not moved; the lidar sees the room around the eye.
    let Pixels::F32(flow) = &get(&obs, "flow").data else {
        panic!()
    };
    assert!(flow.iter().all(|&f| f == 0.0));
    let lidar = get(&obs, "lidar");
    assert_eq!(lidar.shape, vec![16, 360]);
    let Pixels::F32(ranges) = &lidar.data else {
        panic!()
    };
    assert!(ranges.iter().filter(|&&r| r > 0.0).count() > 1000);
}

#[test]
fn fetch_s_head_camera_and_base_laser_follow_it_as_it_turns() {
    let mut env = camera_env("bringing_in_wood", "fetch");
    let (first, _) = env.reset(0).unwrap();
    assert_eq!(get(&first, "lidar").shape, vec![1, 220]);
    // Turn in place for a second: the view changes and the flow is no longer zero.
    let mut action = vec![0.0; env.robot().unwrap().action_dim()];
    action[1] = 1.0;
    let mut last = first;
    for _ in 0..10 {
        last = env.step(&action).unwrap().obs;
    }
    assert_ne!(get(&last, "rgb"), get(&first_again(&mut env), "rgb"));
    let Pixels::F32(flow) = &get(&last, "flow").data else {
        panic!()
    };
    let moving = flow.chunks(2).filter(|f| f[0].abs() > 0.5).count();
    assert!(moving > 1000, "{moving} pixels moved sideways");
}

/// The first observation of the same episode again.
fn first_again(env: &mut Env) -> Obs {
    env.reset(0).unwrap().0
}
