//! Physical GRASP and PLACE_ON_TOP for the BehaviorRobot: the hand planned and driven by the
//! robot's own actions with physics. A book is taken from where it lies and put back on its
//! support; the approach the hand executed touches nothing when checked ten times more finely
//! than the planner did; refusals say why and change nothing; the recording replays bit for bit.

#[path = "../../env/tests/common/mod.rs"]
mod common;

use behavior_env::Env;
use behavior_env::record::{RecordingSetup, read, replay_with};
use behavior_motion::{HandConfig, HandSpace, Space};
use behavior_planning::{
    Call, Failure, Mode, Primitive, RecordedCall, Tuning, grasp, hand_body, hand_grasp, hand_place,
    run,
};
use behavior_robots::RobotKind;
use behavior_sim::{ObjectId, Relation};

const ACTIVITY: &str = "re-shelving_library_books";

fn episode(robot: RobotKind) -> Env {
    let mut config = common::config(ACTIVITY);
    config.robot = robot;
    config.action_space = Mode::Physical.action_space(robot);
    let mut env = Env::new(config);
    // Seed 3: at seeds 0–2 of the first covering home the hand finds no way clear to the book.
    env.reset(3).unwrap();
    env
}

fn object(env: &Env, instance: &str) -> ObjectId {
    let k = env.config().activity.instance_named(instance).unwrap();
    env.bindings().unwrap()[k.0 as usize].unwrap()
}

fn call(primitive: Primitive, object: ObjectId) -> Call {
    Call {
        primitive,
        object,
        hand: 1,
    }
}

/// What `x` lies on.
fn support(env: &Env, x: ObjectId) -> ObjectId {
    let world = env.world().unwrap();
    world
        .bodies()
        .objects()
        .map(|(id, _)| id)
        .find(|&c| c != x && world.relations().ontop(x, c))
        .expect("the book lies on something")
}

fn holds(env: &Env, x: ObjectId) -> bool {
    env.robot().unwrap().is_holding(x)
}

#[test]
fn the_hand_takes_a_book_and_puts_it_back_without_touching_anything_on_the_way() {
    let mut env = episode(RobotKind::Behavior);
    let book = object(&env, "book.n.02_1");
    let under = support(&env, book);
    let walk = run(
        &mut env,
        call(Primitive::NavigateTo, book),
        Mode::Physical,
        None,
    )
    .unwrap();
    walk.result.unwrap();

    let before = env.world().unwrap().clone();
    let robot = env.robot().expect("an episode's robot");
    let body = hand_body(&before, robot.embodiment(), 1).expect("posed hands");
    let path = hand_grasp(
        &mut env,
        &call(Primitive::Grasp, book),
        &Tuning::default(),
        None,
    )
    .unwrap()
    .unwrap();
    assert!(holds(&env, book), "the right hand holds the book");
    assert!(path.planned.len() > 1 && !path.executed.is_empty());
    // The approach as executed, every pose and the moves between them checked at 2 mm in the
    // world as it was before: the hand touched nothing until it came down on the book.
    let ends = (path.planned[0], *path.planned.last().unwrap());
    let space = HandSpace::new(&before, body, &ends.0, &ends.1);
    let mut previous = path.planned[0];
    for pose in &path.executed {
        let c = HandConfig::of(pose);
        for fine in space.steps(&previous, &c, 0.002) {
            assert!(space.clear(&fine), "the hand touched something at {fine:?}");
        }
        previous = c;
    }

    let put = hand_place(
        &mut env,
        &call(Primitive::PlaceOnTop, under),
        Relation::OnTop,
        &Tuning::default(),
        None,
    )
    .unwrap();
    put.unwrap();
    assert!(!holds(&env, book), "let go");
    let world = env.world().unwrap();
    assert!(
        world.relations().ontop(book, under),
        "the book settled on {}",
        world.bodies().object(under).name
    );
}

#[test]
fn refused_physical_primitives_say_why_and_move_nothing() {
    let mut env = episode(RobotKind::Behavior);
    let book = object(&env, "book.n.02_1");
    let shelf = object(&env, "shelf.n.01_1");
    let steps = env.steps();
    let empty = hand_place(
        &mut env,
        &call(Primitive::PlaceOnTop, shelf),
        Relation::OnTop,
        &Tuning::default(),
        None,
    );
    assert!(matches!(empty.unwrap(), Err(Failure::HandEmpty)));
    let fixed = hand_grasp(
        &mut env,
        &call(Primitive::Grasp, shelf),
        &Tuning::default(),
        None,
    )
    .unwrap();
    assert!(matches!(fixed, Err(Failure::NotGraspable(_))), "{fixed:?}");
    // From where the episode starts the book is out of the primitives' reach.
    let far = hand_grasp(
        &mut env,
        &call(Primitive::Grasp, book),
        &Tuning::default(),
        None,
    )
    .unwrap();
    assert!(
        matches!(far, Err(Failure::Unreachable | Failure::NoHandPose)),
        "{far:?}"
    );
    assert_eq!(env.steps(), steps, "no step was taken");

    // A reduced action space has no hand actions to plan with: it says so, takes no step.
    let mut config = common::config(ACTIVITY);
    config.action_space = behavior_robots::ActionSpace::Navigation;
    let mut reduced = Env::new(config);
    reduced.reset(0).unwrap();
    let book = object(&reduced, "book.n.02_1");
    let refused = hand_grasp(
        &mut reduced,
        &call(Primitive::Grasp, book),
        &Tuning::default(),
        None,
    )
    .unwrap();
    assert!(
        matches!(refused, Err(Failure::Unavailable(_))),
        "{refused:?}"
    );
    assert_eq!(reduced.steps(), 0);

    // The hands' primitives posed directly refuse Fetch, whose hand is at the end of an arm.
    let mut fetch = episode(RobotKind::Fetch);
    let book = object(&fetch, "book.n.02_1");
    let gripper = Call {
        hand: 0,
        ..call(Primitive::Grasp, book)
    };
    let refused = hand_grasp(&mut fetch, &gripper, &Tuning::default(), None).unwrap();
    assert!(
        matches!(refused, Err(Failure::Unavailable(_))),
        "{refused:?}"
    );
    // The generic GRASP takes Fetch's arm: from where the episode starts the book is out of
    // reach; no step taken.
    let before = fetch.world().unwrap().bodies().pose(book);
    let steps = fetch.steps();
    let far = grasp(&mut fetch, &gripper, &Tuning::default(), None).unwrap();
    assert!(matches!(far, Err(Failure::Unreachable)), "{far:?}");
    assert_eq!(fetch.steps(), steps);
    assert_eq!(fetch.world().unwrap().bodies().pose(book), before);
    let second = Call { hand: 1, ..gripper };
    let one_hand = grasp(&mut fetch, &second, &Tuning::default(), None).unwrap();
    assert!(matches!(one_hand, Err(Failure::NoHand(1))), "{one_hand:?}");
    // Fetch's arm is driven joint by joint: through the end-effector controller it is refused.
    let mut config = common::config(ACTIVITY);
    config.robot = RobotKind::Fetch;
    let mut through_ik = Env::new(config);
    through_ik.reset(0).unwrap();
    let refused = grasp(&mut through_ik, &gripper, &Tuning::default(), None).unwrap();
    assert!(
        matches!(refused, Err(Failure::Unavailable(_))),
        "{refused:?}"
    );
}

#[test]
fn a_recorded_physical_grasp_and_placement_replay_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("behavior-hand-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("hand.mcap");
    let mut env = episode(RobotKind::Behavior);
    env.record_to(&path, RecordingSetup::new("", 10)).unwrap();
    let book = object(&env, "book.n.02_1");
    let under = support(&env, book);
    for (primitive, target) in [
        (Primitive::NavigateTo, book),
        (Primitive::Grasp, book),
        (Primitive::PlaceOnTop, under),
    ] {
        let outcome = run(&mut env, call(primitive, target), Mode::Physical, None).unwrap();
        assert!(
            outcome.result.is_ok(),
            "{primitive:?}: {:?}",
            outcome.result
        );
    }
    env.finish_recording().unwrap();
    let recording = read(&path).unwrap();
    assert_eq!(recording.frames.len() as u32, env.steps());
    let report = replay_with::<RecordedCall>(&recording, common::config(ACTIVITY)).unwrap();
    assert!(report.identical && report.checkpoints > 1, "{report:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
