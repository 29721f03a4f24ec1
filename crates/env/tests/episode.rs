//! Episodes as a user runs them: reset, step, observations, reward, termination, bad actions.

mod common;

use behavior_assets::Library;
use behavior_env::record::state_digest;
use behavior_env::{Env, EnvError, TASK_OBS_DIM};
use behavior_sampling::instantiate;

#[test]
fn a_reset_puts_the_robot_where_the_agent_stood_and_observes() {
    let mut env = common::env("bringing_in_wood");
    let (obs, info) = env.reset(3).unwrap();
    assert_eq!(obs.proprioception.len(), 22);
    assert_eq!(obs.task_obs.len(), TASK_OBS_DIM);
    // Three planks, valid, and the rest of the slots empty.
    let valid: Vec<f32> = (0..50).map(|k| obs.task_obs[6 + 9 * k]).collect();
    assert_eq!(&valid[..3], &[1.0; 3]);
    assert!(valid[3..].iter().all(|&v| v == 0.0));
    assert_eq!(info.steps, 0);
    assert!(!info.score.success);
    let world = env.world().unwrap();
    let stand_in = world.bodies().object_named("agent.n.01_1").unwrap();
    assert!(
        !world.bodies().object(stand_in).is_present(),
        "the robot replaced the stand-in"
    );
}

#[test]
fn a_seed_whose_own_sampling_fails_starts_from_a_seed_derived_from_it() {
    // Some seeds leave no room for an object of the activity (Gymnasium's `check_env` once drew
    // one for bringing_in_wood), and a reset must not fail on a seed the environment drew. The
    // first such seed of throwing_away_leftovers from a fixed start, found by sampling (about one
    // in seven fails in its first covering home: a plate finds no room on the countertop).
    let activity = common::activity("throwing_away_leftovers");
    let home = common::home(&activity, false);
    let library = Library::new(&common::knowledge().taxonomy);
    let start = 6_711_016_283_805_236_356u64;
    let seed = (start..start + 2_000)
        .find(|&seed| {
            let own = instantiate(
                &activity,
                &home,
                seed,
                &library,
                &common::knowledge().taxonomy,
            );
            own.is_err()
        })
        .expect("one of 2,000 seeds fails to sample by itself");
    eprintln!("seed {seed} fails to sample by itself");
    let mut env = common::env("throwing_away_leftovers");
    let digest = |env: &mut Env| {
        env.reset(seed).unwrap();
        state_digest(env.world().unwrap(), env.robot().unwrap(), 0)
    };
    let first = digest(&mut env);
    assert_eq!(digest(&mut env), first, "the same seed, the same instance");
}

#[test]
fn bad_actions_are_refused_and_change_nothing() {
    let mut env = common::env("bringing_in_wood");
    assert!(matches!(env.step(&[0.0; 26]), Err(EnvError::NotReset)));
    env.reset(1).unwrap();
    let before = env.checkpoint().unwrap();
    let pose = |env: &behavior_env::Env| env.robot().unwrap().base_pose(env.world().unwrap());
    let start = pose(&env);
    for bad in [vec![0.0; 25], vec![f32::NAN; 26], {
        let mut v = vec![0.0; 26];
        v[3] = f32::INFINITY;
        v
    }] {
        let err = env.step(&bad).unwrap_err();
        assert!(matches!(err, EnvError::Action(_)), "{err}");
    }
    assert_eq!(env.steps(), 0);
    assert_eq!(pose(&env), start);
    env.restore(&before);
    assert_eq!(env.steps(), 0);
}

#[test]
fn the_first_option_reward_sums_to_the_change_of_that_option_s_satisfied_fraction() {
    use behavior_bddl::{GroundGoal, PredicateOracle, options::options};
    use behavior_env::{Agent, Env, Reward};
    use behavior_sim::BoundWorld;
    let mut config = common::config("re-shelving_library_books");
    config.reward = Reward::FirstOption;
    let first = options(&GroundGoal::new(&config.activity)).next().unwrap();
    let mut env = Env::new(config);
    env.reset(3).unwrap();
    let fraction = |env: &Env| {
        let oracle = BoundWorld {
            world: env.world().unwrap(),
            bindings: env.bindings().unwrap(),
        };
        let holding = first
            .iter()
            .filter(|l| oracle.holds(l.atom) == l.positive)
            .count();
        holding as f64 / first.len() as f64
    };
    let before = fraction(&env);
    let mut agent = Agent::named("random", 3).unwrap();
    let (mut action, mut total) = (Vec::new(), 0.0);
    for _ in 0..40 {
        agent.act(&env, &mut action);
        total += env.step(&action).unwrap().reward;
    }
    assert!((total - (fraction(&env) - before)).abs() < 1e-12, "{total}");
    assert!(
        before > 0.0,
        "some of the first option holds at the start: {before}"
    );
}
