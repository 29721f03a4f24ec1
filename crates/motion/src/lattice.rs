//! A lattice over the base's configurations, searched with A*: the fallback where RRT-Connect's
//! random samples miss a narrow way (a door between two rooms, a gap between a sofa and a
//! table). The July 2021 version of the original sampled its base planner's points from the
//! home's traversable map for the same reason; a lattice finds such a way where one exists at
//! its resolution within [`PlanParams::expansions`] nodes, and says at once when the goal's cells
//! are cut off from the start's.
//!
//! Nodes stand on a square grid of `LATTICE_CELL` anchored at the start, facing one of
//! `LATTICE_HEADINGS` headings. From a node the base turns to the next heading either way, or
//! drives one cell ahead or back (the grid's neighbour along its heading, straight or diagonal):
//! exactly the motions [`BaseSpace`]'s steps make, so the path found is checked by the same
//! space, at the same resolution, as an RRT path, then shortcut like one.

use crate::base::{BaseConfig, BaseSpace};
use crate::error::PlanError;
use crate::rrt::{PlanParams, Space, smooth, valid};
use behavior_core::rng::seeded;
use pathfinding::directed::astar::astar;
use pathfinding::directed::dijkstra::dijkstra_all;
use std::cell::{Cell, RefCell};
use std::collections::{HashMap, HashSet};
use std::f32::consts::PI;

/// The grid's spacing on the floor, m: two of the space's 0.05 m steps.
pub(crate) const LATTICE_CELL: f32 = 0.1;
/// The headings a node may face: along the grid's axes and diagonals.
pub(crate) const LATTICE_HEADINGS: u8 = 8;
/// How near the goal a node must stand to try the direct motion into it, m.
const GOAL_RADIUS: f32 = 0.25;
/// How many cells away from the start the first nodes may lie, either way along each axis.
const START_REACH: i32 = 2;
/// How much the search trusts its estimate of the drive still to go (weighted A*): a path at
/// most this much dearer than the lattice's best, found in a fraction of the expansions — the
/// way from a garage to a storage room at the home's far end, some 25 m through three doors,
/// took more than the 25,000 nodes allowed at 1 and a few thousand at 1.5; the path is shortcut
/// afterwards anyway.
const HEURISTIC_WEIGHT: f32 = 1.5;
/// Costs are counted in thousandths (of a metre, or of a radian weighted as a metre).
const MILLI: f32 = 1000.0;

/// A node of the search: the start as it is, a lattice node, or the goal as it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Node {
    Start,
    At { i: i32, j: i32, heading: u8 },
    Goal,
}

/// The search's context: the space, its ends, the grid's anchor, and what it has learnt.
struct Lattice<'s, 'w> {
    space: &'s BaseSpace<'w>,
    start: BaseConfig,
    goal: BaseConfig,
    /// Whether each configuration met is free, by its position and heading to the millimetre
    /// and milliradian: a turn's steps are met again from both sides.
    free: RefCell<HashMap<[i32; 3], bool>>,
    /// Nodes expanded before the search gives up.
    budget: usize,
    /// The drive from each cell to the goal's ([`Lattice::drives_to_goal`]).
    to_goal: HashMap<(i32, i32), u32>,
    expanded: Cell<usize>,
}

impl Lattice<'_, '_> {
    fn config(&self, node: Node) -> BaseConfig {
        match node {
            Node::Start => self.start,
            Node::Goal => self.goal,
            Node::At { i, j, heading } => BaseConfig::new(
                self.start.x + i as f32 * LATTICE_CELL,
                self.start.y + j as f32 * LATTICE_CELL,
                yaw(heading),
            ),
        }
    }

    fn is_free(&self, c: &BaseConfig) -> bool {
        let key = [c.x, c.y, c.yaw].map(|v| (v * MILLI).round() as i32);
        if let Some(&free) = self.free.borrow().get(&key) {
            return free;
        }
        let free = self.space.free(c);
        self.free.borrow_mut().insert(key, free);
        free
    }

    /// The cost of the motion from `a` to `b` if every step of it is free.
    fn motion(&self, a: Node, b: Node) -> Option<(Node, u32)> {
        let (from, to) = (self.config(a), self.config(b));
        let steps = self.space.steps(&from, &to, self.space.resolution());
        steps
            .iter()
            .all(|c| self.is_free(c))
            .then(|| (b, (self.space.distance(&from, &to) * MILLI).round() as u32))
    }

    fn successors(&self, node: Node) -> Vec<(Node, u32)> {
        let n = self.expanded.get() + 1;
        self.expanded.set(n);
        if n > self.budget {
            return Vec::new();
        }
        let mut next = Vec::new();
        match node {
            // A start hemmed in may not turn where it stands, but drive out and turn there.
            Node::Start => {
                let near = -START_REACH..=START_REACH;
                for (i, j) in near.clone().flat_map(|i| near.clone().map(move |j| (i, j))) {
                    next.extend((0..LATTICE_HEADINGS).map(|heading| Node::At { i, j, heading }));
                }
            }
            Node::At { i, j, heading } => {
                let (di, dj) = ahead(heading);
                next.extend([1, -1].map(|way| Node::At {
                    i: i + way * di,
                    j: j + way * dj,
                    heading,
                }));
                for turn in [1, LATTICE_HEADINGS - 1] {
                    next.push(Node::At {
                        i,
                        j,
                        heading: (heading + turn) % LATTICE_HEADINGS,
                    });
                }
                let here = self.config(node);
                if (here.x - self.goal.x).hypot(here.y - self.goal.y) <= GOAL_RADIUS {
                    next.push(Node::Goal);
                }
            }
            Node::Goal => {}
        }
        next.into_iter()
            .filter(|b| self.reachable(*b))
            .filter_map(|b| self.motion(node, b))
            .collect()
    }

    /// The cost still to go from `node`, as the drive to the goal over cells where the base
    /// fits at some heading (what the lattice drives at least: it turns too), weighted by
    /// [`HEURISTIC_WEIGHT`].
    fn heuristic(&self, node: Node) -> u32 {
        match node {
            Node::At { i, j, .. } => {
                let drive = self.to_goal.get(&(i, j)).copied().unwrap_or(0);
                (drive as f32 * HEURISTIC_WEIGHT).round() as u32
            }
            Node::Start | Node::Goal => 0,
        }
    }

    /// Whether `node`'s cell is joined to the goal's by cells where the base fits at some
    /// heading: where not, no lattice path leads from it.
    fn reachable(&self, node: Node) -> bool {
        match node {
            Node::At { i, j, .. } => self.to_goal.contains_key(&(i, j)),
            Node::Start | Node::Goal => true,
        }
    }

    /// Whether the base fits in cell (i, j) at any heading.
    fn fits(&self, i: i32, j: i32) -> bool {
        (0..LATTICE_HEADINGS).any(|heading| self.is_free(&self.config(Node::At { i, j, heading })))
    }

    /// The drive from every cell joined to the goal (by cells where the base fits at some
    /// heading, within the space's bounds; the last within [`GOAL_RADIUS`] of it, as the
    /// lattice's last node is), in thousandths of a metre.
    fn drives_to_goal(&self) -> HashMap<(i32, i32), u32> {
        let (min, max) = self.space.bounds();
        let (lo, hi) = (self.cell_of(min[0], min[1]), self.cell_of(max[0], max[1]));
        let within = |(i, j): (i32, i32)| (lo.0..=hi.0).contains(&i) && (lo.1..=hi.1).contains(&j);
        let milli = |d: f32| (d * MILLI).round() as u32;
        // `None` is the goal itself, whose neighbours are the cells near enough to drive in.
        let neighbours = |from: &Option<(i32, i32)>| -> Vec<(Option<(i32, i32)>, u32)> {
            let near: Vec<((i32, i32), u32)> = match *from {
                None => {
                    let (gi, gj) = self.cell_of(self.goal.x, self.goal.y);
                    let r = (GOAL_RADIUS / LATTICE_CELL).ceil() as i32;
                    (gi - r..=gi + r)
                        .flat_map(|i| (gj - r..=gj + r).map(move |j| (i, j)))
                        .filter_map(|c| {
                            let at = self.config(Node::At {
                                i: c.0,
                                j: c.1,
                                heading: 0,
                            });
                            let d = (at.x - self.goal.x).hypot(at.y - self.goal.y);
                            (d <= GOAL_RADIUS).then_some((c, milli(d)))
                        })
                        .collect()
                }
                Some((i, j)) => (0..LATTICE_HEADINGS)
                    .map(ahead)
                    .map(|(di, dj)| {
                        let d = LATTICE_CELL * (di as f32).hypot(dj as f32);
                        ((i + di, j + dj), milli(d))
                    })
                    .collect(),
            };
            near.into_iter()
                .filter(|&(c, _)| within(c) && self.fits(c.0, c.1))
                .map(|(c, cost)| (Some(c), cost))
                .collect()
        };
        dijkstra_all(&None, neighbours)
            .into_iter()
            .filter_map(|(c, (_, cost))| Some((c?, cost)))
            .collect()
    }

    /// The lattice cell nearest (x, y).
    fn cell_of(&self, x: f32, y: f32) -> (i32, i32) {
        (
            ((x - self.start.x) / LATTICE_CELL).round() as i32,
            ((y - self.start.y) / LATTICE_CELL).round() as i32,
        )
    }
}

/// The heading of index `h`, rad.
fn yaw(h: u8) -> f32 {
    let a = 2.0 * PI * h as f32 / LATTICE_HEADINGS as f32;
    if a > PI { a - 2.0 * PI } else { a }
}

/// The grid step one cell ahead when facing heading `h`.
fn ahead(h: u8) -> (i32, i32) {
    const STEPS: [(i32, i32); 8] = [
        (1, 0),
        (1, 1),
        (0, 1),
        (-1, 1),
        (-1, 0),
        (-1, -1),
        (0, -1),
        (1, -1),
    ];
    STEPS[h as usize % 8]
}

/// A free base path from `start` to `goal` over the lattice, or why none was found; then
/// shortcut-smoothed (`params.smoothing` attempts, seeded by `params.seed`) and checked again at
/// half the resolution, as [`crate::plan`]'s paths are.
pub fn lattice_plan(
    space: &BaseSpace<'_>,
    start: &BaseConfig,
    goal: &BaseConfig,
    params: &PlanParams,
) -> Result<Vec<BaseConfig>, PlanError> {
    if !space.free(start) {
        return Err(PlanError::StartInCollision);
    }
    if !space.free(goal) {
        return Err(PlanError::GoalInCollision);
    }
    let mut lattice = Lattice {
        space,
        start: *start,
        goal: *goal,
        free: RefCell::new(HashMap::new()),
        budget: params.expansions,
        to_goal: HashMap::new(),
        expanded: Cell::new(0),
    };
    lattice.to_goal = lattice.drives_to_goal();
    let (nodes, _) = astar(
        &Node::Start,
        |&n| lattice.successors(n),
        |&n| lattice.heuristic(n),
        |&n| n == Node::Goal,
    )
    .ok_or(PlanError::NoLatticePath {
        cell: LATTICE_CELL,
        expansions: lattice.expanded.get().min(params.expansions),
    })?;
    let path = straightened(nodes.into_iter().map(|n| lattice.config(n)).collect());
    let path = smooth(space, path, params.smoothing, &mut seeded(params.seed));
    if valid(space, &path) {
        Ok(path)
    } else {
        Err(PlanError::NoLatticePath {
            cell: LATTICE_CELL,
            expansions: lattice.expanded.get(),
        })
    }
}

/// The floor the base can drive to from a start: the lattice's cells joined to the cells about
/// the start by cells where the base fits at some heading (as the search's guide is joined to
/// the goal). A place to stand outside them lies in a pocket no lattice path leads into.
pub struct Reachable {
    start: BaseConfig,
    cells: HashSet<(i32, i32)>,
}

impl Reachable {
    /// Whether the base's cell at `c`, or one within the search's goal radius of it (the last
    /// node a lattice path drives into `c` from), is reachable.
    pub fn contains(&self, c: &BaseConfig) -> bool {
        let r = (GOAL_RADIUS / LATTICE_CELL).ceil() as i32;
        let (i, j) = (
            ((c.x - self.start.x) / LATTICE_CELL).round() as i32,
            ((c.y - self.start.y) / LATTICE_CELL).round() as i32,
        );
        (i - r..=i + r).any(|a| {
            (j - r..=j + r).any(|b| {
                let at = (
                    self.start.x + a as f32 * LATTICE_CELL,
                    self.start.y + b as f32 * LATTICE_CELL,
                );
                (at.0 - c.x).hypot(at.1 - c.y) <= GOAL_RADIUS && self.cells.contains(&(a, b))
            })
        })
    }
}

/// The cells of `space`'s lattice anchored at `start` (within its bounds) that the base reaches
/// from the cells about the start, each where it fits at some heading.
pub fn reachable_from(space: &BaseSpace<'_>, start: &BaseConfig) -> Reachable {
    let lattice = Lattice {
        space,
        start: *start,
        goal: *start,
        free: RefCell::new(HashMap::new()),
        budget: 0,
        to_goal: HashMap::new(),
        expanded: Cell::new(0),
    };
    let (min, max) = space.bounds();
    let (lo, hi) = (
        lattice.cell_of(min[0], min[1]),
        lattice.cell_of(max[0], max[1]),
    );
    let within = |(i, j): (i32, i32)| (lo.0..=hi.0).contains(&i) && (lo.1..=hi.1).contains(&j);
    let near = -START_REACH..=START_REACH;
    let mut cells = HashSet::new();
    let mut frontier: Vec<(i32, i32)> = near
        .clone()
        .flat_map(|i| near.clone().map(move |j| (i, j)))
        .filter(|&c| lattice.fits(c.0, c.1))
        .collect();
    cells.extend(frontier.iter().copied());
    while let Some((i, j)) = frontier.pop() {
        for (di, dj) in (0..LATTICE_HEADINGS).map(ahead) {
            let next = (i + di, j + dj);
            if within(next) && !cells.contains(&next) && lattice.fits(next.0, next.1) {
                cells.insert(next);
                frontier.push(next);
            }
        }
    }
    Reachable {
        start: *start,
        cells,
    }
}

/// The path without the configurations that only continue a straight drive or a turn in place:
/// the motion between what is left is the same.
fn straightened(path: Vec<BaseConfig>) -> Vec<BaseConfig> {
    let mut out: Vec<BaseConfig> = Vec::with_capacity(path.len());
    for c in path {
        if out.len() >= 2 {
            let (a, b) = (out[out.len() - 2], out[out.len() - 1]);
            let drives_on = a.yaw == b.yaw && b.yaw == c.yaw && same_line(&a, &b, &c);
            let turns_on = a.x == b.x && b.x == c.x && a.y == b.y && b.y == c.y;
            if drives_on || turns_on {
                out.pop();
            }
        }
        out.push(c);
    }
    out
}

/// Whether `b` lies on the drive from `a` to `c` along their common heading.
fn same_line(a: &BaseConfig, b: &BaseConfig, c: &BaseConfig) -> bool {
    let (fx, fy) = (a.yaw.cos(), a.yaw.sin());
    let across = |p: &BaseConfig| (p.x - a.x) * fy - (p.y - a.y) * fx;
    let along = |p: &BaseConfig| (p.x - a.x) * fx + (p.y - a.y) * fy;
    across(b).abs() < 1e-4 && across(c).abs() < 1e-4 && along(b) > 0.0 && along(c) > along(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_drive_and_a_turn_in_place_keep_only_their_ends() {
        let path = vec![
            BaseConfig::new(0.0, 0.0, 0.0),
            BaseConfig::new(0.1, 0.0, 0.0),
            BaseConfig::new(0.2, 0.0, 0.0),
            BaseConfig::new(0.2, 0.0, PI / 4.0),
            BaseConfig::new(0.2, 0.0, PI / 2.0),
            BaseConfig::new(0.2, 0.1, PI / 2.0),
        ];
        let kept = straightened(path);
        assert_eq!(
            kept,
            vec![
                BaseConfig::new(0.0, 0.0, 0.0),
                BaseConfig::new(0.2, 0.0, 0.0),
                BaseConfig::new(0.2, 0.0, PI / 2.0),
                BaseConfig::new(0.2, 0.1, PI / 2.0),
            ]
        );
    }

    #[test]
    fn each_heading_drives_to_the_neighbour_it_faces() {
        for h in 0..LATTICE_HEADINGS {
            let (di, dj) = ahead(h);
            let a = yaw(h);
            let d = (di as f32).hypot(dj as f32);
            assert!((a.cos() - di as f32 / d).abs() < 1e-6, "heading {h}");
            assert!((a.sin() - dj as f32 / d).abs() < 1e-6, "heading {h}");
        }
    }
}
