//! A sampled instance, and its saved form: the home, the bindings and the full world state
//! (every object's pose, joint positions, temperatures, water, switch, dust and stain particles
//! and flags), as JSON; and the logical state of an instance, as facts.

use crate::error::LoadError;
use crate::verify::{InitCheck, check_init};
use behavior_assets::{Library, Scene};
use behavior_bddl::Predicate;
use behavior_bddl::activity::Activity;
use behavior_core::WALL_SYNSET;
use behavior_sim::{BoundWorld, ObjectId, ObjectState, ParticleRecord, StateError, World};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// An object the sampler created from the library (the rest are the home's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Created {
    /// The activity's instance it stands for.
    pub instance: String,
    /// The instance's declared synset.
    pub synset: String,
    /// The archetype it was built from: its synset's or a descendant's.
    pub archetype: String,
    /// Its size (m), as drawn and fitted: rebuilding needs it, since sizes are random.
    pub size: [f32; 3],
    /// Its archetype's variant, drawn like the size.
    pub variant: u32,
}

/// An activity instantiated in a home: the settled world and which object is which instance.
pub struct Instance {
    /// The activity's problem name (`packing_lunches_0`).
    pub activity: String,
    /// The home it was sampled in, kept so that it can be saved and rebuilt.
    pub scene: Scene,
    /// The seed it was sampled from.
    pub seed: u64,
    /// Which attempt succeeded (0 = the first).
    pub attempt: u32,
    /// The settled world: the home and the created objects.
    pub world: World,
    /// The object of each activity instance, in `:objects` order.
    pub bindings: Vec<ObjectId>,
    /// The objects created from the library (the rest are the home's).
    pub created: Vec<Created>,
}

/// One object of a saved world: enough to put it back as it was.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SavedObject {
    /// Its name in the world (unique).
    pub name: String,
    /// Where it stands (m).
    pub position: [f32; 3],
    /// Quaternion x, y, z, w.
    pub rotation: [f32; 4],
    /// The position of each joint, in link order.
    pub joints: Vec<f32>,
    /// The unary predicates true of it, for reading; loading checks that the restored state
    /// agrees.
    pub states: Vec<String>,
    /// Everything else about it the rules read.
    pub state: SavedState,
}

/// An object's non-geometric state in a file (see [`behavior_sim::ObjectState`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SavedState {
    /// °C now.
    pub temperature: f32,
    /// The highest temperature reached (°C); `null` before the object was first stepped.
    pub max_temperature: Option<f32>,
    /// Whether water soaked it.
    pub soaked: bool,
    /// Its switch.
    pub toggled_on: bool,
    /// Steps a hand has been held at its button.
    pub toggle_steps: u32,
    /// Dust particles.
    pub dust: SavedParticles,
    /// Stain particles.
    pub stain: SavedParticles,
    /// The stored flags (`broken`, `perished`, `screwed`, `timeset`) that are true.
    pub flags: Vec<String>,
}

/// Dust or stain particles in a file.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SavedParticles {
    /// How many were placed when the object was made dirty.
    pub placed: usize,
    /// Each remaining particle: the link it lies on (`null`: the object's body) and its
    /// position in that body's frame.
    pub particles: Vec<(Option<usize>, [f32; 3])>,
}

/// An instance as a file: the home, the created objects, bindings, and every object's pose, joint
/// positions and whole state — enough to rebuild the world as it was sampled (velocities, drops in
/// flight and the state setters' generator are not stored: the instance was settled).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SavedInstance {
    /// The activity's problem name: loading checks it.
    pub activity: String,
    /// The seed it was sampled from, for the record.
    pub seed: u64,
    /// The home.
    pub scene: Scene,
    /// The objects created from the library, rebuilt before poses are set.
    pub created: Vec<Created>,
    /// The object name bound to each activity instance, in `:objects` order.
    pub bindings: Vec<String>,
    /// Every object of the world but walls (floors included: they get dusty), in world order.
    pub objects: Vec<SavedObject>,
}

impl Instance {
    /// The bindings as an oracle takes them ([`Instance::oracle`]): every instance is bound.
    pub fn bound(&self) -> Vec<Option<ObjectId>> {
        self.bindings.iter().copied().map(Some).collect()
    }

    /// The world as a BDDL oracle for this activity, given [`Instance::bound`], so that goal
    /// formulas can be evaluated on it.
    pub fn oracle<'a>(&'a self, bound: &'a [Option<ObjectId>]) -> BoundWorld<'a> {
        BoundWorld {
            world: &self.world,
            bindings: bound,
        }
    }

    /// Every `:init` literal of `activity` evaluated in this instance's world, for a report of
    /// what holds (the sampler already required all to hold after settling).
    pub fn check_init(&self, activity: &Activity) -> InitCheck {
        check_init(activity, &self.world, &self.bindings)
    }

    /// The instance as plain data, for a file.
    pub fn save(&self) -> SavedInstance {
        let w = &self.world;
        let objects = w
            .bodies()
            .objects()
            .filter(|(_, o)| o.category != WALL_SYNSET)
            .map(|(id, o)| {
                let pose = w.bodies().pose(id);
                SavedObject {
                    name: o.name.clone(),
                    position: pose.translation.to_array(),
                    rotation: pose.rotation.to_array(),
                    joints: (0..o.links.len())
                        .map(|k| w.joints().position(id, k))
                        .collect(),
                    states: Predicate::UNARY_STATES
                        .iter()
                        .filter(|&&p| w.state(id, p))
                        .map(|p| p.name().to_string())
                        .collect(),
                    state: SavedState::from(w.object_state(id)),
                }
            })
            .collect();
        SavedInstance {
            activity: self.activity.clone(),
            seed: self.seed,
            scene: self.scene.clone(),
            created: self.created.clone(),
            bindings: self
                .bindings
                .iter()
                .map(|&b| w.bodies().object(b).name.clone())
                .collect(),
            objects,
        }
    }
}

impl SavedInstance {
    /// The instance as pretty-printed JSON.
    pub fn to_json(&self) -> String {
        // Plain data of strings and finite numbers always serializes.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Reads an instance file's JSON (not yet checked against an activity: see
    /// [`SavedInstance::load`]).
    pub fn from_json(text: &str) -> Result<SavedInstance, LoadError> {
        Ok(serde_json::from_str(text)?)
    }

    /// Rebuilds the instance: the home, the created objects, then every saved pose, joint and
    /// state; then requires every init literal of `activity` to hold. Fails, naming the object
    /// or literal, on anything that does not fit the activity or the home.
    pub fn load(&self, activity: &Activity, library: &Library) -> Result<Instance, LoadError> {
        if activity.name != self.activity {
            return Err(LoadError::WrongActivity {
                saved: self.activity.clone(),
                activity: activity.name.clone(),
            });
        }
        if self.bindings.len() != activity.instances.len() {
            return Err(LoadError::BindingCount {
                activity: activity.name.clone(),
                bindings: self.bindings.len(),
                instances: activity.instances.len(),
            });
        }
        let mut world = self.scene.build(library)?.world;
        for c in &self.created {
            rebuild(&mut world, library, c)?;
        }
        for saved in &self.objects {
            restore(&mut world, saved)?;
        }
        check_states(&world, &self.objects)?;
        let bindings = self.bindings(activity, &world)?;
        let instance = Instance {
            activity: self.activity.clone(),
            scene: self.scene.clone(),
            seed: self.seed,
            attempt: 0,
            world,
            bindings,
            created: self.created.clone(),
        };
        let check = instance.check_init(activity);
        match check
            .literals
            .into_iter()
            .find_map(|l| Some((l.literal, l.unmet?)))
        {
            Some((literal, why)) => Err(LoadError::InitBroken { literal, why }),
            None => Ok(instance),
        }
    }

    /// The object each instance is bound to in the rebuilt world.
    fn bindings(&self, activity: &Activity, world: &World) -> Result<Vec<ObjectId>, LoadError> {
        self.bindings
            .iter()
            .zip(&activity.instances)
            .map(|(name, instance)| {
                world
                    .bodies()
                    .object_named(name)
                    .ok_or_else(|| LoadError::UnknownBinding {
                        instance: instance.name.clone(),
                        name: name.clone(),
                    })
            })
            .collect()
    }
}

/// Adds a created object back, as it was drawn.
fn rebuild(world: &mut World, library: &Library, c: &Created) -> Result<(), LoadError> {
    let archetype = library.resolve(&c.archetype)?;
    let size = Vector::from_array(c.size);
    let spec = library.instance_of(archetype, &c.synset, &c.instance, size, c.variant);
    world.add(spec).map_err(|cause| LoadError::Add {
        instance: c.instance.clone(),
        cause,
    })?;
    Ok(())
}

/// Puts a saved object back: its pose, joints, whether it was sliced (which makes its halves,
/// restored in turn as the objects after it), and its whole state; then checks that the unary
/// predicates the file lists are exactly those that hold.
fn restore(world: &mut World, saved: &SavedObject) -> Result<(), LoadError> {
    let id = world
        .bodies()
        .object_named(&saved.name)
        .ok_or_else(|| LoadError::UnknownObject {
            name: saved.name.clone(),
        })?;
    let pose_error = |cause| LoadError::Pose {
        name: saved.name.clone(),
        cause,
    };
    let state_error = |cause| LoadError::State {
        name: saved.name.clone(),
        cause,
    };
    // A unit quaternion is kept bit for bit; a hand-edited one is normalized.
    let rotation = Rotation::from_array(saved.rotation);
    let rotation = if rotation.is_normalized() {
        rotation
    } else {
        rotation.normalize()
    };
    let pose = Pose::from_parts(Vector::from_array(saved.position), rotation);
    world.bodies_mut().set_pose(id, pose).map_err(pose_error)?;
    let links = world.bodies().object(id).links.len();
    for (k, &q) in saved.joints.iter().enumerate().take(links) {
        // A non-finite joint position in the file is as bad as a non-finite pose.
        world
            .joints_mut()
            .set_position(id, k, q)
            .map_err(pose_error)?;
    }
    let sliced = saved.states.iter().any(|s| s == Predicate::Sliced.name());
    if sliced && !world.state(id, Predicate::Sliced) {
        world
            .set_state(id, Predicate::Sliced, true)
            .map_err(state_error)?;
    }
    let state = saved.state.to_world(&saved.name).map_err(state_error)?;
    world.set_object_state(id, &state).map_err(state_error)?;
    Ok(())
}

/// Checks that the unary predicates each saved object lists are those that hold once every
/// object is back (a sliced object's states are its halves', restored after it).
fn check_states(world: &World, objects: &[SavedObject]) -> Result<(), LoadError> {
    for saved in objects {
        let Some(id) = world.bodies().object_named(&saved.name) else {
            continue;
        };
        for p in Predicate::UNARY_STATES {
            let listed = saved.states.iter().any(|s| s == p.name());
            if world.state(id, p) != listed {
                return Err(LoadError::StateMismatch {
                    name: saved.name.clone(),
                    predicate: p,
                    listed,
                });
            }
        }
    }
    Ok(())
}

impl From<ObjectState> for SavedState {
    fn from(s: ObjectState) -> SavedState {
        let particles = |r: ParticleRecord| SavedParticles {
            placed: r.placed,
            particles: r.particles,
        };
        SavedState {
            temperature: s.temperature,
            max_temperature: s.max_temperature,
            soaked: s.soaked,
            toggled_on: s.toggled_on,
            toggle_steps: s.toggle_steps,
            dust: particles(s.dust),
            stain: particles(s.stain),
            flags: s.flags.iter().map(|p| p.name().to_string()).collect(),
        }
    }
}

impl SavedState {
    /// The state as the world takes it; an unknown flag is an error naming `object`.
    fn to_world(&self, object: &str) -> Result<ObjectState, StateError> {
        let flags = self
            .flags
            .iter()
            .map(|name| {
                Predicate::from_name(name).ok_or_else(|| StateError::BadRecord {
                    object: object.to_string(),
                    reason: format!("unknown flag `{name}`"),
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let particles = |p: &SavedParticles| ParticleRecord {
            particles: p.particles.clone(),
            placed: p.placed,
        };
        Ok(ObjectState {
            temperature: self.temperature,
            max_temperature: self.max_temperature,
            soaked: self.soaked,
            toggled_on: self.toggled_on,
            toggle_steps: self.toggle_steps,
            dust: particles(&self.dust),
            stain: particles(&self.stain),
            flags,
        })
    }
}
