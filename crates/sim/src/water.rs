//! Water sources and `soaked`.
//!
//! A water source (the sink) runs while it is toggled on (always, if it cannot be toggled) and
//! emits one drop every 3 steps (0.1 s) from 5 cm below its outlet, from a pool of 10 drops:
//! small dynamic spheres of 0.05 g (iGibson 2.0, §1.5). A soakable object that a drop touches
//! becomes soaked, and stays so. A drop returns to the pool when it touches its source or after
//! 2 s (iGibson recycles only on touching the source, so its pool can run dry).

use crate::kinematics::TOUCH_DISTANCE;
use crate::world::{DROP_TAG, ObjectId, PointKind, World};
use behavior_bddl::taxonomy::Ability;
use rapier3d::dynamics::{RigidBodyBuilder, RigidBodyHandle};
use rapier3d::geometry::{Ball, ColliderBuilder};
use rapier3d::math::{Pose, Vector};
use rapier3d::pipeline::QueryFilter;

pub const DROPS_PER_SOURCE: usize = 10;
pub const DROP_RADII: [f32; 3] = [0.01, 0.009, 0.008];
pub const DROP_MASS: f32 = 5e-5;
pub const STEPS_BETWEEN_DROPS: u32 = 3;
pub const DROP_LIFETIME_STEPS: u32 = 60;
/// Drops leave the outlet this far below it (m).
pub const OUTLET_OFFSET: f32 = 0.05;

#[derive(Clone, Debug)]
pub struct WaterStream {
    pub source: ObjectId,
    pub drops: Vec<Drop>,
    pub steps_since_drop: u32,
}

#[derive(Clone, Copy, Debug)]
pub struct Drop {
    pub body: RigidBodyHandle,
    /// Steps since emission; `None` while pooled.
    pub age: Option<u32>,
}

impl World {
    /// Creates the drop pool of a new water source (called when the object is added).
    pub(crate) fn add_water_stream(&mut self, source: ObjectId) {
        let drops = (0..DROPS_PER_SOURCE)
            .map(|k| {
                let mut body = RigidBodyBuilder::dynamic().ccd_enabled(true).build();
                body.set_enabled(false);
                let body = self.physics.insert_body(body);
                let radius = DROP_RADII[k % DROP_RADII.len()];
                let collider = ColliderBuilder::ball(radius)
                    .mass(DROP_MASS)
                    .user_data(DROP_TAG)
                    .build();
                self.physics.insert_collider(collider, Some(body));
                Drop { body, age: None }
            })
            .collect();
        self.water.push(WaterStream {
            source,
            drops,
            steps_since_drop: STEPS_BETWEEN_DROPS,
        });
    }

    /// The drops in flight, as world positions.
    pub fn drops(&self) -> Vec<Vector> {
        let mut out = Vec::new();
        for stream in &self.water {
            for d in stream.drops.iter().filter(|d| d.age.is_some()) {
                out.push(self.physics.bodies[d.body].translation());
            }
        }
        out
    }

    pub(crate) fn update_water(&mut self) {
        for s in 0..self.water.len() {
            let source = self.water[s].source;
            let object = self.object(source);
            let running = !object.has(Ability::Toggleable) || self.object_state(source).toggled_on;
            let outlet = object
                .point(PointKind::WaterOutlet)
                .map(|p| self.pose(source).transform_point(p) - Vector::Z * OUTLET_OFFSET);
            // Soak what drops touch; return old drops and those on their source to the pool.
            for d in 0..self.water[s].drops.len() {
                let drop = self.water[s].drops[d];
                let Some(age) = drop.age else { continue };
                let touched = self.touched_by_drop(drop.body);
                for &id in &touched {
                    if id != source && self.object(id).has(Ability::Soakable) {
                        self.states[id.0 as usize].soaked = true;
                    }
                }
                let done = touched.contains(&source) || age + 1 >= DROP_LIFETIME_STEPS;
                let body = &mut self.physics.bodies[drop.body];
                if done {
                    body.set_enabled(false);
                    self.water[s].drops[d].age = None;
                } else {
                    self.water[s].drops[d].age = Some(age + 1);
                }
            }
            let stream = &mut self.water[s];
            stream.steps_since_drop = stream.steps_since_drop.saturating_add(1);
            let (Some(outlet), true) = (outlet, running) else {
                continue;
            };
            if stream.steps_since_drop < STEPS_BETWEEN_DROPS {
                continue;
            }
            if let Some(d) = stream.drops.iter().position(|d| d.age.is_none()) {
                stream.steps_since_drop = 0;
                stream.drops[d].age = Some(0);
                self.quiet = false;
                let body = &mut self.physics.bodies[stream.drops[d].body];
                body.set_enabled(true);
                body.set_position(Pose::from_translation(outlet), true);
                body.set_linvel(Vector::ZERO, true);
                body.set_angvel(Vector::ZERO, true);
            }
        }
    }

    /// The objects within touching distance of a drop.
    fn touched_by_drop(&self, drop: RigidBodyHandle) -> Vec<ObjectId> {
        let body = &self.physics.bodies[drop];
        let radius = body
            .colliders()
            .first()
            .and_then(|&c| {
                self.physics.colliders[c]
                    .shape()
                    .as_ball()
                    .map(|b| b.radius)
            })
            .unwrap_or(DROP_RADII[0]);
        let probe = Ball::new(radius + TOUCH_DISTANCE);
        let not_a_drop = |_, c: &rapier3d::geometry::Collider| c.user_data != DROP_TAG;
        let filter = QueryFilter::default()
            .exclude_rigid_body(drop)
            .predicate(&not_a_drop);
        let mut hit: Vec<ObjectId> = self
            .physics
            .intersect_shape(Pose::from_translation(body.translation()), &probe, filter)
            .map(|(_, c)| ObjectId(c.user_data as u32))
            .collect();
        hit.sort();
        hit.dedup();
        hit
    }
}
