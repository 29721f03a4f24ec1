//! Our own activities (`activities/*.bddl` at the repository's root, none of them among the
//! official 100): each samples in the first named home that covers it, is solved with symbolic
//! primitives, and is solved with physics by the BehaviorRobot on one of a few seeds, its
//! recording replayed bit for bit. They ask for what the official definitions' tuning could
//! hide: slicing and moving the halves, dusting, soaking, cooking, freezing, thawing out of the
//! cold, switching on, putting under and next to, in six kinds of room.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_env::Env;
use behavior_planning::{Limits, Mode, Solver};
use behavior_robots::RobotKind;

/// Each own activity (its file's stem), the seeds its physical test tries (those solved at the
/// last measurement first; the bathroom's sink is hard to reach), and the primitives a physical
/// solution must have done.
const OWN: [(&str, &[u64], &[&str]); 10] = [
    ("slicing_an_apple", &[1, 2, 3, 0], &["grasp", "slice"]),
    (
        "serving_a_sliced_lemon",
        &[0, 1, 2, 3],
        &["grasp", "slice", "place_ontop"],
    ),
    (
        "dusting_the_living_room_table",
        &[0, 1, 2, 3],
        &["grasp", "wipe"],
    ),
    // Soaked by the drops as the tap is switched on beside it, or by SOAK.
    ("wetting_a_dishtowel", &[7, 8, 3, 0, 1, 2], &["grasp"]),
    (
        "cooking_meat_on_the_stove",
        &[0, 1, 2, 3],
        &["grasp", "place_ontop"],
    ),
    ("freezing_fish", &[0, 1, 2, 3], &["grasp", "place_inside"]),
    (
        "thawing_chicken",
        &[0, 1, 2, 3],
        &["grasp", "place_onfloor"],
    ),
    (
        "switching_on_the_printer",
        &[0, 1, 2, 3],
        &["navigate_to", "toggle_on"],
    ),
    (
        "stowing_shoes_under_the_table",
        &[0, 1, 2, 3],
        &["grasp", "place_under"],
    ),
    (
        "gathering_socks_into_a_basket",
        &[0, 2, 1, 3],
        &["grasp", "place_inside", "place_nextto"],
    ),
];

#[test]
fn the_folder_holds_ten_activities_of_our_own_none_of_them_official() {
    let mut found: Vec<String> = std::fs::read_dir(support::own_folder())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "bddl"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    found.sort();
    let mut listed: Vec<String> = OWN.iter().map(|(n, ..)| n.to_string()).collect();
    listed.sort();
    assert_eq!(found, listed, "activities/ and this test's list differ");
    let official = common::official_activities();
    for name in &found {
        assert!(!official.contains(name), "{name} is an official activity");
        assert_eq!(
            support::own_activity(name).name,
            format!("{name}_0"),
            "{name}'s problem name"
        );
    }
}

#[test]
fn each_samples_and_is_solved_with_symbolic_primitives() {
    for (name, ..) in OWN {
        let mut env = Env::new(support::own_config(name));
        env.reset(0)
            .unwrap_or_else(|e| panic!("{name} does not sample: {e}"));
        let solution = Solver::new(
            &mut env,
            Mode::Symbolic,
            Limits::default(),
            None,
            &mut |_| {},
        )
        .solve()
        .unwrap();
        assert!(
            solution.success,
            "{name}: Q = {}, given up: {:?}",
            solution.q_final, solution.given_up
        );
    }
}

/// One test per activity, so that they run side by side.
macro_rules! physical {
    ($($test:ident: $k:expr;)*) => {$(
        #[test]
        fn $test() {
            let (name, seeds, done) = OWN[$k];
            let config = || support::physical(support::own_config(name), RobotKind::Behavior);
            support::solves_at_least(1, seeds, name, &config, done);
        }
    )*};
}

physical! {
    slicing_an_apple_is_solved_with_physics_and_replays_bit_for_bit: 0;
    serving_a_sliced_lemon_is_solved_with_physics_and_replays_bit_for_bit: 1;
    dusting_the_living_room_table_is_solved_with_physics_and_replays_bit_for_bit: 2;
    wetting_a_dishtowel_is_solved_with_physics_and_replays_bit_for_bit: 3;
    cooking_meat_on_the_stove_is_solved_with_physics_and_replays_bit_for_bit: 4;
    freezing_fish_is_solved_with_physics_and_replays_bit_for_bit: 5;
    thawing_chicken_is_solved_with_physics_and_replays_bit_for_bit: 6;
    switching_on_the_printer_is_solved_with_physics_and_replays_bit_for_bit: 7;
    stowing_shoes_under_the_table_is_solved_with_physics_and_replays_bit_for_bit: 8;
    gathering_socks_into_a_basket_is_solved_with_physics_and_replays_bit_for_bit: 9;
}
