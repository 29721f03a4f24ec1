//! Bidirectional RRT (RRT-Connect) with restarts and shortcut smoothing, over any [`Space`]; the
//! search of the original's `birrt` (iGibson 2.0.3's `envs/behavior_mp_env.py`), its parameters the
//! defaults.

use crate::error::PlanError;
use behavior_core::rng::{SimRng, seeded, uniform};
use serde::{Deserialize, Serialize};

/// A configuration space: how far apart two configurations are, how the robot moves between
/// them, and which configurations are free. Implemented by the base (x, y, yaw) and by arms and
/// hands.
pub trait Space {
    /// A point of the space.
    type Config: Clone + PartialEq + std::fmt::Debug;

    /// The cost of moving from `a` to `b` (nearest neighbours are found by it).
    fn distance(&self, a: &Self::Config, b: &Self::Config) -> f32;
    /// A random configuration within the space's bounds.
    fn sample(&self, rng: &mut SimRng) -> Self::Config;
    /// The configurations the robot passes from `a` to `b`, at most `resolution` apart, without
    /// `a` and ending exactly at `b`.
    fn steps(&self, a: &Self::Config, b: &Self::Config, resolution: f32) -> Vec<Self::Config>;
    /// Whether the robot in `c` touches nothing.
    fn free(&self, c: &Self::Config) -> bool;
    /// How finely paths are checked.
    fn resolution(&self) -> f32;
}

/// The search's budget, by default the original's (pybullet-planning's `RRT_ITERATIONS`,
/// `RRT_RESTARTS`, `RRT_SMOOTHING`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PlanParams {
    /// Iterations of one RRT-Connect run: each grows one tree toward a random sample as far as
    /// it is free, then the other tree toward the first.
    pub iterations: u32,
    /// Runs after the first, each with new trees.
    pub restarts: u32,
    /// Shortcut attempts on the path found.
    pub smoothing: u32,
    /// Seeds the samples: the same seed, world and endpoints give the same path.
    pub seed: u64,
    /// Nodes [`crate::lattice_plan`]'s search expands before it gives up (ours: the original
    /// has no lattice). 25,000 is about 2 s on this machine; traced in one Fetch run
    /// (setting_up_candles, seed 1), the searches that found a way expanded up to 6,700, those
    /// that found none where the goal's cells joined the start's 35,000–51,000 (stands by a
    /// wall that the base can only turn into at their own heading).
    pub expansions: usize,
}

impl Default for PlanParams {
    fn default() -> Self {
        PlanParams {
            iterations: 20,
            restarts: 2,
            smoothing: 20,
            seed: 0,
            expansions: 25_000,
        }
    }
}

/// A collision-free path from the start to the goal, at the space's resolution.
pub type Path<C> = Vec<C>;

/// What [`plan`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct Planned<C> {
    /// The start, the configurations passed, the goal.
    pub path: Path<C>,
    /// 0 if the direct path was free, else which RRT run found it (1 for the first).
    pub run: u32,
}

/// A tree of free configurations, each but the root with its parent.
struct Tree<C> {
    nodes: Vec<(C, Option<usize>)>,
}

impl<C: Clone> Tree<C> {
    fn new(root: C) -> Tree<C> {
        Tree {
            nodes: vec![(root, None)],
        }
    }

    /// The node nearest `to` (the first of equals).
    fn nearest<S: Space<Config = C>>(&self, space: &S, to: &C) -> usize {
        let mut best = (0, f32::INFINITY);
        for (k, (c, _)) in self.nodes.iter().enumerate() {
            let d = space.distance(c, to);
            if d < best.1 {
                best = (k, d);
            }
        }
        best.0
    }

    /// Grows from node `from` toward `to` while free; the last node reached and whether it is
    /// `to`.
    fn grow<S: Space<Config = C>>(&mut self, space: &S, from: usize, to: &C) -> (usize, bool) {
        let mut last = from;
        for c in space.steps(&self.nodes[from].0, to, space.resolution()) {
            if !space.free(&c) {
                return (last, false);
            }
            self.nodes.push((c, Some(last)));
            last = self.nodes.len() - 1;
        }
        (last, true)
    }

    /// The configurations from the root to `node`.
    fn trace(&self, mut node: usize) -> Vec<C> {
        let mut out = vec![self.nodes[node].0.clone()];
        while let Some(parent) = self.nodes[node].1 {
            out.push(self.nodes[parent].0.clone());
            node = parent;
        }
        out.reverse();
        out
    }
}

/// A free path from `start` to `goal`: the direct one if free, else RRT-Connect with restarts;
/// then shortcut-smoothed and checked again at half the resolution.
pub fn plan<S: Space>(
    space: &S,
    start: &S::Config,
    goal: &S::Config,
    params: &PlanParams,
) -> Result<Planned<S::Config>, PlanError> {
    if !space.free(start) {
        return Err(PlanError::StartInCollision);
    }
    if !space.free(goal) {
        return Err(PlanError::GoalInCollision);
    }
    if let Some(path) = direct(space, start, goal) {
        return Ok(Planned { path, run: 0 });
    }
    let mut rng = seeded(params.seed);
    for run in 1..=params.restarts + 1 {
        let Some(path) = connect(space, start, goal, params.iterations, &mut rng) else {
            continue;
        };
        let path = smooth(space, path, params.smoothing, &mut rng);
        if valid(space, &path) {
            return Ok(Planned { path, run });
        }
    }
    Err(PlanError::NoPath {
        restarts: params.restarts,
        iterations: params.iterations,
    })
}

/// The straight motion from `a` to `b` if every step of it is free.
fn direct<S: Space>(space: &S, a: &S::Config, b: &S::Config) -> Option<Path<S::Config>> {
    let steps = space.steps(a, b, space.resolution());
    steps.iter().all(|c| space.free(c)).then(|| {
        let mut path = vec![a.clone()];
        path.extend(steps);
        path
    })
}

/// One RRT-Connect run (pybullet-planning's `rrt_connect`): the smaller tree grows toward a
/// sample, the other toward where the first stopped; done when they meet.
fn connect<S: Space>(
    space: &S,
    start: &S::Config,
    goal: &S::Config,
    iterations: u32,
    rng: &mut SimRng,
) -> Option<Path<S::Config>> {
    let (mut from_start, mut from_goal) = (Tree::new(start.clone()), Tree::new(goal.clone()));
    for _ in 0..iterations {
        let swap = from_start.nodes.len() > from_goal.nodes.len();
        let (first, second) = if swap {
            (&mut from_goal, &mut from_start)
        } else {
            (&mut from_start, &mut from_goal)
        };
        let sample = space.sample(rng);
        let nearest = first.nearest(space, &sample);
        let (reached, _) = first.grow(space, nearest, &sample);
        let target = first.nodes[reached].0.clone();
        let nearest = second.nearest(space, &target);
        let (met, joined) = second.grow(space, nearest, &target);
        if joined {
            let (a, b) = (first.trace(reached), second.trace(met));
            let (to_start_side, to_goal_side) = if swap { (b, a) } else { (a, b) };
            let mut path = to_start_side;
            path.extend(to_goal_side.into_iter().rev().skip(1));
            return Some(path);
        }
    }
    None
}

/// Shortcuts: a random pair of configurations on the path joined directly where that motion is
/// free (pybullet-planning's `smooth_path`).
pub fn smooth<S: Space>(
    space: &S,
    mut path: Path<S::Config>,
    attempts: u32,
    rng: &mut SimRng,
) -> Path<S::Config> {
    for _ in 0..attempts {
        let n = path.len();
        if n < 3 {
            break;
        }
        let pick = |rng: &mut SimRng| ((uniform(rng, 0.0, 1.0) * n as f32) as usize).min(n - 1);
        let (i, j) = (pick(rng), pick(rng));
        let (i, j) = (i.min(j), i.max(j));
        if j <= i + 1 {
            continue;
        }
        if let Some(shortcut) = direct(space, &path[i], &path[j]) {
            let mut out = path[..i].to_vec();
            out.extend(shortcut);
            out.extend_from_slice(&path[j + 1..]);
            path = out;
        }
    }
    path
}

/// Every configuration passed along `path` at the space's resolution, after its first: what a
/// robot is driven through, one configuration at a time.
pub fn steps_along<S: Space>(space: &S, path: &[S::Config]) -> Vec<S::Config> {
    path.windows(2)
        .flat_map(|w| space.steps(&w[0], &w[1], space.resolution()))
        .collect()
}

/// Every motion between consecutive configurations free at half the resolution.
pub fn valid<S: Space>(space: &S, path: &[S::Config]) -> bool {
    let fine = 0.5 * space.resolution();
    path.windows(2).all(|w| {
        space
            .steps(&w[0], &w[1], fine)
            .iter()
            .all(|c| space.free(c))
    })
}
