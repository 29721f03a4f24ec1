//! Room types: where an activity's furniture must stand (`(inroom table.n.02_1 kitchen)`).

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// The eleven room types of BEHAVIOR homes, as the activities' `inroom` literals name them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RoomType {
    /// `kitchen`
    Kitchen,
    /// `living_room`
    LivingRoom,
    /// `bedroom`
    Bedroom,
    /// `bathroom`
    Bathroom,
    /// `dining_room`
    DiningRoom,
    /// `garage`
    Garage,
    /// `home_office`
    HomeOffice,
    /// `storage_room`
    StorageRoom,
    /// `corridor`
    Corridor,
    /// `utility_room`
    UtilityRoom,
    /// `closet`
    Closet,
}

impl RoomType {
    /// Every room type, in the order of the activities' documentation.
    pub const ALL: [RoomType; 11] = [
        RoomType::Kitchen,
        RoomType::LivingRoom,
        RoomType::Bedroom,
        RoomType::Bathroom,
        RoomType::DiningRoom,
        RoomType::Garage,
        RoomType::HomeOffice,
        RoomType::StorageRoom,
        RoomType::Corridor,
        RoomType::UtilityRoom,
        RoomType::Closet,
    ];

    /// The name BDDL uses, e.g. `living_room`.
    pub fn name(self) -> &'static str {
        match self {
            RoomType::Kitchen => "kitchen",
            RoomType::LivingRoom => "living_room",
            RoomType::Bedroom => "bedroom",
            RoomType::Bathroom => "bathroom",
            RoomType::DiningRoom => "dining_room",
            RoomType::Garage => "garage",
            RoomType::HomeOffice => "home_office",
            RoomType::StorageRoom => "storage_room",
            RoomType::Corridor => "corridor",
            RoomType::UtilityRoom => "utility_room",
            RoomType::Closet => "closet",
        }
    }
}

/// A room name that is not one of the eleven [`RoomType`]s.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownRoomType(pub String);

impl fmt::Display for UnknownRoomType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let known: Vec<&str> = RoomType::ALL.iter().map(|r| r.name()).collect();
        write!(
            f,
            "unknown room type `{}` (known: {})",
            self.0,
            known.join(", ")
        )
    }
}

impl std::error::Error for UnknownRoomType {}

impl FromStr for RoomType {
    type Err = UnknownRoomType;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        RoomType::ALL
            .into_iter()
            .find(|r| r.name() == s)
            .ok_or_else(|| UnknownRoomType(s.to_string()))
    }
}

impl fmt::Display for RoomType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_are_errors() {
        for room in RoomType::ALL {
            assert_eq!(room.name().parse::<RoomType>(), Ok(room));
        }
        let err = "ballroom".parse::<RoomType>().unwrap_err();
        assert!(err.to_string().contains("`ballroom`"), "{err}");
    }
}
