"""The Gymnasium environments, as a user meets them: made by id, checked by Gymnasium's own
checker, stepped, fed bad input."""

import threading
import time

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import behavior

ACTIVITY = "bringing_in_wood"


def make(robot="behavior", **kwargs):
    return gymnasium.make(f"behavior/{ACTIVITY}-v0", robot=robot, **kwargs)


def test_every_official_activity_is_registered():
    names = behavior.activities()
    assert len(names) == 100
    for name in names:
        assert f"behavior/{name}-v0" in gymnasium.registry


@pytest.mark.parametrize(
    "robot,dim,proprioception", [("behavior", 26, 22), ("fetch", 11, 49), ("r1", 23, 57)]
)
def test_check_env_passes_with_each_robot(robot, dim, proprioception):
    env = make(robot)
    assert env.action_space.shape == (dim,)
    if robot == "r1":
        # Joint positions within their limits: the torso's first joint -1.1345..1.8326 rad.
        assert env.action_space.low[3] == pytest.approx(-1.1345)
        assert env.action_space.high[3] == pytest.approx(1.8326)
        assert env.action_space.low[0] == -1.0 and env.action_space.high[14] == 1.0
    assert env.observation_space["proprioception"].shape == (proprioception,)
    assert env.observation_space["task_obs"].shape == (456,)
    check_env(env.unwrapped, skip_render_check=True)


def test_an_episode_steps_and_reports_q_and_metrics():
    env = make(max_steps=5)
    obs, info = env.reset(seed=1)
    assert obs["task_obs"].dtype == np.float32
    assert info["steps"] == 0 and 0.0 <= info["q"] <= 1.0
    truncated = False
    steps = 0
    while not truncated:
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        steps += 1
        assert isinstance(reward, float) and not terminated
    assert steps == 5 and info["steps"] == 5
    assert env.unwrapped.metrics()["steps"] == 5


def test_same_seed_and_actions_give_identical_observations():
    actions = np.random.default_rng(3).uniform(-1, 1, size=(20, 26)).astype(np.float32)
    runs = []
    for _ in range(2):
        env = make()
        obs, _ = env.reset(seed=7)
        trace = [obs["task_obs"].copy(), obs["proprioception"].copy()]
        for a in actions:
            obs, *_ = env.step(a)
            trace += [obs["task_obs"].copy(), obs["proprioception"].copy()]
        runs.append(trace)
    for a, b in zip(*runs):
        assert a.tobytes() == b.tobytes()


def test_bad_input_raises_clear_errors():
    env = make(max_steps=1)
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"shape \(26,\)"):
        env.step(np.zeros((2, 13), dtype=np.float32))
    with pytest.raises(ValueError, match="finite"):
        env.step(np.full(26, np.nan, dtype=np.float32))
    raw = env.unwrapped._env
    with pytest.raises(ValueError, match="26 values, got 3"):
        raw.step(np.zeros(3, dtype=np.float32))
    env.step(np.zeros(26, dtype=np.float32))
    with pytest.raises(ValueError, match="episode is over"):
        raw.step(np.zeros(26, dtype=np.float32))
    # An activity is an official name or a definition file (the builder the CLI uses).
    with pytest.raises(ValueError, match="`juggling` is neither a file nor an official activity"):
        behavior.BehaviorEnv(activity="juggling")
    with pytest.raises(ValueError, match="robot must be one of"):
        behavior.BehaviorEnv(robot="roomba")
    with pytest.raises(ValueError, match="named homes"):
        behavior.BehaviorEnv(scene="atlantis")


def test_two_environments_step_at_once_in_threads():
    envs = [make(), make()]
    for k, env in enumerate(envs):
        env.reset(seed=k)
    errors, steps = [], []

    def run(env):
        try:
            for _ in range(10):
                *_, info = env.step(np.zeros(26, dtype=np.float32))
            steps.append(info["steps"])
        except Exception as e:  # reported below
            errors.append(e)

    threads = [threading.Thread(target=run, args=(env,)) for env in envs]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert steps == [10, 10]


@pytest.mark.parametrize("mode", ["symbolic", "physical"])
@pytest.mark.parametrize("robot", ["behavior", "fetch", "r1"])
def test_check_env_passes_with_primitives(robot, mode):
    env = make(robot, action_space="primitives", primitive_mode=mode)
    assert isinstance(env.action_space, gymnasium.spaces.Discrete)
    check_env(env.unwrapped, skip_render_check=True)


def test_primitives_follow_the_mask_and_report_what_they_did():
    env = make(action_space="primitives", primitive_set="paper")
    # Seed 1: at seed 0 the first plank is drawn too heavy for the hand.
    _, info = env.reset(seed=1)
    n_actions = env.action_space.n
    assert n_actions % 6 == 0 and info["action_mask"].shape == (n_actions,)
    assert (info["action_mask"] == env.unwrapped.action_masks()).all()
    n = n_actions // 6
    # navigate_to (primitive 0) the first object, then grasp it (primitive 1), as the mask allows.
    q = info["q"]
    for a in (0, n):
        assert info["action_mask"][a], f"action {a} masked"
        obs, reward, terminated, truncated, info = env.step(a)
        assert info["ok"], info["reason"]
        assert reward == pytest.approx(info["q"] - q)
        q = info["q"]
    assert info["primitive"] == "grasp" and info["object"]
    # A masked action runs and says why it failed.
    masked = int(np.flatnonzero(~info["action_mask"])[0])
    _, reward, _, _, info = env.step(masked)
    assert not info["ok"] and info["reason"] and reward == 0.0


def test_physical_primitives_drive_with_physics():
    env = make(action_space="primitives", primitive_mode="physical")
    _, info = env.reset(seed=0)
    _, _, _, _, info = env.step(0)  # navigate_to the first object
    assert info["primitive"] == "navigate_to" and info["ok"], info["reason"]
    assert info["steps"] > 10  # driven step by step, not teleported


def test_bad_primitive_input_raises():
    env = make(action_space="primitives")
    env.reset(seed=0)
    with pytest.raises(ValueError, match="out of range"):
        env.step(env.action_space.n)
    with pytest.raises(ValueError, match="one integer"):
        env.step(np.zeros(26, dtype=np.float32))
    with pytest.raises(ValueError, match="primitive_mode must be"):
        make(action_space="primitives", primitive_mode="magic")
    with pytest.raises(ValueError, match="primitive_set must be"):
        make(action_space="primitives", primitive_set="many")
    with pytest.raises(ValueError, match="action_space must be"):
        make(action_space="discrete")
    continuous = make()
    with pytest.raises(ValueError, match="continuous, not primitives"):
        continuous.unwrapped._env.step_primitive(0)


def test_camera_images_are_observed_and_the_overview_rendered():
    env = make(
        observations=["task_obs", "rgb", "depth", "seg"], image_size=64,
        render_mode="rgb_array", render_size=96,
    )
    space = env.observation_space
    assert set(space.keys()) == {"task_obs", "rgb", "depth", "seg"}
    assert space["rgb"].shape == (64, 64, 3) and space["rgb"].dtype == np.uint8
    assert space["depth"].shape == (64, 64) and space["depth"].dtype == np.float32
    assert space["seg"].dtype == np.uint16
    obs, _ = env.reset(seed=0)
    assert obs in space
    assert obs["rgb"].std() > 0 and obs["depth"].max() > 0  # something in view
    frame = env.render()
    assert frame.shape == (96, 96, 3) and frame.dtype == np.uint8 and frame.std() > 0
    obs, *_ = env.step(env.action_space.sample())
    assert env.render() is not frame  # a new frame each step
    check_env(env.unwrapped)


def test_bad_observation_options_raise():
    with pytest.raises(ValueError, match="unknown modality `colour`"):
        make(observations=["colour"])
    with pytest.raises(ValueError, match="list of names"):
        make(observations="rgb")
    with pytest.raises(ValueError, match="render_mode must be"):
        behavior.BehaviorEnv(ACTIVITY, render_mode="ansi")
    with pytest.raises(ValueError, match="at least 1 pixel"):
        make(observations=["rgb"], image_size=0)
    with pytest.raises(ValueError, match="unknown image profile `pretty`; known: realistic, fast"):
        make(observations=["rgb"], image_profile="pretty")


def test_the_image_profiles_differ_in_colour_only():
    observed = {}
    for profile in ("realistic", "fast"):
        env = make(observations=["rgb", "depth", "seg"], image_size=48, image_profile=profile)
        observed[profile], _ = env.reset(seed=0)
    realistic, fast = observed["realistic"], observed["fast"]
    assert np.array_equal(realistic["depth"], fast["depth"])
    assert np.array_equal(realistic["seg"], fast["seg"])
    assert not np.array_equal(realistic["rgb"], fast["rgb"])


def test_python_runs_on_another_thread_while_rust_works():
    # A reset (sampling an instance, tens of ms) is one call into Rust; were the interpreter's
    # lock held through it, no Python code could run on another thread until it returned: one
    # gap as long as the call between the other thread's ticks.
    env = make()
    spans = []

    def resets():
        for seed in range(3):
            start = time.perf_counter()
            env.reset(seed=seed)
            spans.append((start, time.perf_counter()))

    worker = threading.Thread(target=resets)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    for start, end in spans:
        assert end - start > 0.005, "the reset was too short to tell"
        points = [start] + [t for t in ticks if start < t < end] + [end]
        longest = max(b - a for a, b in zip(points, points[1:]))
        assert longest < 0.5 * (end - start), (
            f"no Python ran for {longest:.3f} s of a {end - start:.3f} s reset"
        )


def test_restoring_a_checkpoint_continues_bit_for_bit():
    env = make(action_space="primitives").unwrapped
    start_obs, start_info = env.reset(seed=2)
    start = env.checkpoint()
    rng = np.random.default_rng(0)
    actions = []
    for _ in range(6):
        actions.append(int(rng.choice(np.flatnonzero(env.action_masks()))))
        first = env.step(actions[-1])
    obs, info = env.restore(start)
    assert info["steps"] == 0 and info["q"] == start_info["q"]
    for key in start_obs:
        np.testing.assert_array_equal(obs[key], start_obs[key])
    np.testing.assert_array_equal(info["action_mask"], start_info["action_mask"])
    for a in actions:
        again = env.step(a)
    for key in first[0]:
        np.testing.assert_array_equal(again[0][key], first[0][key])
    assert again[1:4] == first[1:4] and again[4]["steps"] == first[4]["steps"]


def test_a_checkpoint_of_another_environment_is_refused():
    source = make().unwrapped
    source.reset(seed=0)
    other = gymnasium.make("behavior/storing_food-v0").unwrapped
    with pytest.raises(ValueError, match="the checkpoint is of bringing_in_wood"):
        other.restore(source.checkpoint())
