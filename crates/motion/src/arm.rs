//! Fetch's torso and arm as an 8-D joint space — the torso lift and the seven arm joints —
//! for the arm planner of Fetch's physical primitives. The links are posed by Fetch's own
//! forward kinematics ([`FetchJoints::link_poses`]) on a base that stays where it is, and
//! checked with what the gripper holds against the world's shapes, without stepping.
//!
//! The original plans only the BehaviorRobot's hand for its primitives; for Fetch we plan as
//! pybullet-planning plans an arm: joint space, unit weights, a resolution of 0.05 (rad, or m for
//! the torso), samples within the joint limits (a continuous joint within half a turn either
//! way of where it starts). The arm's links do not collide with the robot's own base and torso
//! in the robot model (its parts are kinematic bodies, placed by forward kinematics), so the
//! planner does not check that either; what the gripper holds is kept clear of the rest of the
//! robot, which it would hit (the assisted grasp turns off its contacts with the gripper only).

use crate::navigate::inflated;
use crate::rrt::Space;
use behavior_core::rng::{SimRng, uniform};
use behavior_robots::{Fetch, FetchJoint, FetchJoints, FetchLink};
use behavior_sim::{Primitive, QueryFilter, Solid, World};
use rapier3d::math::{Pose, Vector};
use std::f32::consts::{PI, TAU};

/// How far apart the checked configurations of an arm motion are, rad (m for the torso).
pub const ARM_RESOLUTION: f32 = 0.05;

/// How much larger what the gripper holds is checked against the world than it is, m: held
/// by a joint of finite stiffness, it lags the arm (a tile planned past a wall grazed it and
/// its grasp broke).
pub const HELD_MARGIN: f32 = 0.02;

/// Fetch's torso lift, m, and its seven arm joints, rad, shoulder pan first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmConfig(pub [f32; 8]);

impl ArmConfig {
    /// The torso and arm positions of `joints`.
    pub fn of(joints: &FetchJoints) -> ArmConfig {
        ArmConfig(std::array::from_fn(|k| {
            if k == 0 {
                joints.torso
            } else {
                joints.arm[k - 1]
            }
        }))
    }

    /// The same configuration with each continuous joint turned by whole turns to within half
    /// a turn of `from`'s: the same pose of every link, the shorter way there (an IK solution
    /// may lie a turn away, outside [`ArmSpace`]'s bounds).
    pub fn near(&self, from: &ArmConfig) -> ArmConfig {
        ArmConfig(std::array::from_fn(|k| {
            let q = self.0[k];
            if joint(k).info().limits.is_some() {
                return q;
            }
            let turns = ((q - from.0[k]) / TAU).round();
            q - turns * TAU
        }))
    }

    /// All of Fetch's kinematic joints: these, with the head at `head`.
    pub fn joints(&self, head: [f32; 2]) -> FetchJoints {
        FetchJoints {
            torso: self.0[0],
            head,
            arm: std::array::from_fn(|k| self.0[k + 1]),
        }
    }
}

/// The joint of [`ArmConfig`]'s coordinate `k`.
fn joint(k: usize) -> FetchJoint {
    match k {
        0 => FetchJoint::TorsoLift,
        _ => FetchJoint::ARM[k - 1],
    }
}

/// The links the torso and arm move ([`FetchLink::ALL`] from the torso on: the head rides on
/// the torso).
const MOVING: std::ops::Range<usize> = 1..behavior_robots::FETCH_LINKS;

/// The box the finger pads sweep over their travel, in the gripper's frame (Fetch's own
/// blocking box: pads 6 × 1.4 × 2.6 cm, each travelling 5 cm out).
fn finger_sweep() -> (Primitive, Pose) {
    let half_extents = Vector::new(0.03, 0.0643, 0.01315);
    (
        Primitive::Box { half_extents },
        Pose::from_translation(Vector::new(0.001, 0.0, 0.0)),
    )
}

/// Shapes built for tests against each other; one that cannot be built (not finite) is left
/// out, as the world's queries refuse it.
fn solids(shapes: &[(Primitive, Pose)]) -> Vec<Solid> {
    shapes
        .iter()
        .filter_map(|(shape, offset)| Solid::new(shape, *offset).ok())
        .collect()
}

/// Fetch's moving links and what the gripper holds, as the arm planner moves them.
#[derive(Clone, Debug)]
pub struct ArmBody {
    /// Where the base stands, in the world.
    pub base: Pose,
    /// The head's pan and tilt, which the arm's motion keeps.
    pub head: [f32; 2],
    /// Each moving link's shapes in its own frame, in [`FetchLink::ALL`] order from the torso.
    pub links: Vec<Vec<(Primitive, Pose)>>,
    /// What the gripper holds, in the gripper's frame, grown by `HELD_MARGIN`.
    pub held: Vec<(Primitive, Pose)>,
    /// What the links' and the held object's checks against the world ignore: the robot and
    /// what it holds.
    pub filter: QueryFilter,
    /// The same shapes built for tests against each other: what the gripper holds (gripper
    /// frame), and every link's (its own frame), in [`FetchLink::ALL`] order.
    held_solids: Vec<Solid>,
    link_solids: Vec<Vec<Solid>>,
}

impl ArmBody {
    /// Fetch's arm as it stands in `world`, holding what it holds.
    pub fn of(world: &World, fetch: &Fetch) -> ArmBody {
        let parts = fetch.parts();
        let mut all: Vec<_> = FetchLink::ALL
            .map(|link| {
                let id = parts.link(link);
                crate::navigate::shapes_in(world, [id], world.pose(id).inverse())
            })
            .into();
        // The robot keeps the fingers' whole travel out of fixed bodies, open or closed.
        if let Some(gripper) = all.last_mut() {
            gripper.push(finger_sweep());
        }
        let links = all[MOVING].to_vec();
        let held = fetch.holding().map(|b| b.object);
        let gripper = world.pose(parts.gripper()).inverse();
        let held = crate::navigate::shapes_in(world, held, gripper);
        let mut ignored = parts.all().to_vec();
        ignored.extend(fetch.holding().map(|b| b.object));
        let held_solids = solids(&held);
        let held = held
            .into_iter()
            .map(|(shape, offset)| (inflated(&shape, HELD_MARGIN), offset))
            .collect();
        ArmBody {
            base: fetch.base_pose(world),
            head: fetch.joints().head,
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
        if !c.0.iter().all(|x| x.is_finite()) {
            return false;
        }
        let poses = c.joints(self.head).link_poses();
        let core = world.core();
        let free = |shape: &Primitive, pose: Pose| {
            core.overlaps(shape, pose, &self.filter)
                .is_ok_and(|hits| hits.is_empty())
        };
        let links = self.links.iter().zip(MOVING).all(|(shapes, k)| {
            let at = self.base * poses[k];
            shapes.iter().all(|(s, offset)| free(s, at * *offset))
        });
        let gripper = self.base * poses[FetchLink::Gripper as usize];
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

    /// The arm's planning resolution, rad (m for the torso): [`ARM_RESOLUTION`], finer for what
    /// reaches farther than `HELD_REACH` from the gripper, so that its far end moves no more
    /// per step than that of something within it. At 0.05 rad a step, the far end of a sheet
    /// of plywood held by its edge moves about 5 cm between checked configurations: the sheet
    /// met the torso while the arm moved and its grasp broke. The arm also moves it slower,
    /// one step per configuration.
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
        let poses = c.joints(self.head).link_poses();
        let gripper = poses[FetchLink::Gripper as usize];
        let links = self.link_solids[MOVING]
            .iter()
            .zip(&poses[MOVING])
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
        let gripper = poses[FetchLink::Gripper as usize];
        let others = &self.link_solids[..FetchLink::Gripper as usize];
        self.held_solids.iter().any(|h| {
            others
                .iter()
                .zip(poses)
                .any(|(link, &at)| link.iter().any(|s| h.intersects(gripper, s, at)))
        })
    }

    /// The end effector's pose in the world at `c`.
    pub fn eef(&self, c: &ArmConfig) -> Pose {
        self.base * c.joints(self.head).eef()
    }
}

/// The range of joint `k` (torso first): its limits, or for a continuous joint a turn either
/// way from where it is at `start`.
fn bounds(start: &ArmConfig, k: usize) -> [f32; 2] {
    match joint(k).info().limits {
        Some(limits) => limits,
        None => [start.0[k] - PI, start.0[k] + PI],
    }
}

/// A configuration drawn uniformly within the joints' ranges (their limits, or for a continuous
/// joint a turn either way from where it is at `start`): where an IK search may start over.
pub fn any_config(start: &ArmConfig, rng: &mut SimRng) -> ArmConfig {
    ArmConfig(std::array::from_fn(|k| {
        let [lo, hi] = bounds(start, k);
        uniform(rng, lo, hi)
    }))
}

/// How far what the gripper holds may reach from it before the arm plans and moves in finer
/// steps ([`ArmBody::resolution`]), m.
pub const HELD_REACH: f32 = 0.3;

/// How much the reach from the base's axis counts beside the width across its heading in
/// [`ArmBody::spread`].
pub const REACH_WEIGHT: f32 = 0.2;

/// Fetch's arm moving among the world's objects, its base still.
pub struct ArmSpace<'w> {
    world: &'w World,
    body: ArmBody,
    min: [f32; 8],
    max: [f32; 8],
}

impl<'w> ArmSpace<'w> {
    /// The space of the arm from `start`: joint limits, and half a turn either way of the
    /// start for a continuous joint.
    pub fn new(world: &'w World, body: ArmBody, start: &ArmConfig) -> ArmSpace<'w> {
        ArmSpace {
            world,
            body,
            min: std::array::from_fn(|k| bounds(start, k)[0]),
            max: std::array::from_fn(|k| bounds(start, k)[1]),
        }
    }

    /// The arm's body.
    pub fn body(&self) -> &ArmBody {
        &self.body
    }

    /// Whether `c` lies within the joints' limits.
    fn within(&self, c: &ArmConfig) -> bool {
        (0..8).all(|k| (self.min[k]..=self.max[k]).contains(&c.0[k]))
    }
}

impl Space for ArmSpace<'_> {
    type Config = ArmConfig;

    fn distance(&self, a: &ArmConfig, b: &ArmConfig) -> f32 {
        a.0.iter()
            .zip(b.0)
            .map(|(x, y)| (x - y) * (x - y))
            .sum::<f32>()
            .sqrt()
    }

    fn sample(&self, rng: &mut SimRng) -> ArmConfig {
        ArmConfig(std::array::from_fn(|k| {
            uniform(rng, self.min[k], self.max[k])
        }))
    }

    fn steps(&self, a: &ArmConfig, b: &ArmConfig, resolution: f32) -> Vec<ArmConfig> {
        let longest =
            a.0.iter()
                .zip(b.0)
                .fold(0.0f32, |m, (x, y)| m.max((y - x).abs()));
        let n = (longest / resolution).ceil() as usize;
        let mut out: Vec<ArmConfig> = (1..n)
            .map(|i| {
                let t = i as f32 / n as f32;
                ArmConfig(std::array::from_fn(|k| a.0[k] + (b.0[k] - a.0[k]) * t))
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

    fn fetch_in(world: &mut World) -> Fetch {
        Fetch::add(world, Pose::IDENTITY).unwrap()
    }

    #[test]
    fn the_start_pose_is_free_and_a_wall_through_the_gripper_is_not() {
        let mut world = World::default();
        let fetch = fetch_in(&mut world);
        let body = ArmBody::of(&world, &fetch);
        let start = ArmConfig::of(&fetch.joints());
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
        let body = ArmBody::of(&world, &fetch);
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
        let Robot::Fetch(empty, _) = &robot else {
            unreachable!()
        };
        let empty = ArmBody::of(&world, empty);
        robot.grasp_now(&mut world, 0, board).unwrap();
        let Robot::Fetch(fetch, _) = &robot else {
            unreachable!()
        };
        let holding = ArmBody::of(&world, fetch);
        let start = ArmConfig::of(&fetch.joints());
        assert!(
            holding.clear(&world, &start),
            "held out ahead, it touches nothing"
        );
        // Folded over the base, a board 0.4 m long crosses the torso or the base.
        let mut folded = start;
        folded.0[1..].copy_from_slice(&[1.32, 1.4, -0.2, 1.72, 0.0, 1.66, 0.0]);
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
        let body = ArmBody::of(&w, &fetch);
        let a = ArmConfig::of(&fetch.joints());
        let mut b = a;
        b.0[1] += 0.33;
        b.0[0] += 0.01;
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
