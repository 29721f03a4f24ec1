//! Built-in agents for baselines and benchmarks: one that does nothing, one that acts at random.

use crate::Env;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};

/// A policy that needs no observation.
#[derive(Clone, Debug)]
pub enum Agent {
    /// Every action the robot's still one (all zeros for the BehaviorRobot and Fetch; the
    /// joints' present positions for the R1): the original's speed benchmark agent.
    Idle,
    /// Every value uniform within its bounds ([−1, 1], or a joint's limits where the value is
    /// its position), from a generator seeded once.
    Random(Box<ChaCha8Rng>),
}

impl Agent {
    /// The agent called `name` (`idle` or `random`), seeded with `seed` where it draws.
    pub fn named(name: &str, seed: u64) -> Option<Agent> {
        match name {
            "idle" => Some(Agent::Idle),
            "random" => Some(Agent::Random(Box::new(ChaCha8Rng::seed_from_u64(seed)))),
            _ => None,
        }
    }

    /// Its name.
    pub fn name(&self) -> &'static str {
        match self {
            Agent::Idle => "idle",
            Agent::Random(_) => "random",
        }
    }

    /// Its next action for the robot of `env`, written into `out` (nothing without a robot).
    pub fn act(&mut self, env: &Env, out: &mut Vec<f32>) {
        out.clear();
        let Some(robot) = env.robot() else {
            return;
        };
        match self {
            Agent::Idle => out.extend(robot.still_action(robot.space())),
            Agent::Random(rng) => out.extend(robot.action_bounds().into_iter().map(|[lo, hi]| {
                // 24 random bits, exactly representable: a fraction in [0, 1). For [−1, 1]
                // this is −1 + bits / 2^23, exactly.
                let unit = (rng.next_u32() >> 8) as f32 / (1u32 << 24) as f32;
                lo + (hi - lo) * unit
            })),
        }
    }
}
