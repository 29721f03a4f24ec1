//! Each symbolic primitive in a sampled home: what it does when it can, and why it refuses
//! when it cannot (nothing changed then).

#[path = "../../env/tests/common/mod.rs"]
mod common;

use behavior_core::Predicate;
use behavior_env::Env;
use behavior_planning::{Call, Failure, Mode, Primitive, WAIT_STEPS, run, within_reach};
use behavior_sim::ObjectId;

/// An episode of `activity` (its first covering home, no clutter), reset with `seed`.
fn episode(activity: &str, seed: u64) -> Env {
    let mut env = common::env(activity);
    env.reset(seed).unwrap();
    env
}

/// The world object of an activity instance.
fn object(env: &Env, instance: &str) -> ObjectId {
    let k = env.config().activity.instance_named(instance).unwrap();
    env.bindings().unwrap()[k.0 as usize].unwrap()
}

/// Runs a primitive with a hand; its outcome.
fn act(env: &mut Env, primitive: Primitive, object: ObjectId, hand: usize) -> Result<(), Failure> {
    let call = Call {
        primitive,
        object,
        hand,
    };
    run(env, call, Mode::Symbolic, None).unwrap().result
}

/// The first hinged link of an object and its open end.
fn hinge(env: &Env, object: ObjectId) -> (usize, f32) {
    let links = &env.world().unwrap().bodies().object(object).links;
    links
        .iter()
        .enumerate()
        .find(|(_, l)| l.joint.kind == behavior_sim::JointKind::Revolute)
        .and_then(|(i, l)| Some((i, l.joint.limits?[1])))
        .expect("a hinged door")
}

fn state(env: &Env, object: ObjectId, predicate: Predicate) -> bool {
    env.world().unwrap().state(object, predicate)
}

#[test]
fn navigate_grasp_and_place_under_then_switch_on() {
    let mut env = episode("installing_a_modem", 0);
    let (modem, table) = (object(&env, "modem.n.01_1"), object(&env, "table.n.02_1"));
    let floor = object(&env, "floor.n.01_1");
    // Nothing in hand: nothing to place.
    let err = act(&mut env, Primitive::PlaceUnder, table, 1).unwrap_err();
    assert!(matches!(err, Failure::HandEmpty), "{err}");
    // The table is fixed furniture.
    let err = act(&mut env, Primitive::Grasp, table, 1).unwrap_err();
    assert!(matches!(err, Failure::NotGraspable(_)), "{err}");
    act(&mut env, Primitive::NavigateTo, modem, 1).unwrap();
    let (world, robot) = (env.world().unwrap(), env.robot().unwrap());
    assert!(within_reach(world, robot, modem));
    act(&mut env, Primitive::Grasp, modem, 1).unwrap();
    assert_eq!(env.robot().unwrap().held(1), Some(modem));
    // A full hand grasps nothing more; a table is no floor.
    let err = act(&mut env, Primitive::Grasp, modem, 1).unwrap_err();
    assert!(matches!(err, Failure::HandFull(_)), "{err}");
    let err = act(&mut env, Primitive::PlaceOnFloor, table, 1).unwrap_err();
    assert!(matches!(err, Failure::Unable { .. }), "{err}");
    let err = act(&mut env, Primitive::PlaceOnTop, floor, 1).unwrap_err();
    assert!(matches!(err, Failure::Unable { .. }), "{err}");
    act(&mut env, Primitive::PlaceUnder, table, 1).unwrap();
    assert_eq!(env.robot().unwrap().held(1), None);
    assert!(
        env.world().unwrap().relations().under(modem, table),
        "the modem is under the table"
    );
    let err = act(&mut env, Primitive::ToggleOff, modem, 1).unwrap_err();
    assert!(matches!(err, Failure::Already("off")), "{err}");
    let err = act(&mut env, Primitive::Open, modem, 1).unwrap_err();
    assert!(
        matches!(
            err,
            Failure::Unable {
                what: "is not openable"
            }
        ),
        "{err}"
    );
    act(&mut env, Primitive::ToggleOn, modem, 1).unwrap();
    assert!(state(&env, modem, Predicate::ToggledOn));
    assert!(
        env.score().unwrap().success,
        "the modem under the table and on is the goal"
    );
}

#[test]
fn stains_need_a_soaked_tool_and_soaking_needs_running_water() {
    let mut env = episode("cleaning_carpets", 0);
    let towel = object(&env, "hand_towel.n.01_1");
    let (sink, floor) = (object(&env, "sink.n.01_1"), object(&env, "floor.n.01_1"));
    act(&mut env, Primitive::NavigateTo, towel, 0).unwrap();
    act(&mut env, Primitive::Grasp, towel, 0).unwrap();
    act(&mut env, Primitive::NavigateTo, sink, 0).unwrap();
    assert!(state(&env, floor, Predicate::Stained));
    let err = act(&mut env, Primitive::Wipe, floor, 0).unwrap_err();
    assert!(
        matches!(err, Failure::WrongTool { .. } | Failure::Unreachable),
        "{err}"
    );
    let err = act(&mut env, Primitive::Soak, sink, 0).unwrap_err();
    assert!(matches!(err, Failure::WaterOff), "{err}");
    // The other hand holds nothing to soak.
    act(&mut env, Primitive::ToggleOn, sink, 1).unwrap();
    let err = act(&mut env, Primitive::Soak, sink, 1).unwrap_err();
    assert!(matches!(err, Failure::HandEmpty), "{err}");
    act(&mut env, Primitive::Soak, sink, 0).unwrap();
    assert!(state(&env, towel, Predicate::Soaked));
    let err = act(&mut env, Primitive::Wipe, sink, 0).unwrap_err();
    assert!(matches!(err, Failure::Already("clean")), "{err}");
    act(&mut env, Primitive::NavigateTo, floor, 0).unwrap();
    act(&mut env, Primitive::Wipe, floor, 0).unwrap();
    assert!(!state(&env, floor, Predicate::Stained));
    assert!(env.score().unwrap().success, "a clean carpet is the goal");
}

#[test]
fn a_closed_fridge_is_opened_before_things_go_in_and_slicing_needs_a_knife() {
    let mut env = episode("bottling_fruit", 3);
    let fridge = object(&env, "electric_refrigerator.n.01_1");
    let (strawberry, knife) = (
        object(&env, "strawberry.n.01_1"),
        object(&env, "carving_knife.n.01_1"),
    );
    let jar = object(&env, "jar.n.01_1");
    act(&mut env, Primitive::NavigateTo, fridge, 1).unwrap();
    assert!(!state(&env, fridge, Predicate::Open));
    let err = act(&mut env, Primitive::Grasp, strawberry, 1).unwrap_err();
    assert!(matches!(err, Failure::ContainerClosed(_)), "{err}");
    let err = act(&mut env, Primitive::Close, fridge, 1).unwrap_err();
    assert!(matches!(err, Failure::Already("closed")), "{err}");
    // A door a little ajar reads as open; OPEN still swings it all the way, then refuses.
    let door = hinge(&env, fridge);
    env.edit(|e| {
        e.world
            .joints_mut()
            .set_position(fridge, door.0, 0.2 * door.1)
    })
    .unwrap()
    .unwrap();
    assert!(state(&env, fridge, Predicate::Open), "ajar reads as open");
    act(&mut env, Primitive::Open, fridge, 1).unwrap();
    let swung = env.world().unwrap().joints().position(fridge, door.0);
    assert!((swung - door.1).abs() < 1e-4, "{swung} of {}", door.1);
    let err = act(&mut env, Primitive::Open, fridge, 1).unwrap_err();
    assert!(matches!(err, Failure::Already("open")), "{err}");
    act(&mut env, Primitive::Grasp, strawberry, 1).unwrap();
    act(&mut env, Primitive::NavigateTo, jar, 1).unwrap();
    let err = act(&mut env, Primitive::PlaceInside, jar, 1).unwrap_err();
    assert!(
        matches!(err, Failure::ContainerClosed(_)),
        "the jar's lid is on: {err}"
    );
    act(&mut env, Primitive::Open, jar, 0).unwrap();
    act(&mut env, Primitive::PlaceInside, jar, 1).unwrap();
    assert!(env.world().unwrap().relations().inside(strawberry, jar));
    let err = act(&mut env, Primitive::Slice, strawberry, 0).unwrap_err();
    assert!(matches!(err, Failure::HandEmpty), "{err}");
    act(&mut env, Primitive::NavigateTo, knife, 0).unwrap();
    act(&mut env, Primitive::Grasp, knife, 0).unwrap();
    act(&mut env, Primitive::NavigateTo, strawberry, 0).unwrap();
    act(&mut env, Primitive::Slice, strawberry, 0).unwrap();
    assert!(state(&env, strawberry, Predicate::Sliced));
    act(&mut env, Primitive::NavigateTo, fridge, 1).unwrap();
    act(&mut env, Primitive::Close, fridge, 1).unwrap();
    assert!(!state(&env, fridge, Predicate::Open));
}

#[test]
fn a_wait_lasts_a_second_and_a_refused_primitive_changes_nothing() {
    let mut env = episode("installing_a_modem", 1);
    let table = object(&env, "table.n.02_1");
    let steps = env.steps();
    let call = Call {
        primitive: Primitive::Wait,
        object: table,
        hand: 1,
    };
    let outcome = run(&mut env, call, Mode::Symbolic, None).unwrap();
    assert!(outcome.result.is_ok());
    assert_eq!(env.steps(), steps + WAIT_STEPS);
    let digest = |env: &Env| {
        behavior_env::record::state_digest(env.world().unwrap(), env.robot().unwrap(), 0)
    };
    let before = digest(&env);
    let err = env
        .edit(|edit| {
            let call = Call {
                primitive: Primitive::PlaceInside,
                object: table,
                hand: 1,
            };
            behavior_planning::apply(edit, &call)
        })
        .unwrap()
        .unwrap_err();
    assert!(matches!(err, Failure::HandEmpty), "{err}");
    assert_eq!(digest(&env), before, "a refused primitive changes nothing");
}

/// The drawers of `object` that `thing` rests on, by their contacts.
fn drawers_under(env: &Env, object: ObjectId, thing: ObjectId) -> Vec<usize> {
    let world = env.world().unwrap();
    let links = &world.bodies().object(object).links;
    (0..links.len())
        .filter(|&l| links[l].joint.kind == behavior_sim::JointKind::Prismatic)
        .filter(|&l| {
            let drawer = behavior_sim::BodyRef::link(object, l);
            let contacts = world.contacts().of(drawer).unwrap();
            contacts
                .iter()
                .any(|c| c.other.is_some_and(|b| b.object == thing))
        })
        .collect()
}

#[test]
fn what_lies_in_a_drawer_comes_out_and_goes_back_in_with_it() {
    // The necklace lies in the living room's cabinet; the first named home covering the activity
    // whose cabinet puts it in a drawer (a cabinet of doors and shelves has none), at seed 4.
    let activity = common::activity("collect_misplaced_items");
    let library = behavior_assets::Library::new(&common::knowledge().taxonomy);
    let needs = behavior_assets::requirements(&activity);
    let mut found = None;
    for (name, seed) in behavior_assets::NAMED_HOMES {
        let home = behavior_assets::generate(name, seed, &library).unwrap();
        if !behavior_assets::missing(&home, &needs, &common::knowledge().taxonomy).is_empty() {
            continue;
        }
        let config = behavior_env::EnvConfig::new(activity.clone(), common::taxonomy(), vec![home]);
        let mut env = Env::new(config);
        env.reset(4).unwrap();
        let (cabinet, necklace) = (
            object(&env, "cabinet.n.01_1"),
            object(&env, "necklace.n.01_1"),
        );
        act(&mut env, Primitive::NavigateTo, cabinet, 1).unwrap();
        if state(&env, cabinet, Predicate::Open) {
            act(&mut env, Primitive::Close, cabinet, 1).unwrap();
        }
        if let &[drawer] = drawers_under(&env, cabinet, necklace).as_slice() {
            found = Some((env, cabinet, necklace, drawer));
            break;
        }
    }
    let (mut env, cabinet, necklace, drawer) =
        found.expect("in some named home the necklace lies in one drawer");
    let at = |env: &Env| {
        let world = env.world().unwrap();
        let link = world.bodies().link_pose(cabinet, drawer).translation;
        (link, world.bodies().pose(necklace).translation)
    };
    // OPEN until the setter's random subset pulls the necklace's drawer (a few tries).
    let (shut_drawer, shut_necklace) = at(&env);
    for _ in 0..8 {
        act(&mut env, Primitive::Open, cabinet, 1).unwrap();
        if (at(&env).0 - shut_drawer).length() > 0.05 {
            break;
        }
        act(&mut env, Primitive::Close, cabinet, 1).unwrap();
    }
    let (open_drawer, open_necklace) = at(&env);
    let pulled = open_drawer - shut_drawer;
    assert!(pulled.length() > 0.05, "the drawer moved {pulled:?}");
    let moved = open_necklace - shut_necklace;
    assert!(
        (moved - pulled).length() < 1e-4,
        "necklace {moved:?}, drawer {pulled:?}"
    );
    act(&mut env, Primitive::Close, cabinet, 1).unwrap();
    let (closed_drawer, closed_necklace) = at(&env);
    let back = closed_necklace - open_necklace;
    assert!(
        (back - (closed_drawer - open_drawer)).length() < 1e-4,
        "{back:?}"
    );
    assert!(env.world().unwrap().relations().inside(necklace, cabinet));
}
