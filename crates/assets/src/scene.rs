//! Scene files: a home as plain data (rooms, walls, objects with archetype, pose, size, variant
//! and joint positions), saved as JSON and loaded back exactly, and built into a [`World`].
//!
//! Schema (all lengths in metres, z up; a room's floor top is at z = 0):
//! ```json
//! {
//!   "name": "alder", "seed": 1,
//!   "rooms":   [{"kind": "kitchen", "instance": 0, "min": [0.0, 1.6], "max": [4.5, 6.0]}],
//!   "walls":   [{"min": [0.0, 1.55, 0.0], "max": [4.5, 1.65, 2.5]}],
//!   "objects": [{"name": "cabinet_0", "synset": "cabinet.n.01", "room": 0,
//!                "position": [0.5, 5.6, 0.0], "yaw_quarter_turns": 2,
//!                "size": [0.8, 0.5, 0.9], "variant": 0, "joints": [0.0]}]
//! }
//! ```
//! `position` is where the object's bottom centre stands; `yaw_quarter_turns` turns it about z
//! (0: its front faces −y; 1: +x; 2: +y; 3: −x); `joints` are its doors' and drawers' positions.
//! Every room gets a floor object named `floor_<kind>_<instance>`.

use crate::library::{AssetError, Library};
use behavior_core::RoomType;
use behavior_sim::{ObjectId, ObjectSpec, Part, Primitive, Room, World, WorldError};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

pub const WALL_HEIGHT: f32 = 2.5;
pub const FLOOR_THICKNESS: f32 = 0.1;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    pub name: String,
    pub seed: u64,
    pub rooms: Vec<RoomPlan>,
    pub walls: Vec<WallPlan>,
    pub objects: Vec<ObjectPlan>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoomPlan {
    pub kind: RoomType,
    pub instance: u32,
    pub min: [f32; 2],
    pub max: [f32; 2],
}

impl RoomPlan {
    pub fn label(&self) -> String {
        format!("{}_{}", self.kind, self.instance)
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WallPlan {
    pub min: [f32; 3],
    pub max: [f32; 3],
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectPlan {
    pub name: String,
    pub synset: String,
    /// Index into `rooms` of the room it stands in.
    pub room: usize,
    pub position: [f32; 3],
    pub yaw_quarter_turns: u8,
    pub size: [f32; 3],
    pub variant: u32,
    #[serde(default)]
    pub joints: Vec<f32>,
}

#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("the scene file is not valid: {0}")]
    Json(#[from] serde_json::Error),
    #[error("object `{object}`: {source}")]
    Asset { object: String, source: AssetError },
    #[error("{0}")]
    World(#[from] WorldError),
    #[error("object `{object}` names room {room}, but the scene has {rooms} rooms")]
    BadRoom {
        object: String,
        room: usize,
        rooms: usize,
    },
    #[error("{what} has a non-finite or negative size")]
    BadGeometry { what: String },
}

/// A scene built into a world: which object is which.
pub struct BuiltScene {
    pub world: World,
    /// The floor object of each room, in `rooms` order.
    pub floors: Vec<ObjectId>,
    /// The object built for each entry of `objects`.
    pub objects: Vec<ObjectId>,
}

impl Scene {
    pub fn to_json(&self) -> String {
        // Plain data of strings and finite numbers always serializes.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    pub fn from_json(text: &str) -> Result<Scene, SceneError> {
        Ok(serde_json::from_str(text)?)
    }

    /// The room containing (x, y), if any.
    pub fn room_at(&self, x: f32, y: f32) -> Option<usize> {
        self.rooms
            .iter()
            .position(|r| (r.min[0]..=r.max[0]).contains(&x) && (r.min[1]..=r.max[1]).contains(&y))
    }

    /// Builds the world: floors, walls, then every object at its pose with its joints set.
    pub fn build(&self, library: &Library) -> Result<BuiltScene, SceneError> {
        let mut world = World::default();
        let mut floors = Vec::with_capacity(self.rooms.len());
        for room in &self.rooms {
            let (w, d) = (room.max[0] - room.min[0], room.max[1] - room.min[1]);
            if !(w.is_finite() && d.is_finite() && w > 0.0 && d > 0.0) {
                return Err(SceneError::BadGeometry { what: room.label() });
            }
            let slab = Primitive::Box {
                half_extents: Vector::new(w / 2.0, d / 2.0, FLOOR_THICKNESS / 2.0),
            };
            let center = Vector::new(
                (room.min[0] + room.max[0]) / 2.0,
                (room.min[1] + room.max[1]) / 2.0,
                -FLOOR_THICKNESS / 2.0,
            );
            let mut spec = ObjectSpec::new(
                &format!("floor_{}", room.label()),
                "floor.n.01",
                vec![Part::new(slab)],
            )
            .at(center)
            .fixed();
            // Floors get dusty and stained like any surface.
            if let Some(abilities) = library.taxonomy().abilities(&spec.category) {
                spec.abilities = abilities.clone();
            }
            let floor = world.add(spec)?;
            world.add_room(Room {
                kind: room.kind,
                instance: room.instance,
                min: room.min,
                max: room.max,
                floor: Some(floor),
            });
            floors.push(floor);
        }
        for (i, wall) in self.walls.iter().enumerate() {
            let (lo, hi) = (Vector::from_array(wall.min), Vector::from_array(wall.max));
            let half = (hi - lo) * 0.5;
            if !(half.is_finite() && half.min_element() > 0.0) {
                return Err(SceneError::BadGeometry {
                    what: format!("wall {i}"),
                });
            }
            let spec = ObjectSpec::new(
                &format!("wall_{i}"),
                "wall.n.01",
                vec![Part::new(Primitive::Box { half_extents: half })],
            )
            .at(lo + half)
            .fixed();
            world.add(spec)?;
        }
        let mut objects = Vec::with_capacity(self.objects.len());
        for plan in &self.objects {
            if plan.room >= self.rooms.len() {
                return Err(SceneError::BadRoom {
                    object: plan.name.clone(),
                    room: plan.room,
                    rooms: self.rooms.len(),
                });
            }
            let size = Vector::from_array(plan.size);
            if !(size.is_finite() && size.min_element() > 0.0) {
                return Err(SceneError::BadGeometry {
                    what: plan.name.clone(),
                });
            }
            let mut spec = library
                .instance(&plan.synset, &plan.name, size, plan.variant)
                .map_err(|source| SceneError::Asset {
                    object: plan.name.clone(),
                    source,
                })?;
            let turn = Rotation::from_rotation_z(
                f32::from(plan.yaw_quarter_turns % 4) * std::f32::consts::FRAC_PI_2,
            );
            spec.pose = Pose::from_parts(Vector::from_array(plan.position), turn);
            let id = world.add(spec)?;
            let links = world.object(id).links.len();
            for (link, &q) in plan.joints.iter().enumerate().take(links) {
                world
                    .set_joint_position(id, link, q)
                    .map_err(SceneError::World)?;
            }
            objects.push(id);
        }
        Ok(BuiltScene {
            world,
            floors,
            objects,
        })
    }
}
