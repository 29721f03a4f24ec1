//! Furnishing: what stands in a room of each type, and where. Items go against the walls without
//! overlaps and out of the doorways' way; tables stand in the middle with chairs beside them; the
//! microwave stands on a countertop; one living-room table stands across the open plan's
//! opening, placed first so that both rooms furnish around it. An item that does not fit is left
//! out (coverage reports what a home lacks).

use super::WALL_THICKNESS;
use super::arrange::{
    Furnishing, SillRule, Standing, at_the_opening, in_the_middle, on_countertop,
};
use super::footprint::{Rect, footprint};
use super::plan::{Opening, Plan, Segment};
use crate::library::{AssetError, Library};
use crate::scene::ObjectPlan;
use behavior_core::RoomType;
use behavior_core::WINDOW_SYNSET;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use rapier3d::math::Vector;
use std::collections::BTreeMap;

/// The width along a wide opening of the passage kept free through it (m), as a doorway's.
const PASSAGE: f32 = 1.2;

/// How deep on each side of a wide opening its passage reaches (m): no leaf swings there, so
/// less than a doorway's [`super::DOOR_CLEARANCE`]; the paths kept through the room do the rest.
const PASSAGE_DEPTH: f32 = 0.7;

/// The passage kept free through a wide opening: [`PASSAGE`] wide and [`PASSAGE_DEPTH`] deep on
/// both sides; at the opening's middle, or at one of its ends (`shift` −1 or 1), 35 cm from it.
fn passage(open: &Opening, shift: f32) -> Rect {
    let gap = open.gap;
    let room = (gap.length() - PASSAGE) / 2.0 - 0.35;
    let mid = (gap.span[0] + gap.span[1]) / 2.0 + shift * room.max(0.0);
    Segment {
        span: [mid - PASSAGE / 2.0, mid + PASSAGE / 2.0],
        ..gap
    }
    .band(PASSAGE_DEPTH, 0.0)
}

/// How a piece of furniture is placed in its room (see `arrange.rs`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Place {
    /// Backed against a wall, from a wall drawn at random.
    Wall,
    /// Near the room's middle.
    Middle,
    /// Beside the room's last table, facing it.
    Chair,
    /// On the room's first countertop.
    OnCounter,
    /// Under a low window where the room has one; the kitchen's run starts there.
    UnderWindow,
    /// In the kitchen's run along the walls.
    Run,
    /// In front of the room's sofa.
    FacingSofa,
    /// Across the room from its sofa.
    Screen,
    /// Beside the head of the room's bed, at a nightstand's size.
    Nightstand,
}

use Place::*;

/// What stands in a room of each type, in the order placed: the pieces the official activities
/// look for in it (`inroom` literals), and chairs round the dining table. Kitchens and bedrooms
/// keep floor free for what activities set down on it (plywood sheets, a seat).
fn furniture(kind: RoomType) -> &'static [(&'static str, Place)] {
    match kind {
        RoomType::Kitchen => &[
            ("sink.n.01", UnderWindow),
            ("countertop.n.01", Run),
            ("dishwasher.n.01", Run),
            ("countertop.n.01", Run),
            ("stove.n.01", Run),
            ("oven.n.01", Run),
            ("electric_refrigerator.n.01", Run),
            ("cabinet.n.01", Run),
            ("cabinet.n.01", Run),
            ("table.n.02", Middle),
            ("chair.n.01", Chair),
            ("microwave.n.02", OnCounter),
        ],
        RoomType::LivingRoom => &[
            ("sofa.n.01", Wall),
            ("table.n.02", FacingSofa),
            ("cabinet.n.01", Screen),
            ("shelf.n.01", Wall),
            ("table.n.02", Middle),
        ],
        RoomType::Bedroom => &[
            ("bed.n.01", Wall),
            ("cabinet.n.01", Nightstand),
            ("cabinet.n.01", Nightstand),
            ("cabinet.n.01", Wall),
            ("table.n.02", Wall),
        ],
        RoomType::DiningRoom => &[
            ("table.n.02", Middle),
            ("chair.n.01", Chair),
            ("chair.n.01", Chair),
            ("chair.n.01", Chair),
            ("chair.n.01", Chair),
        ],
        RoomType::HomeOffice => &[
            ("table.n.02", Wall),
            ("chair.n.01", Chair),
            ("cabinet.n.01", Wall),
        ],
        RoomType::StorageRoom => &[
            ("shelf.n.01", Wall),
            ("table.n.02", Wall),
            ("sink.n.01", Wall),
        ],
        RoomType::Bathroom => &[
            ("bathtub.n.01", Wall),
            ("shower.n.01", Wall),
            ("toilet.n.02", Wall),
            ("sink.n.01", Wall),
        ],
        RoomType::Garage => &[("shelf.n.01", Wall), ("cabinet.n.01", Wall)],
        RoomType::UtilityRoom => &[
            ("washer.n.03", Wall),
            ("dryer.n.01", Wall),
            ("sink.n.01", Wall),
            ("cabinet.n.01", Wall),
        ],
        RoomType::Closet => &[("shelf.n.01", Wall), ("cabinet.n.01", Wall)],
        _ => &[], // halls stay clear
    }
}

/// What stands in the annex of an L-shaped room of each type (an alcove): one piece against
/// its wall.
fn annex_furniture(kind: RoomType) -> &'static [(&'static str, Place)] {
    match kind {
        RoomType::LivingRoom | RoomType::HomeOffice | RoomType::StorageRoom => {
            &[("shelf.n.01", Wall)]
        }
        RoomType::Corridor | RoomType::Garage => &[],
        _ => &[("cabinet.n.01", Wall)],
    }
}

/// The least length and width of a dining room's table (m): it seats four and holds their
/// plates, cups and bowls.
const DINING_TABLE: [f32; 2] = [1.5, 0.9];

/// The width of a single bed (m), the narrowest the catalogue makes.
const SINGLE_BED: f32 = 1.0;

/// The size a piece drawn at `drawn` is placed at first in a room of `kind`, and the smaller one
/// tried where that fits nowhere: a dining table at least [`DINING_TABLE`] (else as drawn), a
/// double bed (else a single one).
fn sizes(synset: &str, kind: RoomType, drawn: Vector) -> (Vector, Option<Vector>) {
    match synset {
        "table.n.02" if kind == RoomType::DiningRoom => {
            let dining = Vector::new(
                drawn.x.max(DINING_TABLE[0]),
                drawn.y.max(DINING_TABLE[1]),
                drawn.z,
            );
            (dining, (dining != drawn).then_some(drawn))
        }
        "bed.n.01" if drawn.x > SINGLE_BED => {
            (drawn, Some(Vector::new(SINGLE_BED, drawn.y, drawn.z)))
        }
        _ => (drawn, None),
    }
}

/// How far from the open side between an L-shaped room's rectangles furniture keeps (m): none
/// stands along a side that has no wall.
const OPEN_SIDE: f32 = 0.45;

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
    // A passage through each wide opening kept clear, at its middle; across the living room's
    // opening onto a dining room, a table, and the passage beside it where the middle leaves no
    // room for one.
    let mut passages: Vec<Rect> = plan.openings.iter().map(|o| passage(o, 0.0)).collect();
    let mut shared = Vec::new();
    for (k, open) in plan.openings.iter().enumerate() {
        let kinds = open.rooms.map(|r| plan.rooms[r].kind);
        let (living, dining) = match kinds {
            [RoomType::LivingRoom, RoomType::DiningRoom] => (open.rooms[0], open.rooms[1]),
            [RoomType::DiningRoom, RoomType::LivingRoom] => (open.rooms[1], open.rooms[0]),
            _ => continue,
        };
        if shared.iter().any(|t: &SharedTable| t.living == living) {
            continue;
        }
        let (size, variant) = home.library.sample("table.n.02", home.rng)?;
        for shift in [0.0, -1.0, 1.0] {
            let kept = [passage(open, shift)];
            let spot = at_the_opening(open, plan, [living, dining], size, &kept);
            if let Some((position, turns, rect)) = spot {
                home.table_across(living, position, turns, size, variant);
                shared.push(SharedTable {
                    living,
                    dining,
                    rect,
                });
                passages[k] = kept[0];
                break;
            }
        }
    }
    for index in 0..plan.rooms.len() {
        home.room(index, &shared, &passages)?;
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

    /// The living room's table across the opening onto the dining room.
    fn table_across(
        &mut self,
        living: usize,
        position: [f32; 3],
        turns: u8,
        size: Vector,
        variant: u32,
    ) {
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
    }

    /// A room: its doors, its windows, then its furniture, kept out of its doorways' and its
    /// openings' passages.
    fn room(
        &mut self,
        index: usize,
        shared: &[SharedTable],
        passages: &[Rect],
    ) -> Result<(), AssetError> {
        let plan = self.plan;
        let room = &plan.rooms[index];
        let half = WALL_THICKNESS / 2.0;
        let inner = Rect {
            min: [room.min[0] + half + 0.02, room.min[1] + half + 0.02],
            max: [room.max[0] - half - 0.02, room.max[1] - half - 0.02],
        };
        let mut f = Furnishing::new(index, inner);
        let mut tables_to_skip = 0;
        for table in shared {
            if index == table.living || index == table.dining {
                f.taken.push(table.rect);
                f.placed.push(table.rect);
                f.tables.push(table.rect);
            }
            if index == table.living {
                tables_to_skip += 1; // it is one of the living room's tables
            }
        }
        // Keep the doorways clear, on both sides of their walls.
        for door in plan.doors.iter().filter(|d| d.touches(index)) {
            f.taken.push(door.clearance());
            f.ways.push(door.clearance());
        }
        for (open, &passage) in plan.openings.iter().zip(passages) {
            if open.rooms.contains(&index) {
                f.taken.push(passage);
                f.ways.push(passage);
                if open.inner {
                    f.taken.push(open.gap.band(OPEN_SIDE, 0.0));
                }
            }
        }
        self.doors(index)?;
        self.windows(&mut f)?;
        let list = if plan.annexes.iter().any(|a| a.part == index) {
            annex_furniture(room.kind)
        } else {
            furniture(room.kind)
        };
        self.furniture(&mut f, list, tables_to_skip)
    }

    /// The furniture of a room from its list, less the tables already standing in it (the
    /// first tables placed in the middle).
    fn furniture(
        &mut self,
        f: &mut Furnishing,
        list: &[(&str, Place)],
        mut tables_to_skip: usize,
    ) -> Result<(), AssetError> {
        for &(synset, place) in list {
            if synset == "table.n.02" && place == Middle && tables_to_skip > 0 {
                tables_to_skip -= 1;
                continue;
            }
            let (mut size, variant) = self.library.sample(synset, self.rng)?;
            if place == Nightstand {
                size = Vector::new(size.x.min(0.55), size.y.min(0.45), size.z.min(0.72));
            }
            let (first, fallback) = sizes(synset, self.plan.rooms[f.index].kind, size);
            size = first;
            f.sill_rule = SillRule::of(synset, size.z);
            let mut placed = self.place(f, place, size);
            if let Some(smaller) = fallback.filter(|_| placed.is_none()) {
                size = smaller;
                placed = self.place(f, place, size);
            }
            if let Some((position, turns)) = placed {
                if synset == "table.n.02" {
                    let [x, y, _] = position;
                    f.tables.push(footprint(x, y, size.x, size.y, turns));
                }
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

    /// Where an item of `size` placed by `place` stands, if anywhere.
    fn place(&mut self, f: &mut Furnishing, place: Place, size: Vector) -> Option<([f32; 3], u8)> {
        let room = f.index;
        let standing = |synset: &str| Standing::find(&self.objects, room, synset);
        match place {
            OnCounter => on_countertop(&self.objects, room, size),
            Middle => in_the_middle(f, size, false),
            Chair => in_the_middle(f, size, true),
            Wall => {
                let start = self.rng.next_u32() as usize % 4;
                f.against_a_wall(size, start)
            }
            UnderWindow => {
                let windows: Vec<ObjectPlan> = self
                    .objects
                    .iter()
                    .filter(|o| o.room == room && o.synset == WINDOW_SYNSET)
                    .cloned()
                    .collect();
                f.under_a_window(size, &windows)
                    .or_else(|| self.place(f, Run, size))
            }
            Run => {
                let start = match f.run {
                    Some(wall) => wall,
                    None => {
                        let wall = self.rng.next_u32() as usize % 4;
                        f.run = Some(wall);
                        wall
                    }
                };
                f.against_a_wall(size, start)
            }
            FacingSofa => match standing("sofa.n.01") {
                Some(sofa) => f.facing(size, &sofa),
                None => None,
            }
            .or_else(|| in_the_middle(f, size, false)),
            Screen => match standing("sofa.n.01") {
                Some(sofa) => f.across_from(size, &sofa),
                None => None,
            }
            .or_else(|| self.place(f, Wall, size)),
            Nightstand => match standing("bed.n.01") {
                Some(bed) => f.beside(size, &bed),
                None => None,
            }
            .or_else(|| self.place(f, Wall, size)),
        }
    }
}
