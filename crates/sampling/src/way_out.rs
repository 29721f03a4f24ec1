//! Whether the agent's place leads out of its room: the original's robots start on the home's
//! traversable map, in the part joined to the rest of the home, never in a pocket that a
//! toilet, a shower and a wall close round (where a sampled agent stood here, and every
//! navigation of the episode failed at once).
//!
//! The check floods the floor from the agent's place on a grid of [`CELL`], through the cells
//! indoors where an upright disc as wide as the agent and [`SPARE`] clears everything but
//! floors and the hinged parts a body pushes aside (doors, lids), and succeeds on reaching
//! another room. A way the disc passes is one a robot as wide as the agent drives along with
//! room to spare; a pocket the disc cannot leave, such a robot cannot either.
//!
//! The same flood, started from every clear cell within a person's reach of an object on the
//! floor, tells whether anyone can come and pick that object up ([`within_reach`]).

use behavior_core::{AGENT_SYNSET, FLOOR_SYNSET, floor_gap};
use behavior_sim::{BodyRef, ObjectId, Primitive, QueryFilter, World};
use rapier3d::math::{Pose, Vector};
use std::collections::{HashSet, VecDeque};

/// The flood's grid, m.
const CELL: f32 = 0.05;
/// The band of heights the disc stands over, m: above what a base rolls or floats over (a rug,
/// a sheet of plywood), up to a standing body's shoulders.
const BAND: (f32, f32) = (0.2, 1.4);
/// The room a way must leave on each side of the agent, m: a base is driven along a way, not
/// threaded through it.
const SPARE: f32 = 0.05;
/// Cells flooded at most before the place counts as open: a room's worth (40 m²) reached
/// without finding its door is no pocket.
const MOST_CELLS: usize = 16_000;

/// Whether `agent` (an `agent.n.01` stand-in on a floor) stands where a way leads out of its
/// room. A world without rooms, or an agent outside every room, has nothing to leave: true.
pub(crate) fn has_way_out(world: &World, agent: ObjectId) -> bool {
    let b = world.bodies().aabb(agent);
    let centre = b.center();
    let Some(home) = room_of(world, centre.x, centre.y) else {
        return true;
    };
    let radius = 0.5 * (b.maxs.x - b.mins.x).min(b.maxs.y - b.mins.y) + SPARE;
    let flood = Flood::new(world, centre, radius, passable(world, agent));
    flood.leaves(home, vec![(0, 0)])
}

/// How far across the floor from an object's box a person standing by it reaches, m: an arm's
/// length to something on the floor, bending down.
const REACH: f32 = 0.6;
/// The agent stand-in's half width, m (`agent.n.01` is 0.5 m across).
const AGENT_HALF_WIDTH: f32 = 0.25;

/// Whether someone as wide as the agent can stand within [`REACH`] of `object` (resting on a
/// floor) at a place from which a way leads out of its room: an object sampled `onfloor` lies
/// where a person can come and pick it up, not in a gap between a bed and a wall that nobody
/// fits into (where a package was sampled here, and no robot could come near it). An object
/// outside every room: true.
pub(crate) fn within_reach(world: &World, object: ObjectId) -> bool {
    let b = world.bodies().aabb(object);
    let centre = b.center();
    let Some(home) = room_of(world, centre.x, centre.y) else {
        return true;
    };
    let flood = Flood::new(
        world,
        centre,
        AGENT_HALF_WIDTH + SPARE,
        passable(world, object),
    );
    let (min, max) = ([b.mins.x, b.mins.y], [b.maxs.x, b.maxs.y]);
    let span = ((0.5 * (max[0] - min[0]).max(max[1] - min[1]) + REACH) / CELL).ceil() as i32;
    let near: Vec<(i32, i32)> = (-span..=span)
        .flat_map(|i| (-span..=span).map(move |j| (i, j)))
        .filter(|&cell| {
            let (x, y) = flood.at(cell);
            floor_gap(min, max, x, y) <= REACH && flood.clear(cell)
        })
        .collect();
    flood.leaves(home, near)
}

/// The room (type and instance) at (x, y), if any.
fn room_of(world: &World, x: f32, y: f32) -> Option<(behavior_core::RoomType, u32)> {
    world
        .relations()
        .room_at(x, y)
        .map(|r| (r.kind, r.instance))
}

/// The floor on a grid of [`CELL`] round an origin, and an upright disc that stands in its
/// cells where it clears everything but what `filter` ignores.
struct Flood<'w> {
    world: &'w World,
    origin: Vector,
    disc: Primitive,
    filter: QueryFilter,
}

impl<'w> Flood<'w> {
    fn new(world: &'w World, origin: Vector, radius: f32, filter: QueryFilter) -> Flood<'w> {
        let disc = Primitive::Cylinder {
            radius,
            half_height: 0.5 * (BAND.1 - BAND.0),
        };
        Flood {
            world,
            origin,
            disc,
            filter,
        }
    }

    /// The centre of a cell on the floor.
    fn at(&self, (i, j): (i32, i32)) -> (f32, f32) {
        (
            self.origin.x + i as f32 * CELL,
            self.origin.y + j as f32 * CELL,
        )
    }

    /// Whether the disc stands indoors in the cell and touches nothing there.
    fn clear(&self, cell: (i32, i32)) -> bool {
        let (x, y) = self.at(cell);
        let at = Vector::new(x, y, 0.5 * (BAND.0 + BAND.1));
        self.world.relations().room_at(x, y).is_some()
            && self
                .world
                .query()
                .overlaps(&self.disc, Pose::from_translation(at), &self.filter)
                .is_ok_and(|hits| hits.is_empty())
    }

    /// Whether the disc, starting from any of `from` (cells taken as clear), gets out of the
    /// room `home` through clear cells (or floods [`MOST_CELLS`] without finding a way: a room's
    /// worth is no pocket).
    fn leaves(&self, home: (behavior_core::RoomType, u32), from: Vec<(i32, i32)>) -> bool {
        let elsewhere = |cell: (i32, i32)| {
            let (x, y) = self.at(cell);
            room_of(self.world, x, y).is_some_and(|r| r != home)
        };
        let mut seen: HashSet<(i32, i32)> = from.iter().copied().collect();
        let mut frontier: VecDeque<(i32, i32)> = from.into();
        while let Some((i, j)) = frontier.pop_front() {
            if elsewhere((i, j)) || seen.len() >= MOST_CELLS {
                return true;
            }
            for next in [(i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)] {
                if seen.insert(next) && self.clear(next) {
                    frontier.push_back(next);
                }
            }
        }
        false
    }
}

/// What the disc may pass through: `own` (the agent itself, or the object reached for), the
/// agents, the floors, and every hinged or sliding part (a room's door, a cabinet's), which a
/// body pushes aside.
fn passable(world: &World, own: ObjectId) -> QueryFilter {
    let objects = world.bodies().objects();
    let mut ignored = vec![own];
    let mut links = Vec::new();
    for (id, o) in objects {
        if o.category == FLOOR_SYNSET || o.category == AGENT_SYNSET {
            ignored.push(id);
        }
        links.extend((0..o.links.len()).map(|l| BodyRef::link(id, l)));
    }
    QueryFilter {
        exclude_bodies: links,
        ..QueryFilter::excluding(&ignored)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_core::RoomType;
    use behavior_sim::{ObjectSpec, Part, Room};

    /// A fixed box from `min` to `max` (x, y), 2 m high.
    fn wall(world: &mut World, name: &str, min: [f32; 2], max: [f32; 2]) {
        let half = Vector::new(0.5 * (max[0] - min[0]), 0.5 * (max[1] - min[1]), 1.0);
        let part = Part::new(Primitive::Box { half_extents: half });
        let mut spec = ObjectSpec::new(name, "wall.n.01", vec![part]).fixed();
        let centre = Vector::new(0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1]), 1.0);
        spec.pose = Pose::from_translation(centre);
        world.add(spec).unwrap();
    }

    /// Two 4 × 4 m rooms side by side, a wall between them with a 1 m door at y 1.5–2.5, and
    /// an agent stand-in 0.5 m across at (x, y).
    fn home(x: f32, y: f32) -> (World, ObjectId) {
        let mut world = World::default();
        for (k, min_x) in [0.0, 4.0].into_iter().enumerate() {
            world.add_room(Room {
                kind: RoomType::Kitchen,
                instance: k as u32,
                min: [min_x, 0.0],
                max: [min_x + 4.0, 4.0],
                annexes: Vec::new(),
                floor: None,
            });
        }
        wall(&mut world, "wall_below_door", [3.95, 0.0], [4.05, 1.5]);
        wall(&mut world, "wall_above_door", [3.95, 2.5], [4.05, 4.0]);
        let part = Part::new(Primitive::Box {
            half_extents: Vector::new(0.25, 0.25, 0.75),
        });
        let mut spec = ObjectSpec::new("agent_1", AGENT_SYNSET, vec![part]);
        spec.pose = Pose::from_translation(Vector::new(x, y, 0.76));
        let agent = world.add(spec).unwrap();
        (world, agent)
    }

    /// A box 0.2 m across on the floor at (x, y), 0.1 m high.
    fn package(world: &mut World, x: f32, y: f32) -> ObjectId {
        let part = Part::new(Primitive::Box {
            half_extents: Vector::new(0.1, 0.1, 0.05),
        });
        let mut spec = ObjectSpec::new("package_1", "package.n.02", vec![part]);
        spec.pose = Pose::from_translation(Vector::new(x, y, 0.05));
        world.add(spec).unwrap()
    }

    #[test]
    fn an_object_in_a_gap_nobody_fits_into_is_out_of_reach() {
        // A bed 2 m long along the room's middle, 0.3 m from the wall at y 4: a package in the
        // gap, 1 m in from the bed's end, is farther than an arm's length from anywhere a
        // person stands; at the gap's mouth, or out in the room, it is not.
        let (mut world, _) = home(3.0, 0.5);
        wall(&mut world, "bed_1", [0.0, 2.2], [2.0, 3.7]);
        let deep = package(&mut world, 1.0, 3.85);
        assert!(!within_reach(&world, deep));
        let (mut world, _) = home(3.0, 0.5);
        wall(&mut world, "bed_1", [0.0, 2.2], [2.0, 3.7]);
        let mouth = package(&mut world, 1.8, 3.85);
        assert!(within_reach(&world, mouth));
        let (mut world, _) = home(3.0, 0.5);
        let open = package(&mut world, 1.0, 1.0);
        assert!(within_reach(&world, open));
    }

    #[test]
    fn an_agent_in_the_open_has_a_way_out_through_the_door() {
        let (world, agent) = home(1.0, 1.0);
        assert!(has_way_out(&world, agent));
    }

    #[test]
    fn an_agent_in_a_corner_closed_round_by_furniture_has_none() {
        // A cabinet and a shower close the corner at (0.5, 3.5), with a gap of 0.4 m between
        // them: narrower than the agent and the room to spare either side.
        let (mut world, agent) = home(0.5, 3.5);
        wall(&mut world, "cabinet_1", [0.0, 2.8], [0.7, 3.0]);
        wall(&mut world, "shower_1", [1.1, 2.8], [1.3, 4.0]);
        assert!(!has_way_out(&world, agent));
        // Wider, the gap lets it out.
        let (mut world, agent) = home(0.5, 3.5);
        wall(&mut world, "cabinet_1", [0.0, 2.8], [0.3, 3.0]);
        wall(&mut world, "shower_1", [1.1, 2.8], [1.3, 4.0]);
        assert!(has_way_out(&world, agent));
    }
}
