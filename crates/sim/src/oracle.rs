//! The world answers the language's predicates: activity instances bound to objects, and each atom computed
//! by the world's geometry or read from its states.

use crate::World;
use crate::object::ObjectId;
use behavior_core::{Atom, InstanceId, PredicateOracle};

/// A world seen through an activity's bindings: `bindings[i]` is the object of instance `i`.
/// Floors (`floor.n.01_k`) are bound to room floor objects; an unbound instance satisfies nothing.
pub struct BoundWorld<'a> {
    /// The world.
    pub world: &'a World,
    /// The object of each instance, by instance index.
    pub bindings: &'a [Option<ObjectId>],
}

impl BoundWorld<'_> {
    fn object(&self, instance: InstanceId) -> Option<ObjectId> {
        self.bindings.get(instance.0 as usize).copied().flatten()
    }
}

impl PredicateOracle for BoundWorld<'_> {
    fn holds(&self, atom: Atom) -> bool {
        let Some(a) = self.object(atom.subject) else {
            return false;
        };
        let b = atom.object.and_then(|o| self.object(o));
        match (atom.predicate, b) {
            (p, Some(b)) => self.world.relations().relation(p, a, b),
            (p, None) if p.arity() == 1 => self.world.state(a, p),
            _ => false,
        }
    }
}
