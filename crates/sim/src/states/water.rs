//! Water sources and `soaked`.
//!
//! A water source (the sink) runs while it is toggled on (always, if it cannot be toggled) and
//! emits one drop every 4th step from 5 cm below its outlet (iGibson's counter emits once the steps
//! since the last drop reach 0.1 s / (1/30 s) = 3.3, i.e. on the 4th), from a pool of 10 drops:
//! small dynamic spheres of 0.05 g (iGibson 2.0, §1.5). A soakable object that a drop touches
//! becomes soaked, and stays so. A drop returns to the pool when it touches its source or after
//! 2 s (iGibson recycles only on touching the source, so its pool can run dry).

use crate::core::{Core, DROP_TAG, untag};
use crate::kinematics::TOUCH_DISTANCE;
use crate::object::{ObjectId, PointKind};
use crate::states::toggling::Toggles;
use behavior_core::Ability;
use rapier3d::dynamics::{RigidBodyBuilder, RigidBodyHandle};
use rapier3d::geometry::{Ball, ColliderBuilder};
use rapier3d::math::{Pose, Vector};
use rapier3d::pipeline::QueryFilter;
use serde::{Deserialize, Serialize};

/// Drops in each source's pool.
pub const DROPS_PER_SOURCE: usize = 10;
/// Radii of successive drops (m).
pub const DROP_RADII: [f32; 3] = [0.01, 0.009, 0.008];
/// kg.
pub const DROP_MASS: f32 = 5e-5;
/// A running source emits one drop every this many steps.
pub const STEPS_BETWEEN_DROPS: u32 = 4;
/// A drop returns to the pool after this many steps.
pub const DROP_LIFETIME_STEPS: u32 = 60;
/// Drops leave the outlet this far below it (m).
pub const OUTLET_OFFSET: f32 = 0.05;

#[derive(Clone, Debug, Serialize, Deserialize)]
struct WaterStream {
    source: ObjectId,
    drops: Vec<Drop>,
    steps_since_drop: u32,
}

#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
struct Drop {
    body: RigidBodyHandle,
    /// Steps since emission; `None` while pooled.
    age: Option<u32>,
}

/// The water system: each source's drops, and which objects are soaked.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Water {
    streams: Vec<WaterStream>,
    soaked: Vec<bool>,
}

impl Water {
    /// A soaked flag per object; every stream's source is an object and its drops are bodies.
    pub(crate) fn check_consistency(&self, n: usize, core: &Core) -> Result<(), String> {
        let drops_known = self.streams.iter().all(|s| {
            (s.source.0 as usize) < n
                && s.drops
                    .iter()
                    .all(|d| core.bodies.physics.bodies.get(d.body).is_some())
        });
        if self.soaked.len() != n || !drops_known {
            return Err("water: tables disagree with the objects or the physics".into());
        }
        Ok(())
    }
}

impl Water {
    /// A new object: a water source gets its pool of drops (disabled bodies in the physics).
    pub(crate) fn add_object(&mut self, core: &mut Core, id: ObjectId) {
        self.soaked.push(false);
        if !core.bodies.object(id).has(Ability::WaterSource) {
            return;
        }
        let drops = (0..DROPS_PER_SOURCE)
            .map(|k| {
                let mut body = RigidBodyBuilder::dynamic()
                    .ccd_enabled(true)
                    .user_data(DROP_TAG)
                    .build();
                body.set_enabled(false);
                let body = core.bodies.physics.insert_body(body);
                let radius = DROP_RADII[k % DROP_RADII.len()];
                let collider = ColliderBuilder::ball(radius)
                    .mass(DROP_MASS)
                    .user_data(DROP_TAG)
                    .collision_groups(rapier3d::geometry::InteractionGroups::new(
                        rapier3d::geometry::Group::from_bits_retain(crate::contacts::groups::WATER),
                        rapier3d::geometry::Group::ALL,
                        rapier3d::geometry::InteractionTestMode::And,
                    ))
                    .build();
                core.bodies.physics.insert_collider(collider, Some(body));
                Drop { body, age: None }
            })
            .collect();
        self.streams.push(WaterStream {
            source: id,
            drops,
            steps_since_drop: STEPS_BETWEEN_DROPS,
        });
    }

    pub(crate) fn is_soaked(&self, id: ObjectId) -> bool {
        self.soaked[id.0 as usize]
    }

    pub(crate) fn set_soaked(&mut self, id: ObjectId, soaked: bool) {
        self.soaked[id.0 as usize] = soaked;
    }

    /// A half made by slicing starts as wet as the whole.
    pub(crate) fn inherit(&mut self, from: ObjectId, to: ObjectId) {
        self.soaked[to.0 as usize] = self.soaked[from.0 as usize];
    }

    /// The drops in flight, as world positions.
    pub(crate) fn drops(&self, core: &Core) -> Vec<Vector> {
        let mut out = Vec::new();
        for stream in &self.streams {
            for d in stream.drops.iter().filter(|d| d.age.is_some()) {
                out.push(core.bodies.physics.bodies[d.body].translation());
            }
        }
        out
    }

    /// One step: soak what drops touch, recycle old drops, emit a new one from running sources.
    pub(crate) fn update(&mut self, core: &mut Core, toggles: &Toggles) {
        for s in 0..self.streams.len() {
            let source = self.streams[s].source;
            let object = core.bodies.object(source);
            let running = !object.has(Ability::Toggleable) || toggles.is_on(source);
            let outlet = object
                .point(PointKind::WaterOutlet)
                .map(|p| core.bodies.pose(source).transform_point(p) - Vector::Z * OUTLET_OFFSET);
            self.age_drops(core, s);
            let stream = &mut self.streams[s];
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
                core.bodies.quiet = false;
                let body = &mut core.bodies.physics.bodies[stream.drops[d].body];
                body.set_enabled(true);
                body.set_position(Pose::from_translation(outlet), true);
                body.set_linvel(Vector::ZERO, true);
                body.set_angvel(Vector::ZERO, true);
            }
        }
    }

    /// Soaks what a stream's drops touch; returns old drops and those on their source to the pool.
    fn age_drops(&mut self, core: &mut Core, s: usize) {
        let source = self.streams[s].source;
        for d in 0..self.streams[s].drops.len() {
            let drop = self.streams[s].drops[d];
            let Some(age) = drop.age else { continue };
            let touched = touched_by_drop(core, drop.body);
            for &id in &touched {
                if id != source && core.bodies.object(id).has(Ability::Soakable) {
                    self.soaked[id.0 as usize] = true;
                }
            }
            let done = touched.contains(&source) || age + 1 >= DROP_LIFETIME_STEPS;
            if done {
                core.bodies.physics.bodies[drop.body].set_enabled(false);
                self.streams[s].drops[d].age = None;
            } else {
                self.streams[s].drops[d].age = Some(age + 1);
            }
        }
    }
}

/// The objects within touching distance of a drop.
fn touched_by_drop(core: &Core, drop: RigidBodyHandle) -> Vec<ObjectId> {
    let body = &core.bodies.physics.bodies[drop];
    let radius = body
        .colliders()
        .first()
        .and_then(|&c| {
            core.bodies.physics.colliders[c]
                .shape()
                .as_ball()
                .map(|b| b.radius)
        })
        .unwrap_or(DROP_RADII[0]);
    let probe = Ball::new(radius + TOUCH_DISTANCE);
    let not_a_drop = |_, c: &rapier3d::geometry::Collider| c.user_data != DROP_TAG;
    // What ignores water (a robot's body) is not wetted either.
    let groups = body
        .colliders()
        .first()
        .map(|&c| core.bodies.physics.colliders[c].collision_groups())
        .unwrap_or_default();
    let filter = QueryFilter::default()
        .exclude_rigid_body(drop)
        .groups(groups)
        .predicate(&not_a_drop);
    // Drops move only by physics, so rapier's broad phase is current for them.
    let mut hit: Vec<ObjectId> = core
        .bodies
        .physics
        .intersect_shape(Pose::from_translation(body.translation()), &probe, filter)
        .filter_map(|(_, c)| untag(c.user_data).map(|b| b.object))
        .collect();
    hit.sort();
    hit.dedup();
    hit
}
