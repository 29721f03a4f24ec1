//! The corridor plan the named homes were generated with before plan families existed: one
//! corridor along x with every room off it, alternating north and south, a door from each room,
//! the front door at the corridor's west end, windows on each room's wall away from the corridor,
//! and a dining room beside the living room open onto it. Kept, draw for draw, so that the named
//! homes stay what they were until they are regenerated from the families (issue 40).

use super::plan::{Door, Opening, Plan, Segment, WindowWall};
use super::{CORRIDOR_WIDTH, DOORWAY, NAMED_HOMES, WALL_THICKNESS};
use crate::scene::RoomPlan;
use behavior_core::RoomType;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use std::collections::BTreeMap;

/// Room types every home has.
const CORE_ROOMS: [RoomType; 4] = [
    RoomType::Kitchen,
    RoomType::LivingRoom,
    RoomType::Bathroom,
    RoomType::Bedroom,
];

/// Room types the three other rooms are drawn from.
const EXTRA_ROOMS: [RoomType; 6] = [
    RoomType::DiningRoom,
    RoomType::Garage,
    RoomType::HomeOffice,
    RoomType::StorageRoom,
    RoomType::UtilityRoom,
    RoomType::Closet,
];

/// A room's doorway onto the corridor: the room, the x of its centre, the y of the wall it cuts.
struct Doorway {
    room: usize,
    x: f32,
    y: f32,
}

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

fn uniform(rng: &mut ChaCha8Rng, range: [f32; 2]) -> f32 {
    behavior_core::rng::uniform(rng, range[0], range[1])
}

/// The program: the core rooms and three others, in their order along the corridor. The named
/// homes cycle through the other types so that each appears in several of them; the dining
/// room goes beside the living room, on the same side of the corridor.
fn program(name: &str, seed: u64, rng: &mut ChaCha8Rng) -> Vec<RoomType> {
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
    if let Some(d) = kinds.iter().position(|&k| k == RoomType::DiningRoom) {
        kinds.remove(d);
        let l = kinds
            .iter()
            .position(|&k| k == RoomType::LivingRoom)
            .expect("a core room");
        // Two places on is the next room on the same side.
        if l + 2 <= kinds.len() {
            kinds.insert(l + 2, RoomType::DiningRoom);
        } else {
            kinds.insert(l - 1, RoomType::DiningRoom);
        }
    }
    kinds
}

/// The plan of a named home: the program laid out along the corridor, the open plan found, the
/// doors and the windows.
pub(super) fn plan(name: &str, seed: u64, rng: &mut ChaCha8Rng) -> Plan {
    let kinds = program(name, seed, rng);
    let (mut rooms, doorways, length) = rows(&kinds, rng);
    // Even out the rows' ends, then the corridor runs the whole length.
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
    let mut doors: Vec<Door> = doorways
        .iter()
        .map(|d| {
            let line = Segment {
                vertical: false,
                at: d.y,
                span: [rooms[d.room].min[0], rooms[d.room].max[0]],
            };
            Door::into(d.room, Some(corridor), line, d.x, &rooms[d.room])
        })
        .collect();
    doors.push(front_door(corridor));
    let windows = window_walls(&rooms, &doorways);
    let openings = open_plan(&rooms).into_iter().collect();
    Plan {
        rooms,
        doors,
        openings,
        windows,
        keep_paths: false,
    }
}

/// The front door at the corridor's west end, standing just inside it and facing out.
fn front_door(corridor: usize) -> Door {
    let middle = CORRIDOR_WIDTH / 2.0;
    Door {
        room: corridor,
        other: None,
        gap: Segment {
            vertical: true,
            at: 0.0,
            span: [middle - DOORWAY / 2.0, middle + DOORWAY / 2.0],
        },
        leaf: ([WALL_THICKNESS / 2.0 + 0.15, middle], 3),
    }
}

/// Each room's wall away from the corridor, with as many windows as its type gets.
fn window_walls(rooms: &[RoomPlan], doorways: &[Doorway]) -> Vec<WindowWall> {
    doorways
        .iter()
        .map(|d| {
            let room = &rooms[d.room];
            let outer = if d.y > room.min[1] {
                room.min[1]
            } else {
                room.max[1]
            };
            WindowWall {
                room: d.room,
                wall: Segment {
                    vertical: false,
                    at: outer,
                    span: [room.min[0], room.max[0]],
                },
                count: windows(room.kind),
            }
        })
        .collect()
}

/// How many windows a room type gets on its outer wall.
fn windows(kind: RoomType) -> usize {
    match kind {
        RoomType::LivingRoom => 2,
        RoomType::Kitchen | RoomType::Bedroom | RoomType::DiningRoom | RoomType::HomeOffice => 1,
        _ => 0,
    }
}

/// Alternates rooms north (even places) and south (odd) of the corridor, west to east, each
/// with a doorway at a random place along its corridor wall; the rooms, their doorways and the
/// longer row's length.
fn rows(kinds: &[RoomType], rng: &mut ChaCha8Rng) -> (Vec<RoomPlan>, Vec<Doorway>, f32) {
    let mut rooms: Vec<RoomPlan> = Vec::new();
    let mut cursor = [0.0f32, 0.0f32];
    let mut counts: BTreeMap<RoomType, u32> = BTreeMap::new();
    let mut doorways = Vec::new();
    for (k, kind) in kinds.iter().enumerate() {
        let (wr, dr) = room_size(*kind);
        let (w, d) = (
            (uniform(rng, wr) * 10.0).round() / 10.0,
            (uniform(rng, dr) * 10.0).round() / 10.0,
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
        let door_x = x0 + 0.4 + DOORWAY / 2.0 + uniform(rng, [0.0, (w - 0.8 - DOORWAY).max(0.0)]);
        doorways.push(Doorway {
            room: rooms.len() - 1,
            x: door_x,
            y: if side == 0 { CORRIDOR_WIDTH } else { 0.0 },
        });
    }
    (rooms, doorways, cursor[0].max(cursor[1]))
}

/// The opening between the living room and a dining room beside it (the first, if a home drawn
/// from a free seed has several), if the home has both and they share more than a metre of wall.
fn open_plan(rooms: &[RoomPlan]) -> Option<Opening> {
    let living = rooms.iter().position(|r| r.kind == RoomType::LivingRoom)?;
    let l = &rooms[living];
    rooms.iter().enumerate().find_map(|(dining, d)| {
        if d.kind != RoomType::DiningRoom {
            return None;
        }
        let x = if (l.max[0] - d.min[0]).abs() < 1e-4 {
            l.max[0]
        } else if (l.min[0] - d.max[0]).abs() < 1e-4 {
            l.min[0]
        } else {
            return None;
        };
        let y = [l.min[1].max(d.min[1]), l.max[1].min(d.max[1])];
        (y[1] - y[0] > 1.0).then_some(Opening {
            rooms: [living, dining],
            gap: Segment {
                vertical: true,
                at: x,
                span: y,
            },
            keep_clear: false,
        })
    })
}
