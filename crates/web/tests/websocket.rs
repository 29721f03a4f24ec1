//! The server through its websocket, as a page uses it: another site's page is refused, a
//! driver and a watcher join, hostile messages are refused and change nothing, driving moves the robot, the driver leaving ends
//! the episode and keeps its recording, and the recording replays bit for bit.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_env::record::{read, replay};
use behavior_web::Session;
use futures_util::SinkExt;
use support::{bind_local, next_frame, next_of, send, shutdown};
use tokio_tungstenite::connect_async;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;

const ACTIVITY: &str = "bringing_in_wood";

/// A live session of an official activity at `seed`, recording into `dir` with a checkpoint
/// every 10 steps.
fn session(activity: &str, seed: u64, dir: &std::path::Path) -> Session {
    Session {
        env: common::env(activity),
        definition: String::new(),
        seed,
        record_dir: dir.to_path_buf(),
        checkpoint_every: 10,
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_driven_episode_is_refused_bad_input_moves_the_robot_and_replays_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("behavior-web-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let session = session(ACTIVITY, 3, &dir);
    let (server, addr) = bind_local().await;
    let (stop, stopped) = shutdown();
    let running = tokio::spawn(server.run(session, stopped));

    // A page of another site may not open the websocket (the browser says where it came from).
    let mut foreign = format!("ws://{addr}/ws").into_client_request().unwrap();
    let origin = "http://elsewhere.example".parse().unwrap();
    foreign.headers_mut().insert("origin", origin);
    let refused = connect_async(foreign).await.unwrap_err().to_string();
    assert!(refused.contains("403"), "{refused}");

    let (mut driver, _) = connect_async(format!("ws://{addr}/ws")).await.unwrap();
    assert_eq!(next_of(&mut driver, "role").await["driving"], true);
    let scene = next_of(&mut driver, "scene").await;
    assert_eq!(scene["activity"], "bringing_in_wood_0");
    assert_eq!(scene["seed"], 3);
    let literals = scene["literals"].as_array().unwrap();
    assert!(
        literals
            .iter()
            .all(|l| l.as_str().unwrap().starts_with("(onfloor plywood"))
    );
    let nodes = scene["nodes"].as_array().unwrap();
    let robot = &scene["robot"][0];
    let body = nodes
        .iter()
        .position(|n| n["object"] == *robot && n["link"].is_null())
        .expect("the robot's body among the nodes");

    // A watcher may not drive.
    let (mut watcher, _) = connect_async(format!("ws://{addr}/ws?watch"))
        .await
        .unwrap();
    assert_eq!(next_of(&mut watcher, "role").await["driving"], false);
    send(&mut watcher, r#"{"type":"drive","body":[1,0,0,0,0,0]}"#).await;
    let refused = next_of(&mut watcher, "error").await;
    assert!(
        refused["message"].as_str().unwrap().contains("watching"),
        "{refused}"
    );

    // Hostile messages: each answered with why, none reaching the robot.
    let (_, start) = next_frame(&mut driver, body).await;
    let hostile = [
        "{".to_string(),
        r#"{"type":"drive","body":[0,0,0,0,0,5]}"#.to_string(),
        r#"{"type":"teleport","to":[0,0,9]}"#.to_string(),
        format!(r#"{{"type":"drive","pad":"{}"}}"#, "x".repeat(40_000)),
    ];
    for text in &hostile {
        send(&mut driver, text).await;
        let error = next_of(&mut driver, "error").await;
        assert!(!error["message"].as_str().unwrap().is_empty());
    }
    driver
        .send(Message::Binary(vec![1, 2, 3].into()))
        .await
        .unwrap();
    let error = next_of(&mut driver, "error").await;
    assert!(
        error["message"].as_str().unwrap().contains("binary"),
        "{error}"
    );
    let (_, still) = next_frame(&mut driver, body).await;
    let drift = (0..2)
        .map(|i| (still[i] - start[i]).abs())
        .fold(0.0, f32::max);
    assert!(
        drift < 0.01,
        "the robot moved {drift} m on refused messages"
    );

    // Forward at full speed for a second: the body goes ahead.
    send(&mut driver, r#"{"type":"drive","body":[1,0,0,0,0,0]}"#).await;
    let (first, _) = next_frame(&mut driver, body).await;
    let mut moved = 0.0;
    while moved < 0.3 {
        let (step, at) = next_frame(&mut driver, body).await;
        moved = ((at[0] - still[0]).powi(2) + (at[1] - still[1]).powi(2)).sqrt();
        assert!(
            step < first + 90,
            "after {} steps forward the body moved only {moved} m",
            step - first
        );
    }
    // Then at rest a while, so that the recording has checkpoints to compare (every 10 steps).
    send(&mut driver, r#"{"type":"drive"}"#).await;
    while next_frame(&mut driver, body).await.0 < first + 30 {}

    // The driver leaves: the episode ends, recorded; the watcher sees the next one.
    driver.close(None).await.unwrap();
    let ended = next_of(&mut watcher, "ended").await;
    assert_eq!(ended["reason"], "driver left");
    let path = ended["recording"]
        .as_str()
        .expect("a recording")
        .to_string();
    let next = next_of(&mut watcher, "scene").await;
    assert_eq!(
        (next["episode"].as_u64(), next["seed"].as_u64()),
        (Some(2), Some(4))
    );

    stop.send(()).unwrap();
    let written = running.await.unwrap().unwrap();
    assert_eq!(written, vec![std::path::PathBuf::from(&path)]);

    let recording = read(std::path::Path::new(&path)).unwrap();
    let steps = recording.frames.len();
    assert_eq!(
        u64::from(recording.frames.last().unwrap().step),
        steps as u64
    );
    assert!(recording.frames.iter().any(|f| f.action[0] == 1.0));
    assert!(
        recording.frames.iter().all(|f| f.action[5] == 0.0),
        "no refused rate was used"
    );
    let config = recording
        .config(common::activity(ACTIVITY), common::taxonomy())
        .unwrap();
    let report = replay(&recording, config).unwrap();
    assert!(report.checkpoints >= 3, "{report:?}");
    assert!(report.identical, "{report:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn dust_and_stains_reach_the_page_as_the_cameras_draw_them() {
    let dir = std::env::temp_dir().join(format!("behavior-web-dust-{}", std::process::id()));
    let session = session("cleaning_barbecue_grill", 0, &dir);
    let (server, addr) = bind_local().await;
    let (stop, stopped) = shutdown();
    let running = tokio::spawn(server.run(session, stopped));
    let (mut page, _) = connect_async(format!("ws://{addr}/ws?watch"))
        .await
        .unwrap();
    let scene = next_of(&mut page, "scene").await;
    let dust = &scene["particle_colors"]["dust"];
    assert!(
        (dust[0].as_f64().unwrap() - 150.0 / 255.0).abs() < 1e-6,
        "{dust}"
    );
    let status = next_of(&mut page, "status").await;
    let particles = &status["particles"];
    for kind in ["dust", "stain"] {
        let flat = particles[kind].as_array().unwrap();
        assert!(
            !flat.is_empty() && flat.len() % 3 == 0,
            "{kind}: {}",
            flat.len()
        );
    }
    assert!(particles["water"].as_array().unwrap().is_empty());
    stop.send(()).unwrap();
    running.await.unwrap().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
}
