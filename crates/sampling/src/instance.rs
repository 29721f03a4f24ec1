//! A sampled instance, and its saved form: the home, the bindings and the full world state
//! (poses, joint positions and unary states of every object), as JSON.

use crate::error::LoadError;
use crate::verify::{InitCheck, check_init};
use behavior_assets::{Library, Scene};
use behavior_bddl::Predicate;
use behavior_bddl::activity::Activity;
use behavior_sim::{BoundWorld, ObjectId, World};
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
    /// The unary predicates true of it.
    pub states: Vec<String>,
}

/// An instance as a file: the home, the created objects, bindings, and every object's pose, joint
/// positions and unary states — enough to rebuild a world where the same predicates hold
/// (temperatures, particle layouts and velocities are not stored: states are re-set).
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
            .objects()
            .filter(|(_, o)| o.category != "wall.n.01")
            .map(|(id, o)| {
                let pose = w.pose(id);
                SavedObject {
                    name: o.name.clone(),
                    position: pose.translation.to_array(),
                    rotation: pose.rotation.to_array(),
                    joints: (0..o.links.len())
                        .map(|k| w.core().joint_position(id, k))
                        .collect(),
                    states: Predicate::UNARY_STATES
                        .iter()
                        .filter(|&&p| w.state(id, p))
                        .map(|p| p.name().to_string())
                        .collect(),
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
                .map(|&b| w.object(b).name.clone())
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

/// Puts a saved object back: its pose, joints and unary states.
fn restore(world: &mut World, saved: &SavedObject) -> Result<(), LoadError> {
    let id = world
        .object_named(&saved.name)
        .ok_or_else(|| LoadError::UnknownObject {
            name: saved.name.clone(),
        })?;
    let pose = Pose::from_parts(
        Vector::from_array(saved.position),
        Rotation::from_array(saved.rotation).normalize(),
    );
    world.set_pose(id, pose).map_err(|cause| LoadError::Pose {
        name: saved.name.clone(),
        cause,
    })?;
    let links = world.object(id).links.len();
    for (k, &q) in saved.joints.iter().enumerate().take(links) {
        // A non-finite joint position in the file is as bad as a non-finite pose.
        world
            .set_joint_position(id, k, q)
            .map_err(|cause| LoadError::Pose {
                name: saved.name.clone(),
                cause,
            })?;
    }
    for p in Predicate::UNARY_STATES {
        let on = saved.states.iter().any(|s| s == p.name());
        if world.state(id, p) != on {
            world
                .set_state(id, p, on)
                .map_err(|cause| LoadError::State {
                    name: saved.name.clone(),
                    cause,
                })?;
        }
    }
    Ok(())
}
