//! The floor plan: which rooms a home has, in which order along the corridor, how large, where
//! each room's doorway is, and where the living room opens onto a dining room.

use super::footprint::Rect;
use super::{CORRIDOR_WIDTH, DOOR_CLEARANCE, DOORWAY, NAMED_HOMES};
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

/// A home's rooms and their openings: everything walls and furnishing are laid out from.
pub(super) struct Plan {
    /// The rooms along the corridor, west to east and alternating sides, then the corridor.
    pub(super) rooms: Vec<RoomPlan>,
    /// One per room along the corridor, in `rooms` order.
    pub(super) doorways: Vec<Doorway>,
    /// The corridor's index in `rooms` (the last).
    pub(super) corridor: usize,
    /// Where the living room opens onto a dining room, if the home has one beside it.
    pub(super) opening: Option<Opening>,
}

/// A room's doorway onto the corridor.
#[derive(Clone, Copy, Debug)]
pub(super) struct Doorway {
    /// The room's index in `rooms`.
    pub(super) room: usize,
    /// The x of the doorway's centre.
    pub(super) x: f32,
    /// The y of the wall it cuts (a side of the corridor).
    pub(super) y: f32,
}

impl Doorway {
    /// The floor kept free in front of the doorway, on both sides of its wall.
    pub(super) fn clearance(&self) -> Rect {
        Rect {
            min: [self.x - DOORWAY / 2.0 - 0.1, self.y - DOOR_CLEARANCE],
            max: [self.x + DOORWAY / 2.0 + 0.1, self.y + DOOR_CLEARANCE],
        }
    }
}

/// Where the living room opens onto the dining room: the rooms and their shared edge.
pub(super) struct Opening {
    pub(super) living: usize,
    pub(super) dining: usize,
    /// The x of the shared edge.
    pub(super) x: f32,
    /// The shared span along y.
    pub(super) y: [f32; 2],
    /// +1 when the dining room lies east of the living room, −1 when west.
    pub(super) toward_dining: f32,
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
pub(super) fn program(name: &str, seed: u64, rng: &mut ChaCha8Rng) -> Vec<RoomType> {
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

/// Lays the rooms out along the corridor: sizes drawn per type, rows evened out at the east end,
/// the corridor the whole length, and the open plan found.
pub(super) fn lay_out(kinds: &[RoomType], rng: &mut ChaCha8Rng) -> Plan {
    let (mut rooms, doorways, length) = rows(kinds, rng);
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
    let opening = open_plan(&rooms);
    Plan {
        corridor: rooms.len() - 1,
        rooms,
        doorways,
        opening,
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
