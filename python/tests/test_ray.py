"""behavior.ray on a local Ray instance with 2 workers."""

import numpy as np
import pytest
import ray

import behavior.ray as behavior_ray
from behavior import BehaviorVecEnv

ACTIVITY = "bringing_in_wood"


@pytest.fixture(scope="module", autouse=True)
def local_ray():
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def test_rollouts_on_two_workers_are_what_a_local_run_gives():
    results = behavior_ray.rollouts(ACTIVITY, steps=10, num_workers=2, seed=3, max_steps=50)
    assert len(results) == 2
    assert results[0]["rewards"].shape == (10, 1) and results[0]["q"].shape == (10, 1)
    # Worker 1 was reset with seed 4 and drew its random actions from it: the same here.
    envs = BehaviorVecEnv(ACTIVITY, num_envs=1, max_steps=50)
    obs, _ = envs.reset(seed=4)
    rng = np.random.default_rng(4)
    for _ in range(10):
        actions = rng.uniform(envs.action_space.low, envs.action_space.high).astype(np.float32)
        obs, *_ = envs.step(actions)
    assert obs["task_obs"].tobytes() == results[1]["last_task_obs"].tobytes()
    assert results[0]["last_task_obs"].tobytes() != results[1]["last_task_obs"].tobytes()


def test_evaluation_spreads_episodes_over_two_workers():
    report = behavior_ray.evaluate(ACTIVITY, episodes=3, num_workers=2, seed=5, max_steps=4)
    assert [e["seed"] for e in report["episodes"]] == [5, 6, 7]
    assert all(e["steps"] == 4 for e in report["episodes"])
    assert report["success_rate"] == 0.0 and 0.0 <= report["mean_q"] <= 1.0


def test_a_policy_is_called_with_batched_observations():
    def still(obs):
        return np.zeros((obs["task_obs"].shape[0], 26), dtype=np.float32)

    results = behavior_ray.rollouts(ACTIVITY, steps=3, num_workers=2, envs_per_worker=2,
                                    seed=0, policy=still)
    assert results[1]["q"].shape == (3, 2)
