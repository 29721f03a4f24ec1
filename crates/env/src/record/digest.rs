//! A fingerprint of the full state of an episode, for checking replays bit for bit.
//!
//! SHA-256 over, for every object in world order: its presence, the exact bits of its body's
//! and each link's pose and velocities, each joint's position, and its whole non-physical state
//! (temperatures, soaked, switch and counter, particles, flags); then the robot's
//! proprioception bits and the step count. Two states with the same digest are the same state
//! as far as anything observable goes; one flipped bit anywhere changes it.

use behavior_robots::Robot;
use behavior_sim::{BodyRef, World};
use sha2::{Digest, Sha256};

/// The digest of the episode's state, as 64 hex digits.
pub fn state_digest(world: &World, robot: &Robot, steps: u32) -> String {
    let mut hash = Sha256::new();
    let all = world.bodies();
    for (id, object) in all.objects() {
        hash.update([u8::from(object.is_present())]);
        let bodies = std::iter::once(BodyRef::from(id))
            .chain((0..object.links.len()).map(|l| BodyRef::link(id, l)));
        for body in bodies {
            if let Ok(pose) = all.body_pose(body) {
                put(&mut hash, &pose.translation.to_array());
                put(&mut hash, &pose.rotation.to_array());
            }
            if let Ok(v) = all.velocity(body) {
                put(&mut hash, &v.linear.to_array());
                put(&mut hash, &v.angular.to_array());
            }
        }
        let joints: Vec<f32> = (0..object.links.len())
            .map(|l| world.joints().position(id, l))
            .collect();
        put(&mut hash, &joints);
        let state = format!("{:?}", world.object_state(id));
        hash.update(state.as_bytes());
    }
    let mut proprioception = Vec::new();
    robot.proprioception_into(world, &mut proprioception);
    put(&mut hash, &proprioception);
    hash.update(steps.to_le_bytes());
    hash.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

fn put(hash: &mut Sha256, values: &[f32]) {
    for v in values {
        hash.update(v.to_bits().to_le_bytes());
    }
}
