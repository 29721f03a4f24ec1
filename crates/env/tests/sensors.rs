//! The robot's camera and lidar in an episode: the arrays asked for, labelled consistently.

mod common;

use behavior_env::{CameraConfig, Env, FixedCamera, Obs, Placement, Reading, categories};
use behavior_render::{ImageProfile, Modality, Pixels};
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
        let object = world.bodies().object(behavior_sim::ObjectId(ins[k] - 1));
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

#[test]
fn fixed_cameras_stand_still_and_the_overview_takes_in_the_home() {
    let mut config = config("re-shelving_library_books");
    let modalities = vec![Modality::Rgb, Modality::Depth, Modality::InsSeg];
    let eye = CameraConfig {
        modalities: modalities.clone(),
        ..CameraConfig::default()
    };
    config.observations.camera = Some(eye.clone());
    // Where the eye is at the start of this episode.
    let mut probe = Env::new(config.clone());
    probe.reset(0).unwrap();
    let start = probe.robot().unwrap().camera_pose(probe.world().unwrap());
    config.observations.fixed_cameras = vec![
        FixedCamera {
            name: "still".into(),
            placement: Placement::At(start),
            config: eye,
        },
        FixedCamera {
            name: "overview".into(),
            placement: Placement::Overview,
            config: CameraConfig {
                modalities,
                width: 96,
                height: 64,
                vertical_fov: 60f32.to_radians(),
                ..CameraConfig::default()
            },
        },
    ];
    let mut env = Env::new(config);
    let (first, _) = env.reset(0).unwrap();
    // Standing where the eye stands, the fixed camera sees what the eye sees.
    assert_eq!(get(&first, "still/rgb"), get(&first, "rgb"));
    assert_eq!(get(&first, "overview/rgb").shape, vec![64, 96, 3]);
    let Pixels::U32(ins) = &get(&first, "overview/ins_seg").data else {
        panic!("ins_seg is u32")
    };
    let world = env.world().unwrap();
    let seen: std::collections::BTreeSet<u32> = ins.iter().copied().filter(|&i| i > 0).collect();
    let floors = seen
        .iter()
        .filter(|&&i| {
            world
                .bodies()
                .object(behavior_sim::ObjectId(i - 1))
                .category
                == "floor.n.01"
        })
        .count();
    assert!(
        seen.len() >= 20 && floors >= 1,
        "the overview sees {} objects, {floors} floors",
        seen.len()
    );
    // The robot turns for a third of a second: its eye's view changes, the fixed one's hardly.
    let mut action = vec![0.0; env.robot().unwrap().action_dim()];
    action[5] = 1.0;
    let mut last = first.clone();
    for _ in 0..10 {
        last = env.step(&action).unwrap().obs;
    }
    let same = |key: &str| {
        let (Pixels::F32(a), Pixels::F32(b)) = (&get(&first, key).data, &get(&last, key).data)
        else {
            panic!("depth is f32")
        };
        a.iter().zip(b).filter(|(x, y)| x == y).count() as f64 / a.len() as f64
    };
    assert!(
        same("still/depth") > 0.9,
        "the fixed camera's depth: {:.3} unchanged",
        same("still/depth")
    );
    assert!(
        same("depth") < 0.5,
        "the eye's depth: {:.3} unchanged",
        same("depth")
    );
}

#[test]
fn occlusion_culling_leaves_the_eye_s_images_as_they_are_in_furnished_homes() {
    use behavior_render::{Camera, Renderer, Scene, View};
    let mut culled_somewhere = 0;
    let mut renderer = Renderer::new().unwrap();
    for name in [
        "bringing_in_wood",
        "re-shelving_library_books",
        "laying_tile_floors",
    ] {
        let mut env = Env::new(config(name));
        env.reset(0).unwrap();
        let world = env.world().unwrap();
        let camera = Camera::eye(env.robot().unwrap().camera_pose(world));
        let table = categories(&common::taxonomy());
        let scene = Scene {
            world,
            categories: &table,
            highlight: &[],
            hidden: &[],
        };
        let mut frames = Vec::new();
        for cull in [true, false] {
            renderer.set_occlusion_culling(cull);
            let mut view = View::new(camera);
            frames.push(renderer.render(&scene, &mut view, &Modality::ALL).unwrap());
            if cull {
                culled_somewhere += renderer.stats().culled;
            }
        }
        assert_eq!(
            frames[0], frames[1],
            "{name}: culling changed the eye's images"
        );
    }
    assert!(culled_somewhere > 0, "nothing was culled in three homes");
}

/// In a home, with its rooms' lamps and the sun's shadow maps: the realistic and the fast
/// profile differ only in colour, step after step.
#[test]
fn the_image_profiles_differ_in_colour_only() {
    let observe = |profile: ImageProfile| {
        let mut config = config("re-shelving_library_books");
        config.observations.camera = Some(CameraConfig {
            modalities: vec![
                Modality::Rgb,
                Modality::Depth,
                Modality::Seg,
                Modality::Flow,
            ],
            profile,
            ..CameraConfig::default()
        });
        let mut env = Env::new(config);
        let (first, _) = env.reset(0).unwrap();
        let mut action = vec![0.0; env.robot().unwrap().action_dim()];
        action[0] = 0.5;
        action[5] = 0.5;
        let last = (0..5)
            .map(|_| env.step(&action).unwrap().obs)
            .last()
            .unwrap();
        [first, last]
    };
    let (realistic, fast) = (
        observe(ImageProfile::Realistic),
        observe(ImageProfile::Fast),
    );
    for (r, f) in realistic.iter().zip(&fast) {
        for key in ["depth", "seg", "flow"] {
            assert_eq!(
                get(r, key),
                get(f, key),
                "{key} differs between the profiles"
            );
        }
        assert_ne!(
            get(r, "rgb"),
            get(f, "rgb"),
            "the profiles drew the same colours"
        );
    }
    assert_eq!(
        realistic,
        observe(ImageProfile::Realistic),
        "the realistic images changed"
    );
}
