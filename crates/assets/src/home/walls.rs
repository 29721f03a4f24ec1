//! What stands in the walls: the walls themselves along every room edge, with the doorways and
//! the wide openings cut out; the doors in the doorways; the windows in the outside walls.

use super::arrange::Furnishing;
use super::furnish::Furnisher;
use super::plan::Plan;
use super::{DOORWAY, WALL_THICKNESS};
use crate::library::AssetError;
use crate::scene::{ObjectPlan, WALL_HEIGHT, WallPlan};
use behavior_core::RoomType;
use behavior_core::{DOOR_SYNSET, WINDOW_SYNSET};
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

/// What is cut out of the walls: every doorway, inner and outer, and every wide opening.
fn gaps(plan: &Plan) -> Vec<(Line, [f32; 2])> {
    let doors = plan.doors.iter().map(|d| d.gap());
    let openings = plan.openings.iter().map(|o| o.gap);
    doors
        .chain(openings)
        .map(|g| ((g.vertical, key(g.at)), g.span))
        .collect()
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

impl Furnisher<'_, '_> {
    /// The doors that belong to a room, each just inside it in its doorway (a door's front is
    /// its −y side, and its leaf swings to the front).
    pub(super) fn doors(&mut self, room: usize) -> Result<(), AssetError> {
        for door in self.plan.doors.iter().filter(|d| d.room == room) {
            let name = self.name(DOOR_SYNSET);
            let (mut size, variant) = self.library.sample(DOOR_SYNSET, self.rng)?;
            size.x = size.x.min(DOORWAY - 0.05);
            let ([x, y], turns) = door.leaf(&self.plan.rooms[room]);
            self.objects.push(ObjectPlan {
                name,
                synset: DOOR_SYNSET.into(),
                room,
                position: [x, y, 0.0],
                yaw_quarter_turns: turns,
                size: size.to_array(),
                variant,
                joints: vec![0.0],
            });
        }
        Ok(())
    }

    /// The room's windows, evenly spaced along the stretches of outside wall the plan gives it.
    /// Their casements open into the room; a floor-length one (variant 1) sweeps the floor in
    /// front of it, which is kept clear; under a sill-height one (variant 0) only furniture no
    /// taller than the sill may stand.
    pub(super) fn windows(&mut self, f: &mut Furnishing) -> Result<(), AssetError> {
        let room = &self.plan.rooms[f.index];
        for wall in self.plan.windows.iter().filter(|w| w.room == f.index) {
            for k in 0..wall.count {
                let (size, variant) = self.library.sample(WINDOW_SYNSET, self.rng)?;
                // Floor-length windows (variant 1, casements sweeping the floor) open living
                // and dining rooms onto the garden; other rooms have sills, with the bed or the
                // counters under them.
                let garden = matches!(room.kind, RoomType::LivingRoom | RoomType::DiningRoom);
                let variant = if garden { variant } else { 0 };
                let ([x, y], turns, normal) = wall.place(k, room);
                let sweep = if variant == 1 { size.x } else { 0.0 };
                let across = u8::from(wall.wall.vertical);
                let before = super::footprint::footprint(
                    x + normal[0] * sweep / 2.0,
                    y + normal[1] * sweep / 2.0,
                    size.x,
                    0.12 + sweep,
                    across,
                );
                // Low furniture may stand under a sill-height window.
                if variant == 0 {
                    f.sills.push(before);
                } else {
                    f.taken.push(before);
                }
                let name = self.name(WINDOW_SYNSET);
                self.objects.push(ObjectPlan {
                    name,
                    synset: WINDOW_SYNSET.into(),
                    room: f.index,
                    position: [x, y, 0.0],
                    yaw_quarter_turns: turns,
                    size: size.to_array(),
                    variant,
                    joints: vec![0.0],
                });
            }
        }
        Ok(())
    }
}
