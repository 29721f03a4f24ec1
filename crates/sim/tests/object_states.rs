//! One small physical scene per object-state rule; test names carry the predicate they check.

mod common;

use behavior_core::Predicate;
use behavior_sim::{Drive, World};
use common::*;

#[test]
fn cooked_then_burnt_on_a_lit_stove_at_the_thresholds_and_cooling_afterwards() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let stove = stove(&mut world, -1.0, 0.0);
    let apple = sliceable_apple(&mut world, "apple_1", v(-1.0, 0.0, 1.0));
    settle(&mut world, 1.0);
    assert!(world.relations().ontop(apple, stove));
    // Off, nothing happens.
    settle(&mut world, 5.0);
    assert!(!world.state(apple, Predicate::Cooked));
    world.set_state(stove, Predicate::ToggledOn, true).unwrap();
    let (mut cooked_at, mut burnt_at) = (None, None);
    for step in 0..30 * 60 {
        let before = world.temperature(apple);
        world.step();
        if cooked_at.is_none() && world.state(apple, Predicate::Cooked) {
            cooked_at = Some((step, before, world.temperature(apple)));
        }
        if burnt_at.is_none() && world.state(apple, Predicate::Burnt) {
            burnt_at = Some((step, before, world.temperature(apple)));
        }
    }
    let (cook_step, below, above) = cooked_at.expect("the apple cooks");
    assert!(below < 70.0 && above >= 70.0, "{below} → {above}");
    let (burn_step, below, above) = burnt_at.expect("the apple burns");
    assert!(below < 200.0 && above >= 200.0, "{below} → {above}");
    assert!(cook_step < burn_step);
    // 500 °C at 0.02 /s from 23 °C: 70 °C after ln(477/430)/0.02 ≈ 5.2 s, 200 °C after ≈ 23.4 s.
    assert!((150..160).contains(&cook_step), "{cook_step}");
    assert!((695..710).contains(&burn_step), "{burn_step}");
    // Off again: the apple cools toward 23 °C but stays cooked and burnt.
    world.set_state(stove, Predicate::ToggledOn, false).unwrap();
    let hot = world.temperature(apple);
    settle(&mut world, 20.0);
    assert!(world.temperature(apple) < hot - 50.0);
    assert!(world.state(apple, Predicate::Cooked) && world.state(apple, Predicate::Burnt));
}

#[test]
fn cooked_setter_keeps_the_temperature_history_consistent() {
    let mut world = World::default();
    let apple = sliceable_apple(&mut world, "apple_1", v(0.0, 0.0, 1.0));
    world.set_state(apple, Predicate::Cooked, true).unwrap();
    assert!(world.state(apple, Predicate::Cooked) && !world.state(apple, Predicate::Burnt));
    world.set_state(apple, Predicate::Burnt, true).unwrap();
    world.set_state(apple, Predicate::Cooked, false).unwrap();
    assert!(!world.state(apple, Predicate::Cooked) && !world.state(apple, Predicate::Burnt));
    let plate = plate(&mut world, v(1.0, 0.0, 1.0));
    let err = world.set_state(plate, Predicate::Cooked, true).unwrap_err();
    assert_eq!(
        err.to_string(),
        "plate_1 (plate.n.04) cannot be cooked: it lacks the `cookable` ability"
    );
}

#[test]
fn frozen_and_inside_in_a_closed_fridge_but_not_with_the_door_open() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let fridge = fridge(&mut world, -2.0, 0.0);
    let apple = sliceable_apple(&mut world, "apple_1", v(-2.0, 0.0, 0.3));
    settle(&mut world, 1.0);
    assert!(world.relations().inside(apple, fridge));
    assert!(!world.state(fridge, Predicate::Open));
    // −18 °C at 0.02 /s from 23 °C crosses 0 °C after ln(41/18)/0.02 ≈ 41 s.
    settle(&mut world, 40.0);
    assert!(!world.state(apple, Predicate::Frozen));
    settle(&mut world, 2.0);
    assert!(
        world.state(apple, Predicate::Frozen),
        "{}",
        world.temperature(apple)
    );
    // With the door open the fridge does not cool, and the apple thaws toward 23 °C.
    world.set_state(fridge, Predicate::Open, true).unwrap();
    settle(&mut world, 5.0);
    assert!(
        !world.state(apple, Predicate::Frozen),
        "{}",
        world.temperature(apple)
    );
    let frozen_setter = sliceable_apple(&mut world, "apple_2", v(2.0, 0.0, 0.1));
    world
        .set_state(frozen_setter, Predicate::Frozen, true)
        .unwrap();
    assert!(world.state(frozen_setter, Predicate::Frozen));
}

#[test]
fn open_when_the_door_is_beyond_five_percent_of_its_range() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let fridge = fridge(&mut world, -2.0, 0.0);
    settle(&mut world, 0.5);
    assert!(world.joints().position(fridge, 0).abs() < 1e-3);
    world
        .joints_mut()
        .set_position(fridge, 0, 0.04 * 2.0)
        .unwrap();
    settle(&mut world, 0.5);
    assert!(
        !world.state(fridge, Predicate::Open),
        "{}",
        world.joints().position(fridge, 0)
    );
    world
        .joints_mut()
        .set_position(fridge, 0, 0.06 * 2.0)
        .unwrap();
    settle(&mut world, 0.5);
    assert!(
        world.state(fridge, Predicate::Open),
        "{}",
        world.joints().position(fridge, 0)
    );
    world.set_state(fridge, Predicate::Open, false).unwrap();
    assert!(!world.state(fridge, Predicate::Open));
    // The setter opens to a random point between the threshold and the limit, and it stays.
    world.set_state(fridge, Predicate::Open, true).unwrap();
    let opened = world.joints().position(fridge, 0);
    assert!((0.06 * 2.0..=2.0).contains(&opened), "{opened}");
    settle(&mut world, 1.0);
    assert!(world.state(fridge, Predicate::Open));
    let apple = sliceable_apple(&mut world, "apple_1", v(2.0, 0.0, 0.1));
    assert!(world.set_state(apple, Predicate::Open, true).is_err());
}

#[test]
fn toggled_on_after_a_hand_stays_five_steps_at_the_button() {
    let mut world = World::default();
    let stove = stove(&mut world, 0.0, 0.0);
    let button = v(0.35, 0.0, 0.8);
    world.set_hand_points(&[button]);
    for _ in 0..4 {
        world.step();
    }
    assert!(!world.state(stove, Predicate::ToggledOn));
    world.step();
    assert!(world.state(stove, Predicate::ToggledOn));
    // Holding on does not toggle again; leaving and coming back does.
    for _ in 0..20 {
        world.step();
    }
    assert!(world.state(stove, Predicate::ToggledOn));
    world.set_hand_points(&[v(2.0, 0.0, 0.8)]);
    world.step();
    world.set_hand_points(&[button]);
    for _ in 0..5 {
        world.step();
    }
    assert!(!world.state(stove, Predicate::ToggledOn));
    // Too far from the button (0.15 m): nothing.
    world.set_hand_points(&[v(0.45, 0.0, 0.8)]);
    for _ in 0..10 {
        world.step();
    }
    assert!(!world.state(stove, Predicate::ToggledOn));
}

#[test]
fn soaked_a_rag_under_a_running_faucet() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let sink = sink(&mut world, -1.0, 0.0);
    let rag = rag(&mut world, v(-1.0, 0.15, 0.7));
    let dry = common::rag(&mut world, v(-2.5, 0.0, 0.1));
    settle(&mut world, 1.0);
    assert!(world.relations().inside(rag, sink) || world.relations().ontop(rag, sink));
    settle(&mut world, 2.0);
    assert!(!world.state(rag, Predicate::Soaked), "the tap is off");
    world.set_state(sink, Predicate::ToggledOn, true).unwrap();
    settle(&mut world, 2.0);
    assert!(!world.drops().is_empty());
    assert!(world.state(rag, Predicate::Soaked));
    assert!(!world.state(dry, Predicate::Soaked));
}

#[test]
fn soaked_water_drops_leave_a_running_faucet_every_fourth_step() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let sink = sink(&mut world, -1.0, 0.0);
    settle(&mut world, 1.0);
    world.set_state(sink, Predicate::ToggledOn, true).unwrap();
    // Steps after which a drop stands at the emission point, 5 cm below the outlet (1 m up):
    // drops are emitted at the end of a step and fall 1.6 cm during the next.
    let outlet = v(-1.0, 0.0, 0.95);
    let mut emitted = Vec::new();
    for step in 0..40 {
        world.step();
        if world.drops().iter().any(|d| (*d - outlet).length() < 1e-3) {
            emitted.push(step);
        }
    }
    let gaps: Vec<i32> = emitted.windows(2).map(|w| w[1] - w[0]).collect();
    assert!(gaps.len() >= 5, "{emitted:?}");
    assert!(
        gaps.iter().all(|&g| g == 4),
        "one drop every 4th step: {emitted:?}"
    );
}

#[test]
fn stained_only_a_soaked_rag_cleans_and_dusty_any_rag_does() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let plate = dirty_plate(&mut world, v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    assert!(world.relations().ontop(plate, table));
    world.set_state(plate, Predicate::Stained, true).unwrap();
    world.set_state(plate, Predicate::Dusty, true).unwrap();
    assert!(world.state(plate, Predicate::Stained) && world.state(plate, Predicate::Dusty));
    assert!(world.particle_positions(plate, Predicate::Stained).len() >= 10);
    // A dry rag laid over the plate takes the dust but not the stains.
    let rag = rag(&mut world, v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    assert!(world.relations().touching(rag, plate));
    assert!(!world.state(plate, Predicate::Dusty));
    assert!(world.state(plate, Predicate::Stained));
    // Soaked, it takes the stains too.
    world.set_state(rag, Predicate::Soaked, true).unwrap();
    world.step();
    assert!(!world.state(plate, Predicate::Stained));
    assert!(
        world.set_state(table, Predicate::Dusty, true).is_err(),
        "a plain table is not dustyable here"
    );
}

/// Pushes an object down with `newtons` for `steps` action steps.
fn press(world: &mut World, object: behavior_sim::ObjectId, newtons: f32, steps: usize) {
    for _ in 0..steps {
        let down = v(0.0, 0.0, -newtons);
        world.bodies_mut().apply_force(object.into(), down).unwrap();
        world.step();
    }
}

/// A knife's centre height when it lies on `object`, 1 mm above its top.
fn laid_on(world: &World, object: behavior_sim::ObjectId) -> f32 {
    world.bodies().aabb(object).maxs.z + 0.021
}

#[test]
fn sliced_a_knife_pushed_into_a_tomato_and_the_halves_inherit_its_states() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let table = table(&mut world, -1.0, 0.0);
    let tomato = sliceable_apple(&mut world, "tomato_1", v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    world.set_state(tomato, Predicate::Cooked, true).unwrap();
    // Resting on a table is no slicing.
    assert!(!world.state(tomato, Predicate::Sliced));
    let z = laid_on(&world, tomato);
    let knife = knife(&mut world, v(-1.0, 0.0, z));
    press(&mut world, knife, 15.0, 30);
    assert!(world.state(tomato, Predicate::Sliced));
    let [a, b] = world.bodies().object(tomato).replaced_by.unwrap();
    assert!(
        world.state(a, Predicate::Cooked) && world.state(b, Predicate::Cooked),
        "halves inherit states"
    );
    assert!(!world.state(knife, Predicate::Sliced));
    settle(&mut world, 1.0);
    assert!(world.relations().ontop(a, table) || world.relations().ontop(b, table));
    assert!(world.set_state(tomato, Predicate::Sliced, false).is_err());
}

/// A tomato on a table with a knife of [`KNIFE_MASS`] laid on it at rest, then pushed down with
/// `push` newtons for two seconds; whether it was sliced.
fn knife_laid_on_a_tomato_and_pushed(push: f32) -> bool {
    let mut world = World::default();
    two_room_floor(&mut world);
    table(&mut world, -1.0, 0.0);
    let tomato = sliceable_apple(&mut world, "tomato_1", v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    let z = laid_on(&world, tomato);
    let knife = knife(&mut world, v(-1.0, 0.0, z));
    let mass = world.bodies().mass(knife);
    assert!((0.05..=0.3).contains(&mass), "a knife of {mass} kg");
    settle(&mut world, 2.0);
    assert!(
        !world.state(tomato, Predicate::Sliced),
        "the knife's own weight ({:.2} N) does not slice",
        mass * 9.81
    );
    press(&mut world, knife, push, 60);
    world.state(tomato, Predicate::Sliced)
}

#[test]
fn sliced_only_by_a_push_above_10_n_not_by_a_knife_laid_on_top() {
    assert!(
        !knife_laid_on_a_tomato_and_pushed(6.0),
        "6 N (+ 1.9 N of weight) is below 10 N"
    );
    assert!(
        knife_laid_on_a_tomato_and_pushed(12.0),
        "12 N is above 10 N"
    );
}

#[test]
fn cooked_strawberry_when_its_halves_are_cooked_on_the_stove() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let stove = stove(&mut world, -1.0, 0.0);
    let berry = sliceable_apple(&mut world, "strawberry_1", v(-1.0, 0.0, 1.0));
    settle(&mut world, 1.0);
    world.set_state(berry, Predicate::Sliced, true).unwrap();
    let [a, b] = world.bodies().object(berry).replaced_by.unwrap();
    settle(&mut world, 1.0);
    assert!(world.relations().ontop(a, stove) && world.relations().ontop(b, stove));
    assert!(!world.state(berry, Predicate::Cooked));
    world.set_state(stove, Predicate::ToggledOn, true).unwrap();
    // The rule heats the halves, which stand on the burner; the whole is gone.
    settle(&mut world, 10.0);
    assert!(world.state(a, Predicate::Cooked) && world.state(b, Predicate::Cooked));
    assert!(
        world.state(berry, Predicate::Cooked) && world.state(berry, Predicate::Sliced),
        "a sliced strawberry is cooked when both halves are (preserving_food needs both)"
    );
    // Setting a state of the sliced whole sets it on both halves.
    world.set_state(berry, Predicate::Frozen, true).unwrap();
    assert!(world.state(a, Predicate::Frozen) && world.state(b, Predicate::Frozen));
    assert!(world.state(berry, Predicate::Frozen));
}

#[test]
fn open_by_a_motor_driving_the_door() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let fridge = fridge(&mut world, -2.0, 0.0);
    settle(&mut world, 0.5);
    world
        .joints_mut()
        .drive(fridge, 0, Drive::velocity(1.0, 100.0, 1000.0))
        .unwrap();
    settle(&mut world, 1.0);
    assert!(
        world.state(fridge, Predicate::Open),
        "{}",
        world.joints().position(fridge, 0)
    );
    // Released, the damped door coasts on but does not swing shut: nothing pulls it closed.
    world.joints_mut().release(fridge, 0).unwrap();
    let opened = world.joints().position(fridge, 0);
    settle(&mut world, 2.0);
    assert!(world.joints().position(fridge, 0) >= opened - 0.01);
    assert!(
        world.joints().position(fridge, 0) <= 2.0 + 0.05,
        "the joint limit holds"
    );
}

#[test]
fn sliced_only_by_the_edge_not_by_the_handle() {
    use behavior_core::Ability;
    use behavior_sim::{ObjectSpec, Part, PointKind};
    let knife_with_edge = |world: &mut World, at| {
        // The blade is the +x half; its edge runs along the bottom of that half.
        let mut spec = ObjectSpec::new(
            "knife_1",
            "carving_knife.n.01",
            vec![Part::new(cuboid(0.12, 0.01, 0.02))],
        )
        .at(at)
        .ability(Ability::Slicer, &[])
        .point(PointKind::SlicingEdge, v(0.06, 0.0, -0.02));
        spec.density = KNIFE_MASS / (0.24 * 0.02 * 0.04);
        world.add(spec).unwrap()
    };
    let press_on_tomato = |knife_x: f32| {
        let mut world = World::default();
        two_room_floor(&mut world);
        table(&mut world, -1.0, 0.0);
        let tomato = sliceable_apple(&mut world, "tomato_1", v(-1.0, 0.0, 0.8));
        settle(&mut world, 1.0);
        let z = laid_on(&world, tomato);
        let knife = knife_with_edge(&mut world, v(knife_x, 0.0, z));
        press(&mut world, knife, 15.0, 30);
        world.state(tomato, Predicate::Sliced)
    };
    assert!(press_on_tomato(-1.06), "the edge presses the tomato");
    assert!(!press_on_tomato(-0.92), "the handle presses the tomato");
}

#[test]
fn cooked_in_a_microwave_only_when_on_closed_and_inside() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let microwave = microwave(&mut world, -2.0, 0.0);
    let inside = sliceable_apple(&mut world, "apple_1", v(-2.0, 0.0, 1.0));
    let outside = sliceable_apple(&mut world, "apple_2", v(-2.0, -0.5, 0.05));
    settle(&mut world, 1.0);
    assert!(
        world.relations().inside(inside, microwave)
            && !world.relations().inside(outside, microwave)
    );
    // Off: nothing.
    settle(&mut world, 3.0);
    assert!(world.temperature(inside) < 24.0);
    // On but open: nothing.
    world.set_state(microwave, Predicate::Open, true).unwrap();
    world
        .set_state(microwave, Predicate::ToggledOn, true)
        .unwrap();
    settle(&mut world, 3.0);
    assert!(world.temperature(inside) < 24.0);
    // On and closed: 1000 °C at 0.04 /s reaches 70 °C in ln(977/930)/0.04 ≈ 1.2 s.
    world.set_state(microwave, Predicate::Open, false).unwrap();
    settle(&mut world, 2.0);
    assert!(
        world.state(inside, Predicate::Cooked),
        "{}",
        world.temperature(inside)
    );
    assert!(!world.state(outside, Predicate::Cooked));
}

#[test]
fn open_state_survives_teleporting_the_object_with_its_door() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let fridge_id = fridge(&mut world, -2.0, 0.0);
    world.joints_mut().set_position(fridge_id, 0, 0.8).unwrap();
    let before = world.joints().position(fridge_id, 0);
    let mut pose = world.bodies().pose(fridge_id);
    pose.translation.x += 1.0;
    world.bodies_mut().set_pose(fridge_id, pose).unwrap();
    assert!(
        (world.joints().position(fridge_id, 0) - before).abs() < 1e-4,
        "the door moved with the body"
    );
    settle(&mut world, 1.0);
    assert!(world.state(fridge_id, Predicate::Open));
}

/// A chest 0.6 × 0.4 × 0.4 m whose whole top is a lid hinged at the back edge, dustyable.
fn chest(world: &mut World) -> behavior_sim::ObjectId {
    use behavior_core::Ability;
    use behavior_sim::{JointKind, JointSpec, LinkSpec, ObjectSpec, Part};
    let (w, d, h, t) = (0.3, 0.2, 0.2, 0.01);
    let parts = vec![
        Part::at(cuboid(w, d, t), v(0.0, 0.0, t)),
        Part::at(cuboid(t, d, h), v(-w + t, 0.0, h)),
        Part::at(cuboid(t, d, h), v(w - t, 0.0, h)),
        Part::at(cuboid(w, t, h), v(0.0, -d + t, h)),
        Part::at(cuboid(w, t, h), v(0.0, d - t, h)),
    ];
    let lid = LinkSpec {
        name: "lid".into(),
        parts: vec![Part::at(cuboid(w, d, t), v(0.0, 0.0, 2.0 * h + t))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.0, d, 2.0 * h),
            v(-1.0, 0.0, 0.0),
            1.5,
            5.0,
        ),
        density: 300.0,
    };
    let spec = ObjectSpec::new("chest_1", "chest.n.02", parts)
        .at(v(-1.0, 0.0, 0.0))
        .fixed()
        .link(lid)
        .ability(Ability::Openable, &[])
        .ability(Ability::Dustyable, &[]);
    world.add(spec).unwrap()
}

#[test]
fn dusty_particles_differ_between_seeds_and_repeat_for_a_seed() {
    let layout = |seed: u64| {
        let mut world = World::default();
        two_room_floor(&mut world);
        let plate = dirty_plate(&mut world, v(-1.0, 0.0, 0.01));
        world.reseed(seed);
        world.set_state(plate, Predicate::Dusty, true).unwrap();
        let bits: Vec<[u32; 3]> = world
            .particle_positions(plate, Predicate::Dusty)
            .iter()
            .map(|p| p.to_array().map(f32::to_bits))
            .collect();
        bits
    };
    assert!(layout(1).len() >= 5);
    assert_eq!(
        layout(1),
        layout(1),
        "the same seed places the same particles"
    );
    assert_ne!(layout(1), layout(2), "another seed places them elsewhere");
}

#[test]
fn dusty_lid_keeps_its_dust_when_opened() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let chest = chest(&mut world);
    world.set_state(chest, Predicate::Dusty, true).unwrap();
    let closed = world.particle_positions(chest, Predicate::Dusty);
    let lid_top = world.bodies().aabb(chest).maxs.z;
    assert!(
        closed.iter().all(|p| (p.z - lid_top).abs() < 1e-3),
        "on the lid"
    );
    world.joints_mut().set_position(chest, 0, 1.5).unwrap();
    assert!(world.state(chest, Predicate::Open));
    let opened = world.particle_positions(chest, Predicate::Dusty);
    assert_eq!(opened.len(), closed.len());
    // Opened 1.5 rad about the back edge (y = 0.2, z = 0.4), the lid stands nearly upright: its
    // dust turned with it about the hinge, keeping its distance to it.
    let hinge = |p: &rapier3d::math::Vector| ((p.y - 0.2).powi(2) + (p.z - 0.4).powi(2)).sqrt();
    for (c, o) in closed.iter().zip(&opened) {
        assert!(
            (c.x - o.x).abs() < 1e-4 && (hinge(c) - hinge(o)).abs() < 1e-3,
            "{c} → {o}"
        );
        assert!(o.y > 0.19 && o.z >= c.z, "{c} → {o}");
    }
    assert!(world.state(chest, Predicate::Dusty));
}

#[test]
fn sliced_halves_keep_the_whole_s_look_and_friction() {
    use behavior_sim::{Material, Visual};
    let mut world = World::default();
    two_room_floor(&mut world);
    let tomato = sliceable_apple(&mut world, "tomato_1", v(-1.0, 0.0, 0.05));
    let look = Visual {
        color: [200, 30, 20],
        material: Material::Food,
    };
    // Set after building, as a library would: the halves must copy the whole, not the defaults.
    let mut spec = behavior_sim::ObjectSpec::new(
        "tomato_2",
        "tomato.n.01",
        vec![behavior_sim::Part::new(behavior_sim::Primitive::Sphere {
            radius: 0.04,
        })],
    )
    .at(v(-2.0, 0.0, 0.05))
    .ability(behavior_core::Ability::Sliceable, &[]);
    spec.visual = look;
    spec.friction = 1.1;
    spec.angular_damping = 0.3;
    let red = world.add(spec).unwrap();
    world.set_state(red, Predicate::Sliced, true).unwrap();
    world.set_state(tomato, Predicate::Sliced, true).unwrap();
    for half in world.bodies().object(red).replaced_by.unwrap() {
        let o = world.bodies().object(half);
        assert_eq!(o.visual, look);
        assert_eq!((o.friction, o.angular_damping), (1.1, 0.3));
    }
}

#[test]
fn object_state_round_trips_every_state_into_a_fresh_world() {
    let build = || {
        let mut world = World::default();
        two_room_floor(&mut world);
        let stove = stove(&mut world, -1.0, 0.0);
        let plate = dirty_plate(&mut world, v(-2.0, 0.0, 0.01));
        let chest = chest(&mut world);
        (world, stove, plate, chest)
    };
    let (mut world, stove, plate, chest) = build();
    world.reseed(9);
    world.set_state(stove, Predicate::ToggledOn, true).unwrap();
    world.set_state(plate, Predicate::Stained, true).unwrap();
    world.set_state(chest, Predicate::Dusty, true).unwrap();
    world.set_state(plate, Predicate::Perished, true).ok();
    settle(&mut world, 1.0);
    let (mut copy, ..) = build();
    for (id, _) in world.bodies().objects() {
        copy.set_object_state(id, &world.object_state(id)).unwrap();
    }
    for (id, _) in world.bodies().objects() {
        assert_eq!(copy.object_state(id), world.object_state(id));
        assert_eq!(
            copy.temperature(id).to_bits(),
            world.temperature(id).to_bits()
        );
        for p in Predicate::UNARY_STATES
            .into_iter()
            .filter(|&p| p != Predicate::Open)
        {
            assert_eq!(copy.state(id, p), world.state(id, p), "{p}");
        }
    }
    assert!(copy.state(plate, Predicate::Stained) && copy.state(stove, Predicate::ToggledOn));
    // A bad record changes nothing and names the object.
    let mut bad = world.object_state(plate);
    bad.temperature = f32::NAN;
    let err = copy.set_object_state(plate, &bad).unwrap_err().to_string();
    assert!(err.contains("plate_1") && err.contains("finite"), "{err}");
    let mut bad = world.object_state(chest);
    bad.dust.particles[0].0 = Some(7);
    assert!(copy.set_object_state(chest, &bad).is_err());
    assert_eq!(copy.object_state(chest), world.object_state(chest));
}
