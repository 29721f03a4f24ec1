"""Table 1's oracle rows: a start state taken from any step of a recording continues bit for
bit, foreign recordings are refused, a short SAC run trains from a demonstration's state one
second before its success, and the table of runs resumes, reports and runs on Ray."""

import json
from pathlib import Path

import numpy as np
import pytest

from behavior import BehaviorEnv

pytest.importorskip("stable_baselines3")

from behavior.baselines import oracle, oracle_table  # noqa: E402

ACTIVITY = "bringing_in_wood"
# One of the project's own activities: the printer switched on, a short physical plan.
PRINTER = Path(__file__).resolve().parents[2] / "activities" / "switching_on_the_printer.bddl"


def _continuous_recording(path, steps=70):
    """Records `steps` random actions; returns them and the last observation."""
    env = BehaviorEnv(ACTIVITY, seed=3)
    env.reset(seed=3)
    env.record(path, checkpoint_every=30)
    rng = np.random.default_rng(0)
    actions = [rng.uniform(-1, 1, env.action_space.shape).astype(np.float32)
               for _ in range(steps)]
    for a in actions:
        obs, *_ = env.step(a)
    env.close()
    return actions, obs


def test_a_start_state_is_taken_from_any_step_of_a_recording_bit_for_bit(tmp_path):
    path = tmp_path / "run.mcap"
    actions, last = _continuous_recording(path)
    env = BehaviorEnv(ACTIVITY, seed=3)
    # Step 45 lies between the checkpoints of steps 30 and 60.
    obs, info = env.restore(env.checkpoint_from_recording(path, 45))
    assert info["steps"] == 45
    for a in actions[45:]:
        obs, *_ = env.step(a)
    for key in ("proprioception", "task_obs"):
        assert np.array_equal(obs[key], last[key]), key
    with pytest.raises(ValueError, match="ends at step 70"):
        env.checkpoint_from_recording(path, 71)
    with pytest.raises(ValueError, match="non-negative"):
        env.checkpoint_from_recording(path, -1)
    with pytest.raises(ValueError, match="activity"):
        BehaviorEnv("storing_food").checkpoint_from_recording(path, 10)
    with pytest.raises(ValueError, match="robot"):
        BehaviorEnv(ACTIVITY, robot="fetch", seed=3).checkpoint_from_recording(path, 10)


def _demonstration(folder: Path) -> Path:
    """A physical demonstration of switching the printer on, in a folder as ``behavior demos
    generate`` leaves one (the recording and its manifest)."""
    env = BehaviorEnv(str(PRINTER), action_space="primitives", primitive_mode="physical",
                      primitive_set="all")
    env.reset(seed=0)
    actions = env.primitive_actions()
    on_printer = {p: i for i, (p, o) in enumerate(actions) if o.startswith("printer")}
    path = folder / "episodes" / "printer.mcap"
    path.parent.mkdir(parents=True)
    env.record(path)
    info = {"success": False}
    # Going to the printer can end out of the hand's reach: then again, as the planner does.
    for _ in range(3):
        env.step(on_printer["navigate_to"])
        *_, info = env.step(on_printer["toggle_on"])
        if info["success"]:
            break
    env.close()
    assert info["success"], "the demonstration switched the printer on"
    manifest = {"robot": "behavior",
                "demos": [{"activity": "switching_on_the_printer_0", "file": "episodes/printer.mcap"}]}
    (folder / "demos.json").write_text(json.dumps(manifest))
    return path


@pytest.fixture(scope="module")
def demos(tmp_path_factory):
    folder = tmp_path_factory.mktemp("demos")
    _demonstration(folder)
    return folder


def test_episodes_start_one_second_before_the_demonstrations_success(demos):
    config = oracle.OracleConfig(str(PRINTER), before_s=1, demos=demos)
    [start] = oracle.starts_for(config)
    assert start.step == start.success_step - 30 > 0
    assert config.horizon() == 90
    env = oracle.make_env(config, [start])
    for _ in range(2):
        _, info = env.reset()
        assert info["steps"] == start.step and not info["success"]
        q0, total = info["q"], 0.0
        done = False
        while not done:
            _, reward, terminated, truncated, info = env.step(np.zeros(env.action_space.shape,
                                                                       np.float32))
            total += reward
            done = terminated or truncated
        # Within three times the offset, the reward counting goal literals (one here).
        assert info["steps"] - start.step <= 90
        assert total == pytest.approx((info["q"] - q0) * env.get_wrapper_attr("literals"))
    with pytest.raises(ValueError, match="no demonstration of storing_food"):
        oracle.demonstrations(demos, "storing_food")


def test_sac_trains_from_the_demonstrations_states(demos, tmp_path):
    config = oracle.OracleConfig(str(PRINTER), before_s=1, demos=demos, timesteps=200,
                                 evaluation_episodes=3, out=tmp_path / "run")
    result = oracle.train(config)
    assert json.loads((config.out / "result.json").read_text()) == result
    assert result["horizon"] == 90 and result["goal_literals"] == 1
    assert result["starts"][0]["step"] == result["starts"][0]["success_step"] - 30
    assert 0.0 <= result["success_rate"] <= 1.0 and result["training_episodes"] >= 1
    for name in ("curve.csv", "progress.csv", "model.zip"):
        assert (config.out / name).is_file(), name


def test_the_table_resumes_reports_and_runs_on_ray(demos, tmp_path):
    out = tmp_path / "table"
    common = ["--demos", str(demos), "--activities", str(PRINTER), "--seeds", "0",
              "--timesteps", "100", "--evaluation-episodes", "2", "--out", str(out)]
    assert oracle_table.main([*common, "--offsets", "1", "--jobs", "1"]) == 0
    done = out / "switching_on_the_printer" / "T-1s" / "0" / "result.json"
    first = done.read_text()
    # Again, with one more offset, on Ray: the first run is kept, the second trained there.
    ray = pytest.importorskip("ray")
    try:
        assert oracle_table.main([*common, "--offsets", "1", "2", "--ray", "local"]) == 0
    finally:
        ray.shutdown()
    assert done.read_text() == first
    assert (out / "switching_on_the_printer" / "T-2s" / "0" / "result.json").is_file()
    table = (out / "table.md").read_text()
    assert "SR @ T−1 s" in table and "SR @ T−2 s" in table
    assert "| switching_on_the_printer |" in table
    summary = json.loads((out / "summary.json").read_text())
    assert sorted(r["before_s"] for r in summary) == [1.0, 2.0]
    assert all(r["zero_action_success_rate"] in (0.0, 1.0) for r in summary)
    assert (out / "curves.png").stat().st_size > 0
