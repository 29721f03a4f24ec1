//! Creating the activity's other objects (those not bound to the home) from the object library,
//! sized so that what must go on or in something fits there.
//!
//! Supports and containers are made before what they hold, so a held object can be sized to
//! fit; a container that must hold several is made as large as its kind comes. Every object is
//! parked far away until it is placed, in a random orientation: a random yaw about the vertical
//! and one of its archetype's stable resting orientations (a book flat or on its side, a bottle
//! standing or lying), which placement keeps.

use crate::error::SampleError;
use crate::instance::Created;
use crate::instantiate::Attempt;
use crate::order::target;
use behavior_assets::Archetype;
use behavior_bddl::activity::{Activity, InstanceId, Literal};
use behavior_bddl::ground::Node;
use behavior_bddl::{GroundGoal, Predicate};
use behavior_core::rng::uniform;
use rand_chacha::rand_core::Rng;
use rapier3d::math::{Mat3, Pose, Rotation, Vector};

/// Where objects are to go, as sizing sees it: the init's placement literals and every positive
/// `inside`/`ontop` atom of the ground goal, so that the goal stays reachable too.
struct Demands(Vec<Literal>);

impl Demands {
    fn new(activity: &Activity, kinematic: &[Literal]) -> Demands {
        let goal = GroundGoal::new(activity);
        let mut demands: Vec<Literal> = kinematic.to_vec();
        for node in &goal.nodes {
            if let Node::Lit(lit) = node {
                let atom = goal.atom(lit.atom);
                if lit.positive && matches!(atom.predicate, Predicate::Inside | Predicate::OnTop) {
                    demands.push(Literal {
                        atom,
                        positive: true,
                    });
                }
            }
        }
        demands.sort();
        demands.dedup();
        Demands(demands)
    }

    /// The demands on `i`'s own placement.
    fn of(&self, i: InstanceId) -> impl Iterator<Item = &Literal> {
        self.0.iter().filter(move |l| l.atom.subject == i)
    }

    /// How many objects go inside or on top of `j`.
    fn holds(&self, j: InstanceId) -> usize {
        self.0
            .iter()
            .filter(|l| {
                matches!(l.atom.predicate, Predicate::Inside | Predicate::OnTop)
                    && l.atom.object == Some(j)
            })
            .count()
    }
}

impl Attempt<'_> {
    /// Creates every instance not bound to the home (see the module docs).
    pub(crate) fn create_objects(&mut self) -> Result<(), SampleError> {
        let demands = Demands::new(self.activity, &self.kinematic);
        while let Some(i) = self.next_to_create(&demands) {
            self.create(i, &demands)?;
        }
        Ok(())
    }

    /// The first instance not yet made whose supports and containers (and neighbours) are all
    /// made; failing that, the first not yet made.
    fn next_to_create(&self, demands: &Demands) -> Option<InstanceId> {
        let unmade = || {
            (0..self.bindings.len() as u32)
                .map(InstanceId)
                .filter(|i| self.bindings[i.0 as usize].is_none())
        };
        let made = |l: &Literal| {
            let t = target(l);
            l.atom.predicate == Predicate::OnFloor
                || self.bindings[t.0 as usize].is_some()
                || t == l.atom.subject
        };
        unmade()
            .find(|&i| demands.of(i).all(made))
            .or_else(|| unmade().next())
    }

    /// Draws an archetype, size and variant for `i`, fits the size, and adds it, parked.
    fn create(&mut self, i: InstanceId, demands: &Demands) -> Result<(), SampleError> {
        let instance = self.activity.instance(i);
        let synset = self.activity.category(instance.category).name.clone();
        let (archetype, drawn, variant) = self.library.sample_any(&synset, &mut self.rng)?;
        let resting = archetype.shape.resting_orientations();
        let lying = resting[self.rng.next_u32() as usize % resting.len()];
        let size = self.fitted_size(i, archetype, drawn, demands, lying);
        let mut spec = self
            .library
            .instance_of(archetype, &synset, &instance.name, size, variant);
        let parked = Vector::new(1000.0 + 5.0 * i.0 as f32, 1000.0, 0.0);
        let yaw = Rotation::from_rotation_z(uniform(&mut self.rng, 0.0, std::f32::consts::TAU));
        spec.pose = Pose::from_parts(parked, yaw * lying);
        spec.body = behavior_sim::BodyKind::Dynamic;
        let id = self.world.add(spec).map_err(|cause| SampleError::Add {
            instance: instance.name.clone(),
            cause,
        })?;
        self.bindings[i.0 as usize] = Some(id);
        self.created.push(Created {
            instance: instance.name.clone(),
            synset,
            archetype: archetype.synset.to_string(),
            size: size.to_array(),
            variant,
        });
        Ok(())
    }

    /// The drawn size of `i`, made as large as its kind comes if it must hold three or more,
    /// and shrunk, if need be, so that it fits side by side with everything else on or in what
    /// it goes on or in, standing as `lying` turns it. What goes inside something must fit
    /// across it at any yaw (placement turns it at random), so its diagonal is what counts.
    fn fitted_size(
        &self,
        i: InstanceId,
        archetype: &Archetype,
        drawn: Vector,
        demands: &Demands,
        lying: Rotation,
    ) -> Vector {
        let mut size = drawn;
        if demands.holds(i) >= 3 {
            size = Vector::from_array(archetype.max);
        }
        // The box as it will stand: a resting orientation only swaps its axes.
        let turn = Mat3::from_quat(lying).abs();
        let mut standing = turn * size;
        for l in demands.of(i) {
            let o = target(l);
            let Some(host) = self.bindings[o.0 as usize] else {
                continue;
            };
            let b = self.world.bodies().local_aabb(host);
            let room = b.maxs - b.mins;
            let share = 1.0 / (demands.holds(o) as f32).sqrt().ceil().max(1.0);
            match l.atom.predicate {
                Predicate::Inside => {
                    let across = 0.8 * share * room.x.min(room.y);
                    let diagonal = standing.x.hypot(standing.y);
                    let shrink = (across / diagonal).min(1.0);
                    standing.x *= shrink;
                    standing.y *= shrink;
                    standing.z = standing.z.min(0.4 * room.z);
                }
                Predicate::OnTop => {
                    standing = standing.min(room * Vector::new(0.9 * share, 0.9 * share, 10.0));
                }
                _ => {}
            }
        }
        turn.transpose() * standing
    }
}
