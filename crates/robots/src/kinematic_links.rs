//! Robots made of kinematic links placed by their joints (Fetch, the R1): one world object per
//! link, moved each substep to where the base's motion and the joints put it, and never into a
//! fixed body.
//!
//! A robot states its links as a [`LinkModel`] (where each link is at given joint positions, how
//! joints in between two postures are, each link's centre and blocking shapes) and keeps a
//! [`LinkMotion`]: where its parts are at the end of the step begun last and where they were at
//! its start. At a step's start it asks [`LinkMotion::begin`] for a base motion ([`Twist`]) and
//! joint targets and gets as much of them as fixed bodies allow — all of it, or the joints'
//! motion without the base's, or the base's without the joints', or nothing; each substep
//! [`LinkMotion::move_links`] gives every link the velocity that lands it on its pose.
//!
//! Why velocity-driven kinematic bodies, each given each substep the velocity that lands it on
//! its pose: rapier derives a position-driven body's velocity from its target and its pose
//! through a product that is not exactly the identity once the body is turned, so a turned
//! position-driven body never has exactly zero velocity and never sleeps (measured: a
//! BehaviorRobot that has turned away from the origin idles at ≈ 390 µs per step instead of
//! 0.3). Ours are stopped at exactly zero and sleep.

use crate::ik::rotation_error;
use crate::motion::Blocker;
use behavior_sim::{
    ObjectId, ObjectSpec, Part, Primitive, QueryFilter, STEP_SECONDS, Velocity, World, WorldError,
    groups,
};
use rapier3d::math::{Pose, Rotation, Vector};

/// A robot's links as forward kinematics places them (see the module docs).
pub(crate) trait LinkModel {
    /// The positions of the joints the links move with.
    type Joints: Copy + PartialEq;

    /// Every link's pose in the base frame at `joints`, one per link object, in its order.
    fn link_poses(joints: &Self::Joints) -> Vec<Pose>;

    /// The joints a fraction `t` of the way from `a` to `b` (each joint linearly).
    fn between(a: &Self::Joints, b: &Self::Joints, t: f32) -> Self::Joints;

    /// Link `link`'s centre of mass in its own frame: the point whose path the physics
    /// integrates.
    fn centre(link: usize) -> Vector;

    /// The shapes of link `link`, in its frame, that must not move into a fixed body.
    fn blocking(link: usize) -> Vec<(Primitive, Pose)>;
}

/// A part's volume, m³ (1 for a shape without one here): what a link's mass is spread by.
pub(crate) fn part_volume(part: &Part) -> f32 {
    let pi = std::f32::consts::PI;
    match part.primitive {
        Primitive::Box { half_extents: h } => 8.0 * h.x * h.y * h.z,
        Primitive::Cylinder {
            radius,
            half_height,
        } => pi * radius * radius * 2.0 * half_height,
        Primitive::Capsule {
            radius,
            half_height,
        } => pi * radius * radius * 2.0 * half_height + 4.0 / 3.0 * pi * radius.powi(3),
        _ => 1.0,
    }
}

/// A link's centre of mass in its own frame: the centroid of its parts, by volume.
pub(crate) fn parts_centre(parts: &[Part]) -> Vector {
    let total: f32 = parts.iter().map(part_volume).sum();
    parts
        .iter()
        .map(|p| p.offset.translation * part_volume(p))
        .sum::<Vector>()
        / total
}

/// A base's velocity in its own frame: forward (+x) and to the left (+y), m/s, and turning
/// left, rad/s. Held for a step, it moves the base along an arc.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Twist {
    pub(crate) forward: f32,
    pub(crate) left: f32,
    pub(crate) turn: f32,
}

impl Twist {
    /// Where a base at `pose` is after `t` seconds of this twist: along an arc in its own frame.
    pub(crate) fn after(self, pose: Pose, t: f32) -> Pose {
        let turn = self.turn * t;
        let local = if turn.abs() < 1e-6 {
            Vector::new(self.forward * t, self.left * t, 0.0)
        } else {
            let (sin, cos) = (turn.sin(), 1.0 - turn.cos());
            let r = self.forward / self.turn;
            let mut local = Vector::new(r * sin, r * cos, 0.0);
            if self.left != 0.0 {
                // Sideways motion turns with the base as forward motion does.
                let s = self.left / self.turn;
                local += Vector::new(-s * cos, s * sin, 0.0);
            }
            local
        };
        pose * Pose::from_parts(local, Rotation::from_rotation_z(turn))
    }
}

/// Where a robot's kinematic parts are: its base on the floor and its joints.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Posture<J> {
    pub(crate) base: Pose,
    pub(crate) joints: J,
}

/// The motion of a robot's kinematic links in the step begun last (see the module docs).
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct LinkMotion<J> {
    /// Where the parts are at the end of the step begun last.
    pub(crate) now: Posture<J>,
    /// Where they were at its start.
    pub(crate) from: Posture<J>,
    /// The base's velocity in that step.
    twist: Twist,
    /// Whether the links have a velocity set.
    moving: bool,
}

/// Adds each link (its spec, the pose already set) in the robot's collision group: robot parts
/// touch neither each other nor water.
pub(crate) fn add_links(
    world: &mut World,
    specs: impl IntoIterator<Item = ObjectSpec>,
) -> Result<Vec<ObjectId>, WorldError> {
    let others = groups::ALL & !groups::ROBOT & !groups::WATER;
    let mut links = Vec::new();
    for spec in specs {
        let id = world.add(spec)?;
        world.contacts_mut().set_groups(id, groups::ROBOT, others);
        links.push(id);
    }
    Ok(links)
}

impl<J: Copy + PartialEq> LinkMotion<J> {
    /// Standing still at `posture`.
    pub(crate) fn at(posture: Posture<J>) -> Self {
        LinkMotion {
            now: posture,
            from: posture,
            twist: Twist::default(),
            moving: false,
        }
    }

    /// The base's velocity in the step begun last (zero where it did not move).
    pub(crate) fn twist(&self) -> Twist {
        self.twist
    }

    /// Whether the step begun last moves any part.
    pub(crate) fn moves(&self) -> bool {
        self.from != self.now
    }

    /// Begins a step that asks for the base to move at `twist` and the joints to reach
    /// `joints`: as much of it as fixed bodies let `links` do. Whether the base moves.
    pub(crate) fn begin<M: LinkModel<Joints = J>>(
        &mut self,
        world: &World,
        links: &[ObjectId],
        twist: Twist,
        joints: J,
    ) -> bool {
        self.from = self.now;
        let wanted = Posture {
            base: twist.after(self.now.base, STEP_SECONDS),
            joints,
        };
        let allowed = if wanted == self.now {
            wanted
        } else {
            self.allow::<M>(world, links, wanted)
        };
        let base_moves = allowed.base != self.now.base;
        self.twist = if base_moves { twist } else { Twist::default() };
        self.now = allowed;
        base_moves
    }

    /// `wanted` as far as fixed bodies let it be: all of it, or the joints' motion without the
    /// base's, or the base's without the joints', or nothing.
    fn allow<M: LinkModel<Joints = J>>(
        &self,
        world: &World,
        links: &[ObjectId],
        wanted: Posture<J>,
    ) -> Posture<J> {
        let blocker = Blocker {
            world,
            filter: QueryFilter {
                fixed_only: true,
                ..QueryFilter::excluding(links)
            },
        };
        let now = self.now;
        let candidates = [
            wanted,
            Posture {
                base: now.base,
                ..wanted
            },
            Posture {
                joints: now.joints,
                ..wanted
            },
        ];
        candidates
            .into_iter()
            .find(|c| *c != now && !blocked::<M>(&blocker, &now, c))
            .unwrap_or(now)
    }

    /// Moves every link for one substep, if any moves in this step; stops them (velocity
    /// exactly 0, so that they can sleep) in the first substep of a step without motion.
    pub(crate) fn move_links<M: LinkModel<Joints = J>>(
        &mut self,
        world: &mut World,
        links: &[ObjectId],
        substep: u32,
    ) {
        if !self.moves() {
            if self.moving {
                for &id in links {
                    let _ = world
                        .bodies_mut()
                        .set_velocity(id.into(), Velocity::default());
                }
                self.moving = false;
            }
            return;
        }
        let n = world.bodies().substeps().count();
        let posture = if substep + 1 >= n {
            self.now
        } else {
            let t = (substep + 1) as f32 / n as f32;
            Posture {
                base: self.twist.after(self.from.base, t * STEP_SECONDS),
                joints: M::between(&self.from.joints, &self.now.joints, t),
            }
        };
        let poses = M::link_poses(&posture.joints);
        let dt = STEP_SECONDS / n as f32;
        for (k, &id) in links.iter().enumerate() {
            let target = posture.base * poses[k];
            let velocity = velocity_to(world.bodies().pose(id), target, M::centre(k), dt);
            // Finite poses make finite velocities: the world cannot refuse these.
            let _ = world.bodies_mut().set_velocity(id.into(), velocity);
        }
        self.moving = true;
    }

    /// Puts the base at `base` at once, every link where the joints put it, all at rest.
    pub(crate) fn place<M: LinkModel<Joints = J>>(
        &mut self,
        world: &mut World,
        links: &[ObjectId],
        base: Pose,
    ) -> Result<(), WorldError> {
        let posture = Posture { base, ..self.now };
        let poses = M::link_poses(&posture.joints);
        for (k, &id) in links.iter().enumerate() {
            world.bodies_mut().set_pose(id, base * poses[k])?;
        }
        *self = LinkMotion::at(posture);
        Ok(())
    }
}

/// Whether moving every link from `from` to `to` makes one newly overlap a fixed body.
fn blocked<M: LinkModel>(
    blocker: &Blocker,
    from: &Posture<M::Joints>,
    to: &Posture<M::Joints>,
) -> bool {
    let (a, b) = (M::link_poses(&from.joints), M::link_poses(&to.joints));
    a.iter().zip(&b).enumerate().any(|(k, (a, b))| {
        let (pa, pb) = (from.base * *a, to.base * *b);
        pa != pb
            && M::blocking(k)
                .iter()
                .any(|shape| blocker.blocked(shape, pa, pb))
    })
}

/// The velocity that takes a link from `now` to `target` in one substep of `dt`, as the
/// physics integrates a body: a turn about its centre of mass (`centre`, in its frame), then
/// the centre's motion.
fn velocity_to(now: Pose, target: Pose, centre: Vector, dt: f32) -> Velocity {
    let turn = rotation_error(now.rotation, target.rotation);
    Velocity {
        linear: (target.transform_point(centre) - now.transform_point(centre)) / dt,
        angular: turn / dt,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_twist_moves_the_base_along_an_arc() {
        let ahead = Twist {
            forward: 1.0,
            ..Twist::default()
        };
        assert!((ahead.after(Pose::IDENTITY, 1.0).translation - Vector::X).length() < 1e-6);
        // A quarter turn at radius 1: from (0, 0) to (1, 1), facing +y.
        let quarter = std::f32::consts::FRAC_PI_2;
        let arc = Twist {
            forward: quarter,
            turn: quarter,
            ..Twist::default()
        };
        let end = arc.after(Pose::IDENTITY, 1.0);
        assert!((end.translation - Vector::new(1.0, 1.0, 0.0)).length() < 1e-5);
        assert!(((end.rotation * Vector::X) - Vector::Y).length() < 1e-5);
        // Sideways while turning a quarter: from (0, 0) to (−1, 1), the left turned with it.
        let sideways = Twist {
            left: quarter,
            turn: quarter,
            ..Twist::default()
        };
        let end = sideways.after(Pose::IDENTITY, 1.0);
        assert!((end.translation - Vector::new(-1.0, 1.0, 0.0)).length() < 1e-5);
        let straight = Twist {
            left: 0.5,
            ..Twist::default()
        };
        let end = straight.after(Pose::IDENTITY, 2.0);
        assert!((end.translation - Vector::Y).length() < 1e-6);
    }
}
