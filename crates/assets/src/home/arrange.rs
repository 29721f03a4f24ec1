//! Where each piece of furniture stands in its room, by the rules a person would recognise: backed
//! against a wall facing into the room; a kitchen's pieces in a run along its walls from the sink
//! under a window; a table in the middle with chairs on its sides facing it; a low table in front
//! of the sofa and a cabinet (where a screen stands) across the room from it; nightstands at the
//! head of the bed; the microwave on a countertop; a living-room table across the opening onto the
//! dining room. Every placement keeps clear of the doorways and the openings' passages, and keeps
//! a path between the room's ways in for the widest robot base.

use super::WALL_THICKNESS;
use super::footprint::{Rect, footprint};
use super::plan::{Opening, Plan, into_room};
use crate::scene::ObjectPlan;
use rapier3d::math::Vector;

/// Between pieces of furniture (m).
const GAP: f32 = 0.05;
/// The height of a low window's sill (m): what is no taller may stand under it.
const SILL: f32 = 0.9;

/// A room being furnished: its floor inside the walls and what is taken of it.
pub(super) struct Furnishing {
    pub(super) index: usize,
    pub(super) inner: Rect,
    /// Footprints no furniture may take: doorways' clearances, windows, furniture.
    pub(super) taken: Vec<Rect>,
    /// Where the room is entered (its doorways' clearances, its openings' passages), between
    /// which a path is kept for the robots.
    pub(super) ways: Vec<Rect>,
    /// The footprints of the furniture on its floor so far.
    pub(super) placed: Vec<Rect>,
    /// The floor in front of low windows, which only furniture no taller than their sill takes.
    pub(super) sills: Vec<Rect>,
    /// The wall a kitchen's run of counters starts from, once its first piece stands.
    pub(super) run: Option<usize>,
    /// What the piece being placed may do about low windows' sills.
    pub(super) sill_rule: SillRule,
    /// The footprints of the tables standing in the room, the last placed last: chairs go round
    /// the last.
    pub(super) tables: Vec<Rect>,
}

/// What a piece of furniture may do about the floor in front of a low window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SillRule {
    /// Keep clear of it: the piece is taller than the sill.
    Clear,
    /// Stand under the window: one of [`UNDER_SILLS`] no taller than the sill.
    Under,
    /// Stand under it but for its back, which rises above the sill against its own wall: a
    /// bed, whose side may lie under a window and whose headboard may not.
    BackClear,
}

impl SillRule {
    /// The rule for a piece of `synset` and `height`.
    pub(super) fn of(synset: &str, height: f32) -> SillRule {
        if height > SILL {
            SillRule::Clear
        } else if synset == "bed.n.01" {
            SillRule::BackClear
        } else if UNDER_SILLS.contains(&synset) {
            SillRule::Under
        } else {
            SillRule::Clear
        }
    }
}

/// How deep a piece's back is that rises above a sill (a bed's headboard), m.
const BACK: f32 = 0.15;

/// The strip of `rect` along its back, against wall `wall`.
fn back_of(rect: &Rect, wall: usize) -> Rect {
    let mut back = *rect;
    match wall {
        0 => back.min[1] = rect.max[1] - BACK,
        1 => back.min[0] = rect.max[0] - BACK,
        2 => back.max[1] = rect.min[1] + BACK,
        _ => back.max[0] = rect.min[0] + BACK,
    }
    back
}

/// The pieces whose shape stays within their height and that may so stand under a low window
/// when no taller than its sill (a sink's tap and a bed's headboard rise above theirs).
const UNDER_SILLS: [&str; 6] = [
    "countertop.n.01",
    "dishwasher.n.01",
    "cabinet.n.01",
    "table.n.02",
    "sofa.n.01",
    "bathtub.n.01",
];

/// How far a sink under a window stands out from the wall, m: its tap clear of the casement.
const BEFORE_A_WINDOW: f32 = 0.08;

/// How far a footprint may fall outside the floor by rounding, m: one computed back from a
/// centre placed against a west or south wall falls an ulp outside it (which, before, kept many
/// pieces off those walls).
const ROUNDING: f32 = 1e-4;

impl Furnishing {
    /// An empty room `index` with floor `inner`.
    pub(super) fn new(index: usize, inner: Rect) -> Furnishing {
        Furnishing {
            index,
            inner,
            taken: Vec::new(),
            ways: Vec::new(),
            placed: Vec::new(),
            sills: Vec::new(),
            run: None,
            sill_rule: SillRule::Clear,
            tables: Vec::new(),
        }
    }
}

/// The radius of the widest robot base a room's paths are kept for, m: Fetch's 0.28 m and a
/// little to spare.
const PATH_RADIUS: f32 = 0.32;
/// The cell of the grid paths are looked for on, m.
const PATH_CELL: f32 = 0.1;

/// Whether, with `extra` standing in the room too, a base of [`PATH_RADIUS`] can still go
/// between every pair of the room's ways in (true when there are none to keep).
fn paths_kept(f: &Furnishing, extra: &Rect) -> bool {
    if f.ways.is_empty() {
        return true;
    }
    let r = f.inner;
    let n = [
        ((r.max[0] - r.min[0]) / PATH_CELL).floor() as usize,
        ((r.max[1] - r.min[1]) / PATH_CELL).floor() as usize,
    ];
    let centre = |i: usize, j: usize| {
        [
            r.min[0] + (i as f32 + 0.5) * PATH_CELL,
            r.min[1] + (j as f32 + 0.5) * PATH_CELL,
        ]
    };
    let near = |p: [f32; 2], q: &Rect| {
        let dx = (q.min[0] - p[0]).max(p[0] - q.max[0]).max(0.0);
        let dy = (q.min[1] - p[1]).max(p[1] - q.max[1]).max(0.0);
        dx * dx + dy * dy < PATH_RADIUS * PATH_RADIUS
    };
    let inside = |p: [f32; 2], q: &Rect| {
        (q.min[0]..=q.max[0]).contains(&p[0]) && (q.min[1]..=q.max[1]).contains(&p[1])
    };
    // The walls block as furniture does (a base keeps its radius from them); a way's cells
    // reach far enough into the room to be met clear of them.
    let off_walls = |p: [f32; 2]| {
        let edge = (p[0] - r.min[0])
            .min(r.max[0] - p[0])
            .min(p[1] - r.min[1])
            .min(r.max[1] - p[1]);
        edge + 0.02 >= PATH_RADIUS
    };
    let free = |p: [f32; 2]| off_walls(p) && !f.placed.iter().chain([extra]).any(|q| near(p, q));
    let mut seen = vec![false; n[0] * n[1]];
    let mut queue = Vec::new();
    let (mut i0, mut j0) = (0, 0);
    'start: for i in 0..n[0] {
        for j in 0..n[1] {
            if inside(centre(i, j), &f.ways[0]) && free(centre(i, j)) {
                (i0, j0) = (i, j);
                break 'start;
            }
        }
    }
    if !free(centre(i0, j0)) || !inside(centre(i0, j0), &f.ways[0]) {
        return false;
    }
    seen[i0 * n[1] + j0] = true;
    queue.push((i0, j0));
    while let Some((i, j)) = queue.pop() {
        let steps = [
            (i.wrapping_sub(1), j),
            (i + 1, j),
            (i, j.wrapping_sub(1)),
            (i, j + 1),
        ];
        for (a, b) in steps {
            if a < n[0] && b < n[1] && !seen[a * n[1] + b] && free(centre(a, b)) {
                seen[a * n[1] + b] = true;
                queue.push((a, b));
            }
        }
    }
    f.ways[1..].iter().all(|way| {
        (0..n[0]).any(|i| (0..n[1]).any(|j| seen[i * n[1] + j] && inside(centre(i, j), way)))
    })
}

/// Quarter turns of an item backed against wall `w` (0 north, 1 east, 2 south, 3 west), its
/// front facing into the room; the same list maps an item's turns back to its wall.
const WALL_TURNS: [u8; 4] = [0, 3, 2, 1];

/// The wall an item with these turns is backed against.
fn wall_of(turns: u8) -> usize {
    WALL_TURNS.iter().position(|&t| t == turns % 4).unwrap_or(0)
}

/// Where an item of `size` backed against wall `wall` with its centre at `t` along it stands,
/// its turns and footprint.
fn wall_spot(r: &Rect, size: Vector, wall: usize, t: f32) -> ([f32; 2], u8, Rect) {
    wall_spot_off(r, size, wall, t, 0.0)
}

/// [`wall_spot`], standing `off` out from the wall.
fn wall_spot_off(r: &Rect, size: Vector, wall: usize, t: f32, off: f32) -> ([f32; 2], u8, Rect) {
    let (w, d) = (size.x, size.y);
    let turns = WALL_TURNS[wall];
    let (x, y) = match wall {
        0 => (t, r.max[1] - off - d / 2.0),
        1 => (r.max[0] - off - d / 2.0, t),
        2 => (t, r.min[1] + off + d / 2.0),
        _ => (r.min[0] + off + d / 2.0, t),
    };
    ([x, y], turns, footprint(x, y, w, d, turns))
}

/// The stretch of wall `wall` of `r` items can stand along.
fn along(r: &Rect, wall: usize) -> (f32, f32) {
    if wall.is_multiple_of(2) {
        (r.min[0], r.max[0])
    } else {
        (r.min[1], r.max[1])
    }
}

/// The coordinate along its wall of an item standing at (x, y) against wall `wall`.
fn along_of(wall: usize, [x, y]: [f32; 2]) -> f32 {
    if wall.is_multiple_of(2) { x } else { y }
}

impl Furnishing {
    /// Whether the piece being placed may take `rect` against wall `wall`: inside the room,
    /// clear of what is taken (and of low windows' sills as its [`SillRule`] says), and leaving
    /// the room's paths.
    fn free_by_a_wall(&self, rect: &Rect, wall: usize) -> bool {
        let clear_of_sills = |r: &Rect| self.sills.iter().all(|o| !r.overlaps(o, GAP));
        let sills = match self.sill_rule {
            SillRule::Clear => clear_of_sills(rect),
            SillRule::Under => true,
            SillRule::BackClear => clear_of_sills(&back_of(rect, wall)),
        };
        rect.within_by(&self.inner, ROUNDING)
            && self.taken.iter().all(|o| !rect.overlaps(o, GAP))
            && sills
            && paths_kept(self, rect)
    }

    /// Takes `rect` for an item.
    fn take(&mut self, rect: Rect) {
        self.taken.push(rect);
        self.placed.push(rect);
    }

    /// Backs an item against a wall, facing into the room, at the first free spot going along
    /// the walls from wall `start` (0 north, 1 east, 2 south, 3 west) round the room.
    pub(super) fn against_a_wall(&mut self, size: Vector, start: usize) -> Option<([f32; 3], u8)> {
        let r = self.inner;
        for k in 0..4 {
            let wall = (start + k) % 4;
            let (along_lo, along_hi) = along(&r, wall);
            let w = size.x;
            let mut t = along_lo + w / 2.0;
            while t + w / 2.0 <= along_hi {
                let ([x, y], turns, rect) = wall_spot(&r, size, wall, t);
                if self.free_by_a_wall(&rect, wall) {
                    self.take(rect);
                    return Some(([x, y, 0.0], turns));
                }
                t += 0.1;
            }
        }
        None
    }

    /// Backs an item against wall `wall` as near `target` along it as is free (within 1.5 m).
    pub(super) fn near(
        &mut self,
        size: Vector,
        wall: usize,
        target: f32,
    ) -> Option<([f32; 3], u8)> {
        self.near_off(size, wall, target, 0.0)
    }

    /// [`Furnishing::near`], standing `off` out from the wall.
    fn near_off(
        &mut self,
        size: Vector,
        wall: usize,
        target: f32,
        off: f32,
    ) -> Option<([f32; 3], u8)> {
        let r = self.inner;
        let (lo, hi) = along(&r, wall);
        let w = size.x;
        for k in 0..60 {
            let t = target + 0.05 * (k / 2) as f32 * if k % 2 == 0 { 1.0 } else { -1.0 };
            if t - w / 2.0 < lo || t + w / 2.0 > hi {
                continue;
            }
            let ([x, y], turns, rect) = wall_spot_off(&r, size, wall, t, off);
            if self.free_by_a_wall(&rect, wall) {
                self.take(rect);
                return Some(([x, y, 0.0], turns));
            }
        }
        None
    }

    /// Exactly at `t` along wall `wall`, if free.
    fn exactly(&mut self, size: Vector, wall: usize, t: f32) -> Option<([f32; 3], u8)> {
        let r = self.inner;
        let (lo, hi) = along(&r, wall);
        if t - size.x / 2.0 < lo || t + size.x / 2.0 > hi {
            return None;
        }
        let ([x, y], turns, rect) = wall_spot(&r, size, wall, t);
        self.free_by_a_wall(&rect, wall).then(|| {
            self.take(rect);
            ([x, y, 0.0], turns)
        })
    }
}

/// A piece of furniture already standing in the room: its centre on the floor, its wall, its
/// size and turns.
pub(super) struct Standing {
    centre: [f32; 2],
    wall: usize,
    size: [f32; 3],
    turns: u8,
}

impl Standing {
    /// The first object of `synset` in room `room` among `objects`.
    pub(super) fn find(objects: &[ObjectPlan], room: usize, synset: &str) -> Option<Standing> {
        let o = objects
            .iter()
            .find(|o| o.room == room && o.synset == synset)?;
        Some(Standing {
            centre: [o.position[0], o.position[1]],
            wall: wall_of(o.yaw_quarter_turns),
            size: o.size,
            turns: o.yaw_quarter_turns,
        })
    }

    /// The unit vector its front faces.
    fn front(&self) -> [f32; 2] {
        [[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]][usize::from(self.turns % 4)]
    }
}

impl Furnishing {
    /// A table in front of a sofa, 45 cm from its seat's edge, long side along it.
    pub(super) fn facing(&mut self, size: Vector, sofa: &Standing) -> Option<([f32; 3], u8)> {
        let n = sofa.front();
        let reach = sofa.size[1] / 2.0 + 0.45 + size.y / 2.0;
        let (x, y) = (sofa.centre[0] + n[0] * reach, sofa.centre[1] + n[1] * reach);
        let rect = footprint(x, y, size.x, size.y, sofa.turns);
        let clear = rect.within_by(&self.inner, ROUNDING)
            && self.taken.iter().all(|o| !rect.overlaps(o, 0.3))
            && paths_kept(self, &rect);
        clear.then(|| {
            self.take(rect);
            ([x, y, 0.0], sofa.turns)
        })
    }

    /// An item against the wall across the room from `sofa`, as near straight ahead of it as is
    /// free: where a screen stands.
    pub(super) fn across_from(&mut self, size: Vector, sofa: &Standing) -> Option<([f32; 3], u8)> {
        let wall = (sofa.wall + 2) % 4;
        self.near(size, wall, along_of(sofa.wall, sofa.centre))
    }

    /// A nightstand at the head of `bed`, against the same wall: on one side, else the other.
    pub(super) fn beside(&mut self, size: Vector, bed: &Standing) -> Option<([f32; 3], u8)> {
        let t = along_of(bed.wall, bed.centre);
        let off = bed.size[0] / 2.0 + GAP + 0.01 + size.x / 2.0;
        self.exactly(size, bed.wall, t - off)
            .or_else(|| self.exactly(size, bed.wall, t + off))
    }

    /// An item under one of the room's low windows (sill at [`SILL`]), centred on it where free,
    /// and the kitchen's run of counters starting from that wall.
    pub(super) fn under_a_window(
        &mut self,
        size: Vector,
        windows: &[ObjectPlan],
    ) -> Option<([f32; 3], u8)> {
        for w in windows.iter().filter(|w| w.variant == 0) {
            let wall = wall_of(w.yaw_quarter_turns);
            let t = along_of(wall, [w.position[0], w.position[1]]);
            // A sink stands out from the wall, its tap clear of the casement.
            let rule = std::mem::replace(&mut self.sill_rule, SillRule::Under);
            let spot = self.near_off(size, wall, t, BEFORE_A_WINDOW);
            self.sill_rule = rule;
            if let Some(spot) = spot {
                self.run = Some(wall);
                return Some(spot);
            }
        }
        None
    }
}

/// Stands the microwave on the room's longest countertop.
pub(super) fn on_countertop(
    objects: &[ObjectPlan],
    room: usize,
    size: Vector,
) -> Option<([f32; 3], u8)> {
    // The longest, which keeps the most free beside it.
    let counter = objects
        .iter()
        .filter(|o| o.room == room && o.synset == "countertop.n.01")
        .max_by(|a, b| a.size[0].total_cmp(&b.size[0]))?;
    let fits = size.x <= counter.size[0] && size.y <= counter.size[1];
    fits.then(|| {
        let [x, y, z] = counter.position;
        (
            [x, y, z + counter.size[2] + 0.002],
            counter.yaw_quarter_turns,
        )
    })
}

/// Puts a table near the room's middle, or a chair beside the room's last table (none where
/// the room has no table, or no room is left beside it).
pub(super) fn in_the_middle(
    f: &mut Furnishing,
    size: Vector,
    chair: bool,
) -> Option<([f32; 3], u8)> {
    let r = f.inner;
    let mut candidates: Vec<([f32; 2], u8)> = Vec::new();
    if chair {
        candidates.extend(beside_the_last_table(f, size));
    }
    let center = [(r.min[0] + r.max[0]) / 2.0, (r.min[1] + r.max[1]) / 2.0];
    let rings = if chair { 0 } else { 12 };
    for ring in 0..rings {
        let step = 0.25 * ring as f32;
        for (dx, dy) in [
            (0.0, 0.0),
            (step, 0.0),
            (-step, 0.0),
            (0.0, step),
            (0.0, -step),
            (step, step),
            (-step, -step),
        ] {
            candidates.push(([center[0] + dx, center[1] + dy], 0));
        }
    }
    // A table keeps 30 cm from everything; a chair, whose spot is already that far from its
    // table, only the gap between pieces (chairs side by side at a table).
    let margin = if chair { GAP } else { 0.3 };
    for ([x, y], turns) in candidates {
        let rect = footprint(x, y, size.x, size.y, turns);
        if rect.within_by(&r, ROUNDING)
            && f.taken.iter().all(|o| !rect.overlaps(o, margin))
            && paths_kept(f, &rect)
        {
            f.take(rect);
            return Some(([x, y, 0.0], turns));
        }
    }
    None
}

/// Spots for a chair on each side of the room's last table, facing it: two along each side long
/// enough for two chairs, else one at its middle.
fn beside_the_last_table(f: &Furnishing, size: Vector) -> Vec<([f32; 2], u8)> {
    let Some(table) = f.tables.last() else {
        return Vec::new();
    };
    let (cx, cy) = (
        (table.min[0] + table.max[0]) / 2.0,
        (table.min[1] + table.max[1]) / 2.0,
    );
    // 32 cm out from the table: a chair pulled up to it, with room to sit.
    let off = size.y / 2.0 + 0.32;
    let (below, above) = (table.min[1] - off, table.max[1] + off);
    let (left, right) = (table.min[0] - off, table.max[0] + off);
    let pair = size.x * 2.0 + 0.1;
    let (w, d) = (table.max[0] - table.min[0], table.max[1] - table.min[1]);
    // Along x (below and above the table), then along y (left and right of it).
    let along_x = |at: f32, turns: u8| -> Vec<([f32; 2], u8)> {
        if w >= pair {
            vec![([cx - w / 4.0, at], turns), ([cx + w / 4.0, at], turns)]
        } else {
            vec![([cx, at], turns)]
        }
    };
    let along_y = |at: f32, turns: u8| -> Vec<([f32; 2], u8)> {
        if d >= pair {
            vec![([at, cy - d / 4.0], turns), ([at, cy + d / 4.0], turns)]
        } else {
            vec![([at, cy], turns)]
        }
    };
    let mut spots = along_x(below, 2);
    spots.extend(along_x(above, 0));
    spots.extend(along_y(left, 1));
    spots.extend(along_y(right, 3));
    spots
}

/// A table across the opening, its long side crossing it and its centre 0.15 m inside the
/// living room, clear of both rooms' doorways, of the passages kept through openings and of the
/// walls; its position, turns and footprint.
pub(super) fn at_the_opening(
    open: &Opening,
    plan: &Plan,
    [living, dining]: [usize; 2],
    size: Vector,
    passages: &[Rect],
) -> Option<([f32; 3], u8, Rect)> {
    let gap = open.gap;
    // Across the opening's line, and along it.
    let (across, along) = if gap.vertical { (0, 1) } else { (1, 0) };
    let toward_dining = into_room(gap.vertical, gap.at, &plan.rooms[dining])[across];
    let c = gap.at - toward_dining * 0.15;
    let turns = u8::from(!gap.vertical);
    let half = WALL_THICKNESS / 2.0 + 0.3;
    let clear: Vec<Rect> = plan
        .doors
        .iter()
        .filter(|d| d.touches(living) || d.touches(dining))
        .map(|d| d.clearance())
        .chain(passages.iter().copied())
        .collect();
    let (l, d) = (&plan.rooms[living], &plan.rooms[dining]);
    let low = l.min[across].min(d.min[across]);
    let high = l.max[across].max(d.max[across]);
    let mid = (gap.span[0] + gap.span[1]) / 2.0;
    let at = |t: f32| if gap.vertical { (c, t) } else { (t, c) };
    // From the middle of the opening outwards, in 10 cm steps.
    (0..40)
        .map(|k| mid + 0.1 * (k / 2) as f32 * if k % 2 == 0 { 1.0 } else { -1.0 })
        .map(|t| {
            let (x, y) = at(t);
            footprint(x, y, size.x, size.y, turns)
        })
        .find(|rect| {
            rect.min[along] >= gap.span[0] + half
                && rect.max[along] <= gap.span[1] - half
                && clear.iter().all(|c| !rect.overlaps(c, GAP))
                && rect.min[across] > low + half
                && rect.max[across] < high - half
        })
        .map(|rect| {
            let (x, y) = at((rect.min[along] + rect.max[along]) / 2.0);
            ([x, y, 0.0], turns, rect)
        })
}
