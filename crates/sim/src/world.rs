//! The world: a [`Core`] (objects, bodies, joints, rooms, physics) and the state systems, stepped
//! together ([`crate::step`]).
//!
//! Everything geometric is read through [`World::core`] (poses, boxes, joints, contacts,
//! relations, queries); the world adds what spans the core and the systems: adding objects,
//! unary states, teleports and joint moves that must invalidate what depends on them, stepping,
//! and snapshots.

use crate::core::{Core, Substeps, WorldError};
use crate::object::{ObjectId, ObjectSpec};
use crate::room::Room;
use crate::states::Systems;
use behavior_core::Predicate;
use rapier3d::math::{Pose, Vector};

/// The simulated world. It is `Send + Sync`: environments step in threads, and a renderer may read
/// a world while another one steps. Cloning it (or taking a [`Snapshot`]) copies every piece of
/// state, so a clone continues bit-identically.
#[derive(Clone)]
pub struct World {
    pub(crate) core: Core,
    pub(crate) systems: Systems,
}

/// A saved world state; [`World::restore`] continues from it bit-identically.
#[derive(Clone)]
pub struct Snapshot(World);

impl Default for World {
    fn default() -> Self {
        World::new(Substeps::default())
    }
}

impl World {
    /// An empty world with gravity along −z.
    pub fn new(substeps: Substeps) -> World {
        World {
            core: Core::new(substeps),
            systems: Systems::default(),
        }
    }

    /// Objects, bodies, joints, rooms and physics, for reading: poses, boxes, relations,
    /// contacts, joint states, ray and shape queries.
    pub fn core(&self) -> &Core {
        &self.core
    }

    /// The core, for acting on bodies: velocities, forces, kinematic targets, drives,
    /// attachments, collision groups. Teleports go through [`World::set_pose`] and
    /// [`World::set_joint_position`], which the core also offers.
    pub fn core_mut(&mut self) -> &mut Core {
        &mut self.core
    }

    /// Adds an object; a bad spec is an error and leaves the world unchanged.
    pub fn add(&mut self, spec: ObjectSpec) -> Result<ObjectId, WorldError> {
        let id = self.core.add(spec)?;
        self.systems.add_object(&mut self.core, id);
        Ok(id)
    }

    /// Adds a room; `floor`, if given, is the object standing for its floor.
    pub fn add_room(&mut self, room: Room) {
        self.core.rooms.push(room);
    }

    /// The points (palms, fingertips, gripper) that can press buttons, from now on.
    pub fn set_hand_points(&mut self, points: &[Vector]) {
        self.systems.toggles.set_hands(points);
    }

    /// The water drops in flight, as world positions.
    pub fn drops(&self) -> Vec<Vector> {
        self.systems.water.drops(&self.core)
    }

    /// Dust (`Dusty`) or stain (`Stained`) particles of an object, in world coordinates.
    pub fn particle_positions(&self, id: ObjectId, kind: Predicate) -> Vec<Vector> {
        self.systems.dirt.positions(&self.core, id, kind)
    }

    /// The two halves made when an object was sliced.
    pub fn halves(&self, id: ObjectId) -> Option<[ObjectId; 2]> {
        self.core.object(id).replaced_by
    }

    /// Drops every memoized relation (for benchmarks of the uncached computation).
    pub fn forget_relations(&self) {
        self.core.memo.clear();
    }

    /// A copy of the whole state.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot(self.clone())
    }

    /// Goes back to a snapshot; stepping on gives the same states, bit for bit, as stepping on
    /// from when it was taken.
    pub fn restore(&mut self, snapshot: &Snapshot) {
        *self = snapshot.0.clone();
    }

    // Shorthands for the reads nearly every caller needs.

    /// Every object with its id. See [`Core::objects`].
    pub fn objects(&self) -> impl ExactSizeIterator<Item = (ObjectId, &crate::Object)> {
        self.core.objects()
    }

    /// An object. See [`Core::object`].
    pub fn object(&self, id: ObjectId) -> &crate::Object {
        self.core.object(id)
    }

    /// The first object of that name.
    pub fn object_named(&self, name: &str) -> Option<ObjectId> {
        self.core.object_named(name)
    }

    /// Every room.
    pub fn rooms(&self) -> &[Room] {
        self.core.rooms()
    }

    /// The pose of an object's body.
    pub fn pose(&self, id: ObjectId) -> Pose {
        self.core.pose(id)
    }

    /// The axis-aligned box around all of an object's colliders.
    pub fn aabb(&self, id: ObjectId) -> rapier3d::prelude::Aabb {
        self.core.aabb(id)
    }

    /// Moves an object (teleport) with its links, at rest, waking it.
    pub fn set_pose(&mut self, id: ObjectId, pose: Pose) -> Result<(), WorldError> {
        self.core.set_pose(id, pose)
    }

    /// Moves a link to a joint position (clamped to its limits), at rest.
    pub fn set_joint_position(
        &mut self,
        id: ObjectId,
        link: usize,
        position: f32,
    ) -> Result<(), WorldError> {
        self.core.set_joint_position(id, link, position)
    }

    /// Action steps taken so far.
    pub fn steps(&self) -> u64 {
        self.core.steps()
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_world_can_be_shared_and_sent_between_threads() {
        fn send_sync<T: Send + Sync>() {}
        send_sync::<super::World>();
        send_sync::<super::Snapshot>();
    }
}
