//! Property tests: on thousands of small random goals over every operator and quantifier, the
//! fast computations (ground truth, exact Q and volume, the lazy option iterator) agree with a
//! naive enumeration of the disjunctive normal form and a direct reading of the semantics.

mod common;

use behavior_bddl::activity::{Activity, CheckContext};
use behavior_bddl::options::options;
use behavior_bddl::{GroundGoal, Optimizer, Source};
use proptest::prelude::*;

/// A random formula over two categories `a.n.01` and `b.n.01`; term and category choices are
/// indices resolved at rendering time against what is in scope.
#[derive(Clone, Debug)]
enum F {
    Atom(u8, u8, u8),
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
    let leaf = (0u8..4, any::<u8>(), any::<u8>()).prop_map(|(p, a, b)| F::Atom(p, a, b));
    leaf.prop_recursive(4, 24, 3, |inner| {
        prop_oneof![
            inner.clone().prop_map(|f| F::Not(Box::new(f))),
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

fn canonical(mut options: Vec<Vec<behavior_bddl::Literal>>) -> Vec<Vec<behavior_bddl::Literal>> {
    for o in &mut options {
        o.sort();
    }
    options.sort();
    options
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
        let optimizer = Optimizer::new(&ground);

        // Truth: direct semantics, ground tree, and "some consistent option is fully true".
        let direct = common::holds(&activity, &goal_formula, &mut Vec::new(), &truth);
        prop_assert_eq!(ground.holds(&truth), direct);
        let some_option_true = all.iter().any(|o| common::consistent(o) && o.iter().all(|l| truth(l.atom) == l.positive));
        prop_assert_eq!(some_option_true, direct);

        // Exact volume and Q.
        let (volume, q) = common::volume_and_q(&all, &truth);
        prop_assert_eq!(optimizer.volume().map(|v| v as usize), volume);
        let ours = optimizer.q(&truth).map(|r| (r.num, r.den));
        let expected = q.map(|(s, n)| { let r = behavior_bddl::Ratio::new(s, n); (r.num, r.den) });
        prop_assert_eq!(ours, expected);

        // The lazy iterator yields exactly the consistent options, smallest first.
        let listed: Vec<_> = options(&ground).take(common::CAP + 1).collect();
        prop_assert!(listed.windows(2).all(|w| w[0].len() <= w[1].len()));
        let consistent: Vec<_> = all.into_iter().filter(|o| common::consistent(o)).collect();
        prop_assert_eq!(canonical(listed), canonical(consistent));
    }
}
