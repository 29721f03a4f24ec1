//! L-shaped rooms: after the layout, a room may grow into a corner of a room it shares a wall
//! with (beside it in its band, or across the next band where the two end together), as rooms
//! grow into the space of an outline in ProcTHOR. The corner it takes becomes its annex (an
//! alcove joined along a whole side, no wall between), and what is left of the neighbour is an L
//! too: a full-depth or full-length rectangle and a strip. Both keep their type's specification
//! (area; the main rectangle's shortest side), the neighbour's main rectangle stays a whole room
//! of its type, and every arm is wide enough for either robot to turn in. [`SHARE`] is a knob
//! for how many of the homes that can have one do: all of them, as measured today (29 of 100
//! homes of free seeds).
//!
//! Until the home is furnished an annex is a rectangle of its own, appended after the layout's
//! rooms, so every later step works on rectangles: it is joined to its room by an opening as
//! long as their shared side, gets no door of its own to the rest of the home (it is reached
//! through its room) and a piece of furniture against its wall. Then [`merge`] folds each annex
//! into its room's [`RoomPlan::annexes`].

use super::footprint::Rect;
use super::program::{chance, room_spec};
use crate::scene::{ObjectPlan, RoomPlan};
use behavior_core::RoomType;
use behavior_core::rng::uniform;
use behavior_sim::FloorRect;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;

/// The share of homes with an L-shaped pair of rooms, of those where some pair can be.
const SHARE: f32 = 1.0;
/// The narrowest arm of an L (m): each robot's base turns in it and a passage 1.2 m wide runs
/// through the side it is joined by.
const ARM: f32 = 1.5;

/// Rooms a room of this type may be the L of: the rooms people live in, not halls, garages,
/// bathrooms or closets.
fn may_bend(kind: RoomType) -> bool {
    use RoomType::*;
    matches!(
        kind,
        LivingRoom | DiningRoom | Kitchen | Bedroom | HomeOffice | StorageRoom | UtilityRoom
    )
}

/// Whether a room is one of the public rooms, which open onto each other anyway: a corner one
/// took from another would leave short walls between them.
fn public(kind: RoomType) -> bool {
    matches!(
        kind,
        RoomType::LivingRoom | RoomType::DiningRoom | RoomType::Kitchen
    )
}

/// A rectangle of a room other than its first: rooms[part] belongs to rooms[main].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Annex {
    pub(super) part: usize,
    pub(super) main: usize,
}

/// `v` on the 10 cm grid.
fn snap(v: f32) -> f32 {
    (v * 10.0).round() / 10.0
}

fn area(r: &RoomPlan) -> f32 {
    (r.max[0] - r.min[0]) * (r.max[1] - r.min[1])
}

/// A corner of room `b` that room `a` may grow into: they share a wall that ends at a corner of
/// both. Lengths are measured in the wall's frame: `u` along it, `v` from it into `b`.
#[derive(Clone, Copy, Debug)]
struct Corner {
    a: usize,
    b: usize,
    /// The wall is a line of constant x (else of constant y)…
    vertical: bool,
    /// …at this coordinate.
    at: f32,
    /// +1 if `b` lies on the wall's high side.
    into_b: f32,
    /// Where along the wall the shared corner is, and which way the wall runs from it (±1).
    end: f32,
    dir: f32,
    /// How long the shared wall is.
    shared: f32,
    /// `b`'s length along the wall and its depth from it.
    length: f32,
    depth: f32,
}

impl Corner {
    /// The rectangle `along` the wall from the corner (distances from it) and `from` it into
    /// `b` (distances from the wall).
    fn rect(&self, along: [f32; 2], from: [f32; 2]) -> Rect {
        let u = along.map(|t| snap(self.end + self.dir * t));
        let v = from.map(|t| snap(self.at + self.into_b * t));
        let (u, v) = (
            [u[0].min(u[1]), u[0].max(u[1])],
            [v[0].min(v[1]), v[0].max(v[1])],
        );
        if self.vertical {
            Rect {
                min: [v[0], u[0]],
                max: [v[1], u[1]],
            }
        } else {
            Rect {
                min: [u[0], v[0]],
                max: [u[1], v[1]],
            }
        }
    }
}

/// The corners of `b` that `a` shares a wall with, ending at a corner of both.
fn corners(rooms: &[RoomPlan], a: usize, b: usize) -> Vec<Corner> {
    let same = |p: f32, q: f32| (p - q).abs() < 1e-3;
    let (ra, rb) = (&rooms[a], &rooms[b]);
    let mut out = Vec::new();
    for vertical in [true, false] {
        let (across, along) = if vertical { (0, 1) } else { (1, 0) };
        let (at, into_b) = if same(ra.max[across], rb.min[across]) {
            (rb.min[across], 1.0)
        } else if same(ra.min[across], rb.max[across]) {
            (rb.max[across], -1.0)
        } else {
            continue;
        };
        let span = [
            ra.min[along].max(rb.min[along]),
            ra.max[along].min(rb.max[along]),
        ];
        if span[1] - span[0] < ARM {
            continue;
        }
        let ends = [(span[0], 1.0, 0), (span[1], -1.0, 1)];
        for (end, dir, k) in ends {
            let corner_of = |r: &RoomPlan| same([r.min, r.max][k][along], end);
            if corner_of(ra) && corner_of(rb) {
                out.push(Corner {
                    a,
                    b,
                    vertical,
                    at,
                    into_b,
                    end,
                    dir,
                    shared: span[1] - span[0],
                    length: rb.max[along] - rb.min[along],
                    depth: rb.max[across] - rb.min[across],
                });
            }
        }
    }
    out
}

/// How `b` is cut once its corner is taken: the rest of it as its main rectangle and a strip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cut {
    /// The main rectangle keeps `b`'s depth from the wall, beside the corner.
    FullDepth,
    /// The main rectangle keeps `b`'s length along the wall, behind the corner.
    FullLength,
}

/// The largest depth (m) a corner `length` long can take from `b` cut as `cut`, keeping both
/// rooms' specifications, `b`'s main rectangle a whole room of its type by itself (its
/// furniture stands there) and every arm [`ARM`] wide.
fn deepest(rooms: &[RoomPlan], c: &Corner, length: f32, cut: Cut) -> f32 {
    let (sa, sb) = (room_spec(rooms[c.a].kind), room_spec(rooms[c.b].kind));
    let by_area =
        ((sa.area[1] - area(&rooms[c.a])) / length).min((area(&rooms[c.b]) - sb.area[0]) / length);
    let rest = c.length - length;
    let by_sides = match cut {
        Cut::FullDepth if rest >= sb.min_side && rest * c.depth >= sb.area[0] => c.depth - ARM,
        Cut::FullLength if rest >= ARM => {
            (c.depth - sb.min_side).min(c.depth - sb.area[0] / c.length)
        }
        _ => 0.0,
    };
    // 5 cm below the bound before rounding down to the grid.
    ((by_area.min(by_sides) - 0.05) * 10.0).floor() / 10.0
}

/// The longest corner that can be taken along the wall.
fn longest(c: &Corner) -> f32 {
    ((c.shared.min(c.length - ARM) - 0.05) * 10.0).floor() / 10.0
}

/// Perhaps ([`SHARE`] of the homes where some pair can) one room grows into a corner of a room it
/// shares a wall with: the room's annex appended to `rooms`, the neighbour cut down to its main
/// rectangle with the strip left beside the corner appended as its annex. Nothing changes where
/// no pair can keep its specifications.
pub(super) fn grow(rooms: &mut Vec<RoomPlan>, rng: &mut ChaCha8Rng) -> Vec<Annex> {
    let mut options = Vec::new();
    for a in 0..rooms.len() {
        for b in 0..rooms.len() {
            let (ka, kb) = (rooms[a].kind, rooms[b].kind);
            if a == b || !may_bend(ka) || !may_bend(kb) || public(ka) && public(kb) {
                continue;
            }
            for c in corners(rooms, a, b) {
                for cut in [Cut::FullDepth, Cut::FullLength] {
                    if longest(&c) >= ARM && deepest(rooms, &c, ARM, cut) >= ARM {
                        options.push((c, cut));
                    }
                }
            }
        }
    }
    if options.is_empty() || !chance(rng, SHARE) {
        return Vec::new();
    }
    let (c, cut) = options[rng.next_u32() as usize % options.len()];
    // The corner's length along the wall, then its depth within what that length allows.
    let mut length = snap(uniform(rng, ARM, longest(&c))).clamp(ARM, longest(&c));
    while length > ARM && deepest(rooms, &c, length, cut) < ARM {
        length = snap(length - 0.1); // ARM itself fits, as the options were chosen
    }
    let deep = deepest(rooms, &c, length, cut);
    let depth = snap(uniform(rng, ARM, deep)).clamp(ARM, deep);
    let corner = c.rect([0.0, length], [0.0, depth]);
    let (main_b, strip) = match cut {
        Cut::FullDepth => (
            c.rect([length, c.length], [0.0, c.depth]),
            c.rect([0.0, length], [depth, c.depth]),
        ),
        Cut::FullLength => (
            c.rect([0.0, c.length], [depth, c.depth]),
            c.rect([length, c.length], [0.0, depth]),
        ),
    };
    let part = |of: &RoomPlan, r: Rect| RoomPlan::new(of.kind, of.instance, r.min, r.max);
    let annex_a = part(&rooms[c.a], corner);
    let annex_b = part(&rooms[c.b], strip);
    rooms[c.b].min = main_b.min;
    rooms[c.b].max = main_b.max;
    let n = rooms.len();
    rooms.push(annex_a);
    rooms.push(annex_b);
    vec![
        Annex { part: n, main: c.a },
        Annex {
            part: n + 1,
            main: c.b,
        },
    ]
}

/// The home's rooms with each annex folded into its room (annexes come after every room), and
/// the objects of an annex counted in its room.
pub(super) fn merge(
    mut rooms: Vec<RoomPlan>,
    annexes: &[Annex],
    mut objects: Vec<ObjectPlan>,
) -> (Vec<RoomPlan>, Vec<ObjectPlan>) {
    let Some(first) = annexes.iter().map(|a| a.part).min() else {
        return (rooms, objects);
    };
    for annex in annexes {
        let r = &rooms[annex.part];
        let rect = FloorRect {
            min: r.min,
            max: r.max,
        };
        rooms[annex.main].annexes.push(rect);
    }
    for object in &mut objects {
        if let Some(annex) = annexes.iter().find(|a| a.part == object.room) {
            object.room = annex.main;
        }
    }
    rooms.truncate(first);
    (rooms, objects)
}
