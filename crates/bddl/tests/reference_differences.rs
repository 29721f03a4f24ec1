//! Where our semantics differ from the reference implementation's (Python `bddl` 1.0.1), each
//! case named after the reference's behaviour (the guide's chapter on semantics lists them) and
//! shown on a small goal. The reference's answer is stated in each test; ours is asserted. Each test counts
//! options as the reference does (`Counting::Reference`) so that it shows one difference only,
//! except the last, which is about counting itself. None of these situations but counting occurs
//! in the 100 official activities (see `official.rs`).

use behavior_bddl::activity::{Activity, CheckContext};
use behavior_bddl::options::options_with;
use behavior_bddl::{Counting, FactSet, GroundGoal, Optimizer, Predicate, Ratio, Source};

/// Options listed as the reference counts them.
fn options(goal: &GroundGoal) -> impl Iterator<Item = Vec<behavior_bddl::Literal>> + '_ {
    options_with(goal, Counting::Reference)
}

/// The optimizer counting as the reference does.
fn optimizer(goal: &GroundGoal) -> Optimizer<'_> {
    Optimizer::with_counting(goal, Counting::Reference)
}

fn activity(objects: &str, goal: &str) -> Activity {
    let text = format!(
        "(define (problem p_0) (:domain igibson) (:objects {objects}) (:init) (:goal {goal}))"
    );
    Activity::load(&Source::new("p.bddl", text), CheckContext::default())
        .unwrap_or_else(|e| panic!("{e}"))
        .0
}

/// Facts given as (predicate, subject, object) names.
fn state(activity: &Activity, facts: &[(&str, &str, Option<&str>)]) -> FactSet {
    facts
        .iter()
        .map(|&(p, s, o)| behavior_bddl::Atom {
            predicate: Predicate::from_name(p).unwrap(),
            subject: activity.instance_named(s).unwrap(),
            object: o.map(|o| activity.instance_named(o).unwrap()),
        })
        .collect()
}

const AB: &str = "a.n.01_1 a.n.01_2 a.n.01_3 - a.n.01 b.n.01_1 b.n.01_2 b.n.01_3 - b.n.01";

/// Quirk 5: the reference's `forn (N)` means exactly N; the paper (and we) mean at least N.
#[test]
fn quirk_5_forn_means_at_least_n() {
    let a = activity(AB, "(forn (1) (?a.n.01 - a.n.01) (cooked ?a.n.01))");
    let s = state(
        &a,
        &[("cooked", "a.n.01_1", None), ("cooked", "a.n.01_2", None)],
    );
    assert!(GroundGoal::new(&a).holds(&s)); // reference: false (two hold, not exactly one)
}

/// The 3×3 pattern below has a true cell in every row and column but no perfect pairing.
const CROSS: [(&str, &str); 5] = [
    ("a.n.01_1", "b.n.01_1"),
    ("a.n.01_1", "b.n.01_2"),
    ("a.n.01_1", "b.n.01_3"),
    ("a.n.01_2", "b.n.01_1"),
    ("a.n.01_3", "b.n.01_1"),
];

fn cross_state(a: &Activity) -> FactSet {
    let facts: Vec<_> = CROSS.iter().map(|&(x, y)| ("ontop", x, Some(y))).collect();
    state(a, &facts)
}

/// Quirk 6: the reference's `forpairs` only checks that every row and column has a true cell.
#[test]
fn quirk_6_forpairs_needs_a_real_one_to_one_pairing() {
    let a = activity(
        AB,
        "(forpairs (?a.n.01 - a.n.01) (?b.n.01 - b.n.01) (ontop ?a.n.01 ?b.n.01))",
    );
    let goal = GroundGoal::new(&a);
    assert!(!goal.holds(&cross_state(&a))); // reference: true
    // Q: the best pairing has 2 of its 3 pairs true.
    assert_eq!(
        optimizer(&goal).q(&cross_state(&a)).unwrap().to_string(),
        "2/3"
    );
}

/// Quirk 6 for `fornpairs`: the reference counts rows and columns, not disjoint pairs.
#[test]
fn quirk_6_fornpairs_counts_disjoint_pairs() {
    let a = activity(
        AB,
        "(fornpairs (3) (?a.n.01 - a.n.01) (?b.n.01 - b.n.01) (ontop ?a.n.01 ?b.n.01))",
    );
    assert!(!GroundGoal::new(&a).holds(&cross_state(&a))); // reference: true
    let two = activity(
        AB,
        "(fornpairs (2) (?a.n.01 - a.n.01) (?b.n.01 - b.n.01) (ontop ?a.n.01 ?b.n.01))",
    );
    assert!(GroundGoal::new(&two).holds(&cross_state(&two)));
}

/// Quirk 7: the reference drops same-object pairs when both categories are the same; we pair any
/// two instances, so each apple may be paired with itself.
#[test]
fn quirk_7_same_category_pairs_include_an_object_with_itself() {
    let a = activity(
        "a.n.01_1 a.n.01_2 - a.n.01",
        "(forpairs (?x - a.n.01) (?y - a.n.01) (nextto ?x ?y))",
    );
    let s = state(
        &a,
        &[
            ("nextto", "a.n.01_1", Some("a.n.01_1")),
            ("nextto", "a.n.01_2", Some("a.n.01_2")),
        ],
    );
    assert!(GroundGoal::new(&a).holds(&s)); // reference: false (pairs (1,2) and (2,1) only)
}

/// Quirk 8: the reference's `fornpairs` options pair only the first N instances of the first
/// category; ours range over every set of N disjoint pairs.
#[test]
fn quirk_8_fornpairs_options_use_every_instance() {
    let a = activity(
        "a.n.01_1 a.n.01_2 a.n.01_3 - a.n.01 b.n.01_1 b.n.01_2 - b.n.01",
        "(fornpairs (1) (?a.n.01 - a.n.01) (?b.n.01 - b.n.01) (ontop ?a.n.01 ?b.n.01))",
    );
    // reference: 2 options, (a1, b1) and (a1, b2)
    assert_eq!(options(&GroundGoal::new(&a)).count(), 6);
}

/// Quirk 15: the reference keeps `(not (not x))` as a literal; we simplify it to `x`.
#[test]
fn quirk_15_double_negation_is_simplified() {
    let a = activity(AB, "(not (not (cooked a.n.01_1)))");
    let listed: Vec<_> = options(&GroundGoal::new(&a)).collect();
    assert_eq!(listed.len(), 1);
    assert_eq!(a.show_literal(listed[0][0]), "(cooked a.n.01_1)");
}

/// Quirk 12 and the reference's crash on a goal without consistent options: we report `None`
/// for Q and volume of a goal that can never hold, instead of failing.
#[test]
fn a_goal_that_can_never_hold_has_no_volume_or_q() {
    let a = activity(AB, "(and (cooked a.n.01_1) (not (cooked a.n.01_1)))");
    let goal = GroundGoal::new(&a);
    let optimizer = optimizer(&goal);
    assert_eq!(optimizer.volume(), None); // reference: AssertionError (no option)
    assert_eq!(optimizer.q(&FactSet::default()), None);
    assert_eq!(options(&goal).count(), 0);
}

/// The paper's Q divides by the set cardinality of an option; the reference counts a literal
/// each time it is built into the option. Here `(cooked a1)` is reached once per instance of a
/// `forall`, and `(open a1)` both inside an `exists` and at the top.
#[test]
fn an_option_is_a_set_a_literal_written_twice_counts_once() {
    let a = activity(
        AB,
        "(and (forall (?a.n.01 - a.n.01) (and (ontop ?a.n.01 b.n.01_1) (cooked a.n.01_1)))
              (exists (?b.n.01 - b.n.01) (and (open a.n.01_1) (nextto a.n.01_1 ?b.n.01)))
              (open a.n.01_1))",
    );
    let goal = GroundGoal::new(&a);
    let s = state(&a, &[("cooked", "a.n.01_1", None)]);
    // As sets: 3 ontop + cooked + open + one nextto = 6 literals, one true.
    let set = Optimizer::new(&goal);
    assert_eq!(set.volume(), Some(6));
    assert_eq!(set.q(&s), Some(Ratio::new(1, 6)));
    // As lists: cooked three times, open twice: 9 literals, three true.
    let reference = optimizer(&goal);
    assert_eq!(reference.volume(), Some(9));
    assert_eq!(reference.q(&s), Some(Ratio::new(3, 9)));
    // Three ways to pick the `nextto`: three options either way, each a set of 6 by default.
    let sets: Vec<_> = options_with(&goal, Counting::Set).collect();
    assert_eq!(sets.len(), 3);
    assert!(sets.iter().all(|o| o.len() == 6));
    assert!(options(&goal).all(|o| o.len() == 9));
}
