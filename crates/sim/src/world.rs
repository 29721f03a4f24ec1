//! The world: its geometric parts (the core: bodies, rooms, relations, attachments, contacts,
//! joints) and the state systems, stepped together ([`crate::step`]).
//!
//! The world lends out each part by concept — [`World::bodies`], [`World::relations`],
//! [`World::query`], [`World::joints`], [`World::attachments`], [`World::contacts`],
//! [`World::visuals`], [`World::rooms`], with a `_mut` twin where the part can be acted on — and
//! adds what spans the core and the systems: adding objects, unary states, stepping, placement
//! and snapshots.

use crate::attachments::{Attachments, AttachmentsMut};
use crate::bodies::Bodies;
use crate::contacts::{Contacts, ContactsMut};
use crate::core::{Core, Substeps, WorldError};
use crate::joints::{Joints, JointsMut};
use crate::kinematics::Relations;
use crate::object::{ObjectId, ObjectSpec};
use crate::query::Query;
use crate::room::Room;
use crate::states::Systems;
use crate::visual::Visuals;
use behavior_core::Predicate;
use rapier3d::math::Vector;

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

    /// Every object's bodies, colliders and joints, for reading: objects, poses, masses, boxes,
    /// velocities, sleeping, motion counts, steps.
    pub fn bodies(&self) -> &Bodies {
        &self.core.bodies
    }

    /// The bodies, for acting on them: teleports, velocities, forces, kinematic targets,
    /// substeps, sleeping, ghosts.
    pub fn bodies_mut(&mut self) -> &mut Bodies {
        &mut self.core.bodies
    }

    /// The kinematic relations between objects (`ontop`, `inside`, …) and the rooms they are in.
    pub fn relations(&self) -> Relations<'_> {
        Relations::new(&self.core)
    }

    /// Ray and shape queries.
    pub fn query(&self) -> Query<'_> {
        Query {
            bodies: &self.core.bodies,
        }
    }

    /// Joint positions, velocities, efforts and `open`.
    pub fn joints(&self) -> Joints<'_> {
        Joints::new(&self.core)
    }

    /// The joints, for moving them and setting their drives.
    pub fn joints_mut(&mut self) -> JointsMut<'_> {
        JointsMut::new(&mut self.core)
    }

    /// The attachments' conditions.
    pub fn attachments(&self) -> Attachments<'_> {
        Attachments::new(&self.core)
    }

    /// The attachments, for making and removing them.
    pub fn attachments_mut(&mut self) -> AttachmentsMut<'_> {
        AttachmentsMut::new(&mut self.core)
    }

    /// Contacts as the last substep found them, and which pairs are ignored.
    pub fn contacts(&self) -> Contacts<'_> {
        Contacts::new(&self.core)
    }

    /// Collision groups and ignored pairs.
    pub fn contacts_mut(&mut self) -> ContactsMut<'_> {
        ContactsMut::new(&mut self.core)
    }

    /// What to draw of each object.
    pub fn visuals(&self) -> Visuals<'_> {
        Visuals {
            bodies: &self.core.bodies,
        }
    }

    /// Every room.
    pub fn rooms(&self) -> &[Room] {
        &self.core.rooms
    }

    /// Adds an object; a bad spec is an error and leaves the world unchanged.
    pub fn add(&mut self, spec: ObjectSpec) -> Result<ObjectId, WorldError> {
        let id = self.core.bodies.add(spec)?;
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
