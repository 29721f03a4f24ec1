//! Footprints on the floor: the axis-aligned rectangles that furnishing keeps apart, and the
//! rectangle an object covers once turned.

/// An axis-aligned footprint on the floor.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rect {
    pub(super) min: [f32; 2],
    pub(super) max: [f32; 2],
}

impl Rect {
    /// Whether the two come closer than `margin` (or overlap).
    pub(super) fn overlaps(&self, other: &Rect, margin: f32) -> bool {
        self.min[0] < other.max[0] + margin
            && other.min[0] < self.max[0] + margin
            && self.min[1] < other.max[1] + margin
            && other.min[1] < self.max[1] + margin
    }

    /// Whether it lies inside `other` but for `rounding` (m): a footprint computed back from a
    /// centre placed against a west or south wall falls an ulp outside it.
    pub(super) fn within_by(&self, other: &Rect, rounding: f32) -> bool {
        self.min[0] >= other.min[0] - rounding
            && self.min[1] >= other.min[1] - rounding
            && self.max[0] <= other.max[0] + rounding
            && self.max[1] <= other.max[1] + rounding
    }
}

/// Footprint of an object of size (w, d) standing at (x, y) after `turns` quarter turns.
pub(super) fn footprint(x: f32, y: f32, w: f32, d: f32, turns: u8) -> Rect {
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
