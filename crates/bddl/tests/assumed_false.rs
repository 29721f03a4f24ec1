//! Goals with atoms known to be false (an object next to itself): options skip them, truth keeps.

use behavior_bddl::activity::{Activity, CheckContext};
use behavior_bddl::options::options;
use behavior_bddl::{GroundGoal, Source};

#[test]
fn options_never_ask_for_an_atom_assumed_false() {
    // Every envelope touches one of the first two: the smallest options pick `e1` for `e1`.
    let text = "(define (problem p_0) (:domain igibson)
      (:objects e.n.01_1 e.n.01_2 e.n.01_3 - e.n.01) (:init)
      (:goal (forall (?e.n.01 - e.n.01) (or (touching ?e.n.01 ?e.n.01_1) (touching ?e.n.01 ?e.n.01_2)))))";
    let (activity, _) = Activity::load(&Source::new("p.bddl", text), CheckContext::default())
        .unwrap_or_else(|e| panic!("{e}"));
    let goal = GroundGoal::new(&activity);
    let is_self = |a: behavior_bddl::Atom| a.object == Some(a.subject);
    let first = options(&goal).next().unwrap();
    assert!(
        first.iter().any(|l| is_self(l.atom)),
        "the plain goal asks for self-touching"
    );

    let assumed = goal.assuming_false(is_self);
    let all: Vec<_> = options(&assumed).collect();
    // e1 must touch e2, e2 must touch e1, e3 either: two options.
    assert_eq!(all.len(), 2);
    assert!(all.iter().flatten().all(|l| !is_self(l.atom)));
    // Truth agrees with the plain goal on every state where the self atoms are false.
    let atoms: Vec<_> = goal
        .atoms
        .iter()
        .copied()
        .filter(|&a| !is_self(a))
        .collect();
    for bits in 0u32..(1 << atoms.len()) {
        let truth = |a: behavior_bddl::Atom| {
            atoms
                .iter()
                .position(|&b| b == a)
                .is_some_and(|k| bits & (1 << k) != 0)
        };
        let plain = goal.node_holds(goal.root, &|id| truth(goal.atom(id)));
        let with = assumed.node_holds(assumed.root, &|id| truth(assumed.atom(id)));
        assert_eq!(plain, with, "state {bits:b}");
    }
}
