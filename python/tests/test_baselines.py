"""The baselines: short runs of PPO (plain and masked, state and images) and SAC that complete
and leave what a run leaves, and the instance every training episode starts from."""

import csv
import json

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from behavior.baselines import ppo, sac, table1  # noqa: E402
from behavior.baselines.training import TrainConfig, make_env  # noqa: E402


def _check_run(config, result):
    saved = json.loads((config.out / "result.json").read_text())
    assert saved == result
    assert 0.0 <= result["q"] <= 1.0 and 0.0 <= result["success_rate"] <= 1.0
    with open(config.out / "curve.csv") as f:
        rows = list(csv.DictReader(f))
    assert rows, "training ended episodes"
    steps = [int(r["timesteps"]) for r in rows]
    assert steps == sorted(steps) and steps[-1] <= config.timesteps
    assert all(0.0 <= float(r["q"]) <= 1.0 for r in rows)
    assert (config.out / "model.zip").stat().st_size > 0
    assert (config.out / "progress.csv").is_file(), "SB3 logs into the run's folder"


@pytest.mark.parametrize("masked", [False, True])
def test_ppo_on_primitives_completes(tmp_path, masked):
    config = TrainConfig("bringing_in_wood", "ap_nophys_fullobs", timesteps=512, horizon=20,
                         masked=masked, out=tmp_path)
    _check_run(config, ppo.train(config))


def test_ppo_sees_images_through_the_cnn(tmp_path):
    config = TrainConfig("bringing_in_wood", "ap_nophys", timesteps=256, horizon=20,
                         image_size=64, out=tmp_path)
    result = ppo.train(config)
    _check_run(config, result)
    from stable_baselines3 import PPO

    model = PPO.load(config.out / "model.zip", device="cpu")
    extractor = model.policy.features_extractor
    assert sorted(extractor.parts) == ["depth", "proprioception", "rgb"]
    assert extractor.features_dim == 3 * 128


def test_sac_on_continuous_actions_completes(tmp_path):
    config = TrainConfig("bringing_in_wood", "ca_fullobs", timesteps=1100, horizon=100,
                         out=tmp_path)
    _check_run(config, sac.train(config))


def test_each_algorithm_refuses_the_other_action_space(tmp_path):
    with pytest.raises(ValueError, match="use sac"):
        ppo.train(TrainConfig("bringing_in_wood", "ca_fullobs", out=tmp_path))
    with pytest.raises(ValueError, match="use ppo"):
        sac.train(TrainConfig("bringing_in_wood", "ap_nophys_fullobs", out=tmp_path))


def test_every_training_episode_starts_from_the_same_instance():
    env = make_env(TrainConfig("storing_food", "ap_nophys_fullobs", instance=3))
    first, _ = env.reset()
    rng = np.random.default_rng(0)
    for _ in range(3):
        for _ in range(5):
            mask = env.get_wrapper_attr("action_masks")()
            env.step(int(rng.choice(np.flatnonzero(mask))))
        again, info = env.reset()
        assert info["steps"] == 0
        for key in first:
            np.testing.assert_array_equal(again[key], first[key])


def test_the_table_puts_ours_beside_the_papers():
    results = {a: [{"q": 0.5, "wall_s": 10.0}, {"q": 1.0, "wall_s": 20.0}]
               for a in table1.ACTIVITIES}

    class Args:
        row = "ap_nophys_fullobs"
        seeds = [0, 1]

    markdown = table1.table(Args, results)
    assert "| bringing_in_wood | 1.00 | 0.75 | 0.50 1.00 | 15 |" in markdown
    assert "| **mean** | 0.63 | 0.75 | | |" in markdown
    results["storing_food"] = []
    partial = table1.table(Args, results)
    assert "| storing_food | 1.00 | not run yet | | |" in partial
    assert "| **mean of the 11 run** | 0.60 | 0.75 | | |" in partial
