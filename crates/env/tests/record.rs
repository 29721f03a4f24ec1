//! Recording and replay: a recorded episode replays bit for bit, a cut file replays up to where
//! it was cut and says so, a file that is not a recording is refused, and an episode resumed
//! from a checkpoint continues identically.

mod common;

use behavior_env::record::{RecordingSetup, read, replay, resume, state_digest};
use behavior_env::{Agent, Env};
use std::path::PathBuf;

/// A path named `name` in a scratch folder of its own, removed when the folder is dropped.
fn temp(name: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::Builder::new()
        .prefix("behavior-env-test-")
        .tempdir()
        .unwrap();
    let path = dir.path().join(name);
    (dir, path)
}

/// Records `steps` steps of a random agent; returns the environment at the end.
fn record(path: &std::path::Path, steps: u32, every: u32) -> Env {
    record_with(common::config("bringing_in_wood"), path, steps, every)
}

fn record_with(
    config: behavior_env::EnvConfig,
    path: &std::path::Path,
    steps: u32,
    every: u32,
) -> Env {
    let mut env = Env::new(config);
    env.reset(5).unwrap();
    env.record_to(path, RecordingSetup::new("(definition text)", every))
        .unwrap();
    let mut agent = Agent::named("random", 5).unwrap();
    let mut action = Vec::new();
    for _ in 0..steps {
        agent.act(&env, &mut action);
        env.step(&action).unwrap();
    }
    env.finish_recording().unwrap();
    env
}

#[test]
fn a_recorded_episode_replays_bit_for_bit() {
    let (_path_dir, path) = temp("whole.mcap");
    let env = record(&path, 90, 30);
    let recording = read(&path).unwrap();
    assert_eq!(recording.damage, None);
    assert_eq!(recording.frames.len(), 90);
    assert_eq!(recording.checkpoints.len(), 4, "steps 0, 30, 60, 90");
    let config = recording
        .config(common::activity("bringing_in_wood"), common::taxonomy())
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert_eq!((report.frames, report.checkpoints), (90, 4));
    assert!(report.identical, "{report:?}");
    // The recording's last checkpoint is the digest of the original run's state.
    let (world, robot) = (env.world().unwrap(), env.robot().unwrap());
    assert_eq!(recording.checkpoints[3].1, state_digest(world, robot, 90));
}

#[test]
fn the_last_step_is_checkpointed_and_the_poses_of_what_moved_rebuild_every_pose() {
    let (_path_dir, path) = temp("last.mcap");
    let env = record(&path, 70, 30);
    let recording = read(&path).unwrap();
    let steps: Vec<u32> = recording.checkpoints.iter().map(|(s, _)| *s).collect();
    assert_eq!(steps, [0, 30, 60, 70], "the closing step checkpointed too");
    let (world, robot) = (env.world().unwrap(), env.robot().unwrap());
    assert_eq!(recording.checkpoints[3].1, state_digest(world, robot, 70));
    let config = recording
        .config(common::activity("bringing_in_wood"), common::taxonomy())
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert!(report.identical && report.checkpoints == 4, "{report:?}");

    // Every object's pose after the last step, rebuilt from the poses of what moved.
    let last = recording.frames.last().unwrap().poses.clone().unwrap();
    let now: Vec<[f32; 7]> = world
        .bodies()
        .objects()
        .map(|(id, _)| {
            let p = world.bodies().pose(id);
            let (t, r) = (p.translation, p.rotation);
            [t.x, t.y, t.z, r.x, r.y, r.z, r.w]
        })
        .collect();
    assert_eq!(last.len(), recording.header.objects.len());
    assert!(
        last.iter()
            .zip(&now)
            .all(|(a, b)| a.map(f32::to_bits) == b.map(f32::to_bits))
    );
    // The file holds far fewer poses than objects × steps: most of a home does not move.
    let bytes = std::fs::read(&path).unwrap();
    let mut written = 0;
    for message in mcap::MessageStream::new(&bytes).unwrap() {
        let message = message.unwrap();
        if message.channel.topic == "/poses" {
            let value: serde_json::Value = serde_json::from_slice(&message.data).unwrap();
            written += value["poses"].as_array().unwrap().len();
        }
    }
    let objects = recording.header.objects.len();
    assert!(
        written < objects * 71 / 4,
        "{written} poses written for {objects} objects over 71 states"
    );
}

#[test]
fn a_fetch_episode_replays_bit_for_bit() {
    let (_path_dir, path) = temp("fetch.mcap");
    let mut config = common::config("re-shelving_library_books");
    config.robot = behavior_robots::RobotKind::Fetch;
    record_with(config, &path, 60, 20);
    let recording = read(&path).unwrap();
    assert_eq!(recording.header.robot, "fetch");
    assert_eq!(recording.frames[0].action.len(), 11);
    let config = recording
        .config(
            common::activity("re-shelving_library_books"),
            common::taxonomy(),
        )
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert!(report.identical && report.checkpoints == 4, "{report:?}");
}

#[test]
fn a_replay_notices_a_different_action() {
    let (_path_dir, path) = temp("changed.mcap");
    record(&path, 40, 20);
    let mut recording = read(&path).unwrap();
    recording.frames[25].action[0] = -recording.frames[25].action[0] + 0.5;
    let config = recording
        .config(common::activity("bringing_in_wood"), common::taxonomy())
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert!(!report.identical);
    assert_eq!(report.first_difference, Some(40));
}

#[test]
fn a_cut_recording_replays_up_to_the_cut_and_says_where() {
    let (_path_dir, path) = temp("cut.mcap");
    record(&path, 120, 10);
    let bytes = std::fs::read(&path).unwrap();
    let (_cut_dir, cut) = temp("cut_short.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() * 6 / 10]).unwrap();
    let recording = read(&cut).unwrap();
    let damage = recording.damage.clone().expect("the cut is reported");
    assert!(damage.contains("after step"), "{damage}");
    let frames = recording.frames.len();
    assert!(frames > 10 && frames < 120, "{frames} frames survive");
    let config = recording
        .config(common::activity("bringing_in_wood"), common::taxonomy())
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert!(report.identical && report.checkpoints >= 2, "{report:?}");
}

#[test]
fn files_that_are_not_recordings_are_refused_with_a_reason() {
    let (_junk_dir, junk) = temp("junk.mcap");
    std::fs::write(&junk, b"not an mcap file at all").unwrap();
    let err = read(&junk).unwrap_err().to_string();
    assert!(err.contains("junk.mcap"), "{err}");
    let (_path_dir, path) = temp("header_only.mcap");
    record(&path, 5, 10);
    let bytes = std::fs::read(&path).unwrap();
    let (_cut_dir, cut) = temp("too_short.mcap");
    std::fs::write(&cut, &bytes[..40]).unwrap();
    let err = read(&cut).unwrap_err().to_string();
    assert!(err.contains("header"), "{err}");
    assert!(read(&temp("missing.mcap").1).is_err());
}

#[test]
fn an_episode_resumed_from_a_checkpoint_continues_identically() {
    let mut env = common::env("bringing_in_wood");
    env.reset(8).unwrap();
    let mut agent = Agent::named("random", 8).unwrap();
    let actions: Vec<Vec<f32>> = (0..60)
        .map(|_| {
            let mut a = Vec::new();
            agent.act(&env, &mut a);
            a
        })
        .collect();
    for a in &actions[..20] {
        env.step(a).unwrap();
    }
    let checkpoint = env.checkpoint().unwrap();
    let digest = |env: &Env| state_digest(env.world().unwrap(), env.robot().unwrap(), env.steps());
    for a in &actions[20..] {
        env.step(a).unwrap();
    }
    let first = (digest(&env), env.metrics().unwrap());
    env.restore(&checkpoint);
    for a in &actions[20..] {
        env.step(a).unwrap();
    }
    assert_eq!((digest(&env), env.metrics().unwrap()), first);
}

#[test]
fn a_recording_resumed_at_a_checkpoint_continues_as_recorded() {
    let (_path_dir, path) = temp("resume.mcap");
    let env = record(&path, 60, 20);
    let mut recording = read(&path).unwrap();
    assert_eq!(
        recording.states.len(),
        4,
        "a full state with every checkpoint"
    );
    let config = |r: &behavior_env::record::Recording| {
        r.config(common::activity("bringing_in_wood"), common::taxonomy())
            .unwrap()
    };
    let digest = |env: &Env| state_digest(env.world().unwrap(), env.robot().unwrap(), env.steps());
    for at in [20, 40] {
        let mut resumed = resume(&recording, config(&recording), at).unwrap();
        assert_eq!(resumed.steps(), at);
        for frame in &recording.frames[at as usize..] {
            resumed.step(&frame.action).unwrap();
        }
        assert_eq!(digest(&resumed), digest(&env));
        assert_eq!(digest(&resumed), recording.checkpoints[3].1);
        assert_eq!(resumed.metrics(), env.metrics());
    }
    assert!(
        resume(&recording, config(&recording), 25).is_err(),
        "no checkpoint at 25"
    );
    // A damaged saved state is refused, naming the checkpoint; without saved states the
    // episode is re-simulated to the checkpoint instead.
    let state = &mut recording.states[2].1;
    let middle = state.len() / 2;
    state[middle] ^= 0x55;
    let err = match resume(&recording, config(&recording), 40) {
        Ok(_) => panic!("a damaged state was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(err.contains("step 40"), "{err}");
    recording.states.clear();
    let resimulated = resume(&recording, config(&recording), 40).unwrap();
    assert_eq!(resimulated.steps(), 40);
}

#[test]
fn a_recording_is_taken_to_any_step_between_its_checkpoints() {
    use behavior_env::NoEdits;
    use behavior_env::record::{ReplayError, state_at};
    let (_path_dir, path) = temp("any-step.mcap");
    let env = record(&path, 60, 20);
    let recording = read(&path).unwrap();
    let config = || {
        recording
            .config(common::activity("bringing_in_wood"), common::taxonomy())
            .unwrap()
    };
    let digest = |env: &Env| state_digest(env.world().unwrap(), env.robot().unwrap(), env.steps());
    // Step 33 by the saved state of step 20 and 13 actions, against the episode begun again
    // and every action taken from the reset (no saved state used).
    let at = state_at::<NoEdits>(&recording, config(), 33).unwrap();
    assert_eq!(at.steps(), 33);
    let mut straight = Env::new(config());
    straight.reset(5).unwrap();
    for frame in &recording.frames[..33] {
        straight.step(&frame.action).unwrap();
    }
    assert_eq!(digest(&at), digest(&straight));
    assert_eq!(at.score(), straight.score());
    // It goes on as recorded to the end.
    let mut at = at;
    for frame in &recording.frames[33..] {
        at.step(&frame.action).unwrap();
    }
    assert_eq!(digest(&at), digest(&env));
    let start = state_at::<NoEdits>(&recording, config(), 0).unwrap();
    assert_eq!(start.steps(), 0);
    let past = state_at::<NoEdits>(&recording, config(), 61).err();
    assert!(
        matches!(past, Some(ReplayError::PastTheEnd { step: 61, last: 60 })),
        "{past:?}"
    );
}

/// An edit of the world for the tests: lifts the object of that name by `mm` millimetres.
#[derive(serde::Serialize, serde::Deserialize)]
struct Lift {
    object: String,
    mm: u32,
}

#[derive(Debug, thiserror::Error)]
#[error("no object `{0}`")]
struct NoSuchObject(String);

impl behavior_env::WorldEdit for Lift {
    type Error = NoSuchObject;

    fn apply(&self, edit: behavior_env::Edit<'_>) -> Result<(), NoSuchObject> {
        let id = (edit.world.bodies().object_named(&self.object))
            .ok_or_else(|| NoSuchObject(self.object.clone()))?;
        let mut pose = edit.world.bodies().pose(id);
        pose.translation.z += self.mm as f32 / 1000.0;
        edit.world
            .bodies_mut()
            .set_pose(id, pose)
            .map_err(|_| NoSuchObject(self.object.clone()))
    }
}

#[test]
fn the_episode_records_its_own_edits_and_a_replay_of_their_type_does_them_again() {
    use behavior_env::EnvError;
    use behavior_env::record::{ReplayError, replay_with};
    let (_dir, path) = temp("edited.mcap");
    let mut env = common::env("bringing_in_wood");
    env.reset(5).unwrap();
    env.record_to(&path, RecordingSetup::new("(definition text)", 10))
        .unwrap();
    let plank = env
        .world()
        .unwrap()
        .bodies()
        .objects()
        .map(|(_, o)| o.name.clone());
    let plank = plank
        .into_iter()
        .find(|n| n.starts_with("plywood"))
        .unwrap();
    let still = vec![0.0; env.robot().unwrap().action_dim()];
    for step in 0..20 {
        if step == 7 {
            // Recorded, as every edit of a recording episode must be.
            let lift = Lift {
                object: plank.clone(),
                mm: 30,
            };
            env.apply(&lift).unwrap().unwrap();
            // An edit that fails changes nothing and is not recorded.
            let missing = Lift {
                object: "no_such_thing".into(),
                mm: 1,
            };
            assert!(env.apply(&missing).unwrap().is_err());
            // An edit that would go unrecorded is refused.
            let refused = env.edit(|e| e.world.bodies().objects().count());
            assert!(
                matches!(refused, Err(EnvError::UnrecordedEdit)),
                "{refused:?}"
            );
        }
        env.step(&still).unwrap();
    }
    env.finish_recording().unwrap();
    assert!(!env.is_recording());
    let recording = read(&path).unwrap();
    assert_eq!(recording.frames.len(), 20);
    assert_eq!(recording.edits.len(), 1, "{:?}", recording.edits);
    assert_eq!(recording.edits[0].0, 7, "after step 7");
    let config = || {
        recording
            .config(common::activity("bringing_in_wood"), common::taxonomy())
            .unwrap()
    };
    let report = replay_with::<Lift>(&recording, config()).unwrap();
    assert!(report.identical && report.checkpoints == 3, "{report:?}");
    // Taken to a step after the edit, from the reset's saved state (the edit done again) or
    // from step 10's (the edit already in it), the episode goes on to the recorded end.
    for at in [8, 15] {
        let mut resumed = behavior_env::record::state_at::<Lift>(&recording, config(), at).unwrap();
        for frame in &recording.frames[at as usize..] {
            resumed.step(&frame.action).unwrap();
        }
        let end = state_digest(resumed.world().unwrap(), resumed.robot().unwrap(), 20);
        assert_eq!(end, recording.checkpoints[2].1, "taken to step {at}");
    }
    // Without the edit's type, the replay stops at the edit and says why.
    let plain = replay(&recording, config());
    assert!(
        matches!(plain, Err(ReplayError::UnreadableEdit { step: 7, .. })),
        "{plain:?}"
    );
}
