//! Goal feasibility: before an instance is handed out, some goal option's objects are placed for
//! real in a copy of its world, as iGibson does, so that no activity starts unwinnable.

use crate::error::{Literals, SampleError, Unreachable};
use crate::instance::Instance;
use crate::order::placement_order;
use crate::place::{place_by, placement};
use behavior_bddl::activity::{Activity, InstanceId, Literal};
use behavior_bddl::{GroundGoal, Predicate};
use rand_chacha::ChaCha8Rng;
use rapier3d::math::{Pose, Vector};

/// How many goal options (smallest first) [`goal_feasible`] tries before giving up: options
/// grow combinatorially, and the smallest are the likeliest to fit.
pub const FEASIBILITY_OPTIONS: usize = 64;
/// How many of those, having passed the shape test, it places physically (iGibson tries 10):
/// each costs a copy of the world and a placement per moved object.
pub const PHYSICAL_OPTIONS: usize = 10;

/// Checks that some goal option can be reached in this home: every object in a positive
/// `ontop`, `inside`, `under`, `nextto`, `touching` or `onfloor` literal of the option can be
/// placed as it asks.
///
/// Options are tried smallest first, leaving out those that relate an object to itself. Each
/// must first pass a shape test — nothing on, in or under two things that stay too far apart for
/// it to reach both, inside a container whose box can hold its box (in some orientation), on a
/// support whose widest side is at least its narrowest, under something whose largest side is
/// at least its smallest — and then the first [`PHYSICAL_OPTIONS`] that do are placed for real in
/// a copy of the world: the objects the option moves are lifted out, then put back in the same
/// dependency order the initial state is placed in, each by all its literals at once, among the
/// objects that stay. The error reports why the first option failed.
pub fn goal_feasible(
    activity: &Activity,
    instance: &Instance,
    rng: &mut ChaCha8Rng,
) -> Result<(), SampleError> {
    // No object is on, in, under, next to or touching itself: options asking so are skipped.
    let goal = GroundGoal::new(activity).assuming_false(|atom| atom.object == Some(atom.subject));
    let mut check = GoalCheck {
        activity,
        instance,
        rng,
    };
    let mut first_failure: Option<Failure> = None;
    let mut physical = 0;
    for option in behavior_bddl::options::options(&goal).take(FEASIBILITY_OPTIONS) {
        let outcome = match check.shape_test(&option) {
            Err(failure) => Err(failure),
            Ok(()) if physical < PHYSICAL_OPTIONS => {
                physical += 1;
                check.place_option(&option)
            }
            Ok(()) => continue,
        };
        match outcome {
            Ok(()) => return Ok(()),
            Err(failure) => {
                first_failure.get_or_insert(failure);
            }
        }
    }
    match first_failure {
        Some(failure) => Err(SampleError::Infeasible {
            literals: Literals::of(activity, &failure.literals),
            why: failure.why,
        }),
        None => Err(SampleError::NoGoalOption),
    }
}

/// Why an option failed: its literals at fault, as the goal writes them, and the reason.
struct Failure {
    literals: Vec<Literal>,
    why: Unreachable,
}

/// The goal check of one instance.
struct GoalCheck<'a> {
    activity: &'a Activity,
    instance: &'a Instance,
    rng: &'a mut ChaCha8Rng,
}

impl GoalCheck<'_> {
    /// An instance's extents in the instance's world, smallest first.
    fn dims(&self, i: InstanceId) -> [f32; 3] {
        let b = self
            .instance
            .world
            .bodies()
            .aabb(self.instance.bindings[i.0 as usize]);
        let mut d = (b.maxs - b.mins).to_array();
        d.sort_by(f32::total_cmp);
        d
    }

    /// The first positive literal of `option` that cannot hold by the objects' shapes alone
    /// (see [`goal_feasible`]).
    fn shape_test(&self, option: &[Literal]) -> Result<(), Failure> {
        let misfit = option
            .iter()
            .filter(|l| l.positive)
            .find_map(|l| Some((*l, self.misfit(option, l)?)));
        match misfit {
            None => Ok(()),
            Some((literal, why)) => Err(Failure {
                literals: vec![literal],
                why,
            }),
        }
    }

    /// Why the positive literal `l` of `option` cannot hold by shapes, if it cannot.
    fn misfit(&self, option: &[Literal], l: &Literal) -> Option<Unreachable> {
        let subject = l.atom.subject;
        let target = l.atom.object?;
        let (a, b) = (self.dims(subject), self.dims(target));
        let support = |o: &&Literal| {
            matches!(
                o.atom.predicate,
                Predicate::OnTop | Predicate::Inside | Predicate::Under
            ) && o.positive
                && o.atom.subject == subject
        };
        let torn = || {
            option
                .iter()
                .filter(support)
                .filter_map(|o| o.atom.object)
                .any(|other| self.apart(option, subject, (target, other)))
        };
        match l.atom.predicate {
            Predicate::OnTop | Predicate::Inside | Predicate::Under if torn() => {
                Some(Unreachable::TwoPlaces)
            }
            Predicate::Inside if (0..3).any(|k| a[k] > 0.95 * b[k]) => {
                Some(Unreachable::DoesNotFit {
                    object: a,
                    container: b,
                })
            }
            Predicate::OnTop if a[0] > b[2] => Some(Unreachable::TooWide {
                side: a[0],
                widest: b[2],
            }),
            Predicate::Under if a[0] > b[2] => Some(Unreachable::TooLarge),
            _ => None,
        }
    }

    /// Whether `subject` is to go on, in or under both `target` and `other`, which both stay
    /// where they are (the option moves neither), though they stand too far apart for it to
    /// reach both.
    fn apart(
        &self,
        option: &[Literal],
        subject: InstanceId,
        (target, other): (InstanceId, InstanceId),
    ) -> bool {
        let moved = |i: InstanceId| option.iter().any(|l| l.positive && l.atom.subject == i);
        let world = &self.instance.world;
        let (t, o) = (
            world
                .bodies()
                .aabb(self.instance.bindings[target.0 as usize]),
            world
                .bodies()
                .aabb(self.instance.bindings[other.0 as usize]),
        );
        let gap = (t.mins - o.maxs).max(o.mins - t.maxs).max(Vector::ZERO);
        !moved(target) && !moved(other) && gap.x.hypot(gap.y) > self.dims(subject)[2]
    }

    /// Places a goal option's positive placement literals in a copy of the instance's world.
    fn place_option(&mut self, option: &[Literal]) -> Result<(), Failure> {
        let placements: Vec<Literal> = option
            .iter()
            .filter(|l| placement(l).is_some())
            .copied()
            .collect();
        let stays: Vec<bool> = (0..self.activity.instances.len() as u32)
            .map(|i| !placements.iter().any(|l| l.atom.subject == InstanceId(i)))
            .collect();
        let steps = placement_order(&placements, &stays);
        let bindings = &self.instance.bindings;
        // What the goal moves is lifted out first, so it does not stand in its own way; an
        // object whose literals were all handed on stays where it is, for the others to come
        // to it.
        let mut world = self.instance.world.clone();
        for (k, step) in steps.iter().enumerate() {
            if step.literals.is_empty() {
                continue;
            }
            let id = bindings[step.subject.0 as usize];
            let parked = Pose::from_parts(
                Vector::new(-2000.0 - 5.0 * k as f32, -2000.0, 0.0),
                world.bodies().pose(id).rotation,
            );
            world
                .bodies_mut()
                .set_pose(id, parked)
                .map_err(|e| Failure {
                    literals: step.written().copied().collect(),
                    why: Unreachable::Lift(e),
                })?;
        }
        for step in steps.iter().filter(|s| !s.literals.is_empty()) {
            place_by(&mut world, bindings, step, self.rng).map_err(|e| Failure {
                literals: step.written().copied().collect(),
                why: Unreachable::Placement(e),
            })?;
        }
        Ok(())
    }
}
