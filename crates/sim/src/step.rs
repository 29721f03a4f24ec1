//! One action step, and the hooks for code that must run inside it.
//!
//! [`World::step_with`] runs, in this order:
//!
//! 1. for each physics substep (10 of 1/300 s, or 4 of 1/120 s):
//!    - [`StepHooks::before_substep`]: controllers set drives, velocities, forces and kinematic
//!      targets (MuJoCo's `mj_step1`, where controls are computed from the current state);
//!    - the physics substep (rapier), skipping contacts between ignored pairs;
//!    - the world watches the substep: slicers' contact impulses (summed over the step),
//!      attachments' forces (breaking those past their maximum);
//! 2. objects that moved are marked, which invalidates their memoized relations;
//! 3. the state rules, in the order [`crate::states`] documents (water, toggling, temperature,
//!    cleaning, slicing);
//! 4. forces applied for the step are cleared, the step count advances;
//! 5. [`StepHooks::after_step`]: code that needs the finished step (assisted grasping deciding to
//!    release, metrics, recording) — like MuJoCo's `mj_step2` callbacks or rapier's event
//!    handlers.
//!
//! While every body sleeps and nothing changed, the physics is skipped: `before_substep` is
//! called once (a controller may wake something), and if all is still at rest the step's
//! substeps are skipped, since they would change nothing.

use crate::World;
use crate::contacts::ContactFilter;
use crate::core::STEP_SECONDS;
use crate::object::ObjectId;
use crate::states::slicing::{SlicerPush, slicer_impulses};

/// Code run inside [`World::step_with`]; see the module docs for when. Both methods do nothing by
/// default, and `()` implements the trait for a step without hooks.
pub trait StepHooks {
    /// Before each physics substep; `substep` counts from 0.
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        let _ = (world, substep);
    }

    /// After the step's last physics substep, before its state rules (for timing, or for
    /// reading contacts as the solver left them).
    fn after_physics(&mut self, world: &mut World) {
        let _ = world;
    }

    /// After the state rules of the step.
    fn after_step(&mut self, world: &mut World) {
        let _ = world;
    }
}

impl StepHooks for () {}

impl World {
    /// Advances one action step (1/30 s) with no hooks.
    ///
    /// ```
    /// use behavior_sim::{ObjectSpec, Part, Primitive, World};
    /// use rapier3d::math::Vector;
    ///
    /// let mut world = World::default();
    /// let slab = Primitive::Box { half_extents: Vector::new(0.5, 0.5, 0.05) };
    /// let table = world.add(ObjectSpec::new("table_1", "table.n.02", vec![Part::new(slab)]).fixed()).unwrap();
    /// let ball = Primitive::Sphere { radius: 0.04 };
    /// let apple = world.add(ObjectSpec::new("apple_1", "apple.n.01", vec![Part::new(ball)]).at(Vector::new(0.0, 0.0, 0.3))).unwrap();
    /// for _ in 0..60 {
    ///     world.step();
    /// }
    /// assert!(world.relations().ontop(apple, table));
    /// assert_eq!(world.bodies().steps(), 60);
    /// ```
    pub fn step(&mut self) {
        self.step_with(&mut ());
    }

    /// Advances one action step, running `hooks` inside it (see the module docs).
    pub fn step_with(&mut self, hooks: &mut dyn StepHooks) {
        let pressed = self.substeps(hooks);
        hooks.after_physics(self);
        self.core.bodies.note_motion();
        self.systems.update(&mut self.core, STEP_SECONDS);
        for id in pressed {
            // A sliceable object always accepts slicing; an error here would be a bug in add().
            let _ = self.set_sliced(id, true);
        }
        self.core.bodies.clear_forces();
        self.core.bodies.steps += 1;
        hooks.after_step(self);
    }

    /// The physics substeps; returns the objects slicers pressed hard enough, in id order.
    fn substeps(&mut self, hooks: &mut dyn StepHooks) -> Vec<ObjectId> {
        let mut push = SlicerPush::default();
        for substep in 0..self.core.bodies.substeps.count() {
            hooks.before_substep(self, substep);
            if substep == 0 && self.core.bodies.quiet {
                return Vec::new();
            }
            let core = &mut self.core;
            core.attachments.note_drift(&core.bodies, substep);
            let bodies = &mut core.bodies;
            bodies.lead_kinematic_chains();
            let filter = ContactFilter {
                ignored: &core.ignored,
            };
            bodies.physics.step_with_events(&filter, &());
            bodies.restore_sleep_times();
            bodies.index.clear_moving();
            core.attachments.watch(bodies);
            push.add(slicer_impulses(bodies));
        }
        let bodies = &mut self.core.bodies;
        bodies.quiet = bodies.physics.islands.num_active_bodies() == 0;
        push.pressed(STEP_SECONDS)
    }

    /// Steps until every body sleeps or `max_steps` have passed; whether the world came to rest.
    pub fn settle(&mut self, max_steps: usize) -> bool {
        for _ in 0..max_steps {
            self.step();
            if self.core.bodies.quiet {
                return true;
            }
        }
        false
    }
}
