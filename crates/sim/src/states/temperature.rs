//! Temperature: heat sources and sinks, and the decay toward room temperature.
//!
//! Each step (1/30 s) an object with a temperature state (cookable, burnable or freezable) is
//! pulled toward every active source that reaches it, `T += (T_source − T) · rate · dt`, each
//! computed from the old temperature; an object no source reaches decays toward 23 °C at
//! 0.02 /s. A source reaches an object when one of its heating elements (a stove has several
//! burners) is within its distance threshold of the object's centre, or, for sources that need it
//! inside (ovens, microwaves, fridges), when the object is inside it. A source is active when it is toggled on (if it needs
//! to be) and closed (if it needs to be). Constants and per-synset parameters are iGibson 2.0's
//! (`igibson/object_states/temperature.py`'s and its heat sources'), read from the taxonomy's
//! abilities.

use crate::core::Core;
use crate::joints::Joints;
use crate::kinematics::Relations;
use crate::object::{Object, ObjectId, PointKind};
use crate::states::toggling::Toggles;
use behavior_core::Ability;
use rapier3d::math::Vector;
use serde::{Deserialize, Serialize};

/// °C.
pub const ROOM_TEMPERATURE: f32 = 23.0;
/// Per second, toward room temperature, when no source reaches the object.
pub const DECAY_RATE: f32 = 0.02;
/// °C, when the taxonomy gives none.
pub const DEFAULT_COOK_TEMPERATURE: f32 = 70.0;
/// °C, when the taxonomy gives none.
pub const DEFAULT_BURN_TEMPERATURE: f32 = 200.0;
/// °C.
pub const DEFAULT_FREEZE_TEMPERATURE: f32 = 0.0;
/// Defaults of a heat source whose ability lists no parameters.
pub const DEFAULT_SOURCE_TEMPERATURE: f32 = 200.0;
/// Per second, of the gap to the source's temperature.
pub const DEFAULT_HEATING_RATE: f32 = 0.04;
/// How far a heating element reaches (m).
pub const DEFAULT_DISTANCE_THRESHOLD: f32 = 0.2;

/// What a source does to objects this step.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct Source {
    id: ObjectId,
    temperature: f32,
    rate: f32,
    /// How far its heating elements reach (a stove has several burners), or `None` when the
    /// object must be inside.
    reach: Option<f32>,
}

/// The temperature system: each object's temperature and the highest it ever reached.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Temperatures {
    now: Vec<f32>,
    /// `-inf` before the first step.
    max: Vec<f32>,
    /// The active sources of the current step, kept between steps so that a step allocates
    /// nothing.
    sources: Vec<Source>,
    /// The heat and cold sources, in id order.
    source_ids: Vec<ObjectId>,
    /// The objects that can cook, burn or freeze, in id order: the rule visits only them.
    thermal: Vec<ObjectId>,
}

impl Temperatures {
    /// Two temperatures per object; every source and thermal object is an object.
    pub(crate) fn check_consistency(&self, n: usize) -> Result<(), String> {
        let ids = self.sources.iter().map(|s| s.id);
        let ids = ids.chain(self.source_ids.iter().copied());
        let mut ids = ids.chain(self.thermal.iter().copied());
        if self.now.len() != n || self.max.len() != n || ids.any(|id| id.0 as usize >= n) {
            return Err("temperature: tables disagree with the objects".into());
        }
        Ok(())
    }
}

impl Temperatures {
    pub(crate) fn add_object(&mut self, id: ObjectId, object: &Object) {
        self.now.push(ROOM_TEMPERATURE);
        self.max.push(f32::NEG_INFINITY);
        if [Ability::HeatSource, Ability::ColdSource]
            .into_iter()
            .any(|a| object.has(a))
        {
            self.source_ids.push(id);
        }
        if [Ability::Cookable, Ability::Burnable, Ability::Freezable]
            .into_iter()
            .any(|a| object.has(a))
        {
            self.thermal.push(id);
        }
    }

    /// °C now.
    pub(crate) fn now(&self, id: ObjectId) -> f32 {
        self.now[id.0 as usize]
    }

    /// The highest temperature ever reached (°C).
    pub(crate) fn max(&self, id: ObjectId) -> f32 {
        self.max[id.0 as usize]
    }

    /// Sets the current and highest temperatures, keeping the highest at least the current.
    pub(crate) fn set(&mut self, id: ObjectId, now: f32, max: f32) {
        self.now[id.0 as usize] = now;
        self.max[id.0 as usize] = max.max(now);
    }

    /// Puts back saved temperatures as they were (`max` may be `-inf`: never stepped).
    pub(crate) fn restore(&mut self, id: ObjectId, now: f32, max: f32) {
        self.now[id.0 as usize] = now;
        self.max[id.0 as usize] = max;
    }

    /// A half made by slicing starts at the whole's temperatures.
    pub(crate) fn inherit(&mut self, from: ObjectId, to: ObjectId) {
        let (f, t) = (from.0 as usize, to.0 as usize);
        self.now[t] = self.now[f];
        self.max[t] = self.max[f];
    }

    /// Fills `sources` with the sources active this step.
    fn find_active_sources(&mut self, core: &Core, toggles: &Toggles) {
        let sources = &mut self.sources;
        sources.clear();
        for &id in &self.source_ids {
            let object = core.bodies.object(id);
            let Some(ability) = [Ability::HeatSource, Ability::ColdSource]
                .into_iter()
                .find(|&a| object.has(a))
            else {
                continue;
            };
            let needs_on = object.flag(ability, "requires_toggled_on", false);
            let needs_closed = object.flag(ability, "requires_closed", false);
            let needs_inside = object.flag(ability, "requires_inside", false);
            if (needs_on && !toggles.is_on(id)) || (needs_closed && Joints::new(core).is_open(id)) {
                continue;
            }
            let has_element = object
                .points
                .iter()
                .any(|(kind, _)| *kind == PointKind::HeatingElement);
            // Without an element there is nothing to heat from (as in iGibson).
            if !needs_inside && !has_element {
                continue;
            }
            let reach = (!needs_inside)
                .then(|| object.param(ability, "distance_threshold", DEFAULT_DISTANCE_THRESHOLD));
            sources.push(Source {
                id,
                temperature: object.param(ability, "temperature", DEFAULT_SOURCE_TEMPERATURE),
                rate: object.param(ability, "heating_rate", DEFAULT_HEATING_RATE),
                reach,
            });
        }
    }

    /// Whether a point lies within `reach` of one of the source's heating elements.
    fn near_element(core: &Core, source: ObjectId, at: Vector, reach: f32) -> bool {
        let pose = core.bodies.pose(source);
        core.bodies
            .object(source)
            .points
            .iter()
            .filter(|(kind, _)| *kind == PointKind::HeatingElement)
            .any(|(_, p)| (at - pose.transform_point(*p)).length() <= reach)
    }

    /// One step of the temperature rule.
    pub(crate) fn update(&mut self, core: &Core, toggles: &Toggles, dt: f32) {
        self.find_active_sources(core, toggles);
        for &id in &self.thermal {
            let i = id.0 as usize;
            let old = self.now[i];
            let center = core.bodies.aabb(id).center();
            let mut new = old;
            let mut reached = false;
            for source in self.sources.iter().filter(|s| s.id != id) {
                let reaches = match source.reach {
                    Some(reach) => Self::near_element(core, source.id, center, reach),
                    None => Relations::new(core).inside(id, source.id),
                };
                if reaches {
                    new += (source.temperature - old) * source.rate * dt;
                    reached = true;
                }
            }
            if !reached {
                new += (ROOM_TEMPERATURE - old) * DECAY_RATE * dt;
            }
            self.now[i] = new;
            self.max[i] = self.max[i].max(new);
        }
    }
}
