//! An object's whole non-geometric state as plain data, to save an instance and load it back:
//! temperatures and their maximum, soaked, the switch and its counter, dust and stain particles,
//! the stored flags. Poses and joint positions are the bodies' and joints' ([`crate::Bodies::set_pose`],
//! [`crate::JointsMut::set_position`]); drops in flight are not kept (a loaded world starts
//! with every stream's pool full).

use crate::World;
use crate::object::ObjectId;
use crate::states::dirt::{Particle, ParticleSet};
use crate::states::{Flags, StateError};
use behavior_core::Predicate;
use rapier3d::math::Vector;
use serde::{Deserialize, Serialize};

/// Dust or stain particles of one object, as [`crate::World::object_state`] reports them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ParticleRecord {
    /// Each particle: the link it lies on (`None`: the object's body) and its position in that
    /// body's frame.
    pub particles: Vec<(Option<usize>, [f32; 3])>,
    /// How many were placed when the object was made dirty (the 50 % / 75 % rule counts against
    /// it).
    pub placed: usize,
}

/// The non-geometric state of one object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObjectState {
    /// °C now.
    pub temperature: f32,
    /// The highest temperature reached (°C); `None` before the object was first heated, cooled
    /// or stepped.
    pub max_temperature: Option<f32>,
    /// Whether water soaked it.
    pub soaked: bool,
    /// Its switch.
    pub toggled_on: bool,
    /// Steps a hand has been held at its button.
    pub toggle_steps: u32,
    /// Dust particles.
    pub dust: ParticleRecord,
    /// Stain particles.
    pub stain: ParticleRecord,
    /// The stored flags that no rule computes (`broken`, `perished`, `screwed`, `timeset`).
    pub flags: Vec<Predicate>,
}

impl World {
    /// An object's non-geometric state, to save it (see the module docs).
    pub fn object_state(&self, id: ObjectId) -> ObjectState {
        let s = &self.systems;
        let max = s.temperatures.max(id);
        let record = |kind| {
            let set = s.dirt.particles(id, kind);
            ParticleRecord {
                particles: set
                    .points
                    .iter()
                    .map(|p| (p.link, p.local.to_array()))
                    .collect(),
                placed: set.placed,
            }
        };
        ObjectState {
            temperature: s.temperatures.now(id),
            max_temperature: max.is_finite().then_some(max),
            soaked: s.water.is_soaked(id),
            toggled_on: s.toggles.is_on(id),
            toggle_steps: s.toggles.held_steps(id),
            dust: record(Predicate::Dusty),
            stain: record(Predicate::Stained),
            flags: Flags::STORED
                .into_iter()
                .filter(|&p| s.flags.get(id, p))
                .collect(),
        }
    }

    /// Puts back a state [`World::object_state`] reported. Checked first, so that a bad record (a
    /// non-finite temperature, a particle on a link the object lacks, more particles than were
    /// placed) is an error naming the object and changes nothing.
    pub fn set_object_state(
        &mut self,
        id: ObjectId,
        state: &ObjectState,
    ) -> Result<(), StateError> {
        self.check_record(id, state)?;
        let s = &mut self.systems;
        let max = state.max_temperature.unwrap_or(f32::NEG_INFINITY);
        s.temperatures.restore(id, state.temperature, max);
        s.water.set_soaked(id, state.soaked);
        s.toggles.restore(id, state.toggled_on, state.toggle_steps);
        for (kind, record) in [
            (Predicate::Dusty, &state.dust),
            (Predicate::Stained, &state.stain),
        ] {
            let points = record
                .particles
                .iter()
                .map(|&(link, local)| Particle {
                    link,
                    local: Vector::from_array(local),
                })
                .collect();
            s.dirt.put(
                id,
                kind,
                ParticleSet {
                    points,
                    placed: record.placed,
                },
            );
        }
        for p in Flags::STORED {
            s.flags.set(id, p, state.flags.contains(&p));
        }
        Ok(())
    }

    fn check_record(&self, id: ObjectId, state: &ObjectState) -> Result<(), StateError> {
        let object = self.core.bodies.object(id);
        let bad = |reason: String| StateError::BadRecord {
            object: object.name.clone(),
            reason,
        };
        if !state.temperature.is_finite() || state.max_temperature.is_some_and(|t| !t.is_finite()) {
            return Err(bad("a temperature is not a finite number".into()));
        }
        for (kind, record) in [("dust", &state.dust), ("stain", &state.stain)] {
            if record.particles.len() > record.placed {
                return Err(bad(format!(
                    "{} {kind} particles remain of {} placed",
                    record.particles.len(),
                    record.placed
                )));
            }
            for &(link, local) in &record.particles {
                if link.is_some_and(|l| l >= object.links.len()) {
                    return Err(bad(format!(
                        "a {kind} particle lies on a link it does not have"
                    )));
                }
                if !local.iter().all(|x| x.is_finite()) {
                    return Err(bad(format!("a {kind} particle has a non-finite position")));
                }
            }
        }
        if let Some(p) = state.flags.iter().find(|p| !Flags::STORED.contains(p)) {
            return Err(bad(format!("`{p}` is not a stored flag")));
        }
        Ok(())
    }
}
