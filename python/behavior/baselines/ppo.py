"""PPO on the primitive action space (Stable-Baselines3; sb3-contrib's MaskablePPO with
``--masked``), the original's network (``BehaviorExtractor``) in front of the policy and value
heads. ``python -m behavior.baselines.ppo ACTIVITY --row ap_nophys_fullobs --seed 0``."""

import sys

from . import training
from .rows import row

# Stable-Baselines3's defaults but for a shorter rollout (episodes are at most 50 primitives)
# and a little entropy to keep trying primitives that fail at first.
HYPERPARAMETERS = {
    "n_steps": 256,
    "batch_size": 64,
    "n_epochs": 10,
    "learning_rate": 3e-4,
    "gamma": 0.99,
    "ent_coef": 0.01,
}


def train(config: training.TrainConfig) -> dict:
    """Trains PPO for the run; returns its result (also written to its folder)."""
    if row(config.row).action_space != "primitives":
        raise ValueError(f"PPO trains the primitive rows; {config.row} is continuous (use sac)")
    training.set_threads(config)
    if config.masked:
        from sb3_contrib import MaskablePPO as Algorithm
    else:
        from stable_baselines3 import PPO as Algorithm
    model = Algorithm(
        "MultiInputPolicy",
        training.vector_env(config),
        policy_kwargs=training.policy_kwargs(),
        seed=config.seed,
        device="cpu",
        verbose=0,
        **HYPERPARAMETERS,
    )
    return training.learn(model, config, "maskable_ppo" if config.masked else "ppo")


def main(argv=None) -> int:
    p = training.parser(__doc__)
    p.add_argument("--masked", action="store_true",
                   help="MaskablePPO: only feasible primitives are chosen")
    config = training.config_from(p.parse_args(argv), "ppo")
    print(training.summary_line(config, train(config)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
