"""The vector environment's semantics: batched shapes, Gymnasium 1.x autoreset (next step),
seeding, determinism, bad input."""

import gymnasium
import numpy as np
import pytest

import behavior

ACTIVITY = "bringing_in_wood"


def test_four_environments_step_with_batched_arrays():
    envs = behavior.make_vec(ACTIVITY, num_envs=4, max_steps=50)
    obs, info = envs.reset(seed=0)
    assert obs["task_obs"].shape == (4, 456) and obs["proprioception"].shape == (4, 22)
    assert envs.action_space.shape == (4, 26)
    for _ in range(3):
        obs, rewards, terminated, truncated, info = envs.step(envs.action_space.sample())
    assert rewards.shape == terminated.shape == truncated.shape == (4,)
    assert list(info["steps"]) == [3, 3, 3, 3] and info["_q"].all()
    assert obs in envs.observation_space


def test_made_through_gymnasium_make_vec():
    envs = gymnasium.make_vec(
        f"behavior/{ACTIVITY}-v0", num_envs=2, vectorization_mode="vector_entry_point",
        robot="fetch",
    )
    obs, _ = envs.reset(seed=1)
    assert obs["proprioception"].shape == (2, 49)
    assert envs.single_action_space.shape == (11,)


def test_environment_k_is_the_single_environment_seeded_seed_plus_k():
    envs = behavior.make_vec(ACTIVITY, num_envs=2)
    batched, _ = envs.reset(seed=10)
    for k in range(2):
        single = behavior.BehaviorEnv(ACTIVITY)
        obs, _ = single.reset(seed=10 + k)
        assert obs["task_obs"].tobytes() == batched["task_obs"][k].tobytes()
    # Neighbouring seeds sample different instances.
    assert batched["task_obs"][0].tobytes() != batched["task_obs"][1].tobytes()


def test_an_ended_episode_resets_on_the_next_step():
    envs = behavior.make_vec(ACTIVITY, num_envs=2, max_steps=3)
    first, _ = envs.reset(seed=4)
    zeros = np.zeros((2, 26), dtype=np.float32)
    for _ in range(2):
        _, _, terminated, truncated, _ = envs.step(zeros)
        assert not truncated.any() and not terminated.any()
    _, _, terminated, truncated, info = envs.step(zeros)
    assert truncated.all() and list(info["steps"]) == [3, 3]
    # The next step ignores the actions and starts new episodes.
    obs, rewards, terminated, truncated, info = envs.step(np.full((2, 26), 0.5, np.float32))
    assert list(info["steps"]) == [0, 0]
    assert not rewards.any() and not terminated.any() and not truncated.any()
    # Their seeds are new: not the first episodes again.
    assert obs["task_obs"].tobytes() != first["task_obs"].tobytes()


def test_same_seed_and_actions_give_identical_runs_through_autoresets():
    actions = np.random.default_rng(5).uniform(-1, 1, size=(8, 2, 26)).astype(np.float32)
    traces = []
    for _ in range(2):
        envs = behavior.make_vec(ACTIVITY, num_envs=2, max_steps=3)
        obs, _ = envs.reset(seed=2)
        trace = [obs["task_obs"].tobytes()]
        for a in actions:
            obs, rewards, *_ = envs.step(a)
            trace += [obs["task_obs"].tobytes(), obs["proprioception"].tobytes(), rewards.tobytes()]
        traces.append(trace)
    assert traces[0] == traces[1]


def test_bad_input_raises():
    envs = behavior.make_vec(ACTIVITY, num_envs=2)
    envs.reset(seed=0)
    with pytest.raises(ValueError, match=r"shape \(2, 26\)"):
        envs.step(np.zeros((3, 26), dtype=np.float32))
    nan = np.zeros((2, 26), dtype=np.float32)
    nan[1, 4] = np.nan
    with pytest.raises(ValueError, match=r"\[1, 4\] is NaN"):
        envs.step(nan)
    # Neither environment stepped.
    _, _, _, _, info = envs.step(np.zeros((2, 26), dtype=np.float32))
    assert list(info["steps"]) == [1, 1]
    with pytest.raises(ValueError, match=r"actions must have shape \(2, 26\)"):
        envs.unwrapped._env.step(np.zeros((2, 5), dtype=np.float32))
    with pytest.raises(ValueError, match="one integer"):
        envs.reset(seed=[1, 2])
    with pytest.raises(ValueError, match="at least 1"):
        behavior.make_vec(ACTIVITY, num_envs=0)


def test_vector_observes_images_batched():
    envs = behavior.make_vec(ACTIVITY, num_envs=2, observations=["rgb", "proprioception"],
                             image_size=32)
    obs, _ = envs.reset(seed=0)
    assert obs["rgb"].shape == (2, 32, 32, 3) and obs["rgb"].dtype == np.uint8
    assert envs.single_observation_space["rgb"].shape == (32, 32, 3)
    obs, *_ = envs.step(envs.action_space.sample())
    assert obs in envs.observation_space
