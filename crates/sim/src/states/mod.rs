//! Object states beyond pose, each kept by a system that owns its data and its rule, and the
//! unary BDDL predicates read from them.
//!
//! The systems, in the order their rules run after the physics substeps of a step
//! ([`crate::World::step`]):
//!
//! 1. [`water`]: drops soak what they touch, old drops return to the pool, running sources emit;
//! 2. [`toggling`]: a hand held at a button for 5 steps flips the switch;
//! 3. [`temperature`]: active heat and cold sources pull temperatures, the rest decay;
//! 4. [`dirt`]: cleaning tools wipe dust (and, soaked, stains) off what they touch;
//! 5. [`slicing`]: objects a slicer pressed hard enough during the substeps split in two.
//!
//! Water runs before toggling and temperature after it, as in iGibson 2.0's state update order,
//! so a switch flipped this step heats from the next; cleaning follows water so a rag soaked this
//! step cleans stains at once; slicing comes last so that its halves start from the states the
//! whole ended the step with.
//!
//! Each unary predicate is read from one system: `cooked`/`burnt` from the running maximum
//! temperature against the synset's thresholds, `frozen` from the current temperature, `open`
//! from the joints, `soaked` from water, `toggled_on` from toggling, `dusty`/`stained` from dirt,
//! `sliced` from whether the object was replaced by halves. Once sliced, an object's other states
//! are read from and written to its two halves (true when true of both). `broken`, `perished`,
//! `screwed` and `timeset`, which no activity uses, are plain stored flags.
//!
//! Every setter leaves the world consistent with the value it sets (setting `cooked` raises the
//! temperature history, setting `open` moves the joints), so that the rules agree afterwards.
//! Setters that iGibson randomizes (particle layouts; `open`, which opens a random non-empty set
//! of joints each to a random point between the open threshold and the limit) draw from the
//! world's seeded generator ([`World::reseed`]).

pub(crate) mod dirt;
pub(crate) mod record;
pub(crate) mod slicing;
pub(crate) mod temperature;
pub(crate) mod toggling;
pub(crate) mod water;

use crate::World;
use crate::core::Core;
use crate::joints::{Joints, JointsMut};
use crate::object::ObjectId;
use behavior_core::rng::{SimRng, seeded};
use behavior_core::{Ability, Predicate};
use dirt::Dirt;
use serde::{Deserialize, Serialize};
use temperature::{
    DEFAULT_BURN_TEMPERATURE, DEFAULT_COOK_TEMPERATURE, DEFAULT_FREEZE_TEMPERATURE,
    ROOM_TEMPERATURE, Temperatures,
};
use toggling::Toggles;
use water::Water;

/// Why a state could not be set.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum StateError {
    /// The predicate is not a unary state.
    #[error("`{predicate}` is not a unary state")]
    NotUnary {
        /// The predicate.
        predicate: Predicate,
    },
    /// The object's synset lacks the ability the state needs.
    #[error("{object} ({category}) cannot be {predicate}: it lacks the `{ability}` ability")]
    Lacks {
        /// The object's name.
        object: String,
        /// Its synset.
        category: String,
        /// The state.
        predicate: Predicate,
        /// The ability it needs.
        ability: Ability,
    },
    /// `open` on an object without joints.
    #[error("{object} has no joint to open or close")]
    NoJoints {
        /// The object's name.
        object: String,
    },
    /// A saved state that cannot be put back as it is.
    #[error("{object}: the saved state is not valid: {reason}")]
    BadRecord {
        /// The object's name.
        object: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The world cannot make the state hold (or stop holding) for this object.
    #[error("{object}: `{predicate}` cannot be set to {value}: {reason}")]
    Unsupported {
        /// The object's name.
        object: String,
        /// The state.
        predicate: Predicate,
        /// The value asked for.
        value: bool,
        /// Why not.
        reason: String,
    },
}

/// Stored truth of the unary predicates that no rule computes.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Flags(Vec<u32>);

impl Flags {
    /// The predicates kept as plain flags: no rule computes them.
    pub(crate) const STORED: [Predicate; 4] = [
        Predicate::Broken,
        Predicate::Perished,
        Predicate::Screwed,
        Predicate::TimeSet,
    ];

    pub(crate) fn get(&self, id: ObjectId, p: Predicate) -> bool {
        self.0[id.0 as usize] & (1 << p as u32) != 0
    }

    pub(crate) fn set(&mut self, id: ObjectId, p: Predicate, value: bool) {
        let bits = &mut self.0[id.0 as usize];
        if value {
            *bits |= 1 << p as u32;
        } else {
            *bits &= !(1 << p as u32);
        }
    }
}

/// Every state system, each owning its data (one entry per object, by id), and the generator
/// the setters draw from.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct Systems {
    pub(crate) water: Water,
    pub(crate) toggles: Toggles,
    pub(crate) temperatures: Temperatures,
    pub(crate) dirt: Dirt,
    pub(crate) flags: Flags,
    /// Draws of the setters: particle layouts, how far `open` opens.
    pub(crate) rng: SimRng,
}

impl Default for Systems {
    fn default() -> Self {
        Systems {
            water: Water::default(),
            toggles: Toggles::default(),
            temperatures: Temperatures::default(),
            dirt: Dirt::default(),
            flags: Flags::default(),
            rng: seeded(0),
        }
    }
}

impl Systems {
    /// Makes room for a new object in every system.
    pub(crate) fn add_object(&mut self, core: &mut Core, id: ObjectId) {
        self.water.add_object(core, id);
        let object = core.bodies.object(id);
        self.toggles.add_object(id, object);
        self.temperatures.add_object(id, object);
        self.dirt.add_object(id, object);
        self.flags.0.push(0);
    }

    /// A half made by slicing starts with the whole's states.
    pub(crate) fn inherit(&mut self, from: ObjectId, to: ObjectId) {
        self.water.inherit(from, to);
        self.toggles.inherit(from, to);
        self.temperatures.inherit(from, to);
        self.dirt.inherit(from, to);
        let bits = self.flags.0[from.0 as usize];
        self.flags.0[to.0 as usize] = bits;
    }

    /// The rules of one step, in the documented order; slicing is the caller's (it adds objects).
    pub(crate) fn update(&mut self, core: &mut Core, dt: f32) {
        self.water.update(core, &self.toggles);
        self.toggles.update(core);
        self.temperatures.update(core, &self.toggles, dt);
        self.dirt.update(core, &self.water);
    }
}

impl Systems {
    /// Whether decoded systems fit the decoded core: an entry per object in every table, and
    /// every object or body they name present (see [`World::from_bytes`]).
    pub(crate) fn check_consistency(&self, n: usize, core: &Core) -> Result<(), String> {
        if self.flags.0.len() != n {
            return Err("flags: a table that disagrees with the objects".into());
        }
        self.water.check_consistency(n, core)?;
        self.toggles.check_consistency(n)?;
        self.temperatures.check_consistency(n)?;
        self.dirt.check_consistency(core)
    }
}

impl World {
    /// Seeds the draws of the state setters — where dust and stain particles fall, which joints
    /// `open` opens and how far — so that instances sampled from different seeds differ and the
    /// same seed repeats. A new world starts from seed 0; snapshots carry the generator.
    pub fn reseed(&mut self, seed: u64) {
        self.systems.rng = seeded(seed);
    }

    /// An object's current temperature (°C).
    pub fn temperature(&self, id: ObjectId) -> f32 {
        self.systems.temperatures.now(id)
    }

    /// The truth of a unary predicate for an object; `false` for binary predicates. A sliced
    /// object's states (but `sliced`) are its halves': true when true of both, as iGibson's
    /// grouper of the two halves answers, so cooking the halves cooks the strawberry.
    pub fn state(&self, id: ObjectId, predicate: Predicate) -> bool {
        let object = self.core.bodies.object(id);
        if let (Some(halves), false) = (object.replaced_by, predicate == Predicate::Sliced) {
            return halves.iter().all(|&h| self.state(h, predicate));
        }
        let s = &self.systems;
        match predicate {
            Predicate::Cooked => {
                object.has(Ability::Cookable)
                    && s.temperatures.max(id) >= self.threshold(id, predicate)
            }
            Predicate::Burnt => {
                object.has(Ability::Burnable)
                    && s.temperatures.max(id) >= self.threshold(id, predicate)
            }
            Predicate::Frozen => {
                object.has(Ability::Freezable)
                    && s.temperatures.now(id) <= DEFAULT_FREEZE_TEMPERATURE
            }
            Predicate::Open => Joints::new(&self.core).is_open(id),
            Predicate::Soaked => s.water.is_soaked(id),
            Predicate::ToggledOn => s.toggles.is_on(id),
            Predicate::Sliced => object.replaced_by.is_some(),
            Predicate::Dusty | Predicate::Stained => s.dirt.is_dirty(&self.core, id, predicate),
            p if p.arity() == 1 => s.flags.get(id, p),
            _ => false,
        }
    }

    /// The cook or burn temperature of an object's synset.
    fn threshold(&self, id: ObjectId, predicate: Predicate) -> f32 {
        let object = self.core.bodies.object(id);
        if predicate == Predicate::Cooked {
            object.param(
                Ability::Cookable,
                "cook_temperature",
                DEFAULT_COOK_TEMPERATURE,
            )
        } else {
            object.param(
                Ability::Burnable,
                "burn_temperature",
                DEFAULT_BURN_TEMPERATURE,
            )
        }
    }

    /// Makes a unary predicate true or false, changing the underlying state consistently.
    ///
    /// ```
    /// use behavior_core::{Ability, Predicate};
    /// use behavior_sim::{ObjectSpec, Part, Primitive, World};
    ///
    /// let mut world = World::default();
    /// let ball = Part::new(Primitive::Sphere { radius: 0.04 });
    /// let apple = world
    ///     .add(ObjectSpec::new("apple_1", "apple.n.01", vec![ball]).ability(Ability::Cookable, &[]))
    ///     .unwrap();
    /// world.set_state(apple, Predicate::Cooked, true).unwrap();
    /// assert!(world.state(apple, Predicate::Cooked));
    /// assert!(world.temperature(apple) <= 70.0); // cooked is history, not a hot apple
    /// // An apple cannot be toggled: the error names the missing ability.
    /// let err = world.set_state(apple, Predicate::ToggledOn, true).unwrap_err();
    /// assert!(err.to_string().contains("toggleable"));
    /// ```
    pub fn set_state(
        &mut self,
        id: ObjectId,
        predicate: Predicate,
        value: bool,
    ) -> Result<(), StateError> {
        let Some(ability) = predicate.required_ability() else {
            return Err(StateError::NotUnary { predicate });
        };
        let object = self.core.bodies.object(id);
        if let (Some(halves), false) = (object.replaced_by, predicate == Predicate::Sliced) {
            // The whole is gone; its halves carry its states.
            for half in halves {
                self.set_state(half, predicate, value)?;
            }
            return Ok(());
        }
        if !object.has(ability) {
            return Err(StateError::Lacks {
                object: object.name.clone(),
                category: object.category.clone(),
                predicate,
                ability,
            });
        }
        let systems = &mut self.systems;
        match predicate {
            Predicate::Cooked | Predicate::Burnt => {
                let threshold = self.threshold(id, predicate);
                let t = &mut self.systems.temperatures;
                let max = if value {
                    t.max(id).max(threshold)
                } else {
                    t.max(id).min(threshold - 1.0)
                };
                let now = t.now(id).min(max.max(ROOM_TEMPERATURE));
                t.set(id, now, max);
            }
            Predicate::Frozen => {
                // iGibson draws from [freeze − 50, freeze − 10]; the middle keeps runs identical.
                let now = if value {
                    DEFAULT_FREEZE_TEMPERATURE - 30.0
                } else {
                    DEFAULT_FREEZE_TEMPERATURE + 1.0
                };
                let max = systems.temperatures.max(id).max(now);
                systems.temperatures.set(id, now, max);
            }
            Predicate::Open => {
                JointsMut::new(&mut self.core).set_open(id, value, &mut systems.rng)?
            }
            Predicate::Soaked => systems.water.set_soaked(id, value),
            Predicate::ToggledOn => systems.toggles.set(id, value),
            Predicate::Sliced => self.set_sliced(id, value)?,
            Predicate::Dusty | Predicate::Stained => {
                let rng = &mut systems.rng;
                systems
                    .dirt
                    .set_dirty(&self.core, id, (predicate, value), rng)?
            }
            p => systems.flags.set(id, p, value),
        }
        Ok(())
    }
}
