//! How a palm follows its target: a smooth reference path, and a force-limited servo onto it.
//!
//! **The reference.** A [`Follower`] heads for the hand's target each substep at the fastest
//! speed from which it can still stop there, changing its velocity by at most
//! `acceleration · dt` ([`HAND_LIMITS`]: 150 m/s², what the original's 300 N constraint gives
//! its 2 kg hand). A target that jumps by 5 cm becomes a path the palm can follow.
//!
//! **The servo.** The palm is a dynamic body. Each substep [`servo`] sets its velocity to land
//! on the reference at the end of the substep (gravity compensated), the change limited to what
//! [`HAND_FORCE`] (300 N, the original's hand constraint) gives the hand in a substep; the
//! fingers are moved with it. So a hand presses on what it meets with bounded force and yields —
//! where a kinematic palm would squeeze an apple against a table with unbounded force and shoot
//! it across the room — and what it holds is accelerated through the grasp by at most what 300 N
//! gives hand and load together: a held 10 kg object (the heaviest a hand may hold) needs about
//! 10 · (300 / 12 + 9.81) ≈ 350 N, under the grasp's 500 N, so the hand's own motion never
//! breaks a grasp.

use crate::hand::HAND_MASS;
use behavior_sim::{BodyRef, ObjectId, Velocity, World};
use rapier3d::math::{Pose, Rotation, Vector};

/// How fast a follower may move and change speed.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Limits {
    /// m/s.
    pub(crate) speed: f32,
    /// m/s².
    pub(crate) acceleration: f32,
    /// rad/s.
    pub(crate) angular_speed: f32,
    /// rad/s².
    pub(crate) angular_acceleration: f32,
}

/// The most force a palm's servo applies, N (the original's hand constraint).
pub const HAND_FORCE: f32 = 300.0;
/// The most a palm's servo changes its angular velocity per second, rad/s².
const HAND_ANGULAR_ACCELERATION: f32 = 1000.0;

/// A hand's limits: fast enough to keep up with its target (a hand command and the body's
/// motion together reach about 5 m/s at full reach), accelerating as the original's hand can.
pub(crate) const HAND_LIMITS: Limits = Limits {
    speed: 6.0,
    acceleration: HAND_FORCE / HAND_MASS,
    angular_speed: 6.0,
    angular_acceleration: 500.0,
};

/// Closer than this (m or rad) and slow, a follower snaps onto its target and stops.
const SNAP: f32 = 1e-5;

/// A kinematic part's pose and velocity.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Follower {
    pub(crate) pose: Pose,
    linear: Vector,
    angular: Vector,
}

impl Follower {
    /// At rest at `pose`.
    pub(crate) fn at(pose: Pose) -> Follower {
        Follower {
            pose,
            linear: Vector::ZERO,
            angular: Vector::ZERO,
        }
    }

    /// Whether it rests exactly on `target`.
    pub(crate) fn rests_on(&self, target: &Pose) -> bool {
        self.pose == *target && self.linear == Vector::ZERO && self.angular == Vector::ZERO
    }

    /// One substep of `dt` toward `target`; whether it moved.
    pub(crate) fn advance(&mut self, target: &Pose, dt: f32, limits: &Limits) -> bool {
        if self.rests_on(target) {
            return false;
        }
        let error = target.translation - self.pose.translation;
        self.linear = approach(error, self.linear, dt, limits.speed, limits.acceleration);
        let turn = rotation_error(self.pose.rotation, target.rotation);
        let (w_max, alpha) = (limits.angular_speed, limits.angular_acceleration);
        self.angular = approach(turn, self.angular, dt, w_max, alpha);
        self.pose.translation += self.linear * dt;
        let step = Rotation::from_scaled_axis(self.angular * dt);
        self.pose.rotation = (step * self.pose.rotation).normalize();
        self.snap(target, dt, limits);
        true
    }

    fn snap(&mut self, target: &Pose, dt: f32, limits: &Limits) {
        let error = (target.translation - self.pose.translation).length();
        if error < SNAP && self.linear.length() <= limits.acceleration * dt {
            self.pose.translation = target.translation;
            self.linear = Vector::ZERO;
        }
        let turn = rotation_error(self.pose.rotation, target.rotation).length();
        if turn < SNAP && self.angular.length() <= limits.angular_acceleration * dt {
            self.pose.rotation = target.rotation;
            self.angular = Vector::ZERO;
        }
    }
}

/// Sets a hand's velocity so that its palm lands on `reference` at the end of a substep of `dt`,
/// within the force limit (see the module docs). The fingers are shapes of the hand's body, so
/// they move with it.
pub(crate) fn servo(world: &mut World, hand: ObjectId, reference: &Pose, dt: f32) {
    let palm = BodyRef::from(hand);
    let (Ok(now), Ok(velocity), Ok(centre)) = (
        world.bodies().body_pose(palm),
        world.bodies().velocity(palm),
        world.bodies().centre_of_mass(palm),
    ) else {
        return;
    };
    // The velocity is the centre of mass's (off the palm's origin: the fingers weigh too), so
    // it is sent where it is when the hand is at the reference.
    let centre_there = reference.transform_point(now.inverse_transform_point(centre));
    // What gravity takes off the velocity during the substep, given back in advance.
    let lift = -world.bodies().gravity() * dt;
    let wanted = (centre_there - centre) / dt + lift;
    let limit = HAND_FORCE / HAND_MASS * dt;
    let linear = velocity.linear + (wanted - velocity.linear).clamp_length_max(limit);
    let turn = rotation_error(now.rotation, reference.rotation) / dt;
    let spin = (turn - velocity.angular).clamp_length_max(HAND_ANGULAR_ACCELERATION * dt);
    let twist = Velocity {
        linear,
        angular: velocity.angular + spin,
    };
    // Finite: the reference and the hand's state are; the world cannot refuse it.
    let _ = world.bodies_mut().set_velocity(palm, twist);
}

/// Whether a palm rests within a few millimetres of `reference`: close enough to be parked there.
pub(crate) fn settled(world: &World, palm: BodyRef, reference: &Pose) -> bool {
    let (Ok(now), Ok(velocity)) = (
        world.bodies().body_pose(palm),
        world.bodies().velocity(palm),
    ) else {
        return false;
    };
    let offset = (now.translation - reference.translation).length();
    let turn = rotation_error(now.rotation, reference.rotation).length();
    offset < PARK_DISTANCE
        && turn < PARK_ANGLE
        && velocity.linear.length() < PARK_SPEED
        && velocity.angular.length() < 10.0 * PARK_SPEED
}

/// A palm this close to its reference (m, rad) and this slow (m/s) may be parked.
const PARK_DISTANCE: f32 = 0.002;
const PARK_ANGLE: f32 = 0.01;
const PARK_SPEED: f32 = 0.05;

/// The rotation vector (axis × angle, the short way round) taking `from` to `to`.
pub(crate) fn rotation_error(from: Rotation, to: Rotation) -> Vector {
    let mut q = to * from.inverse();
    if q.w < 0.0 {
        q = -q;
    }
    q.to_scaled_axis()
}

/// The velocity after one substep of closing an `error`: toward it at the fastest speed from which
/// it can still stop in time (and no faster than lands on it this substep), changing by at most
/// `acceleration · dt`.
fn approach(error: Vector, velocity: Vector, dt: f32, max_speed: f32, acceleration: f32) -> Vector {
    let distance = error.length();
    let wanted = if distance > 0.0 {
        let speed = max_speed
            .min((2.0 * acceleration * distance).sqrt())
            .min(distance / dt);
        error * (speed / distance)
    } else {
        Vector::ZERO
    };
    velocity + (wanted - velocity).clamp_length_max(acceleration * dt)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f32 = 1.0 / 300.0;

    #[test]
    fn a_follower_reaches_its_target_and_stops_there_exactly() {
        let target = Pose::from_parts(Vector::new(0.3, -0.2, 0.1), Rotation::from_rotation_z(0.7));
        let mut f = Follower::at(Pose::IDENTITY);
        let mut steps = 0;
        while f.advance(&target, DT, &HAND_LIMITS) {
            steps += 1;
            assert!(steps < 1000, "never arrived: {f:?}");
        }
        assert!(f.rests_on(&target));
        // 0.37 m at 150 m/s² takes at least 2·√(0.37/150) ≈ 0.1 s.
        assert!(steps as f32 * DT > 0.099, "arrived after {steps} substeps");
    }

    #[test]
    fn its_velocity_never_changes_faster_than_its_limit() {
        let mut f = Follower::at(Pose::IDENTITY);
        let mut before = Vector::ZERO;
        // A target jumping back and forth by 5 cm, as random actions do.
        for k in 0..600 {
            let x = if (k / 10) % 2 == 0 { 0.05 } else { -0.05 };
            f.advance(
                &Pose::from_translation(Vector::new(x, 0.0, 0.0)),
                DT,
                &HAND_LIMITS,
            );
            let change = (f.linear - before).length() / DT;
            assert!(change <= HAND_LIMITS.acceleration * 1.0001, "{change} m/s²");
            before = f.linear;
        }
    }
}
