//! OPEN and CLOSE by hand, by the BehaviorRobot in a small real scene (our own activity
//! `freezing_fish`: a refrigerator in a kitchen): the robot brought before the refrigerator by
//! the physical NAVIGATE_TO, a call the primitive refuses (the counter is not openable; nothing
//! moves), then the door taken by the hand and swung wide open, and swung shut again. The
//! calls go through `swing`, which has no kinematic fallback: a door that ends open was opened
//! by the hand. Physics makes runs chaotic, and in some homes furniture stands in the door's
//! swing (the first covering home's refrigerator opens 4° before a cabinet stops it), so the
//! robot is given the named homes that cover the activity in turn, a few seeds each: in one of
//! them the hand must open and close it. Fetch and the R1, whose arms are moved kinematically,
//! cannot hold a door on its hinge: `swing` says so and moves nothing, and `run` sets the door
//! open instead, its outcome marked as set.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_assets::{Library, NAMED_HOMES, generate, missing, requirements};
use behavior_core::Predicate;
use behavior_env::{Env, EnvConfig};
use behavior_planning::{Call, Failure, Mode, Primitive, Tuning, run, swing};
use behavior_robots::RobotKind;
use behavior_sim::ObjectId;

/// The robots whose arms are moved kinematically: they cannot hold a door on its hinge, and
/// their OPEN falls back to the setter.
const ARMS: [RobotKind; 2] = [RobotKind::Fetch, RobotKind::R1];
const SEEDS: [u64; 3] = [0, 1, 2];

/// `freezing_fish` in each named home that covers it, without clutter.
fn configs() -> Vec<(&'static str, EnvConfig)> {
    let activity = support::own_activity("freezing_fish");
    let taxonomy = common::taxonomy();
    let library = Library::new(&taxonomy);
    let needs = requirements(&activity);
    NAMED_HOMES
        .into_iter()
        .map(|(name, seed)| (name, generate(name, seed, &library).unwrap()))
        .filter(|(_, home)| missing(home, &needs, &taxonomy).is_empty())
        .map(|(name, home)| {
            (
                name,
                EnvConfig::new(activity.clone(), taxonomy.clone(), vec![home]),
            )
        })
        .collect()
}

fn object(env: &Env, instance: &str) -> ObjectId {
    let k = env.config().activity.instance_named(instance).unwrap();
    env.bindings().unwrap()[k.0 as usize].unwrap()
}

/// The fraction of its range each of the object's limited joints is open.
fn openings(env: &Env, object: ObjectId) -> Vec<f32> {
    let world = env.world().unwrap();
    let links = &world.bodies().object(object).links;
    links
        .iter()
        .enumerate()
        .filter_map(|(i, l)| {
            let [lo, hi] = l.joint.limits?;
            Some((world.joints().position(object, i) - lo) / (hi - lo))
        })
        .collect()
}

/// One seed's try: `Ok` where the hand opened the refrigerator wide and shut it again, else
/// what happened.
fn open_and_close(config: &EnvConfig, robot: RobotKind, seed: u64) -> Result<(), String> {
    let mut env = Env::new(support::physical(config.clone(), robot));
    env.reset(seed).unwrap();
    let fridge = object(&env, "electric_refrigerator.n.01_1");
    let counter = object(&env, "countertop.n.01_1");
    let hand = env.robot().unwrap().hands() - 1;
    let call = |primitive, object| Call {
        primitive,
        object,
        hand,
    };
    let drive = run(
        &mut env,
        call(Primitive::NavigateTo, fridge),
        Mode::Physical,
        None,
    );
    drive
        .unwrap()
        .result
        .map_err(|why| format!("not prepared: {why}"))?;
    let tuning = Tuning::default();
    let steps = env.steps();
    let refused = swing(&mut env, &call(Primitive::Open, counter), &tuning, None).unwrap();
    assert!(
        matches!(
            refused,
            Err(Failure::Unable {
                what: "is not openable"
            })
        ),
        "{} seed {seed}: {refused:?}",
        robot.name()
    );
    assert_eq!(env.steps(), steps, "the refusal took no step");
    if env.world().unwrap().state(fridge, Predicate::Open) {
        return Err("the refrigerator was sampled open".into());
    }
    let opened = swing(&mut env, &call(Primitive::Open, fridge), &tuning, None).unwrap();
    let wide = openings(&env, fridge);
    if opened.is_err() || !env.world().unwrap().state(fridge, Predicate::Open) {
        return Err(format!(
            "open: {opened:?}, joints at {wide:?} of their ranges"
        ));
    }
    // The door swung past the planner's "wide open" (65 % of its range), by the hand's steps.
    assert!(
        wide.iter().any(|&f| f >= 0.65),
        "{} seed {seed}: {wide:?}",
        robot.name()
    );
    assert!(
        env.steps() > steps + 20,
        "the hand took the door over steps"
    );
    assert_eq!(
        env.robot().unwrap().held(hand),
        None,
        "the hand let the door go"
    );
    let closed = swing(&mut env, &call(Primitive::Close, fridge), &tuning, None).unwrap();
    let shut = openings(&env, fridge);
    match (closed, env.world().unwrap().state(fridge, Predicate::Open)) {
        (Ok(()), false) => Ok(()),
        (closed, _) => Err(format!("close: {closed:?}, joints at {shut:?}")),
    }
}

#[test]
fn the_behavior_robot_opens_a_refrigerator_by_hand_and_shuts_it_and_is_refused_the_counter() {
    let configs = configs();
    assert!(!configs.is_empty(), "a named home covers freezing_fish");
    let mut outcomes = Vec::new();
    let tries = configs
        .iter()
        .flat_map(|c| SEEDS.iter().map(move |&s| (c, s)));
    let done = tries.into_iter().any(|((home, config), seed)| {
        match open_and_close(config, RobotKind::Behavior, seed) {
            Ok(()) => true,
            Err(why) => {
                outcomes.push(format!("{home} seed {seed}: {why}"));
                false
            }
        }
    });
    assert!(
        done,
        "the hand never opened and shut the refrigerator: {outcomes:#?}"
    );
}

#[test]
fn an_arm_moved_kinematically_leaves_the_door_to_the_setter() {
    let (_, config) = &configs()[0];
    for robot in ARMS {
        let mut env = Env::new(support::physical(config.clone(), robot));
        env.reset(0).unwrap();
        let fridge = object(&env, "electric_refrigerator.n.01_1");
        let call = |primitive| Call {
            primitive,
            object: fridge,
            hand: 0,
        };
        let drive = run(&mut env, call(Primitive::NavigateTo), Mode::Physical, None).unwrap();
        assert!(drive.result.is_ok(), "{}: {:?}", robot.name(), drive.result);
        let steps = env.steps();
        let refused = swing(&mut env, &call(Primitive::Open), &Tuning::default(), None).unwrap();
        assert!(
            matches!(refused, Err(Failure::Unavailable(why)) if why.contains("kinematically")),
            "{}: {refused:?}",
            robot.name()
        );
        assert_eq!(
            env.steps(),
            steps,
            "{}: the refusal moved nothing",
            robot.name()
        );
        // The primitive as the planner runs it: set open, and said to be.
        let outcome = run(&mut env, call(Primitive::Open), Mode::Physical, None).unwrap();
        assert!(
            outcome.result.is_ok(),
            "{}: {:?}",
            robot.name(),
            outcome.result
        );
        assert!(outcome.set, "{}: the setter opened it", robot.name());
        assert!(env.world().unwrap().state(fridge, Predicate::Open));
    }
}
