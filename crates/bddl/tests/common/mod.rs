//! An independent, deliberately naive reading of the goal semantics, used as the oracle that the
//! fast implementations are tested against. It works on the lifted goal (no grounding tree), builds
//! the disjunctive normal form by plain products and unions, and searches pairings by brute force.
//! It shares nothing with `ground`, `optimize`, `options` or `matching` but the data types (and
//! the `Counting` switch, which says how to count an option's literals).

#![allow(dead_code)]

use behavior_bddl::Counting;
use behavior_bddl::activity::{Activity, Atom, CategoryId, Goal, InstanceId, Literal, Term};

/// Options beyond this many make a case too large to enumerate.
pub const CAP: usize = 50_000;

fn instances(activity: &Activity, c: CategoryId) -> Vec<InstanceId> {
    activity.category(c).instances.clone()
}

fn atom(goal: &Goal, env: &[InstanceId]) -> Atom {
    let Goal::Atom { predicate, args } = goal else {
        unreachable!()
    };
    let resolve = |t: &Term| match *t {
        Term::Instance(i) => i,
        Term::Var(d) => env[d as usize],
    };
    Atom {
        predicate: *predicate,
        subject: resolve(&args[0]),
        object: args.get(1).map(resolve),
    }
}

/// All k-subsets of 0..n, in lexicographic order.
pub fn subsets(n: usize, k: usize) -> Vec<Vec<usize>> {
    if k == 0 {
        return vec![vec![]];
    }
    if k > n {
        return vec![];
    }
    let mut out = Vec::new();
    for first in 0..=n - k {
        for rest in subsets(n - first - 1, k - 1) {
            let mut s = vec![first];
            s.extend(rest.into_iter().map(|r| r + first + 1));
            out.push(s);
        }
    }
    out
}

/// All injective maps from `k` chosen rows to columns: lists of (row, col).
fn pairings(rows: usize, cols: usize, k: usize) -> Vec<Vec<(usize, usize)>> {
    let mut out = Vec::new();
    for chosen in subsets(rows, k) {
        let mut stack = vec![(0usize, Vec::<(usize, usize)>::new())];
        while let Some((i, acc)) = stack.pop() {
            if i == chosen.len() {
                out.push(acc);
                continue;
            }
            for c in 0..cols {
                if acc.iter().all(|&(_, used)| used != c) {
                    let mut next = acc.clone();
                    next.push((chosen[i], c));
                    stack.push((i + 1, next));
                }
            }
        }
    }
    out
}

/// Whether the goal holds, by direct reading of the semantics.
pub fn holds(
    activity: &Activity,
    goal: &Goal,
    env: &mut Vec<InstanceId>,
    truth: &dyn Fn(Atom) -> bool,
) -> bool {
    let with = |env: &mut Vec<InstanceId>, bound: &[InstanceId], g: &Goal| {
        env.extend_from_slice(bound);
        let r = holds(activity, g, env, truth);
        env.truncate(env.len() - bound.len());
        r
    };
    match goal {
        Goal::Atom { .. } => truth(atom(goal, env)),
        Goal::Not(g) => !holds(activity, g, env, truth),
        Goal::And(gs) => gs.iter().all(|g| holds(activity, g, env, truth)),
        Goal::Or(gs) => gs.iter().any(|g| holds(activity, g, env, truth)),
        Goal::Imply(a, c) => !holds(activity, a, env, truth) || holds(activity, c, env, truth),
        Goal::Iff(a, b) => holds(activity, a, env, truth) == holds(activity, b, env, truth),
        Goal::Forall(c, g) => instances(activity, *c).iter().all(|&i| with(env, &[i], g)),
        Goal::Exists(c, g) => instances(activity, *c).iter().any(|&i| with(env, &[i], g)),
        Goal::ForN(n, c, g) => {
            instances(activity, *c)
                .iter()
                .filter(|&&i| with(env, &[i], g))
                .count()
                >= *n as usize
        }
        Goal::ForPairs(a, b, g) | Goal::ForNPairs(_, a, b, g) => {
            let (ra, rb) = (instances(activity, *a), instances(activity, *b));
            let n = match goal {
                Goal::ForNPairs(n, ..) => *n as usize,
                _ => ra.len().min(rb.len()),
            };
            if n > ra.len().min(rb.len()) {
                return false;
            }
            pairings(ra.len(), rb.len(), n)
                .iter()
                .any(|p| p.iter().all(|&(i, j)| with(env, &[ra[i], rb[j]], g)))
        }
    }
}

type Dnf = Vec<Vec<Literal>>;

fn product(parts: Vec<Dnf>) -> Option<Dnf> {
    let mut acc: Dnf = vec![vec![]];
    for part in parts {
        if acc.len() * part.len() > CAP {
            return None;
        }
        let mut next = Vec::new();
        for a in &acc {
            for p in &part {
                let mut o = a.clone();
                o.extend_from_slice(p);
                next.push(o);
            }
        }
        acc = next;
    }
    Some(acc)
}

fn union(parts: Vec<Dnf>) -> Option<Dnf> {
    let out: Dnf = parts.into_iter().flatten().collect();
    (out.len() <= CAP).then_some(out)
}

/// The options of the goal (or of its negation), by the documented construction; `None` if
/// there would be more than [`CAP`] at some step.
pub fn dnf(
    activity: &Activity,
    goal: &Goal,
    env: &mut Vec<InstanceId>,
    positive: bool,
) -> Option<Dnf> {
    let under = |env: &mut Vec<InstanceId>, bound: &[InstanceId], g: &Goal, pos: bool| {
        env.extend_from_slice(bound);
        let r = dnf(activity, g, env, pos);
        env.truncate(env.len() - bound.len());
        r
    };
    match goal {
        Goal::Atom { .. } => Some(vec![vec![Literal {
            atom: atom(goal, env),
            positive,
        }]]),
        Goal::Not(g) => dnf(activity, g, env, !positive),
        Goal::And(gs) | Goal::Or(gs) => {
            let parts = gs
                .iter()
                .map(|g| dnf(activity, g, env, positive))
                .collect::<Option<Vec<_>>>()?;
            if matches!(goal, Goal::And(_)) == positive {
                product(parts)
            } else {
                union(parts)
            }
        }
        Goal::Imply(a, c) => {
            let (a, c) = (
                dnf(activity, a, env, !positive)?,
                dnf(activity, c, env, positive)?,
            );
            if positive {
                union(vec![a, c])
            } else {
                product(vec![a, c])
            }
        }
        Goal::Iff(a, b) => {
            let both = product(vec![
                dnf(activity, a, env, true)?,
                dnf(activity, b, env, positive)?,
            ])?;
            let neither = product(vec![
                dnf(activity, a, env, false)?,
                dnf(activity, b, env, !positive)?,
            ])?;
            union(vec![both, neither])
        }
        Goal::Forall(c, g) | Goal::Exists(c, g) => {
            let parts = instances(activity, *c)
                .iter()
                .map(|&i| under(env, &[i], g, positive))
                .collect::<Option<Vec<_>>>()?;
            if matches!(goal, Goal::Forall(..)) == positive {
                product(parts)
            } else {
                union(parts)
            }
        }
        Goal::ForN(n, c, g) => {
            let parts = instances(activity, *c)
                .iter()
                .map(|&i| under(env, &[i], g, positive))
                .collect::<Option<Vec<_>>>()?;
            let k = parts.len();
            let need = if positive {
                *n as usize
            } else {
                (k + 1).saturating_sub(*n as usize)
            };
            let mut out = Vec::new();
            for s in subsets(k, need) {
                out.push(product(s.iter().map(|&i| parts[i].clone()).collect())?);
            }
            union(out)
        }
        Goal::ForPairs(a, b, g) | Goal::ForNPairs(_, a, b, g) => {
            let (ra, rb) = (instances(activity, *a), instances(activity, *b));
            let n = match goal {
                Goal::ForNPairs(n, ..) => *n as usize,
                _ => ra.len().min(rb.len()),
            };
            let mut cells = Vec::new();
            for &x in &ra {
                for &y in &rb {
                    cells.push(under(env, &[x, y], g, positive)?);
                }
            }
            let cols = rb.len();
            let mut out = Vec::new();
            if positive {
                for p in pairings(ra.len(), rb.len(), n) {
                    out.push(product(
                        p.iter()
                            .map(|&(i, j)| cells[i * cols + j].clone())
                            .collect(),
                    )?);
                }
            } else if n == 0 {
                // "no empty pairing exists" is false: no options.
            } else if n > ra.len().min(rb.len()) {
                out.push(vec![vec![]]);
            } else {
                // Cover n − 1 of the rows and columns; every uncovered cell must hold (negated).
                for lines in subsets(ra.len() + rb.len(), n - 1) {
                    let uncovered: Vec<Dnf> = (0..ra.len())
                        .filter(|i| !lines.contains(i))
                        .flat_map(|i| {
                            (0..cols)
                                .filter(|j| !lines.contains(&(ra.len() + j)))
                                .map(move |j| (i, j))
                        })
                        .map(|(i, j)| cells[i * cols + j].clone())
                        .collect();
                    out.push(product(uncovered)?);
                }
            }
            union(out)
        }
    }
}

pub fn consistent(option: &[Literal]) -> bool {
    option.iter().all(|a| {
        option
            .iter()
            .all(|b| a.atom != b.atom || a.positive == b.positive)
    })
}

/// An option's literals as that counting counts them: each once, sorted, for sets; as built,
/// for the reference's lists.
pub fn counted(option: &[Literal], counting: Counting) -> Vec<Literal> {
    let mut literals = option.to_vec();
    if counting == Counting::Set {
        literals.sort();
        literals.dedup();
    }
    literals
}

/// The consistent options as that counting lists them, in a canonical order: for sets, every
/// option's literals sorted and deduplicated, each set once; for the reference's lists, every
/// option as built (literals sorted), as often as it is built.
pub fn consistent_options(options: &Dnf, counting: Counting) -> Dnf {
    let mut listed: Dnf = options
        .iter()
        .filter(|o| consistent(o))
        .map(|o| {
            let mut o = counted(o, counting);
            o.sort();
            o
        })
        .collect();
    listed.sort();
    if counting == Counting::Set {
        listed.dedup();
    }
    listed
}

/// (smallest size, best ratio as (satisfied, size)) over the consistent options, their literals
/// counted as `counting` says.
pub fn volume_and_q(
    options: &Dnf,
    truth: &dyn Fn(Atom) -> bool,
    counting: Counting,
) -> (Option<usize>, Option<(u64, u64)>) {
    let mut volume: Option<usize> = None;
    let mut best: Option<(u64, u64)> = None;
    for o in options.iter().filter(|o| consistent(o)) {
        let o = counted(o, counting);
        volume = Some(volume.map_or(o.len(), |v| v.min(o.len())));
        let sat = o.iter().filter(|l| truth(l.atom) == l.positive).count() as u64;
        let ratio = if o.is_empty() {
            (1, 1)
        } else {
            (sat, o.len() as u64)
        };
        if best.is_none_or(|(bs, bn)| ratio.0 * bn > bs * ratio.1) {
            best = Some(ratio);
        }
    }
    (volume, best)
}

/// A deterministic pseudo-random truth assignment: each atom is true with probability ~1/2.
pub fn random_truth(seed: u64) -> impl Fn(Atom) -> bool {
    move |a: Atom| {
        let mut x = seed
            ^ (a.predicate as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15)
            ^ u64::from(a.subject.0).wrapping_mul(0xbf58_476d_1ce4_e5b9)
            ^ a.object
                .map_or(0x1234_5678, |o| u64::from(o.0) + 1)
                .wrapping_mul(0x94d0_49bb_1331_11eb);
        x ^= x >> 31;
        x = x.wrapping_mul(0xd6e8_feb8_6659_fd93);
        x ^= x >> 29;
        x & 1 == 1
    }
}

/// Every `:init` literal as a fact in the form `behavior facts` prints (`["ontop", "a", "b"]`,
/// `["inroom", "a", "kitchen"]`), with whether it must hold: to read an initial state off a list
/// of facts alone.
pub fn init_as_facts(activity: &Activity) -> Vec<(Vec<String>, bool)> {
    use behavior_bddl::activity::InitLiteral;
    let name = |i: InstanceId| activity.instance(i).name.clone();
    activity
        .init
        .iter()
        .map(|literal| match literal {
            InitLiteral::Atom(l) => {
                let mut fact = vec![l.atom.predicate.name().to_string(), name(l.atom.subject)];
                fact.extend(l.atom.object.map(name));
                (fact, l.positive)
            }
            InitLiteral::InRoom {
                instance,
                room,
                positive,
            } => (
                vec!["inroom".into(), name(*instance), room.name().to_string()],
                *positive,
            ),
        })
        .collect()
}
