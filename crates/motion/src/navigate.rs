//! Where the base may stand to act on an object — NAVIGATE_TO's pose search (iGibson 2.0.3's
//! `envs/behavior_mp_env.py`) — and the robot's footprint, read from the world.

use crate::base::{BaseConfig, Footprint, KEEL, stands_inside};
use behavior_core::rng::{SimRng, uniform};
use behavior_core::{FLOOR_SYNSET, floor_gap};
use behavior_robots::Robot;
use behavior_sim::{BodyRef, ObjectId, Primitive, QueryFilter, Solid, World};
use rapier3d::math::{Pose, Vector};
use std::f32::consts::PI;

/// The distances from the object tried, m: the original's 0.6–2.4 (with 0.8 and 1.0 between),
/// nearest first, then two nearer ones, last, for where none of those serve: a small thing on
/// the floor by furniture, which a hand reaches only from a stand close beside it (a spoon
/// 0.9 m from every shoulder at 0.6 was out of reach 1 m down).
pub(crate) const STAND_DISTANCES: [f32; 8] = [0.6, 0.8, 1.0, 1.2, 1.8, 2.4, 0.45, 0.35];
/// Random headings tried per distance.
pub(crate) const STAND_HEADINGS: usize = 20;
/// How clear of everything the robot must stand, m.
pub(crate) const STAND_CLEARANCE: f32 = 0.01;

/// The robot as it stands now: its base's configuration on the floor, and the shapes of its
/// parts (base, hands or arm) and of what it holds, in the base's floor frame, which move with
/// it. (The original's check ignores held objects; a carton carried into a wall breaks the
/// grasp, so ours keeps them clear too.)
pub struct Standing {
    /// Where the base stands.
    pub config: BaseConfig,
    /// What moves with it.
    pub footprint: Footprint,
    /// The eye in the base's floor frame.
    pub eye: Pose,
    /// What the robot's checks ignore: itself, what it holds and the floors it stands on.
    pub filter: QueryFilter,
}

impl Standing {
    /// The robot as it stands in the world now.
    pub fn of(world: &World, robot: &Robot) -> Standing {
        let base = robot.base_pose(world);
        let forward = base.rotation * Vector::X;
        let config = BaseConfig::new(
            base.translation.x,
            base.translation.y,
            forward.y.atan2(forward.x),
        );
        let floor = config.pose().inverse();
        let held = (0..robot.hands()).filter_map(|h| robot.held(h));
        let mut shapes = shapes_in(world, robot.objects(), floor);
        // What the hands carry sways and trails as the base drives: it is kept clear by a margin
        // (the robot's `carry_sway`).
        let carried = shapes_in(world, held, floor);
        let margin = robot.spec().carry_sway;
        shapes.extend(
            carried
                .into_iter()
                .map(|(shape, pose)| (inflated(&shape, margin), pose)),
        );
        // What stops the base beyond its own shapes (a BehaviorRobot's palms' sweeps) goes with
        // it too.
        let sweeps = robot.base_sweep(world).into_iter();
        shapes.extend(sweeps.map(|(shape, pose)| (shape, floor * pose)));
        let mut ignored = robot.objects();
        ignored.extend((0..robot.hands()).filter_map(|h| robot.held(h)));
        // The base stands on the floors (Fetch's wheels touch them): they are no obstacle.
        let floors = world
            .bodies()
            .objects()
            .filter(|(_, o)| o.category == FLOOR_SYNSET);
        ignored.extend(floors.map(|(id, _)| id));
        Standing {
            config,
            footprint: Footprint { shapes },
            eye: floor * robot.camera_pose(world),
            filter: QueryFilter::excluding(&ignored),
        }
    }

    /// The bodies the robot's parts would overlap at `c`.
    pub fn overlapping(&self, world: &World, c: &BaseConfig) -> Vec<BodyRef> {
        let base = c.pose();
        let mut out = Vec::new();
        for (shape, offset) in &self.footprint.shapes {
            let hits = world.query().overlaps(shape, base * *offset, &self.filter);
            out.extend(hits.unwrap_or_default());
        }
        out.sort();
        out.dedup();
        out
    }

    /// Whether every part would stand at least `STAND_CLEARANCE` from everything at `c`,
    /// and not within something whose walls it clears.
    pub fn clear_at(&self, world: &World, c: &BaseConfig) -> bool {
        let base = c.pose();
        let clear = self.footprint.shapes.iter().all(|(shape, offset)| {
            world
                .query()
                .nearest(shape, base * *offset, STAND_CLEARANCE, &self.filter)
                .is_ok_and(|near| near.is_none())
        });
        clear && !stands_inside(world, &self.filter, c.x, c.y)
    }

    /// Whether a part of the robot low over the floor (Fetch's base, 3 cm up) would stand over
    /// `object` at `c`: taken down to the floor, it overlaps it. A sheet of plywood 1.8 cm thick
    /// passes under Fetch's base, which then stood over its edge; the gripper took the edge and
    /// lifted it into the base, and the grasp broke.
    pub fn over(&self, world: &World, c: &BaseConfig, object: ObjectId) -> bool {
        let base = c.pose();
        self.footprint.shapes.iter().any(|(shape, offset)| {
            let at = base * *offset;
            let Ok(solid) = Solid::new(shape, Pose::IDENTITY) else {
                return false;
            };
            let (low, _) = solid.aabb(at);
            if low.z > KEEL {
                return false;
            }
            let down = Pose::from_translation(-Vector::Z * low.z.max(0.0)) * at;
            let hits = world.query().overlaps(shape, down, &self.filter);
            hits.is_ok_and(|hits| hits.iter().any(|b| b.object == object))
        })
    }

    /// Whether the eye at `c` sees `object`'s centre before anything else.
    pub fn sees(&self, world: &World, c: &BaseConfig, object: ObjectId) -> bool {
        let eye = (c.pose() * self.eye).translation;
        let centre: Vector = world.bodies().aabb(object).center();
        let to = centre - eye;
        let distance = to.length();
        if distance < 1e-4 {
            return false;
        }
        world
            .query()
            .cast_ray(eye, to / distance, distance + 0.05, &self.filter)
            .ok()
            .flatten()
            .is_some_and(|hit| hit.body.is_some_and(|b| b.object == object))
    }

    /// A place to stand facing `object`: at each of `STAND_DISTANCES` from its centre in turn,
    /// `STAND_HEADINGS` random headings, the first that is clear and sees it.
    pub fn near(&self, world: &World, object: ObjectId, rng: &mut SimRng) -> Option<BaseConfig> {
        self.near_where(world, object, &|_| true, rng)
    }

    /// As [`Standing::near`], but only places that `accept` takes (checked last).
    pub fn near_where(
        &self,
        world: &World,
        object: ObjectId,
        accept: &dyn Fn(&BaseConfig) -> bool,
        rng: &mut SimRng,
    ) -> Option<BaseConfig> {
        self.search(world, object, rng, |c| {
            self.sees(world, c, object) && accept(c)
        })
    }

    /// As [`Standing::near`], but the first clear place within `reach` of the object's box
    /// (across the floor),
    /// seen or not: for what no clear place sees (a sink's centre lies under its counter's top).
    pub fn within(
        &self,
        world: &World,
        object: ObjectId,
        reach: f32,
        accept: &dyn Fn(&BaseConfig) -> bool,
        rng: &mut SimRng,
    ) -> Option<BaseConfig> {
        let close = box_within(world, object, reach);
        self.search(world, object, rng, |c| close(c) && accept(c))
    }

    /// As [`Standing::near`], but only where the object's box lies within `reach` across the
    /// floor: where a hand can act on what it sees (the farther rings of `STAND_DISTANCES`
    /// see a plate on a counter but leave it out of reach). Both take only the places that
    /// `accept` (an arm's reach from there, say; checked last, being the dearest).
    pub fn near_within(
        &self,
        world: &World,
        object: ObjectId,
        reach: f32,
        accept: &dyn Fn(&BaseConfig) -> bool,
        rng: &mut SimRng,
    ) -> Option<BaseConfig> {
        let close = box_within(world, object, reach);
        self.search(world, object, rng, |c| {
            close(c) && self.sees(world, c, object) && accept(c)
        })
    }

    /// The search of [`Standing::near`], with `fits` in place of the view check.
    fn search(
        &self,
        world: &World,
        object: ObjectId,
        rng: &mut SimRng,
        fits: impl Fn(&BaseConfig) -> bool,
    ) -> Option<BaseConfig> {
        let centre: Vector = world.bodies().aabb(object).center();
        for d in STAND_DISTANCES {
            for _ in 0..STAND_HEADINGS {
                let psi = uniform(rng, -PI, PI);
                let yaw = psi - PI;
                let c = BaseConfig::new(centre.x + d * psi.cos(), centre.y + d * psi.sin(), yaw);
                if indoors(world, &c)
                    && self.clear_at(world, &c)
                    && !self.over(world, &c, object)
                    && fits(&c)
                {
                    return Some(c);
                }
            }
        }
        None
    }
}

/// Whether a base configuration stands in one of the home's rooms (in a world without rooms,
/// anywhere): a place clear beside an outer wall may lie outside the house, where no door
/// leads.
fn indoors(world: &World, c: &BaseConfig) -> bool {
    world.rooms().is_empty() || world.relations().room_at(c.x, c.y).is_some()
}

/// Whether a base configuration stands within `reach` of the object's box across the floor.
fn box_within(world: &World, object: ObjectId, reach: f32) -> impl Fn(&BaseConfig) -> bool {
    let b = world.bodies().aabb(object);
    let (min, max) = ([b.mins.x, b.mins.y], [b.maxs.x, b.maxs.y]);
    move |c| floor_gap(min, max, c.x, c.y) <= reach
}

/// `shape` grown by `margin` on every side (a convex hull, each point pushed out from its
/// centre).
pub fn inflated(shape: &Primitive, margin: f32) -> Primitive {
    match shape {
        Primitive::Box { half_extents } => Primitive::Box {
            half_extents: *half_extents + Vector::splat(margin),
        },
        Primitive::Cylinder {
            radius,
            half_height,
        } => Primitive::Cylinder {
            radius: radius + margin,
            half_height: half_height + margin,
        },
        Primitive::Sphere { radius } => Primitive::Sphere {
            radius: radius + margin,
        },
        Primitive::Capsule {
            radius,
            half_height,
        } => Primitive::Capsule {
            radius: radius + margin,
            half_height: *half_height,
        },
        Primitive::ConvexHull { points } => {
            let centre = points.iter().copied().sum::<Vector>() / points.len().max(1) as f32;
            Primitive::ConvexHull {
                points: points
                    .iter()
                    .map(|&p| p + (p - centre).normalize_or_zero() * margin)
                    .collect(),
            }
        }
    }
}

/// The collision shapes of `objects` as they are now, each placed in the frame that `to_frame`
/// maps the world into: what moves with a base or a hand, for checks at other poses.
pub fn shapes_in(
    world: &World,
    objects: impl IntoIterator<Item = ObjectId>,
    to_frame: Pose,
) -> Vec<(Primitive, Pose)> {
    objects
        .into_iter()
        .flat_map(|id| world.query().collision_parts(id))
        .map(|(shape, pose)| (shape.clone(), to_frame * pose))
        .collect()
}
