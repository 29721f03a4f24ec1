//! The robot's base in (x, y, yaw) on the floor: its footprint, how it moves between two
//! configurations (the original's: turn toward the next point, drive straight to it, turn to its
//! heading; here also backing onto a point behind, the smaller turn), and collision checks
//! through the world's overlap queries, without stepping.

use crate::rrt::Space;
use behavior_core::rng::{SimRng, uniform};
use behavior_sim::{Primitive, QueryFilter, World};
use rapier3d::math::{Pose, Rotation, Vector};
use serde::{Deserialize, Serialize};
use std::f32::consts::{FRAC_PI_2, PI};

/// Where the base stands: position on the floor, m, and heading, rad.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BaseConfig {
    /// Position along the world's x, m.
    pub x: f32,
    /// Position along the world's y, m.
    pub y: f32,
    /// Heading about z from +x, rad.
    pub yaw: f32,
}

impl BaseConfig {
    /// A configuration from its three numbers.
    pub fn new(x: f32, y: f32, yaw: f32) -> BaseConfig {
        BaseConfig { x, y, yaw }
    }

    /// The base's frame: on the floor at (x, y), turned by yaw about z.
    pub fn pose(&self) -> Pose {
        Pose::from_parts(
            Vector::new(self.x, self.y, 0.0),
            Rotation::from_rotation_z(self.yaw),
        )
    }

    fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.yaw.is_finite()
    }
}

/// The shapes that move with the base, each placed in the base's frame (on the floor under its
/// origin): the BehaviorRobot's body capsule 0.7 m up, say, and the hands where they are.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Footprint {
    /// Each shape with its pose in the base's frame.
    pub shapes: Vec<(Primitive, Pose)>,
}

/// How far a heading may turn per step, relative to the resolution in metres: 1 rad counts as
/// 1 m, so a 0.05 resolution turns 0.05 rad (about 3°) per step.
const TURN_WEIGHT: f32 = 1.0;

/// Room around the start and goal that samples may use, m (the original's ±1 m box).
const MARGIN: f32 = 1.0;

/// The base of a robot in a world, planned between two configurations.
pub struct BaseSpace<'w> {
    world: &'w World,
    footprint: Footprint,
    /// What collisions ignore: the robot itself and what it holds.
    filter: QueryFilter,
    /// Samples fall in `[min, max]` on x and y.
    min: [f32; 2],
    max: [f32; 2],
    resolution: f32,
}

/// The signed turn from `from` to `to`, in (−π, π].
fn turn(from: f32, to: f32) -> f32 {
    let d = (to - from).rem_euclid(2.0 * PI);
    if d > PI { d - 2.0 * PI } else { d }
}

impl<'w> BaseSpace<'w> {
    /// The space between `start` and `goal` (samples within their box widened by 1 m), checked
    /// at 0.05 (m or rad, the original's resolution).
    pub fn new(
        world: &'w World,
        footprint: Footprint,
        filter: QueryFilter,
        start: &BaseConfig,
        goal: &BaseConfig,
    ) -> BaseSpace<'w> {
        BaseSpace {
            world,
            footprint,
            filter,
            min: [start.x.min(goal.x) - MARGIN, start.y.min(goal.y) - MARGIN],
            max: [start.x.max(goal.x) + MARGIN, start.y.max(goal.y) + MARGIN],
            resolution: 0.05,
        }
    }

    /// Samples within `[min, max]` on x and y instead (the whole home, say: the July 2021
    /// version sampled the traversable map, so that a path may leave the box around its ends).
    pub fn with_bounds(self, min: [f32; 2], max: [f32; 2]) -> BaseSpace<'w> {
        BaseSpace { min, max, ..self }
    }

    /// The box on the floor (x, y) that samples fall in.
    pub(crate) fn bounds(&self) -> ([f32; 2], [f32; 2]) {
        (self.min, self.max)
    }

    /// The heading the base keeps driving from `a` to `b` (`a`'s own if they stand at one
    /// point): facing the drive, or backing along it where that is the smaller turn. Both
    /// robots' wheels drive either way, and the drive's executor backs onto a point behind
    /// (`physical::drive_toward`); a base facing a table close up gets away only backwards.
    fn heading(a: &BaseConfig, b: &BaseConfig) -> f32 {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        if dx.hypot(dy) < 1e-6 {
            return a.yaw;
        }
        let ahead = dy.atan2(dx);
        let way = if turn(a.yaw, ahead).abs() > FRAC_PI_2 {
            ahead + PI
        } else {
            ahead
        };
        a.yaw + turn(a.yaw, way)
    }
}

/// The box of the home's rooms on the floor (x, y), if it has rooms: where a base planner may
/// sample to go round what blocks the box around start and goal.
pub fn home_extent(world: &World) -> Option<([f32; 2], [f32; 2])> {
    let rooms = world.rooms();
    let first = rooms.first()?.bounds();
    let (mut min, mut max) = (first.min, first.max);
    for r in rooms.iter().map(|r| r.bounds()) {
        min = [min[0].min(r.min[0]), min[1].min(r.min[1])];
        max = [max[0].max(r.max[0]), max[1].max(r.max[1])];
    }
    Some((min, max))
}

/// How high above the floor the check for standing inside something starts, m: under the
/// BehaviorRobot's body (its capsule ends 0.2 m up), over what lies flat on the floor.
pub(crate) const KEEL: f32 = 0.15;

/// Whether a base at (x, y) stands within something whose walls its parts clear (an open
/// container, a bathtub): straight down from `KEEL`, the first thing met reaches above it.
/// The BehaviorRobot's body floats 0.2 m up, over what is lower than that.
pub fn stands_inside(world: &World, filter: &QueryFilter, x: f32, y: f32) -> bool {
    let from = Vector::new(x, y, KEEL);
    match world.query().cast_ray(from, -Vector::Z, KEEL, filter) {
        Ok(Some(hit)) => hit
            .body
            .is_some_and(|b| world.bodies().aabb(b.object).maxs.z > KEEL),
        _ => false,
    }
}

/// How many even steps of at most `resolution` cover `length`.
fn even_steps(length: f32, resolution: f32) -> usize {
    (length / resolution).ceil().max(0.0) as usize
}

impl Space for BaseSpace<'_> {
    type Config = BaseConfig;

    fn distance(&self, a: &BaseConfig, b: &BaseConfig) -> f32 {
        let heading = BaseSpace::heading(a, b);
        let drive = (b.x - a.x).hypot(b.y - a.y);
        drive + TURN_WEIGHT * (turn(a.yaw, heading).abs() + turn(heading, b.yaw).abs())
    }

    fn sample(&self, rng: &mut SimRng) -> BaseConfig {
        BaseConfig {
            x: uniform(rng, self.min[0], self.max[0]),
            y: uniform(rng, self.min[1], self.max[1]),
            yaw: uniform(rng, -PI, PI),
        }
    }

    fn steps(&self, a: &BaseConfig, b: &BaseConfig, resolution: f32) -> Vec<BaseConfig> {
        let heading = BaseSpace::heading(a, b);
        let mut out = Vec::new();
        let first = turn(a.yaw, heading);
        let n = even_steps(TURN_WEIGHT * first.abs(), resolution);
        out.extend((1..=n).map(|k| BaseConfig {
            yaw: a.yaw + first * k as f32 / n as f32,
            ..*a
        }));
        let drive = (b.x - a.x).hypot(b.y - a.y);
        let n = even_steps(drive, resolution);
        out.extend((1..=n).map(|k| {
            let t = k as f32 / n as f32;
            BaseConfig::new(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, heading)
        }));
        let last = turn(heading, b.yaw);
        let n = even_steps(TURN_WEIGHT * last.abs(), resolution);
        out.extend((1..=n).map(|k| BaseConfig {
            x: b.x,
            y: b.y,
            yaw: heading + last * k as f32 / n as f32,
        }));
        // End exactly at `b` (its yaw unwrapped as given), whatever the rounding.
        match out.last_mut() {
            Some(end) => *end = *b,
            None if a != b => out.push(*b),
            None => {}
        }
        out
    }

    fn free(&self, c: &BaseConfig) -> bool {
        if !c.is_finite() {
            return false;
        }
        let base = c.pose();
        let query = self.world.query();
        let clear = self.footprint.shapes.iter().all(|(shape, offset)| {
            query
                .overlaps(shape, base * *offset, &self.filter)
                .is_ok_and(|hits| hits.is_empty())
        });
        clear && !stands_inside(self.world, &self.filter, c.x, c.y)
    }

    fn resolution(&self) -> f32 {
        self.resolution
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_turn_takes_the_short_way_round() {
        assert!((turn(3.0, -3.0) - (2.0 * PI - 6.0)).abs() < 1e-5);
        assert!((turn(-3.0, 3.0) + (2.0 * PI - 6.0)).abs() < 1e-5);
        assert_eq!(turn(0.5, 0.5), 0.0);
    }

    #[test]
    fn a_move_turns_drives_and_turns_in_steps_no_longer_than_the_resolution() {
        let world = World::default();
        let (a, b) = (
            BaseConfig::new(0.0, 0.0, 0.0),
            BaseConfig::new(0.0, 1.0, PI),
        );
        let space = BaseSpace::new(&world, Footprint::default(), QueryFilter::default(), &a, &b);
        let steps = space.steps(&a, &b, 0.05);
        assert_eq!(*steps.last().unwrap(), b);
        let mut previous = a;
        for s in &steps {
            let moved =
                (s.x - previous.x).hypot(s.y - previous.y) + turn(previous.yaw, s.yaw).abs();
            assert!(moved <= 0.05 + 1e-5, "{previous:?} → {s:?}");
            previous = *s;
        }
        // A quarter turn to face +y, one metre, a quarter turn: about 31 + 20 + 31 steps.
        assert!((80..=85).contains(&steps.len()), "{} steps", steps.len());
    }

    #[test]
    fn a_point_behind_is_backed_onto_with_the_smaller_turn() {
        let world = World::default();
        let a = BaseConfig::new(0.0, 0.0, 0.0);
        let behind = BaseConfig::new(-1.0, 0.0, 0.0);
        let space = BaseSpace::new(&world, Footprint::default(), QueryFilter::default(), &a, &a);
        let steps = space.steps(&a, &behind, 0.05);
        assert_eq!(steps.len(), 20);
        assert!(steps.iter().all(|s| s.yaw == 0.0));
        assert!((space.distance(&a, &behind) - 1.0).abs() < 1e-6);
        // Back and to the right: an eighth of a turn, backing, not three eighths ahead.
        let aside = BaseConfig::new(-1.0, -1.0, FRAC_PI_2 / 2.0);
        let steps = space.steps(&a, &aside, 0.05);
        assert!(
            steps
                .iter()
                .all(|s| (0.0..=FRAC_PI_2 / 2.0 + 1e-6).contains(&s.yaw))
        );
    }
}
