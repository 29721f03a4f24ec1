//! Built-in agents for baselines and benchmarks: one that does nothing, one that acts at random.

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{Rng, SeedableRng};

/// A policy that needs no observation.
#[derive(Clone, Debug)]
pub enum Agent {
    /// Every action all zeros: the robot holds still (the original's speed benchmark agent).
    Idle,
    /// Every value uniform in [−1, 1], from a generator seeded once.
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

    /// Its next action of `dim` values, written into `out`.
    pub fn act(&mut self, dim: usize, out: &mut Vec<f32>) {
        out.clear();
        match self {
            Agent::Idle => out.resize(dim, 0.0),
            Agent::Random(rng) => out.extend((0..dim).map(|_| {
                // 24 random bits, exactly representable: a value in [−1, 1).
                (rng.next_u32() >> 8) as f32 / (1u32 << 23) as f32 - 1.0
            })),
        }
    }
}
