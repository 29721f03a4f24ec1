//! The predicate vocabulary of BEHAVIOR-100 and the abilities each unary state requires.
//!
//! The set is closed on purpose: a simulator must implement every predicate an activity may use, so
//! the checker rejects names outside it instead of deferring the failure to run time. The domain
//! file `domain_igibson.bddl` declares 17 of these; `onfloor`, `touching` and `inroom` are used by
//! the official activities without being declared there, as in the original simulator.

use crate::taxonomy::Ability;
use std::fmt;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Predicate {
    Inside,
    NextTo,
    OnTop,
    Under,
    Touching,
    OnFloor,
    /// `(inroom obj room_type)`: its second argument is a room type, not an object. `:init` only.
    InRoom,
    Cooked,
    Burnt,
    Frozen,
    Soaked,
    Open,
    Dusty,
    Stained,
    Sliced,
    ToggledOn,
    Broken,
    Perished,
    Screwed,
    TimeSet,
}

impl Predicate {
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

    pub fn from_name(name: &str) -> Option<Predicate> {
        Predicate::ALL.into_iter().find(|p| p.name() == name)
    }

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
}
