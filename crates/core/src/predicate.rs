//! The predicate vocabulary of BEHAVIOR-100 and the abilities each unary state requires.
//!
//! The set is closed on purpose: a simulator must implement every predicate an activity may use, so
//! the checker rejects names outside it instead of deferring the failure to run time. The domain
//! file `domain_igibson.bddl` declares 17 of these; `onfloor`, `touching` and `inroom` are used by
//! the official activities without being declared there, as in the original simulator.

use crate::Ability;
use serde::{Deserialize, Serialize};
use std::fmt;

/// A BDDL predicate. The set is closed: see the module docs. Serialized by its BDDL name
/// ([`Predicate::name`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Predicate {
    /// `(inside a b)`: `a` is within `b`.
    Inside,
    /// `(nextto a b)`: beside each other, a small gap apart.
    #[serde(rename = "nextto")]
    NextTo,
    /// `(ontop a b)`: `b` supports `a` from below.
    #[serde(rename = "ontop")]
    OnTop,
    /// `(under a b)`: `a` is below `b`.
    Under,
    /// `(touching a b)`: in contact.
    Touching,
    /// `(onfloor a floor)`: resting on a room's floor.
    #[serde(rename = "onfloor")]
    OnFloor,
    /// `(inroom obj room_type)`: its second argument is a room type, not an object. `:init` only.
    #[serde(rename = "inroom")]
    InRoom,
    /// Heated past its cook temperature at some time.
    Cooked,
    /// Heated past its burn temperature at some time.
    Burnt,
    /// Colder than its freeze temperature now.
    Frozen,
    /// Wet through (water touched it).
    Soaked,
    /// A door, drawer or lid open beyond 5 % of its range.
    Open,
    /// Covered in dust particles.
    Dusty,
    /// Covered in stain particles.
    Stained,
    /// Cut in two.
    Sliced,
    /// Switched on.
    ToggledOn,
    /// Broken (no official activity uses it).
    Broken,
    /// Spoiled (no official activity uses it).
    Perished,
    /// Screwed in (no official activity uses it).
    Screwed,
    /// Its time set (no official activity uses it).
    #[serde(rename = "timeset")]
    TimeSet,
}

impl Predicate {
    /// Every predicate.
    pub const ALL: [Predicate; 20] = [
        Predicate::Inside,
        Predicate::NextTo,
        Predicate::OnTop,
        Predicate::Under,
        Predicate::Touching,
        Predicate::OnFloor,
        Predicate::InRoom,
        Predicate::Cooked,
        Predicate::Burnt,
        Predicate::Frozen,
        Predicate::Soaked,
        Predicate::Open,
        Predicate::Dusty,
        Predicate::Stained,
        Predicate::Sliced,
        Predicate::ToggledOn,
        Predicate::Broken,
        Predicate::Perished,
        Predicate::Screwed,
        Predicate::TimeSet,
    ];

    /// The unary states the official activities use (iGibson's nine).
    pub const UNARY_STATES: [Predicate; 9] = [
        Predicate::Cooked,
        Predicate::Burnt,
        Predicate::Frozen,
        Predicate::Soaked,
        Predicate::Open,
        Predicate::Dusty,
        Predicate::Stained,
        Predicate::Sliced,
        Predicate::ToggledOn,
    ];

    /// The name BDDL uses, e.g. `toggled_on`.
    pub fn name(self) -> &'static str {
        match self {
            Predicate::Inside => "inside",
            Predicate::NextTo => "nextto",
            Predicate::OnTop => "ontop",
            Predicate::Under => "under",
            Predicate::Touching => "touching",
            Predicate::OnFloor => "onfloor",
            Predicate::InRoom => "inroom",
            Predicate::Cooked => "cooked",
            Predicate::Burnt => "burnt",
            Predicate::Frozen => "frozen",
            Predicate::Soaked => "soaked",
            Predicate::Open => "open",
            Predicate::Dusty => "dusty",
            Predicate::Stained => "stained",
            Predicate::Sliced => "sliced",
            Predicate::ToggledOn => "toggled_on",
            Predicate::Broken => "broken",
            Predicate::Perished => "perished",
            Predicate::Screwed => "screwed",
            Predicate::TimeSet => "timeset",
        }
    }

    /// The predicate BDDL calls `name`.
    pub fn from_name(name: &str) -> Option<Predicate> {
        Predicate::ALL.into_iter().find(|p| p.name() == name)
    }

    /// How many arguments it takes (`inroom`'s second is a room type).
    pub fn arity(self) -> usize {
        match self {
            Predicate::Inside
            | Predicate::NextTo
            | Predicate::OnTop
            | Predicate::Under
            | Predicate::Touching
            | Predicate::OnFloor
            | Predicate::InRoom => 2,
            _ => 1,
        }
    }

    /// The ability an object's synset needs for this state to make sense (`cooked` → `cookable`).
    pub fn required_ability(self) -> Option<Ability> {
        Some(match self {
            Predicate::Cooked => Ability::Cookable,
            Predicate::Burnt => Ability::Burnable,
            Predicate::Frozen => Ability::Freezable,
            Predicate::Soaked => Ability::Soakable,
            Predicate::Dusty => Ability::Dustyable,
            Predicate::Stained => Ability::Stainable,
            Predicate::Sliced => Ability::Sliceable,
            Predicate::ToggledOn => Ability::Toggleable,
            Predicate::Open => Ability::Openable,
            Predicate::Broken => Ability::Breakable,
            Predicate::Perished => Ability::Perishable,
            Predicate::Screwed => Ability::Screwable,
            Predicate::TimeSet => Ability::TimeSetable,
            _ => return None,
        })
    }
}

impl fmt::Display for Predicate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for p in Predicate::ALL {
            assert_eq!(Predicate::from_name(p.name()), Some(p));
        }
        assert_eq!(Predicate::from_name("ontopp"), None);
    }

    #[test]
    fn predicates_and_abilities_serialize_by_their_names() {
        for p in Predicate::ALL {
            let text = serde_json::to_string(&p).unwrap();
            assert_eq!(text, format!("\"{}\"", p.name()));
            assert_eq!(serde_json::from_str::<Predicate>(&text).unwrap(), p);
        }
        for a in Ability::ALL {
            let text = serde_json::to_string(&a).unwrap();
            assert_eq!(text, format!("\"{}\"", a.name()));
            assert_eq!(serde_json::from_str::<Ability>(&text).unwrap(), a);
        }
    }
}
