//! Furnishing: what stands in a room of each type, and where. Items go against the walls without
//! overlaps and out of the doorways' way; tables stand in the middle with chairs beside them; the
//! microwave stands on a countertop; one living-room table stands across the open plan's
//! opening, placed first so that both rooms furnish around it. An item that does not fit is left
//! out (coverage reports what a home lacks).

use super::WALL_THICKNESS;
use super::footprint::{Rect, footprint};
use super::plan::{Opening, Plan};
use crate::library::{AssetError, Library};
use crate::scene::ObjectPlan;
use behavior_core::RoomType;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use rapier3d::math::Vector;
use std::collections::BTreeMap;

/// Between pieces of furniture (m).
const GAP: f32 = 0.05;

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
        _ => &["shelf.n.01", "cabinet.n.01"], // closet
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
    pub(super) taken: Vec<Rect>,
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
    let shared_table = match &plan.opening {
        Some(open) => home.table_at_the_opening(open)?,
        None => None,
    };
    for index in 0..plan.rooms.len() {
        if index == plan.corridor {
            // The corridor stays clear except for the front door.
            home.front_door()?;
        } else {
            home.room(index, shared_table)?;
        }
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
    fn table_at_the_opening(&mut self, open: &Opening) -> Result<Option<Rect>, AssetError> {
        let (size, variant) = self.library.sample("table.n.02", self.rng)?;
        let Some((position, rect)) = at_the_opening(open, self.plan, size) else {
            return Ok(None);
        };
        let name = self.name("table.n.02");
        self.objects.push(ObjectPlan {
            name,
            synset: "table.n.02".into(),
            room: open.living,
            position,
            yaw_quarter_turns: 0,
            size: size.to_array(),
            variant,
            joints: Vec::new(),
        });
        Ok(Some(rect))
    }

    /// A room off the corridor: its door, its windows, then its furniture.
    fn room(&mut self, index: usize, shared_table: Option<Rect>) -> Result<(), AssetError> {
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
        };
        let mut tables_to_skip = 0;
        if let (Some(open), Some(rect)) = (&plan.opening, shared_table) {
            if index == open.living || index == open.dining {
                f.taken.push(rect);
            }
            if index == open.living {
                tables_to_skip = 1; // it is one of the living room's tables
            }
        }
        // Keep the room's doorway clear, on both sides of its wall.
        for doorway in plan.doorways.iter().filter(|d| d.room == index) {
            f.taken.push(doorway.clearance());
        }
        self.room_door(index)?;
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
            if rect.within(&r) && f.taken.iter().all(|o| !rect.overlaps(o, GAP)) {
                f.taken.push(rect);
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
        if rect.within(&r) && f.taken.iter().all(|o| !rect.overlaps(o, 0.3)) {
            f.taken.push(rect);
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

/// A table across the opening, long side along x, its centre 0.15 m inside the living room, clear
/// of both rooms' doorways and the walls; its position and footprint.
fn at_the_opening(open: &Opening, plan: &Plan, size: Vector) -> Option<([f32; 3], Rect)> {
    let x = open.x - open.toward_dining * 0.15;
    let half = WALL_THICKNESS / 2.0 + 0.3;
    let clear: Vec<Rect> = plan
        .doorways
        .iter()
        .filter(|d| d.room == open.living || d.room == open.dining)
        .map(|d| d.clearance())
        .collect();
    let (l, d) = (&plan.rooms[open.living], &plan.rooms[open.dining]);
    let (west, east) = (l.min[0].min(d.min[0]), l.max[0].max(d.max[0]));
    let mid = (open.y[0] + open.y[1]) / 2.0;
    // From the middle of the opening outwards, in 10 cm steps.
    (0..40)
        .map(|k| mid + 0.1 * (k / 2) as f32 * if k % 2 == 0 { 1.0 } else { -1.0 })
        .map(|y| footprint(x, y, size.x, size.y, 0))
        .find(|rect| {
            rect.min[1] >= open.y[0] + half
                && rect.max[1] <= open.y[1] - half
                && clear.iter().all(|c| !rect.overlaps(c, GAP))
                && rect.min[0] > west + half
                && rect.max[0] < east - half
        })
        .map(|rect| {
            let y = (rect.min[1] + rect.max[1]) / 2.0;
            ([x, y, 0.0], rect)
        })
}
