//! The floor plan every home is laid out from, whatever its family: rectangular rooms (an
//! L-shaped room's annex among them, see `lshape.rs`), the doors
//! and wide openings between them (and to the outside), and the stretches of outside wall that
//! hold windows. Walls and furnishing read only this, so a new family is a new way of filling it.

use super::footprint::Rect;
use super::lshape::Annex;
use super::{DOOR_CLEARANCE, DOORWAY, WALL_THICKNESS};
use crate::scene::RoomPlan;

/// A stretch of a wall line: vertical (constant x) or not (constant y), at coordinate `at`,
/// from `span[0]` to `span[1]` along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Segment {
    pub(super) vertical: bool,
    pub(super) at: f32,
    pub(super) span: [f32; 2],
}

impl Segment {
    /// Its length, m.
    pub(super) fn length(&self) -> f32 {
        self.span[1] - self.span[0]
    }

    /// The floor point at `t` along it, as (x, y).
    pub(super) fn point(&self, t: f32) -> [f32; 2] {
        if self.vertical {
            [self.at, t]
        } else {
            [t, self.at]
        }
    }

    /// The rectangle reaching `depth` to both sides of it, `extra` beyond its ends.
    pub(super) fn band(&self, depth: f32, extra: f32) -> Rect {
        let (a, b) = (self.span[0] - extra, self.span[1] + extra);
        if self.vertical {
            Rect {
                min: [self.at - depth, a],
                max: [self.at + depth, b],
            }
        } else {
            Rect {
                min: [a, self.at - depth],
                max: [b, self.at + depth],
            }
        }
    }
}

/// The unit normal of a wall line pointing into `room` (which has an edge on it), as (x, y).
pub(super) fn into_room(vertical: bool, at: f32, room: &RoomPlan) -> [f32; 2] {
    let axis = usize::from(!vertical);
    let centre = (room.min[axis] + room.max[axis]) / 2.0;
    let sign = if centre > at { 1.0 } else { -1.0 };
    if vertical { [sign, 0.0] } else { [0.0, sign] }
}

/// Quarter turns that make an object's front (its −y side when unturned) face `normal`.
fn turns_facing(normal: [f32; 2]) -> u8 {
    match normal {
        [_, y] if y < -0.5 => 0,
        [x, _] if x > 0.5 => 1,
        [_, y] if y > 0.5 => 2,
        _ => 3,
    }
}

/// A doorway with its door: in a wall between two rooms, or between a room and the outside.
#[derive(Clone, Copy, Debug)]
pub(super) struct Door {
    /// The room the door belongs to: its leaf stands just inside it and swings into it, and
    /// its furnishing draws it.
    pub(super) room: usize,
    /// The room on the other side, or `None` for the outside.
    pub(super) other: Option<usize>,
    /// The wall line it is in.
    pub(super) line: Segment,
    /// Its centre along `line`.
    pub(super) t: f32,
}

impl Door {
    /// The doorway: a [`DOORWAY`]-wide stretch of its wall.
    pub(super) fn gap(&self) -> Segment {
        Segment {
            span: [self.t - DOORWAY / 2.0, self.t + DOORWAY / 2.0],
            ..self.line
        }
    }

    /// Where the door's bottom centre stands (15 cm inside its room, `room` being
    /// `rooms[self.room]`) and its quarter turns, its front facing into the room.
    pub(super) fn leaf(&self, room: &RoomPlan) -> ([f32; 2], u8) {
        let normal = into_room(self.line.vertical, self.line.at, room);
        let [x, y] = self.line.point(self.t);
        (
            [x + 0.15 * normal[0], y + 0.15 * normal[1]],
            turns_facing(normal),
        )
    }

    /// The floor kept free in front of the doorway, on both sides of its wall.
    pub(super) fn clearance(&self) -> Rect {
        self.gap().band(DOOR_CLEARANCE, 0.1)
    }

    /// Whether it joins `room` to anything.
    pub(super) fn touches(&self, room: usize) -> bool {
        self.room == room || self.other == Some(room)
    }
}

/// A wide opening with no wall between two rooms (an open plan's living and dining rooms), or
/// between an L-shaped room's main rectangle and its annex (`inner`: one room, no wall at all).
#[derive(Clone, Copy, Debug)]
pub(super) struct Opening {
    pub(super) rooms: [usize; 2],
    pub(super) gap: Segment,
    pub(super) inner: bool,
}

/// A stretch of outside wall of a room holding `count` windows, evenly spaced along it.
#[derive(Clone, Copy, Debug)]
pub(super) struct WindowWall {
    pub(super) room: usize,
    pub(super) wall: Segment,
    pub(super) count: usize,
}

impl WindowWall {
    /// Where window `k` stands (its bottom centre, just inside the wall), its quarter turns and
    /// the unit normal into the room.
    pub(super) fn place(&self, k: usize, room: &RoomPlan) -> ([f32; 2], u8, [f32; 2]) {
        let w = self.wall;
        let t = w.span[0] + (k as f32 + 1.0) * w.length() / (self.count as f32 + 1.0);
        let normal = into_room(w.vertical, w.at, room);
        let [x, y] = w.point(t);
        let half = WALL_THICKNESS / 2.0;
        (
            [
                x + normal[0] * half + normal[0] * 0.05,
                y + normal[1] * half + normal[1] * 0.05,
            ],
            turns_facing(normal),
            normal,
        )
    }
}

/// A home's plan: everything walls and furnishing are laid out from.
pub(super) struct Plan {
    /// The rooms, each an axis-aligned rectangle; halls are rooms of type corridor; the annexes
    /// of L-shaped rooms last.
    pub(super) rooms: Vec<RoomPlan>,
    /// Which of `rooms` are annexes, and of which room.
    pub(super) annexes: Vec<Annex>,
    /// Every doorway, inner and outer, in the order their doors are drawn.
    pub(super) doors: Vec<Door>,
    /// Wide openings between rooms.
    pub(super) openings: Vec<Opening>,
    /// Where the windows go.
    pub(super) windows: Vec<WindowWall>,
}
