//! The logical state of an instance: every predicate that holds among the activity's objects, by
//! their instance names, in the form `behavior bddl eval --state` reads.

use crate::instance::Instance;
use behavior_bddl::activity::{Activity, Atom, InstanceId};
use behavior_bddl::{Predicate, PredicateOracle};
use serde::ser::{Serialize, SerializeSeq, Serializer};

/// The binary predicates a fact can relate two objects by (`inroom` relates an object to a room
/// type and is listed apart).
const RELATIONS: [Predicate; 6] = [
    Predicate::OnTop,
    Predicate::Inside,
    Predicate::Under,
    Predicate::NextTo,
    Predicate::Touching,
    Predicate::OnFloor,
];

/// A predicate that holds, with its arguments: instance names, and for `inroom` a room type.
/// Serializes as a list, `["ontop", "apple.n.01_1", "table.n.02_1"]`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Fact {
    /// The predicate.
    pub predicate: Predicate,
    /// Its arguments.
    pub args: Vec<String>,
}

impl Serialize for Fact {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(1 + self.args.len()))?;
        seq.serialize_element(self.predicate.name())?;
        for arg in &self.args {
            seq.serialize_element(arg)?;
        }
        seq.end()
    }
}

impl std::fmt::Display for Fact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "({} {})", self.predicate, self.args.join(" "))
    }
}

impl Instance {
    /// Every predicate that holds among the activity's objects: each object's unary states and
    /// room, then every relation between two of them (both orders), in `:objects` order.
    pub fn facts(&self, activity: &Activity) -> Vec<Fact> {
        let bound = self.bound();
        let oracle = self.oracle(&bound);
        let n = activity.instances.len() as u32;
        let name = |i: u32| activity.instance(InstanceId(i)).name.clone();
        let mut facts = Vec::new();
        for i in 0..n {
            let subject = InstanceId(i);
            for predicate in Predicate::UNARY_STATES {
                let atom = Atom {
                    predicate,
                    subject,
                    object: None,
                };
                if oracle.holds(atom) {
                    facts.push(Fact {
                        predicate,
                        args: vec![name(i)],
                    });
                }
            }
            if let Some(room) = self.world.relations().room_of(self.bindings[i as usize]) {
                facts.push(Fact {
                    predicate: Predicate::InRoom,
                    args: vec![name(i), room.name().to_string()],
                });
            }
        }
        for i in 0..n {
            for j in (0..n).filter(|&j| j != i) {
                for predicate in RELATIONS {
                    let atom = Atom {
                        predicate,
                        subject: InstanceId(i),
                        object: Some(InstanceId(j)),
                    };
                    if oracle.holds(atom) {
                        facts.push(Fact {
                            predicate,
                            args: vec![name(i), name(j)],
                        });
                    }
                }
            }
        }
        facts
    }
}
