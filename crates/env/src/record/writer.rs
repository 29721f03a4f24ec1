//! Writing a recording as the episode runs (see the module docs for the layout).

use super::{CHUNK_BYTES, FORMAT_VERSION, Header, RecordingSetup, STATE_ENCODING, state_digest};
use crate::env::Env;
use crate::metrics::ACTION_HZ;
use mcap::records::MessageHeader;
use mcap::{Compression, WriteOptions, Writer};
use serde::Serialize;
use serde_json::json;
use std::collections::BTreeMap;
use std::fs::File;
use std::path::{Path, PathBuf};

/// Why a recording could not be written.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    /// The file could not be created or written.
    #[error("cannot write the recording {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The MCAP writer refused.
    #[error("cannot write the recording {path}: {source}")]
    Mcap {
        /// The file.
        path: PathBuf,
        /// Why.
        source: mcap::McapError,
    },
    /// There is no episode to record: reset the environment first.
    #[error("nothing to record: reset the environment first")]
    NoEpisode,
}

/// The topics, in the order their channels are added.
const TOPICS: [&str; 8] = [
    "/header",
    "/action",
    "/poses",
    "/score",
    "/checkpoint",
    "/edit",
    "/device",
    "/state",
];

/// The index in [`TOPICS`] of `/state`, the one channel without a JSON schema.
const STATE: usize = 7;

/// An episode being recorded: the environment owns it ([`Env::record_to`]) and writes every
/// step and edit as it happens, so that no caller pairs a step with its recording.
pub(crate) struct Recorder {
    writer: Writer<File>,
    path: PathBuf,
    channels: [u16; 8],
    sequence: u32,
    checkpoint_every: u32,
    /// The poses last written, in the header's object order (empty before the first).
    poses: Vec<[f32; 7]>,
    /// The step of the last checkpoint written.
    checkpointed: u32,
    /// Whether the world was edited since the last poses were written.
    edited: bool,
}

impl Recorder {
    /// Starts a recording of the episode `env` has just reset: writes the header, the starting
    /// poses and the first checkpoint, as `setup` asks.
    pub(crate) fn create(
        path: &Path,
        env: &Env,
        setup: RecordingSetup<'_>,
    ) -> Result<Recorder, RecordError> {
        let checkpoint_every = setup.checkpoint_every.max(1);
        let (Some(start), Some(world)) = (env.start(), env.world()) else {
            return Err(RecordError::NoEpisode);
        };
        let io = |source| RecordError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = File::create(path).map_err(io)?;
        let mcap = |source| RecordError::Mcap {
            path: path.to_path_buf(),
            source,
        };
        let options = WriteOptions::new()
            .compression(Some(Compression::Zstd))
            .chunk_size(Some(CHUNK_BYTES))
            .profile("behavior");
        let mut writer = options.create(file).map_err(mcap)?;
        let mut channels = [0; 8];
        for (k, topic) in TOPICS.iter().enumerate().take(STATE) {
            let schema = writer
                .add_schema(topic, "jsonschema", schema_of(topic).as_bytes())
                .map_err(mcap)?;
            channels[k] = writer
                .add_channel(schema, topic, "json", &BTreeMap::new())
                .map_err(mcap)?;
        }
        // The episode's bytes: no schema, the encoding names the format.
        channels[STATE] = writer
            .add_channel(0, TOPICS[STATE], STATE_ENCODING, &BTreeMap::new())
            .map_err(mcap)?;
        let config = env.config();
        let header = Header {
            format_version: FORMAT_VERSION,
            crate_version: env!("CARGO_PKG_VERSION").to_string(),
            activity: config.activity.name.clone(),
            definition: setup.definition.to_string(),
            scene: start.instance.scene.name.clone(),
            seed: start.seed,
            robot: config.robot.name().to_string(),
            action_space: config.action_space.name().to_string(),
            physics_hz: config.physics.count() * ACTION_HZ,
            action_hz: ACTION_HZ,
            max_steps: config.max_steps,
            checkpoint_every,
            instance: start.instance.clone(),
            objects: world
                .bodies()
                .objects()
                .map(|(_, o)| o.name.clone())
                .collect(),
            provenance: setup.provenance,
        };
        let mut recorder = Recorder {
            writer,
            path: path.to_path_buf(),
            channels,
            sequence: 0,
            checkpoint_every,
            poses: Vec::new(),
            checkpointed: 0,
            edited: false,
        };
        recorder.write(0, 0, &header)?;
        recorder.write_state(env)?;
        Ok(recorder)
    }

    /// Records the step `env` has just taken with `action`.
    pub(crate) fn record(&mut self, env: &Env, action: &[f32]) -> Result<(), RecordError> {
        let step = env.steps();
        self.write(1, step, &json!({ "step": step, "values": action }))?;
        self.write_state(env)
    }

    /// Records that the world was edited between steps ([`Env::apply`]) after the step `env`
    /// has taken last: `edit` says what was done, in the words of whoever did it (a symbolic
    /// primitive's name and object), for a replay's editor to do it again.
    pub(crate) fn record_edit(
        &mut self,
        env: &Env,
        edit: &impl Serialize,
    ) -> Result<(), RecordError> {
        let step = env.steps();
        self.edited = true;
        self.write(5, step, &json!({ "step": step, "edit": edit }))
    }

    /// Records what a teleoperation device reported for the step `env` is about to take (raw
    /// headset poses, keyboard rates): not needed to replay, kept so that a demonstration says
    /// what the person did as well as what the robot was told.
    pub(crate) fn record_device(
        &mut self,
        env: &Env,
        device: &impl Serialize,
    ) -> Result<(), RecordError> {
        let step = env.steps() + 1;
        self.write(6, step, &json!({ "step": step, "device": device }))
    }

    /// Closes the file with MCAP's summary and index, after a last checkpoint of the state
    /// `env` ends in where the last step had none (and no edit followed it, which a replay does
    /// only after comparing): a replay then checks the episode to its end.
    pub(crate) fn finish(mut self, env: &Env) -> Result<(), RecordError> {
        let step = env.steps();
        if step != self.checkpointed && !self.edited {
            self.write_checkpoint(env)?;
        }
        let path = self.path.clone();
        self.writer
            .finish()
            .map(|_| ())
            .map_err(|source| RecordError::Mcap { path, source })
    }

    /// Poses and score after a step (or the reset), and a checkpoint when one is due.
    fn write_state(&mut self, env: &Env) -> Result<(), RecordError> {
        let (Some(world), Some(score)) = (env.world(), env.score()) else {
            return Err(RecordError::NoEpisode);
        };
        let step = env.steps();
        let poses: Vec<[f32; 7]> = world
            .bodies()
            .objects()
            .map(|(id, _)| {
                let p = world.bodies().pose(id);
                let (t, r) = (p.translation, p.rotation);
                [t.x, t.y, t.z, r.x, r.y, r.z, r.w]
            })
            .collect();
        // Only what moved since the last poses (bit for bit), all of them the first time: most
        // of a home sleeps, and every pose at every step made a demonstration 80 MB.
        let bits = |p: &[f32; 7]| p.map(f32::to_bits);
        let moved: Vec<usize> = if self.poses.len() == poses.len() {
            (0..poses.len())
                .filter(|&i| bits(&poses[i]) != bits(&self.poses[i]))
                .collect()
        } else {
            (0..poses.len()).collect()
        };
        let changed: Vec<[f32; 7]> = moved.iter().map(|&i| poses[i]).collect();
        let message = json!({ "step": step, "objects": moved, "poses": changed });
        self.write(2, step, &message)?;
        self.poses = poses;
        self.edited = false;
        let score = json!({
            "step": step,
            "q": score.q,
            "success": score.success,
            "conjuncts": score.conjuncts,
        });
        self.write(3, step, &score)?;
        if step.is_multiple_of(self.checkpoint_every) {
            self.write_checkpoint(env)?;
        }
        Ok(())
    }

    /// The digest and full state of the step `env` stands at; the file flushed.
    fn write_checkpoint(&mut self, env: &Env) -> Result<(), RecordError> {
        let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
            return Err(RecordError::NoEpisode);
        };
        let step = env.steps();
        let digest = state_digest(world, robot, step);
        self.write(4, step, &json!({ "step": step, "digest": digest }))?;
        if let Some(checkpoint) = env.checkpoint() {
            self.write_bytes(STATE, step, &checkpoint.to_bytes())?;
        }
        self.checkpointed = step;
        self.writer.flush().map_err(|source| RecordError::Mcap {
            path: self.path.clone(),
            source,
        })
    }

    fn write(
        &mut self,
        channel: usize,
        step: u32,
        value: &impl Serialize,
    ) -> Result<(), RecordError> {
        let data = serde_json::to_vec(value).map_err(|e| RecordError::Io {
            path: self.path.clone(),
            source: e.into(),
        })?;
        self.write_bytes(channel, step, &data)
    }

    fn write_bytes(&mut self, channel: usize, step: u32, data: &[u8]) -> Result<(), RecordError> {
        let time = u64::from(step) * 1_000_000_000 / u64::from(ACTION_HZ);
        let header = MessageHeader {
            channel_id: self.channels[channel],
            sequence: self.sequence,
            log_time: time,
            publish_time: time,
        };
        self.sequence += 1;
        self.writer
            .write_to_known_channel(&header, data)
            .map_err(|source| RecordError::Mcap {
                path: self.path.clone(),
                source,
            })
    }
}

/// The JSON Schema of a topic's messages.
fn schema_of(topic: &str) -> String {
    let number = json!({ "type": "number" });
    let step = json!({ "type": "integer", "minimum": 0 });
    let schema = match topic {
        "/header" => json!({ "type": "object", "description": "behavior_env::record::Header" }),
        "/action" => json!({ "type": "object", "properties": {
            "step": step, "values": { "type": "array", "items": number } } }),
        "/poses" => json!({ "type": "object", "properties": {
            "step": step,
            "objects": { "type": "array", "items": { "type": "integer", "minimum": 0 },
                "description": "the header's indices of the objects whose poses follow: those that moved since the last /poses (all at the first)" },
            "poses": { "type": "array", "items": {
                "type": "array", "items": number, "minItems": 7, "maxItems": 7,
                "description": "x, y, z (m), qx, qy, qz, qw" } } } }),
        "/score" => json!({ "type": "object", "properties": {
            "step": step, "q": number, "success": { "type": "boolean" },
            "conjuncts": { "type": "array", "items": { "type": "boolean" } } } }),
        "/edit" => json!({ "type": "object", "properties": {
            "step": step, "edit": { "description": "what was done between this step and the next" } } }),
        "/device" => json!({ "type": "object", "properties": {
            "step": step, "device": { "description": "what the teleoperation device reported for this step" } } }),
        _ => json!({ "type": "object", "properties": {
            "step": step, "digest": { "type": "string", "description": "SHA-256, hex" } } }),
    };
    schema.to_string()
}
