//! Where a step's time goes, split as the original's speed benchmark reports it (iGibson's speed
//! benchmark, `envs/benchmark_env.py`): physics (the substeps with the robot's control), the state
//! rules (non-physics), the goal check with the metrics, and the observations.

use behavior_sim::{StepHooks, World};
use std::time::{Duration, Instant};

/// Accumulated step times.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepTimings {
    /// Steps measured.
    pub steps: u32,
    /// Physics substeps and the robot's control.
    pub physics: Duration,
    /// The state rules (heat, water, dirt, slicing, toggling).
    pub rules: Duration,
    /// Q (the goal check) and the metrics.
    pub scoring: Duration,
    /// The observations (proprioception, `task_obs`, sensors).
    pub observing: Duration,
    /// The whole steps.
    pub total: Duration,
}

impl StepTimings {
    /// Adds a step: physics, rules, scoring and observing times, and the whole step's.
    pub(crate) fn add(&mut self, parts: [Duration; 4], total: Duration) {
        self.steps += 1;
        self.physics += parts[0];
        self.rules += parts[1];
        self.scoring += parts[2];
        self.observing += parts[3];
        self.total += total;
    }
}

/// The robot's hooks, with clocks read at the end of the physics and of the state rules.
pub(crate) struct Timed<'a, H: StepHooks> {
    hooks: &'a mut H,
    start: Instant,
    physics_done: Option<Instant>,
    rules_done: Option<Instant>,
}

impl<'a, H: StepHooks> Timed<'a, H> {
    pub(crate) fn new(hooks: &'a mut H, start: Instant) -> Self {
        Timed {
            hooks,
            start,
            physics_done: None,
            rules_done: None,
        }
    }

    /// (physics, rules) of the step just taken.
    pub(crate) fn split(&self) -> (Duration, Duration) {
        let end = self.rules_done.unwrap_or_else(Instant::now);
        let physics_done = self.physics_done.unwrap_or(end);
        (physics_done - self.start, end - physics_done)
    }
}

impl<H: StepHooks> StepHooks for Timed<'_, H> {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        self.hooks.before_substep(world, substep);
    }

    fn after_physics(&mut self, world: &mut World) {
        self.hooks.after_physics(world);
        self.physics_done = Some(Instant::now());
    }

    fn after_step(&mut self, world: &mut World) {
        self.rules_done = Some(Instant::now());
        self.hooks.after_step(world);
    }
}
