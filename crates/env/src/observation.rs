//! What the agent perceives: proprioception, the full-observability `task_obs` vector, and
//! what [`Sensor`]s add (the robot's camera and lidar of `sensors.rs`, or one's own).
//!
//! `task_obs` follows iGibson 2.0's full-observability layout (iGibson 2.0.3's
//! `robots/behavior_robot.py`), 456 numbers:
//!
//! | index | value |
//! |---|---|
//! | 0–2 | the robot base's position, world frame, m |
//! | 3–5 | its roll, pitch, yaw (fixed axes x, y, z), rad |
//! | 6 + 9k | object k: 1 if the slot holds an object, else 0 (and the slot is all zeros) |
//! | 7 + 9k … 9 + 9k | its position (centre of its bounding box), m |
//! | 10 + 9k … 12 + 9k | its roll, pitch, yaw, rad |
//! | 13 + 9k, 14 + 9k | held by the left / right hand (Fetch: its gripper / always 0) |
//!
//! Objects are the activity's `:objects` in file order, floors and the agent left out (the
//! original lists only its `URDFObject`s, which floors and the robot are not), at most
//! [`TASK_OBJECTS`]. A sliced object reports its first half's pose while that half exists.

use behavior_render::Pixels;
use behavior_robots::Robot;
use behavior_sim::{ObjectId, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::Pose;

/// Object slots in `task_obs`.
pub const TASK_OBJECTS: usize = 50;
/// Numbers per object slot.
pub const TASK_OBJECT_DIM: usize = 9;
/// The length of `task_obs`: 6 + 50 × 9 = 456.
pub const TASK_OBS_DIM: usize = 6 + TASK_OBJECTS * TASK_OBJECT_DIM;

/// One observation of a sensor: numbers and their shape (row-major), e.g. `[128, 128, 3]` of u8
/// for an RGB image.
#[derive(Clone, Debug, PartialEq)]
pub struct Reading {
    /// Dimensions, outermost first.
    pub shape: Vec<usize>,
    /// `shape.iter().product()` numbers, of the type the modality has (u8 colour, f32 depth in
    /// metres, u16 or u32 ids).
    pub data: Pixels,
}

/// What a sensor may look at when it observes.
pub struct SensorInput<'a> {
    /// The world after the step.
    pub world: &'a World,
    /// The robot.
    pub robot: &'a Robot,
    /// The objects bound to the activity's instances, in `:objects` order (`None` for one that
    /// has no object, as the agent's stand-in once the robot replaced it).
    pub bindings: &'a [Option<ObjectId>],
}

/// A source of observations beyond proprioception and `task_obs`: cameras and lidars (see
/// `sensors.rs`), or one's own, handed to [`crate::Env::add_sensor`].
pub trait Sensor: Send {
    /// Its name, for errors.
    fn name(&self) -> &str;
    /// A new episode starts (a camera forgets its last frame, so the first flow is zero).
    fn reset(&mut self) {}
    /// Observes the world after a reset or a step, adding its readings, each under its own key.
    fn observe(
        &mut self,
        input: &SensorInput,
        out: &mut Vec<(String, Reading)>,
    ) -> Result<(), Box<dyn std::error::Error + Send + Sync>>;
}

/// An observation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Obs {
    /// The robot's proprioception (empty when not asked for).
    pub proprioception: Vec<f32>,
    /// The full-observability vector of the module docs (empty when not asked for).
    pub task_obs: Vec<f32>,
    /// The sensors' readings (`rgb`, `depth`, `lidar`, …), in the order the sensors were added.
    pub sensors: Vec<(String, Reading)>,
}

impl Obs {
    /// A sensor reading by its key (`rgb`, `depth`, `lidar`, …).
    pub fn get(&self, key: &str) -> Option<&Reading> {
        self.sensors.iter().find(|(k, _)| k == key).map(|(_, r)| r)
    }
}

fn euler(pose: &Pose) -> [f32; 3] {
    let (yaw, pitch, roll) = pose.rotation.to_euler(EulerRot::ZYX);
    [roll, pitch, yaw]
}

/// Writes `task_obs` into `out` (cleared first); `objects` are the slots' objects in order.
pub(crate) fn task_obs(world: &World, robot: &Robot, objects: &[ObjectId], out: &mut Vec<f32>) {
    out.clear();
    out.resize(TASK_OBS_DIM, 0.0);
    let base = robot.base_pose(world);
    out[0..3].copy_from_slice(&base.translation.to_array());
    out[3..6].copy_from_slice(&euler(&base));
    for (k, &id) in objects.iter().take(TASK_OBJECTS).enumerate() {
        let shown = match world.bodies().object(id).replaced_by {
            Some([first, _]) if !world.bodies().object(id).is_present() => first,
            _ => id,
        };
        let slot = &mut out[6 + k * TASK_OBJECT_DIM..6 + (k + 1) * TASK_OBJECT_DIM];
        slot[0] = 1.0;
        slot[1..4].copy_from_slice(&world.bodies().aabb(shown).center().to_array());
        slot[4..7].copy_from_slice(&euler(&world.bodies().pose(shown)));
        for hand in 0..robot.hands().min(2) {
            let held = robot.held(hand);
            slot[7 + hand] = f32::from(u8::from(held == Some(id) || held == Some(shown)));
        }
    }
}
