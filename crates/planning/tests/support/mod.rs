//! Physical solves checked end to end, shared by the tests of the official activities and of
//! our own: the planner in the episode `behavior solve` makes, on several seeds, each solved
//! seed's recording replayed bit for bit.

#![allow(dead_code)]

use crate::common;
use behavior_bddl::Activity;
use behavior_env::EnvConfig;
use behavior_env::record::{RecordingSetup, read, replay_with};
use behavior_planning::{Limits, Mode, RecordedCall, Solver};
use behavior_robots::RobotKind;
use std::path::PathBuf;
use std::sync::Arc;

/// The edits a physical solution may record: forced grasps, hands put back where they were
/// pinned, the home's doors opened before the first drive, and switches (kinematic in the
/// original's motion-planning mode too); the rest is actions.
const EDITS: [&str; 7] = [
    behavior_planning::FORCED_GRASP,
    behavior_planning::HAND_RESET,
    behavior_planning::DOORS_OPENED,
    "open",
    "close",
    "toggle_on",
    "toggle_off",
];

/// The folder of our own activities (`activities/` at the repository's root).
pub fn own_folder() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../activities")
}

/// Our own activity `name` (its file's stem), checked against the official knowledge.
pub fn own_activity(name: &str) -> Arc<Activity> {
    let path = own_folder().join(format!("{name}.bddl"));
    let source = behavior_bddl::load::read_source(&path).unwrap();
    Arc::new(common::knowledge().load(&source).unwrap().0)
}

/// The episode `behavior solve activities/NAME.bddl` makes: the first covering home, with its
/// clutter.
pub fn own_config(name: &str) -> EnvConfig {
    let a = own_activity(name);
    let home = common::home(&a, true);
    EnvConfig::new(a, common::taxonomy(), vec![home])
}

/// `config` for `robot` driven by the physical primitives, with `behavior solve`'s step limit.
pub fn physical(mut config: EnvConfig, robot: RobotKind) -> EnvConfig {
    config.max_steps = 20_000;
    config.robot = robot;
    config.action_space = Mode::Physical.action_space(robot);
    config
}

/// Solves `name`'s episode (made by `config`) physically on seeds tried in the order given
/// until `k` are solved; panics, listing every seed's outcome, if too few can be. Physics makes
/// runs chaotic (which seeds are solved changes with any change to the planner or the homes:
/// README, "Physical mode"), so a test states on how many of several seeds its activity is
/// solved, not that one lucky seed is; the seeds solved at the last measurement come first, so
/// that a passing test takes no longer than it must.
pub fn solves_at_least(
    k: usize,
    seeds: &[u64],
    name: &str,
    config: &dyn Fn() -> EnvConfig,
    done: &[&str],
) {
    let mut outcomes = Vec::new();
    let mut solved = 0;
    for (tried, &seed) in seeds.iter().enumerate() {
        if solved + (seeds.len() - tried) < k {
            break;
        }
        let outcome = solve_physically(name, config, seed, done);
        solved += usize::from(outcome.is_ok());
        outcomes.push((seed, outcome));
        if solved == k {
            return;
        }
    }
    panic!("{name} solved on fewer than {k} of seeds {seeds:?}: {outcomes:#?}");
}

/// One physical solve of [`solves_at_least`]: `Err` says why it is not solved. A solution that
/// is solved but did not do each primitive of `done` with success, recorded an edit other than
/// [`EDITS`], or does not replay bit for bit fails the test.
pub fn solve_physically(
    name: &str,
    config: &dyn Fn() -> EnvConfig,
    seed: u64,
    done: &[&str],
) -> Result<(), String> {
    let dir = std::env::temp_dir().join(format!(
        "behavior-{name}-{seed}-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("solution.mcap");
    let mut env = behavior_env::Env::new(config());
    env.reset(seed).unwrap();
    env.record_to(&path, RecordingSetup::new("", 50)).unwrap();
    let solution = Solver::new(
        &mut env,
        Mode::Physical,
        Limits::default(),
        None,
        &mut |_| {},
    )
    .solve()
    .unwrap();
    env.finish_recording().unwrap();
    if !solution.success {
        std::fs::remove_dir_all(&dir).unwrap();
        return Err(format!(
            "Q = {}, given up: {:?}",
            solution.q_final, solution.given_up
        ));
    }
    // The primitive that reached the goal counts though the episode ended on its way.
    let last = solution.primitives.len().saturating_sub(1);
    for name_done in done {
        let did = solution
            .primitives
            .iter()
            .enumerate()
            .any(|(k, p)| p.name == *name_done && (p.ok || k == last));
        assert!(did, "{name} (seed {seed}): no {name_done} done");
    }
    let recording = read(&path).unwrap();
    assert_eq!(
        recording.damage, None,
        "{name}: the recording reads to its end"
    );
    for (step, edit) in &recording.edits {
        let primitive = edit["primitive"].as_str().unwrap_or_default();
        assert!(EDITS.contains(&primitive), "{name}: step {step}: {edit}");
    }
    let report = replay_with::<RecordedCall>(&recording, config()).unwrap();
    assert!(
        report.identical,
        "{name}: differs from step {:?}",
        report.first_difference
    );
    assert_eq!(report.q_final, 1.0);
    std::fs::remove_dir_all(&dir).unwrap();
    Ok(())
}
