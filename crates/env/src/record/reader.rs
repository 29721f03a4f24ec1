//! Reading a recording back: the header, then one frame per step, as far as the file is whole.

use super::{FORMAT_VERSION, Header};
use crate::metrics::ACTION_HZ;
use mcap::read::{MessageStream, Options};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Why a recording cannot be read at all.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// It is not an MCAP file, or its start is damaged.
    #[error("{path} is not a readable MCAP recording: {reason}")]
    NotMcap {
        /// The file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
    /// It has no header message, or one this version cannot read.
    #[error("{path}: {reason}")]
    BadHeader {
        /// The file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
}

/// One recorded step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frame {
    /// The step (1 for the first action).
    pub step: u32,
    /// The action taken.
    pub action: Vec<f32>,
    /// Q after it, if recorded.
    pub q: Option<f64>,
    /// Every object's pose after it, if recorded.
    pub poses: Option<Vec<[f32; 7]>>,
}

/// A recording as read.
#[derive(Clone, Debug)]
pub struct Recording {
    /// The header.
    pub header: Header,
    /// Q at the start (step 0).
    pub start_q: Option<f64>,
    /// The steps, in order.
    pub frames: Vec<Frame>,
    /// The checkpoints: (step, digest).
    pub checkpoints: Vec<(u32, String)>,
    /// The full states saved with the checkpoints: (step, episode checkpoint bytes).
    pub states: Vec<(u32, Vec<u8>)>,
    /// The edits of the world between steps, in order: (the step after which each was made,
    /// what was done).
    pub edits: Vec<(u32, serde_json::Value)>,
    /// What a teleoperation device reported for each step it drove: (step, report).
    pub devices: Vec<(u32, serde_json::Value)>,
    /// Where and why reading stopped early, for a damaged or cut file; the frames before it
    /// are usable.
    pub damage: Option<String>,
}

#[derive(Deserialize)]
struct ActionMsg {
    step: u32,
    values: Vec<f32>,
}

#[derive(Deserialize)]
struct PosesMsg {
    step: u32,
    /// Whose poses follow (format 2); absent, every object's in order (format 1).
    #[serde(default)]
    objects: Option<Vec<usize>>,
    poses: Vec<[f32; 7]>,
}

#[derive(Deserialize)]
struct ScoreMsg {
    step: u32,
    q: f64,
}

#[derive(Deserialize)]
struct EditMsg {
    step: u32,
    edit: serde_json::Value,
}

#[derive(Deserialize)]
struct DeviceMsg {
    step: u32,
    device: serde_json::Value,
}

#[derive(Deserialize)]
struct CheckpointMsg {
    step: u32,
    digest: String,
}

impl Recording {
    /// How many steps each kind of teleoperation device drove (`keys`, `xr`: a report is
    /// `{"<kind>": …}`); empty for an agent's or a planner's episode.
    pub fn device_steps(&self) -> std::collections::BTreeMap<String, usize> {
        let mut by = std::collections::BTreeMap::new();
        for (_, report) in &self.devices {
            let kind = match report.as_object().and_then(|o| o.keys().next()) {
                Some(kind) => kind.clone(),
                None => "unknown".to_string(),
            };
            *by.entry(kind).or_insert(0) += 1;
        }
        by
    }
}

/// Reads a recording. A file cut or damaged after its header reads up to the last whole
/// chunk, with [`Recording::damage`] saying where it stopped.
pub fn read(path: &Path) -> Result<Recording, ReadError> {
    let bytes = std::fs::read(path).map_err(|source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let not_mcap = |reason: String| ReadError::NotMcap {
        path: path.to_path_buf(),
        reason,
    };
    let stream = MessageStream::new_with_options(&bytes, Options::IgnoreEndMagic.into())
        .map_err(|e| not_mcap(e.to_string()))?;
    let mut reading = Reading::default();
    for message in stream {
        let message = match message {
            Ok(m) => m,
            Err(e) => {
                reading.damage = Some(format!(
                    "the file ({} bytes) is damaged or cut after step {}: {e}",
                    bytes.len(),
                    reading.last_step(),
                ));
                break;
            }
        };
        if message.channel.topic == "/state" {
            // Log times are whole nanoseconds of step / 30 s, rounded down: round back.
            let step = (message.log_time * u64::from(ACTION_HZ) + 500_000_000) / 1_000_000_000;
            let step = u32::try_from(step).unwrap_or(u32::MAX);
            reading.states.push((step, message.data.into_owned()));
            continue;
        }
        if let Err(reason) = reading.take(&message.channel.topic, &message.data) {
            reading.damage = Some(format!("after step {}: {reason}", reading.last_step()));
            break;
        }
    }
    reading.finish(path)
}

/// What has been read so far.
#[derive(Default)]
struct Reading {
    header: Option<Header>,
    start_q: Option<f64>,
    frames: Vec<Frame>,
    checkpoints: Vec<(u32, String)>,
    states: Vec<(u32, Vec<u8>)>,
    edits: Vec<(u32, serde_json::Value)>,
    devices: Vec<(u32, serde_json::Value)>,
    damage: Option<String>,
    /// Every object's pose as of the last `/poses`.
    poses: Vec<[f32; 7]>,
}

impl Reading {
    fn last_step(&self) -> u32 {
        self.frames.last().map_or(0, |f| f.step)
    }

    /// Takes one message; an error says why it makes no sense.
    fn take(&mut self, topic: &str, data: &[u8]) -> Result<(), String> {
        let bad = |e: serde_json::Error| format!("a bad {topic} message: {e}");
        match topic {
            "/header" => {
                let header: Header = serde_json::from_slice(data).map_err(bad)?;
                if !(1..=FORMAT_VERSION).contains(&header.format_version) {
                    return Err(format!(
                        "format version {} (this build reads 1 to {FORMAT_VERSION})",
                        header.format_version
                    ));
                }
                // Until the first poses, each object at the origin, unturned.
                self.poses = vec![[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]; header.objects.len()];
                self.header = Some(header);
            }
            "/action" => {
                let m: ActionMsg = serde_json::from_slice(data).map_err(bad)?;
                if m.step != self.last_step() + 1 {
                    return Err(format!("action of step {} out of order", m.step));
                }
                self.frames.push(Frame {
                    step: m.step,
                    action: m.values,
                    ..Frame::default()
                });
            }
            "/poses" => {
                let m: PosesMsg = serde_json::from_slice(data).map_err(bad)?;
                match m.objects {
                    None => self.poses = m.poses,
                    Some(objects) => {
                        if objects.len() != m.poses.len() {
                            return Err(format!(
                                "{} objects for {} poses",
                                objects.len(),
                                m.poses.len()
                            ));
                        }
                        for (i, pose) in objects.into_iter().zip(m.poses) {
                            // Objects appear during an episode (a sliced one's halves), one
                            // after the last known, when all poses are written again.
                            if i == self.poses.len() {
                                self.poses.push(pose);
                                continue;
                            }
                            let Some(slot) = self.poses.get_mut(i) else {
                                return Err(format!(
                                    "the pose of object {i}, past the {} known",
                                    self.poses.len()
                                ));
                            };
                            *slot = pose;
                        }
                    }
                }
                if let Some(f) = self.frames.last_mut().filter(|f| f.step == m.step) {
                    f.poses = Some(self.poses.clone());
                }
            }
            "/score" => {
                let m: ScoreMsg = serde_json::from_slice(data).map_err(bad)?;
                match self.frames.last_mut().filter(|f| f.step == m.step) {
                    Some(f) => f.q = Some(m.q),
                    None if m.step == 0 => self.start_q = Some(m.q),
                    None => {}
                }
            }
            "/checkpoint" => {
                let m: CheckpointMsg = serde_json::from_slice(data).map_err(bad)?;
                self.checkpoints.push((m.step, m.digest));
            }
            "/edit" => {
                let m: EditMsg = serde_json::from_slice(data).map_err(bad)?;
                if m.step != self.last_step() {
                    return Err(format!("edit after step {} out of order", m.step));
                }
                self.edits.push((m.step, m.edit));
            }
            "/device" => {
                let m: DeviceMsg = serde_json::from_slice(data).map_err(bad)?;
                if m.step != self.last_step() + 1 {
                    return Err(format!("device report for step {} out of order", m.step));
                }
                self.devices.push((m.step, m.device));
            }
            _ => {}
        }
        Ok(())
    }

    fn finish(self, path: &Path) -> Result<Recording, ReadError> {
        let Some(header) = self.header else {
            let reason = match self.damage {
                Some(damage) => format!("no readable header: {damage}"),
                None => "no header message: not a BEHAVIOR recording".to_string(),
            };
            return Err(ReadError::BadHeader {
                path: path.to_path_buf(),
                reason,
            });
        };
        Ok(Recording {
            header,
            start_q: self.start_q,
            frames: self.frames,
            checkpoints: self.checkpoints,
            states: self.states,
            edits: self.edits,
            devices: self.devices,
            damage: self.damage,
        })
    }
}
