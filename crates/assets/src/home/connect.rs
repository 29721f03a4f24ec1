//! Joining the rooms of a layout: wide openings between the public rooms, a door from each room
//! to the room a person would expect it off (a bathroom off a hall or a bedroom, a garage off the
//! utility room or the kitchen), a repair that adds doors until every room is reached from the
//! front door, the front door and the other outside doors, and windows on outside walls only,
//! as many as the room's type and its outside walls allow.

use super::DOORWAY;
use super::layout::Layout;
use super::lshape::Annex;
use super::plan::{Door, Opening, Plan, Segment, WindowWall};
use super::program::{Family, chance};
use crate::scene::RoomPlan;
use behavior_core::RoomType;
use behavior_core::rng::uniform;
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;

/// The least length of shared wall that takes a door, m: the doorway and 35 cm on each side.
const DOOR_WALL: f32 = DOORWAY + 0.7;
/// The least length of outside wall that takes a door, m: the doorway and 25 cm on each side
/// (a hall's end, as the corridor of the named homes has its front door).
const OUTER_DOOR_WALL: f32 = DOORWAY + 0.5;
/// The least length of shared wall that is opened up between public rooms, m.
const OPENING_WALL: f32 = 2.0;
/// The shortest hall end that is opened onto a public room, m.
const HALL_END: f32 = 1.2;
/// The length of outside wall a window needs, m.
const WINDOW_WALL: f32 = 1.7;

/// A stretch of wall two rooms share.
#[derive(Clone, Copy, Debug)]
struct Shared {
    rooms: [usize; 2],
    wall: Segment,
}

/// The rooms `a` and `b` touch along, if they share a stretch of wall.
fn shared(a: &RoomPlan, b: &RoomPlan) -> Option<Segment> {
    let same = |p: f32, q: f32| (p - q).abs() < 1e-3;
    for vertical in [true, false] {
        let (across, along) = if vertical { (0, 1) } else { (1, 0) };
        let at = if same(a.max[across], b.min[across]) {
            a.max[across]
        } else if same(a.min[across], b.max[across]) {
            a.min[across]
        } else {
            continue;
        };
        let span = [
            a.min[along].max(b.min[along]),
            a.max[along].min(b.max[along]),
        ];
        if span[1] - span[0] > 1e-3 {
            return Some(Segment { vertical, at, span });
        }
    }
    None
}

/// The rooms a room of `kind` opens off, most expected first.
fn parents(kind: RoomType) -> &'static [RoomType] {
    use RoomType::*;
    match kind {
        Kitchen => &[DiningRoom, LivingRoom, Corridor],
        DiningRoom => &[LivingRoom, Kitchen, Corridor],
        LivingRoom => &[Corridor, DiningRoom, Kitchen],
        Bedroom => &[Corridor, LivingRoom, DiningRoom],
        Bathroom => &[Corridor, Bedroom, LivingRoom],
        HomeOffice => &[Corridor, LivingRoom, DiningRoom, Bedroom],
        Closet => &[Bedroom, Corridor, LivingRoom],
        StorageRoom => &[Garage, UtilityRoom, Corridor, Kitchen],
        UtilityRoom => &[Kitchen, Corridor, Garage, DiningRoom],
        Garage => &[UtilityRoom, Kitchen, Corridor, StorageRoom],
        Corridor => &[LivingRoom, DiningRoom, Kitchen, Corridor],
    }
}

/// Whether two rooms of these types sharing `wall` are opened up to each other in this family:
/// public rooms along a wall of at least [`OPENING_WALL`], and a hall whose end meets a public
/// room (an archway as wide as the hall).
fn open_to_each_other(family: Family, a: RoomType, b: RoomType, wall: Segment) -> bool {
    use RoomType::*;
    let public = |k: RoomType| matches!(k, LivingRoom | DiningRoom | Kitchen);
    let long = wall.length() >= OPENING_WALL;
    match (a.min(b), a.max(b)) {
        (LivingRoom, DiningRoom) | (Kitchen, DiningRoom) => long,
        (Kitchen, LivingRoom) => long && matches!(family, Family::Studio | Family::OpenPlan),
        (x, Corridor) if public(x) => (HALL_END..OPENING_WALL).contains(&wall.length()),
        _ => false,
    }
}

/// How many windows a room of `kind` wants.
fn windows_wanted(kind: RoomType) -> usize {
    match kind {
        RoomType::LivingRoom => 3,
        RoomType::Kitchen | RoomType::Bedroom | RoomType::DiningRoom => 2,
        RoomType::HomeOffice | RoomType::Bathroom | RoomType::Garage => 1,
        _ => 0,
    }
}

/// The rooms of a layout, numbered per type.
pub(super) fn rooms(layout: &Layout) -> Vec<RoomPlan> {
    let mut counts: BTreeMap<RoomType, u32> = BTreeMap::new();
    layout
        .iter()
        .map(|(kind, r)| {
            let n = counts.entry(*kind).or_insert(0);
            *n += 1;
            RoomPlan::new(*kind, *n - 1, r.min, r.max)
        })
        .collect()
}

/// The plan of a laid-out home: its openings, doors and windows; `None` if some room cannot be
/// reached from the front door (the caller draws again). Each annex opens onto its room along
/// their whole shared side.
pub(super) fn connect(
    family: Family,
    rooms: Vec<RoomPlan>,
    annexes: Vec<Annex>,
    rng: &mut ChaCha8Rng,
) -> Option<Plan> {
    let one_room = |s: &Shared| {
        annexes
            .iter()
            .any(|a| s.rooms.contains(&a.part) && s.rooms.contains(&a.main))
    };
    let mut walls = Vec::new();
    for i in 0..rooms.len() {
        for j in i + 1..rooms.len() {
            if let Some(wall) = shared(&rooms[i], &rooms[j]) {
                walls.push(Shared {
                    rooms: [i, j],
                    wall,
                });
            }
        }
    }
    let mut openings = Vec::new();
    for s in &walls {
        let [a, b] = s.rooms.map(|r| rooms[r].kind);
        let inner = one_room(s);
        if inner || open_to_each_other(family, a, b, s.wall) {
            openings.push(Opening {
                rooms: s.rooms,
                gap: s.wall,
                inner,
            });
        }
    }
    let mut doors = Vec::new();
    let outside = outside_walls(&rooms);
    let entry = entry(family, &rooms, &outside)?;
    doors.push(outer_door(entry, &rooms, &outside, rng)?);
    inner_doors(&rooms, &annexes, &walls, &openings, &mut doors, rng);
    repair(&rooms, &walls, &openings, &mut doors, rng)?;
    // A garage's door, a back door at a hall's end, and half the time one from the kitchen.
    for extra in [RoomType::Garage, RoomType::Kitchen, RoomType::Corridor] {
        let Some(room) = rooms.iter().position(|r| r.kind == extra) else {
            continue;
        };
        if room != entry && (extra != RoomType::Kitchen || chance(rng, 0.5)) {
            doors.extend(outer_door(room, &rooms, &outside, rng));
        }
    }
    let windows = window_walls(&rooms, &annexes, &outside, &doors);
    Some(Plan {
        rooms,
        annexes,
        doors,
        openings,
        windows,
    })
}

/// Each room's stretches of outside wall: its edges less what other rooms share of them.
fn outside_walls(rooms: &[RoomPlan]) -> Vec<Vec<Segment>> {
    rooms
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let edges = [
                Segment {
                    vertical: false,
                    at: r.min[1],
                    span: [r.min[0], r.max[0]],
                },
                Segment {
                    vertical: true,
                    at: r.max[0],
                    span: [r.min[1], r.max[1]],
                },
                Segment {
                    vertical: false,
                    at: r.max[1],
                    span: [r.min[0], r.max[0]],
                },
                Segment {
                    vertical: true,
                    at: r.min[0],
                    span: [r.min[1], r.max[1]],
                },
            ];
            let mut out = Vec::new();
            for edge in edges {
                let mut pieces = vec![edge.span];
                for (j, other) in rooms.iter().enumerate() {
                    if j == i {
                        continue;
                    }
                    if let Some(s) = shared(r, other)
                        .filter(|s| s.vertical == edge.vertical && (s.at - edge.at).abs() < 1e-3)
                    {
                        pieces = pieces
                            .into_iter()
                            .flat_map(|[a, b]| [[a, b.min(s.span[0])], [a.max(s.span[1]), b]])
                            .filter(|[a, b]| b - a > 0.05)
                            .collect();
                    }
                }
                out.extend(pieces.into_iter().map(|span| Segment { span, ..edge }));
            }
            out
        })
        .collect()
}

/// The room the front door opens into: in the families built round a hall, the hall, else the
/// living room, else any room with an outside wall long enough.
fn entry(family: Family, rooms: &[RoomPlan], outside: &[Vec<Segment>]) -> Option<usize> {
    let has_door_wall = |i: usize| outside[i].iter().any(|s| s.length() >= OUTER_DOOR_WALL);
    let first =
        |kind: RoomType| (0..rooms.len()).find(|&i| rooms[i].kind == kind && has_door_wall(i));
    let hall = matches!(family, Family::Corridor | Family::CentralHall);
    hall.then(|| first(RoomType::Corridor))
        .flatten()
        .or_else(|| first(RoomType::LivingRoom))
        .or_else(|| (0..rooms.len()).find(|&i| has_door_wall(i)))
}

/// A door from `room` to the outside, on its longest outside wall facing south if it has one
/// long enough, else on its longest.
fn outer_door(
    room: usize,
    rooms: &[RoomPlan],
    outside: &[Vec<Segment>],
    rng: &mut ChaCha8Rng,
) -> Option<Door> {
    let r = &rooms[room];
    let walls = outside[room]
        .iter()
        .filter(|s| s.length() >= OUTER_DOOR_WALL);
    let south = |s: &&Segment| !s.vertical && (s.at - r.min[1]).abs() < 1e-3;
    let longest = |a: &&Segment, b: &&Segment| a.length().total_cmp(&b.length());
    let wall = walls
        .clone()
        .filter(south)
        .max_by(longest)
        .or_else(|| walls.max_by(longest))?;
    Some(door_in(room, None, *wall, OUTER_DOOR_WALL, rng))
}

/// A door in `room` somewhere along `wall` (at least `needs` long), clear of its ends.
fn door_in(
    room: usize,
    other: Option<usize>,
    wall: Segment,
    needs: f32,
    rng: &mut ChaCha8Rng,
) -> Door {
    let margin = needs / 2.0;
    let t = uniform(rng, wall.span[0] + margin, wall.span[1] - margin);
    let t = (t * 20.0).round() / 20.0;
    Door {
        room,
        other,
        line: wall,
        t,
    }
}

/// The door between `room` and `other`, belonging to whichever is not a hall, so that its leaf
/// swings into a room and never across a hall.
fn inner_door(
    room: usize,
    other: usize,
    wall: Segment,
    rooms: &[RoomPlan],
    rng: &mut ChaCha8Rng,
) -> Door {
    let (owner, beyond) = if rooms[room].kind == RoomType::Corridor {
        (other, room)
    } else {
        (room, other)
    };
    door_in(owner, Some(beyond), wall, DOOR_WALL, rng)
}

/// Whether `a` and `b` are joined by a door or an opening.
fn joined(a: usize, b: usize, doors: &[Door], openings: &[Opening]) -> bool {
    doors.iter().any(|d| d.touches(a) && d.touches(b))
        || openings
            .iter()
            .any(|o| o.rooms.contains(&a) && o.rooms.contains(&b))
}

/// A door from each room not yet opened onto anything to the room it is most expected off, with
/// a wall long enough between them; a bathroom beside a bedroom with no bathroom of its own goes
/// off that bedroom half the time (an en suite).
fn inner_doors(
    rooms: &[RoomPlan],
    annexes: &[Annex],
    walls: &[Shared],
    openings: &[Opening],
    doors: &mut Vec<Door>,
    rng: &mut ChaCha8Rng,
) {
    for (room, r) in rooms.iter().enumerate() {
        let open = openings.iter().any(|o| !o.inner && o.rooms.contains(&room));
        if open && r.kind != RoomType::Corridor {
            continue; // an open public room is reached through its neighbour
        }
        if annexes.iter().any(|a| a.part == room) {
            continue; // an annex is reached through its room
        }
        let mut choices: Vec<(usize, usize, Segment)> = walls
            .iter()
            .filter(|s| s.rooms.contains(&room) && s.wall.length() >= DOOR_WALL)
            .filter_map(|s| {
                let other = if s.rooms[0] == room {
                    s.rooms[1]
                } else {
                    s.rooms[0]
                };
                let rank = parents(r.kind)
                    .iter()
                    .position(|&k| k == rooms[other].kind)?;
                Some((rank, other, s.wall))
            })
            .collect();
        choices.sort_by_key(|c| c.0);
        if r.kind == RoomType::Bathroom {
            let suite = choices.iter().position(|&(_, other, _)| {
                rooms[other].kind == RoomType::Bedroom
                    && !doors
                        .iter()
                        .any(|d| d.touches(other) && rooms[d.room].kind == RoomType::Bathroom)
            });
            if let Some(k) = suite.filter(|_| chance(rng, 0.5)) {
                let pick = choices.remove(k);
                choices.insert(0, pick);
            }
        }
        if let Some(&(_, other, wall)) = choices.first()
            && !joined(room, other, doors, openings)
        {
            doors.push(inner_door(room, other, wall, rooms, rng));
        }
    }
}

/// The rooms reached from the front door's room through doors and openings.
fn reached(rooms: usize, doors: &[Door], openings: &[Opening]) -> Vec<bool> {
    let mut seen = vec![false; rooms];
    let Some(start) = doors.iter().find(|d| d.other.is_none()).map(|d| d.room) else {
        return seen;
    };
    seen[start] = true;
    let mut queue = vec![start];
    while let Some(a) = queue.pop() {
        for (b, seen) in seen.iter_mut().enumerate() {
            if !*seen && joined(a, b, doors, openings) {
                *seen = true;
                queue.push(b);
            }
        }
    }
    seen
}

/// Adds doors until every room is reached from the front door: each time, from a room not
/// reached into a reached neighbour, a hall first, then the room it is most expected off. `None`
/// if some room shares no wall long enough with any reached room.
fn repair(
    rooms: &[RoomPlan],
    walls: &[Shared],
    openings: &[Opening],
    doors: &mut Vec<Door>,
    rng: &mut ChaCha8Rng,
) -> Option<()> {
    loop {
        let seen = reached(rooms.len(), doors, openings);
        if seen.iter().all(|&s| s) {
            return Some(());
        }
        let rank = |room: usize, other: usize| {
            let kind = rooms[other].kind;
            let expected = parents(rooms[room].kind).iter().position(|&k| k == kind);
            (kind != RoomType::Corridor, expected.unwrap_or(usize::MAX))
        };
        let best = walls
            .iter()
            .filter(|s| s.wall.length() >= DOOR_WALL && seen[s.rooms[0]] != seen[s.rooms[1]])
            .map(|s| {
                let (room, other) = if seen[s.rooms[0]] {
                    (s.rooms[1], s.rooms[0])
                } else {
                    (s.rooms[0], s.rooms[1])
                };
                (rank(room, other), room, other, s.wall)
            })
            .min_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)))?;
        let (_, room, other, wall) = best;
        doors.push(inner_door(room, other, wall, rooms, rng));
    }
}

/// The windows of each room on its outside walls, clear of the outside doors: as many as its
/// type wants and its walls hold, spread over its longest walls first.
fn window_walls(
    rooms: &[RoomPlan],
    annexes: &[Annex],
    outside: &[Vec<Segment>],
    doors: &[Door],
) -> Vec<WindowWall> {
    let mut out = Vec::new();
    for (room, r) in rooms.iter().enumerate() {
        let wanted = windows_wanted(r.kind);
        // An annex has a window if its room has any: an alcove's.
        let wanted = if annexes.iter().any(|a| a.part == room) {
            wanted.min(1)
        } else {
            wanted
        };
        let mut walls: Vec<Segment> = outside[room]
            .iter()
            .flat_map(|w| clear_of_doors(*w, doors))
            .filter(|w| w.length() >= WINDOW_WALL)
            .collect();
        walls.sort_by(|a, b| b.length().total_cmp(&a.length()));
        let mut counts = vec![0usize; walls.len()];
        let mut left = wanted;
        'spread: while left > 0 {
            let mut placed = false;
            for (k, w) in walls.iter().enumerate() {
                if left == 0 {
                    break 'spread;
                }
                if ((counts[k] + 1) as f32) * WINDOW_WALL <= w.length() {
                    counts[k] += 1;
                    left -= 1;
                    placed = true;
                }
            }
            if !placed {
                break;
            }
        }
        for (wall, count) in walls.into_iter().zip(counts) {
            if count > 0 {
                out.push(WindowWall { room, wall, count });
            }
        }
    }
    out
}

/// The parts of an outside wall away from its outside doors (30 cm kept beside each).
fn clear_of_doors(wall: Segment, doors: &[Door]) -> Vec<Segment> {
    let mut pieces = vec![wall.span];
    for d in doors.iter().filter(|d| d.other.is_none()) {
        let g = d.gap();
        if g.vertical != wall.vertical || (g.at - wall.at).abs() > 1e-3 {
            continue;
        }
        let (lo, hi) = (g.span[0] - 0.3, g.span[1] + 0.3);
        pieces = pieces
            .into_iter()
            .flat_map(|[a, b]| [[a, b.min(lo)], [a.max(hi), b]])
            .filter(|[a, b]| b - a > 0.05)
            .collect();
    }
    pieces
        .into_iter()
        .map(|span| Segment { span, ..wall })
        .collect()
}
