//! Setting the init's unary states (`cooked`, `open`, `dusty`, …), positive and negative, once
//! every object is placed.

use crate::error::{Literals, SampleError, Unsatisfied};
use crate::instantiate::Attempt;
use behavior_bddl::activity::InitLiteral;
use behavior_sim::ObjectId;

impl Attempt<'_> {
    /// Sets every unary init literal that does not already hold: `(not (open x))` needs no
    /// joints moved, `(not (frozen x))` no cooling.
    pub(crate) fn set_states(&mut self, bindings: &[ObjectId]) -> Result<(), SampleError> {
        for literal in &self.activity.init {
            let InitLiteral::Atom(l) = literal else {
                continue;
            };
            if l.atom.object.is_some() {
                continue;
            }
            let object = bindings[l.atom.subject.0 as usize];
            if self.world.state(object, l.atom.predicate) == l.positive {
                continue;
            }
            self.world
                .set_state(object, l.atom.predicate, l.positive)
                .map_err(|e| SampleError::Literal {
                    literals: Literals::of(self.activity, [l]),
                    why: Unsatisfied::State(e),
                })?;
        }
        Ok(())
    }
}
