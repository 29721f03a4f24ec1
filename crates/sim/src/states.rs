//! Unary object states and their setters.
//!
//! Each BDDL unary predicate is read from the state that the world's rules maintain:
//! `cooked`/`burnt` from the running maximum temperature against the synset's thresholds,
//! `frozen` from the current temperature, `open` from the joints ([`crate::articulation`]);
//! `soaked`, `toggled_on` and `sliced` are latches that rules set. `broken`, `perished`,
//! `screwed` and `timeset`, which no activity uses, are plain stored flags.
//!
//! Every setter leaves the world consistent with the value it sets (setting `cooked` raises the
//! temperature history, setting `open` moves the joints), so that the rules agree afterwards.

use crate::particles::ParticleSet;
use crate::temperature::{
    DEFAULT_BURN_TEMPERATURE, DEFAULT_COOK_TEMPERATURE, DEFAULT_FREEZE_TEMPERATURE,
    ROOM_TEMPERATURE,
};
use crate::world::{ObjectId, World};
use behavior_bddl::Predicate;
use behavior_bddl::taxonomy::Ability;

/// The state of one object beyond its pose.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectState {
    /// °C.
    pub temperature: f32,
    /// The highest temperature ever reached (°C); `-inf` before the first step.
    pub max_temperature: f32,
    pub soaked: bool,
    pub toggled_on: bool,
    pub sliced: bool,
    /// The two objects that replaced this one when it was sliced.
    pub halves: Option<[ObjectId; 2]>,
    pub dust: ParticleSet,
    pub stain: ParticleSet,
    /// Consecutive steps a hand has been near the toggle button.
    pub(crate) toggle_steps: u32,
    flags: UnaryFlags,
}

impl Default for ObjectState {
    fn default() -> Self {
        ObjectState {
            temperature: ROOM_TEMPERATURE,
            max_temperature: f32::NEG_INFINITY,
            soaked: false,
            toggled_on: false,
            sliced: false,
            halves: None,
            dust: ParticleSet::default(),
            stain: ParticleSet::default(),
            toggle_steps: 0,
            flags: UnaryFlags::default(),
        }
    }
}

/// Stored truth of the unary predicates that no rule computes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct UnaryFlags(u32);

impl UnaryFlags {
    fn get(self, p: Predicate) -> bool {
        self.0 & (1 << p as u32) != 0
    }
    fn set(&mut self, p: Predicate, value: bool) {
        if value {
            self.0 |= 1 << p as u32;
        } else {
            self.0 &= !(1 << p as u32);
        }
    }
}

#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum StateError {
    #[error("`{predicate}` is not a unary state")]
    NotUnary { predicate: Predicate },
    #[error("{object} ({category}) cannot be {predicate}: it lacks the `{ability}` ability")]
    Lacks {
        object: String,
        category: String,
        predicate: Predicate,
        ability: Ability,
    },
    #[error("{object} has no joint to open or close")]
    NoJoints { object: String },
    #[error("{object}: `{predicate}` cannot be set to {value}: {reason}")]
    Unsupported {
        object: String,
        predicate: Predicate,
        value: bool,
        reason: String,
    },
}

impl World {
    /// An object's current temperature (°C).
    pub fn temperature(&self, id: ObjectId) -> f32 {
        self.object_state(id).temperature
    }

    pub(crate) fn object_state(&self, id: ObjectId) -> &ObjectState {
        &self.states[id.0 as usize]
    }

    /// The truth of a unary predicate for an object; `false` for binary predicates.
    pub fn state(&self, id: ObjectId, predicate: Predicate) -> bool {
        let object = self.object(id);
        let s = self.object_state(id);
        match predicate {
            Predicate::Cooked => {
                object.has(Ability::Cookable) && s.max_temperature >= self.cook_temperature(id)
            }
            Predicate::Burnt => {
                object.has(Ability::Burnable) && s.max_temperature >= self.burn_temperature(id)
            }
            Predicate::Frozen => {
                object.has(Ability::Freezable) && s.temperature <= DEFAULT_FREEZE_TEMPERATURE
            }
            Predicate::Open => self.is_open(id),
            Predicate::Soaked => s.soaked,
            Predicate::ToggledOn => s.toggled_on,
            Predicate::Sliced => s.sliced,
            Predicate::Dusty | Predicate::Stained => self.is_dirty(id, predicate),
            p if p.arity() == 1 => s.flags.get(p),
            _ => false,
        }
    }

    pub(crate) fn cook_temperature(&self, id: ObjectId) -> f32 {
        self.object(id).param(
            Ability::Cookable,
            "cook_temperature",
            DEFAULT_COOK_TEMPERATURE,
        )
    }

    pub(crate) fn burn_temperature(&self, id: ObjectId) -> f32 {
        self.object(id).param(
            Ability::Burnable,
            "burn_temperature",
            DEFAULT_BURN_TEMPERATURE,
        )
    }

    /// Makes a unary predicate true or false, changing the underlying state consistently.
    pub fn set_state(
        &mut self,
        id: ObjectId,
        predicate: Predicate,
        value: bool,
    ) -> Result<(), StateError> {
        let Some(ability) = predicate.required_ability() else {
            return Err(StateError::NotUnary { predicate });
        };
        let object = self.object(id);
        if !object.has(ability) {
            return Err(StateError::Lacks {
                object: object.name.clone(),
                category: object.category.clone(),
                predicate,
                ability,
            });
        }
        match predicate {
            Predicate::Cooked | Predicate::Burnt => {
                let threshold = if predicate == Predicate::Cooked {
                    self.cook_temperature(id)
                } else {
                    self.burn_temperature(id)
                };
                let s = &mut self.states[id.0 as usize];
                s.max_temperature = if value {
                    s.max_temperature.max(threshold)
                } else {
                    s.max_temperature.min(threshold - 1.0)
                };
                s.temperature = s.temperature.min(s.max_temperature.max(ROOM_TEMPERATURE));
            }
            Predicate::Frozen => {
                // iGibson draws from [freeze − 50, freeze − 10]; the middle keeps runs identical.
                let s = &mut self.states[id.0 as usize];
                s.temperature = if value {
                    DEFAULT_FREEZE_TEMPERATURE - 30.0
                } else {
                    DEFAULT_FREEZE_TEMPERATURE + 1.0
                };
                s.max_temperature = s.max_temperature.max(s.temperature);
            }
            Predicate::Open => self.set_open(id, value)?,
            Predicate::Soaked => self.states[id.0 as usize].soaked = value,
            Predicate::ToggledOn => {
                let s = &mut self.states[id.0 as usize];
                s.toggled_on = value;
                s.toggle_steps = 0;
            }
            Predicate::Sliced => self.set_sliced(id, value)?,
            Predicate::Dusty | Predicate::Stained => self.set_dirty(id, predicate, value)?,
            p => self.states[id.0 as usize].flags.set(p, value),
        }
        Ok(())
    }
}
