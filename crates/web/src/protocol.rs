//! The websocket protocol between the page and the server.
//!
//! Client → server: JSON text messages, [`ClientMessage`]: `drive` (keyboard or gamepad rates),
//! `xr` (a headset's poses, see `xr.rs`), `end` for a live episode; `play`, `pause`, `rate`,
//! `seek` for a recording played back (`playback.rs`); `seen` from any page, how many frames it
//! has drawn (see [`crate::clients`]). Each is parsed and checked before it
//! reaches the simulation; one that is not valid JSON, not a known message, too large, binary,
//! or carries a bad number is answered with `{"type": "error", "message": …}` and changes
//! nothing.
//!
//! Server → client, text (JSON): `role` on joining (driving or watching), `scene` when a client joins and at each new
//! episode (what to draw, the goal's literals), `status` after every step (Q, the metrics, which
//! literals hold, recoloured surfaces), `ended` when an episode ends (its recording), `xr_rig`
//! when an `xr` message recentered the rig (so that the page draws the world around the
//! headset as the server maps the headset into the world), `timeline` when a recording is
//! played (where playback stands, how much is re-simulated), `error`.
//! Binary: one frame of poses per step — little-endian `u32` step, then for every node of the
//! scene, in the scene's order, position (x, y, z) and rotation quaternion (x, y, z, w) as `f32`
//! (a node whose object left the world has NaN position).

use crate::checklist::ChecklistStatus;
use crate::playback::{RATES, Timeline};
use crate::scene::{Particles, Recolor, SceneDescription};
use crate::teleop::{BadRate, Drive};
use crate::xr::{BadDevice, XrInput, XrRig};
use behavior_env::EpisodeMetrics;
use serde::{Deserialize, Serialize};

/// The largest client message accepted, bytes (a drive command is about 200, an `xr` one 400).
pub const MAX_CLIENT_MESSAGE: usize = 16 * 1024;

/// What a client may say.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ClientMessage {
    /// Drive the robot at these rates from the next step on (the driver only).
    Drive(Drive),
    /// Drive the robot from a headset's poses from the next step on (the driver only).
    Xr(XrInput),
    /// End the episode now: its recording is closed and a new episode waits (the driver only).
    End,
    /// Play the recording from the step shown (from the start once at the end).
    Play,
    /// Stop playing.
    Pause,
    /// Play at this many times real time.
    Rate {
        /// In [0.05, 16].
        rate: f32,
    },
    /// Show this step of the recording (0: the start), and stop playing.
    Seek {
        /// The step.
        step: u32,
    },
    /// The page has taken this many binary frames since it joined: from then on the server
    /// keeps it only a few frames ahead of what it has drawn (any page may say it).
    Seen {
        /// Frames taken.
        frames: u64,
    },
}

/// Why a client message was refused.
#[derive(Debug, thiserror::Error)]
pub enum ProtocolError {
    /// Not JSON, or not a message of the protocol.
    #[error("not a message of the protocol: {0}")]
    Malformed(#[from] serde_json::Error),
    /// A number out of range.
    #[error(transparent)]
    BadRate(#[from] BadRate),
    /// A device value no headset reports.
    #[error(transparent)]
    BadDevice(#[from] BadDevice),
    /// Larger than `MAX_CLIENT_MESSAGE`.
    #[error("a message of {0} bytes; at most {MAX_CLIENT_MESSAGE} are accepted")]
    TooLarge(usize),
    /// A binary message: the client speaks JSON text.
    #[error("binary messages are not part of the protocol; send JSON text")]
    Binary,
    /// A command that only the driving client may give.
    #[error("this client is watching; only the driving client may send `{0}`")]
    NotDriver(&'static str),
    /// A command of the other kind of server (a live episode's, or a recording's).
    #[error("`{message}` needs {needs}")]
    NotHere {
        /// The message's type.
        message: &'static str,
        /// What serves it.
        needs: &'static str,
    },
    /// A playback rate outside `RATES`.
    #[error("a rate of {0}; it must lie in [{min}, {max}]", min = RATES.0, max = RATES.1)]
    BadPlayRate(f32),
    /// A step after the recording's last.
    #[error("step {step} is past the recording's last step, {steps}")]
    PastTheEnd {
        /// The step asked for.
        step: u32,
        /// The recording's steps.
        steps: u32,
    },
}

impl ClientMessage {
    /// Parses and checks a text message.
    pub fn parse(text: &str) -> Result<ClientMessage, ProtocolError> {
        if text.len() > MAX_CLIENT_MESSAGE {
            return Err(ProtocolError::TooLarge(text.len()));
        }
        let message: ClientMessage = serde_json::from_str(text)?;
        match &message {
            ClientMessage::Drive(drive) => drive.check()?,
            ClientMessage::Xr(input) => input.check()?,
            ClientMessage::Rate { rate } if !(RATES.0..=RATES.1).contains(rate) => {
                return Err(ProtocolError::BadPlayRate(*rate));
            }
            _ => {}
        }
        Ok(message)
    }

    /// The message's `type`, for error replies.
    pub(crate) fn name(&self) -> &'static str {
        match self {
            ClientMessage::Drive(_) => "drive",
            ClientMessage::Xr(_) => "xr",
            ClientMessage::End => "end",
            ClientMessage::Play => "play",
            ClientMessage::Pause => "pause",
            ClientMessage::Rate { .. } => "rate",
            ClientMessage::Seek { .. } => "seek",
            ClientMessage::Seen { .. } => "seen",
        }
    }
}

/// What the server says in text.
#[derive(Debug, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub(crate) enum ServerMessage<'a> {
    /// Whether this client drives the robot or watches; sent on joining.
    Role {
        /// It drives.
        driving: bool,
    },
    /// What to draw and what the goal is; sent on joining and at each new episode.
    Scene(&'a SceneDescription),
    /// How the episode stands after a step.
    Status(Status<'a>),
    /// An episode ended.
    Ended(Ended),
    /// How headset poses are carried into the body frame from now on.
    XrRig(&'a XrRig),
    /// Where a recording's playback stands.
    Timeline(&'a Timeline),
    /// A message was refused.
    Error {
        /// Why.
        message: String,
    },
}

/// How the episode stands after a step.
#[derive(Debug, Serialize)]
pub(crate) struct Status<'a> {
    /// Action steps taken.
    pub(crate) step: u32,
    /// The success score.
    pub(crate) q: f64,
    /// Whether the goal holds.
    pub(crate) success: bool,
    /// The efficiency metrics so far.
    pub(crate) metrics: &'a EpisodeMetrics,
    /// Which of the goal's literals hold, and the option closest to holding.
    pub(crate) checklist: &'a ChecklistStatus,
    /// Every surface whose colour has changed since the scene was sent, with its colour now
    /// (so that a page that skipped statuses is right again at the next one).
    pub(crate) recolor: &'a [Recolor],
    /// Every particle, when they changed since the last status (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) particles: Option<&'a Particles>,
}

/// An episode that ended.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Ended {
    /// Steps taken.
    pub(crate) steps: u32,
    /// Whether the goal held at the end.
    pub(crate) success: bool,
    /// Q at the end.
    pub(crate) q: f64,
    /// Where the episode was recorded (none for an episode of no steps).
    pub(crate) recording: Option<String>,
    /// Why it ended: `goal`, `time limit`, `ended by the driver`, `driver left`, `server stopped`.
    pub(crate) reason: &'static str,
}

impl ServerMessage<'_> {
    /// The message as JSON text.
    pub(crate) fn to_text(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| {
            format!(r#"{{"type":"error","message":"the server could not encode a reply: {e}"}}"#)
        })
    }
}

/// An error reply's text.
pub(crate) fn error_text(error: &dyn std::error::Error) -> String {
    ServerMessage::Error {
        message: error.to_string(),
    }
    .to_text()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drive_command_parses_with_missing_parts_at_rest() {
        let m = ClientMessage::parse(r#"{"type":"drive","body":[1,0,0,0,0,0.5]}"#).unwrap();
        let ClientMessage::Drive(d) = m else {
            panic!("{m:?}")
        };
        assert_eq!(d.body[5], 0.5);
        assert_eq!(d.right, [0.0; 6]);
        assert_eq!(
            ClientMessage::parse(r#"{"type":"end"}"#).unwrap(),
            ClientMessage::End
        );
    }

    #[test]
    fn hostile_messages_are_refused_with_the_reason() {
        let refused = |text: &str| ClientMessage::parse(text).unwrap_err().to_string();
        assert!(refused("{").contains("not a message"));
        assert!(refused(r#"{"type":"explode"}"#).contains("unknown variant"));
        assert!(refused(r#"{"type":"drive","body":[1,2]}"#).contains("not a message"));
        assert!(refused(r#"{"type":"drive","body":[0,0,0,0,0,7]}"#).contains("body[5]"));
        assert!(refused(r#"{"type":"drive","nose":[0]}"#).contains("unknown field"));
        let xr = r#"{"type":"xr","head":[0,1.6,0,0,0,0,1],"right":{"pose":[0,1,0,0,0,0,1],"trigger":2}}"#;
        assert!(refused(xr).contains("right.trigger[0]"), "{}", refused(xr));
        assert!(refused(r#"{"type":"rate","rate":"NaN"}"#).contains("not a message"));
        assert!(refused(r#"{"type":"rate","rate":100}"#).contains("[0.05, 16]"));
        assert!(refused(r#"{"type":"seek","step":-1}"#).contains("not a message"));
        let huge = format!(r#"{{"type":"drive","pad":"{}"}}"#, "x".repeat(20_000));
        assert!(refused(&huge).contains("at most"));
    }
}
