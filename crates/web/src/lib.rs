//! `behavior serve`: the browser viewer and teleoperation server.
//!
//! A page, embedded in the binary with three.js, draws the home from the world's visual
//! description and follows the simulation live: every step the server streams each body's pose
//! (a binary frame), and a status message with Q, the efficiency metrics, the goal as a
//! checklist of ground literals and the colours states give surfaces (as the cameras show them).
//! The person at the page drives the BehaviorRobot — the embodiment people used for the paper's
//! demonstrations — from the keyboard, a gamepad or a WebXR headset and its controllers; the server turns each command into the
//! robot's 26-number action, steps the episode at 30 Hz with its physics, and records every
//! episode to MCAP, so a demonstration is an action sequence that replays bit for bit.
//!
//! It owns the HTTP server, the websocket protocol (`protocol.rs`: every client message is
//! checked, and a bad one gets an error reply and changes nothing), the simulation thread that
//! owns the episode (`session.rs`), the connected pages (`clients.rs`), what the page is sent
//! about the world (`scene.rs`), the goal
//! checklist (`checklist.rs`), keyboard and gamepad commands (`teleop.rs`) and headset poses
//! (`xr.rs`). It knows nothing of the
//! command line: its caller builds the environment ([`Session`]) and says where to listen
//! ([`ServeOptions`]).
//!
//! `behavior view` plays a recording in the same page instead (`playback.rs`): re-simulated
//! as `behavior replay` does, with a timeline to play, pause and scrub.
//!
//! One client drives at a time (the first to connect without `?watch`); others watch. When the
//! driver's tab closes, the episode ends, its recording is closed, and the next episode waits
//! for the next driver.
//!
//! Serving an environment on loopback, and what a page may say:
//!
//! ```no_run
//! use behavior_env::{Env, EnvConfig};
//! use behavior_web::{ClientMessage, ServeOptions, Session, serve};
//!
//! /// Serves episodes of `config` (its robot the BehaviorRobot) until Ctrl-C; the recordings.
//! fn teleoperate(config: EnvConfig, definition: String) -> Result<usize, behavior_web::WebError> {
//!     let session = Session {
//!         env: Env::new(config),
//!         definition,
//!         seed: 0,
//!         record_dir: "recordings".into(),
//!         checkpoint_every: 300,
//!     };
//!     let options = ServeOptions {
//!         addr: "127.0.0.1:8000".parse().expect("an address"),
//!     };
//!     let recordings = serve(session, &options, |addr| println!("open http://{addr}"))?;
//!     Ok(recordings.len())
//! }
//!
//! // Every message a page sends is checked before it reaches the episode.
//! assert!(ClientMessage::parse("{\"not\": \"a message\"}").is_err());
//! ```

mod assets;
mod checklist;
mod clients;
mod playback;
mod protocol;
mod scene;
mod server;
mod session;
mod teleop;
mod xr;

pub use playback::{Playback, PlaybackEditor};
pub use protocol::{ClientMessage, ProtocolError};
pub use server::{ServeOptions, Server, WebError, serve, view};
pub use session::Session;
pub use teleop::Drive;
pub use xr::{BadDevice, STICK_DEAD_ZONE, Targets, XrController, XrInput, XrPose, XrRig};
