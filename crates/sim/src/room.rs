//! Rooms: typed footprints with their floors, for `inroom` and `onfloor`.

use crate::object::ObjectId;
use behavior_core::RoomType;
use serde::{Deserialize, Serialize};

/// An axis-aligned rectangle on the floor, m.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FloorRect {
    /// Its lowest corner (x, y).
    pub min: [f32; 2],
    /// Its highest corner (x, y).
    pub max: [f32; 2],
}

impl FloorRect {
    /// Whether it contains (x, y), edges included.
    pub fn contains(&self, x: f32, y: f32) -> bool {
        (self.min[0]..=self.max[0]).contains(&x) && (self.min[1]..=self.max[1]).contains(&y)
    }

    /// Its area, m².
    pub fn area(&self) -> f32 {
        (self.max[0] - self.min[0]) * (self.max[1] - self.min[1])
    }

    /// The rectangles of a footprint: the main one, from `min` to `max`, then its `annexes`
    /// (as a [`Room`] and a scene file's room both hold them).
    pub fn footprint(
        min: [f32; 2],
        max: [f32; 2],
        annexes: &[FloorRect],
    ) -> impl Iterator<Item = FloorRect> + '_ {
        std::iter::once(FloorRect { min, max }).chain(annexes.iter().copied())
    }
}

/// A room of a home: its type, its instance number among rooms of that type, its footprint and
/// its floor object. The footprint is a rectangle, or for an L-shaped room a rectangle and the
/// annexes that join it along a whole side with no wall between (an alcove).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Room {
    /// Kitchen, bedroom, …
    pub kind: RoomType,
    /// 0 for the first room of its type, 1 for the second, …
    pub instance: u32,
    /// The main rectangle's lowest corner (x, y), m.
    pub min: [f32; 2],
    /// The main rectangle's highest corner (x, y), m.
    pub max: [f32; 2],
    /// Further rectangles of an L-shaped room; empty for a rectangular one.
    pub annexes: Vec<FloorRect>,
    /// The object standing for its floor, if any.
    pub floor: Option<ObjectId>,
}

impl Room {
    /// The rectangles that make up its footprint, the main one first.
    pub fn rects(&self) -> impl Iterator<Item = FloorRect> + '_ {
        FloorRect::footprint(self.min, self.max, &self.annexes)
    }

    /// Whether the footprint contains (x, y), edges included.
    pub fn contains(&self, x: f32, y: f32) -> bool {
        self.rects().any(|r| r.contains(x, y))
    }

    /// The rectangle around its whole footprint.
    pub fn bounds(&self) -> FloorRect {
        self.rects().fold(
            FloorRect {
                min: self.min,
                max: self.max,
            },
            |b, r| FloorRect {
                min: [b.min[0].min(r.min[0]), b.min[1].min(r.min[1])],
                max: [b.max[0].max(r.max[0]), b.max[1].max(r.max[1])],
            },
        )
    }

    /// The floor area of its footprint, m².
    pub fn area(&self) -> f32 {
        self.rects().map(|r| r.area()).sum()
    }
}
