//! A sampled instance, and its saved form: the home, the bindings and the full world state
//! (poses, joint positions and unary states of every object), as JSON.

use crate::sample::{SampleError, first_unmet};
use behavior_assets::{Library, Scene};
use behavior_bddl::Predicate;
use behavior_bddl::activity::Activity;
use behavior_sim::{BoundWorld, ObjectId, World};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};

/// An object the sampler created from the library (the rest are the home's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Created {
    pub instance: String,
    pub synset: String,
    /// The archetype it was built from: its synset's or a descendant's.
    pub archetype: String,
    pub size: [f32; 3],
    pub variant: u32,
}

/// An activity instantiated in a home: the settled world and which object is which instance.
pub struct Instance {
    pub activity: String,
    pub scene: Scene,
    pub seed: u64,
    /// Which attempt succeeded (0 = the first).
    pub attempt: u32,
    pub world: World,
    /// The object of each activity instance, in `:objects` order.
    pub bindings: Vec<ObjectId>,
    pub created: Vec<Created>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SavedObject {
    pub name: String,
    pub position: [f32; 3],
    /// Quaternion x, y, z, w.
    pub rotation: [f32; 4],
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
    pub activity: String,
    pub seed: u64,
    pub scene: Scene,
    pub created: Vec<Created>,
    /// The object name bound to each activity instance, in `:objects` order.
    pub bindings: Vec<String>,
    /// Every object of the world but walls (floors included: they get dusty), in world order.
    pub objects: Vec<SavedObject>,
}

impl Instance {
    /// The world as a BDDL oracle for this activity.
    pub fn bound(&self) -> Vec<Option<ObjectId>> {
        self.bindings.iter().copied().map(Some).collect()
    }

    pub fn oracle<'a>(&'a self, bound: &'a [Option<ObjectId>]) -> BoundWorld<'a> {
        BoundWorld {
            world: &self.world,
            bindings: bound,
        }
    }

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
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    pub fn from_json(text: &str) -> Result<SavedInstance, serde_json::Error> {
        serde_json::from_str(text)
    }

    /// Rebuilds the instance: the home, the created objects, then every saved pose, joint and
    /// state. Fails, naming the object, on anything that does not fit the activity or the home.
    pub fn load(&self, activity: &Activity, library: &Library) -> Result<Instance, SampleError> {
        let bad = |what: String| SampleError::Literal {
            literal: self.activity.clone(),
            reason: what,
        };
        if activity.name != self.activity {
            return Err(bad(format!(
                "the file is for {}, not {}",
                self.activity, activity.name
            )));
        }
        let built = self.scene.build(library)?;
        let mut world = built.world;
        for c in &self.created {
            let archetype = library.resolve(&c.archetype)?;
            let size = Vector::from_array(c.size);
            let spec = library.instance_of(archetype, &c.synset, &c.instance, size, c.variant);
            world.add(spec).map_err(|e| bad(e.to_string()))?;
        }
        for saved in &self.objects {
            let id = world
                .object_named(&saved.name)
                .ok_or_else(|| bad(format!("no object named `{}`", saved.name)))?;
            let pose = Pose::from_parts(
                Vector::from_array(saved.position),
                Rotation::from_array(saved.rotation).normalize(),
            );
            world.set_pose(id, pose).map_err(|e| bad(e.to_string()))?;
            for (k, &q) in saved
                .joints
                .iter()
                .enumerate()
                .take(world.object(id).links.len())
            {
                world
                    .set_joint_position(id, k, q)
                    .map_err(|e| bad(format!("{}: {e}", saved.name)))?;
            }
            for p in Predicate::UNARY_STATES {
                let on = saved.states.iter().any(|s| s == p.name());
                if world.state(id, p) != on {
                    world
                        .set_state(id, p, on)
                        .map_err(|e| bad(format!("{}: {e}", saved.name)))?;
                }
            }
        }
        let bindings = self
            .bindings
            .iter()
            .map(|name| {
                world
                    .object_named(name)
                    .ok_or_else(|| bad(format!("no object named `{name}`")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if bindings.len() != activity.instances.len() {
            return Err(bad(format!(
                "{} bindings for {} instances",
                bindings.len(),
                activity.instances.len()
            )));
        }
        let instance = Instance {
            activity: self.activity.clone(),
            scene: self.scene.clone(),
            seed: self.seed,
            attempt: 0,
            world,
            bindings,
            created: self.created.clone(),
        };
        if let Some((literal, reason)) = first_unmet(activity, &instance.world, &instance.bindings)
        {
            return Err(SampleError::Literal { literal, reason });
        }
        Ok(instance)
    }
}
