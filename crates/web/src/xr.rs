//! WebXR teleoperation: a headset and its two controllers drive the BehaviorRobot, as people
//! drove it with a Vive in the paper's demonstrations.
//!
//! The page sends the devices' poses as WebXR reports them, in the `local-floor` reference
//! space (metres; y up, −z ahead of where the person stood when the session began), with each
//! controller's trigger and thumbstick. The server turns them into the robot's ordinary 26-d
//! action, so a demonstration is an action sequence like any other and replays bit for bit;
//! the raw poses are recorded beside the actions.
//!
//! - **Rig.** A recenter (the page asks for one when a session starts) ties the person's
//!   head, as it is then, to the robot's eye: the head's heading becomes the body's +x and its
//!   position the eye's. From then on every device pose is carried into the body frame
//!   ([`XrRig::to_body`]).
//! - **Head → eye, controllers → hands.** Each step moves the eye and each hand towards where
//!   its device is, by at most the action's 0.05 m and 0.05 rad; a controller's pointing
//!   direction is the hand's fingers, its top the back of the hand.
//! - **Triggers grasp.** A pressed trigger (its value 0 to 1) closes its hand, a released one
//!   opens it: the trigger's rate is `2 × value − 1` (assisted grasping does the rest).
//! - **Thumbsticks move the body.** The left stick walks and strafes, the right stick's x turns
//!   (a dead zone of 0.15 as for gamepads). Walking in the room does not move the body: the eye
//!   follows the head up to its reach of 0.5 m.

use behavior_robots::{ACTION_DIM, ACTION_SCALE, Action, Embodiment, Side};
use behavior_sim::World;
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// Thumbstick values smaller than this are read as zero (sticks rest a little off centre).
pub const STICK_DEAD_ZONE: f32 = 0.15;

/// How far from the reference space's origin a device may be reported, m: beyond any room.
const MAX_DISTANCE: f32 = 100.0;

/// A pose as WebXR reports it: position (x, y, z) then orientation quaternion (x, y, z, w).
pub type XrPose = [f32; 7];

/// One controller's state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct XrController {
    /// The grip's pose (WebXR's `gripSpace`).
    pub pose: XrPose,
    /// The trigger, 0 (released) to 1 (pressed).
    #[serde(default)]
    pub trigger: f32,
    /// The thumbstick (x right, y down as the Gamepad API reports it), each in [−1, 1].
    #[serde(default)]
    pub stick: [f32; 2],
}

/// What a headset reports in one frame: the head's pose and each tracked controller's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct XrInput {
    /// The head (the viewer's pose).
    pub head: XrPose,
    /// The left controller, when tracked.
    #[serde(default)]
    pub left: Option<XrController>,
    /// The right controller, when tracked.
    #[serde(default)]
    pub right: Option<XrController>,
    /// Tie the rig anew to where the head is now (see the module docs).
    #[serde(default)]
    pub recenter: bool,
}

/// A value of an [`XrInput`] that no device reports.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{field}[{index}]` is {value}: {expected}")]
pub struct BadDevice {
    /// Where it is (`head`, `left.pose`, `right.trigger`…).
    pub field: &'static str,
    /// Its index there.
    pub index: usize,
    /// The value sent.
    pub value: f32,
    /// What was expected.
    pub expected: &'static str,
}

impl XrInput {
    /// The first value that no device reports: not finite, a position farther than 100 m, a
    /// quaternion far from unit length, a trigger outside [0, 1], a stick outside [−1, 1].
    pub fn check(&self) -> Result<(), BadDevice> {
        check_pose("head", &self.head)?;
        let controllers = [
            (["left.pose", "left.trigger", "left.stick"], &self.left),
            (["right.pose", "right.trigger", "right.stick"], &self.right),
        ];
        for ([pose, trigger, stick], controller) in controllers {
            let Some(c) = controller else { continue };
            check_pose(pose, &c.pose)?;
            check_range(trigger, &[c.trigger], 0.0, "a trigger value in [0, 1]")?;
            check_range(stick, &c.stick, -1.0, "a stick value in [-1, 1]")?;
        }
        Ok(())
    }
}

fn check_pose(field: &'static str, pose: &XrPose) -> Result<(), BadDevice> {
    let bad = |index: usize, expected| BadDevice {
        field,
        index,
        value: pose[index],
        expected,
    };
    if let Some(index) = pose.iter().position(|v| !v.is_finite()) {
        return Err(bad(index, "every value must be a finite number"));
    }
    if let Some(index) = pose[..3].iter().position(|v| v.abs() > MAX_DISTANCE) {
        return Err(bad(index, "a position within 100 m of the origin"));
    }
    let norm = pose[3..].iter().map(|v| v * v).sum::<f32>().sqrt();
    if !(0.5..=2.0).contains(&norm) {
        return Err(bad(3, "an orientation quaternion of unit length"));
    }
    Ok(())
}

fn check_range(
    field: &'static str,
    values: &[f32],
    low: f32,
    expected: &'static str,
) -> Result<(), BadDevice> {
    match values
        .iter()
        .position(|v| !v.is_finite() || *v < low || *v > 1.0)
    {
        Some(index) => Err(BadDevice {
            field,
            index,
            value: values[index],
            expected,
        }),
        None => Ok(()),
    }
}

/// WebXR's axes in the body's: ahead is −z there and +x here, left −x and +y, up +y and +z.
fn basis() -> Rotation {
    Rotation::from_mat3(&rapier3d::glamx::Mat3::from_cols(
        Vector::new(0.0, -1.0, 0.0),
        Vector::new(0.0, 0.0, 1.0),
        Vector::new(-1.0, 0.0, 0.0),
    ))
}

/// Where the robot's eye and hands are told to be now, body frame: what a step's action moves
/// them from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Targets {
    /// The eye.
    pub eye: Pose,
    /// The hands, left then right.
    pub hands: [Pose; 2],
}

impl Targets {
    /// The robot's targets now: its camera (the eye) and its two posed hands' targets, in
    /// the base's frame; `None` for a robot without two posed hands.
    pub fn of(robot: &dyn Embodiment, world: &World) -> Option<Targets> {
        let body = robot.base_pose(world);
        let target = |hand: usize| robot.posed_hand(hand).map(|h| h.target());
        Some(Targets {
            eye: body.inverse() * robot.camera_pose(world),
            hands: [target(0)?, target(1)?],
        })
    }
}

/// How device poses are carried into the robot's body frame: WebXR's axes turned into the
/// body's, then the heading at the last recenter turned away and the head moved onto the eye.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct XrRig {
    /// The turn about the body's z undoing the head's heading at the recenter, rad.
    pub yaw: f32,
    /// Added after the turn, m (body frame).
    pub offset: [f32; 3],
}

impl XrRig {
    /// The rig that puts `head` where the eye is now (`eye`, body frame), facing the body's +x.
    pub fn recentered(head: &XrPose, eye: &Pose) -> XrRig {
        let ahead = basis() * quat(head) * basis().inverse() * Vector::X;
        let yaw = -ahead.y.atan2(ahead.x);
        let position = Rotation::from_rotation_z(yaw) * (basis() * position(head));
        let offset = eye.translation - position;
        XrRig {
            yaw,
            offset: offset.to_array(),
        }
    }

    /// A device's pose in the body frame.
    pub fn to_body(&self, pose: &XrPose) -> Pose {
        let turn = Rotation::from_rotation_z(self.yaw) * basis();
        let translation = turn * position(pose) + Vector::from_array(self.offset);
        let rotation = turn * quat(pose) * basis().inverse();
        Pose::from_parts(translation, rotation.normalize())
    }

    /// The action of one step that moves the robot towards `input` (see the module docs).
    pub fn action(&self, input: &XrInput, now: &Targets) -> [f32; ACTION_DIM] {
        let mut a = [0.0; ACTION_DIM];
        a[Action::EYE].copy_from_slice(&towards(&now.eye, &self.to_body(&input.head)));
        let controllers = [input.left, input.right];
        for (side, controller) in Side::BOTH.into_iter().zip(controllers) {
            let Some(c) = controller else { continue };
            let target = self.to_body(&c.pose);
            a[Action::hand_range(side)]
                .copy_from_slice(&towards(&now.hands[side.index()], &target));
            a[Action::trigger_index(side)] = (2.0 * c.trigger - 1.0).clamp(-1.0, 1.0);
        }
        let stick = |c: Option<XrController>, k: usize| {
            let v = c.map_or(0.0, |c| c.stick[k]);
            if v.abs() < STICK_DEAD_ZONE { 0.0 } else { v }
        };
        a[Action::BODY.start] = -stick(input.left, 1);
        a[Action::BODY.start + 1] = -stick(input.left, 0);
        a[Action::BODY.start + 5] = -stick(input.right, 0);
        a
    }
}

fn position(pose: &XrPose) -> Vector {
    Vector::new(pose[0], pose[1], pose[2])
}

fn quat(pose: &XrPose) -> Rotation {
    Rotation::from_xyzw(pose[3], pose[4], pose[5], pose[6]).normalize()
}

/// The six rates (Δx, Δy, Δz, roll, pitch, yaw, each in [−1, 1]) that move `from` towards `to`
/// by at most one step's scale: each axis of the translation clipped, the rotation cut along
/// its arc to at most the scale's angle.
fn towards(from: &Pose, to: &Pose) -> [f32; 6] {
    let s = ACTION_SCALE;
    let d = (to.translation - from.translation) / s;
    let mut turn = (to.rotation * from.rotation.inverse()).normalize();
    let angle = turn.angle_between(Rotation::IDENTITY);
    if angle > s {
        turn = Rotation::IDENTITY.slerp(turn, s / angle);
    }
    let (yaw, pitch, roll) = turn.to_euler(EulerRot::ZYX);
    let rates = [d.x, d.y, d.z, roll / s, pitch / s, yaw / s];
    rates.map(|v| v.clamp(-1.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    const LEVEL: XrPose = [0.0, 1.6, 0.0, 0.0, 0.0, 0.0, 1.0];

    fn eye() -> Pose {
        Pose::from_translation(Vector::new(0.05, 0.0, 0.4))
    }

    #[test]
    fn the_head_at_a_recenter_lands_on_the_eye_and_ahead_is_the_body_s_x() {
        let rig = XrRig::recentered(&LEVEL, &eye());
        let head = rig.to_body(&LEVEL);
        assert!((head.translation - eye().translation).length() < 1e-6);
        assert!(head.rotation.angle_between(Rotation::IDENTITY) < 1e-6);
        // A controller 0.4 m ahead of the head (−z in WebXR), 0.2 m to its right and 0.3 m
        // below is 0.4 m along the body's x, 0.2 m along −y, 0.3 m down from the eye.
        let hand = rig.to_body(&[0.2, 1.3, -0.4, 0.0, 0.0, 0.0, 1.0]);
        let expected = eye().translation + Vector::new(0.4, -0.2, -0.3);
        assert!((hand.translation - expected).length() < 1e-6, "{hand:?}");
    }

    #[test]
    fn a_head_turned_at_the_recenter_still_looks_along_the_body() {
        // Turned 90° to the left about WebXR's y (up): ahead is then −x there.
        let h = std::f32::consts::FRAC_1_SQRT_2;
        let turned = [1.0, 1.6, 2.0, 0.0, h, 0.0, h];
        let rig = XrRig::recentered(&turned, &eye());
        let head = rig.to_body(&turned);
        assert!((head.translation - eye().translation).length() < 1e-5);
        assert!(head.rotation.angle_between(Rotation::IDENTITY) < 1e-5);
        // Half a metre ahead of that head (−x in WebXR) is half a metre along the body's x.
        let ahead = rig.to_body(&[0.5, 1.6, 2.0, 0.0, h, 0.0, h]);
        assert!((ahead.translation - eye().translation - Vector::X * 0.5).length() < 1e-5);
    }

    #[test]
    fn rates_step_towards_the_devices_and_stop_there() {
        let rig = XrRig::recentered(&LEVEL, &eye());
        let hand = Pose::from_translation(Vector::new(0.3, -0.2, 0.1));
        let now = Targets {
            eye: eye(),
            hands: [hand, hand],
        };
        // The right controller 1 cm ahead of where the right hand is told to be, and pressed.
        let target = Vector::new(0.31, -0.2, 0.1) - Vector::from_array(rig.offset);
        let xr = basis().inverse() * target;
        let right = XrController {
            pose: [xr.x, xr.y, xr.z, 0.0, 0.0, 0.0, 1.0],
            trigger: 1.0,
            stick: [0.05, -0.8],
        };
        let input = XrInput {
            head: LEVEL,
            left: None,
            right: Some(right),
            recenter: false,
        };
        let a = rig.action(&input, &now);
        let r = Action::RIGHT_HAND.start;
        assert!(
            (a[r] - 0.2).abs() < 1e-4,
            "1 cm is a fifth of a step: {}",
            a[r]
        );
        assert!(a[r + 1..r + 6].iter().all(|v| v.abs() < 1e-4), "{a:?}");
        assert_eq!(a[Action::RIGHT_TRIGGER], 1.0);
        assert_eq!(
            a[Action::LEFT_TRIGGER],
            0.0,
            "an untracked controller does nothing"
        );
        assert!(
            a[Action::EYE].iter().all(|v| v.abs() < 1e-5),
            "the head is at the eye"
        );
        // The right stick's x is in its dead zone; its y does not drive.
        assert_eq!(a[Action::BODY].to_vec(), vec![0.0; 6]);
        Action::new(&a).expect("a valid action");
    }

    #[test]
    fn a_far_turn_is_cut_to_one_step_along_its_arc() {
        let from = Pose::IDENTITY;
        let to = Pose::from_parts(Vector::new(1.0, -1.0, 0.0), Rotation::from_rotation_z(1.0));
        let rates = towards(&from, &to);
        assert_eq!(&rates[..3], &[1.0, -1.0, 0.0]);
        assert!(
            (rates[5] - 1.0).abs() < 1e-4 && rates[3].abs() < 1e-4,
            "{rates:?}"
        );
    }

    #[test]
    fn impossible_device_values_are_named() {
        let mut input = XrInput {
            head: LEVEL,
            left: Some(XrController {
                pose: LEVEL,
                trigger: 0.5,
                stick: [0.0, 0.0],
            }),
            right: None,
            recenter: true,
        };
        assert_eq!(input.check(), Ok(()));
        input.head[6] = 0.0;
        let e = input.check().unwrap_err();
        assert_eq!((e.field, e.index), ("head", 3));
        input.head[6] = 1.0;
        input.head[1] = f32::NAN;
        assert_eq!(input.check().unwrap_err().field, "head");
        input.head[1] = 1.6;
        input.left.as_mut().unwrap().trigger = 1.5;
        let e = input.check().unwrap_err();
        assert_eq!((e.field, e.index), ("left.trigger", 0));
        assert!(e.to_string().contains("[0, 1]"), "{e}");
        input.left.as_mut().unwrap().trigger = 0.0;
        input.left.as_mut().unwrap().pose[0] = 1e6;
        assert_eq!(input.check().unwrap_err().field, "left.pose");
    }
}
