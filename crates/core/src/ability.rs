//! Abilities: what an object of a synset can do or undergo, as the taxonomy
//! (`hierarchy_owned.json`) annotates synsets, with their parameters.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;
use std::str::FromStr;

/// What an object of a synset can do or undergo, as annotated in the taxonomy. Serialized by
/// its taxonomy spelling ([`Ability::name`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Ability {
    /// Can break.
    Breakable,
    /// Can burn (`burn_temperature`).
    Burnable,
    /// Wipes dust (and, soaked, stains) off what it touches.
    CleaningTool,
    /// Cools what is near or inside it (fridges).
    ColdSource,
    /// Can be cooked (`cook_temperature`).
    Cookable,
    /// Can gather dust.
    Dustyable,
    /// Can freeze.
    Freezable,
    /// Heats what is near or inside it (stoves, ovens).
    HeatSource,
    /// Is a liquid.
    Liquid,
    /// Has doors, drawers or a lid.
    Openable,
    /// Can spoil.
    Perishable,
    /// Can be screwed in.
    Screwable,
    /// Can be cut in two.
    Sliceable,
    /// Cuts sliceable objects (knives).
    Slicer,
    /// Can get wet through.
    Soakable,
    /// Can be stained.
    Stainable,
    /// Has a timer.
    TimeSetable,
    /// Can be switched on and off.
    Toggleable,
    /// Gives water (sinks).
    WaterSource,
}

impl Ability {
    /// Every ability.
    pub const ALL: [Ability; 19] = [
        Ability::Breakable,
        Ability::Burnable,
        Ability::CleaningTool,
        Ability::ColdSource,
        Ability::Cookable,
        Ability::Dustyable,
        Ability::Freezable,
        Ability::HeatSource,
        Ability::Liquid,
        Ability::Openable,
        Ability::Perishable,
        Ability::Screwable,
        Ability::Sliceable,
        Ability::Slicer,
        Ability::Soakable,
        Ability::Stainable,
        Ability::TimeSetable,
        Ability::Toggleable,
        Ability::WaterSource,
    ];

    /// The spelling used in the taxonomy file.
    pub fn name(self) -> &'static str {
        match self {
            Ability::Breakable => "breakable",
            Ability::Burnable => "burnable",
            Ability::CleaningTool => "cleaningTool",
            Ability::ColdSource => "coldSource",
            Ability::Cookable => "cookable",
            Ability::Dustyable => "dustyable",
            Ability::Freezable => "freezable",
            Ability::HeatSource => "heatSource",
            Ability::Liquid => "liquid",
            Ability::Openable => "openable",
            Ability::Perishable => "perishable",
            Ability::Screwable => "screwable",
            Ability::Sliceable => "sliceable",
            Ability::Slicer => "slicer",
            Ability::Soakable => "soakable",
            Ability::Stainable => "stainable",
            Ability::TimeSetable => "timeSetable",
            Ability::Toggleable => "toggleable",
            Ability::WaterSource => "waterSource",
        }
    }
}

impl FromStr for Ability {
    type Err = ();
    fn from_str(s: &str) -> Result<Self, ()> {
        Ability::ALL.into_iter().find(|a| a.name() == s).ok_or(())
    }
}

impl fmt::Display for Ability {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One parameter of an ability, e.g. `cook_temperature: 70.0` or `requires_closed: true`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ParamValue {
    /// `requires_closed: true`
    Bool(bool),
    /// `cook_temperature: 70`
    Number(f64),
}

impl ParamValue {
    /// The number, if it is one.
    pub fn as_f64(self) -> Option<f64> {
        match self {
            ParamValue::Number(x) => Some(x),
            ParamValue::Bool(_) => None,
        }
    }
    /// The flag, if it is one.
    pub fn as_bool(self) -> Option<bool> {
        match self {
            ParamValue::Bool(b) => Some(b),
            ParamValue::Number(_) => None,
        }
    }
}

/// An ability's parameters by name, as the taxonomy lists them.
pub type AbilityParams = BTreeMap<String, ParamValue>;
