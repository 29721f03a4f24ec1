//! Rooms: typed footprints with their floors, for `inroom` and `onfloor`.

use crate::object::ObjectId;
use behavior_core::RoomType;
use serde::{Deserialize, Serialize};

/// A room of a home: its type, its instance number among rooms of that type, its footprint (an
/// axis-aligned rectangle in x, y) and its floor object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Room {
    /// Kitchen, bedroom, …
    pub kind: RoomType,
    /// 0 for the first room of its type, 1 for the second, …
    pub instance: u32,
    /// The footprint's lowest corner (x, y), m.
    pub min: [f32; 2],
    /// The footprint's highest corner (x, y), m.
    pub max: [f32; 2],
    /// The object standing for its floor, if any.
    pub floor: Option<ObjectId>,
}

impl Room {
    /// Whether the footprint contains (x, y), edges included.
    pub fn contains(&self, x: f32, y: f32) -> bool {
        (self.min[0]..=self.max[0]).contains(&x) && (self.min[1]..=self.max[1]).contains(&y)
    }
}
