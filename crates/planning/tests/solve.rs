//! The task planner end to end: activities solved with symbolic primitives, some with physical
//! primitives (the BehaviorRobot and Fetch), and their recordings replayed bit for bit with the
//! edits done again.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_env::record::{RecordingSetup, read, replay, replay_with};
use behavior_planning::{Limits, Mode, RecordedCall, Solution, Solver};
use behavior_robots::RobotKind;

fn solve(activity: &str, seed: u64) -> (Solution, behavior_env::Env) {
    let mut env = common::env(activity);
    env.reset(seed).unwrap();
    let solution = solve_in(&mut env, Mode::Symbolic).unwrap();
    (solution, env)
}

/// The planner in `env` as it is (recording if the episode records).
fn solve_in(
    env: &mut behavior_env::Env,
    mode: Mode,
) -> Result<Solution, behavior_planning::RunError> {
    Solver::new(env, mode, Limits::default(), None, &mut |_| {}).solve()
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
        let (solution, env) = solve(activity, 1);
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
    env.record_to(&path, RecordingSetup::new("", 5)).unwrap();
    let solution = solve_in(&mut env, Mode::Symbolic).unwrap();
    env.finish_recording().unwrap();
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
    let report = replay_with::<RecordedCall>(&recording, config()).unwrap();
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
    let err = solve_in(&mut env, Mode::Symbolic).unwrap_err();
    assert!(
        matches!(
            err,
            behavior_planning::RunError::Env(behavior_env::EnvError::NotReset)
        ),
        "{err}"
    );
}

/// Checks that `activity` is solved physically by `robot` on at least `k` of `seeds` in the
/// episode `behavior solve` makes (the first covering home with its clutter, every navigation
/// driven, every grasp and placement planned and executed with physics), `placement` done
/// physically on each, and that each solved seed's recording replays bit for bit (see
/// `support::solves_at_least`).
fn solves_at_least(k: usize, seeds: [u64; 6], activity: &str, placement: &str, robot: RobotKind) {
    let config = || {
        let a = common::activity(activity);
        let home = common::home(&a, true);
        let c = behavior_env::EnvConfig::new(a, common::taxonomy(), vec![home]);
        support::physical(c, robot)
    };
    let done = ["grasp", placement, "navigate_to"];
    let name = format!("{activity} ({})", robot.name());
    support::solves_at_least(k, &seeds, &name, &config, &done);
}

// Each physical test tries Table 1's seeds 0–5 (`bench/table1`), those solved at the last
// measurement (2026-11-28, issue 41's runs) first.

#[test]
fn laying_tile_floors_is_solved_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // Tiles carried to the bathroom floor (every seed of 0–5 solved).
    let seeds = [0, 1, 2, 3, 4, 5];
    solves_at_least(
        1,
        seeds,
        "laying_tile_floors",
        "place_onfloor",
        RobotKind::Behavior,
    );
}

#[test]
fn re_shelving_library_books_is_solved_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // Books carried from the tables onto a shelf (seeds 0, 1, 3 and 4 solved).
    let seeds = [0, 1, 3, 4, 2, 5];
    let activity = "re-shelving_library_books";
    solves_at_least(1, seeds, activity, "place_ontop", RobotKind::Behavior);
}

#[test]
fn throwing_away_leftovers_is_solved_physically_on_two_of_six_seeds_and_replays_bit_for_bit() {
    // Hamburgers taken off plates and put into an ashcan (every seed of 0–5 solved).
    let seeds = [0, 1, 2, 3, 4, 5];
    let activity = "throwing_away_leftovers";
    solves_at_least(2, seeds, activity, "place_inside", RobotKind::Behavior);
}

#[test]
fn organizing_file_cabinet_is_solved_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // Documents and folders put into a file cabinet's drawer: a folder held by its cover keeps
    // its other half off the palm, and where one place in the drawer has no way in, the next
    // (seeds 0, 3, 4 and 5 solved).
    let seeds = [3, 0, 4, 5, 1, 2];
    let activity = "organizing_file_cabinet";
    solves_at_least(1, seeds, activity, "place_inside", RobotKind::Behavior);
}

#[test]
fn collect_misplaced_items_is_solved_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // A necklace taken from the cabinet drawer it lies in, pulled out with the drawer by OPEN,
    // a shoe and a notebook from under tables, socks from a sofa and the floor, all put on a
    // table (seeds 3 and 4 solved).
    let seeds = [4, 3, 0, 1, 2, 5];
    let activity = "collect_misplaced_items";
    solves_at_least(1, seeds, activity, "place_ontop", RobotKind::Behavior);
}

#[test]
fn fetch_throws_away_leftovers_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // Fetch's arm driven joint by joint: hamburgers taken off plates with the gripper pointing
    // down, carried over the base, and let go above the ashcan (seeds 0, 1, 3, 4 and 5 solved).
    let seeds = [3, 0, 1, 4, 5, 2];
    let activity = "throwing_away_leftovers";
    solves_at_least(1, seeds, activity, "place_inside", RobotKind::Fetch);
}

#[test]
fn fetch_carries_plywood_upright_through_doors_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // Sheets of plywood 0.9 m across taken by their edge off the floor (the base standing clear
    // of the sheet, not over it), carried upright beside the base through doorways 0.75 m wide,
    // and laid on the kitchen floor (seeds 1, 3 and 5 solved).
    let seeds = [1, 3, 5, 0, 2, 4];
    solves_at_least(
        1,
        seeds,
        "bringing_in_wood",
        "place_onfloor",
        RobotKind::Fetch,
    );
}

#[test]
fn r1_reshelves_library_books_physically_on_one_of_six_seeds_and_replays_bit_for_bit() {
    // The R1, built only through the robot interfaces: its torso bent and its right arm moved
    // joint by joint through the 23-d action's positions, books taken off the tables with the
    // gripper pointing down and put on a shelf (seeds 0, 1, 3 and 5 solved).
    let seeds = [0, 1, 3, 5, 2, 4];
    let activity = "re-shelving_library_books";
    solves_at_least(1, seeds, activity, "place_ontop", RobotKind::R1);
}
