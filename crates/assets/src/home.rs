//! Procedural homes: a floor plan, walls with doorways and doors, windows, and furniture per room
//! type, from a seed.
//!
//! The plan is a corridor along x with rooms on both sides, each opening onto it through a
//! doorway (so every room is reachable, and the corridor stays clear for the agent), and a front
//! door at the corridor's west end. Every home has a kitchen, a living room, a bathroom and a
//! bedroom; three more rooms are drawn from the other types. Each room type gets the furniture the
//! official activities look for in it (`inroom` literals), placed against the walls without
//! overlaps and out of the doorways' way; tables stand in the middle with chairs beside them, and
//! the microwave stands on a countertop. An item that does not fit is left out (coverage
//! reports what a home lacks). [`NAMED_HOMES`] are fifteen fixed seeds forming the default set.
//!
//! A dining room, when there is one (the first, when there are several), adjoins the living room
//! with no wall between them: an open
//! plan, as in many homes and in iGibson's scans, where the rooms are told apart by the floor map
//! only. One of the living room's tables stands at that opening, its centre just inside the living
//! room and its far end over the dining room's floor. This is what makes
//! `collect_misplaced_items` possible as written: its shoe lies under a living-room table and on
//! the dining room's floor.

use crate::library::{AssetError, Library};
use crate::scene::{ObjectPlan, RoomPlan, Scene, WALL_HEIGHT, WallPlan};
use behavior_core::RoomType;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};
use std::collections::BTreeMap;

/// The default homes: name and seed.
pub const NAMED_HOMES: [(&str, u64); 15] = [
    ("alder", 101),
    ("birch", 102),
    ("cedar", 103),
    ("dogwood", 104),
    ("elm", 105),
    ("fir", 106),
    ("ginkgo", 107),
    ("hazel", 108),
    ("juniper", 109),
    ("larch", 110),
    ("maple", 111),
    ("oak", 112),
    ("pine", 113),
    ("rowan", 114),
    ("willow", 115),
];

pub const WALL_THICKNESS: f32 = 0.1;
pub const CORRIDOR_WIDTH: f32 = 1.6;
pub const DOORWAY: f32 = 1.0;
/// Kept free in front of a doorway, on both sides (m).
pub const DOOR_CLEARANCE: f32 = 1.1;
/// Between pieces of furniture (m).
const GAP: f32 = 0.05;

/// Room types every home has, and the others it draws from.
const CORE_ROOMS: [RoomType; 4] = [
    RoomType::Kitchen,
    RoomType::LivingRoom,
    RoomType::Bathroom,
    RoomType::Bedroom,
];
const EXTRA_ROOMS: [RoomType; 6] = [
    RoomType::DiningRoom,
    RoomType::Garage,
    RoomType::HomeOffice,
    RoomType::StorageRoom,
    RoomType::UtilityRoom,
    RoomType::Closet,
];

/// Width and depth ranges (m) of a room type.
fn room_size(kind: RoomType) -> ([f32; 2], [f32; 2]) {
    match kind {
        RoomType::Kitchen => ([4.4, 5.4], [4.2, 5.0]),
        RoomType::LivingRoom => ([4.8, 6.0], [4.5, 5.5]),
        RoomType::Bedroom => ([3.8, 4.6], [3.8, 4.6]),
        RoomType::Bathroom => ([3.0, 3.6], [3.2, 3.8]),
        RoomType::DiningRoom => ([3.6, 4.4], [3.6, 4.4]),
        RoomType::Garage => ([5.0, 6.0], [5.0, 6.0]),
        RoomType::HomeOffice => ([3.2, 4.0], [3.2, 4.0]),
        RoomType::StorageRoom => ([2.8, 3.6], [2.8, 3.4]),
        RoomType::UtilityRoom => ([3.0, 3.6], [3.0, 3.4]),
        _ => ([2.4, 3.0], [2.4, 3.0]), // closet
    }
}

/// What stands in a room of each type, biggest first; `table` and `chair` go in the middle.
fn furniture(kind: RoomType) -> &'static [&'static str] {
    match kind {
        RoomType::Kitchen => &[
            "electric_refrigerator.n.01",
            "countertop.n.01",
            "countertop.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "dishwasher.n.01",
            "oven.n.01",
            "stove.n.01",
            "sink.n.01",
            "table.n.02",
            "chair.n.01",
            "microwave.n.02",
        ],
        RoomType::LivingRoom => &[
            "sofa.n.01",
            "shelf.n.01",
            "cabinet.n.01",
            "table.n.02",
            "table.n.02",
        ],
        RoomType::Bedroom => &[
            "bed.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "table.n.02",
        ],
        RoomType::Bathroom => &["bathtub.n.01", "shower.n.01", "toilet.n.02", "sink.n.01"],
        RoomType::DiningRoom => &["table.n.02", "chair.n.01", "chair.n.01"],
        RoomType::Garage => &["shelf.n.01", "cabinet.n.01"],
        RoomType::HomeOffice => &["cabinet.n.01", "table.n.02", "chair.n.01"],
        RoomType::StorageRoom => &["shelf.n.01", "sink.n.01", "table.n.02"],
        RoomType::UtilityRoom => &["washer.n.03", "dryer.n.01", "sink.n.01", "cabinet.n.01"],
        _ => &["shelf.n.01", "cabinet.n.01"], // closet
    }
}

/// How many windows a room type gets on its outer wall.
fn windows(kind: RoomType) -> usize {
    match kind {
        RoomType::LivingRoom => 2,
        RoomType::Kitchen | RoomType::Bedroom | RoomType::DiningRoom | RoomType::HomeOffice => 1,
        _ => 0,
    }
}

fn uniform(rng: &mut ChaCha8Rng, range: [f32; 2]) -> f32 {
    behavior_core::rng::uniform(rng, range[0], range[1])
}

/// An axis-aligned footprint on the floor.
#[derive(Clone, Copy, Debug)]
struct Rect {
    min: [f32; 2],
    max: [f32; 2],
}

impl Rect {
    fn overlaps(&self, other: &Rect, margin: f32) -> bool {
        self.min[0] < other.max[0] + margin
            && other.min[0] < self.max[0] + margin
            && self.min[1] < other.max[1] + margin
            && other.min[1] < self.max[1] + margin
    }
    fn within(&self, other: &Rect) -> bool {
        self.min[0] >= other.min[0]
            && self.min[1] >= other.min[1]
            && self.max[0] <= other.max[0]
            && self.max[1] <= other.max[1]
    }
}

/// Footprint of an object of size (w, d) standing at (x, y) after `turns` quarter turns.
fn footprint(x: f32, y: f32, w: f32, d: f32, turns: u8) -> Rect {
    let (hx, hy) = if turns.is_multiple_of(2) {
        (w / 2.0, d / 2.0)
    } else {
        (d / 2.0, w / 2.0)
    };
    Rect {
        min: [x - hx, y - hy],
        max: [x + hx, y + hy],
    }
}

/// A room being furnished.
struct Furnishing {
    index: usize,
    inner: Rect,
    taken: Vec<Rect>,
}

/// Generates the home of a seed. Named homes pass their name; any other seed makes a new home.
pub fn generate(name: &str, seed: u64, library: &Library) -> Result<Scene, AssetError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // The program: the core rooms and three others. The named homes cycle through the other
    // types so that each appears in several of them.
    let mut kinds: Vec<RoomType> = CORE_ROOMS.to_vec();
    let named = NAMED_HOMES
        .iter()
        .position(|&(n, s)| n == name && s == seed);
    for k in 0..3 {
        let pick = match named {
            Some(i) => EXTRA_ROOMS[(i + 2 * k) % EXTRA_ROOMS.len()],
            None => EXTRA_ROOMS[rng.next_u32() as usize % EXTRA_ROOMS.len()],
        };
        kinds.push(pick);
    }
    // Shuffle the order along the corridor (Fisher–Yates with the home's generator).
    for i in (1..kinds.len()).rev() {
        let j = rng.next_u32() as usize % (i + 1);
        kinds.swap(i, j);
    }
    // The dining room goes beside the living room, on the same side of the corridor.
    if let Some(d) = kinds.iter().position(|&k| k == RoomType::DiningRoom) {
        kinds.remove(d);
        let l = kinds
            .iter()
            .position(|&k| k == RoomType::LivingRoom)
            .expect("a core room");
        if l + 2 <= kinds.len() {
            kinds.insert(l + 2, RoomType::DiningRoom);
        } else {
            kinds.insert(l - 1, RoomType::DiningRoom);
        }
    }
    // Alternate rooms north and south of the corridor, west to east.
    let mut rooms: Vec<RoomPlan> = Vec::new();
    let mut cursor = [0.0f32, 0.0f32];
    let mut counts: BTreeMap<RoomType, u32> = BTreeMap::new();
    let mut doorways: Vec<(usize, f32, f32)> = Vec::new(); // (room, x centre, wall y)
    for (k, kind) in kinds.iter().enumerate() {
        let (wr, dr) = room_size(*kind);
        let (w, d) = (
            (uniform(&mut rng, wr) * 10.0).round() / 10.0,
            (uniform(&mut rng, dr) * 10.0).round() / 10.0,
        );
        let side = k % 2;
        let x0 = cursor[side];
        let (y0, y1) = if side == 0 {
            (CORRIDOR_WIDTH, CORRIDOR_WIDTH + d)
        } else {
            (-d, 0.0)
        };
        let instance = counts.entry(*kind).or_insert(0);
        rooms.push(RoomPlan {
            kind: *kind,
            instance: *instance,
            min: [x0, y0],
            max: [x0 + w, y1],
        });
        *instance += 1;
        cursor[side] += w;
        let door_x =
            x0 + 0.4 + DOORWAY / 2.0 + uniform(&mut rng, [0.0, (w - 0.8 - DOORWAY).max(0.0)]);
        doorways.push((
            rooms.len() - 1,
            door_x,
            if side == 0 { CORRIDOR_WIDTH } else { 0.0 },
        ));
    }
    // Even out the rows' ends, then the corridor runs the whole length.
    let length = cursor[0].max(cursor[1]);
    for side in 0..2 {
        if let Some(last) = rooms
            .iter_mut()
            .enumerate()
            .filter(|(k, _)| k % 2 == side)
            .map(|(_, r)| r)
            .last()
        {
            last.max[0] = length;
        }
    }
    rooms.push(RoomPlan {
        kind: RoomType::Corridor,
        instance: 0,
        min: [0.0, 0.0],
        max: [length, CORRIDOR_WIDTH],
    });
    let corridor = rooms.len() - 1;
    let opening = open_plan(&rooms);

    let walls = build_walls(&rooms, &doorways, corridor, opening.as_ref());

    // Furniture, doors and windows.
    let mut objects: Vec<ObjectPlan> = Vec::new();
    let mut names: BTreeMap<String, u32> = BTreeMap::new();
    let mut next_name = |synset: &str| {
        let lemma = synset.split('.').next().unwrap_or(synset).to_string();
        let n = names.entry(lemma.clone()).or_insert(0);
        *n += 1;
        format!("{lemma}_{}", *n - 1)
    };
    let half = WALL_THICKNESS / 2.0;
    // The table at the opening comes first: both rooms then furnish around it.
    let mut shared_table: Option<Rect> = None;
    if let Some(open) = &opening {
        let (size, variant) = library.sample("table.n.02", &mut rng)?;
        if let Some((position, rect)) = at_the_opening(open, &rooms, &doorways, size) {
            shared_table = Some(rect);
            let name = next_name("table.n.02");
            objects.push(ObjectPlan {
                name,
                synset: "table.n.02".into(),
                room: open.living,
                position,
                yaw_quarter_turns: 0,
                size: size.to_array(),
                variant,
                joints: Vec::new(),
            });
        }
    }
    for index in 0..rooms.len() {
        let room = &rooms[index];
        let inner = Rect {
            min: [room.min[0] + half + 0.02, room.min[1] + half + 0.02],
            max: [room.max[0] - half - 0.02, room.max[1] - half - 0.02],
        };
        let mut f = Furnishing {
            index,
            inner,
            taken: Vec::new(),
        };
        let mut tables_to_skip = 0;
        if let (Some(open), Some(rect)) = (&opening, shared_table) {
            if index == open.living || index == open.dining {
                f.taken.push(rect);
            }
            if index == open.living {
                tables_to_skip = 1; // it is one of the living room's tables
            }
        }
        // Keep every doorway of this room clear, on both sides of its wall.
        for &(r, x, y) in &doorways {
            if r == index || index == corridor {
                f.taken.push(Rect {
                    min: [x - DOORWAY / 2.0 - 0.1, y - DOOR_CLEARANCE],
                    max: [x + DOORWAY / 2.0 + 0.1, y + DOOR_CLEARANCE],
                });
            }
        }
        // The corridor stays clear except for the front door.
        if index == corridor {
            let y = CORRIDOR_WIDTH / 2.0;
            let plan = place_door(
                library,
                &mut rng,
                next_name("door.n.01"),
                index,
                [0.0 + half + 0.15, y],
                3,
            )?;
            objects.push(plan);
            continue;
        }
        let (_, door_x, door_y) = doorways[index];
        // The door stands just inside its room and its leaf swings into the room (a door's
        // front is its −y side), so an open door still stands in its room.
        let inward = if door_y > room.min[1] { -0.15 } else { 0.15 };
        let turns = if door_y > room.min[1] { 0 } else { 2 };
        objects.push(place_door(
            library,
            &mut rng,
            next_name("door.n.01"),
            index,
            [door_x, door_y + inward],
            turns,
        )?);
        // Windows on the outer wall (the one away from the corridor).
        let outer_y = if door_y > room.min[1] {
            room.min[1]
        } else {
            room.max[1]
        };
        for k in 0..windows(room.kind) {
            let (size, variant) = library.sample("window.n.01", &mut rng)?;
            let x = room.min[0]
                + (k as f32 + 1.0) * (room.max[0] - room.min[0])
                    / (windows(room.kind) as f32 + 1.0);
            let y = if outer_y < door_y {
                outer_y + half + 0.05
            } else {
                outer_y - half - 0.05
            };
            // Its casement opens into the room too; a floor-length one (variant 1) sweeps the
            // floor in front of it, which is kept clear.
            let turns = if outer_y < door_y { 2 } else { 0 };
            let sweep = if variant == 1 { size.x } else { 0.0 };
            let inward = if outer_y < door_y { 1.0 } else { -1.0 };
            f.taken.push(footprint(
                x,
                y + inward * sweep / 2.0,
                size.x,
                0.12 + sweep,
                0,
            ));
            objects.push(ObjectPlan {
                name: next_name("window.n.01"),
                synset: "window.n.01".into(),
                room: index,
                position: [x, y, 0.0],
                yaw_quarter_turns: turns,
                size: size.to_array(),
                variant,
                joints: vec![0.0],
            });
        }
        for synset in furniture(room.kind) {
            if *synset == "table.n.02" && tables_to_skip > 0 {
                tables_to_skip -= 1;
                continue;
            }
            let (size, variant) = library.sample(synset, &mut rng)?;
            let plan = match *synset {
                "microwave.n.02" => on_countertop(&objects, index, size),
                "table.n.02" | "chair.n.01" => in_the_middle(&mut f, size, synset == &"chair.n.01"),
                _ => against_a_wall(&mut f, size, &mut rng),
            };
            if let Some((position, turns)) = plan {
                let name = next_name(synset);
                let links = library.instance(synset, &name, size, variant)?.links.len();
                objects.push(ObjectPlan {
                    name,
                    synset: synset.to_string(),
                    room: f.index,
                    position,
                    yaw_quarter_turns: turns,
                    size: size.to_array(),
                    variant,
                    joints: vec![0.0; links],
                });
            }
        }
    }
    Ok(Scene {
        name: name.to_string(),
        seed,
        rooms,
        walls,
        objects,
    })
}

fn place_door(
    library: &Library,
    rng: &mut ChaCha8Rng,
    name: String,
    room: usize,
    at: [f32; 2],
    turns: u8,
) -> Result<ObjectPlan, AssetError> {
    let (mut size, variant) = library.sample("door.n.01", rng)?;
    size.x = size.x.min(DOORWAY - 0.05);
    Ok(ObjectPlan {
        name,
        synset: "door.n.01".into(),
        room,
        position: [at[0], at[1], 0.0],
        yaw_quarter_turns: turns,
        size: size.to_array(),
        variant,
        joints: vec![0.0],
    })
}

/// Stands the microwave on the room's first countertop.
fn on_countertop(
    objects: &[ObjectPlan],
    room: usize,
    size: rapier3d::math::Vector,
) -> Option<([f32; 3], u8)> {
    let counter = objects
        .iter()
        .find(|o| o.room == room && o.synset == "countertop.n.01")?;
    let fits = size.x <= counter.size[0] && size.y <= counter.size[1];
    fits.then(|| {
        let [x, y, z] = counter.position;
        (
            [x, y, z + counter.size[2] + 0.002],
            counter.yaw_quarter_turns,
        )
    })
}

/// Backs an item against a wall, facing into the room, at the first free spot from a random
/// starting wall.
fn against_a_wall(
    f: &mut Furnishing,
    size: rapier3d::math::Vector,
    rng: &mut ChaCha8Rng,
) -> Option<([f32; 3], u8)> {
    let r = f.inner;
    let start = rng.next_u32() as usize % 4;
    for k in 0..4 {
        // Walls: north (front faces −y, 0 turns), east (faces −x, 3), south (+y, 2), west (+x, 1).
        let wall = (start + k) % 4;
        let turns: u8 = [0, 3, 2, 1][wall];
        let (along_lo, along_hi) = if wall.is_multiple_of(2) {
            (r.min[0], r.max[0])
        } else {
            (r.min[1], r.max[1])
        };
        let (w, d) = (size.x, size.y);
        let mut t = along_lo + w / 2.0;
        while t + w / 2.0 <= along_hi {
            let (x, y) = match wall {
                0 => (t, r.max[1] - d / 2.0),
                1 => (r.max[0] - d / 2.0, t),
                2 => (t, r.min[1] + d / 2.0),
                _ => (r.min[0] + d / 2.0, t),
            };
            let rect = footprint(x, y, w, d, turns);
            if rect.within(&r) && f.taken.iter().all(|o| !rect.overlaps(o, GAP)) {
                f.taken.push(rect);
                return Some(([x, y, 0.0], turns));
            }
            t += 0.1;
        }
    }
    None
}

/// Puts a table near the room's middle, or a chair beside the room's last table.
fn in_the_middle(
    f: &mut Furnishing,
    size: rapier3d::math::Vector,
    chair: bool,
) -> Option<([f32; 3], u8)> {
    let r = f.inner;
    let center = [(r.min[0] + r.max[0]) / 2.0, (r.min[1] + r.max[1]) / 2.0];
    let mut candidates: Vec<([f32; 2], u8)> = Vec::new();
    if chair {
        // Around the most recent table-sized footprint (the last one placed in the middle).
        if let Some(table) = f
            .taken
            .iter()
            .rev()
            .find(|t| t.max[0] - t.min[0] > 0.5 && t.max[1] - t.min[1] > 0.5)
        {
            let (cx, cy) = (
                (table.min[0] + table.max[0]) / 2.0,
                (table.min[1] + table.max[1]) / 2.0,
            );
            // Beyond the 0.3 m kept around every middle piece, so the chair is accepted.
            let off = size.y / 2.0 + 0.32;
            candidates.push(([cx, table.min[1] - off], 2));
            candidates.push(([cx, table.max[1] + off], 0));
            candidates.push(([table.min[0] - off, cy], 1));
            candidates.push(([table.max[0] + off, cy], 3));
        }
    }
    for ring in 0..12 {
        let step = 0.25 * ring as f32;
        for (dx, dy) in [
            (0.0, 0.0),
            (step, 0.0),
            (-step, 0.0),
            (0.0, step),
            (0.0, -step),
            (step, step),
            (-step, -step),
        ] {
            candidates.push(([center[0] + dx, center[1] + dy], 0));
        }
    }
    for ([x, y], turns) in candidates {
        let rect = footprint(x, y, size.x, size.y, turns);
        if rect.within(&r) && f.taken.iter().all(|o| !rect.overlaps(o, 0.3)) {
            f.taken.push(rect);
            return Some(([x, y, 0.0], turns));
        }
    }
    None
}

/// Where the living room opens onto the dining room: the rooms and their shared edge.
struct Opening {
    living: usize,
    dining: usize,
    /// The x of the shared edge.
    x: f32,
    /// The shared span along y.
    y: [f32; 2],
    /// +1 when the dining room lies east of the living room, −1 when west.
    toward_dining: f32,
}

/// The opening between the living room and a dining room beside it (the first, if a home drawn
/// from a free seed has several), if the home has both.
fn open_plan(rooms: &[RoomPlan]) -> Option<Opening> {
    let living = rooms.iter().position(|r| r.kind == RoomType::LivingRoom)?;
    let l = &rooms[living];
    rooms.iter().enumerate().find_map(|(dining, d)| {
        if d.kind != RoomType::DiningRoom {
            return None;
        }
        let (x, toward_dining) = if (l.max[0] - d.min[0]).abs() < 1e-4 {
            (l.max[0], 1.0)
        } else if (l.min[0] - d.max[0]).abs() < 1e-4 {
            (l.min[0], -1.0)
        } else {
            return None;
        };
        let y = [l.min[1].max(d.min[1]), l.max[1].min(d.max[1])];
        (y[1] - y[0] > 1.0).then_some(Opening {
            living,
            dining,
            x,
            y,
            toward_dining,
        })
    })
}

/// A table across the opening, long side along x, its centre 0.15 m inside the living room, clear
/// of both rooms' doorways and the walls; its position and footprint.
fn at_the_opening(
    open: &Opening,
    rooms: &[RoomPlan],
    doorways: &[(usize, f32, f32)],
    size: rapier3d::math::Vector,
) -> Option<([f32; 3], Rect)> {
    let x = open.x - open.toward_dining * 0.15;
    let half = WALL_THICKNESS / 2.0 + 0.3;
    let clear: Vec<Rect> = doorways
        .iter()
        .filter(|&&(r, _, _)| r == open.living || r == open.dining)
        .map(|&(_, dx, dy)| Rect {
            min: [dx - DOORWAY / 2.0 - 0.1, dy - DOOR_CLEARANCE],
            max: [dx + DOORWAY / 2.0 + 0.1, dy + DOOR_CLEARANCE],
        })
        .collect();
    let (l, d) = (&rooms[open.living], &rooms[open.dining]);
    let (west, east) = (l.min[0].min(d.min[0]), l.max[0].max(d.max[0]));
    let mid = (open.y[0] + open.y[1]) / 2.0;
    // From the middle of the opening outwards, in 10 cm steps.
    (0..40)
        .map(|k| mid + 0.1 * (k / 2) as f32 * if k % 2 == 0 { 1.0 } else { -1.0 })
        .map(|y| footprint(x, y, size.x, size.y, 0))
        .find(|rect| {
            rect.min[1] >= open.y[0] + half
                && rect.max[1] <= open.y[1] - half
                && clear.iter().all(|c| !rect.overlaps(c, GAP))
                && rect.min[0] > west + half
                && rect.max[0] < east - half
        })
        .map(|rect| {
            let y = (rect.min[1] + rect.max[1]) / 2.0;
            ([x, y, 0.0], rect)
        })
}

/// Walls along every room edge, merged where rooms meet, with the doorways and the open plan's
/// opening cut out.
fn build_walls(
    rooms: &[RoomPlan],
    doorways: &[(usize, f32, f32)],
    corridor: usize,
    opening: Option<&Opening>,
) -> Vec<WallPlan> {
    // Lines keyed by (vertical?, coordinate in mm) → intervals along them.
    let mut lines: BTreeMap<(bool, i64), Vec<[f32; 2]>> = BTreeMap::new();
    let key = |x: f32| (x * 1000.0).round() as i64;
    for r in rooms {
        lines
            .entry((false, key(r.min[1])))
            .or_default()
            .push([r.min[0], r.max[0]]);
        lines
            .entry((false, key(r.max[1])))
            .or_default()
            .push([r.min[0], r.max[0]]);
        lines
            .entry((true, key(r.min[0])))
            .or_default()
            .push([r.min[1], r.max[1]]);
        lines
            .entry((true, key(r.max[0])))
            .or_default()
            .push([r.min[1], r.max[1]]);
    }
    let mut gaps: Vec<(bool, i64, [f32; 2])> = doorways
        .iter()
        .map(|&(_, x, y)| (false, key(y), [x - DOORWAY / 2.0, x + DOORWAY / 2.0]))
        .collect();
    // The front door, at the corridor's west end.
    let c = &rooms[corridor];
    gaps.push((
        true,
        key(c.min[0]),
        [
            CORRIDOR_WIDTH / 2.0 - DOORWAY / 2.0,
            CORRIDOR_WIDTH / 2.0 + DOORWAY / 2.0,
        ],
    ));
    if let Some(open) = opening {
        gaps.push((true, key(open.x), open.y));
    }
    let half = WALL_THICKNESS / 2.0;
    let mut walls = Vec::new();
    for ((vertical, at), mut spans) in lines {
        spans.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut merged: Vec<[f32; 2]> = Vec::new();
        for s in spans {
            match merged.last_mut() {
                Some(last) if s[0] <= last[1] + 1e-4 => last[1] = last[1].max(s[1]),
                _ => merged.push(s),
            }
        }
        // Cut the doorways out.
        let mut pieces = merged;
        for &(_, _, gap) in gaps.iter().filter(|g| g.0 == vertical && g.1 == at) {
            pieces = pieces
                .into_iter()
                .flat_map(|[a, b]| {
                    let mut out = Vec::new();
                    if gap[0] > a {
                        out.push([a, gap[0].min(b)]);
                    }
                    if gap[1] < b {
                        out.push([gap[1].max(a), b]);
                    }
                    out
                })
                .filter(|[a, b]| b - a > 0.01)
                .collect();
        }
        let coordinate = at as f32 / 1000.0;
        for [a, b] in pieces {
            let (min, max) = if vertical {
                (
                    [coordinate - half, a - half, 0.0],
                    [coordinate + half, b + half, WALL_HEIGHT],
                )
            } else {
                (
                    [a - half, coordinate - half, 0.0],
                    [b + half, coordinate + half, WALL_HEIGHT],
                )
            };
            walls.push(WallPlan { min, max });
        }
    }
    walls
}
