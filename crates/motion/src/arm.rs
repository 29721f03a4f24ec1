//! A robot's jointed arm as a joint space for the arm planner of physical primitives, read
//! through the robot's [`Arm`] (Fetch's: the torso lift and the seven arm joints). The links
//! are posed by the arm's own forward kinematics ([`Arm::link_poses`]) on a base that stays
//! where it is, and checked with what the gripper holds against the world's shapes, without
//! stepping.
//!
//! The original plans only the BehaviorRobot's hand for its primitives; for an arm we plan as
//! pybullet-planning plans one: joint space, unit weights, a resolution of 0.05 (rad, or m for
//! a prismatic joint), samples within the joint limits (a continuous joint within half a turn
//! either way of where it starts). The arm's links do not collide with the robot's own base and
//! torso in the robot model (its parts are kinematic bodies, placed by forward kinematics), so
//! the planner does not check that either; what the gripper holds is kept clear of the rest of
//! the robot, which it would hit (the assisted grasp turns off its contacts with the gripper
//! only).

use crate::navigate::inflated;
use crate::rrt::Space;
use behavior_core::rng::{SimRng, uniform};
use behavior_robots::{Arm, ArmConfig, Embodiment};
use behavior_sim::{Primitive, QueryFilter, Solid, World};
use rapier3d::math::{Pose, Vector};
use std::f32::consts::{PI, TAU};
use std::sync::Arc;

/// How far apart the checked configurations of an arm motion are, rad (m for a prismatic
/// joint).
pub(crate) const ARM_RESOLUTION: f32 = 0.05;

/// How much larger what the gripper holds is checked against the world than it is, m: held
/// by a joint of finite stiffness, it lags the arm (a tile planned past a wall grazed it and
/// its grasp broke).
pub(crate) const HELD_MARGIN: f32 = 0.02;

/// `c` with each continuous joint of `arm` turned by whole turns to within half a turn of
/// `from`'s: the same pose of every link, the shorter way there (an IK solution may lie a turn
/// away, outside [`ArmSpace`]'s bounds).
pub fn closest_turn(arm: &dyn Arm, c: &ArmConfig, from: &ArmConfig) -> ArmConfig {
    let limits = arm.limits();
    ArmConfig::from_fn(c.len(), |k| {
        let q = c[k];
        if limits.get(k).is_none_or(Option::is_some) {
            return q;
        }
        let turns = ((q - from[k]) / TAU).round();
        q - turns * TAU
    })
}

/// Shapes built for tests against each other; one that cannot be built (not finite) is left
/// out, as the world's queries refuse it.
fn solids(shapes: &[(Primitive, Pose)]) -> Vec<Solid> {
    shapes
        .iter()
        .filter_map(|(shape, offset)| Solid::new(shape, *offset).ok())
        .collect()
}

/// An arm's moving links and what its gripper holds, as the arm planner moves them.
#[derive(Clone, Debug)]
pub struct ArmBody {
    /// The arm as it stood when the body was made.
    pub arm: Arc<dyn Arm>,
    /// Where the base stands, in the world.
    pub base: Pose,
    /// Each moving link's shapes in its own frame, in [`Arm::moving`] order.
    pub links: Vec<Vec<(Primitive, Pose)>>,
    /// What the gripper holds, in the gripper's frame, grown by `HELD_MARGIN`.
    pub held: Vec<(Primitive, Pose)>,
    /// What the links' and the held object's checks against the world ignore: the robot and
    /// what it holds.
    pub filter: QueryFilter,
    /// The same shapes built for tests against each other: what the gripper holds (gripper
    /// frame), and every link's (its own frame), in [`Arm::links`] order.
    held_solids: Vec<Solid>,
    link_solids: Vec<Vec<Solid>>,
}

impl ArmBody {
    /// `robot`'s `arm` as it stands in `world`, holding what its hand holds.
    pub fn of(world: &World, robot: &dyn Embodiment, arm: Arc<dyn Arm>) -> ArmBody {
        let mut all: Vec<_> = arm
            .links()
            .iter()
            .map(|&id| crate::navigate::shapes_in(world, [id], world.bodies().pose(id).inverse()))
            .collect();
        // The robot keeps the fingers' whole travel out of fixed bodies, open or closed.
        if let Some(gripper) = all.get_mut(arm.gripper()) {
            gripper.push(arm.finger_sweep());
        }
        let links = all.get(arm.moving()).unwrap_or_default().to_vec();
        let holding = robot.held(arm.hand());
        let gripper = arm
            .links()
            .get(arm.gripper())
            .map(|&id| world.bodies().pose(id));
        let gripper = gripper.unwrap_or(Pose::IDENTITY).inverse();
        let held = crate::navigate::shapes_in(world, holding, gripper);
        let mut ignored = robot.objects();
        ignored.extend(holding);
        let held_solids = solids(&held);
        let held = held
            .into_iter()
            .map(|(shape, offset)| (inflated(&shape, HELD_MARGIN), offset))
            .collect();
        ArmBody {
            base: robot.base_pose(world),
            arm,
            links,
            held_solids,
            held,
            filter: QueryFilter::excluding(&ignored),
            link_solids: all.iter().map(|shapes| solids(shapes)).collect(),
        }
    }

    /// Whether the moving links and what the gripper holds touch nothing at `c`, and what it
    /// holds touches no part of the robot but the gripper.
    pub fn clear(&self, world: &World, c: &ArmConfig) -> bool {
        if !c.is_finite() {
            return false;
        }
        let poses = self.arm.link_poses(c);
        let free = |shape: &Primitive, pose: Pose| {
            world
                .query()
                .overlaps(shape, pose, &self.filter)
                .is_ok_and(|hits| hits.is_empty())
        };
        let links = self.links.iter().zip(self.arm.moving()).all(|(shapes, k)| {
            let at = self.base * poses[k];
            shapes.iter().all(|(s, offset)| free(s, at * *offset))
        });
        let gripper = self.base * poses[self.arm.gripper()];
        links
            && self
                .held
                .iter()
                .all(|(s, offset)| free(s, gripper * *offset))
            && !self.held_touches_robot(&poses)
    }

    /// The centre of what the gripper holds in the gripper's frame (of its box), if it holds
    /// anything.
    pub fn held_centre(&self) -> Option<Vector> {
        self.held_box(Pose::IDENTITY)
            .map(|(lo, hi)| (lo + hi) / 2.0)
    }

    /// The arm's planning resolution, rad (m for a prismatic joint): `ARM_RESOLUTION`, finer
    /// for what reaches farther than `HELD_REACH` from the gripper, so that its far end moves no
    /// more per step than that of something within it. At 0.05 rad a step, the far end of a
    /// sheet of plywood held by its edge moves about 5 cm between checked configurations: the
    /// sheet met the torso while the arm moved and its grasp broke. The arm also moves it
    /// slower, one step per configuration.
    pub fn resolution(&self) -> f32 {
        let reach = self.held_box(Pose::IDENTITY).map_or(0.0, |(lo, hi)| {
            let far = lo.abs().max(hi.abs());
            far.length()
        });
        ARM_RESOLUTION * (HELD_REACH / reach.max(HELD_REACH))
    }

    /// The box of what the gripper holds with the gripper at `gripper`: its lowest and highest
    /// corners, if it holds anything.
    pub fn held_box(&self, gripper: Pose) -> Option<(Vector, Vector)> {
        let boxes = self.held_solids.iter().map(|s| s.aabb(gripper));
        boxes.reduce(|(a, b), (c, d)| (a.min(c), b.max(d)))
    }

    /// How big the base's footprint is as it drives with the arm at `c`, m: how far the arm and
    /// what it holds reach to either side of the base's heading, plus `REACH_WEIGHT` of how
    /// far they reach out from its vertical axis. The width decides which doors it passes; the
    /// reach, where it can turn. (By reach alone, a sheet of plywood carried flat, 0.94 m
    /// across, ranked before the same sheet carried upright along the way, and passed no door.)
    pub fn spread(&self, c: &ArmConfig) -> f32 {
        let poses = self.arm.link_poses(c);
        let gripper = poses[self.arm.gripper()];
        let moving = self.arm.moving();
        let links = self.link_solids[moving.clone()]
            .iter()
            .zip(&poses[moving])
            .flat_map(|(solids, &at)| solids.iter().map(move |s| (s, at)));
        let held = self.held_solids.iter().map(|s| (s, gripper));
        let (width, reach) = links
            .chain(held)
            .map(|(solid, at)| {
                let (lo, hi) = solid.aabb(at);
                let x = lo.x.abs().max(hi.x.abs());
                let y = lo.y.abs().max(hi.y.abs());
                (y, x.hypot(y))
            })
            .fold((0.0f32, 0.0f32), |(w, r), (y, d)| (w.max(y), r.max(d)));
        width + REACH_WEIGHT * reach
    }

    /// Whether what the gripper holds touches a link other than the gripper, the links posed
    /// at `poses` (base frame). The assisted grasp turns off what it holds' contacts with the
    /// gripper only: against the rest of the robot it collides (a tile swung against the
    /// forearm as the arm came back broke its grasp).
    fn held_touches_robot(&self, poses: &[Pose]) -> bool {
        let g = self.arm.gripper();
        let gripper = poses[g];
        self.held_solids.iter().any(|h| {
            self.link_solids
                .iter()
                .zip(poses)
                .enumerate()
                .filter(|&(k, _)| k != g)
                .any(|(_, (link, &at))| link.iter().any(|s| h.intersects(gripper, s, at)))
        })
    }

    /// The end effector's pose in the world at `c`.
    pub fn eef(&self, c: &ArmConfig) -> Pose {
        self.base * self.arm.eef(c)
    }
}

/// The range of joint `k`: its limits, or for a continuous joint a turn either way from where
/// it is at `start`.
fn bounds(arm: &dyn Arm, start: &ArmConfig, k: usize) -> [f32; 2] {
    match arm.limits().get(k).copied().flatten() {
        Some(limits) => limits,
        None => [start[k] - PI, start[k] + PI],
    }
}

/// A configuration of `arm` drawn uniformly within the joints' ranges (their limits, or for a
/// continuous joint a turn either way from where it is at `start`): where an IK search may
/// start over.
pub fn any_config(arm: &dyn Arm, start: &ArmConfig, rng: &mut SimRng) -> ArmConfig {
    ArmConfig::from_fn(start.len(), |k| {
        let [lo, hi] = bounds(arm, start, k);
        uniform(rng, lo, hi)
    })
}

/// How far what the gripper holds may reach from it before the arm plans and moves in finer
/// steps ([`ArmBody::resolution`]), m.
pub(crate) const HELD_REACH: f32 = 0.3;

/// How much the reach from the base's axis counts beside the width across its heading in
/// [`ArmBody::spread`].
pub(crate) const REACH_WEIGHT: f32 = 0.2;

/// An arm moving among the world's objects, its base still.
pub struct ArmSpace<'w> {
    world: &'w World,
    body: ArmBody,
    min: ArmConfig,
    max: ArmConfig,
}

impl<'w> ArmSpace<'w> {
    /// The space of the arm from `start`: joint limits, and half a turn either way of the
    /// start for a continuous joint.
    pub fn new(world: &'w World, body: ArmBody, start: &ArmConfig) -> ArmSpace<'w> {
        let arm = body.arm.as_ref();
        let min = ArmConfig::from_fn(start.len(), |k| bounds(arm, start, k)[0]);
        let max = ArmConfig::from_fn(start.len(), |k| bounds(arm, start, k)[1]);
        ArmSpace {
            world,
            body,
            min,
            max,
        }
    }

    /// The arm's body.
    pub fn body(&self) -> &ArmBody {
        &self.body
    }

    /// Whether `c` lies within the joints' limits.
    fn within(&self, c: &ArmConfig) -> bool {
        c.len() == self.min.len()
            && (0..c.len()).all(|k| (self.min[k]..=self.max[k]).contains(&c[k]))
    }
}

impl Space for ArmSpace<'_> {
    type Config = ArmConfig;

    fn distance(&self, a: &ArmConfig, b: &ArmConfig) -> f32 {
        a.values()
            .iter()
            .zip(b.values())
            .map(|(x, y)| (x - y) * (x - y))
            .sum::<f32>()
            .sqrt()
    }

    fn sample(&self, rng: &mut SimRng) -> ArmConfig {
        ArmConfig::from_fn(self.min.len(), |k| uniform(rng, self.min[k], self.max[k]))
    }

    fn steps(&self, a: &ArmConfig, b: &ArmConfig, resolution: f32) -> Vec<ArmConfig> {
        let longest = a
            .values()
            .iter()
            .zip(b.values())
            .fold(0.0f32, |m, (x, y)| m.max((y - x).abs()));
        let n = (longest / resolution).ceil() as usize;
        let mut out: Vec<ArmConfig> = (1..n)
            .map(|i| {
                let t = i as f32 / n as f32;
                ArmConfig::from_fn(a.len(), |k| a[k] + (b[k] - a[k]) * t)
            })
            .collect();
        if a != b {
            out.push(*b);
        }
        out
    }

    fn free(&self, c: &ArmConfig) -> bool {
        self.within(c) && self.body.clear(self.world, c)
    }

    fn resolution(&self) -> f32 {
        self.body.resolution()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{BodyKind, ObjectSpec, Part};

    use behavior_robots::Fetch;

    fn fetch_in(world: &mut World) -> Fetch {
        Fetch::add(world, Pose::IDENTITY).unwrap()
    }

    fn body_of(world: &World, robot: &dyn Embodiment) -> ArmBody {
        ArmBody::of(world, robot, robot.arm(0).unwrap())
    }

    #[test]
    fn the_start_pose_is_free_and_a_wall_through_the_gripper_is_not() {
        let mut world = World::default();
        let fetch = fetch_in(&mut world);
        let body = body_of(&world, &fetch);
        let start = body.arm.now();
        assert!(body.clear(&world, &start));
        let at = body.eef(&start).translation;
        let wall = ObjectSpec::new(
            "wall",
            "wall.n.01",
            vec![Part::at(
                Primitive::Box {
                    half_extents: Vector::new(0.02, 1.0, 1.0),
                },
                Vector::ZERO,
            )],
        )
        .body(BodyKind::Fixed);
        let mut spec = wall;
        spec.pose = Pose::from_translation(at);
        world.add(spec).unwrap();
        let body = body_of(&world, &fetch);
        assert!(!body.clear(&world, &start));
    }

    #[test]
    fn what_the_gripper_holds_may_not_pass_through_the_rest_of_the_robot() {
        use behavior_robots::{ActionSpace, Robot, RobotKind};
        let mut world = World::default();
        let space = ActionSpace::Joints;
        let mut robot = Robot::add(RobotKind::Fetch, space, &mut world, Pose::IDENTITY).unwrap();
        let board = ObjectSpec::new(
            "board",
            "plywood.n.01",
            vec![Part::new(Primitive::Box {
                half_extents: Vector::new(0.2, 0.04, 0.01),
            })],
        )
        .at(Vector::new(3.0, 0.0, 0.5));
        let board = world.add(board).unwrap();
        let empty = body_of(&world, &*robot);
        robot.grasp_now(&mut world, 0, board).unwrap();
        let holding = body_of(&world, &*robot);
        let start = holding.arm.now();
        assert!(
            holding.clear(&world, &start),
            "held out ahead, it touches nothing"
        );
        // Folded over the base, a board 0.4 m long crosses the torso or the base.
        let mut folded = start;
        folded.values_mut()[1..].copy_from_slice(&[1.32, 1.4, -0.2, 1.72, 0.0, 1.66, 0.0]);
        assert!(empty.clear(&world, &folded), "the folded arm alone is free");
        assert!(!holding.clear(&world, &folded));
        // Its centre, in the gripper's frame, is where it hangs: within its half length.
        let centre = holding.held_centre().unwrap();
        assert!(centre.length() < 0.6, "{centre:?}");
        assert!(empty.held_centre().is_none());
        assert!(holding.spread(&start) > empty.spread(&start));
    }

    #[test]
    fn steps_are_no_longer_than_the_resolution_and_end_at_the_goal() {
        let world = World::default();
        let mut w = world.clone();
        let fetch = fetch_in(&mut w);
        let body = body_of(&w, &fetch);
        let a = body.arm.now();
        let mut b = a;
        b[1] += 0.33;
        b[0] += 0.01;
        let space = ArmSpace::new(&world, body, &a);
        let steps = space.steps(&a, &b, ARM_RESOLUTION);
        assert_eq!(steps.len(), 7);
        assert_eq!(*steps.last().unwrap(), b);
        let mut previous = a;
        for s in &steps {
            assert!(space.distance(&previous, s) <= ARM_RESOLUTION * 1.01);
            previous = *s;
        }
    }
}
