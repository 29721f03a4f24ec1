//! Furnishing: what stands in a room of each type, and where. Items go against the walls without
//! overlaps and out of the doorways' way; tables stand in the middle with chairs beside them; the
//! microwave stands on a countertop; one living-room table stands across the open plan's
//! opening, placed first so that both rooms furnish around it. An item that does not fit is left
//! out (coverage reports what a home lacks).

use super::WALL_THICKNESS;
use super::footprint::{Rect, footprint};
use super::plan::{Opening, Plan, into_room};
use crate::library::{AssetError, Library};
use crate::scene::ObjectPlan;
use behavior_core::RoomType;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use rapier3d::math::Vector;
use std::collections::BTreeMap;

/// Between pieces of furniture (m).
const GAP: f32 = 0.05;

/// Kept free on each side of a wide opening that the plan keeps clear (m).
const OPENING_CLEARANCE: f32 = 0.8;

/// What stands in a room of each type, biggest first; `table` and `chair` go in the middle.
fn furniture(kind: RoomType) -> &'static [&'static str] {
    match kind {
        RoomType::Kitchen => &[
            "electric_refrigerator.n.01",
            "countertop.n.01",
            "countertop.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "dishwasher.n.01",
            "oven.n.01",
            "stove.n.01",
            "sink.n.01",
            "table.n.02",
            "chair.n.01",
            "microwave.n.02",
        ],
        RoomType::LivingRoom => &[
            "sofa.n.01",
            "shelf.n.01",
            "cabinet.n.01",
            "table.n.02",
            "table.n.02",
        ],
        RoomType::Bedroom => &[
            "bed.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "cabinet.n.01",
            "table.n.02",
        ],
        RoomType::Bathroom => &["bathtub.n.01", "shower.n.01", "toilet.n.02", "sink.n.01"],
        RoomType::DiningRoom => &["table.n.02", "chair.n.01", "chair.n.01"],
        RoomType::Garage => &["shelf.n.01", "cabinet.n.01"],
        RoomType::HomeOffice => &["cabinet.n.01", "table.n.02", "chair.n.01"],
        RoomType::StorageRoom => &["shelf.n.01", "sink.n.01", "table.n.02"],
        RoomType::UtilityRoom => &["washer.n.03", "dryer.n.01", "sink.n.01", "cabinet.n.01"],
        RoomType::Closet => &["shelf.n.01", "cabinet.n.01"],
        RoomType::Corridor => &[], // halls stay clear
    }
}

/// The state shared while a home is furnished: the plan, the library and the home's generator
/// (every draw in a fixed order, so a seed gives one home), and the objects placed so far with
/// the counters that name them.
pub(super) struct Furnisher<'a, 't> {
    pub(super) plan: &'a Plan,
    pub(super) library: &'a Library<'t>,
    pub(super) rng: &'a mut ChaCha8Rng,
    pub(super) objects: Vec<ObjectPlan>,
    names: BTreeMap<String, u32>,
}

/// A room being furnished: its floor inside the walls and the footprints already taken.
pub(super) struct Furnishing {
    pub(super) index: usize,
    inner: Rect,
    /// Where the room is entered (its doorways' clearances, its open sides), when paths between
    /// them must be kept for the robots; empty for the named homes' original plan.
    ways: Vec<Rect>,
    /// The footprints of the furniture on its floor so far.
    placed: Vec<Rect>,
    pub(super) taken: Vec<Rect>,
}

/// A living-room table standing across the opening onto a dining room: both rooms furnish
/// around its footprint, and it is one of the living room's tables.
#[derive(Clone, Copy)]
struct SharedTable {
    living: usize,
    dining: usize,
    rect: Rect,
}

/// Places the doors, windows and furniture of every room; the objects in the order placed.
pub(super) fn furnish(
    plan: &Plan,
    library: &Library,
    rng: &mut ChaCha8Rng,
) -> Result<Vec<ObjectPlan>, AssetError> {
    let mut home = Furnisher {
        plan,
        library,
        rng,
        objects: Vec::new(),
        names: BTreeMap::new(),
    };
    let mut shared = Vec::new();
    for open in &plan.openings {
        let kinds = open.rooms.map(|r| plan.rooms[r].kind);
        let (living, dining) = match kinds {
            [RoomType::LivingRoom, RoomType::DiningRoom] => (open.rooms[0], open.rooms[1]),
            [RoomType::DiningRoom, RoomType::LivingRoom] => (open.rooms[1], open.rooms[0]),
            _ => continue,
        };
        if shared.iter().any(|t: &SharedTable| t.living == living) {
            continue;
        }
        if let Some(rect) = home.table_at_the_opening(open, living, dining)? {
            shared.push(SharedTable {
                living,
                dining,
                rect,
            });
        }
    }
    for index in 0..plan.rooms.len() {
        home.room(index, &shared)?;
    }
    Ok(home.objects)
}

impl Furnisher<'_, '_> {
    /// A fresh name for an object of `synset`: its lemma and a counter, `table_0`, `table_1`…
    pub(super) fn name(&mut self, synset: &str) -> String {
        let lemma = synset.split('.').next().unwrap_or(synset).to_string();
        let n = self.names.entry(lemma.clone()).or_insert(0);
        *n += 1;
        format!("{lemma}_{}", *n - 1)
    }

    /// The living room's table across the opening onto the dining room, if one fits; its
    /// footprint, which both rooms then furnish around.
    fn table_at_the_opening(
        &mut self,
        open: &Opening,
        living: usize,
        dining: usize,
    ) -> Result<Option<Rect>, AssetError> {
        let (size, variant) = self.library.sample("table.n.02", self.rng)?;
        let Some((position, turns, rect)) = at_the_opening(open, self.plan, [living, dining], size)
        else {
            return Ok(None);
        };
        let name = self.name("table.n.02");
        self.objects.push(ObjectPlan {
            name,
            synset: "table.n.02".into(),
            room: living,
            position,
            yaw_quarter_turns: turns,
            size: size.to_array(),
            variant,
            joints: Vec::new(),
        });
        Ok(Some(rect))
    }

    /// A room: its doors, its windows, then its furniture, kept out of its doorways' way (and
    /// of the wide openings' where the plan asks).
    fn room(&mut self, index: usize, shared: &[SharedTable]) -> Result<(), AssetError> {
        let plan = self.plan;
        let room = &plan.rooms[index];
        let half = WALL_THICKNESS / 2.0;
        let mut f = Furnishing {
            index,
            inner: Rect {
                min: [room.min[0] + half + 0.02, room.min[1] + half + 0.02],
                max: [room.max[0] - half - 0.02, room.max[1] - half - 0.02],
            },
            taken: Vec::new(),
            ways: Vec::new(),
            placed: Vec::new(),
        };
        let mut tables_to_skip = 0;
        for table in shared {
            if index == table.living || index == table.dining {
                f.taken.push(table.rect);
                f.placed.push(table.rect);
            }
            if index == table.living {
                tables_to_skip += 1; // it is one of the living room's tables
            }
        }
        // Keep the doorways clear, on both sides of their walls.
        for door in plan.doors.iter().filter(|d| d.touches(index)) {
            f.taken.push(door.clearance());
            if plan.keep_paths {
                f.ways.push(door.clearance());
            }
        }
        for open in plan.openings.iter().filter(|o| o.keep_clear) {
            if open.rooms.contains(&index) {
                f.taken.push(open.gap.band(OPENING_CLEARANCE, 0.0));
                f.ways.push(open.gap.band(OPENING_CLEARANCE, 0.0));
            }
        }
        self.doors(index)?;
        self.windows(&mut f)?;
        self.furniture(&mut f, room.kind, tables_to_skip)
    }

    /// The furniture of a room of type `kind`, less the tables already standing in it.
    fn furniture(
        &mut self,
        f: &mut Furnishing,
        kind: RoomType,
        mut tables_to_skip: usize,
    ) -> Result<(), AssetError> {
        for synset in furniture(kind) {
            if *synset == "table.n.02" && tables_to_skip > 0 {
                tables_to_skip -= 1;
                continue;
            }
            let (size, variant) = self.library.sample(synset, self.rng)?;
            let plan = match *synset {
                "microwave.n.02" => on_countertop(&self.objects, f.index, size),
                "table.n.02" | "chair.n.01" => in_the_middle(f, size, synset == &"chair.n.01"),
                _ => against_a_wall(f, size, self.rng),
            };
            if let Some((position, turns)) = plan {
                let name = self.name(synset);
                let links = self
                    .library
                    .instance(synset, &name, size, variant)?
                    .links
                    .len();
                self.objects.push(ObjectPlan {
                    name,
                    synset: synset.to_string(),
                    room: f.index,
                    position,
                    yaw_quarter_turns: turns,
                    size: size.to_array(),
                    variant,
                    joints: vec![0.0; links],
                });
            }
        }
        Ok(())
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
    // A way's cells reach to the walls (a doorway is in one), so only furniture blocks them.
    let free = |p: [f32; 2]| !f.placed.iter().chain([extra]).any(|q| near(p, q));
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

/// Stands the microwave on the room's first countertop.
fn on_countertop(objects: &[ObjectPlan], room: usize, size: Vector) -> Option<([f32; 3], u8)> {
    let counter = objects
        .iter()
        .find(|o| o.room == room && o.synset == "countertop.n.01")?;
    let fits = size.x <= counter.size[0] && size.y <= counter.size[1];
    fits.then(|| {
        let [x, y, z] = counter.position;
        (
            [x, y, z + counter.size[2] + 0.002],
            counter.yaw_quarter_turns,
        )
    })
}

/// Backs an item against a wall, facing into the room, at the first free spot from a random
/// starting wall.
fn against_a_wall(
    f: &mut Furnishing,
    size: Vector,
    rng: &mut ChaCha8Rng,
) -> Option<([f32; 3], u8)> {
    let r = f.inner;
    let start = rng.next_u32() as usize % 4;
    for k in 0..4 {
        // Walls: north (front faces −y, 0 turns), east (faces −x, 3), south (+y, 2), west (+x, 1).
        let wall = (start + k) % 4;
        let turns: u8 = [0, 3, 2, 1][wall];
        let (along_lo, along_hi) = if wall.is_multiple_of(2) {
            (r.min[0], r.max[0])
        } else {
            (r.min[1], r.max[1])
        };
        let (w, d) = (size.x, size.y);
        let mut t = along_lo + w / 2.0;
        while t + w / 2.0 <= along_hi {
            let (x, y) = match wall {
                0 => (t, r.max[1] - d / 2.0),
                1 => (r.max[0] - d / 2.0, t),
                2 => (t, r.min[1] + d / 2.0),
                _ => (r.min[0] + d / 2.0, t),
            };
            let rect = footprint(x, y, w, d, turns);
            if rect.within(&r)
                && f.taken.iter().all(|o| !rect.overlaps(o, GAP))
                && paths_kept(f, &rect)
            {
                f.taken.push(rect);
                f.placed.push(rect);
                return Some(([x, y, 0.0], turns));
            }
            t += 0.1;
        }
    }
    None
}

/// Puts a table near the room's middle, or a chair beside the room's last table.
fn in_the_middle(f: &mut Furnishing, size: Vector, chair: bool) -> Option<([f32; 3], u8)> {
    let r = f.inner;
    let mut candidates: Vec<([f32; 2], u8)> = Vec::new();
    if chair {
        candidates.extend(beside_the_last_table(f, size));
    }
    let center = [(r.min[0] + r.max[0]) / 2.0, (r.min[1] + r.max[1]) / 2.0];
    for ring in 0..12 {
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
    for ([x, y], turns) in candidates {
        let rect = footprint(x, y, size.x, size.y, turns);
        if rect.within(&r) && f.taken.iter().all(|o| !rect.overlaps(o, 0.3)) && paths_kept(f, &rect)
        {
            f.taken.push(rect);
            f.placed.push(rect);
            return Some(([x, y, 0.0], turns));
        }
    }
    None
}

/// Spots for a chair on each side of the most recent table-sized footprint (the last one placed
/// in the middle), facing it.
fn beside_the_last_table(f: &Furnishing, size: Vector) -> Vec<([f32; 2], u8)> {
    let Some(table) = f
        .taken
        .iter()
        .rev()
        .find(|t| t.max[0] - t.min[0] > 0.5 && t.max[1] - t.min[1] > 0.5)
    else {
        return Vec::new();
    };
    let (cx, cy) = (
        (table.min[0] + table.max[0]) / 2.0,
        (table.min[1] + table.max[1]) / 2.0,
    );
    // Beyond the 0.3 m kept around every middle piece, so the chair is accepted.
    let off = size.y / 2.0 + 0.32;
    vec![
        ([cx, table.min[1] - off], 2),
        ([cx, table.max[1] + off], 0),
        ([table.min[0] - off, cy], 1),
        ([table.max[0] + off, cy], 3),
    ]
}

/// A table across the opening, its long side crossing it and its centre 0.15 m inside the
/// living room, clear of both rooms' doorways and of the walls; its position, turns and
/// footprint.
fn at_the_opening(
    open: &Opening,
    plan: &Plan,
    [living, dining]: [usize; 2],
    size: Vector,
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
