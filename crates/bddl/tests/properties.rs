//! Property tests: on thousands of small random goals over every operator and quantifier, the
//! fast computations (ground truth, exact Q and volume, the lazy option iterator) agree with a
//! naive enumeration of the disjunctive normal form and a direct reading of the semantics, with
//! options counted as sets (the default) and as the reference's lists. The goals repeat literals
//! on purpose — a subformula written twice, literals over fixed instances inside quantifiers —
//! so that the two countings differ often.

mod common;

use behavior_bddl::activity::{Activity, CheckContext};
use behavior_bddl::options::options_with;
use behavior_bddl::{Counting, GroundGoal, Optimizer, Source};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

/// A random formula over two categories `a.n.01` and `b.n.01`; term and category choices are
/// indices resolved at rendering time against what is in scope.
#[derive(Clone, Debug)]
enum F {
    Atom(u8, u8, u8),
    /// One of two literals over fixed instances, `(cooked a.n.01_1)` or `(open b.n.01_1)`: the
    /// same literal wherever it appears, in every branch of a quantifier around it.
    Fixed(bool),
    /// The subformula written twice, under `and` (true) or `or`.
    Twice(bool, Box<F>),
    Not(Box<F>),
    And(Vec<F>),
    Or(Vec<F>),
    Imply(Box<F>, Box<F>),
    Iff(Box<F>, Box<F>),
    Forall(bool, Box<F>),
    Exists(bool, Box<F>),
    ForN(u8, bool, Box<F>),
    ForPairs(Box<F>),
    ForNPairs(u8, Box<F>),
}

fn formula() -> impl Strategy<Value = F> {
    let atom = (0u8..4, any::<u8>(), any::<u8>()).prop_map(|(p, a, b)| F::Atom(p, a, b));
    let leaf = prop_oneof![3 => atom, 1 => any::<bool>().prop_map(F::Fixed)];
    leaf.prop_recursive(4, 24, 3, |inner| {
        prop_oneof![
            inner.clone().prop_map(|f| F::Not(Box::new(f))),
            (any::<bool>(), inner.clone()).prop_map(|(and, f)| F::Twice(and, Box::new(f))),
            prop::collection::vec(inner.clone(), 0..3).prop_map(F::And),
            prop::collection::vec(inner.clone(), 0..3).prop_map(F::Or),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| F::Imply(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| F::Iff(Box::new(a), Box::new(b))),
            (any::<bool>(), inner.clone()).prop_map(|(c, f)| F::Forall(c, Box::new(f))),
            (any::<bool>(), inner.clone()).prop_map(|(c, f)| F::Exists(c, Box::new(f))),
            (0u8..4, any::<bool>(), inner.clone()).prop_map(|(n, c, f)| F::ForN(n, c, Box::new(f))),
            inner.clone().prop_map(|f| F::ForPairs(Box::new(f))),
            (0u8..4, inner).prop_map(|(n, f)| F::ForNPairs(n, Box::new(f))),
        ]
    })
}

const PREDICATES: [(&str, bool); 4] = [
    ("cooked", false),
    ("open", false),
    ("ontop", true),
    ("inside", true),
];

fn category(b: bool) -> &'static str {
    if b { "b.n.01" } else { "a.n.01" }
}

/// Renders `head (var - category)... body)` with the variables bound while rendering the body.
fn nested(
    f: &F,
    vars: &[(String, bool)],
    head: String,
    instances: &[String],
    scope: &mut Vec<String>,
    out: &mut String,
) {
    out.push_str(&head);
    for (v, c) in vars {
        out.push_str(&format!(" ({v} - {})", category(*c)));
    }
    out.push(' ');
    scope.extend(vars.iter().map(|(v, _)| v.clone()));
    render(f, instances, scope, out);
    scope.truncate(scope.len() - vars.len());
    out.push(')');
}

/// Renders BDDL text; `scope` holds the variables bound so far.
fn render(f: &F, instances: &[String], scope: &mut Vec<String>, out: &mut String) {
    let nested =
        |f: &F,
         vars: &[(String, bool)],
         head: String,
         scope: &mut Vec<String>,
         out: &mut String| { nested(f, vars, head, instances, scope, out) };
    let depth = scope.len();
    match f {
        F::Atom(p, a, b) => {
            let terms: Vec<&String> = instances.iter().chain(scope.iter()).collect();
            let (name, binary) = PREDICATES[*p as usize];
            out.push_str(&format!("({name} {}", terms[*a as usize % terms.len()]));
            if binary {
                out.push_str(&format!(" {}", terms[*b as usize % terms.len()]));
            }
            out.push(')');
        }
        F::Fixed(cooked) => out.push_str(if *cooked {
            "(cooked a.n.01_1)"
        } else {
            "(open b.n.01_1)"
        }),
        F::Twice(and, g) => {
            out.push_str(if *and { "(and " } else { "(or " });
            render(g, instances, scope, out);
            out.push(' ');
            render(g, instances, scope, out);
            out.push(')');
        }
        F::Not(g) => nested(g, &[], "(not".into(), scope, out),
        F::And(gs) | F::Or(gs) => {
            out.push_str(if matches!(f, F::And(_)) {
                "(and"
            } else {
                "(or"
            });
            for g in gs {
                out.push(' ');
                render(g, instances, scope, out);
            }
            out.push(')');
        }
        F::Imply(a, b) | F::Iff(a, b) => {
            out.push_str(if matches!(f, F::Imply(..)) {
                "(imply "
            } else {
                "(iff "
            });
            render(a, instances, scope, out);
            out.push(' ');
            render(b, instances, scope, out);
            out.push(')');
        }
        F::Forall(c, g) => nested(
            g,
            &[(format!("?v{depth}"), *c)],
            "(forall".into(),
            scope,
            out,
        ),
        F::Exists(c, g) => nested(
            g,
            &[(format!("?v{depth}"), *c)],
            "(exists".into(),
            scope,
            out,
        ),
        F::ForN(n, c, g) => nested(
            g,
            &[(format!("?v{depth}"), *c)],
            format!("(forn ({n})"),
            scope,
            out,
        ),
        F::ForPairs(g) => nested(
            g,
            &[(format!("?v{depth}"), false), (format!("?w{depth}"), true)],
            "(forpairs".into(),
            scope,
            out,
        ),
        F::ForNPairs(n, g) => nested(
            g,
            &[(format!("?v{depth}"), false), (format!("?w{depth}"), true)],
            format!("(fornpairs ({n})"),
            scope,
            out,
        ),
    }
}

fn activity(f: &F, a: usize, b: usize) -> Activity {
    let mut instances: Vec<String> = (1..=a).map(|i| format!("a.n.01_{i}")).collect();
    instances.extend((1..=b).map(|i| format!("b.n.01_{i}")));
    let mut goal = String::new();
    render(f, &instances, &mut Vec::new(), &mut goal);
    let objects = format!(
        "{} - a.n.01 {} - b.n.01",
        instances[..a].join(" "),
        instances[a..].join(" ")
    );
    let text = format!(
        "(define (problem random_0) (:domain igibson) (:objects {objects}) (:init) (:goal {goal}))"
    );
    match Activity::load(
        &Source::new("random.bddl", text.clone()),
        CheckContext::default(),
    ) {
        Ok((activity, _)) => activity,
        Err(e) => panic!("generated text did not check:\n{text}\n{e}"),
    }
}

/// Our options in the naive evaluator's canonical order: literals sorted within each option,
/// options sorted; nothing removed, so a repeated literal or option of ours shows.
fn canonical(mut options: Vec<Vec<behavior_bddl::Literal>>) -> Vec<Vec<behavior_bddl::Literal>> {
    for o in &mut options {
        o.sort();
    }
    options.sort();
    options
}

/// Volume, Q and the listed options under one counting, against the naive enumeration.
fn agree_under(
    ground: &GroundGoal,
    all: &Vec<Vec<behavior_bddl::Literal>>,
    truth: &dyn Fn(behavior_bddl::Atom) -> bool,
    counting: Counting,
) -> Result<(), TestCaseError> {
    let optimizer = Optimizer::with_counting(ground, counting);
    let (volume, q) = common::volume_and_q(all, truth, counting);
    prop_assert_eq!(
        optimizer.volume().map(|v| v as usize),
        volume,
        "{:?}",
        counting
    );
    let ours = optimizer.q(&truth).map(|r| (r.num, r.den));
    let expected = q.map(|(s, n)| {
        let r = behavior_bddl::Ratio::new(s, n);
        (r.num, r.den)
    });
    prop_assert_eq!(ours, expected, "{:?}", counting);

    // The lazy iterator yields exactly the consistent options, smallest first.
    let listed: Vec<_> = options_with(ground, counting)
        .take(common::CAP + 1)
        .collect();
    prop_assert!(
        listed.windows(2).all(|w| w[0].len() <= w[1].len()),
        "{:?}",
        counting
    );
    prop_assert_eq!(
        canonical(listed),
        common::consistent_options(all, counting),
        "{:?}",
        counting
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn fast_computations_agree_with_enumeration(f in formula(), a in 1usize..4, b in 1usize..4, seed in any::<u64>()) {
        let activity = activity(&f, a, b);
        let goal_formula = activity.goal_formula();
        let Some(all) = common::dnf(&activity, &goal_formula, &mut Vec::new(), true) else {
            return Ok(()); // too many options to enumerate; the case is skipped
        };
        let truth = common::random_truth(seed);
        let ground = GroundGoal::new(&activity);

        // Truth: direct semantics, ground tree, and "some consistent option is fully true".
        let direct = common::holds(&activity, &goal_formula, &mut Vec::new(), &truth);
        prop_assert_eq!(ground.holds(&truth), direct);
        let some_option_true = all.iter().any(|o| common::consistent(o) && o.iter().all(|l| truth(l.atom) == l.positive));
        prop_assert_eq!(some_option_true, direct);

        agree_under(&ground, &all, &truth, Counting::Set)?;
        agree_under(&ground, &all, &truth, Counting::Reference)?;
    }
}

/// The generator must make the countings differ often, or the property above would not test
/// set counting: on 500 random goals, volume or Q (on a random state) differ between the naive
/// set and list countings in at least 10 %.
#[test]
fn random_goals_often_count_differently_as_sets() {
    let mut runner = TestRunner::deterministic();
    let (mut enumerated, mut differ) = (0, 0);
    for seed in 0..500u64 {
        let f = formula().new_tree(&mut runner).unwrap().current();
        let activity = activity(&f, 2, 2);
        let Some(all) = common::dnf(&activity, &activity.goal_formula(), &mut Vec::new(), true)
        else {
            continue;
        };
        enumerated += 1;
        let truth = common::random_truth(seed);
        let set = common::volume_and_q(&all, &truth, Counting::Set);
        let list = common::volume_and_q(&all, &truth, Counting::Reference);
        differ += usize::from(set != list);
    }
    assert!(enumerated > 400, "only {enumerated} goals enumerated");
    assert!(
        differ * 10 >= enumerated,
        "only {differ} of {enumerated} goals count differently as sets"
    );
}
