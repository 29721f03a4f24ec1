//! Placing objects: each by all its placement literals at once, in dependency order
//! ([`crate::order`]); the literal ↔ relation helpers the binding probes and the goal check use
//! too.

use crate::error::{Literals, SampleError, Unsatisfied};
use crate::instantiate::Attempt;
use crate::order::{Step, placement_order, target};
use crate::way_out::{has_way_out, within_reach};
use behavior_bddl::Predicate;
use behavior_bddl::activity::Literal;
use behavior_core::AGENT_SYNSET;
use behavior_sim::{ObjectId, PlacementError, Relation, World};
use rand_chacha::ChaCha8Rng;

impl Attempt<'_> {
    /// Places every created object in dependency order, each by all its placement literals at
    /// once (a soap on a towel on the floor; a shoe under a table and on the floor of the room
    /// that end of the table is in). Bound furniture and floors already stand.
    pub(crate) fn place_objects(&mut self, bindings: &[ObjectId]) -> Result<(), SampleError> {
        for step in placement_order(&self.kinematic, &self.home_bound) {
            if !step.anchored {
                return Err(SampleError::Unanchored {
                    instance: self.activity.instance(step.subject).name.clone(),
                });
            }
            place_by(&mut self.world, bindings, &step, &mut self.rng).map_err(|e| {
                SampleError::Literal {
                    literals: Literals::of(self.activity, step.written()),
                    why: Unsatisfied::Placement(e),
                }
            })?;
        }
        Ok(())
    }
}

/// Places a step's object by all its literals at once, at a random heading (see
/// [`World::place_turning`]).
pub(crate) fn place_by(
    world: &mut World,
    bindings: &[ObjectId],
    step: &Step,
    rng: &mut ChaCha8Rng,
) -> Result<(), PlacementError> {
    let mut relations: Vec<(Relation, ObjectId)> = step
        .literals
        .iter()
        .map(|l| {
            (
                relation_of(&l.placed),
                bindings[target(&l.placed).0 as usize],
            )
        })
        .collect();
    order_relations(world, &mut relations);
    let object = bindings[step.subject.0 as usize];
    world.place_turning(object, &relations, rng)?;
    if world.bodies().object(object).category != AGENT_SYNSET {
        // Something only on a floor is placed again until a person can come and reach it (see
        // [`within_reach`]); if none of [`OBJECT_PLACES`] is, it keeps the last.
        let floor_only = relations.iter().all(|&(r, _)| r == Relation::OnFloor);
        for _ in 1..OBJECT_PLACES {
            if !floor_only || within_reach(world, object) {
                break;
            }
            world.place_turning(object, &relations, rng)?;
        }
        return Ok(());
    }
    // The agent is placed again until a way leads out of its room from where it stands; if
    // none of [`AGENT_PLACES`] does, it keeps the last place (a room all pockets, where the
    // episode's base planner reports it boxed in).
    for _ in 1..AGENT_PLACES {
        if has_way_out(world, object) {
            break;
        }
        world.place_turning(object, &relations, rng)?;
    }
    Ok(())
}

/// How many places the agent is given at most, the first included, for one with a way out.
const AGENT_PLACES: usize = 20;
/// How many places an object only on a floor is given at most, the first included, for one a
/// person reaches.
const OBJECT_PLACES: usize = 20;

/// The placement a literal asks for: a positive `ontop`, `inside`, `under`, `nextto`, `touching`
/// or `onfloor`.
pub(crate) fn placement(l: &Literal) -> Option<Relation> {
    let relation = match l.atom.predicate {
        Predicate::OnTop => Relation::OnTop,
        Predicate::Inside => Relation::Inside,
        Predicate::Under => Relation::Under,
        Predicate::NextTo => Relation::NextTo,
        Predicate::Touching => Relation::Touching,
        Predicate::OnFloor => Relation::OnFloor,
        _ => return None,
    };
    l.positive.then_some(relation)
}

/// The relation of a literal already known to be a placement.
pub(crate) fn relation_of(l: &Literal) -> Relation {
    placement(l).expect("a placement literal")
}

/// Whether a literal is a placement that holds both ways round (`nextto`, `touching`).
pub(crate) fn is_symmetric(l: &Literal) -> bool {
    placement(l).is_some_and(Relation::is_symmetric)
}

/// Puts first the relation that picks where an object rests ([`World::place_jointly`]): a support
/// (`ontop`, `inside`, `under`) before a neighbour (`nextto`, `touching`) before a floor, and
/// among equals the smallest target, whose narrow surroundings are the hardest to hit by chance.
pub(crate) fn order_relations(world: &World, relations: &mut [(Relation, ObjectId)]) {
    let rank = |r: Relation| match r {
        Relation::OnTop | Relation::Inside | Relation::Under => 0,
        Relation::NextTo | Relation::Touching => 1,
        Relation::OnFloor => 2,
    };
    let volume = |t: ObjectId| {
        let b = world.bodies().aabb(t);
        let d = b.maxs - b.mins;
        d.x * d.y * d.z
    };
    relations.sort_by(|a, b| {
        rank(a.0)
            .cmp(&rank(b.0))
            .then(volume(a.1).total_cmp(&volume(b.1)))
    });
}
