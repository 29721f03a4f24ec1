//! Rugs, laid once a home is furnished: under the dining table (wide enough for the chairs
//! round it), under the low table in front of the sofa, and under the foot of a bed. A rug lies
//! within the rectangle of its room that holds what it lies under, clear of the walls; it draws
//! nothing from the home's generator, so a home's plan and furniture are what they would be
//! without rugs.

use super::WALL_THICKNESS;
use super::footprint::{Rect, footprint};
use crate::scene::{ObjectPlan, RoomPlan, RugPlan};
use behavior_core::RoomType;

/// Rug colours: madder red, indigo, sand, sage, charcoal, rust.
const COLOURS: [[u8; 3]; 6] = [
    [150, 52, 48],
    [52, 62, 110],
    [196, 178, 140],
    [122, 140, 110],
    [70, 70, 74],
    [170, 92, 50],
];

/// How far a rug reaches beyond what it lies under (m): a dining chair pulled out stays on it.
const BEYOND_DINING: f32 = 0.6;
/// …beyond a low table or a bed.
const BEYOND: f32 = 0.4;
/// The least side of a rug worth laying (m).
const LEAST: f32 = 1.0;

fn grown(r: &Rect, by: f32) -> Rect {
    Rect {
        min: [r.min[0] - by, r.min[1] - by],
        max: [r.max[0] + by, r.max[1] + by],
    }
}

fn clipped(r: &Rect, to: &Rect) -> Option<Rect> {
    let c = Rect {
        min: [r.min[0].max(to.min[0]), r.min[1].max(to.min[1])],
        max: [r.max[0].min(to.max[0]), r.max[1].min(to.max[1])],
    };
    (c.max[0] - c.min[0] >= LEAST && c.max[1] - c.min[1] >= LEAST).then_some(c)
}

fn object_rect(o: &ObjectPlan) -> Rect {
    let [x, y, _] = o.position;
    footprint(x, y, o.size[0], o.size[1], o.yaw_quarter_turns)
}

fn centre(r: &Rect) -> [f32; 2] {
    [(r.min[0] + r.max[0]) / 2.0, (r.min[1] + r.max[1]) / 2.0]
}

/// What a rug in a room of `kind` lies under, and how far beyond it reaches: the room's first
/// table (dining room), the table nearest its sofa (living room), its first bed (bedroom).
fn under(kind: RoomType, room: usize, objects: &[ObjectPlan]) -> Option<(Rect, f32)> {
    let first = |synset: &str| {
        objects
            .iter()
            .find(|o| o.room == room && o.synset == synset)
            .map(object_rect)
    };
    match kind {
        RoomType::DiningRoom => first("table.n.02").map(|t| (t, BEYOND_DINING)),
        RoomType::Bedroom => first("bed.n.01").map(|b| (b, BEYOND)),
        RoomType::LivingRoom => {
            let sofa = centre(&first("sofa.n.01")?);
            let gap = |r: &Rect| {
                let c = centre(r);
                (c[0] - sofa[0]).hypot(c[1] - sofa[1])
            };
            objects
                .iter()
                .filter(|o| o.room == room && o.synset == "table.n.02")
                .map(object_rect)
                .min_by(|a, b| gap(a).total_cmp(&gap(b)))
                .map(|t| (t, BEYOND))
        }
        _ => None,
    }
}

/// Lays the rugs of a furnished home into its rooms.
pub(super) fn lay(rooms: &mut [RoomPlan], objects: &[ObjectPlan], seed: u64) {
    let inset = WALL_THICKNESS / 2.0 + 0.05;
    for (index, room) in rooms.iter_mut().enumerate() {
        let Some((what, beyond)) = under(room.kind, index, objects) else {
            continue;
        };
        let [cx, cy] = centre(&what);
        let Some(rect) = room.rects().find(|r| r.contains(cx, cy)) else {
            continue;
        };
        let inner = Rect {
            min: [rect.min[0] + inset, rect.min[1] + inset],
            max: [rect.max[0] - inset, rect.max[1] - inset],
        };
        if let Some(rug) = clipped(&grown(&what, beyond), &inner) {
            let colour = COLOURS[(seed as usize + 5 * index) % COLOURS.len()];
            room.rugs.push(RugPlan {
                min: rug.min,
                max: rug.max,
                color: colour,
            });
        }
    }
}
