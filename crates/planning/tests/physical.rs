//! Physical NAVIGATE_TO: a base plan driven by the robot's own actions with physics — the
//! robot ends in reach, no configuration it passed through collides when checked ten times
//! more finely than the planner did, and the recording replays bit for bit.

#[path = "../../env/tests/common/mod.rs"]
mod common;

use behavior_env::Env;
use behavior_env::record::{Recorder, read, replay};
use behavior_planning::{
    BaseSpace, Call, Primitive, Space, Standing, base_config, drive_to, within_reach,
};
use behavior_robots::RobotKind;

fn episode(activity: &str, robot: RobotKind, seed: u64) -> Env {
    let mut config = common::config(activity);
    config.robot = robot;
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
        let path = drive_to(&mut env, &call, None).unwrap().unwrap();
        assert!(!path.executed.is_empty(), "{robot:?} moved");
        let (world, bot) = (env.world().unwrap(), env.robot().unwrap());
        assert!(within_reach(world, bot, plank), "{robot:?} ends in reach");
        let after = base_config(&env);
        assert!(
            (after.x - before.x).hypot(after.y - before.y) > 0.1,
            "{robot:?}: {before:?} → {after:?}"
        );
        let end = path.planned.last().unwrap();
        assert!(
            (after.x - end.x).hypot(after.y - end.y)
                <= behavior_planning::POSITION_TOLERANCE + 1e-4
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
    let mut recorder = Recorder::create(&path, &env, "", 10).unwrap();
    let call = Call {
        primitive: Primitive::NavigateTo,
        object: object(&env, "plywood.n.01_2"),
        hand: 1,
    };
    drive_to(&mut env, &call, Some(&mut recorder))
        .unwrap()
        .unwrap();
    recorder.finish().unwrap();
    let recording = read(&path).unwrap();
    assert!(recording.edits.is_empty(), "driving is actions, not edits");
    assert_eq!(recording.frames.len() as u32, env.steps());
    let report = replay(&recording, common::config("bringing_in_wood")).unwrap();
    assert!(report.identical && report.checkpoints > 1, "{report:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
