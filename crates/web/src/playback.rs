//! `behavior view`: a recording played in the page, with a timeline.
//!
//! The simulation thread re-simulates the recording (the same episode begun again, every
//! recorded action and edit done again, as `behavior replay` does) a few steps per tick, and
//! keeps what the page needs at every step: the binary frame of poses, Q, the metrics, the
//! checklist and the surfaces recoloured. So the page can scrub anywhere already computed
//! without simulating again, while the rest is still being computed. Every state digest the
//! recording checkpointed is compared on the way; the timeline says if one differs.
//!
//! All pages share one cursor: any of them may play, pause, change the rate or seek, and all
//! follow. Nothing a page says can change the recording or the episode.

use crate::checklist::{Checklist, ChecklistStatus};
use crate::clients::{Clients, Outgoing};
use crate::protocol::{ClientMessage, ProtocolError, ServerMessage, Status, error_text};
use crate::scene::{Describe, Particles, Recolor, SceneFiles, SceneView};
use crate::server::WebError;
use crate::session::{Event, ToSim, ticks};
use axum::body::Bytes;
use behavior_env::record::{Recording, ReplayError, state_digest};
use behavior_env::{Env, EpisodeMetrics, Start};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::Receiver;
use std::time::{Duration, Instant};
use tokio::sync::mpsc::Sender;

/// Does the edit recorded after a step again (a planner's primitive), as
/// [`behavior_env::record::redo`] does for the edits' own type:
/// `redo::<behavior_planning::RecordedCall>`.
pub type PlaybackEditor = fn(&mut Env, u32, &serde_json::Value) -> Result<(), ReplayError>;

/// What `behavior view` plays: a recording and the environment it was made in.
pub struct Playback {
    /// The environment of the recording's header (`Recording::config`); it is reset here to the
    /// recorded start.
    pub env: Env,
    /// The recording.
    pub recording: Recording,
    /// Does the recording's edits again (a recording without edits never calls it).
    pub editor: PlaybackEditor,
    /// What the page calls the recording (its file name).
    pub name: String,
}

/// Time per tick spent re-simulating, so that playing and seeking stay smooth meanwhile.
const COMPUTE_BUDGET: Duration = Duration::from_millis(20);

/// The fastest and slowest rates a page may ask for, × real time.
pub(crate) const RATES: (f32, f32) = (0.05, 16.0);

/// Everything the page is shown at one step.
struct Snapshot {
    /// Which scene description it is drawn with (an index into `Viewer::scenes`).
    scene: usize,
    frame: Bytes,
    q: f64,
    success: bool,
    metrics: EpisodeMetrics,
    checklist: ChecklistStatus,
    /// Surfaces whose colour changed at this step.
    recolor: Vec<Recolor>,
    /// Its particles (an index into `Viewer::particles`).
    particles: usize,
}

/// Where playback stands, as the page's timeline shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Timeline {
    /// The recording's name.
    recording: String,
    /// Steps in the recording.
    steps: u32,
    /// Steps re-simulated so far (the page may seek up to here).
    computed: u32,
    /// The step shown.
    step: u32,
    playing: bool,
    /// × real time (30 steps a second at 1).
    rate: f32,
    /// Teleoperated steps by device (`keys`, `xr`); empty for an agent's or a planner's episode.
    devices: BTreeMap<String, usize>,
    /// The first checkpoint whose state differs from the recording's, if one did.
    differs_from: Option<u32>,
    /// Why re-simulation stopped before the end (a cut file, an edit not done again).
    stopped: Option<String>,
}

struct Viewer {
    playback: Playback,
    checklist: Checklist,
    view: SceneView,
    scenes: Vec<String>,
    /// Where the scenes' glTF files are published for the pages (all of them: the timeline
    /// may go back to any).
    files: Arc<SceneFiles>,
    /// Each different set of particles, in the order they appeared.
    particles: Vec<Particles>,
    snapshots: Vec<Snapshot>,
    /// Index of the next recorded frame to re-simulate.
    next: usize,
    timeline: Timeline,
    /// Steps of play not yet shown (the rate's fraction of a step).
    carry: f32,
    /// A step asked for before it was computed.
    pending: Option<u32>,
    /// The step every page shows now.
    shown: u32,
    /// The computed steps the pages were last told of, and ticks since.
    told_computed: u32,
    progress_ticks: u32,
    clients: Clients,
}

/// Plays the recording until [`ToSim::Stop`] or until every sender is gone.
pub(crate) fn run(
    playback: Playback,
    inbox: Receiver<ToSim>,
    files: Arc<SceneFiles>,
) -> Result<Vec<PathBuf>, WebError> {
    let mut viewer = Viewer::start(playback, files)?;
    ticks(&inbox, |event| {
        match event {
            Event::Message(message) => viewer.handle(message),
            Event::Tick => viewer.tick(),
        }
        Ok(())
    })?;
    Ok(Vec::new())
}

impl Viewer {
    fn start(mut playback: Playback, files: Arc<SceneFiles>) -> Result<Viewer, WebError> {
        let header = &playback.recording.header;
        let start = Start {
            seed: header.seed,
            instance: header.instance.clone(),
        };
        playback.env.reset_to(start)?;
        let checklist = Checklist::new(&playback.env.config().activity);
        let timeline = Timeline {
            recording: playback.name.clone(),
            steps: playback.recording.frames.len() as u32,
            computed: 0,
            step: 0,
            playing: false,
            rate: 1.0,
            devices: playback.recording.device_steps(),
            differs_from: None,
            stopped: playback.recording.damage.clone(),
        };
        let mut viewer = Viewer {
            playback,
            checklist,
            view: SceneView::default(),
            scenes: Vec::new(),
            files,
            particles: Vec::new(),
            snapshots: Vec::new(),
            next: 0,
            timeline,
            carry: 0.0,
            pending: None,
            shown: 0,
            told_computed: 0,
            progress_ticks: 0,
            clients: Clients::default(),
        };
        viewer.describe();
        viewer.snapshot();
        viewer.check_digest();
        Ok(viewer)
    }

    /// A new scene description from the world as it is now.
    fn describe(&mut self) {
        let env = &self.playback.env;
        let seed = self.playback.recording.header.seed;
        let described = Describe::episode(env, &self.checklist, seed, 1);
        if let Some((view, description)) = described.map(|d| d.build(&self.files, usize::MAX)) {
            self.view = view;
            self.scenes
                .push(ServerMessage::Scene(&description).to_text());
        }
    }

    /// Keeps what the page needs at the step just simulated.
    fn snapshot(&mut self) {
        let env = &self.playback.env;
        let (Some(world), Some(bindings), Some(score), Some(metrics)) =
            (env.world(), env.bindings(), env.score(), env.metrics())
        else {
            return;
        };
        let particles = Particles::of(world);
        if self.particles.last() != Some(&particles) {
            self.particles.push(particles);
        }
        let snapshot = Snapshot {
            scene: self.scenes.len() - 1,
            particles: self.particles.len() - 1,
            frame: Bytes::from(self.view.frame(world, env.steps())),
            q: score.q,
            success: score.success,
            metrics,
            checklist: self.checklist.status(world, bindings),
            recolor: self.view.recolor(world),
        };
        self.snapshots.push(snapshot);
        self.timeline.computed = env.steps();
    }

    /// Compares the state with the recording's checkpoint at this step, if it has one.
    fn check_digest(&mut self) {
        let env = &self.playback.env;
        let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
            return;
        };
        let step = env.steps();
        let recorded = self.playback.recording.checkpoints.iter();
        let differs = recorded
            .filter(|(s, _)| *s == step)
            .any(|(_, digest)| *digest != state_digest(world, robot, step));
        if differs && self.timeline.differs_from.is_none() {
            self.timeline.differs_from = Some(step);
        }
    }

    /// Re-simulates the next recorded step (its edits first); false once there is none or
    /// one failed (the timeline says why).
    fn compute_one(&mut self) -> bool {
        let recording = &self.playback.recording;
        let Some(frame) = recording.frames.get(self.next) else {
            return false;
        };
        let (step, action) = (frame.step, frame.action.clone());
        let done = self.playback.env.steps();
        let edits: Vec<_> = recording
            .edits
            .iter()
            .filter(|(s, _)| *s >= done && *s < step)
            .cloned()
            .collect();
        for (at, edit) in edits {
            if let Err(e) = (self.playback.editor)(&mut self.playback.env, at, &edit) {
                return self.stop(e.to_string());
            }
        }
        if let Err(e) = self.playback.env.step(&action) {
            return self.stop(format!("step {step}: {e}"));
        }
        self.next += 1;
        let world = self.playback.env.world();
        if world.is_some_and(|w| !self.view.matches(w)) {
            self.describe();
        }
        self.snapshot();
        self.check_digest();
        true
    }

    fn stop(&mut self, why: String) -> bool {
        self.timeline.stopped = Some(why);
        self.next = self.playback.recording.frames.len();
        false
    }

    fn tick(&mut self) {
        let until = Instant::now() + COMPUTE_BUDGET;
        while Instant::now() < until && self.compute_one() {}
        let before = self.timeline.clone();
        let t = &mut self.timeline;
        if let Some(step) = self.pending.filter(|&s| s <= t.computed) {
            t.step = step;
            self.pending = None;
        }
        if t.playing {
            self.carry += t.rate;
            let advance = self.carry.floor();
            self.carry -= advance;
            t.step = (t.step + advance as u32).min(t.computed);
            // At the end, or where re-simulation stopped; a cursor that caught up with the
            // computation waits for it.
            t.playing = t.step < t.computed || self.next < self.playback.recording.frames.len();
        }
        self.show();
        // Progress alone is told twice a second (and when it is complete); anything else at once.
        self.progress_ticks += 1;
        let finished = self.next >= self.playback.recording.frames.len();
        let progressed = self.told_computed != self.timeline.computed;
        let progress_due = progressed && (self.progress_ticks >= 15 || finished);
        if before != self.timeline || progress_due {
            self.tell_timeline();
        }
    }

    fn tell_timeline(&mut self) {
        self.progress_ticks = 0;
        self.told_computed = self.timeline.computed;
        let text = ServerMessage::Timeline(&self.timeline).to_text();
        self.clients.broadcast(Outgoing::Text(text));
    }

    fn handle(&mut self, message: ToSim) {
        match message {
            ToSim::Joined { client, tx, .. } => self.join(client, tx),
            ToSim::Said { client, message } => self.said(client, message),
            ToSim::Left { client } => self.clients.leave(client),
            ToSim::Stop => {}
        }
    }

    fn join(&mut self, client: u64, tx: Sender<Outgoing>) {
        let mut messages = vec![Outgoing::Text(
            ServerMessage::Role { driving: false }.to_text(),
        )];
        messages.extend(self.messages(None, self.shown));
        messages.push(Outgoing::Text(
            ServerMessage::Timeline(&self.timeline).to_text(),
        ));
        self.clients.join(client, tx, messages);
    }

    fn said(&mut self, client: u64, message: ClientMessage) {
        if let ClientMessage::Seen { frames } = message {
            self.clients.seen(client, frames);
            return;
        }
        let t = &mut self.timeline;
        let refused = match message {
            ClientMessage::Play => {
                if t.step >= t.steps {
                    t.step = 0;
                }
                t.playing = true;
                None
            }
            ClientMessage::Pause => {
                t.playing = false;
                None
            }
            ClientMessage::Rate { rate } => {
                t.rate = rate;
                None
            }
            ClientMessage::Seek { step } if step > t.steps => Some(ProtocolError::PastTheEnd {
                step,
                steps: t.steps,
            }),
            ClientMessage::Seek { step } => {
                t.playing = false;
                if step <= t.computed {
                    t.step = step;
                    self.pending = None;
                } else {
                    self.pending = Some(step);
                }
                None
            }
            other => Some(ProtocolError::NotHere {
                message: other.name(),
                needs: "`behavior serve`: this page plays a recording",
            }),
        };
        match refused {
            Some(error) => self
                .clients
                .send_to(client, Outgoing::Text(error_text(&error))),
            None => {
                self.show();
                self.tell_timeline();
            }
        }
    }

    /// Moves every page from the step shown to the cursor.
    fn show(&mut self) {
        let step = self.timeline.step;
        if step == self.shown {
            return;
        }
        for message in self.messages(Some(self.shown), step) {
            self.clients.broadcast(message);
        }
        self.shown = step;
    }

    /// What takes a page from showing step `from` (none: nothing yet) to showing `to`: the
    /// scene if it changes (or going back: the scene's colours are those of its first step),
    /// every recolouring on the way, the frame and the status.
    fn messages(&self, from: Option<u32>, to: u32) -> Vec<Outgoing> {
        let Some(target) = self.snapshots.get(to as usize) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        let before = from.and_then(|f| self.snapshots.get(f as usize).map(|s| (f, s)));
        let same_particles = before.is_some_and(|(_, s)| s.particles == target.particles);
        let forward = before.filter(|&(f, s)| f <= to && s.scene == target.scene);
        let first = match forward {
            Some((f, _)) => f as usize + 1,
            None => {
                out.push(Outgoing::Text(self.scenes[target.scene].clone()));
                self.snapshots
                    .iter()
                    .position(|s| s.scene == target.scene)
                    .map_or(to as usize, |p| p + 1)
            }
        };
        let recolor: Vec<Recolor> = self.snapshots[first.min(to as usize + 1)..=to as usize]
            .iter()
            .flat_map(|s| s.recolor.iter().copied())
            .collect();
        let status = ServerMessage::Status(Status {
            step: to,
            q: target.q,
            success: target.success,
            metrics: &target.metrics,
            checklist: &target.checklist,
            recolor: &recolor,
            particles: (!same_particles).then(|| &self.particles[target.particles]),
        });
        out.push(Outgoing::Binary(target.frame.clone()));
        out.push(Outgoing::Text(status.to_text()));
        out
    }
}
