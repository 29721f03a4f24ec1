//! The order in which objects are placed, for the initial state and for a goal option alike.
//!
//! An object waits until everything it goes on, in or under is placed (a soap on a towel on the
//! floor: floor, towel, soap). `nextto` and `touching` are symmetric: one towards an object not
//! yet placed makes nothing wait but is handed on to that object, reversed, so two objects that
//! touch each other do not wait for each other. Among the objects free to go, the first (in
//! `:objects` order) with something placed to go by — a target of its own literals, or a
//! literal handed on to it — goes next. When none has, the first that waits for nothing goes
//! unanchored (in a goal, it stays where it is for the others to come to it), and in a cycle (a
//! inside b, b inside a) the first left goes anyway and its placement is left to fail.

use crate::place::is_symmetric;
use behavior_bddl::activity::{InstanceId, Literal};

/// A literal an object is placed by: as it is placed (perhaps reversed, handed on from the
/// other side) and as the definition writes it, for error messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PlacedBy {
    /// With the object placed as its subject.
    pub(crate) placed: Literal,
    /// As written in the definition.
    pub(crate) written: Literal,
}

/// One object's turn: what it is placed by, handed-on literals first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Step {
    /// The instance placed.
    pub(crate) subject: InstanceId,
    /// What it is placed by; empty when everything was handed on.
    pub(crate) literals: Vec<PlacedBy>,
    /// Whether it had something placed to go by when its turn came.
    pub(crate) anchored: bool,
}

impl Step {
    /// The literals as the definition writes them.
    pub(crate) fn written(&self) -> impl Iterator<Item = &Literal> {
        self.literals.iter().map(|l| &l.written)
    }
}

/// Orders the instances with `stays[i]` false by the placement literals `placements` (positive
/// `ontop`, `inside`, `under`, `nextto`, `touching`, `onfloor`); instances that stay count as
/// placed from the start. Every instance that does not stay gets exactly one step.
pub(crate) fn placement_order(placements: &[Literal], stays: &[bool]) -> Vec<Step> {
    let mut state = Ordering {
        placements,
        placed: stays.to_vec(),
        handed: Vec::new(),
    };
    let movers = stays.iter().filter(|s| !**s).count();
    (0..movers).map(|_| state.next_step()).collect()
}

/// The ordering in progress.
struct Ordering<'a> {
    placements: &'a [Literal],
    /// Whether each instance stays or has had its step.
    placed: Vec<bool>,
    /// Symmetric literals handed on to an instance not yet placed: (to whom, the literal).
    handed: Vec<(InstanceId, PlacedBy)>,
}

impl Ordering<'_> {
    fn own(&self, s: InstanceId) -> impl Iterator<Item = &Literal> {
        self.placements.iter().filter(move |l| l.atom.subject == s)
    }

    fn is_placed(&self, i: InstanceId) -> bool {
        self.placed[i.0 as usize]
    }

    /// Whether `s` goes on, in or under something still to be placed.
    fn waiting(&self, s: InstanceId) -> bool {
        self.own(s)
            .any(|l| !is_symmetric(l) && target(l) != s && !self.is_placed(target(l)))
    }

    /// Whether `s` has something placed to go by.
    fn anchored(&self, s: InstanceId) -> bool {
        self.own(s).any(|l| self.is_placed(target(l))) || self.handed.iter().any(|h| h.0 == s)
    }

    /// The next object (see the module docs) and whether it is anchored.
    fn pick(&self) -> (InstanceId, bool) {
        let free = || {
            (0..self.placed.len() as u32)
                .map(InstanceId)
                .filter(|&i| !self.is_placed(i))
        };
        if let Some(s) = free().find(|&s| !self.waiting(s) && self.anchored(s)) {
            return (s, true);
        }
        let s = free()
            .find(|&s| !self.waiting(s))
            .or_else(|| free().next())
            .expect("an unplaced instance is left while steps are due");
        (s, false)
    }

    /// Takes the next object's turn: what was handed on to it, then its own literals, except the
    /// symmetric ones towards objects still to come, which it hands on to them.
    fn next_step(&mut self) -> Step {
        let (subject, anchored) = self.pick();
        let mut literals = Vec::new();
        self.handed.retain(|&(to, l)| {
            let mine = to == subject;
            if mine {
                literals.push(l);
            }
            !mine
        });
        let own: Vec<Literal> = self.own(subject).copied().collect();
        for l in own {
            let t = target(&l);
            if is_symmetric(&l) && t != subject && !self.is_placed(t) {
                let reversed = PlacedBy {
                    placed: reversed(&l),
                    written: l,
                };
                self.handed.push((t, reversed));
            } else {
                literals.push(PlacedBy {
                    placed: l,
                    written: l,
                });
            }
        }
        self.placed[subject.0 as usize] = true;
        Step {
            subject,
            literals,
            anchored,
        }
    }
}

/// The second argument of a placement literal; `onfloor`'s is the floor.
pub(crate) fn target(l: &Literal) -> InstanceId {
    l.atom.object.expect("placement literals are binary")
}

/// The same relation stated from its object's side (for symmetric ones).
fn reversed(l: &Literal) -> Literal {
    let mut r = *l;
    (r.atom.subject, r.atom.object) = (target(l), Some(l.atom.subject));
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_bddl::Predicate;
    use behavior_bddl::activity::Atom;

    fn lit(predicate: Predicate, s: u32, o: u32) -> Literal {
        Literal {
            atom: Atom {
                predicate,
                subject: InstanceId(s),
                object: Some(InstanceId(o)),
            },
            positive: true,
        }
    }

    fn order(steps: &[Step]) -> Vec<u32> {
        steps.iter().map(|s| s.subject.0).collect()
    }

    #[test]
    fn an_object_waits_for_what_it_stands_on() {
        // 0 on 1, 1 on 2, 2 on the floor 3 (which stays).
        let placements = [
            lit(Predicate::OnTop, 0, 1),
            lit(Predicate::OnTop, 1, 2),
            lit(Predicate::OnFloor, 2, 3),
        ];
        let steps = placement_order(&placements, &[false, false, false, true]);
        assert_eq!(order(&steps), [2, 1, 0]);
        assert!(steps.iter().all(|s| s.anchored && s.literals.len() == 1));
    }

    #[test]
    fn symmetric_literals_towards_later_objects_are_handed_on_reversed() {
        // 0 on the table 2 and touching 1; 1 touching 0 too; 1 has nothing else.
        let placements = [
            lit(Predicate::OnTop, 0, 2),
            lit(Predicate::Touching, 0, 1),
            lit(Predicate::Touching, 1, 0),
        ];
        let steps = placement_order(&placements, &[false, false, true]);
        assert_eq!(order(&steps), [0, 1]);
        assert_eq!(steps[0].literals.len(), 1);
        // 1 gets 0's literal reversed (shown as written) before its own.
        let got: Vec<(Literal, Literal)> = steps[1]
            .literals
            .iter()
            .map(|l| (l.placed, l.written))
            .collect();
        assert_eq!(
            got,
            [
                (
                    lit(Predicate::Touching, 1, 0),
                    lit(Predicate::Touching, 0, 1)
                ),
                (
                    lit(Predicate::Touching, 1, 0),
                    lit(Predicate::Touching, 1, 0)
                ),
            ]
        );
        assert!(steps[1].anchored);
    }

    #[test]
    fn an_object_with_nothing_placed_to_go_by_is_unanchored() {
        // 0 next to 1, neither related to anything that stays.
        let placements = [lit(Predicate::NextTo, 0, 1)];
        let steps = placement_order(&placements, &[false, false]);
        assert_eq!(order(&steps), [0, 1]);
        assert!(!steps[0].anchored && steps[0].literals.is_empty());
        assert!(steps[1].anchored && steps[1].literals.len() == 1);
    }

    #[test]
    fn a_literal_handed_on_counts_as_something_to_go_by() {
        // Four newspapers touching in a ring-like pattern, none related to anything that stays
        // (as in `sorting_mail`'s goal): the first goes unanchored and stays; the fourth, handed
        // the first's literal, goes before the third, which then comes to it.
        let placements = [
            lit(Predicate::Touching, 0, 3),
            lit(Predicate::Touching, 1, 0),
            lit(Predicate::Touching, 2, 3),
            lit(Predicate::Touching, 3, 2),
        ];
        let steps = placement_order(&placements, &[false; 4]);
        assert_eq!(order(&steps), [0, 1, 3, 2]);
        assert!(!steps[0].anchored && steps[0].literals.is_empty());
        assert!(steps[1..].iter().all(|s| s.anchored));
        let written: Vec<Vec<Literal>> = steps
            .iter()
            .map(|s| s.written().copied().collect())
            .collect();
        assert_eq!(written[2], [placements[0]]);
        assert_eq!(written[3], [placements[3], placements[2]]);
    }

    #[test]
    fn a_cycle_is_ordered_anyway() {
        let placements = [lit(Predicate::Inside, 0, 1), lit(Predicate::Inside, 1, 0)];
        let steps = placement_order(&placements, &[false, false]);
        assert_eq!(order(&steps), [0, 1]);
        assert!(!steps[0].anchored);
        assert_eq!(steps[0].literals.len(), 1);
    }
}
