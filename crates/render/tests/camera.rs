//! The renderer on a small real scene: a red box 2 m in front of a camera, apples raw and
//! cooked, a lidar beside the box.

use behavior_core::{Ability, Predicate, RoomType};
use behavior_render::{
    Camera, CategoryTable, Frame, ImageProfile, Lidar, Modality, Pattern, Pixels, Renderer, Scene,
    View,
};
use behavior_sim::{
    Material, Model, ModelLibrary, ModelPiece, ObjectId, ObjectSpec, Part, Primitive, QueryFilter,
    Room, Visual, VisualMesh, World,
};
use rapier3d::math::{Pose, Vector};
use std::sync::Arc;

fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

/// A fixed 20 cm red box whose near face is 2 m ahead of the origin.
fn red_box(world: &mut World) -> ObjectId {
    let cube = Part::new(Primitive::Box {
        half_extents: Vector::splat(0.1),
    });
    let spec = ObjectSpec::new("box_1", "carton.n.02", vec![cube])
        .looks([220, 30, 30], Material::Plastic)
        .at(v(2.1, 0.0, 0.0))
        .fixed();
    world.add(spec).unwrap()
}

fn categories() -> CategoryTable {
    CategoryTable::new(["carton.n.02", "apple.n.01"])
}

/// `world` labelled by `categories`, nothing highlighted or hidden.
fn scene<'a>(world: &'a World, categories: &'a CategoryTable) -> Scene<'a> {
    Scene {
        world,
        categories,
        highlight: &[],
        hidden: &[],
    }
}

fn render(
    world: &World,
    view: &mut View,
    highlight: &[ObjectId],
    modalities: &[Modality],
) -> Frame {
    let categories = categories();
    let scene = Scene {
        highlight,
        ..scene(world, &categories)
    };
    let mut renderer =
        Renderer::new().expect("a renderer (install mesa-vulkan-drivers libvulkan1)");
    renderer.render(&scene, view, modalities).unwrap()
}

fn u8s(frame: &Frame, m: Modality) -> &[u8] {
    match &frame.get(m).unwrap().pixels {
        Pixels::U8(p) => p,
        other => panic!("{m}: {other:?}"),
    }
}

fn f32s(frame: &Frame, m: Modality) -> &[f32] {
    match &frame.get(m).unwrap().pixels {
        Pixels::F32(p) => p,
        other => panic!("{m}: {other:?}"),
    }
}

#[test]
fn a_red_box_ahead_is_red_two_metres_away_facing_the_camera_and_labelled() {
    let mut world = World::default();
    let id = red_box(&mut world);
    let mut view = View::new(Camera::eye(Pose::IDENTITY));
    let frame = render(&world, &mut view, &[id], &Modality::ALL);
    assert_eq!((frame.width, frame.height), (128, 128));
    let centre = frame.index(64, 64);
    let rgb = &u8s(&frame, Modality::Rgb)[3 * centre..3 * centre + 3];
    assert!(
        rgb[0] > 100 && rgb[0] > 3 * rgb[1] && rgb[0] > 3 * rgb[2],
        "{rgb:?}"
    );
    let depth = f32s(&frame, Modality::Depth)[centre];
    assert!((depth - 2.0).abs() < 0.01, "depth {depth}");
    let normal = &f32s(&frame, Modality::Normal)[3 * centre..3 * centre + 3];
    assert!(
        normal[0] < -0.99,
        "the face looks back at the camera: {normal:?}"
    );
    let Pixels::U32(ins) = &frame.get(Modality::InsSeg).unwrap().pixels else {
        panic!()
    };
    assert_eq!(ins[centre], id.0 + 1);
    let Pixels::U16(seg) = &frame.get(Modality::Seg).unwrap().pixels else {
        panic!()
    };
    assert_eq!(seg[centre], categories().id("carton.n.02"));
    assert_eq!(u8s(&frame, Modality::Highlight)[centre], 1);
    // A corner pixel sees nothing.
    let corner = frame.index(0, 0);
    assert_eq!(
        (
            ins[corner],
            seg[corner],
            f32s(&frame, Modality::Depth)[corner]
        ),
        (0, 0, 0.0)
    );
    // The image spans 2 · 2 m · tan 60° = 6.93 m at 2 m, over 128 pixels: the box 3.7 of them.
    let wide = (0..128)
        .filter(|&x| ins[frame.index(x, 64)] == id.0 + 1)
        .count();
    let expected = 0.2 / (2.0 * 2.0 * 60f32.to_radians().tan()) * 128.0;
    assert!(
        (wide as f32 - expected).abs() <= 1.5,
        "{wide} pixels wide, expected {expected}"
    );
}

#[test]
fn moving_the_box_one_pixel_width_gives_a_flow_of_one_pixel() {
    let mut world = World::default();
    let id = red_box(&mut world);
    let mut view = View::new(Camera::eye(Pose::IDENTITY));
    let first = render(
        &world,
        &mut view,
        &[],
        &[Modality::Flow, Modality::SceneFlow],
    );
    assert!(
        f32s(&first, Modality::Flow).iter().all(|&f| f == 0.0),
        "nothing moved yet"
    );
    // One pixel at 2 m: the image's 2·2·tan(60°) m over 128 pixels; toward −y is rightward.
    let pixel = 2.0 * 2.0 * 60f32.to_radians().tan() / 128.0;
    let moved = Pose::from_translation(v(2.1, -pixel, 0.0));
    world.bodies_mut().set_pose(id, moved).unwrap();
    let frame = render(
        &world,
        &mut view,
        &[],
        &[Modality::Flow, Modality::SceneFlow, Modality::InsSeg],
    );
    let Pixels::U32(ins) = &frame.get(Modality::InsSeg).unwrap().pixels else {
        panic!()
    };
    let flow = f32s(&frame, Modality::Flow);
    let scene = f32s(&frame, Modality::SceneFlow);
    let mut seen = 0;
    for (k, _) in ins.iter().enumerate().filter(|&(_, &i)| i == id.0 + 1) {
        let (dx, dy) = (flow[2 * k], flow[2 * k + 1]);
        assert!(
            (dx - 1.0).abs() < 0.05 && dy.abs() < 0.05,
            "flow ({dx}, {dy}) at {k}"
        );
        assert!(
            (scene[3 * k + 1] + pixel).abs() < 1e-4,
            "scene flow {:?}",
            &scene[3 * k..3 * k + 3]
        );
        seen += 1;
    }
    // 0.2 m at 2 m is 3.7 pixels of 128 over 120°: a 4 × 4 square, or 3 × 4 moved.
    assert!(seen >= 12, "{seen} box pixels");
}

#[test]
fn lidar_ranges_are_the_distances_of_the_world_rays() {
    let mut world = World::default();
    red_box(&mut world);
    let lidar = Lidar {
        pose: Pose::IDENTITY,
        pattern: Pattern::Planar {
            beams: 181,
            fov: std::f32::consts::PI,
        },
        min_range: 0.05,
        max_range: 10.0,
    };
    let scan = lidar.scan(&world, &QueryFilter::default()).unwrap();
    assert_eq!((scan.rows, scan.columns, scan.ranges.len()), (1, 181, 181));
    let (_, _, directions) = lidar.directions();
    for (range, d) in scan.ranges.iter().zip(&directions) {
        let ray = world
            .query()
            .cast_ray(Vector::ZERO, *d, 10.0, &QueryFilter::default())
            .unwrap();
        assert_eq!(*range, ray.map_or(0.0, |h| h.distance));
    }
    // The middle beam looks straight at the box's face.
    assert!((scan.ranges[90] - 2.0).abs() < 1e-4);
    assert_eq!(
        scan.points.len(),
        scan.ranges.iter().filter(|&&r| r > 0.0).count()
    );
    let cloud = Lidar {
        pattern: Pattern::MultiBeam {
            rows: 16,
            columns: 360,
            vertical_fov: 30f32.to_radians(),
        },
        ..lidar
    };
    let scan = cloud.scan(&world, &QueryFilter::default()).unwrap();
    assert_eq!((scan.rows, scan.columns), (16, 360));
    assert!(scan.points.iter().all(|p| (p[0] - 2.0).abs() < 0.21));
}

/// Two apples side by side, the right one cooked; the mean colour of each one's pixels.
#[test]
fn a_cooked_apple_renders_browner_than_a_raw_one() {
    let mut world = World::default();
    let apple = |world: &mut World, name: &str, y: f32| {
        let ball = Part::new(Primitive::Sphere { radius: 0.1 });
        let spec = ObjectSpec::new(name, "apple.n.01", vec![ball])
            .looks([200, 35, 30], Material::Food)
            .ability(Ability::Cookable, &[])
            .at(v(1.0, y, 0.0))
            .fixed();
        world.add(spec).unwrap()
    };
    let raw = apple(&mut world, "apple_1", 0.2);
    let cooked = apple(&mut world, "apple_2", -0.2);
    world.set_state(cooked, Predicate::Cooked, true).unwrap();
    let narrow = Camera {
        vertical_fov: 0.8,
        ..Camera::eye(Pose::IDENTITY)
    };
    let mut view = View::new(narrow);
    let frame = render(&world, &mut view, &[], &[Modality::Rgb, Modality::InsSeg]);
    let Pixels::U32(ins) = &frame.get(Modality::InsSeg).unwrap().pixels else {
        panic!()
    };
    let rgb = u8s(&frame, Modality::Rgb);
    let mean = |id: ObjectId| {
        let px: Vec<usize> = (0..ins.len()).filter(|&k| ins[k] == id.0 + 1).collect();
        assert!(px.len() > 50);
        let sum = px.iter().fold([0f32; 3], |s, &k| {
            std::array::from_fn(|c| s[c] + f32::from(rgb[3 * k + c]))
        });
        sum.map(|c| c / px.len() as f32)
    };
    let (r, c) = (mean(raw), mean(cooked));
    // Brown: less red than the raw apple's red, more green, redder than it is green or blue.
    assert!(c[0] < r[0] && c[1] > r[1], "raw {r:?}, cooked {c:?}");
    assert!(c[0] > c[1] && c[1] > c[2], "cooked {c:?} is not brown");
}

#[test]
fn two_renders_of_the_same_state_are_identical() {
    let mut world = World::default();
    red_box(&mut world);
    let eye = Camera::looking_at(v(-1.0, 1.0, 1.0), v(2.0, 0.0, 0.0), 96, 64, 1.0);
    let a = render(&world, &mut View::new(eye), &[], &Modality::ALL);
    let b = render(&world, &mut View::new(eye), &[], &Modality::ALL);
    assert_eq!(a, b);
    assert_eq!((a.width, a.height), (96, 64));
    assert_eq!(a.get(Modality::Rgb).unwrap().shape, vec![64, 96, 3]);
}

#[test]
fn only_the_modalities_asked_for_come_back() {
    let mut world = World::default();
    red_box(&mut world);
    let frame = render(
        &world,
        &mut View::new(Camera::eye(Pose::IDENTITY)),
        &[],
        &[Modality::Depth],
    );
    assert_eq!(frame.images.len(), 1);
    assert!(frame.get(Modality::Rgb).is_none());
    let mut bad = Camera::eye(Pose::IDENTITY);
    bad.width = 0;
    let categories = categories();
    let scene = scene(&world, &categories);
    let err = Renderer::new()
        .unwrap()
        .render(&scene, &mut View::new(bad), &[Modality::Rgb])
        .unwrap_err();
    assert!(err.to_string().contains("width"), "{err}");
}

/// Each frame writes only the targets its modalities need (depth alone, or with the normals);
/// every modality must come out the same whatever it is asked with.
#[test]
fn a_modality_asked_for_alone_equals_it_asked_for_with_all_the_others() {
    let mut world = World::default();
    red_box(&mut world);
    red_box_at(&mut world, 1, v(3.0, 0.6, 0.4));
    let eye = Camera::looking_at(v(-1.0, 1.0, 1.0), v(2.0, 0.0, 0.0), 64, 48, 1.2);
    let all = render(&world, &mut View::new(eye), &[], &Modality::ALL);
    for m in Modality::ALL {
        for with in [vec![m], vec![m, Modality::Rgb], vec![m, Modality::Depth]] {
            let frame = render(&world, &mut View::new(eye), &[], &with);
            assert_eq!(frame.get(m), all.get(m), "{m} asked with {with:?}");
        }
    }
    let depth = all.get(Modality::Depth).unwrap();
    let Pixels::F32(d) = &depth.pixels else {
        panic!("depth is f32")
    };
    assert!(d.iter().any(|&x| x > 1.0), "no box seen");
}

/// A fixed grey box (a wall, a crate) of `half` extents at `at`.
fn slab(world: &mut World, name: &str, at: Vector, half: Vector) -> ObjectId {
    let part = Part::new(Primitive::Box { half_extents: half });
    let spec = ObjectSpec::new(name, "carton.n.02", vec![part])
        .looks([150, 150, 150], Material::Plastic)
        .at(at)
        .fixed();
    world.add(spec).unwrap()
}

#[test]
fn what_walls_hide_is_left_out_without_changing_a_pixel() {
    // A wall 3 m ahead with a 0.6 m doorway in its middle; four crates behind it, and one
    // farther on, seen through the doorway.
    let mut world = World::default();
    slab(&mut world, "wall_left", v(3.0, 2.3, 1.0), v(0.05, 2.0, 2.0));
    slab(
        &mut world,
        "wall_right",
        v(3.0, -2.3, 1.0),
        v(0.05, 2.0, 2.0),
    );
    let mut behind = Vec::new();
    for (k, y) in [-2.5f32, -1.5, 1.5, 2.5].into_iter().enumerate() {
        behind.push(red_box_at(&mut world, k, v(5.0, y, 0.5)));
    }
    let through_door = red_box_at(&mut world, 9, v(6.0, 0.0, 0.3));
    let mut view = View::new(Camera::eye(Pose::IDENTITY));
    let categories = categories();
    let scene = scene(&world, &categories);
    let mut renderer = Renderer::new().unwrap();
    let culled = renderer.render(&scene, &mut view, &Modality::ALL).unwrap();
    let stats = renderer.stats();
    renderer.set_occlusion_culling(false);
    let mut again = View::new(Camera::eye(Pose::IDENTITY));
    let everything = renderer.render(&scene, &mut again, &Modality::ALL).unwrap();
    assert_eq!(culled, everything, "culling changed the images");
    assert_eq!(renderer.stats().culled, 0);
    assert_eq!(
        (stats.culled, stats.instances, renderer.stats().instances),
        (4, 3, 7),
        "the four crates behind the wall are left out, the one in the doorway is not"
    );
    let Pixels::U32(ins) = &everything.get(Modality::InsSeg).unwrap().pixels else {
        panic!()
    };
    assert!(ins.contains(&(through_door.0 + 1)));
    assert!(behind.iter().all(|id| !ins.contains(&(id.0 + 1))));
}

/// A 20 cm red crate at `at`.
fn red_box_at(world: &mut World, k: usize, at: Vector) -> ObjectId {
    let cube = Part::new(Primitive::Box {
        half_extents: Vector::splat(0.1),
    });
    let spec = ObjectSpec::new(&format!("crate_{k}"), "carton.n.02", vec![cube])
        .looks([220, 30, 30], Material::Plastic)
        .at(at)
        .fixed();
    world.add(spec).unwrap()
}

/// A grey 6 × 6 m ground slab with a tall grey post on it, seen from above and aside.
fn post_on_ground() -> (World, Camera) {
    let mut world = World::default();
    slab(&mut world, "ground", v(0.0, 0.0, -0.05), v(3.0, 3.0, 0.05));
    slab(&mut world, "post", v(0.0, 0.0, 0.75), v(0.15, 0.15, 0.75));
    let eye = Camera::looking_at(v(-4.0, -3.0, 4.0), v(0.0, 0.0, 0.0), 96, 96, 1.3);
    (world, eye)
}

/// The frame of `view` in `profile`, every modality.
fn in_profile(world: &World, camera: Camera, profile: ImageProfile) -> Frame {
    render(
        world,
        &mut View::with_profile(camera, profile),
        &[],
        &Modality::ALL,
    )
}

#[test]
fn both_profiles_give_the_same_depth_normals_segmentation_and_flow() {
    let (mut world, eye) = post_on_ground();
    red_box_at(&mut world, 1, v(1.0, -1.0, 0.1));
    let realistic = in_profile(&world, eye, ImageProfile::Realistic);
    let fast = in_profile(&world, eye, ImageProfile::Fast);
    for m in Modality::ALL.into_iter().filter(|&m| m != Modality::Rgb) {
        assert_eq!(
            realistic.get(m),
            fast.get(m),
            "{m} differs between the profiles"
        );
    }
    assert_ne!(
        u8s(&realistic, Modality::Rgb),
        u8s(&fast, Modality::Rgb),
        "the profiles drew the same colours"
    );
}

/// The brightness (sum of RGB) of the ground's pixels.
fn ground_brightness(frame: &Frame, ground: ObjectId) -> Vec<u32> {
    let Pixels::U32(ins) = &frame.get(Modality::InsSeg).unwrap().pixels else {
        panic!()
    };
    let rgb = u8s(frame, Modality::Rgb);
    (0..ins.len())
        .filter(|&k| ins[k] == ground.0 + 1)
        .map(|k| rgb[3 * k..3 * k + 3].iter().map(|&c| u32::from(c)).sum())
        .collect()
}

/// The brightness (sum of RGB) of a 64² frame's middle pixel, which must show `object`.
fn middle_brightness(frame: &Frame, object: ObjectId) -> f32 {
    let Pixels::U32(ids) = &frame.get(Modality::InsSeg).unwrap().pixels else {
        panic!("instance ids are u32")
    };
    let k = 32 * 64 + 32;
    assert_eq!(ids[k], object.0 + 1, "the middle pixel is not {object:?}");
    u8s(frame, Modality::Rgb)[3 * k..3 * k + 3]
        .iter()
        .map(|&c| u32::from(c))
        .sum::<u32>() as f32
}

/// The post shades part of the ground in the realistic profile; the fast one has no shadows.
#[test]
fn the_sun_casts_the_shadow_of_a_post_on_the_ground() {
    let (world, eye) = post_on_ground();
    let ground = world.bodies().object_named("ground").unwrap();
    let brightness = |profile| ground_brightness(&in_profile(&world, eye, profile), ground);
    let (fast, real) = (
        brightness(ImageProfile::Fast),
        brightness(ImageProfile::Realistic),
    );
    let median = |b: &[u32]| {
        let mut sorted = b.to_vec();
        sorted.sort_unstable();
        sorted[sorted.len() / 2] as f32
    };
    // The ground's top face: what the fast profile, which has no shadows, draws evenly (its
    // edges, facing sideways, are darker); most of it is in the sun.
    let (fast_lit, real_lit) = (median(&fast), median(&real));
    let top: Vec<usize> = (0..fast.len())
        .filter(|&k| fast[k] as f32 >= 0.8 * fast_lit)
        .collect();
    assert!(
        top.len() > fast.len() * 3 / 4,
        "{} of {} on top",
        top.len(),
        fast.len()
    );
    let shaded = top
        .iter()
        .filter(|&&k| (real[k] as f32) < 0.6 * real_lit)
        .count();
    // The post's shadow: 0.3 m wide and at least 1.5 m long on the ground (the sun is at most
    // 60° high), some dozens of pixels of the 96² image; the textured ground alone varies by
    // a few per cent.
    assert!(
        shaded >= 20 && shaded < top.len() / 2,
        "{shaded} of {} top pixels in shadow",
        top.len()
    );
}

/// Ambient occlusion: a low board over the ground (a table top, 4 m square at 0.5 m: whatever
/// the sun's height and side, its shadow covers the middle) dims the ground under it beyond its
/// shadow, by what it hides of the sky; turned off, the same frame is lighter there, and the
/// other modalities are the same either way.
#[test]
fn a_board_overhead_dims_the_ground_under_it_beyond_its_shadow() {
    let mut world = World::default();
    slab(&mut world, "ground", v(0.0, 0.0, -0.05), v(4.0, 4.0, 0.05));
    slab(&mut world, "board", v(0.0, 0.0, 0.5), v(2.0, 2.0, 0.01));
    let eye = Camera::looking_at(v(-3.0, -2.0, 0.3), v(0.0, 0.0, 0.0), 64, 64, 0.6);
    let categories = categories();
    let scene = scene(&world, &categories);
    let mut renderer = Renderer::new().unwrap();
    let mut frame = |occlusion: bool| {
        renderer.set_ambient_occlusion(occlusion);
        let mut view = View::with_profile(eye, ImageProfile::Realistic);
        renderer.render(&scene, &mut view, &Modality::ALL).unwrap()
    };
    let (with, without) = (frame(true), frame(false));
    let ins = |f: &Frame| f.get(Modality::InsSeg).cloned();
    assert_eq!(ins(&with), ins(&without), "occlusion changed what is seen");
    let ground = world.bodies().object_named("ground").unwrap();
    let (dim, lit) = (
        middle_brightness(&with, ground),
        middle_brightness(&without, ground),
    );
    assert!(
        dim < 0.85 * lit,
        "the ground under the board is {dim} with occlusion, {lit} without"
    );
}

/// The lamp of the camera's room casts shadows: a board hung 1 m up under the lamp (which hangs
/// 2.3 m up over the middle of a 6 m room) darkens the floor straight under it. A ceiling keeps
/// the sun out and ambient occlusion is off, so that only the lamp's shadow can tell the floor
/// with the board from the floor without.
#[test]
fn the_lamp_of_the_cameras_room_shades_the_floor_under_a_board() {
    let room = |world: &mut World| {
        let floor = slab(world, "ground", v(0.0, 0.0, -0.05), v(3.0, 3.0, 0.05));
        slab(world, "ceiling", v(0.0, 0.0, 2.55), v(3.0, 3.0, 0.05));
        world.add_room(Room {
            kind: RoomType::LivingRoom,
            instance: 0,
            min: [-3.0, -3.0],
            max: [3.0, 3.0],
            annexes: Vec::new(),
            floor: Some(floor),
        });
        floor
    };
    let mut bare = World::default();
    let ground = room(&mut bare);
    let mut boarded = World::default();
    room(&mut boarded);
    slab(&mut boarded, "board", v(0.0, 0.0, 1.0), v(0.3, 0.3, 0.01));
    // Low, from the side: the floor's middle is seen under the board.
    let eye = Camera::looking_at(v(-2.5, 0.0, 0.3), v(0.0, 0.0, 0.0), 64, 64, 0.6);
    let categories = categories();
    let mut renderer = Renderer::new().unwrap();
    renderer.set_ambient_occlusion(false);
    let mut middle = |world: &World| {
        let mut view = View::with_profile(eye, ImageProfile::Realistic);
        let frame = renderer
            .render(
                &scene(world, &categories),
                &mut view,
                &[Modality::Rgb, Modality::InsSeg],
            )
            .unwrap();
        middle_brightness(&frame, ground)
    };
    let (lit, shaded) = (middle(&bare), middle(&boarded));
    assert!(
        shaded < 0.85 * lit,
        "the floor under the board is {shaded}, without the board {lit}"
    );
}

/// Patterns follow the object's seed (its name): two boards alike but for their names differ
/// in texture, and each is drawn the same again.
#[test]
fn patterns_change_with_the_object_and_repeat_for_it() {
    let board = |world: &mut World, name: &str, y: f32| {
        let part = Part::new(Primitive::Box {
            half_extents: v(0.05, 0.3, 0.3),
        });
        let spec = ObjectSpec::new(name, "carton.n.02", vec![part])
            .looks([170, 120, 80], Material::Wood)
            .at(v(1.5, y, 0.0))
            .fixed();
        world.add(spec).unwrap()
    };
    let texture = |name: &str| {
        let mut world = World::default();
        board(&mut world, name, 0.0);
        let eye = Camera::looking_at(v(0.0, 0.0, 0.0), v(1.5, 0.0, 0.0), 64, 64, 0.5);
        let frame = in_profile(&world, eye, ImageProfile::Realistic);
        u8s(&frame, Modality::Rgb).to_vec()
    };
    let (a, b) = (texture("board_1"), texture("board_2"));
    assert_eq!(a, texture("board_1"), "the same board drew differently");
    let differing = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| x.abs_diff(**y) > 4)
        .count();
    assert!(
        differing > 300,
        "only {differing} channels differ between two boards"
    );
}

/// An 8-sided diamond (an octahedron) of `radius`, as a model piece's mesh: closed, outward.
fn diamond(radius: f32, color: [u8; 3]) -> VisualMesh {
    let r = radius;
    let vertices = vec![
        v(r, 0.0, 0.0),
        v(-r, 0.0, 0.0),
        v(0.0, r, 0.0),
        v(0.0, -r, 0.0),
        v(0.0, 0.0, r),
        v(0.0, 0.0, -r),
    ];
    let triangles = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    VisualMesh {
        link: None,
        vertices,
        triangles,
        visual: Visual {
            color,
            material: Material::Plastic,
        },
    }
}

#[test]
fn a_model_piece_is_drawn_from_its_meshes_where_the_renderer_holds_them() {
    let piece = ModelPiece {
        model: Model::Fetch,
        piece: 3,
    };
    let mut world = World::default();
    // A 20 cm box standing in for the piece, 28 cm ahead: 23 px in radius on the image.
    let cube = Part::new(Primitive::Box {
        half_extents: Vector::splat(0.1),
    });
    let mut spec = ObjectSpec::new("link_1", "agent.n.01", vec![cube])
        .looks([220, 30, 30], Material::Plastic)
        .at(v(0.28, 0.0, 0.0))
        .fixed();
    spec.model = Some(piece);
    let id = world.add(spec).unwrap();
    let mut library = ModelLibrary::default();
    library.insert(piece, vec![diamond(0.1, [20, 200, 20])]);
    let library = Arc::new(library);
    let categories = categories();
    let mut renderer = Renderer::new().unwrap();
    let draw = |renderer: &mut Renderer, camera: Camera| {
        let mut view = View::new(camera);
        let frame = renderer
            .render(
                &scene(&world, &categories),
                &mut view,
                &[Modality::Rgb, Modality::InsSeg],
            )
            .unwrap();
        let Pixels::U32(ins) = &frame.get(Modality::InsSeg).unwrap().pixels else {
            panic!("instance ids are u32");
        };
        let count = ins.iter().filter(|&&i| i == id.0 + 1).count();
        let centre = frame.index(64, 64);
        let rgb = u8s(&frame, Modality::Rgb)[3 * centre..3 * centre + 3].to_vec();
        (count, rgb)
    };
    let ahead = Camera::eye(Pose::IDENTITY);
    let (boxed, box_rgb) = draw(&mut renderer, ahead);
    renderer.set_models(library.clone());
    let (cut, diamond_rgb) = draw(&mut renderer, ahead);
    // Seen along an axis, the diamond's outline is a square turned 45° in its middle plane, 28 cm
    // away, with corners 10 cm out; the box's near face, 18 cm away, is 20 cm wide: in
    // perspective 2·(0.1/0.28)² against (0.2/0.18)², a fifth of the pixels.
    assert!(boxed > 1000, "the box covers {boxed} px");
    let share = cut as f32 / boxed as f32;
    assert!((0.16..0.26).contains(&share), "{cut} of {boxed} px");
    assert!(
        box_rgb[0] > 2 * box_rgb[1],
        "the stand-in is red: {box_rgb:?}"
    );
    assert!(
        diamond_rgb[1] > 2 * diamond_rgb[0],
        "the mesh is green: {diamond_rgb:?}"
    );
    // Far away (under 20 px in radius) the stand-in is drawn again: 10 m ahead, about 3 px.
    let far = Camera::eye(Pose::from_translation(v(-9.0, 0.0, 0.0)));
    let (far_count, _) = draw(&mut renderer, far);
    let mut plain = Renderer::new().unwrap();
    assert_eq!(draw(&mut plain, far).0, far_count, "far away it is its box");
    // A camera inside the piece's box draws nothing of it.
    let inside = Camera::eye(Pose::from_translation(v(0.28, 0.0, 0.0)));
    assert_eq!(draw(&mut renderer, inside).0, 0);
    // Without the library again, the box is back, pixel for pixel.
    renderer.set_models(Arc::new(ModelLibrary::default()));
    assert_eq!(draw(&mut renderer, ahead), (boxed, box_rgb));
}

/// Normal detail: a kitchen's tiled floor, seen from close above, shades the bevelled edges of
/// its tiles by their relief as well as their colour; turned off, the tiles' faces are the same
/// and the edges differ, and every other modality (the normal one included) is the same.
#[test]
fn a_tiled_floor_shades_its_grout_by_its_relief() {
    let mut world = World::default();
    let part = Part::new(Primitive::Box {
        half_extents: v(2.0, 2.0, 0.05),
    });
    let floor = world
        .add(
            ObjectSpec::new("floor_kitchen_0", "floor.n.01", vec![part])
                .looks([200, 200, 200], Material::Stone)
                .at(v(0.0, 0.0, -0.05))
                .fixed(),
        )
        .unwrap();
    world.add_room(Room {
        kind: RoomType::Kitchen,
        instance: 0,
        min: [-2.0, -2.0],
        max: [2.0, 2.0],
        annexes: Vec::new(),
        floor: Some(floor),
    });
    // 40 cm above the floor, looking down a little aslant: a pixel is about 3.5 mm there, so the
    // tiles' 12 mm bevels span enough pixels to be drawn (finer relief fades out), and a grout
    // line or two of the 20 or 30 cm tiles is in view wherever the tiles start.
    let eye = Camera::looking_at(v(-0.1, -0.05, 0.4), v(0.05, 0.05, 0.0), 128, 128, 1.0);
    let categories = categories();
    let mut renderer = Renderer::new().unwrap();
    let mut frame = |detail: bool| {
        renderer.set_normal_detail(detail);
        let mut view = View::with_profile(eye, ImageProfile::Realistic);
        renderer
            .render(&scene(&world, &categories), &mut view, &Modality::ALL)
            .unwrap()
    };
    let (with, without) = (frame(true), frame(false));
    for m in Modality::ALL.into_iter().filter(|&m| m != Modality::Rgb) {
        assert_eq!(
            with.get(m),
            without.get(m),
            "{m} changed with normal detail"
        );
    }
    let (a, b) = (u8s(&with, Modality::Rgb), u8s(&without, Modality::Rgb));
    let changed = (0..a.len() / 3)
        .filter(|&k| (0..3).any(|c| a[3 * k + c].abs_diff(b[3 * k + c]) > 2))
        .count();
    // The grout lines: a few per cent of the floor's pixels, not the tiles' faces.
    assert!(
        changed > 50 && changed < a.len() / 3 / 3,
        "{changed} of {} pixels changed by the relief",
        a.len() / 3
    );
}

/// A closed room 4 m square, 2.5 m high, its walls 10 cm thick, with a window 1.4 m wide in
/// the middle of each wall from 0.9 to 2.1 m (`windows`) or none; no ceiling, seen from above.
fn room(windows: bool) -> (World, ObjectId, Camera) {
    let mut world = World::default();
    let floor = slab(&mut world, "floor", v(0.0, 0.0, -0.05), v(2.0, 2.0, 0.05));
    let wall = |world: &mut World, name: &str, at: Vector, half: Vector| {
        let part = Part::new(Primitive::Box { half_extents: half });
        let spec = ObjectSpec::new(name, "wall.n.01", vec![part])
            .looks([200, 200, 200], Material::Stone)
            .at(at)
            .fixed();
        world.add(spec).unwrap();
    };
    wall(
        &mut world,
        "wall_s",
        v(0.0, -2.05, 1.25),
        v(2.1, 0.05, 1.25),
    );
    wall(&mut world, "wall_n", v(0.0, 2.05, 1.25), v(2.1, 0.05, 1.25));
    wall(
        &mut world,
        "wall_w",
        v(-2.05, 0.0, 1.25),
        v(0.05, 2.0, 1.25),
    );
    wall(&mut world, "wall_e", v(2.05, 0.0, 1.25), v(0.05, 2.0, 1.25));
    if windows {
        let frames = [
            (v(0.0, -1.95, 1.5), v(0.7, 0.02, 0.6)),
            (v(0.0, 1.95, 1.5), v(0.7, 0.02, 0.6)),
            (v(-1.95, 0.0, 1.5), v(0.02, 0.7, 0.6)),
            (v(1.95, 0.0, 1.5), v(0.02, 0.7, 0.6)),
        ];
        for (k, (at, half)) in frames.into_iter().enumerate() {
            let pane = Part::new(Primitive::Box { half_extents: half });
            let spec = ObjectSpec::new(&format!("window_{k}"), "window.n.01", vec![pane])
                .looks([170, 210, 240], Material::Glass)
                .at(at)
                .fixed();
            world.add(spec).unwrap();
        }
    }
    let above = Camera::looking_at(v(0.01, 0.0, 9.0), v(0.0, 0.0, 0.0), 96, 96, 0.9);
    (world, floor, above)
}

/// The sun comes into a walled room through its windows only (the default): a windowless
/// room's floor is all in shade (the homes have no ceilings, but the sun's map lays a roof over
/// the walls), and with a window in each wall the sun lights patches of the floor under the one
/// it faces. (`Renderer::set_sun_through_windows(false)` lets the sun fall from above too; in a
/// room this small the walls shade most of the floor from the side anyway, 319 against 316 as
/// the floor's median brightness, so that is left to the post's test.)
#[test]
fn the_sun_comes_into_a_room_through_its_windows() {
    let lit_with = |windows, through: Option<bool>| {
        let (world, floor, above) = room(windows);
        let categories = categories();
        let mut renderer = Renderer::new().unwrap();
        if let Some(on) = through {
            renderer.set_sun_through_windows(on);
        }
        let mut view = View::with_profile(above, ImageProfile::Realistic);
        let frame = renderer
            .render(&scene(&world, &categories), &mut view, &Modality::ALL)
            .unwrap();
        let b = ground_brightness(&frame, floor);
        let median = {
            let mut s = b.clone();
            s.sort_unstable();
            s[s.len() / 2]
        };
        let bright = b
            .iter()
            .filter(|&&x| x as f32 > 1.5 * median as f32)
            .count();
        (bright, b.len())
    };
    // The default.
    let lit = |windows| lit_with(windows, None);
    let (closed, seen) = lit(false);
    assert!(seen > 1000, "the floor fills the view: {seen} pixels");
    assert!(
        closed < seen / 50,
        "{closed} of {seen} floor pixels sunlit without a window"
    );
    let (open, seen) = lit(true);
    // Measured: none closed; 143 of 1,936 (7 %) through the windows.
    assert_eq!(
        lit_with(true, Some(true)),
        (open, seen),
        "the default is through the windows"
    );
    assert!(
        open > seen / 30,
        "only {open} of {seen} floor pixels sunlit through the windows"
    );
}
