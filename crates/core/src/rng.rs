//! Seeded randomness: one generator type for the whole project, and one way to draw floats from it.
//!
//! Everything random in a simulation (home layouts, object sizes, poses, particles) comes from a
//! [`SimRng`] made from a seed and passed down, so that the same seed gives bit-identical worlds
//! in every process. Floats are drawn by [`uniform`] from 24 random bits, which every platform
//! turns into the same `f32`.

use rand_chacha::rand_core::{Rng, SeedableRng};

/// The project's random generator: ChaCha with 8 rounds, fast and identical on every platform.
pub type SimRng = rand_chacha::ChaCha8Rng;

/// A generator seeded from a number.
pub fn seeded(seed: u64) -> SimRng {
    SimRng::seed_from_u64(seed)
}

/// A uniform draw in `[lo, hi)` from 24 random bits (`lo` when the range is empty).
///
/// ```
/// let mut rng = behavior_core::rng::seeded(7);
/// let x = behavior_core::rng::uniform(&mut rng, 1.0, 2.0);
/// assert!((1.0..2.0).contains(&x));
/// assert_eq!(x, behavior_core::rng::uniform(&mut behavior_core::rng::seeded(7), 1.0, 2.0));
/// ```
pub fn uniform(rng: &mut SimRng, lo: f32, hi: f32) -> f32 {
    let unit = (rng.next_u32() >> 8) as f32 / (1u32 << 24) as f32;
    lo + (hi - lo) * unit
}
