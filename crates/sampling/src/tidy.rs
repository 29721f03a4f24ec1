//! Tidying: once the activity's furniture and floors are bound, the home's clutter on, in,
//! under or beside those of them the activity places things relative to (in its initial state
//! or in its goal) is put away — left out of the instance's home — so that the activity's own
//! objects find room there, now and when the goal is checked.
//!
//! The original does the same the other way round: it loads its clutter after sampling and
//! keeps only what collides with nothing of the activity. Clutter elsewhere in the home stays,
//! and no clutter is ever bound to an instance (see `bind`).

use crate::instantiate::Attempt;
use crate::place::placement;
use behavior_assets::Scene;
use behavior_bddl::activity::{Activity, InstanceId, Literal};
use behavior_bddl::{GroundGoal, ground::Node};
use behavior_sim::{ObjectId, Relations};
use std::collections::BTreeSet;

impl Attempt<'_> {
    /// Puts away the clutter at the activity's bound supports (see the module docs), rebuilding
    /// the home without it. Furniture and floors are built before clutter, so their ids, and the
    /// bindings, stay as they are.
    pub(crate) fn tidy(&mut self) -> Result<(), crate::SampleError> {
        let supports: Vec<ObjectId> = placed_relative_to(self.activity, &self.kinematic)
            .into_iter()
            .filter(|i| self.home_bound[i.0 as usize])
            .filter_map(|i| self.bindings[i.0 as usize])
            .collect();
        let relations = self.world.relations();
        let kept: Vec<bool> = self
            .clutter
            .iter()
            .map(|&c| !supports.iter().any(|&s| around(relations, c, s)))
            .collect();
        if kept.iter().all(|&k| k) {
            return Ok(());
        }
        let mut marks = kept.iter();
        let mut home = self.scene.clone();
        home.clutter
            .retain(|_| marks.next().copied().unwrap_or(true));
        self.rebuild(home)
    }

    /// Builds the world of a home whose furniture is the current one's.
    fn rebuild(&mut self, home: Scene) -> Result<(), crate::SampleError> {
        let built = home.build(self.library)?;
        debug_assert_eq!(built.objects, self.furniture);
        self.world = built.world;
        self.clutter = built.clutter;
        self.scene = home;
        Ok(())
    }
}

/// Whether a thing is on, in, under, beside or against an object.
fn around(relations: Relations, thing: ObjectId, support: ObjectId) -> bool {
    relations.touching(thing, support)
        || relations.inside(thing, support)
        || relations.under(thing, support)
        || relations.nextto(thing, support)
}

/// The instances some placement of the activity's initial state (`kinematic`) or of its goal
/// (its positive `ontop`, `inside`, `under`, `nextto`, `touching` and `onfloor` atoms) names,
/// on either side.
fn placed_relative_to(activity: &Activity, kinematic: &[Literal]) -> BTreeSet<InstanceId> {
    let goal = GroundGoal::new(activity);
    let in_goal = goal.nodes.iter().filter_map(|node| match node {
        Node::Lit(lit) => Some(Literal {
            atom: goal.atom(lit.atom),
            positive: lit.positive,
        }),
        _ => None,
    });
    kinematic
        .iter()
        .copied()
        .chain(in_goal)
        .filter(|l| placement(l).is_some())
        .flat_map(|l| [Some(l.atom.subject), l.atom.object])
        .flatten()
        .collect()
}
