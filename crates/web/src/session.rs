//! The simulation thread: it owns the episode, steps it at 30 Hz while someone drives, records
//! it, and tells every connected page what happened.
//!
//! The server's tasks only pass messages: a client joined, said something (already parsed and
//! checked), or left. Everything that touches the world happens here, on one thread, in the
//! order messages arrive, so the recorded actions are exactly the actions stepped and a
//! recording replays bit for bit.

use crate::checklist::Checklist;
use crate::clients::{Clients, Outgoing};
use crate::protocol::{ClientMessage, Ended, ProtocolError, ServerMessage, Status, error_text};
use crate::scene::{Describe, Particles, SceneFiles, SceneView};
use crate::server::WebError;
use crate::teleop::Drive;
use crate::xr::{Targets, XrInput, XrRig};
use axum::body::Bytes;
use behavior_env::Env;
use behavior_env::record::{Provenance, RecordingSetup};
use behavior_robots::ACTION_DIM;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};
use tokio::sync::mpsc::Sender;

/// One action step: 30 Hz, as the paper's agents and people act.
pub(crate) const TICK: Duration = Duration::from_nanos(1_000_000_000 / 30);

/// What the server runs: an environment with the BehaviorRobot, and where to keep recordings.
pub struct Session {
    /// The environment (its robot must be the BehaviorRobot); it is reset here.
    pub env: Env,
    /// The activity's BDDL text, written into every recording.
    pub definition: String,
    /// The first episode's seed; each later episode takes the next.
    pub seed: u64,
    /// Where recordings go, one MCAP file per episode with steps.
    pub record_dir: PathBuf,
    /// Full-state checkpoints in a recording every this many steps.
    pub checkpoint_every: u32,
}

/// What the server's tasks tell the simulation thread.
pub(crate) enum ToSim {
    Joined {
        client: u64,
        watch: bool,
        tx: Sender<Outgoing>,
    },
    Said {
        client: u64,
        message: ClientMessage,
    },
    Left {
        client: u64,
    },
    Stop,
}

/// The driver's latest command, applied to every step until the next; recorded with each step
/// as the device's report.
#[derive(Clone, Copy, Debug, Serialize)]
#[serde(rename_all = "snake_case")]
enum Control {
    /// Keyboard or gamepad rates.
    Keys(Drive),
    /// A headset's poses.
    Xr(XrInput),
}

/// The episode being played and what the pages were told about it.
struct Running {
    session: Session,
    checklist: Checklist,
    view: SceneView,
    scene_text: String,
    /// Where the scenes' glTF files are published for the pages.
    files: Arc<SceneFiles>,
    /// The file the episode records to, from its first step.
    recording: Option<PathBuf>,
    episodes: u32,
    seed: u64,
    control: Control,
    rig: Option<XrRig>,
    /// The particles the pages were last sent, and whether a page needs them all again.
    particles: Particles,
    resend_particles: bool,
    clients: Clients,
    driver: Option<u64>,
    written: Vec<PathBuf>,
}

/// Runs the simulation until [`ToSim::Stop`] or until every sender is gone; returns the
/// recordings written.
pub(crate) fn run(
    session: Session,
    inbox: Receiver<ToSim>,
    files: Arc<SceneFiles>,
) -> Result<Vec<PathBuf>, WebError> {
    let mut running = Running::start(session, files)?;
    ticks(&inbox, |event| match event {
        Event::Message(message) => running.handle(message),
        Event::Tick if running.driver.is_some() => running.step(),
        Event::Tick => Ok(()),
    })?;
    running.end("server stopped")?;
    Ok(running.written)
}

/// What a simulation thread is woken by: a message from a page, or the next [`TICK`].
pub(crate) enum Event {
    Message(ToSim),
    Tick,
}

/// A simulation thread's clock (the live session's and the playback's): hands `on` each
/// message as it arrives and a tick every [`TICK`], until [`ToSim::Stop`] or until every
/// sender is gone; the first error `on` returns ends it.
pub(crate) fn ticks(
    inbox: &Receiver<ToSim>,
    mut on: impl FnMut(Event) -> Result<(), WebError>,
) -> Result<(), WebError> {
    let mut next = Instant::now() + TICK;
    loop {
        let wait = next.saturating_duration_since(Instant::now());
        match inbox.recv_timeout(wait) {
            Ok(ToSim::Stop) | Err(RecvTimeoutError::Disconnected) => return Ok(()),
            Ok(message) => {
                on(Event::Message(message))?;
                continue;
            }
            Err(RecvTimeoutError::Timeout) => {}
        }
        // A late tick is not made up for: the simulation never runs ahead in bursts.
        next = (next + TICK).max(Instant::now());
        on(Event::Tick)?;
    }
}

impl Running {
    fn start(mut session: Session, files: Arc<SceneFiles>) -> Result<Running, WebError> {
        let seed = session.seed;
        session.env.reset(seed)?;
        let drives = session
            .env
            .robot()
            .is_some_and(|r| r.action_dim() == ACTION_DIM);
        if !drives || targets(&session.env).is_none() {
            return Err(WebError::NotTeleoperable);
        }
        let checklist = Checklist::new(&session.env.config().activity);
        let mut running = Running {
            session,
            checklist,
            view: SceneView::default(),
            scene_text: String::new(),
            files,
            recording: None,
            episodes: 1,
            seed,
            control: Control::Keys(Drive::default()),
            rig: None,
            particles: Particles::default(),
            resend_particles: true,
            clients: Clients::default(),
            driver: None,
            written: Vec::new(),
        };
        running.describe();
        Ok(running)
    }

    /// Rebuilds what the pages draw from the world as it is now.
    fn describe(&mut self) {
        let env = &self.session.env;
        let described = Describe::episode(env, &self.checklist, self.seed, self.episodes);
        // A page may still be fetching the scene before.
        let Some((view, description)) = described.map(|d| d.build(&self.files, 4)) else {
            return;
        };
        self.view = view;
        self.scene_text = ServerMessage::Scene(&description).to_text();
    }

    fn handle(&mut self, message: ToSim) -> Result<(), WebError> {
        match message {
            ToSim::Joined { client, watch, tx } => self.join(client, watch, tx),
            ToSim::Said { client, message } => self.said(client, message)?,
            ToSim::Left { client } => self.left(client)?,
            ToSim::Stop => {}
        }
        Ok(())
    }

    fn join(&mut self, client: u64, watch: bool, tx: Sender<Outgoing>) {
        let driving = !watch && self.driver.is_none();
        if driving {
            self.driver = Some(client);
        }
        let role = ServerMessage::Role { driving }.to_text();
        let first = vec![
            Outgoing::Text(role),
            Outgoing::Text(self.scene_text.clone()),
        ];
        if self.clients.join(client, tx, first) {
            self.resend_particles = true;
            self.send_frame();
        }
    }

    fn said(&mut self, client: u64, message: ClientMessage) -> Result<(), WebError> {
        if let ClientMessage::Seen { frames } = message {
            self.clients.seen(client, frames);
            return Ok(());
        }
        if self.driver != Some(client) {
            let error = ProtocolError::NotDriver(message.name());
            self.clients
                .send_to(client, Outgoing::Text(error_text(&error)));
            return Ok(());
        }
        match message {
            ClientMessage::Drive(drive) => self.control = Control::Keys(drive),
            ClientMessage::Xr(input) => self.xr(client, input),
            ClientMessage::End => self.end("ended by the driver")?,
            other => {
                let error = ProtocolError::NotHere {
                    message: other.name(),
                    needs: "`behavior view`: this server runs a live episode",
                };
                self.clients
                    .send_to(client, Outgoing::Text(error_text(&error)));
            }
        }
        Ok(())
    }

    /// Headset poses: the rig tied to the eye first if asked (or never done), and the page
    /// told how.
    fn xr(&mut self, client: u64, input: XrInput) {
        if input.recenter || self.rig.is_none() {
            let Some(targets) = self.targets() else {
                return;
            };
            let rig = XrRig::recentered(&input.head, &targets.eye);
            self.rig = Some(rig);
            let told = ServerMessage::XrRig(&rig).to_text();
            self.clients.send_to(client, Outgoing::Text(told));
        }
        self.control = Control::Xr(input);
    }

    /// Where the robot's eye and hands are told to be now.
    fn targets(&self) -> Option<Targets> {
        targets(&self.session.env)
    }

    /// This step's action from the driver's latest command.
    fn action(&self) -> [f32; ACTION_DIM] {
        match (&self.control, self.rig, self.targets()) {
            (Control::Xr(input), Some(rig), Some(now)) => rig.action(input, &now),
            (Control::Keys(drive), ..) => drive.action(),
            _ => [0.0; ACTION_DIM],
        }
    }

    fn left(&mut self, client: u64) -> Result<(), WebError> {
        self.clients.leave(client);
        if self.driver == Some(client) {
            self.driver = None;
            self.end("driver left")?;
        }
        Ok(())
    }

    /// One action step with the driver's latest command.
    fn step(&mut self) -> Result<(), WebError> {
        let action = self.action();
        // An episode is recorded from its first step: one file per episode with steps.
        if self.recording.is_none() {
            let path = fresh_path(&self.session.record_dir, &self.file_stem())?;
            let s = &mut self.session;
            let setup =
                RecordingSetup::new(&s.definition, s.checkpoint_every).by(Provenance::Person);
            s.env.record_to(&path, setup)?;
            self.recording = Some(path);
        }
        self.session.env.record_device(&self.control)?;
        let step = self.session.env.step(&action)?;
        let world = self.session.env.world().ok_or(WebError::NoEpisode)?;
        if !self.view.matches(world) {
            self.describe();
            self.clients
                .broadcast(Outgoing::Text(self.scene_text.clone()));
        }
        self.send_frame();
        if step.terminated {
            self.end("goal")?;
        } else if step.truncated {
            self.end("time limit")?;
        }
        Ok(())
    }

    /// Sends every client the poses and the status.
    fn send_frame(&mut self) {
        let env = &self.session.env;
        let (Some(world), Some(bindings), Some(score), Some(metrics)) =
            (env.world(), env.bindings(), env.score(), env.metrics())
        else {
            return;
        };
        let frame = Bytes::from(self.view.frame(world, env.steps()));
        let recolor = self.view.recolor(world);
        let checklist = self.checklist.status(world, bindings);
        let particles = Particles::of(world);
        let changed = self.resend_particles || particles != self.particles;
        self.resend_particles = false;
        self.particles = particles;
        let status = ServerMessage::Status(Status {
            step: env.steps(),
            q: score.q,
            success: score.success,
            metrics: &metrics,
            checklist: &checklist,
            recolor: &recolor,
            particles: changed.then_some(&self.particles),
        })
        .to_text();
        self.clients.broadcast(Outgoing::Binary(frame));
        // A status is whole (its recolouring lists every surface that ever changed), so a slow
        // page may skip it, unless it brings new particles, which are sent only when they change.
        self.clients.broadcast(if changed {
            Outgoing::Text(status)
        } else {
            Outgoing::Update(status)
        });
    }

    /// Ends the episode (keeping its recording) and resets to the next seed's.
    fn end(&mut self, reason: &'static str) -> Result<(), WebError> {
        let env = &mut self.session.env;
        let steps = env.steps();
        if steps == 0 {
            return Ok(());
        }
        let score = env.score().cloned().unwrap_or_default();
        env.finish_recording()?;
        let recording = self.recording.take();
        self.written.extend(recording.clone());
        let ended = ServerMessage::Ended(Ended {
            steps,
            success: score.success,
            q: score.q,
            recording: recording.map(|p| p.display().to_string()),
            reason,
        });
        self.clients.broadcast(Outgoing::Text(ended.to_text()));
        if reason == "server stopped" {
            return Ok(());
        }
        self.seed += 1;
        self.episodes += 1;
        self.control = Control::Keys(Drive::default());
        self.session.env.reset(self.seed)?;
        self.describe();
        self.clients
            .broadcast(Outgoing::Text(self.scene_text.clone()));
        self.send_frame();
        Ok(())
    }

    fn file_stem(&self) -> String {
        let activity = &self.session.env.config().activity.name;
        format!("{activity}-seed{}", self.seed)
    }
}

/// `dir/stem-N.mcap` for the first N whose file does not exist: no recording overwrites another.
fn fresh_path(dir: &Path, stem: &str) -> Result<PathBuf, WebError> {
    std::fs::create_dir_all(dir).map_err(|source| WebError::RecordDir {
        dir: dir.to_path_buf(),
        source,
    })?;
    let mut n = 1;
    loop {
        let path = dir.join(format!("{stem}-{n:03}.mcap"));
        if !path.exists() {
            return Ok(path);
        }
        n += 1;
    }
}

/// Where the episode's robot's eye and posed hands are told to be now; `None` for a robot
/// without two posed hands.
fn targets(env: &Env) -> Option<Targets> {
    Targets::of(env.robot()?.embodiment(), env.world()?)
}
