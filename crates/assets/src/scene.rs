//! Scene files: a home as plain data (rooms, walls, objects with archetype, pose, size, variant
//! and joint positions, and its clutter at settled poses), saved as JSON and loaded back exactly,
//! and built into a [`World`].
//!
//! Schema (all lengths in metres, z up; a room's floor top is at z = 0):
//! ```json
//! {
//!   "name": "alder", "seed": 1,
//!   "rooms":   [{"kind": "kitchen", "instance": 0, "min": [0.0, 1.6], "max": [4.5, 6.0]},
//!               {"kind": "bedroom", "instance": 0, "min": [4.5, 1.6], "max": [8.0, 6.0],
//!                "annexes": [{"min": [8.0, 4.0], "max": [9.6, 6.0]}],
//!                "rugs": [{"min": [5.0, 2.0], "max": [7.2, 4.8], "color": [150, 52, 48]}]}],
//!   "walls":   [{"min": [0.0, 1.55, 0.0], "max": [4.5, 1.65, 2.5]}],
//!   "objects": [{"name": "cabinet_0", "synset": "cabinet.n.01", "room": 0,
//!                "position": [0.5, 5.6, 0.0], "yaw_quarter_turns": 2,
//!                "size": [0.8, 0.5, 0.9], "variant": 0, "joints": [0.0]}],
//!   "clutter": [{"name": "clutter_mug_0", "synset": "mug.n.04", "archetype": "mug.n.04",
//!                "position": [0.52, 5.61, 0.4717], "rotation": [0.0, 0.0, 0.7071, 0.7071],
//!                "size": [0.09, 0.09, 0.11], "variant": 1}]
//! }
//! ```
//! `position` is where the object's bottom centre stands; `yaw_quarter_turns` turns it about z
//! (0: its front faces −y; 1: +x; 2: +y; 3: −x); `joints` are its doors' and drawers' positions.
//! A thing of the clutter has a full pose instead (its frame's origin, its bottom centre as
//! built, and a unit quaternion x, y, z, w), where it came to rest; `clutter` may be left out
//! (a furniture-only home, which is then written without it). Every room gets a floor object
//! named `floor_<kind>_<instance>`: a slab under its rectangle and under each of its `annexes`
//! (an L-shaped room's further rectangles, each sharing a whole side with the first), and its
//! `rugs` on top, 1 cm slabs of pile; both are left out of the file where there are none.
//!
//! A scene file describes a home at rest, so the world it builds starts asleep: the doors,
//! drawers and lids of its furniture and all its clutter (see [`behavior_sim::ObjectSpec::asleep`]).
//! Nothing moves, or costs anything per step, until something touches it.

use crate::library::{AssetError, Library};
use behavior_core::RoomType;
use behavior_core::{FLOOR_SYNSET, WALL_SYNSET};
use behavior_sim::{
    FloorRect, Material, ObjectId, ObjectSpec, Part, Primitive, Room, Visual, World, WorldError,
};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// Of every wall (m): above a standing agent's reach and a lidar's plane.
pub const WALL_HEIGHT: f32 = 2.5;
/// Of a room's floor slab (m), whose top is at z = 0: thick enough that nothing tunnels through.
pub const FLOOR_THICKNESS: f32 = 0.1;

/// A home as plain data: what a scene file holds, and what [`crate::generate`] makes. Kept apart
/// from the world it builds so that a home can be saved, edited, diffed and rebuilt exactly.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// A named home's name, or any label.
    pub name: String,
    /// The seed it was generated from, kept so that it can be generated again.
    pub seed: u64,
    /// The plan family it was generated as; none for a home made otherwise (and for the named
    /// homes' original corridor plan), and then left out of the file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub family: Option<crate::Family>,
    /// Its rooms, each of which gets a floor.
    pub rooms: Vec<RoomPlan>,
    /// Its wall pieces, doorways already cut out.
    pub walls: Vec<WallPlan>,
    /// Its furniture, doors and windows.
    pub objects: Vec<ObjectPlan>,
    /// Everyday things lying about that no activity asks for (books on shelves, food in the
    /// fridge), settled: see [`crate::clutter`]. Empty in a furniture-only home, and then left
    /// out of the file, so such a file reads as it did before clutter existed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub clutter: Vec<ClutterPlan>,
}

/// A room: its type, its extent on the floor (a rectangle, with annexes for an L-shaped room)
/// and the rugs on its floor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoomPlan {
    /// What kind of room, as `inroom` literals name it.
    pub kind: RoomType,
    /// Counts rooms of the same type from 0, so `bedroom_1` is the second bedroom.
    pub instance: u32,
    /// Its main rectangle's south-west corner (x, y), m.
    pub min: [f32; 2],
    /// Its main rectangle's north-east corner (x, y), m.
    pub max: [f32; 2],
    /// Further rectangles of an L-shaped room, each sharing a whole side with the main one
    /// (no wall between); left out of the file for a rectangular room.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub annexes: Vec<FloorRect>,
    /// Rugs lying on its floor; left out of the file where there are none.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rugs: Vec<RugPlan>,
}

impl RoomPlan {
    /// A rectangular room with no rugs.
    pub fn new(kind: RoomType, instance: u32, min: [f32; 2], max: [f32; 2]) -> RoomPlan {
        RoomPlan {
            kind,
            instance,
            min,
            max,
            annexes: Vec::new(),
            rugs: Vec::new(),
        }
    }

    /// Its name in the world and in messages: `kitchen_0`, `bedroom_1`.
    pub fn label(&self) -> String {
        format!("{}_{}", self.kind, self.instance)
    }

    /// The rectangles of its floor, the main one first.
    pub fn rects(&self) -> impl Iterator<Item = FloorRect> + '_ {
        FloorRect::footprint(self.min, self.max, &self.annexes)
    }

    /// Whether its floor contains (x, y), edges included.
    pub fn contains(&self, x: f32, y: f32) -> bool {
        self.rects().any(|r| r.contains(x, y))
    }
}

/// A rug: a thin slab of pile lying on a room's floor, part of the floor object (so that what
/// stands on it is `onfloor`, and robots' bases drive over it as over the floor).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RugPlan {
    /// Its south-west corner (x, y), m.
    pub min: [f32; 2],
    /// Its north-east corner (x, y), m.
    pub max: [f32; 2],
    /// Its colour, sRGB.
    pub color: [u8; 3],
}

/// How thick a rug is, m: under the 3 cm that Fetch's base clears and the 3 cm of the flat
/// things an object still counts `onfloor` on.
pub const RUG_THICKNESS: f32 = 0.01;

/// A wall piece: an axis-aligned box standing on the floor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WallPlan {
    /// Its lowest corner, m.
    pub min: [f32; 3],
    /// Its highest corner, m.
    pub max: [f32; 3],
}

/// An object of the home: which archetype, built how, standing where. Size and variant are
/// stored rather than redrawn, so that a scene file rebuilds the same objects whatever the
/// generator does.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectPlan {
    /// Its name in the world, e.g. `cabinet_0`.
    pub name: String,
    /// Its synset, which the library resolves to an archetype.
    pub synset: String,
    /// Index into `rooms` of the room it stands in.
    pub room: usize,
    /// Where its bottom centre stands, m.
    pub position: [f32; 3],
    /// Turns about z: 0, its front faces −y; 1, +x; 2, +y; 3, −x.
    pub yaw_quarter_turns: u8,
    /// Its bounding box as built (width, depth, height), m.
    pub size: [f32; 3],
    /// Which of its shape's variants.
    pub variant: u32,
    /// Positions of its doors and drawers, in link order; missing ones stay closed.
    #[serde(default)]
    pub joints: Vec<f32>,
}

/// A thing of the home's clutter, at the pose where it came to rest when the clutter was made,
/// so that a rebuilt home holds it exactly there, asleep. Size and variant are stored, like an
/// [`ObjectPlan`]'s, so the file rebuilds the same object whatever the library draws.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClutterPlan {
    /// Its name in the world, e.g. `clutter_book_3`: never an activity instance's name.
    pub name: String,
    /// Its synset.
    pub synset: String,
    /// The catalog synset whose archetype it is built from: its synset's own, or a descendant's.
    pub archetype: String,
    /// Where the origin of its frame (its bottom centre as built) is, m.
    pub position: [f32; 3],
    /// Its orientation as a unit quaternion (x, y, z, w): any settled orientation, not only
    /// turns about z.
    pub rotation: [f32; 4],
    /// Its bounding box as built, in its own frame (width, depth, height), m.
    pub size: [f32; 3],
    /// Which of its shape's variants.
    pub variant: u32,
}

/// Why a scene could not be loaded or built. Each message is a complete sentence with its cause;
/// no variant also returns the cause as [`std::error::Error::source`], so a report that walks
/// sources (`anyhow`'s `{:#}`) does not print it twice.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The text is not a scene file: bad JSON, a missing or unknown field.
    #[error("the scene file is not valid: {0}")]
    Json(serde_json::Error),
    /// An object's synset has no archetype.
    #[error("object `{object}`: {cause}")]
    Asset {
        /// The object's name.
        object: String,
        /// The library's reason.
        cause: AssetError,
    },
    /// The world refused an object or a joint position (its message names the object).
    #[error(transparent)]
    World(#[from] WorldError),
    /// An object refers to a room the scene does not have.
    #[error("object `{object}` names room {room}, but the scene has {rooms} rooms")]
    BadRoom {
        /// The object's name.
        object: String,
        /// The room index it gives.
        room: usize,
        /// How many rooms the scene has.
        rooms: usize,
    },
    /// A room, wall or object has a size that cannot be built.
    #[error("{what} has a non-finite or negative size")]
    BadGeometry {
        /// The room's label, `wall <i>`, or the object's name.
        what: String,
    },
}

impl From<serde_json::Error> for SceneError {
    fn from(error: serde_json::Error) -> SceneError {
        SceneError::Json(error)
    }
}

/// A scene built into a world: which object is which.
pub struct BuiltScene {
    /// The world with floors, walls and objects, joints set, not yet stepped.
    pub world: World,
    /// The floor object of each room, in `rooms` order.
    pub floors: Vec<ObjectId>,
    /// The object built for each entry of `objects`.
    pub objects: Vec<ObjectId>,
    /// The object built for each entry of `clutter`, asleep: no activity may bind these.
    pub clutter: Vec<ObjectId>,
}

impl BuiltScene {
    /// Whether an object is part of the home's clutter.
    pub fn is_clutter(&self, id: ObjectId) -> bool {
        // Clutter is added last, in one run, so its ids are contiguous and sorted.
        self.clutter.binary_search(&id).is_ok()
    }
}

impl Scene {
    /// The scene file's text: pretty-printed JSON, which [`Scene::from_json`] reads back
    /// exactly (floats print in their shortest round-tripping form).
    pub fn to_json(&self) -> String {
        // Plain data of strings and finite numbers always serializes.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Reads a scene file; unknown fields are errors, so a typo does not pass silently.
    pub fn from_json(text: &str) -> Result<Scene, SceneError> {
        Ok(serde_json::from_str(text)?)
    }

    /// The room containing (x, y), if any.
    pub fn room_at(&self, x: f32, y: f32) -> Option<usize> {
        self.rooms.iter().position(|r| r.contains(x, y))
    }

    /// Builds the world: floors, walls, every object at its pose with its joints set, then the
    /// clutter — furniture links and clutter asleep (see the module docs). Clutter comes last, so
    /// the ids of floors and furniture are the same with or without it.
    pub fn build(&self, library: &Library) -> Result<BuiltScene, SceneError> {
        let mut world = World::default();
        let floors = self
            .rooms
            .iter()
            .map(|room| add_floor(&mut world, room, library))
            .collect::<Result<Vec<_>, _>>()?;
        for (i, wall) in self.walls.iter().enumerate() {
            add_wall(&mut world, i, wall)?;
        }
        let objects = self
            .objects
            .iter()
            .map(|plan| self.add_object(&mut world, plan, library))
            .collect::<Result<Vec<_>, _>>()?;
        let clutter = self
            .clutter
            .iter()
            .map(|plan| add_clutter(&mut world, plan, library, true))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(BuiltScene {
            world,
            floors,
            objects,
            clutter,
        })
    }

    /// The same home without its clutter: furniture only.
    pub fn without_clutter(&self) -> Scene {
        Scene {
            clutter: Vec::new(),
            ..self.clone()
        }
    }

    /// Adds an object at its pose with its joints set (those beyond its links are ignored).
    fn add_object(
        &self,
        world: &mut World,
        plan: &ObjectPlan,
        library: &Library,
    ) -> Result<ObjectId, SceneError> {
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
            .map_err(|cause| SceneError::Asset {
                object: plan.name.clone(),
                cause,
            })?;
        let turn = Rotation::from_rotation_z(
            f32::from(plan.yaw_quarter_turns % 4) * std::f32::consts::FRAC_PI_2,
        );
        spec.pose = Pose::from_parts(Vector::from_array(plan.position), turn);
        // A home is built at rest: doors, drawers and lids start asleep, so that clutter resting
        // against them or in them is not woken by them, and an untouched home costs nothing.
        spec.asleep = true;
        let id = world.add(spec)?;
        let links = world.bodies().object(id).links.len();
        for (link, &q) in plan.joints.iter().enumerate().take(links) {
            // Links are built closed (at 0); moving one there anyway would only wake it.
            if q != 0.0 {
                world.joints_mut().set_position(id, link, q)?;
            }
        }
        Ok(id)
    }
}

/// Adds a thing of the clutter at its pose, asleep when it is known to rest there (as a scene
/// file's clutter is), awake while it is being settled. A non-unit rotation is refused by the
/// world with the object's name, as it is: normalizing it here would move a valid one by a bit.
pub(crate) fn add_clutter(
    world: &mut World,
    plan: &ClutterPlan,
    library: &Library,
    asleep: bool,
) -> Result<ObjectId, SceneError> {
    let size = Vector::from_array(plan.size);
    if !(size.is_finite() && size.min_element() > 0.0) {
        return Err(SceneError::BadGeometry {
            what: plan.name.clone(),
        });
    }
    let asset = |cause| SceneError::Asset {
        object: plan.name.clone(),
        cause,
    };
    let archetype = library.resolve(&plan.archetype).map_err(asset)?;
    if library.taxonomy().get(&plan.synset).is_none() {
        return Err(asset(AssetError::UnknownSynset(plan.synset.clone())));
    }
    let mut spec = library.instance_of(archetype, &plan.synset, &plan.name, size, plan.variant);
    spec.body = behavior_sim::BodyKind::Dynamic;
    spec.asleep = asleep;
    spec.pose = Pose::from_parts(
        Vector::from_array(plan.position),
        Rotation::from_array(plan.rotation),
    );
    Ok(world.add(spec)?)
}

/// The box between `min` and `max` on the floor, from `z0` to `z1`, as a part of an object
/// whose origin is at `origin`; `None` if it is empty or not finite.
fn slab_part(min: [f32; 2], max: [f32; 2], [z0, z1]: [f32; 2], origin: Vector) -> Option<Part> {
    let (w, d) = (max[0] - min[0], max[1] - min[1]);
    if !(w.is_finite() && d.is_finite() && w > 0.0 && d > 0.0) {
        return None;
    }
    let half = Vector::new(w / 2.0, d / 2.0, (z1 - z0) / 2.0);
    let centre = Vector::new(
        (min[0] + max[0]) / 2.0,
        (min[1] + max[1]) / 2.0,
        (z0 + z1) / 2.0,
    );
    Some(Part::at(
        Primitive::Box { half_extents: half },
        centre - origin,
    ))
}

/// Adds a room's floor, a slab whose top is at z = 0 under each of its rectangles, with its rugs
/// on top (parts of the floor, in pile), and registers the room with it.
fn add_floor(
    world: &mut World,
    room: &RoomPlan,
    library: &Library,
) -> Result<ObjectId, SceneError> {
    let bad = || SceneError::BadGeometry { what: room.label() };
    let center = Vector::new(
        (room.min[0] + room.max[0]) / 2.0,
        (room.min[1] + room.max[1]) / 2.0,
        -FLOOR_THICKNESS / 2.0,
    );
    let slab = [-FLOOR_THICKNESS, 0.0];
    let mut parts = room
        .rects()
        .map(|r| slab_part(r.min, r.max, slab, center).ok_or_else(bad))
        .collect::<Result<Vec<_>, _>>()?;
    for rug in &room.rugs {
        let part = slab_part(rug.min, rug.max, [0.0, RUG_THICKNESS], center).ok_or_else(bad)?;
        parts.push(part.with_visual(Visual {
            color: rug.color,
            material: Material::Cloth,
        }));
    }
    let mut spec = ObjectSpec::new(&format!("floor_{}", room.label()), FLOOR_SYNSET, parts)
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
        annexes: room.annexes.clone(),
        floor: Some(floor),
    });
    Ok(floor)
}

/// Adds wall piece `i`, fixed.
fn add_wall(world: &mut World, i: usize, wall: &WallPlan) -> Result<(), SceneError> {
    let (lo, hi) = (Vector::from_array(wall.min), Vector::from_array(wall.max));
    let half = (hi - lo) * 0.5;
    if !(half.is_finite() && half.min_element() > 0.0) {
        return Err(SceneError::BadGeometry {
            what: format!("wall {i}"),
        });
    }
    let spec = ObjectSpec::new(
        &format!("wall_{i}"),
        WALL_SYNSET,
        vec![Part::new(Primitive::Box { half_extents: half })],
    )
    .at(lo + half)
    .fixed();
    world.add(spec)?;
    Ok(())
}
