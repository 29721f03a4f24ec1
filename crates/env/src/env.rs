//! The environment: Gymnasium's `reset` and `step`, in Rust.

use crate::config::{EnvConfig, Instances, Reward};
use crate::edit::{Edit, WorldEdit};
use crate::episode::{CheckpointError, Episode, Start, embody};
use crate::metrics::{EpisodeMetrics, Series, Tracker};
use crate::observation::{Obs, Sensor, SensorInput, task_obs};
use crate::record::{RecordError, Recorder, RecordingSetup};
use crate::score::{Score, Scorer};
use crate::sensors::{CameraSensor, LidarSensor, categories};
use crate::timing::{StepTimings, Timed};
use behavior_assets::Library;
use behavior_core::{AGENT_SYNSET, FLOOR_SYNSET};
use behavior_render::RenderError;
use behavior_robots::{ActionError, Robot, RobotError};
use behavior_sampling::{LoadError, SampleError, SavedInstance, instantiate};
use behavior_sim::{BoundWorld, ObjectId, World};
use std::sync::Arc;
use std::time::Instant;

/// Steps of settling after a reset, at most (the original's `SIMULATOR_SETTLE_TIME`).
pub const SETTLE_STEPS: usize = 150;

/// Sampling seeds a reset tries before it gives up. About 0.3 % of sampling attempts fail (a
/// goal placement that does not fit, say); a training run resets thousands of times, so a
/// reset whose seed does not sample tries the seeds derived from it, in a fixed order, and the
/// same seed always gives the same instance.
pub const SAMPLE_TRIES: u32 = 5;

/// Why a reset or a step could not be done. A refused step changes nothing; a failed reset
/// leaves no episode (step refuses until a reset succeeds).
#[derive(Debug, thiserror::Error)]
pub enum EnvError {
    /// `step` before the first `reset`.
    #[error("step called before reset")]
    NotReset,
    /// `step` after the episode ended (terminated or truncated); reset first.
    #[error("the episode is over after {steps} steps; call reset to start another")]
    EpisodeOver {
        /// Steps the episode took.
        steps: u32,
    },
    /// The action is not one of the robot's.
    #[error("bad action: {0}")]
    Action(#[from] ActionError),
    /// The configuration has no home to sample in, or no saved instance to draw.
    #[error("the environment has no {0} to start episodes from")]
    Empty(&'static str),
    /// No instance could be sampled.
    #[error("sampling {activity} in {scene} (seed {seed}, {tries} sampling seeds tried): {source}")]
    Sample {
        /// The activity.
        activity: String,
        /// The home.
        scene: String,
        /// The reset's seed.
        seed: u64,
        /// How many sampling seeds were tried ([`SAMPLE_TRIES`]).
        tries: u32,
        /// Why the last one failed.
        source: Box<SampleError>,
    },
    /// A saved instance does not load.
    #[error("loading the instance: {0}")]
    Load(#[from] LoadError),
    /// The robot could not be added.
    #[error("adding the robot: {0}")]
    Robot(#[from] RobotError),
    /// The camera could not be made (no graphics adapter, a bad camera size).
    #[error("the camera: {0}")]
    Render(#[from] RenderError),
    /// The episode's recording could not be written: after a step, the step was taken and the
    /// recording stopped (the file keeps what was written up to its last whole chunk).
    #[error("the recording: {0}")]
    Record(#[from] RecordError),
    /// An edit of the world that would not be recorded while the episode is recording: a
    /// recorded episode's edits go through [`Env::apply`].
    #[error("the episode is recording: an edit of the world must be a recorded value (Env::apply)")]
    UnrecordedEdit,
    /// A sensor failed to observe. After a step the step was taken; only its observation is
    /// missing.
    #[error("sensor `{sensor}`: {source}")]
    Sensor {
        /// The sensor's name.
        sensor: String,
        /// Why.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
}

/// What a step returns (Gymnasium's five values; `info` is [`Info`]).
#[derive(Clone, Debug)]
pub struct Step {
    /// The observation after the step.
    pub obs: Obs,
    /// The reward (see [`Reward`]).
    pub reward: f64,
    /// The goal holds: the episode succeeded.
    pub terminated: bool,
    /// The step limit was reached first.
    pub truncated: bool,
    /// Q, success and the goal's conjuncts after the step.
    pub info: Info,
}

/// What the environment says besides the observation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Info {
    /// Steps taken in the episode.
    pub steps: u32,
    /// The goal's standing.
    pub score: Score,
}

/// A saved episode state; [`Env::restore`] continues from it bit-identically.
#[derive(Clone)]
pub struct Checkpoint(Episode);

impl Checkpoint {
    /// The checkpoint as bytes (mostly the world's, 0.92 MB for a cluttered home): the world's own bytes, the
    /// robot, the bindings and the running metrics, with a magic and a format version. How the
    /// episode began is not in them: [`Env::restore_bytes`] is given it.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.0.to_bytes()
    }
}

impl std::fmt::Debug for Checkpoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Checkpoint(step {})", self.0.steps)
    }
}

/// A BEHAVIOR environment: one activity, a robot, episodes reset from a seed (see the crate
/// docs for an example).
pub struct Env {
    config: EnvConfig,
    scorer: Scorer,
    /// The objects `task_obs` reports, as activity instance indices.
    task_objects: Vec<usize>,
    /// The on-board sensors the configuration asks for, made at the first reset.
    onboard: Option<Vec<Box<dyn Sensor>>>,
    /// Sensors added with [`Env::add_sensor`].
    sensors: Vec<Box<dyn Sensor>>,
    episode: Option<Episode>,
    timings: StepTimings,
    /// The recording of the episode, if it is being recorded.
    recorder: Option<Recorder>,
}

impl Env {
    /// An environment for `config`; no episode runs until [`Env::reset`].
    pub fn new(config: EnvConfig) -> Env {
        let activity = &config.activity;
        let task_objects = activity
            .instances
            .iter()
            .enumerate()
            .filter(|(_, i)| {
                let synset = &activity.categories[i.category.0 as usize].name;
                synset != AGENT_SYNSET && synset != FLOOR_SYNSET
            })
            .map(|(k, _)| k)
            .collect();
        Env {
            scorer: Scorer::new(activity),
            config,
            task_objects,
            onboard: None,
            sensors: Vec::new(),
            episode: None,
            timings: StepTimings::default(),
            recorder: None,
        }
    }

    /// Adds a sensor; its readings appear in every observation from the next reset or step.
    pub fn add_sensor(&mut self, sensor: Box<dyn Sensor>) {
        self.sensors.push(sensor);
    }

    /// The configuration.
    pub fn config(&self) -> &EnvConfig {
        &self.config
    }

    /// Starts an episode from `seed`: an instance sampled (or drawn from the saved ones), the
    /// robot put where the activity's agent stands, the world settled; returns the first
    /// observation. On error the previous episode is gone and `step` refuses until a reset
    /// succeeds.
    pub fn reset(&mut self, seed: u64) -> Result<(Obs, Info), EnvError> {
        self.finish_recording()?;
        self.episode = None;
        let instance = self.instance_for(seed)?;
        self.reset_to(Start { seed, instance })
    }

    /// Starts an episode from a given initial state (a recording's header does this).
    pub fn reset_to(&mut self, start: Start) -> Result<(Obs, Info), EnvError> {
        self.finish_recording()?;
        self.episode = None;
        self.make_onboard_sensors()?;
        let library = Library::new(&self.config.taxonomy);
        let loaded = start.instance.load(&self.config.activity, &library)?;
        let mut world = loaded.world;
        world.bodies_mut().set_substeps(self.config.physics);
        let (robot, agent) = embody(
            &mut world,
            &self.config.activity,
            &loaded.bindings,
            self.config.robot,
            self.config.action_space,
        )?;
        world.settle(SETTLE_STEPS);
        let mut bindings: Vec<Option<ObjectId>> =
            loaded.bindings.iter().copied().map(Some).collect();
        let base = robot.base();
        for b in bindings
            .iter_mut()
            .filter(|b| **b == agent && agent.is_some())
        {
            *b = Some(base);
        }
        let mut ignored = robot.objects();
        ignored.extend(agent);
        let oracle = BoundWorld {
            world: &world,
            bindings: &bindings,
        };
        let score = self.scorer.score(&oracle);
        let atoms = self.scorer.atoms(&oracle);
        let potential = self.scorer.first_option(&oracle);
        let tracker = Tracker::start(&world, &robot, &ignored, &score);
        self.episode = Some(Episode {
            world,
            robot,
            bindings,
            steps: 0,
            atoms,
            score: score.clone(),
            potential,
            tracker,
            start: Arc::new(start),
            over: false,
        });
        self.reset_sensors();
        // A reset whose first observation fails leaves no episode, as any failed reset.
        let obs = self.observe().inspect_err(|_| self.episode = None)?;
        Ok((obs, Info { steps: 0, score }))
    }

    /// The camera and lidar the configuration asks for, once.
    fn make_onboard_sensors(&mut self) -> Result<(), EnvError> {
        if self.onboard.is_some() {
            return Ok(());
        }
        let wanted = &self.config.observations;
        let mut onboard: Vec<Box<dyn Sensor>> = Vec::new();
        if wanted.camera.is_some() || !wanted.fixed_cameras.is_empty() {
            let categories = categories(&self.config.taxonomy);
            let cameras =
                CameraSensor::new(wanted.camera.clone(), &wanted.fixed_cameras, categories)?;
            onboard.push(Box::new(cameras));
        }
        if wanted.lidar {
            onboard.push(Box::new(LidarSensor));
        }
        self.onboard = Some(onboard);
        Ok(())
    }

    /// The initial state for a seed, from the configured source.
    fn instance_for(&self, seed: u64) -> Result<SavedInstance, EnvError> {
        let c = &self.config;
        match &c.instances {
            Instances::Saved(saved) if saved.is_empty() => Err(EnvError::Empty("saved instance")),
            Instances::Saved(saved) => Ok(saved[(seed % saved.len() as u64) as usize].clone()),
            Instances::Sampled if c.scenes.is_empty() => Err(EnvError::Empty("home")),
            Instances::Sampled => {
                let scene = &c.scenes[(seed % c.scenes.len() as u64) as usize];
                let library = Library::new(&c.taxonomy);
                let mut sampling_seed = seed;
                let mut tries = 0;
                loop {
                    tries += 1;
                    match instantiate(&c.activity, scene, sampling_seed, &library, &c.taxonomy) {
                        Ok(instance) => return Ok(instance.save()),
                        Err(_) if tries < SAMPLE_TRIES => {
                            sampling_seed = derived_seed(sampling_seed, 0)
                        }
                        Err(source) => {
                            return Err(EnvError::Sample {
                                activity: c.activity.name.clone(),
                                scene: scene.name.clone(),
                                seed,
                                tries,
                                source: Box::new(source),
                            });
                        }
                    }
                }
            }
        }
    }

    /// Takes one action step (1/30 s). A bad action, or a step outside an episode, is an error
    /// and changes nothing.
    pub fn step(&mut self, action: &[f32]) -> Result<Step, EnvError> {
        let episode = self.episode.as_mut().ok_or(EnvError::NotReset)?;
        if episode.over {
            return Err(EnvError::EpisodeOver {
                steps: episode.steps,
            });
        }
        episode.robot.set_action(action)?;
        let start = Instant::now();
        let mut timed = Timed::new(&mut episode.robot, start);
        episode.world.step_with(&mut timed);
        let (physics, rules) = timed.split();
        let stepped = Instant::now();
        let oracle = BoundWorld {
            world: &episode.world,
            bindings: &episode.bindings,
        };
        let score = self
            .scorer
            .rescore(&oracle, &mut episode.atoms, &episode.score);
        let reward = match self.config.reward {
            Reward::DeltaQ => score.q - episode.score.q,
            Reward::FirstOption => {
                let potential = self.scorer.first_option(&oracle);
                let change = potential - episode.potential;
                episode.potential = potential;
                change
            }
        };
        episode.steps += 1;
        episode.tracker.step(&episode.world, &episode.robot, &score);
        let terminated = score.success;
        let truncated = !terminated && episode.steps >= self.config.max_steps;
        episode.over = terminated || truncated;
        episode.score = score.clone();
        let info = Info {
            steps: episode.steps,
            score,
        };
        let scored = Instant::now();
        self.record_step(action)?;
        let obs = self.observe()?;
        let observed = Instant::now();
        let parts = [physics, rules, scored - stepped, observed - scored];
        self.timings.add(parts, observed - start);
        Ok(Step {
            obs,
            reward,
            terminated,
            truncated,
            info,
        })
    }

    /// The observation of the episode's world now, as a step gives it: after a [`Env::restore`],
    /// what the agent sees there (empty outside an episode).
    pub fn observe(&mut self) -> Result<Obs, EnvError> {
        let Some(episode) = &self.episode else {
            return Ok(Obs::default());
        };
        let (world, robot) = (&episode.world, &episode.robot);
        let mut obs = Obs::default();
        if self.config.observations.proprioception {
            robot.proprioception_into(world, &mut obs.proprioception);
        }
        if self.config.observations.task_obs {
            let objects: Vec<ObjectId> = self
                .task_objects
                .iter()
                .filter_map(|&k| episode.bindings[k])
                .collect();
            task_obs(world, robot, &objects, &mut obs.task_obs);
        }
        let input = SensorInput {
            world,
            robot,
            bindings: &episode.bindings,
        };
        for sensor in self.onboard.iter_mut().flatten().chain(&mut self.sensors) {
            sensor
                .observe(&input, &mut obs.sensors)
                .map_err(|source| EnvError::Sensor {
                    sensor: sensor.name().to_string(),
                    source,
                })?;
        }
        Ok(obs)
    }

    fn current(&self) -> Option<&Episode> {
        self.episode.as_ref()
    }

    /// The episode's world (`None` before the first reset).
    pub fn world(&self) -> Option<&World> {
        self.current().map(|e| &e.world)
    }

    /// The episode's robot.
    pub fn robot(&self) -> Option<&Robot> {
        self.current().map(|e| &e.robot)
    }

    /// How the episode began.
    pub fn start(&self) -> Option<&Start> {
        self.current().map(|e| e.start.as_ref())
    }

    /// The object of each activity instance (the agent's is the robot's base).
    pub fn bindings(&self) -> Option<&[Option<ObjectId>]> {
        self.current().map(|e| e.bindings.as_slice())
    }

    /// Steps taken in the episode.
    pub fn steps(&self) -> u32 {
        self.current().map_or(0, |e| e.steps)
    }

    /// The goal's standing after the last step.
    pub fn score(&self) -> Option<&Score> {
        self.current().map(|e| &e.score)
    }

    /// How many literals the goal's first option has (a smallest option,
    /// `behavior_bddl::options::options`' first): a reward of ΔQ times this counts goal literals,
    /// one each, where Q's best option is that size.
    pub fn goal_literals(&self) -> usize {
        self.scorer.first_option_len()
    }

    /// Whether the episode ended (terminated or truncated).
    pub fn is_over(&self) -> bool {
        self.current().is_some_and(|e| e.over)
    }

    /// The episode's metrics as of now: the logical disarrangement compares the start with the
    /// world now (a few milliseconds in a full home, so ask at the end).
    pub fn metrics(&self) -> Option<EpisodeMetrics> {
        self.current().map(|e| e.tracker.finish(&e.world))
    }

    /// The per-step values of the episode so far (for plots).
    pub fn series(&self) -> Option<&Series> {
        self.current().map(|e| e.tracker.series())
    }

    /// Where the time of the steps since the last [`Env::take_timings`] went.
    pub fn take_timings(&mut self) -> StepTimings {
        std::mem::take(&mut self.timings)
    }

    /// The episode's whole state (`None` before the first reset).
    pub fn checkpoint(&self) -> Option<Checkpoint> {
        self.current().cloned().map(Checkpoint)
    }

    /// Goes back to a checkpoint of this environment; the episode continues from there as it
    /// did the first time, bit for bit.
    pub fn restore(&mut self, checkpoint: &Checkpoint) {
        self.episode = Some(checkpoint.0.clone());
        self.reset_sensors();
    }

    /// Sensors start over (a camera's next flow is zero): after a reset or a restore.
    fn reset_sensors(&mut self) {
        for sensor in self.onboard.iter_mut().flatten().chain(&mut self.sensors) {
            sensor.reset();
        }
    }

    /// Goes on from a checkpoint's bytes ([`Checkpoint::to_bytes`]) of an episode begun as
    /// `start` says, bit for bit as the original continued. Damaged bytes are an error and
    /// leave the environment as it was.
    pub fn restore_bytes(&mut self, start: Start, bytes: &[u8]) -> Result<(), CheckpointError> {
        self.episode = Some(Episode::from_bytes(bytes, Arc::new(start))?);
        self.reset_sensors();
        Ok(())
    }

    /// The robot, for code that drives it between steps (a planner's primitives).
    pub fn robot_mut(&mut self) -> Option<&mut Robot> {
        self.episode.as_mut().map(|e| &mut e.robot)
    }

    /// Does `edit` to the world and the robot between two steps, outside physics and actions
    /// (a symbolic primitive teleports, attaches, sets states; see `edit.rs`), and records it
    /// when the episode is recording and it was done. The score, metrics and observation see
    /// the change at the next step, as the original's primitives are followed by one step. The
    /// outer error: no episode, or the recording failed (the edit was done); the inner one: the
    /// edit's own.
    pub fn apply<E: WorldEdit>(&mut self, edit: &E) -> Result<Result<(), E::Error>, EnvError> {
        let done = self.edit_unrecorded(|e| edit.apply(e))?;
        if done.is_ok()
            && let Some(mut recorder) = self.recorder.take()
        {
            recorder.record_edit(self, edit)?;
            self.recorder = Some(recorder);
        }
        Ok(done)
    }

    /// Lets `f` change the world and the robot between two steps without saying what it did:
    /// for setting up an episode that is not being recorded (a test puts the robot somewhere).
    /// While the episode records, [`EnvError::UnrecordedEdit`]: its edits go through
    /// [`Env::apply`].
    pub fn edit<R>(&mut self, f: impl FnOnce(Edit<'_>) -> R) -> Result<R, EnvError> {
        if self.recorder.is_some() {
            return Err(EnvError::UnrecordedEdit);
        }
        self.edit_unrecorded(f)
    }

    fn edit_unrecorded<R>(&mut self, f: impl FnOnce(Edit<'_>) -> R) -> Result<R, EnvError> {
        let episode = self.episode.as_mut().ok_or(EnvError::NotReset)?;
        if episode.over {
            return Err(EnvError::EpisodeOver {
                steps: episode.steps,
            });
        }
        Ok(f(Edit {
            world: &mut episode.world,
            robot: &mut episode.robot,
            bindings: &episode.bindings,
            seed: episode.start.seed,
            steps: episode.steps,
        }))
    }

    /// Starts recording the episode just reset to `path` (an MCAP file; see [`crate::record`]):
    /// from now on every step and every edit ([`Env::apply`]) is written as it happens, until
    /// [`Env::finish_recording`] or the next reset closes the file. `setup` holds the
    /// activity's BDDL text (a replay needs no other file), how often a full state is saved and
    /// who chooses the actions. A recording already running is closed first.
    pub fn record_to(
        &mut self,
        path: &std::path::Path,
        setup: RecordingSetup<'_>,
    ) -> Result<(), RecordError> {
        self.finish_recording()?;
        self.recorder = Some(Recorder::create(path, self, setup)?);
        Ok(())
    }

    /// Closes the recording, if one is running, with MCAP's summary and index.
    pub fn finish_recording(&mut self) -> Result<(), RecordError> {
        match self.recorder.take() {
            Some(recorder) => recorder.finish(self),
            None => Ok(()),
        }
    }

    /// Whether the episode is being recorded.
    pub fn is_recording(&self) -> bool {
        self.recorder.is_some()
    }

    /// Records what a teleoperation device reported for the step about to be taken (raw
    /// headset poses, keyboard rates), if recording: not needed to replay, kept so that a
    /// demonstration says what the person did as well as what the robot was told.
    pub fn record_device(&mut self, device: &impl serde::Serialize) -> Result<(), RecordError> {
        let Some(mut recorder) = self.recorder.take() else {
            return Ok(());
        };
        recorder.record_device(self, device)?;
        self.recorder = Some(recorder);
        Ok(())
    }

    /// Records the step just taken with `action`, if recording. A failure stops the recording.
    fn record_step(&mut self, action: &[f32]) -> Result<(), RecordError> {
        let Some(mut recorder) = self.recorder.take() else {
            return Ok(());
        };
        recorder.record(self, action)?;
        self.recorder = Some(recorder);
        Ok(())
    }
}

/// The `k`-th seed derived from `seed` (SplitMix64's (k + 1)-th output from the state
/// `seed`): the sampling seed a reset tries after `seed` fails (`k` = 0), and the seeds of the
/// episodes a vector environment starts by itself. Neighbouring seeds' derived seeds do not run
/// into each other.
pub fn derived_seed(seed: u64, k: u64) -> u64 {
    const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut z = seed.wrapping_add(k.wrapping_mul(GAMMA)).wrapping_add(GAMMA);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
