//! The BehaviorRobot's hand as a free-flying 6-D body — position and roll, pitch, yaw in the
//! world — for the hand planner of the original's motion-planning primitives (iGibson 2.0.3's
//! `envs/behavior_mp_env.py`: bounds the box of the hand and the goal ±0.5 m, weights (1, 1, 1, 5,
//! 5, 5), resolution
//! 0.02). What the hand holds moves with it and is checked with it; the hand must stay within
//! its reach of the shoulder (a target beyond it would be pulled back and leave the plan).

use crate::rrt::Space;
use behavior_core::rng::{SimRng, uniform};
use behavior_core::wrap_angle;
use behavior_sim::{Primitive, QueryFilter, World};
use rapier3d::glamx::EulerRot;
use rapier3d::math::{Pose, Rotation, Vector};

/// A hand's pose: position, m, and roll, pitch, yaw, rad (pitch about y after roll about x,
/// then yaw about z, fixed axes: the action's convention).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandConfig {
    /// The palm's position in the world, m.
    pub position: Vector,
    /// Roll, pitch and yaw.
    pub angles: [f32; 3],
}

impl HandConfig {
    /// The configuration of a palm pose.
    pub fn of(pose: &Pose) -> HandConfig {
        let (yaw, pitch, roll) = pose.rotation.to_euler(EulerRot::ZYX);
        HandConfig {
            position: pose.translation,
            angles: [roll, pitch, yaw],
        }
    }

    /// The palm pose it stands for.
    pub fn pose(&self) -> Pose {
        let [roll, pitch, yaw] = self.angles;
        Pose::from_parts(
            self.position,
            Rotation::from_euler(EulerRot::ZYX, yaw, pitch, roll),
        )
    }

    /// The six coordinates, position first.
    fn coordinates(&self) -> [f32; 6] {
        let [x, y, z] = self.position.to_array();
        let [r, p, w] = self.angles;
        [x, y, z, r, p, w]
    }

    /// From `self` toward `to`, each angle the short way round.
    fn difference(&self, to: &HandConfig) -> [f32; 6] {
        let (a, b) = (self.coordinates(), to.coordinates());
        std::array::from_fn(|k| {
            let d = b[k] - a[k];
            if k < 3 { d } else { wrap_angle(d) }
        })
    }
}

/// The weights of the six coordinates in the planner's distance (the original's).
pub(crate) const HAND_WEIGHTS: [f32; 6] = [1.0, 1.0, 1.0, 5.0, 5.0, 5.0];
/// How far apart the checked poses of a hand motion are, m or rad per coordinate.
pub const HAND_RESOLUTION: f32 = 0.02;
/// Room around the hand and its goal that samples may use, m.
pub(crate) const HAND_MARGIN: f32 = 0.5;
/// Room around the ends' angles that samples may use, rad. (The original samples any
/// orientation; a hand that turns over on the way to a table is no better a plan.)
pub(crate) const ANGLE_MARGIN: f32 = 0.5;

/// A hand, and what it holds, moving among the world's objects.
pub struct HandSpace<'w> {
    world: &'w World,
    body: HandBody,
    min: [f32; 6],
    max: [f32; 6],
}

/// Where a hand moves: the shapes carried, what they ignore, its shoulder and reach.
#[derive(Clone, Debug)]
pub struct HandBody {
    /// The shapes that move with the hand, in its frame: palm, fingers, what it holds.
    pub shapes: Vec<(Primitive, Pose)>,
    /// What collisions ignore: the robot and what it holds.
    pub filter: QueryFilter,
    /// The shoulder in the world.
    pub shoulder: Vector,
    /// How far from the shoulder the hand may be, m.
    pub reach: f32,
}

impl HandBody {
    /// Whether the hand and what it holds touch nothing in `world` at `c`, wherever the
    /// shoulder is.
    pub fn clear(&self, world: &World, c: &HandConfig) -> bool {
        let finite = c.position.is_finite() && c.angles.iter().all(|x| x.is_finite());
        if !finite {
            return false;
        }
        let pose = c.pose();
        self.shapes.iter().all(|(shape, offset)| {
            world
                .query()
                .overlaps(shape, pose * *offset, &self.filter)
                .is_ok_and(|hits| hits.is_empty())
        })
    }

    /// Whether `c` lies within the hand's reach of the shoulder.
    pub fn reaches(&self, c: &HandConfig) -> bool {
        (c.position - self.shoulder).length() <= self.reach
    }
}

impl<'w> HandSpace<'w> {
    /// The space between `start` and `goal`.
    pub fn new(
        world: &'w World,
        body: HandBody,
        start: &HandConfig,
        goal: &HandConfig,
    ) -> HandSpace<'w> {
        let (a, b) = (start.coordinates(), goal.coordinates());
        // Angles from the start's, so that the goal's lie the short way round.
        let d = start.difference(goal);
        let mut min = [0.0; 6];
        let mut max = [0.0; 6];
        for k in 0..6 {
            let (lo, hi) = if k < 3 {
                (a[k].min(b[k]), a[k].max(b[k]))
            } else {
                (a[k].min(a[k] + d[k]), a[k].max(a[k] + d[k]))
            };
            let margin = if k < 3 { HAND_MARGIN } else { ANGLE_MARGIN };
            min[k] = lo - margin;
            max[k] = hi + margin;
        }
        HandSpace {
            world,
            body,
            min,
            max,
        }
    }

    /// Whether the hand and what it holds touch nothing at `c`, wherever the shoulder is.
    pub fn clear(&self, c: &HandConfig) -> bool {
        self.body.clear(self.world, c)
    }
}

impl Space for HandSpace<'_> {
    type Config = HandConfig;

    fn distance(&self, a: &HandConfig, b: &HandConfig) -> f32 {
        let d = a.difference(b);
        d.iter()
            .zip(HAND_WEIGHTS)
            .map(|(x, w)| w * x * x)
            .sum::<f32>()
            .sqrt()
    }

    fn sample(&self, rng: &mut SimRng) -> HandConfig {
        let c: [f32; 6] = std::array::from_fn(|k| uniform(rng, self.min[k], self.max[k]));
        HandConfig {
            position: Vector::new(c[0], c[1], c[2]),
            angles: [c[3], c[4], c[5]],
        }
    }

    fn steps(&self, a: &HandConfig, b: &HandConfig, resolution: f32) -> Vec<HandConfig> {
        let d = a.difference(b);
        let longest = d.iter().fold(0.0f32, |m, x| m.max(x.abs()));
        let n = (longest / resolution).ceil() as usize;
        let mut out: Vec<HandConfig> = (1..n)
            .map(|k| {
                let t = k as f32 / n as f32;
                HandConfig {
                    position: a.position + Vector::new(d[0], d[1], d[2]) * t,
                    angles: std::array::from_fn(|i| a.angles[i] + d[3 + i] * t),
                }
            })
            .collect();
        if a != b {
            out.push(*b);
        }
        out
    }

    fn free(&self, c: &HandConfig) -> bool {
        self.body.reaches(c) && self.clear(c)
    }

    fn resolution(&self) -> f32 {
        HAND_RESOLUTION
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pose_survives_the_round_trip_through_its_angles() {
        let pose = Pose::from_parts(
            Vector::new(0.3, -0.2, 1.1),
            Rotation::from_euler(EulerRot::ZYX, 2.9, -0.4, 0.3),
        );
        let back = HandConfig::of(&pose).pose();
        assert!((back.translation - pose.translation).length() < 1e-6);
        assert!(back.rotation.angle_between(pose.rotation) < 1e-4);
    }

    #[test]
    fn steps_turn_the_short_way_and_are_no_longer_than_the_resolution() {
        let world = World::default();
        let a = HandConfig {
            position: Vector::ZERO,
            angles: [0.0, 0.0, 3.0],
        };
        let b = HandConfig {
            position: Vector::new(0.1, 0.0, 0.0),
            angles: [0.0, 0.0, -3.0],
        };
        let body = HandBody {
            shapes: Vec::new(),
            filter: QueryFilter::default(),
            shoulder: Vector::ZERO,
            reach: 1.0,
        };
        let space = HandSpace::new(&world, body, &a, &b);
        let steps = space.steps(&a, &b, HAND_RESOLUTION);
        // 2π − 6 ≈ 0.283 rad the short way: 15 steps of at most 0.02.
        assert_eq!(steps.len(), 15);
        assert_eq!(*steps.last().unwrap(), b);
        let mut previous = a;
        for s in &steps {
            let d = previous.difference(s);
            assert!(d.iter().all(|x| x.abs() <= HAND_RESOLUTION + 1e-5), "{d:?}");
            previous = *s;
        }
    }
}
