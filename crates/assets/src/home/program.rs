//! What a home holds before it is laid out: its plan family, and the rooms it asks for with their
//! areas, drawn from each room type's specification.
//!
//! The areas are ranges around the sizes of rooms in detached homes (a bedroom 11–18 m², a
//! bathroom 6–10 m², a kitchen 16–26 m²), widened upwards where the furniture the official
//! activities look for in a room must fit in it (a kitchen's run of twelve pieces, a bathroom's
//! bathtub and shower). The shortest side keeps a room usable by both robots and its furniture;
//! a garage's lets a car turned any way stand in it (the sampler turns what it sets on a floor
//! by a random yaw).

use behavior_core::RoomType;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// How a home's rooms are arranged: the plan families, after the kinds of house plan that are
/// common in real homes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// A corridor the length of the house with rooms on both sides, the front door at its end.
    Corridor,
    /// A hall from the front door through the middle, public rooms on one side and private
    /// rooms on the other.
    CentralHall,
    /// Living, dining and kitchen in one open space along the front, the private rooms behind
    /// them (off a hall where there are many).
    OpenPlan,
    /// An L: the public rooms in one wing, the bedrooms along a hall in the other.
    LShaped,
    /// A public block in the middle with a wing on each side: a main bedroom's suite in one, the
    /// other bedrooms along a hall in the other.
    TwoWings,
    /// A small home: a living room open onto its kitchen, a bathroom, perhaps a bedroom.
    Studio,
}

impl Family {
    /// Every family, in the order homes of free seeds cycle through them.
    pub const ALL: [Family; 6] = [
        Family::Corridor,
        Family::CentralHall,
        Family::OpenPlan,
        Family::LShaped,
        Family::TwoWings,
        Family::Studio,
    ];

    /// Its name on the command line and in scene files, e.g. `open_plan`.
    pub fn name(self) -> &'static str {
        match self {
            Family::Corridor => "corridor",
            Family::CentralHall => "central_hall",
            Family::OpenPlan => "open_plan",
            Family::LShaped => "l_shaped",
            Family::TwoWings => "two_wings",
            Family::Studio => "studio",
        }
    }

    /// The family a home of a free seed gets: the seeds cycle through them.
    pub fn of_seed(seed: u64) -> Family {
        Family::ALL[(seed % Family::ALL.len() as u64) as usize]
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name that is not one of the plan [`Family`]s.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown plan family `{0}` (known: corridor, central_hall, open_plan, l_shaped, two_wings, studio)"
)]
pub struct UnknownFamily(pub String);

impl FromStr for Family {
    type Err = UnknownFamily;

    fn from_str(s: &str) -> Result<Family, UnknownFamily> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| UnknownFamily(s.to_string()))
    }
}

/// Where a room belongs in the home.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Zone {
    /// Living, dining, kitchen: by the front door, open onto each other.
    Public,
    /// Bedrooms, bathrooms, the home office, closets: away from the front door.
    Private,
    /// Utility room, garage, storage: beside the kitchen.
    Service,
}

/// A room type's specification, which every room of a home generated from a family meets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoomSpec {
    /// Floor area, m², between the walls' centre lines.
    pub area: [f32; 2],
    /// The shortest side, m.
    pub min_side: f32,
}

/// The specification of a room type. Halls (corridors) take the width of a hall and whatever
/// length their plan gives them.
pub fn room_spec(kind: RoomType) -> RoomSpec {
    let (area, min_side) = match kind {
        RoomType::Kitchen => ([16.0, 26.0], 3.6),
        RoomType::LivingRoom => ([18.0, 32.0], 3.8),
        RoomType::DiningRoom => ([11.0, 18.0], 3.0),
        RoomType::Bedroom => ([11.0, 18.0], 3.0),
        RoomType::Bathroom => ([6.5, 11.0], 2.4),
        RoomType::HomeOffice => ([8.0, 14.0], 2.6),
        RoomType::Garage => ([24.0, 40.0], 4.8),
        RoomType::UtilityRoom => ([6.0, 11.0], 2.4),
        RoomType::StorageRoom => ([5.0, 11.0], 2.2),
        RoomType::Closet => ([4.0, 8.0], 1.8),
        RoomType::Corridor => ([2.0, 80.0], 1.4),
    };
    RoomSpec { area, min_side }
}

/// The zone of a room type.
pub(super) fn zone(kind: RoomType) -> Zone {
    match kind {
        RoomType::Kitchen | RoomType::LivingRoom | RoomType::DiningRoom => Zone::Public,
        RoomType::UtilityRoom | RoomType::Garage | RoomType::StorageRoom => Zone::Service,
        _ => Zone::Private,
    }
}

/// The most rooms a home has, its hall included.
pub(super) const MAX_ROOMS: usize = 12;

/// A room the program asks for: its type and its drawn area.
#[derive(Clone, Copy, Debug)]
pub(super) struct Want {
    pub(super) kind: RoomType,
    pub(super) area: f32,
}

/// A number drawn evenly from `lo..=hi`.
pub(super) fn count(rng: &mut ChaCha8Rng, lo: usize, hi: usize) -> usize {
    lo + rng.next_u32() as usize % (hi - lo + 1)
}

/// Whether a draw with probability `p` comes out true.
pub(super) fn chance(rng: &mut ChaCha8Rng, p: f32) -> bool {
    behavior_core::rng::uniform(rng, 0.0, 1.0) < p
}

/// The rooms of a home of `family` (halls are the layout's business), each with an area drawn
/// from its type's range: the public rooms first, then the private, then the service rooms.
pub(super) fn program(family: Family, rng: &mut ChaCha8Rng) -> Vec<Want> {
    use RoomType::*;
    let mut kinds = vec![LivingRoom, Kitchen];
    let (bedrooms, bathrooms, extras): ((usize, usize), (usize, usize), (usize, usize)) =
        match family {
            Family::Studio => ((0, 1), (1, 1), (0, 1)),
            Family::Corridor => ((1, 3), (1, 2), (1, 3)),
            Family::CentralHall => ((2, 3), (1, 2), (0, 2)),
            Family::OpenPlan => ((1, 3), (1, 2), (0, 2)),
            Family::LShaped => ((2, 3), (1, 2), (1, 3)),
            Family::TwoWings => ((2, 3), (2, 2), (1, 3)),
        };
    if family != Family::Studio {
        kinds.push(DiningRoom);
    }
    kinds.extend(std::iter::repeat_n(
        Bedroom,
        count(rng, bedrooms.0, bedrooms.1),
    ));
    kinds.extend(std::iter::repeat_n(
        Bathroom,
        count(rng, bathrooms.0, bathrooms.1),
    ));
    let pool: &[RoomType] = match family {
        Family::Studio => &[Closet],
        _ => &[HomeOffice, Closet, UtilityRoom, Garage, StorageRoom],
    };
    let mut pool = pool.to_vec();
    for _ in 0..count(rng, extras.0, extras.1) {
        let pick = pool.remove(rng.next_u32() as usize % pool.len());
        kinds.push(pick);
        // A garage mostly comes with a storage room beside it.
        if pick == Garage && pool.contains(&StorageRoom) && chance(rng, 0.6) {
            pool.retain(|&k| k != StorageRoom);
            kinds.push(StorageRoom);
        }
    }
    // Half the homes with bedrooms have a walk-in closet besides.
    if family != Family::Studio && !kinds.contains(&Closet) && chance(rng, 0.5) {
        kinds.push(Closet);
    }
    // At most eleven rooms besides the one hall a layout may add: twelve in all.
    kinds.truncate(MAX_ROOMS - 1);
    // Public, then private, then service, each in the order drawn.
    let mut ordered: Vec<RoomType> = Vec::new();
    for z in [Zone::Public, Zone::Private, Zone::Service] {
        ordered.extend(kinds.iter().filter(|&&k| zone(k) == z));
    }
    ordered
        .into_iter()
        .map(|kind| {
            let [lo, hi] = room_spec(kind).area;
            // Drawn from the lower 80 % of the range: rounding the layout may add a little.
            let area = behavior_core::rng::uniform(rng, lo, lo + 0.8 * (hi - lo));
            Want { kind, area }
        })
        .collect()
}
