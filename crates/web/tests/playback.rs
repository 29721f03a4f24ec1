//! `behavior view` through its websocket: a recorded episode played back, every step shown
//! where the episode had it, seeking both ways, playing to the end, and what a playback refuses.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_env::record::{RecordingSetup, read};
use behavior_robots::ACTION_DIM;
use behavior_web::Playback;
use support::{Socket, bind_local, next_frame, next_of, send, shutdown};
use tokio_tungstenite::connect_async;

const ACTIVITY: &str = "bringing_in_wood";
const STEPS: u32 = 40;

/// Records `STEPS` steps (ahead, then turning) and returns the file and the body's position
/// after every step (index 0: the start).
fn record(path: &std::path::Path) -> Vec<[f32; 3]> {
    let mut env = common::env(ACTIVITY);
    env.reset(5).unwrap();
    env.record_to(path, RecordingSetup::new("", 10)).unwrap();
    let body = env.robot().unwrap().objects()[0];
    let position = |env: &behavior_env::Env| {
        let t = env.world().unwrap().bodies().pose(body).translation;
        [t.x, t.y, t.z]
    };
    let mut positions = vec![position(&env)];
    for step in 0..STEPS {
        let mut action = [0.0; ACTION_DIM];
        action[if step < 20 { 0 } else { 5 }] = 1.0;
        env.step(&action).unwrap();
        positions.push(position(&env));
    }
    env.finish_recording().unwrap();
    positions
}

/// The frame of `step` (skipping others): the body's position in it.
async fn frame_at(socket: &mut Socket, body: usize, step: u32) -> [f32; 3] {
    loop {
        let (at, position) = next_frame(socket, body).await;
        if at == step {
            return position;
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_recording_plays_every_step_where_the_episode_had_it_and_refuses_driving() {
    let dir = std::env::temp_dir().join(format!("behavior-view-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("episode.mcap");
    let positions = record(&path);
    let recording = read(&path).unwrap();
    let config = recording
        .config(common::activity(ACTIVITY), common::taxonomy())
        .unwrap();
    let playback = Playback {
        env: behavior_env::Env::new(config),
        recording,
        editor: behavior_env::record::redo::<behavior_env::NoEdits>,
        name: "episode.mcap".to_string(),
    };
    let (server, addr) = bind_local().await;
    let (stop, stopped) = shutdown();
    let running = tokio::spawn(server.play(playback, stopped));

    let (mut page, _) = connect_async(format!("ws://{addr}/ws")).await.unwrap();
    assert_eq!(next_of(&mut page, "role").await["driving"], false);
    let scene = next_of(&mut page, "scene").await;
    let robot = &scene["robot"][0];
    let body = scene["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .position(|n| n["object"] == *robot && n["link"].is_null())
        .expect("the robot's body among the nodes");
    assert_eq!(frame_at(&mut page, body, 0).await, positions[0]);
    let mut timeline = next_of(&mut page, "timeline").await;
    assert_eq!(timeline["recording"], "episode.mcap");
    assert_eq!(timeline["steps"], STEPS);
    assert_eq!(
        timeline["devices"],
        serde_json::json!({}),
        "an agent's episode"
    );
    while timeline["computed"] != STEPS {
        timeline = next_of(&mut page, "timeline").await;
    }
    assert!(timeline["differs_from"].is_null(), "{timeline}");

    // Seeking shows the step exactly as the episode had it, forward and back.
    for step in [25, 7, 40, 0, 13] {
        send(&mut page, &format!(r#"{{"type":"seek","step":{step}}}"#)).await;
        let shown = frame_at(&mut page, body, step).await;
        assert_eq!(shown, positions[step as usize], "step {step}");
        let status = next_of(&mut page, "status").await;
        assert_eq!(status["step"], step);
    }

    // What a recording cannot do: be driven, or seek past its end.
    for (text, says) in [
        (r#"{"type":"drive","body":[1,0,0,0,0,0]}"#, "behavior serve"),
        (
            r#"{"type":"seek","step":41}"#,
            "past the recording's last step, 40",
        ),
        (r#"{"type":"rate","rate":0}"#, "[0.05, 16]"),
    ] {
        send(&mut page, text).await;
        let error = next_of(&mut page, "error").await;
        let message = error["message"].as_str().unwrap();
        assert!(message.contains(says), "{text}: {message}");
    }

    // Playing at 16× runs to the end and stops there.
    send(&mut page, r#"{"type":"rate","rate":16}"#).await;
    send(&mut page, r#"{"type":"play"}"#).await;
    assert_eq!(frame_at(&mut page, body, STEPS).await, positions[40]);
    loop {
        let t = next_of(&mut page, "timeline").await;
        if t["playing"] == false {
            assert_eq!(t["step"], STEPS);
            break;
        }
    }

    stop.send(()).unwrap();
    running.await.unwrap().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}
