//! The metrics on scripted episodes, against values computed by hand from what the test saw.

mod common;

use behavior_env::record::RecordingSetup;
use behavior_env::{Agent, Env};
use behavior_robots::ActionSpace;

fn base_position(env: &Env) -> rapier3d::math::Vector {
    env.robot()
        .unwrap()
        .base_pose(env.world().unwrap())
        .translation
}

#[test]
fn an_idle_episode_takes_time_and_disarranges_nothing() {
    let mut env = common::env("bringing_in_wood");
    let (_, info) = env.reset(2).unwrap();
    let mut agent = Agent::named("idle", 0).unwrap();
    let mut action = Vec::new();
    for _ in 0..45 {
        agent.act(&env, &mut action);
        let step = env.step(&action).unwrap();
        assert_eq!(step.reward, 0.0);
    }
    let m = env.metrics().unwrap();
    assert_eq!(m.steps, 45);
    assert_eq!(m.sim_time_s, 1.5, "45 steps / 30 Hz");
    assert_eq!(m.q_final, info.score.q);
    assert_eq!(m.kinematic_disarrangement, 0.0);
    assert_eq!(m.logical_disarrangement, 0);
    assert_eq!(m.distance_navigated, 0.0);
    assert_eq!(m.hand_displacement_left + m.hand_displacement_right, 0.0);
}

#[test]
fn distance_navigated_is_the_sum_of_the_base_s_steps() {
    let mut config = common::config("bringing_in_wood");
    config.action_space = ActionSpace::Navigation;
    let mut env = Env::new(config);
    env.reset(2).unwrap();
    let mut by_hand = 0.0f64;
    let mut last = base_position(&env);
    // Forward, then turning while moving sideways: 30 steps of at most 0.05 m.
    for k in 0..30 {
        let action = if k < 15 {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 0.6, 1.0]
        };
        env.step(&action).unwrap();
        let now = base_position(&env);
        by_hand += f64::from((now - last).length());
        last = now;
    }
    let m = env.metrics().unwrap();
    assert!(by_hand > 0.3, "the robot moved {by_hand} m");
    assert!(
        (m.distance_navigated - by_hand).abs() < 1e-9,
        "{} vs {by_hand}",
        m.distance_navigated
    );
    assert!(m.distance_navigated <= 15.0 * 0.05 + 15.0 * 0.03 + 1e-6);
    // The hands came along in the air, touching nothing: no hand displacement.
    assert_eq!(m.hand_displacement_left + m.hand_displacement_right, 0.0);
    assert!(
        m.parts[1].distance > 0.3,
        "the left hand moved with the body"
    );
}

#[test]
fn an_idle_agent_navigates_nothing_and_a_random_one_more() {
    let run = |agent: &str| {
        let mut env = common::env("bringing_in_wood");
        env.reset(4).unwrap();
        let mut agent = Agent::named(agent, 4).unwrap();
        let mut action = Vec::new();
        for _ in 0..60 {
            agent.act(&env, &mut action);
            env.step(&action).unwrap();
        }
        env.metrics().unwrap()
    };
    let (idle, random) = (run("idle"), run("random"));
    assert_eq!(idle.distance_navigated, 0.0);
    assert!(
        random.distance_navigated > 1.0,
        "{}",
        random.distance_navigated
    );
    assert!(random.work > 0.0 && idle.work < random.work);
}

#[test]
fn an_agent_is_normalized_by_a_recorded_demonstration() {
    use behavior_env::Start;
    use behavior_env::metrics::HumanReference;
    use behavior_env::record::read;
    // A "demonstration": 60 random steps, recorded.
    let dir = tempfile::Builder::new()
        .prefix("behavior-demo-")
        .tempdir()
        .unwrap();
    let path = dir.path().join("demo.mcap");
    let mut env = common::env("bringing_in_wood");
    env.reset(6).unwrap();
    env.record_to(&path, RecordingSetup::new("(text)", 30))
        .unwrap();
    let mut agent = Agent::named("random", 6).unwrap();
    let mut action = Vec::new();
    for _ in 0..60 {
        agent.act(&env, &mut action);
        env.step(&action).unwrap();
    }
    env.finish_recording().unwrap();
    // The demonstration's metrics, from the recording alone (begun again, its actions replayed).
    let recording = read(&path).unwrap();
    let config = recording
        .config(common::activity("bringing_in_wood"), common::taxonomy())
        .unwrap();
    let mut demo = Env::new(config);
    let start = Start {
        seed: recording.header.seed,
        instance: recording.header.instance.clone(),
    };
    demo.reset_to(start.clone()).unwrap();
    for frame in &recording.frames {
        demo.step(&frame.action).unwrap();
    }
    let human = demo.metrics().unwrap();
    assert_eq!(Some(&human), env.metrics().as_ref());
    let mut reference = HumanReference::new();
    reference.add("bringing_in_wood", "alder/6", &human);
    // An agent that idles 90 steps on the same instance: 1.5 × the time, no distance.
    let mut idle = Env::new(common::config("bringing_in_wood"));
    idle.reset_to(start).unwrap();
    for _ in 0..90 {
        idle.step(&[0.0; 26]).unwrap();
    }
    let n = reference
        .normalize("bringing_in_wood", "alder/6", &idle.metrics().unwrap())
        .unwrap();
    assert_eq!(n.simulated_time, Some(1.5));
    assert_eq!(n.distance_navigated, Some(0.0));
    assert!(human.distance_navigated > 1.0);
}
