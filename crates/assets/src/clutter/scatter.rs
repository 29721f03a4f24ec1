//! Scattering: each rule of each room draws things from the library and places them on, in or
//! beside its furniture with the world's placement helper (collision-free, the relation checked),
//! in a scratch copy of the home, until the rule's share of the furniture's footprint is covered
//! or a few placements in a row fail. Nothing is stepped here: [`super::settle`] lets the
//! placed things come to rest.

use super::ClutterError;
use super::rules::{Rule, STAND_ON_EDGE, Spot, rules};
use crate::library::Library;
use crate::scene::{ClutterPlan, Scene};
use behavior_core::rng::{SimRng, uniform};
use behavior_sim::{ObjectId, Relation, World};
use rand_chacha::rand_core::Rng;
use rapier3d::math::{Pose, Rotation, Vector};

/// Failed placements in a row after which a rule stops at a piece of furniture: it is as full
/// as random placement gets it.
const MISSES: u32 = 3;
/// How far from a quarter turn a thing's heading may be (rad): roughly squared up with the
/// furniture, as people leave things, without looking machine-placed.
const YAW_JITTER: f32 = 0.2;

/// A thing placed by a rule, and what it must stay on, in or beside.
#[derive(Clone, Debug)]
pub(super) struct Placed {
    /// Its plan, with the pose it has now.
    pub(super) plan: ClutterPlan,
    /// Where it went relative to its furniture.
    pub(super) spot: Spot,
    /// Index of its furniture in the scene's `objects`.
    pub(super) furniture: usize,
    /// Index of its furniture's room in the scene's `rooms`, whose floor a thing beside stands on.
    pub(super) room: usize,
}

/// The scratch home things are placed in, and what was placed so far.
struct Scatter<'a, 't> {
    world: World,
    floors: Vec<ObjectId>,
    furniture: Vec<ObjectId>,
    library: &'a Library<'t>,
    rng: &'a mut SimRng,
    placed: Vec<Placed>,
    /// Things added to the scratch world so far, placed or not (those not placed stay parked
    /// far away, apart from each other).
    added: usize,
}

/// Places the clutter of every room, room by room, rule by rule, furniture in scene order.
pub(super) fn scatter(
    home: &Scene,
    library: &Library,
    rng: &mut SimRng,
) -> Result<Vec<Placed>, ClutterError> {
    let built = home.build(library)?;
    let mut scatter = Scatter {
        world: built.world,
        floors: built.floors,
        furniture: built.objects,
        library,
        rng,
        placed: Vec::new(),
        added: 0,
    };
    for (room, plan) in home.rooms.iter().enumerate() {
        for rule in rules(plan.kind) {
            let pieces = home
                .objects
                .iter()
                .enumerate()
                .filter(|(_, o)| o.room == room && o.synset == rule.furniture);
            for (furniture, _) in pieces {
                scatter.fill(rule, furniture, room)?;
            }
        }
    }
    Ok(scatter.placed)
}

impl Scatter<'_, '_> {
    /// Places things of a rule at one piece of furniture until their footprints cover the rule's
    /// share of its footprint, or [`MISSES`] placements in a row fail.
    fn fill(&mut self, rule: &Rule, furniture: usize, room: usize) -> Result<(), ClutterError> {
        let footprint = area(&self.world, self.furniture[furniture]);
        let budget = rule.fill * footprint;
        let (mut covered, mut misses) = (0.0, 0);
        while covered < budget && misses < MISSES {
            match self.place_one(rule, furniture, room)? {
                Some(area) => (covered, misses) = (covered + area, 0),
                None => misses += 1,
            }
        }
        Ok(())
    }

    /// Draws a thing of the rule and tries to place it; its footprint if it found a place.
    fn place_one(
        &mut self,
        rule: &Rule,
        furniture: usize,
        room: usize,
    ) -> Result<Option<f32>, ClutterError> {
        let synset = rule.items[self.rng.next_u32() as usize % rule.items.len()];
        let asset = |cause| ClutterError::Asset {
            synset: synset.to_string(),
            cause,
        };
        let (archetype, size, variant) =
            self.library.sample_any(synset, self.rng).map_err(asset)?;
        let rotation = self.orientation(synset, archetype.shape);
        let name = format!("clutter_{}", self.added);
        let mut spec = self
            .library
            .instance_of(archetype, synset, &name, size, variant);
        // Parked out of the way until placed; one that finds no place stays parked.
        let park = Vector::new(-1000.0 - 3.0 * self.added as f32, -1000.0, 0.0);
        spec.pose = Pose::from_parts(park, rotation);
        let id = self.world.add(spec)?;
        self.added += 1;
        let target = self.furniture[furniture];
        let relations = match rule.spot {
            Spot::On => vec![(Relation::OnTop, target)],
            Spot::In => vec![(Relation::Inside, target)],
            Spot::Beside => vec![
                (Relation::NextTo, target),
                (Relation::OnFloor, self.floors[room]),
            ],
        };
        let Ok(pose) = self.world.place_jointly(id, &relations, self.rng) else {
            return Ok(None);
        };
        self.placed.push(Placed {
            plan: ClutterPlan {
                name,
                synset: synset.to_string(),
                archetype: archetype.synset.to_string(),
                position: pose.translation.to_array(),
                rotation: pose.rotation.to_array(),
                size: size.to_array(),
                variant,
            },
            spot: rule.spot,
            furniture,
            room,
        });
        Ok(Some(area(&self.world, id)))
    }

    /// A resting orientation (upright, or on an edge for books) turned to a heading near a
    /// quarter turn.
    fn orientation(&mut self, synset: &str, shape: crate::Shape) -> Rotation {
        let rest = if STAND_ON_EDGE.contains(&synset) {
            let all = shape.resting_orientations();
            all[self.rng.next_u32() as usize % all.len()]
        } else {
            Rotation::IDENTITY
        };
        let quarter = (self.rng.next_u32() % 4) as f32 * std::f32::consts::FRAC_PI_2;
        let yaw = quarter + uniform(self.rng, -YAW_JITTER, YAW_JITTER);
        Rotation::from_rotation_z(yaw) * rest
    }
}

/// The area of an object's box seen from above, m².
fn area(world: &World, id: ObjectId) -> f32 {
    let b = world.bodies().aabb(id);
    (b.maxs.x - b.mins.x) * (b.maxs.y - b.mins.y)
}
