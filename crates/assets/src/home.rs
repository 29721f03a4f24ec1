//! Procedural homes: a floor plan, walls with doorways and doors, windows, and furniture per room
//! type, from a seed.
//!
//! The plan is a corridor along x with rooms on both sides, each opening onto it through a
//! doorway (so every room is reachable, and the corridor stays clear for the agent), and a front
//! door at the corridor's west end. Every home has a kitchen, a living room, a bathroom and a
//! bedroom; three more rooms are drawn from the other types. Each room type gets the furniture the
//! official activities look for in it (`inroom` literals), placed against the walls without
//! overlaps and out of the doorways' way; tables stand in the middle with chairs beside them, and
//! the microwave stands on a countertop. An item that does not fit is left out (coverage
//! reports what a home lacks). [`NAMED_HOMES`] are fifteen fixed seeds forming the default set.
//!
//! A dining room, when there is one (the first, when there are several), adjoins the living room
//! with no wall between them: an open plan, as in many homes and in iGibson's scans, where the
//! rooms are told apart by the floor map only. One of the living room's tables stands at that
//! opening, its centre just inside the living room and its far end over the dining room's floor.
//! This is what makes `collect_misplaced_items` possible as written: its shoe lies under a
//! living-room table and on the dining room's floor.
//!
//! [`generate`] runs three steps, each in a private module of its own, all drawing from the
//! home's one generator in a fixed order (so a seed gives one home, bit for bit): `plan` lays out
//! the rooms and their doorways, `walls` raises the walls (and places the doors and windows in
//! them), `furnish` fills each room; `footprint` holds the floor rectangles they share.

mod connect;
mod footprint;
mod furnish;
mod layout;
mod legacy;
mod plan;
mod program;
mod walls;

pub use program::{Family, RoomSpec, UnknownFamily, room_spec};

use crate::library::{AssetError, Library};
use crate::scene::Scene;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

/// The default homes: name and seed.
pub const NAMED_HOMES: [(&str, u64); 15] = [
    ("alder", 101),
    ("birch", 102),
    ("cedar", 103),
    ("dogwood", 104),
    ("elm", 105),
    ("fir", 106),
    ("ginkgo", 107),
    ("hazel", 108),
    ("juniper", 109),
    ("larch", 110),
    ("maple", 111),
    ("oak", 112),
    ("pine", 113),
    ("rowan", 114),
    ("willow", 115),
];

/// Of every wall (m); walls stand centred on room edges, half in each room.
pub const WALL_THICKNESS: f32 = 0.1;
/// Of the corridor the rooms open onto (m): room for the agent to pass open doors.
pub const CORRIDOR_WIDTH: f32 = 1.6;
/// Width of a doorway (m); doors are drawn a little narrower so they swing free.
pub const DOORWAY: f32 = 1.0;
/// Kept free in front of a doorway, on both sides (m).
pub const DOOR_CLEARANCE: f32 = 1.1;

/// The fifteen [`NAMED_HOMES`], generated in their fixed order.
pub fn named_homes(library: &Library) -> Result<Vec<Scene>, AssetError> {
    NAMED_HOMES
        .iter()
        .map(|(n, s)| generate(n, *s, library))
        .collect()
}

/// The named home called `name`, generated; `None` if no named home is called so.
pub fn named_home(name: &str, library: &Library) -> Option<Result<Scene, AssetError>> {
    let (n, seed) = NAMED_HOMES.iter().find(|(n, _)| *n == name)?;
    Some(generate(n, *seed, library))
}

/// How many programs and layouts a home draws before giving up on its seed: over thousands of
/// seeds of every family the most any took was far below this (see the tests).
const ATTEMPTS: usize = 400;

/// Generates the home of a seed. Named homes pass their name; any other seed makes a new home
/// of the family [`Family::of_seed`] gives it.
pub fn generate(name: &str, seed: u64, library: &Library) -> Result<Scene, AssetError> {
    if NAMED_HOMES.contains(&(name, seed)) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let plan = legacy::plan(name, seed, &mut rng);
        return finish(name, seed, None, plan, library, &mut rng);
    }
    generate_family(name, seed, Family::of_seed(seed), library)
}

/// Generates a home of `family` from a seed: a program of rooms drawn for the family, laid out,
/// joined by doors and openings, with windows, then furnished. A program whose layout breaks a
/// room's specification, or leaves a room unreachable, is drawn again.
pub fn generate_family(
    name: &str,
    seed: u64,
    family: Family,
    library: &Library,
) -> Result<Scene, AssetError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..ATTEMPTS {
        let wants = program::program(family, &mut rng);
        let Some(layout) = layout::lay_out(family, &wants, &mut rng) else {
            continue;
        };
        let rooms = connect::rooms(&layout);
        if let Some(plan) = connect::connect(family, rooms, &mut rng) {
            return finish(name, seed, Some(family), plan, library, &mut rng);
        }
    }
    Err(AssetError::NoPlan {
        family: family.name(),
        seed,
    })
}

/// The home of a plan: its walls and its furnishing.
fn finish(
    name: &str,
    seed: u64,
    family: Option<Family>,
    plan: plan::Plan,
    library: &Library,
    rng: &mut ChaCha8Rng,
) -> Result<Scene, AssetError> {
    let walls = walls::walls(&plan);
    let objects = furnish::furnish(&plan, library, rng)?;
    Ok(Scene {
        name: name.to_string(),
        seed,
        family,
        rooms: plan.rooms,
        walls,
        objects,
        clutter: Vec::new(),
    })
}
