//! Physical NAVIGATE_TO: a base plan driven by the robot's own actions with physics — the
//! robot ends in reach, no configuration it passed through collides when checked ten times
//! more finely than the planner did, and the recording replays bit for bit.

#[path = "../../env/tests/common/mod.rs"]
mod common;

use behavior_core::Predicate;
use behavior_env::Env;
use behavior_env::record::{RecordingSetup, read, replay_with};
use behavior_motion::{BaseConfig, BaseSpace, Space, Standing};
use behavior_planning::{
    Call, Mode, Primitive, RecordedCall, Tuning, base_config, drive_to, reaches, within_reach,
};
use behavior_robots::RobotKind;

fn episode(activity: &str, robot: RobotKind, seed: u64) -> Env {
    let mut config = common::config(activity);
    config.robot = robot;
    config.action_space = Mode::Physical.action_space(robot);
    let mut env = Env::new(config);
    env.reset(seed).unwrap();
    env
}

fn object(env: &Env, instance: &str) -> behavior_sim::ObjectId {
    let k = env.config().activity.instance_named(instance).unwrap();
    env.bindings().unwrap()[k.0 as usize].unwrap()
}

#[test]
fn both_robots_drive_to_an_object_without_touching_anything() {
    for robot in RobotKind::ALL {
        let mut env = episode("bringing_in_wood", robot, 0);
        let plank = object(&env, "plywood.n.01_1");
        let before = base_config(&env);
        let call = Call {
            primitive: Primitive::NavigateTo,
            object: plank,
            hand: 0,
        };
        let path = drive_to(&mut env, &call, &Tuning::default(), None)
            .unwrap()
            .unwrap();
        assert!(!path.executed.is_empty(), "{robot:?} moved");
        let (world, bot) = (env.world().unwrap(), env.robot().unwrap());
        assert!(within_reach(world, bot, plank), "{robot:?} ends in reach");
        // Each robot stands where what it acts with reaches the plank: Fetch's arm has a free
        // configuration over it, a BehaviorRobot's hand comes to it open from above or across.
        assert!(
            reaches(&env, plank, None, &Tuning::default()),
            "{robot:?}'s hand reaches it"
        );
        let after = base_config(&env);
        assert!(
            (after.x - before.x).hypot(after.y - before.y) > 0.1,
            "{robot:?}: {before:?} → {after:?}"
        );
        let end = path.planned.last().unwrap();
        assert!(
            (after.x - end.x).hypot(after.y - end.y) <= Tuning::default().position_tolerance + 1e-4
        );
        // Every configuration driven through, and every move between two of them checked ten
        // times more finely than the planner's resolution, is free.
        let standing = Standing::of(world, bot);
        let space = BaseSpace::new(world, standing.footprint, standing.filter, &before, &after);
        let mut previous = before;
        for c in &path.executed {
            for fine in space.steps(&previous, c, 0.005) {
                assert!(space.free(&fine), "{robot:?}: {fine:?} collides");
            }
            previous = *c;
        }
    }
}

#[test]
fn a_recorded_drive_replays_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("behavior-drive-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("drive.mcap");
    let mut env = episode("bringing_in_wood", RobotKind::Behavior, 1);
    env.record_to(&path, RecordingSetup::new("", 10)).unwrap();
    let call = Call {
        primitive: Primitive::NavigateTo,
        object: object(&env, "plywood.n.01_2"),
        hand: 1,
    };
    drive_to(&mut env, &call, &Tuning::default(), None)
        .unwrap()
        .unwrap();
    env.finish_recording().unwrap();
    let recording = read(&path).unwrap();
    // Driving is actions; the one edit opens the home's doors before the first drive.
    let edits: Vec<&str> = (recording.edits.iter())
        .map(|(_, e)| e["primitive"].as_str().unwrap_or_default())
        .collect();
    assert_eq!(edits, [behavior_planning::DOORS_OPENED]);
    assert_eq!(recording.frames.len() as u32, env.steps());
    let config = common::config("bringing_in_wood");
    let report = replay_with::<RecordedCall>(&recording, config).unwrap();
    assert!(report.identical && report.checkpoints > 1, "{report:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Puts the robot 10 cm into the first fixed piece of furniture beside which that is all it
/// overlaps, facing away from it with room ahead, as a door it opened or a push can leave it.
fn put_into_furniture(env: &mut Env) -> behavior_sim::ObjectId {
    let (world, robot) = (env.world().unwrap(), env.robot().unwrap());
    let mut standing = Standing::of(world, robot);
    let base = robot.base_pose(world);
    let radius = match robot.kind() {
        RobotKind::Behavior => behavior_robots::BODY_RADIUS,
        RobotKind::Fetch => behavior_robots::BASE_RADIUS,
        RobotKind::R1 => behavior_robots::R1_BASE_RADIUS,
    };
    let found = world.bodies().objects().find_map(|(id, o)| {
        let b = world.bodies().aabb(id);
        let c = BaseConfig::new(b.maxs.x + radius - 0.1, 0.5 * (b.mins.y + b.maxs.y), 0.0);
        standing.config = c;
        let only_it = standing.overlapping(world, &c) == [id.into()];
        let ahead = BaseConfig::new(c.x + 0.3, c.y, 0.0);
        let way_out = standing.overlapping(world, &ahead).is_empty();
        // Furniture: fixed, without doors, lower than a wall.
        let furniture = o.is_fixed() && o.links.is_empty() && b.maxs.z < 1.5;
        (furniture && only_it && way_out).then_some((id, c))
    });
    let (furniture, c) = found.expect("a fixed piece of furniture to stand in");
    let pose = rapier3d::math::Pose::from_parts(
        rapier3d::math::Vector::new(c.x, c.y, base.translation.z),
        rapier3d::math::Rotation::IDENTITY,
    );
    env.edit(|edit| edit.robot.teleport(edit.world, pose))
        .unwrap()
        .unwrap();
    furniture
}

#[test]
fn a_robot_put_into_furniture_backs_out_and_stands_clear_by_it() {
    // The BehaviorRobot: Fetch backs out the same way (straight back or forward only), but its
    // base plans reach half the stands the BehaviorRobot's do (README), none in this home here.
    for robot in [RobotKind::Behavior] {
        let mut env = episode("bringing_in_wood", robot, 0);
        let furniture = put_into_furniture(&mut env);
        let (world, bot) = (env.world().unwrap(), env.robot().unwrap());
        let standing = Standing::of(world, bot);
        let start = standing.config;
        assert_eq!(standing.overlapping(world, &start), [furniture.into()]);
        // Asked to face the furniture it stands in: out, then to a clear place by it.
        let call = Call {
            primitive: Primitive::NavigateTo,
            object: furniture,
            hand: 0,
        };
        let path = drive_to(&mut env, &call, &Tuning::default(), None).unwrap();
        let path = path.unwrap_or_else(|f| panic!("{robot:?}: {f}"));
        let (world, bot) = (env.world().unwrap(), env.robot().unwrap());
        assert!(
            within_reach(world, bot, furniture),
            "{robot:?} ends in reach"
        );
        let end = Standing::of(world, bot);
        assert!(
            end.overlapping(world, &end.config).is_empty(),
            "{robot:?} ends clear"
        );
        // It left the furniture without turning first: the heading is kept until it is out.
        let out = path
            .planned
            .iter()
            .position(|c| standing.overlapping(world, c).is_empty())
            .expect("the plan leaves the furniture");
        assert!(out > 0, "{robot:?}: the plan starts inside the furniture");
        for c in &path.planned[..out] {
            assert_eq!(c.yaw, start.yaw, "{robot:?} turned inside the furniture");
        }
    }
}

#[test]
fn a_primitive_that_uses_up_the_episode_ends_it_truncated_rather_than_failing() {
    let mut config = common::config("bringing_in_wood");
    config.max_steps = 10;
    let mut env = Env::new(config);
    env.reset(0).unwrap();
    let call = Call {
        primitive: Primitive::NavigateTo,
        object: object(&env, "plywood.n.01_1"),
        hand: 0,
    };
    let outcome = behavior_planning::run(&mut env, call, Mode::Physical, None).unwrap();
    assert!(env.is_over());
    assert!(outcome.result.is_err(), "the drive was cut short");
    assert!(outcome.step.truncated && !outcome.step.terminated);
    assert_eq!(outcome.step.info.steps, 10);
}

#[test]
fn a_drive_opens_the_homes_doors_but_not_one_the_activity_names() {
    // cleaning_carpets names a door of the corridor; the home's other doors start closed.
    let mut env = episode("cleaning_carpets", RobotKind::Behavior, 0);
    let named = object(&env, "door.n.01_1");
    let doors = |env: &Env| -> Vec<(behavior_sim::ObjectId, bool)> {
        let world = env.world().unwrap();
        world
            .bodies()
            .objects()
            .filter(|(_, o)| o.category == "door.n.01")
            .map(|(id, _)| (id, world.state(id, Predicate::Open)))
            .collect()
    };
    let before = doors(&env);
    let home_closed = before.iter().filter(|&&(id, open)| id != named && !open);
    assert!(home_closed.count() > 0, "{before:?}");
    let call = Call {
        primitive: Primitive::NavigateTo,
        object: object(&env, "hand_towel.n.01_1"),
        hand: 0,
    };
    let _ = drive_to(&mut env, &call, &Tuning::default(), None).unwrap();
    for ((id, was), (_, is)) in before.iter().zip(doors(&env)) {
        if *id == named {
            assert_eq!(is, *was, "the activity's door keeps its state");
        } else {
            assert!(is, "door {id:?} of the home is open after the drive");
        }
    }
}
