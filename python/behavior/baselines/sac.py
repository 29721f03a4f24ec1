"""SAC on the robot's continuous actions (Stable-Baselines3), the original's network
(``BehaviorExtractor``) in front of the actor and critics.
``python -m behavior.baselines.sac ACTIVITY --row ca_fullobs --seed 0``."""

import sys

from . import training
from .rows import row

# Stable-Baselines3's defaults but for the replay buffer, sized for a CPU machine's memory: a
# stored image observation (128² RGB-D) and its successor take ~230 kB.
HYPERPARAMETERS = {
    "learning_rate": 3e-4,
    "batch_size": 256,
    "learning_starts": 1000,
    "gamma": 0.99,
    "train_freq": 1,
    "gradient_steps": 1,
}
BUFFER_STATE = 200_000
BUFFER_IMAGES = 10_000


def model(env, seed: int, images: bool):
    """SAC over `env` (a vectorized environment) with the original's network in front,
    `HYPERPARAMETERS`, the replay buffer sized for what is observed, on the CPU."""
    from stable_baselines3 import SAC

    return SAC(
        "MultiInputPolicy",
        env,
        policy_kwargs=training.policy_kwargs(),
        buffer_size=BUFFER_IMAGES if images else BUFFER_STATE,
        seed=seed,
        device="cpu",
        verbose=0,
        **HYPERPARAMETERS,
    )


def train(config: training.TrainConfig) -> dict:
    """Trains SAC for the run; returns its result (also written to its folder)."""
    spec = row(config.row)
    if spec.action_space != "continuous":
        raise ValueError(f"SAC trains the continuous rows; {config.row} is primitives (use ppo)")
    training.set_threads(config)
    images = "rgb" in spec.observations or "depth" in spec.observations
    return training.learn(model(training.vector_env(config), config.seed, images), config, "sac")


def main(argv=None) -> int:
    p = training.parser(__doc__)
    p.set_defaults(row="ca_fullobs")
    config = training.config_from(p.parse_args(argv), "sac")
    print(training.summary_line(config, train(config)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
