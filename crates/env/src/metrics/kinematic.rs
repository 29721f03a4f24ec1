//! Kinematic disarrangement (iGibson 2.0.3's `metrics/`): how far the home's objects moved.
//!
//! Every movable object but the robot's parts and the agent's stand-in is followed by the
//! position of its origin. Per step: the sum of the distances moved. Integrated: the sum of the
//! per-step values. Relative (what the benchmark reports): the sum of the distances between
//! where each object is now and where it was at the start. A sliced object's halves take over
//! from the whole: each half's first step is measured from the whole's last position and its
//! relative distance from the whole's start; the whole then drops out.

use behavior_sim::{ObjectId, World};
use rapier3d::math::Vector;

/// One followed object: where it started and where it was last step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
struct Followed {
    id: ObjectId,
    start: Vector,
    last: Vector,
    /// The world's motion count of the object when last read: unchanged, it has not moved.
    motion: u64,
}

/// The running kinematic disarrangement of an episode.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub(crate) struct Kinematic {
    followed: Vec<Followed>,
    /// Objects the world had when last looked at (new ones may be halves).
    seen: usize,
    pub(crate) integrated: f64,
}

impl Kinematic {
    /// Starts following every movable object of `world` but `ignored`.
    pub(crate) fn start(world: &World, ignored: &[ObjectId]) -> Kinematic {
        let followed = world
            .bodies()
            .objects()
            .filter(|(id, o)| !o.is_fixed() && o.is_present() && !ignored.contains(id))
            .map(|(id, _)| {
                let at = world.bodies().pose(id).translation;
                Followed {
                    id,
                    start: at,
                    last: at,
                    motion: world.bodies().motion(id),
                }
            })
            .collect();
        Kinematic {
            followed,
            seen: world.bodies().objects().len(),
            integrated: 0.0,
        }
    }

    /// Measures one step; returns its disarrangement, m.
    pub(crate) fn step(&mut self, world: &World) -> f64 {
        self.adopt_halves(world);
        let mut moved = 0.0;
        for f in &mut self.followed {
            let motion = world.bodies().motion(f.id);
            if motion == f.motion {
                continue;
            }
            f.motion = motion;
            let now = world.bodies().pose(f.id).translation;
            moved += f64::from((now - f.last).length());
            f.last = now;
        }
        self.integrated += moved;
        moved
    }

    /// The relative disarrangement: Σ ‖now − start‖, m.
    pub(crate) fn relative(&self) -> f64 {
        self.followed
            .iter()
            .map(|f| f64::from((f.last - f.start).length()))
            .sum()
    }

    /// Objects added since the last look that are halves of a followed whole replace it.
    fn adopt_halves(&mut self, world: &World) {
        let count = world.bodies().objects().len();
        if count == self.seen {
            return;
        }
        self.seen = count;
        let mut followed = Vec::with_capacity(self.followed.len() + 2);
        for f in self.followed.drain(..) {
            match world.bodies().object(f.id).replaced_by {
                Some(halves) if !world.bodies().object(f.id).is_present() => {
                    followed.extend(halves.map(|id| Followed { id, ..f }));
                }
                _ => followed.push(f),
            }
        }
        self.followed = followed;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{ObjectSpec, Part, Primitive};
    use rapier3d::math::Pose;

    fn block(world: &mut World, name: &str, x: f32) -> ObjectId {
        let shape = Primitive::Box {
            half_extents: Vector::splat(0.05),
        };
        let spec = ObjectSpec::new(name, "block.n.01", vec![Part::new(shape)])
            .at(Vector::new(x, 0.0, 2.0));
        world.add(spec).unwrap()
    }

    #[test]
    fn moves_are_summed_per_step_integrated_and_measured_from_the_start() {
        let mut world = World::default();
        world.bodies_mut().set_sleeping_allowed(false);
        let a = block(&mut world, "a", 0.0);
        let ignored = block(&mut world, "robot", 5.0);
        let mut k = Kinematic::start(&world, &[ignored]);
        // Teleported 3-4-5 away and back halfway, with gravity off by holding it in place.
        let at = |x: f32, y: f32| Pose::from_translation(Vector::new(x, y, 2.0));
        world.bodies_mut().set_pose(a, at(0.3, 0.4)).unwrap();
        world.bodies_mut().set_pose(ignored, at(9.0, 0.0)).unwrap();
        let first = k.step(&world);
        world.bodies_mut().set_pose(a, at(0.0, 0.4)).unwrap();
        let second = k.step(&world);
        assert!((first - 0.5).abs() < 1e-6, "{first}");
        assert!((second - 0.3).abs() < 1e-6, "{second}");
        assert!((k.integrated - 0.8).abs() < 1e-6);
        assert!((k.relative() - 0.4).abs() < 1e-6, "{}", k.relative());
    }
}
