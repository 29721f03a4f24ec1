//! What stands in the walls: the walls themselves along every room edge, with the doorways, the
//! front door's gap and the open plan's opening cut out; the doors in the doorways; the windows
//! in the rooms' outer walls.

use super::furnish::{Furnisher, Furnishing};
use super::plan::Plan;
use super::{CORRIDOR_WIDTH, DOORWAY, WALL_THICKNESS};
use crate::library::AssetError;
use crate::scene::{ObjectPlan, WALL_HEIGHT, WallPlan};
use behavior_core::RoomType;
use std::collections::BTreeMap;

/// A wall line: vertical (along y) or not, and its coordinate in millimetres (so that edges of
/// neighbouring rooms meet exactly).
type Line = (bool, i64);

fn key(x: f32) -> i64 {
    (x * 1000.0).round() as i64
}

/// Walls along every room edge, merged where rooms meet, with the doorways and the open plan's
/// opening cut out.
pub(super) fn walls(plan: &Plan) -> Vec<WallPlan> {
    let gaps = gaps(plan);
    let mut walls = Vec::new();
    for ((vertical, at), spans) in lines(plan) {
        let mut pieces = merged(spans);
        for &(_, gap) in gaps.iter().filter(|g| g.0 == (vertical, at)) {
            pieces = cut(pieces, gap);
        }
        walls.extend(pieces.into_iter().map(|span| slab((vertical, at), span)));
    }
    walls
}

/// Every room's four edges, as intervals on their lines.
fn lines(plan: &Plan) -> BTreeMap<Line, Vec<[f32; 2]>> {
    let mut lines: BTreeMap<Line, Vec<[f32; 2]>> = BTreeMap::new();
    for r in &plan.rooms {
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
    lines
}

/// What is cut out of the walls: the doorways, the front door at the corridor's west end, and
/// the open plan's opening.
fn gaps(plan: &Plan) -> Vec<(Line, [f32; 2])> {
    let mut gaps: Vec<(Line, [f32; 2])> = plan
        .doorways
        .iter()
        .map(|d| {
            (
                (false, key(d.y)),
                [d.x - DOORWAY / 2.0, d.x + DOORWAY / 2.0],
            )
        })
        .collect();
    let c = &plan.rooms[plan.corridor];
    gaps.push((
        (true, key(c.min[0])),
        [
            CORRIDOR_WIDTH / 2.0 - DOORWAY / 2.0,
            CORRIDOR_WIDTH / 2.0 + DOORWAY / 2.0,
        ],
    ));
    if let Some(open) = &plan.opening {
        gaps.push(((true, key(open.x)), open.y));
    }
    gaps
}

/// Intervals on one line, sorted and merged where they touch.
fn merged(mut spans: Vec<[f32; 2]>) -> Vec<[f32; 2]> {
    spans.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut merged: Vec<[f32; 2]> = Vec::new();
    for s in spans {
        match merged.last_mut() {
            Some(last) if s[0] <= last[1] + 1e-4 => last[1] = last[1].max(s[1]),
            _ => merged.push(s),
        }
    }
    merged
}

/// The intervals with `gap` cut out, dropping slivers of a centimetre or less.
fn cut(pieces: Vec<[f32; 2]>, gap: [f32; 2]) -> Vec<[f32; 2]> {
    pieces
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
        .collect()
}

/// The wall standing on `line` from `a` to `b`, overlapping its neighbours by half a thickness
/// at each end so corners close.
fn slab((vertical, at): Line, [a, b]: [f32; 2]) -> WallPlan {
    let half = WALL_THICKNESS / 2.0;
    let coordinate = at as f32 / 1000.0;
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
    WallPlan { min, max }
}

/// How many windows a room type gets on its outer wall.
fn windows(kind: RoomType) -> usize {
    match kind {
        RoomType::LivingRoom => 2,
        RoomType::Kitchen | RoomType::Bedroom | RoomType::DiningRoom | RoomType::HomeOffice => 1,
        _ => 0,
    }
}

impl Furnisher<'_, '_> {
    /// The front door, just inside the corridor's west end, its front facing −x.
    pub(super) fn front_door(&mut self) -> Result<(), AssetError> {
        let at = [0.0 + WALL_THICKNESS / 2.0 + 0.15, CORRIDOR_WIDTH / 2.0];
        let door = self.door(self.plan.corridor, at, 3)?;
        self.objects.push(door);
        Ok(())
    }

    /// A room's door. It stands just inside its room and its leaf swings into the room (a door's
    /// front is its −y side), so an open door still stands in its room.
    pub(super) fn room_door(&mut self, room: usize) -> Result<(), AssetError> {
        let doorway = self.plan.doorways[room];
        let into_room = doorway.y > self.plan.rooms[room].min[1];
        let inward = if into_room { -0.15 } else { 0.15 };
        let turns = if into_room { 0 } else { 2 };
        let door = self.door(room, [doorway.x, doorway.y + inward], turns)?;
        self.objects.push(door);
        Ok(())
    }

    /// A door of a drawn size (narrow enough for a doorway) standing at `at`.
    fn door(&mut self, room: usize, at: [f32; 2], turns: u8) -> Result<ObjectPlan, AssetError> {
        let name = self.name("door.n.01");
        let (mut size, variant) = self.library.sample("door.n.01", self.rng)?;
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

    /// The room's windows, evenly spaced along its outer wall (the one away from the corridor).
    /// Their casements open into the room; a floor-length one (variant 1) sweeps the floor in
    /// front of it, which is kept clear.
    pub(super) fn windows(&mut self, f: &mut Furnishing) -> Result<(), AssetError> {
        let room = &self.plan.rooms[f.index];
        let door_y = self.plan.doorways[f.index].y;
        let outer_y = if door_y > room.min[1] {
            room.min[1]
        } else {
            room.max[1]
        };
        let half = WALL_THICKNESS / 2.0;
        let count = windows(room.kind);
        for k in 0..count {
            let (size, variant) = self.library.sample("window.n.01", self.rng)?;
            let x =
                room.min[0] + (k as f32 + 1.0) * (room.max[0] - room.min[0]) / (count as f32 + 1.0);
            let y = if outer_y < door_y {
                outer_y + half + 0.05
            } else {
                outer_y - half - 0.05
            };
            let turns = if outer_y < door_y { 2 } else { 0 };
            let sweep = if variant == 1 { size.x } else { 0.0 };
            let inward = if outer_y < door_y { 1.0 } else { -1.0 };
            f.taken.push(super::footprint::footprint(
                x,
                y + inward * sweep / 2.0,
                size.x,
                0.12 + sweep,
                0,
            ));
            let name = self.name("window.n.01");
            self.objects.push(ObjectPlan {
                name,
                synset: "window.n.01".into(),
                room: f.index,
                position: [x, y, 0.0],
                yaw_quarter_turns: turns,
                size: size.to_array(),
                variant,
                joints: vec![0.0],
            });
        }
        Ok(())
    }
}
